// GCC 12 reports false -Wmaybe-uninitialized inside Eigen's AVX-512 kernels at -O3.
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"

#include "analysis/kmeans.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>

namespace tactile::analysis {
namespace {

// Three tight clusters far apart, 30 rows each, in 2-D.
Eigen::MatrixXd threeClusters() {
  Eigen::MatrixXd x(90, 2);
  Rng rng(3);
  const double cx[3] = {0.0, 1000.0, 0.0};
  const double cy[3] = {0.0, 0.0, 1000.0};
  for (int r = 0; r < 90; ++r) {
    x(r, 0) = cx[r % 3] + rng.uniform();
    x(r, 1) = cy[r % 3] + rng.uniform();
  }
  return x;
}

TEST(KMeansPlusPlus, PicksOneCentreInEachSeparatedCluster) {
  const Eigen::MatrixXd x = threeClusters();
  for (std::uint64_t seed = 1; seed <= 5; ++seed) {
    Rng rng(seed);
    const Eigen::MatrixXd c = kmeansPlusPlus(x, 3, rng);
    std::set<int> clusters;
    for (int i = 0; i < 3; ++i)
      clusters.insert(c(i, 0) > 500 ? 1 : (c(i, 1) > 500 ? 2 : 0));
    EXPECT_EQ(clusters.size(), 3u) << "seed " << seed;
  }
}

TEST(KMeansPlusPlus, MoreCentresThanDistinctRowsGivesRowsWithoutFailing) {
  Eigen::MatrixXd x(4, 1);
  x << 1, 1, 2, 2;
  Rng rng(1);
  const Eigen::MatrixXd c = kmeansPlusPlus(x, 6, rng);
  ASSERT_EQ(c.rows(), 6);
  for (int i = 0; i < 6; ++i)
    EXPECT_TRUE(c(i, 0) == 1.0 || c(i, 0) == 2.0);
  EXPECT_TRUE((c.array() == 1.0).any() && (c.array() == 2.0).any());
}

TEST(AssignNearest, TiesGoToTheLowestIndex) {
  Eigen::MatrixXd x(1, 1);
  x << 0.0;
  Eigen::MatrixXd c(2, 1);
  c << -1.0, 1.0;
  std::vector<int> a;
  assignNearest(x, c, a);
  EXPECT_EQ(a[0], 0);
}

TEST(Lloyd, MovesCentresToTheClusterMeans) {
  const Eigen::MatrixXd x = threeClusters();
  Eigen::MatrixXd c(3, 2);
  c << 10, 10, 900, 50, 50, 900;
  std::vector<int> a;
  const int iterations = lloydIterations(x, c, 20, a);
  EXPECT_LE(iterations, 20);
  for (int k = 0; k < 3; ++k) {
    Eigen::RowVectorXd mean = Eigen::RowVectorXd::Zero(2);
    int count = 0;
    for (int r = 0; r < 90; ++r)
      if (a[static_cast<std::size_t>(r)] == k) {
        mean += x.row(r);
        ++count;
      }
    ASSERT_EQ(count, 30);
    EXPECT_LT((c.row(k) - mean / count).norm(), 1e-9);
  }
}

TEST(KMeansPlusPlus, ResultDoesNotDependOnTheThreadCount) {
  Eigen::MatrixXd x(20000, 3);
  Rng data(5);
  for (Eigen::Index r = 0; r < x.rows(); ++r)
    for (Eigen::Index j = 0; j < 3; ++j)
      x(r, j) = data.uniform() * 10.0;
  Rng a(9), b(9);
  Eigen::MatrixXd ca = kmeansPlusPlus(x, 12, a, 1);
  Eigen::MatrixXd cb = kmeansPlusPlus(x, 12, b, 2);
  EXPECT_TRUE(ca == cb);
  std::vector<int> aa, ab;
  lloydIterations(x, ca, 5, aa, 1);
  lloydIterations(x, cb, 5, ab, 2);
  EXPECT_EQ(aa, ab);
  EXPECT_TRUE(ca == cb);
}

}  // namespace
}  // namespace tactile::analysis
