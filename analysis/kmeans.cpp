#include "analysis/kmeans.h"

#include "analysis/gmm_kernels.h"
#include "base/parallel.h"

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace tactile::analysis {

namespace {
constexpr Eigen::Index kBlockRows = 512;
// Fewer rows than this run on the calling thread (waking workers would cost more).
constexpr Eigen::Index kMinRowsForThreads = 4096;

// Runs f(firstBlock, endBlock) over groups of blocks of `rows` rows on `threads` threads. Every
// caller writes one result per block and reduces them in block order, so results do not depend on
// the number of threads.
template <class F>
void forEachBlockGroup(Eigen::Index rows, Eigen::Index blocks, int threads, F&& f) {
  if (rows < kMinRowsForThreads) threads = 1;
  constexpr Eigen::Index kBlocksPerPart = 4;
  const int parts = static_cast<int>((blocks + kBlocksPerPart - 1) / kBlocksPerPart);
  pooledParallelFor(parts, threads, [&](int p) {
    f(p * kBlocksPerPart, std::min(blocks, (p + 1) * kBlocksPerPart));
  });
}
}  // namespace

Eigen::MatrixXd kmeansPlusPlus(const Eigen::Ref<const Eigen::MatrixXd>& samples, int k, Rng& rng,
                               int threads) {
  const Eigen::Index n = samples.rows();
  const Eigen::Index d = samples.cols();
  Eigen::MatrixXd centres(k, d);
  if (n == 0 || k <= 0) return centres;
  Eigen::Index first = static_cast<Eigen::Index>(rng.below(static_cast<std::uint64_t>(n)));
  centres.row(0) = samples.row(first);
  // D(x_n)^2 to the nearest chosen centre; each candidate costs one blocked pass over the data.
  // Every block of kBlockRows rows also keeps its own sum, so drawing a row by D^2 walks the block
  // sums first and then one block, instead of every row.
  const Eigen::Index blocks = (n + kBlockRows - 1) / kBlockRows;
  Eigen::ArrayXd dist2(n), dist2Blocks(blocks);
  // out = min(current, |x - row|^2) (current == nullptr: just the distance), outBlocks = the
  // block sums; returns their sum, added in block order.
  const auto distances = [&](const Eigen::RowVectorXd& c, const double* current, double* out,
                             double* outBlocks) {
    const Eigen::VectorXd centre = c.transpose();
    forEachBlockGroup(n, blocks, threads, [&](Eigen::Index begin, Eigen::Index end) {
      for (Eigen::Index blk = begin; blk < end; ++blk) {
        const Eigen::Index start = blk * kBlockRows;
        const Eigen::Index b = std::min(kBlockRows, n - start);
        outBlocks[blk] = blockSquaredDistances(samples.data() + start, samples.outerStride(), b,
                                               static_cast<int>(d), centre.data(),
                                               current ? current + start : nullptr, out + start);
      }
    });
    double total = 0.0;
    for (Eigen::Index blk = 0; blk < blocks; ++blk)
      total += outBlocks[blk];
    return total;
  };
  double potential = distances(centres.row(0), nullptr, dist2.data(), dist2Blocks.data());
  // Greedy k-means++ (as scikit-learn): 2 + floor(ln k) candidates per step, keep the one that
  // lowers the potential sum D^2 most.
  const int trials = 2 + static_cast<int>(std::log(static_cast<double>(k)));
  Eigen::ArrayXd candidate(n), bestCandidate(n), candidateBlocks(blocks), bestBlocks(blocks);
  for (int c = 1; c < k; ++c) {
    double bestPotential = std::numeric_limits<double>::infinity();
    Eigen::Index bestPick = 0;
    for (int t = 0; t < trials; ++t) {
      Eigen::Index pick = 0;
      if (!(potential > 0.0) || !std::isfinite(potential)) {
        pick = static_cast<Eigen::Index>(rng.below(static_cast<std::uint64_t>(n)));
      } else {
        // The first row at which the running sum of D^2 (block sums, then rows) passes the target.
        const double target = rng.uniform() * potential;
        double run = 0.0;
        pick = n - 1;
        Eigen::Index blk = 0;
        while (blk < blocks && run + dist2Blocks(blk) <= target)
          run += dist2Blocks(blk++);
        const Eigen::Index end = blk < blocks ? std::min(n, (blk + 1) * kBlockRows) : n;
        for (Eigen::Index i = blk * kBlockRows; i < end; ++i) {
          run += dist2(i);
          if (run > target && dist2(i) > 0.0) {
            pick = i;
            break;
          }
        }
        while (pick > 0 && !(dist2(pick) > 0.0))
          --pick;  // never pick an already-covered row
      }
      const double p =
          distances(samples.row(pick), dist2.data(), candidate.data(), candidateBlocks.data());
      if (p < bestPotential) {
        bestPotential = p;
        bestPick = pick;
        bestCandidate.swap(candidate);
        bestBlocks.swap(candidateBlocks);
      }
    }
    centres.row(c) = samples.row(bestPick);
    dist2.swap(bestCandidate);
    dist2Blocks.swap(bestBlocks);
    potential = bestPotential;
  }
  return centres;
}

double assignNearest(const Eigen::Ref<const Eigen::MatrixXd>& samples,
                     const Eigen::MatrixXd& centres, std::vector<int>& assignment, int threads) {
  const Eigen::Index n = samples.rows();
  const int k = static_cast<int>(centres.rows());
  assignment.assign(static_cast<std::size_t>(n), 0);
  if (n == 0 || k == 0) return 0.0;
  const Eigen::Index blocks = (n + kBlockRows - 1) / kBlockRows;
  std::vector<double> blockInertia(static_cast<std::size_t>(blocks));
  forEachBlockGroup(n, blocks, threads, [&](Eigen::Index begin, Eigen::Index end) {
    for (Eigen::Index blk = begin; blk < end; ++blk) {
      const Eigen::Index start = blk * kBlockRows;
      blockInertia[static_cast<std::size_t>(blk)] = blockNearestCentres(
          samples.data() + start, samples.outerStride(), std::min(kBlockRows, n - start),
          static_cast<int>(samples.cols()), centres.data(), k, assignment.data() + start);
    }
  });
  double inertia = 0.0;
  for (double v : blockInertia)
    inertia += v;
  return inertia;
}

int lloydIterations(const Eigen::Ref<const Eigen::MatrixXd>& samples, Eigen::MatrixXd& centres,
                    int iterations, std::vector<int>& assignment, int threads) {
  const Eigen::Index n = samples.rows();
  const Eigen::Index k = centres.rows();
  const Eigen::Index d = samples.cols();
  assignNearest(samples, centres, assignment, threads);
  int done = 0;
  std::vector<int> next;
  // Sums per part of the rows (a fixed number of parts for a given n), added in part order.
  const int parts = static_cast<int>(std::clamp<Eigen::Index>(n / 8192, 1, 16));
  std::vector<Eigen::MatrixXd> partSums(static_cast<std::size_t>(parts));
  std::vector<Eigen::VectorXd> partCounts(static_cast<std::size_t>(parts));
  Eigen::MatrixXd sums(k, d);
  Eigen::VectorXd counts(k);
  const int partThreads = n < kMinRowsForThreads ? 1 : threads;
  while (done < iterations) {
    pooledParallelFor(parts, partThreads, [&](int p) {
      Eigen::MatrixXd& ps = partSums[static_cast<std::size_t>(p)];
      Eigen::VectorXd& pc = partCounts[static_cast<std::size_t>(p)];
      ps.setZero(k, d);
      pc.setZero(k);
      const Eigen::Index begin = n * p / parts, end = n * (p + 1) / parts;
      for (Eigen::Index r = begin; r < end; ++r)
        pc(assignment[static_cast<std::size_t>(r)]) += 1.0;
      for (Eigen::Index j = 0; j < d; ++j) {
        const double* xj = samples.data() + j * samples.outerStride();
        double* sj = ps.data() + j * k;
        for (Eigen::Index r = begin; r < end; ++r)
          sj[assignment[static_cast<std::size_t>(r)]] += xj[r];
      }
    });
    sums.setZero();
    counts.setZero();
    for (int p = 0; p < parts; ++p) {
      sums += partSums[static_cast<std::size_t>(p)];
      counts += partCounts[static_cast<std::size_t>(p)];
    }
    for (Eigen::Index i = 0; i < k; ++i)
      if (counts(i) > 0.0) centres.row(i) = sums.row(i) / counts(i);
    ++done;
    assignNearest(samples, centres, next, threads);
    if (next == assignment) break;
    assignment.swap(next);
  }
  return done;
}

}  // namespace tactile::analysis
