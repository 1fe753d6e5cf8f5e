// GCC 12 reports false -Wmaybe-uninitialized inside Eigen's AVX-512 kernels at -O3.
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"

#include "analysis/kmeans.h"

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <thread>

namespace tactile {

namespace {
constexpr Eigen::Index kBlockRows = 512;
// Rows are split into this many parts whatever the thread count; partial sums are added in part
// order, so results do not depend on the number of threads.
constexpr int kParts = 8;

template <class F>
void forEachPart(Eigen::Index n, int threads, F&& f) {
  const auto run = [&](int p) { f(n * p / kParts, n * (p + 1) / kParts, p); };
  threads = std::clamp(threads, 1, kParts);
  if (threads == 1 || n < 4096) {
    for (int p = 0; p < kParts; ++p)
      run(p);
    return;
  }
  std::vector<std::thread> pool;
  for (int t = 1; t < threads; ++t)
    pool.emplace_back([&, t] {
      for (int p = t; p < kParts; p += threads)
        run(p);
    });
  for (int p = 0; p < kParts; p += threads)
    run(p);
  for (auto& th : pool)
    th.join();
}
}  // namespace

Eigen::MatrixXd kmeansPlusPlus(const Eigen::MatrixXd& samples, int k, Rng& rng, int threads) {
  const Eigen::Index n = samples.rows();
  const Eigen::Index d = samples.cols();
  Eigen::MatrixXd centres(k, d);
  if (n == 0 || k <= 0) return centres;
  Eigen::Index first = static_cast<Eigen::Index>(rng.below(static_cast<std::uint64_t>(n)));
  centres.row(0) = samples.row(first);
  // D(x_n)^2 to the nearest chosen centre; each candidate costs one blocked pass over the data.
  Eigen::ArrayXd dist2(n);
  // out = min(current, |x - row|^2) (current == nullptr: just the distance); returns sum(out).
  const auto distances = [&](const Eigen::RowVectorXd& c, const double* current, double* out) {
    std::array<double, kParts> partial{};
    forEachPart(n, threads, [&](Eigen::Index begin, Eigen::Index end, int part) {
      double acc[kBlockRows];
      double total = 0.0;
      for (Eigen::Index start = begin; start < end; start += kBlockRows) {
        const Eigen::Index b = std::min(kBlockRows, end - start);
        for (Eigen::Index r = 0; r < b; ++r)
          acc[r] = 0.0;
        for (Eigen::Index j = 0; j < d; ++j) {
          const double* xj = samples.data() + j * n + start;
          const double cj = c(j);
          for (Eigen::Index r = 0; r < b; ++r) {
            const double t = xj[r] - cj;
            acc[r] += t * t;
          }
        }
        for (Eigen::Index r = 0; r < b; ++r) {
          const double v = current ? std::min(current[start + r], acc[r]) : acc[r];
          out[start + r] = v;
          total += v;
        }
      }
      partial[static_cast<std::size_t>(part)] = total;
    });
    double total = 0.0;
    for (double p : partial)
      total += p;
    return total;
  };
  double potential = distances(centres.row(0), nullptr, dist2.data());
  // Greedy k-means++ (as scikit-learn): 2 + floor(ln k) candidates per step, keep the one that
  // lowers the potential sum D^2 most.
  const int trials = 2 + static_cast<int>(std::log(static_cast<double>(k)));
  Eigen::ArrayXd candidate(n), bestCandidate(n);
  for (int c = 1; c < k; ++c) {
    double bestPotential = std::numeric_limits<double>::infinity();
    Eigen::Index bestPick = 0;
    for (int t = 0; t < trials; ++t) {
      Eigen::Index pick = 0;
      if (!(potential > 0.0) || !std::isfinite(potential)) {
        pick = static_cast<Eigen::Index>(rng.below(static_cast<std::uint64_t>(n)));
      } else {
        const double target = rng.uniform() * potential;
        double run = 0.0;
        pick = n - 1;
        for (Eigen::Index i = 0; i < n; ++i) {
          run += dist2(i);
          if (run > target && dist2(i) > 0.0) {
            pick = i;
            break;
          }
        }
        while (pick > 0 && !(dist2(pick) > 0.0))
          --pick;  // never pick an already-covered row
      }
      const double p = distances(samples.row(pick), dist2.data(), candidate.data());
      if (p < bestPotential) {
        bestPotential = p;
        bestPick = pick;
        bestCandidate.swap(candidate);
      }
    }
    centres.row(c) = samples.row(bestPick);
    dist2.swap(bestCandidate);
    potential = bestPotential;
  }
  return centres;
}

double assignNearest(const Eigen::MatrixXd& samples, const Eigen::MatrixXd& centres,
                     std::vector<int>& assignment, int threads) {
  const Eigen::Index n = samples.rows();
  const Eigen::Index k = centres.rows();
  assignment.assign(static_cast<std::size_t>(n), 0);
  const Eigen::VectorXd c2 = centres.rowwise().squaredNorm();
  std::array<double, kParts> partial{};
  forEachPart(n, threads, [&](Eigen::Index begin, Eigen::Index end, int part) {
    Eigen::MatrixXd prod(kBlockRows, k);
    double inertia = 0.0;
    double best[kBlockRows];
    int bestIndex[kBlockRows];
    for (Eigen::Index start = begin; start < end; start += kBlockRows) {
      const Eigen::Index b = std::min(kBlockRows, end - start);
      auto block = samples.middleRows(start, b);
      prod.topRows(b).noalias() = block * centres.transpose();
      // argmin_i (|c_i|^2 - 2 x . c_i), vectorised over rows; ties keep the lowest index.
      for (Eigen::Index r = 0; r < b; ++r) {
        best[r] = c2(0) - 2.0 * prod(r, 0);
        bestIndex[r] = 0;
      }
      for (Eigen::Index i = 1; i < k; ++i) {
        const double* col = prod.data() + i * kBlockRows;
        const double ci = c2(i);
        const int ii = static_cast<int>(i);
        for (Eigen::Index r = 0; r < b; ++r) {
          const double v = ci - 2.0 * col[r];
          const bool better = v < best[r];
          best[r] = better ? v : best[r];
          bestIndex[r] = better ? ii : bestIndex[r];
        }
      }
      for (Eigen::Index r = 0; r < b; ++r) {
        assignment[static_cast<std::size_t>(start + r)] = bestIndex[r];
        inertia += std::max(0.0, best[r] + block.row(r).squaredNorm());
      }
    }
    partial[static_cast<std::size_t>(part)] = inertia;
  });
  double inertia = 0.0;
  for (double p : partial)
    inertia += p;
  return inertia;
}

int lloydIterations(const Eigen::MatrixXd& samples, Eigen::MatrixXd& centres, int iterations,
                    std::vector<int>& assignment, int threads) {
  const Eigen::Index n = samples.rows();
  const Eigen::Index k = centres.rows();
  const Eigen::Index d = samples.cols();
  assignNearest(samples, centres, assignment, threads);
  int done = 0;
  std::vector<int> next;
  Eigen::MatrixXd sums(k, d);
  Eigen::VectorXd counts(k);
  while (done < iterations) {
    sums.setZero();
    counts.setZero();
    for (Eigen::Index r = 0; r < n; ++r)
      counts(assignment[static_cast<std::size_t>(r)]) += 1.0;
    for (Eigen::Index j = 0; j < d; ++j) {
      const double* xj = samples.data() + j * n;
      double* sj = sums.data() + j * k;
      for (Eigen::Index r = 0; r < n; ++r)
        sj[assignment[static_cast<std::size_t>(r)]] += xj[r];
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

}  // namespace tactile
