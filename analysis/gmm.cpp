// EM for Gaussian mixtures (thesis 4.4), blocked and multi-threaded.
//
// Numerical scheme (see docs/learning.md):
//  - the data are centred once on their column means; every density is evaluated in log space
//    through Cholesky factors (full forms) or 1/sigma (diagonal forms) and combined by log-sum-exp;
//  - the M-step statistics of component i are accumulated around its previous mean c_i
//    (shifted/centred accumulation): S1 = sum r (x - c_i), S2 = sum r (x - c_i)(x - c_i)^T, so
//    Sigma_i = S2 / N_i - d d^T with d = S1 / N_i small; no large-offset cancellation;
//  - rows are split into a fixed number of chunks that depends only on N; each chunk accumulates
//    its own statistics, and chunks are reduced in index order, so results do not depend on the
//    number of threads.
#include "analysis/gmm.h"

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <sstream>
#include <thread>

#include "analysis/gaussian.h"
#include "analysis/kmeans.h"
#include "base/parallel.h"

namespace tactile::analysis {

// ---------------------------------------------------------------------------------------------
// Name tables.

namespace {
constexpr std::array<std::pair<Regularization, std::string_view>, 2> kRegNames{{
    {Regularization::Floor, "floor"},
    {Regularization::Add, "add"},
}};
constexpr std::array<std::pair<GmmInit, std::string_view>, 2> kInitNames{{
    {GmmInit::KMeansPlusPlus, "kmeans++"},
    {GmmInit::RandomFromData, "random-from-data"},
}};
constexpr std::array<std::pair<ConvergenceRule, std::string_view>, 2> kRuleNames{{
    {ConvergenceRule::Relative, "relative"},
    {ConvergenceRule::Absolute, "absolute"},
}};

template <class E, std::size_t N>
std::string_view nameOf(const std::array<std::pair<E, std::string_view>, N>& table, E value) {
  for (const auto& [v, name] : table)
    if (v == value) return name;
  return "?";
}
template <class E, std::size_t N>
std::optional<E> parseName(const std::array<std::pair<E, std::string_view>, N>& table,
                           std::string_view text) {
  for (const auto& [v, name] : table)
    if (name == text) return v;
  return std::nullopt;
}

// Samples as the kernels read them: column-major, any leading dimension (outer stride).
using DataRef = Eigen::Ref<const Eigen::MatrixXd>;
constexpr int kMaxChunks = 16;
// A component whose total responsibility falls below this many samples has lost its weight: it
// is removed and the remaining weights renormalised (docs/learning.md, "empty components").
constexpr double kMinComponentMass = 1e-6;
// Fits on fewer rows than this run single-threaded (thread start-up would dominate).
constexpr Eigen::Index kMinRowsForThreads = 4096;

std::string formatDouble(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

}  // namespace

std::string_view regularizationName(Regularization reg) {
  return nameOf(kRegNames, reg);
}
std::optional<Regularization> parseRegularization(std::string_view name) {
  return parseName(kRegNames, name);
}
std::string_view gmmInitName(GmmInit init) {
  return nameOf(kInitNames, init);
}
std::optional<GmmInit> parseGmmInit(std::string_view name) {
  return parseName(kInitNames, name);
}
std::string_view convergenceRuleName(ConvergenceRule rule) {
  return nameOf(kRuleNames, rule);
}
std::optional<ConvergenceRule> parseConvergenceRule(std::string_view name) {
  return parseName(kRuleNames, name);
}

std::vector<std::string> varianceFloorWarnings(const Eigen::MatrixXd& samples, double varianceFloor,
                                               const std::vector<std::string>& featureNames) {
  return varianceFloorWarnings(std::span<const Eigen::MatrixXd>(&samples, 1), varianceFloor,
                               featureNames);
}

std::vector<std::string> varianceFloorWarnings(std::span<const Eigen::MatrixXd> parts,
                                               double varianceFloor,
                                               const std::vector<std::string>& featureNames) {
  std::vector<std::string> out;
  Eigen::Index n = 0;
  for (const Eigen::MatrixXd& p : parts)
    n += p.rows();
  if (n < 2 || !(varianceFloor > 0.0)) return out;
  const double rows = static_cast<double>(n);
  // var_j = (1/N) sum_n (x_nj - mean_j)^2, two passes over the rows of every part.
  for (Eigen::Index j = 0; j < parts.front().cols(); ++j) {
    double sum = 0.0;
    for (const Eigen::MatrixXd& p : parts)
      sum += p.col(j).sum();
    const double mean = sum / rows;
    double squares = 0.0;
    for (const Eigen::MatrixXd& p : parts)
      squares += (p.col(j).array() - mean).square().sum();
    const double variance = squares / rows;
    if (!(variance > 0.0) || !std::isfinite(variance) || varianceFloor < 100.0 * variance) continue;
    const std::size_t js = static_cast<std::size_t>(j);
    const std::string name = "feature " + std::to_string(j) +
                             (js < featureNames.size() ? " (" + featureNames[js] + ")" : "");
    out.push_back("variance floor " + formatDouble(varianceFloor) + " is " +
                  formatDouble(varianceFloor / variance) + " times the variance of " + name +
                  " over the training data (standard deviation " +
                  formatDouble(std::sqrt(variance)) +
                  "): the floor hides that feature's spread, so classes that differ only there "
                  "are not told apart; rescale the features or lower the variance floor");
  }
  return out;
}

// ---------------------------------------------------------------------------------------------
// GaussianMixture.

// ---------------------------------------------------------------------------------------------
// EM engine.

namespace {

// Sufficient statistics of one chunk of rows, accumulated around the previous means c_i.
struct Stats {
  Eigen::VectorXd nk;  // K: sum_n r_ni
  Eigen::MatrixXd s1;  // K x D: sum_n r_ni (x_n - c_i)
  Eigen::MatrixXd s2;  // diagonal: K x D, sum r (x - c)^2; full: D x (K*D), lower triangles
  double logLik = 0.0;

  void reset(int k, int d, bool diagonal, bool withMoments) {
    logLik = 0.0;
    if (!withMoments) return;
    nk.setZero(k);
    s1.setZero(k, d);
    if (diagonal)
      s2.setZero(k, d);
    else
      s2.setZero(d, static_cast<Eigen::Index>(k) * d);
  }
  void add(const Stats& o, bool withMoments) {
    logLik += o.logLik;
    if (!withMoments) return;
    nk += o.nk;
    s1 += o.s1;
    s2 += o.s2;
  }
};

struct EmState {
  Eigen::VectorXd weights;            // K
  Eigen::MatrixXd means;              // K x D, in the centred frame
  std::vector<Eigen::MatrixXd> covs;  // K (nodal) or 1 (grand), D x D
  GmmDensityCache cache;
  // `add` regularisation: how far, in total nats, the M-step that made this state may have
  // lowered the log-likelihood (docs/learning.md, "Monotone EM"); 0 for the floor clamp.
  double regularizationBound = 0.0;
};

struct Chunking {
  Eigen::Index rows = 0;
  int chunks = 1;
  // Chunks start on multiples of 8 rows (aligned vector loads); the last one ends at `rows`.
  Eigen::Index begin(int c) const { return rows * c / chunks / 8 * 8; }
  Eigen::Index end(int c) const { return c + 1 == chunks ? rows : begin(c + 1); }
};

Chunking makeChunking(Eigen::Index n) {
  Chunking ch;
  ch.rows = n;
  const Eigen::Index wanted = (n + 4 * kDensityBlockRows - 1) / (4 * kDensityBlockRows);
  ch.chunks = static_cast<int>(std::clamp<Eigen::Index>(wanted, 1, kMaxChunks));
  return ch;
}

// Runs f(chunk) for every chunk on `threads` threads (the calling thread is one of them).
template <class F>
void forEachChunk(int chunks, int threads, F&& f) {
  pooledParallelFor(chunks, threads, [&](int c) { f(c); });
}

// One E-step pass over the centred data: log-likelihood, and if withMoments the M-step statistics
// around the current means. Per-chunk results are reduced in chunk order into `total`.
void emPass(const DataRef& x, const EmState& state, bool withMoments, int threads,
            const Chunking& ch, std::vector<Stats>& chunkStats, Stats& total) {
  const GmmDensityCache& cache = state.cache;
  const int k = cache.components;
  const int d = cache.dimension;
  const bool diagonal = cache.diagonal;
  chunkStats.resize(static_cast<std::size_t>(ch.chunks));
  forEachChunk(ch.chunks, threads, [&](int c) {
    Stats& st = chunkStats[static_cast<std::size_t>(c)];
    st.reset(k, d, diagonal, withMoments);
    // Eigen-allocated (64-byte aligned) buffers with a fixed leading dimension: every vectorised
    // reduction below then splits its work identically whatever the thread and allocation.
    const int ld = static_cast<int>(kDensityBlockRows);
    Eigen::VectorXd logp(kDensityBlockRows * k);
    Eigen::VectorXd resp(withMoments ? kDensityBlockRows * k : 0);
    Eigen::VectorXd lse(kDensityBlockRows);
    Eigen::VectorXd scratch(2 * kDensityBlockRows);
    Eigen::MatrixXd tail;  // zero-padded copy of a last block shorter than kDensityBlockRows
    const Eigen::Index chunkEnd = ch.end(c);
    for (Eigen::Index start = ch.begin(c); start < chunkEnd; start += kDensityBlockRows) {
      const int b = static_cast<int>(std::min(kDensityBlockRows, chunkEnd - start));
      const int bp = paddedRows(b);
      const double* xb = x.data() + start;
      Eigen::Index ldx = x.outerStride();
      // fitGmm pads the columns to a multiple of 8 rows, so a padded block is readable in place;
      // other callers get a zero-padded copy.
      if (start + bp > ldx) {
        tail = Eigen::MatrixXd::Zero(bp, d);
        tail.topRows(b) = x.middleRows(start, b);
        xb = tail.data();
        ldx = bp;
      }
      blockComponentLogDensities(cache, xb, ldx, bp, logp.data(), ld);
      blockLogSumExp(logp.data(), ld, bp, k, lse.data(), withMoments ? resp.data() : nullptr,
                     scratch.data());
      st.logLik += lse.head(b).sum();
      if (!withMoments) continue;
      for (int i = 0; i < k && bp != b; ++i)
        for (int r = b; r < bp; ++r)
          resp(static_cast<Eigen::Index>(i) * ld + r) = 0.0;
      blockAccumulateStats(cache, xb, ldx, bp, resp.data(), ld, st.nk, st.s1, st.s2);
    }
  });
  total = Stats{};
  total.reset(k, d, diagonal, withMoments);
  for (const Stats& st : chunkStats)
    total.add(st, withMoments);
}

// Applies the variance floor or the additive regularisation to one covariance.
Eigen::MatrixXd regularize(const Eigen::MatrixXd& cov, const GmmOptions& o) {
  const bool diagonal = isDiagonal(o.form);
  const Eigen::Index d = cov.rows();
  if (diagonal) {
    Eigen::MatrixXd out = Eigen::MatrixXd::Zero(d, d);
    for (Eigen::Index j = 0; j < d; ++j)
      out(j, j) = o.reg == Regularization::Floor ? std::max(cov(j, j), o.varianceFloor)
                                                 : cov(j, j) + o.varianceFloor;
    return out;
  }
  if (o.reg == Regularization::Add) {
    Eigen::MatrixXd out = 0.5 * (cov + cov.transpose());
    out.diagonal().array() += o.varianceFloor;
    return out;
  }
  return clampEigenvalues(cov, o.varianceFloor);
}

std::string singularReason(int component, int k, const GmmOptions& o) {
  std::string who = isNodal(o.form)
                        ? "component " + std::to_string(component + 1) + " of " + std::to_string(k)
                        : "the shared (grand) covariance";
  return "covariance of " + who + " is singular with variance floor " +
         formatDouble(o.varianceFloor) + " (" + std::string(regularizationName(o.reg)) +
         "): duplicate or degenerate samples need a positive variance floor";
}

// What `add` may cost the log-likelihood of an EM step, in total nats, for a component of mass
// `mass` whose maximum-likelihood covariance is `raw`. With Q the EM auxiliary function,
// l(new) - l(old) >= Q(new) - Q(old) >= Q(new) - Q(ml) = -cost, and for Sigma = raw + eps I
// cost = mass/2 sum_j [log(1 + eps/lambda_j) - eps/(lambda_j + eps)] over the eigenvalues
// lambda_j of raw (its diagonal for diagonal forms). Infinite when raw is singular (no bound).
double addRegularizationCost(const Eigen::MatrixXd& raw, double mass, double eps, bool diagonal) {
  Eigen::VectorXd lambda;
  if (diagonal) {
    lambda = raw.diagonal();
  } else {
    const Eigen::MatrixXd sym = 0.5 * (raw + raw.transpose());
    Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> solver(sym, Eigen::EigenvaluesOnly);
    if (solver.info() != Eigen::Success) return std::numeric_limits<double>::infinity();
    lambda = solver.eigenvalues();
  }
  double sum = 0.0;
  for (Eigen::Index j = 0; j < lambda.size(); ++j) {
    if (!(lambda(j) > 0.0)) return std::numeric_limits<double>::infinity();
    const double u = eps / lambda(j);
    sum += std::log1p(u) - u / (1.0 + u);
  }
  return 0.5 * mass * sum;
}

// M-step from statistics accumulated around state.means. Components with mass below
// kMinComponentMass are dropped. Returns false with a reason if a covariance is singular.
bool mStep(const Stats& st, const EmState& old, const GmmOptions& o, EmState& next, int& dropped,
           std::string& reason) {
  const int k = static_cast<int>(old.weights.size());
  const int d = static_cast<int>(old.means.cols());
  const bool diagonal = isDiagonal(o.form);
  const bool nodal = isNodal(o.form);
  std::vector<int> kept;
  double mass = 0.0;
  for (int i = 0; i < k; ++i) {
    if (st.nk(i) >= kMinComponentMass && std::isfinite(st.nk(i))) {
      kept.push_back(i);
      mass += st.nk(i);
    }
  }
  if (kept.empty()) {
    reason = "every component lost its weight (no sample is explained by the model)";
    return false;
  }
  dropped += k - static_cast<int>(kept.size());
  const int kk = static_cast<int>(kept.size());
  next.weights.resize(kk);
  next.means.resize(kk, d);
  std::vector<Eigen::MatrixXd> raw(static_cast<std::size_t>(kk));
  for (int a = 0; a < kk; ++a) {
    const int i = kept[static_cast<std::size_t>(a)];
    const double ni = st.nk(i);
    next.weights(a) = ni / mass;
    const Eigen::VectorXd delta = st.s1.row(i).transpose() / ni;
    next.means.row(a) = old.means.row(i) + delta.transpose();
    Eigen::MatrixXd cov(d, d);
    if (diagonal) {
      cov.setZero();
      for (int j = 0; j < d; ++j)
        cov(j, j) = st.s2(i, j) / ni - delta(j) * delta(j);
    } else {
      const auto block = st.s2.middleCols(static_cast<Eigen::Index>(i) * d, d);
      for (int j = 0; j < d; ++j)
        for (int l = 0; l <= j; ++l) {
          cov(j, l) = block(j, l) / ni - delta(j) * delta(l);
          cov(l, j) = cov(j, l);
        }
    }
    raw[static_cast<std::size_t>(a)] = std::move(cov);
  }
  next.covs.clear();
  next.regularizationBound = 0.0;
  const bool add = o.reg == Regularization::Add && o.varianceFloor > 0.0;
  if (nodal) {
    for (int a = 0; a < kk; ++a) {
      const Eigen::MatrixXd& r = raw[static_cast<std::size_t>(a)];
      next.covs.push_back(regularize(r, o));
      if (add)
        next.regularizationBound += addRegularizationCost(
            r, st.nk(kept[static_cast<std::size_t>(a)]), o.varianceFloor, diagonal);
    }
  } else {
    Eigen::MatrixXd pooled = Eigen::MatrixXd::Zero(d, d);
    for (int a = 0; a < kk; ++a)
      pooled += next.weights(a) * raw[static_cast<std::size_t>(a)];
    next.covs.push_back(regularize(pooled, o));
    if (add)
      next.regularizationBound = addRegularizationCost(pooled, mass, o.varianceFloor, diagonal);
  }
  int bad = -1;
  if (!buildDensityCache(next.weights, next.means, next.covs, diagonal, nodal, next.cache, &bad)) {
    reason = singularReason(nodal ? kept[static_cast<std::size_t>(bad)] : 0, k, o);
    return false;
  }
  return true;
}

// Statistics of a hard assignment (one-hot responsibilities) around `centres`, per chunk of rows
// on `threads` threads, reduced in chunk order (the result does not depend on `threads`).
Stats hardAssignmentStats(const DataRef& x, const Eigen::MatrixXd& centres,
                          const std::vector<int>& assignment, bool diagonal, int threads) {
  const int k = static_cast<int>(centres.rows());
  const int d = static_cast<int>(x.cols());
  const Chunking ch = makeChunking(x.rows());
  std::vector<Stats> parts(static_cast<std::size_t>(ch.chunks));
  forEachChunk(ch.chunks, threads, [&](int c) {
    Stats& st = parts[static_cast<std::size_t>(c)];
    st.reset(k, d, diagonal, true);
    Eigen::VectorXd z(d);
    for (Eigen::Index r = ch.begin(c); r < ch.end(c); ++r) {
      const int a = assignment[static_cast<std::size_t>(r)];
      z = x.row(r).transpose() - centres.row(a).transpose();
      st.nk(a) += 1.0;
      st.s1.row(a) += z.transpose();
      if (diagonal) {
        st.s2.row(a) += z.array().square().matrix().transpose();
      } else {
        auto block = st.s2.middleCols(static_cast<Eigen::Index>(a) * d, d);
        for (int j = 0; j < d; ++j)
          for (int l = 0; l <= j; ++l)
            block(j, l) += z(j) * z(l);
      }
    }
  });
  Stats total;
  total.reset(k, d, diagonal, true);
  for (const Stats& st : parts)
    total.add(st, true);
  return total;
}

struct Attempt {
  bool ok = false;
  bool cancelled = false;
  bool fatal = false;  // an EM step lowered the log-likelihood: the whole fit fails
  std::string reason;
  EmState state;
  int iterations = 0;
  bool converged = false;
  double logLik = -std::numeric_limits<double>::infinity();  // total, final model
  int dropped = 0;
  int undoneIteration = 0;
  double likelihoodDrop = 0.0;
  std::vector<double> trace;
};

struct ProgressCounter {
  const ProgressFn* fn = nullptr;
  std::size_t done = 0;
  std::size_t total = 0;
  bool tick() {
    ++done;
    return !fn || !*fn || (*fn)(done, total);
  }
};

bool initialState(const DataRef& x, const GmmOptions& o, Rng& rng, int threads, EmState& state,
                  int& dropped, std::string& reason) {
  const Eigen::Index n = x.rows();
  const int d = static_cast<int>(x.cols());
  const int k = o.components;
  const bool diagonal = isDiagonal(o.form);
  if (o.init == GmmInit::KMeansPlusPlus) {
    Eigen::MatrixXd centres = kmeansPlusPlus(x, k, rng, threads);
    std::vector<int> assignment;
    if (o.kmeansIterations > 0)
      lloydIterations(x, centres, o.kmeansIterations, assignment, threads);
    else
      assignNearest(x, centres, assignment, threads);
    const Stats st = hardAssignmentStats(x, centres, assignment, diagonal, threads);
    EmState seed;
    seed.weights = Eigen::VectorXd::Constant(k, 1.0 / k);
    seed.means = centres;
    return mStep(st, seed, o, state, dropped, reason);
  }
  // Random rows as means (distinct indices while there are enough rows), equal weights, the data
  // covariance (biased, around the data mean, which is 0 in the centred frame) for every component.
  std::vector<Eigen::Index> index(static_cast<std::size_t>(n));
  for (Eigen::Index i = 0; i < n; ++i)
    index[static_cast<std::size_t>(i)] = i;
  state.means.resize(k, d);
  for (int i = 0; i < k; ++i) {
    const Eigen::Index slot = i % n;
    if (slot == 0 && i > 0) {
      // more components than rows: start a new round of the shuffle
    }
    const Eigen::Index pick =
        slot + static_cast<Eigen::Index>(rng.below(static_cast<std::uint64_t>(n - slot)));
    std::swap(index[static_cast<std::size_t>(slot)], index[static_cast<std::size_t>(pick)]);
    state.means.row(i) = x.row(index[static_cast<std::size_t>(slot)]);
  }
  state.weights = Eigen::VectorXd::Constant(k, 1.0 / k);
  const Eigen::RowVectorXd mean = x.colwise().mean();
  const Eigen::MatrixXd centred = x.rowwise() - mean;
  Eigen::MatrixXd cov = (centred.transpose() * centred) / static_cast<double>(n);
  if (diagonal) cov = Eigen::MatrixXd(cov.diagonal().asDiagonal());
  const Eigen::MatrixXd reg = regularize(cov, o);
  state.covs.assign(isNodal(o.form) ? static_cast<std::size_t>(k) : 1, reg);
  int bad = -1;
  if (!buildDensityCache(state.weights, state.means, state.covs, diagonal, isNodal(o.form),
                         state.cache, &bad)) {
    reason = "the data covariance is singular with variance floor " +
             formatDouble(o.varianceFloor) +
             ": duplicate or degenerate samples need a positive variance floor";
    return false;
  }
  return true;
}

bool hasConverged(double previous, double current, const GmmOptions& o) {
  const double change = std::abs(current - previous);
  if (o.rule == ConvergenceRule::Absolute) return change < o.tolerance;
  return change < o.tolerance * std::max(1.0, std::abs(current));
}

// A fall of the mean log-likelihood up to this much relative to max(1, |l|) is rounding.
constexpr double kRoundingFall = 1e-12;

enum class StepCheck { Accept, Undo, Fail };

// Judges an EM step by the mean log-likelihoods before (`before`) and after (`after`) it
// (docs/learning.md, "Monotone EM"). removed: the step removed empty components (a change of the
// model, not an EM step: exempt). addBound: for `add`, how far the step may lower it (per sample).
StepCheck checkStep(double before, double after, bool removed, double addBound) {
  if (!(after < before) || removed) return StepCheck::Accept;
  const double fall = before - after;
  const double rounding = kRoundingFall * std::max(1.0, std::abs(before));
  if (fall <= rounding + addBound) return StepCheck::Undo;
  return StepCheck::Fail;
}

std::string fallReason(int iteration, double before, double after, const GmmOptions& o) {
  std::string limit = "rounding";
  if (o.reg == Regularization::Add) limit += " and the bound of the add regularisation";
  return "the log-likelihood fell by " + formatDouble(before - after) +
         " nats per sample at EM iteration " + std::to_string(iteration) + " (from " +
         formatDouble(before) + " to " + formatDouble(after) + "), more than " + limit +
         ": EM must never lower it";
}

Attempt runEm(const DataRef& x, const GmmOptions& o, std::uint64_t seed, int threads,
              ProgressCounter& progress) {
  Attempt at;
  const Eigen::Index n = x.rows();
  const double nd = static_cast<double>(n);
  Rng rng(seed);
  if (!initialState(x, o, rng, threads, at.state, at.dropped, at.reason)) return at;
  const Chunking ch = makeChunking(n);
  std::vector<Stats> chunkStats;
  Stats total;
  EmState next;  // after a step: the parameters before it, to undo it
  // Mean and total log-likelihood of the parameters before the last M-step.
  double previous = -std::numeric_limits<double>::infinity();
  double previousTotal = previous;
  bool removed = false;  // the last M-step removed empty components
  // Every E-step's log-likelihood is checked against the one before it: EM with the floor clamp
  // never lowers it, so a fall beyond rounding is an error; with `add` a fall within the step's
  // bound is the method's own (its M-step does not maximise the likelihood) and ends the fit.
  // A fall that is not an error undoes the step: the model is the one before it.
  const auto judge = [&](int it, double current) {
    const StepCheck c = checkStep(previous, current, removed, at.state.regularizationBound / nd);
    if (c == StepCheck::Fail) {
      at.reason = fallReason(it, previous, current, o);
      at.fatal = true;
    } else if (c == StepCheck::Undo) {
      const double fall = previous - current;
      at.undoneIteration = it;
      at.likelihoodDrop = fall;
      at.converged = fall <= kRoundingFall * std::max(1.0, std::abs(previous)) ||
                     hasConverged(previous, current, o);
      std::swap(at.state, next);
      at.logLik = previousTotal;
    }
    return c;
  };
  bool undone = false;
  for (int it = 1; it <= o.maxIterations; ++it) {
    emPass(x, at.state, true, threads, ch, chunkStats, total);
    const double current = total.logLik / nd;
    if (!std::isfinite(current)) {
      at.reason = "the log-likelihood is not finite at iteration " + std::to_string(it) +
                  " (a sample lies where every component has zero density)";
      return at;
    }
    if (o.keepTrace) at.trace.push_back(current);
    if (it > 1) {
      const StepCheck c = judge(it, current);
      if (c == StepCheck::Fail) return at;
      if (c == StepCheck::Undo) {
        undone = true;
        break;
      }
    }
    const int droppedBefore = at.dropped;
    if (!mStep(total, at.state, o, next, at.dropped, at.reason)) return at;
    removed = at.dropped != droppedBefore;
    if (o.afterMStep) {
      o.afterMStep(it, next.weights, next.means, next.covs);
      int bad = -1;
      if (!buildDensityCache(next.weights, next.means, next.covs, isDiagonal(o.form),
                             isNodal(o.form), next.cache, &bad)) {
        at.reason = "the parameters changed after M-step " + std::to_string(it) + " are invalid";
        return at;
      }
    }
    std::swap(at.state, next);
    at.iterations = it;
    if (!progress.tick()) {
      at.cancelled = true;
      at.reason = "cancelled";
      return at;
    }
    const bool converged = it > 1 && hasConverged(previous, current, o);
    previous = current;
    previousTotal = total.logLik;
    if (converged) {
      at.converged = true;
      break;
    }
  }
  if (undone) {
    if (o.keepTrace) at.trace.push_back(at.logLik / nd);
    at.ok = true;
    return at;
  }
  // The returned parameters come from the last M-step: its step is checked like every other.
  emPass(x, at.state, false, threads, ch, chunkStats, total);
  if (!std::isfinite(total.logLik)) {
    at.reason = "the final log-likelihood is not finite";
    return at;
  }
  const double last = total.logLik / nd;
  if (o.keepTrace) at.trace.push_back(last);
  at.logLik = total.logLik;
  if (at.iterations >= 1) {
    const StepCheck c = judge(at.iterations + 1, last);
    if (c == StepCheck::Fail) return at;
    if (c == StepCheck::Undo && o.keepTrace) at.trace.push_back(at.logLik / nd);
  }
  at.ok = true;
  return at;
}

}  // namespace

GmmFit fitGmm(const Eigen::MatrixXd& samples, const GmmOptions& o, const ProgressFn& progress) {
  GmmFit fit;
  const Eigen::Index n = samples.rows();
  const Eigen::Index d = samples.cols();
  const auto fail = [&](std::string reason) {
    fit.ok = false;
    fit.reason = std::move(reason);
    return fit;
  };
  if (n < 1) return fail("no samples to fit");
  if (d < 1) return fail("samples have no features (dimension 0)");
  if (o.components < 1) return fail("the model order must be at least 1");
  if (!(o.varianceFloor >= 0.0) || !std::isfinite(o.varianceFloor))
    return fail("the variance floor must be finite and >= 0");
  if (o.varianceFloor > 0.0 && o.varianceFloor < kMinVarianceFloor) {
    return fail("the variance floor " + formatDouble(o.varianceFloor) +
                " is too small to hold: use 0 for no floor, or at least " +
                formatDouble(kMinVarianceFloor) + " (the smallest normal double)");
  }
  if (o.maxIterations < 1) return fail("the iteration limit must be at least 1");
  if (!(o.tolerance >= 0.0)) return fail("the tolerance must be >= 0");
  if (o.restarts < 1) return fail("restarts must be at least 1");
  if (!samples.allFinite()) return fail("the samples contain a non-finite value");

  int threads = o.threads > 0 ? o.threads
                              : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  if (n < kMinRowsForThreads) threads = 1;

  // Centre once on the column means: keeps common offsets out of every sum.
  const Eigen::RowVectorXd offset = samples.colwise().mean();
  // The centred copy has its columns padded with zero rows to a multiple of 8, so that with Eigen's
  // 64-byte aligned allocation every block of rows starts on a cache line (unaligned vector loads
  // cost about 30% of the E-step on AVX-512) and the last block needs no copy.
  const Eigen::Index paddedN = (n + 7) / 8 * 8;
  Eigen::MatrixXd centred(paddedN, d);
  centred.topRows(n) = samples.rowwise() - offset;
  centred.bottomRows(paddedN - n).setZero();
  const DataRef x = centred.topRows(n);

  const int reinitialisations =
      o.init == GmmInit::RandomFromData ? std::max(0, o.maxReinitialisations) : 0;
  ProgressCounter counter;
  counter.fn = &progress;
  counter.total = static_cast<std::size_t>(o.maxIterations) * static_cast<std::size_t>(o.restarts) *
                  static_cast<std::size_t>(1 + reinitialisations);

  Attempt best;
  std::string lastReason;
  for (int r = 0; r < o.restarts; ++r) {
    std::uint64_t stream = o.seed ^ (0xA0761D6478BD642FULL * static_cast<std::uint64_t>(r));
    Attempt bestOfRestart;
    for (int attempt = 0; attempt <= reinitialisations; ++attempt) {
      const std::uint64_t seed = splitMix64(stream);
      Attempt at = runEm(x, o, seed, threads, counter);
      fit.totalIterations += at.iterations;
      if (at.cancelled) return fail("cancelled");
      if (at.fatal) return fail(at.reason);
      if (!at.ok) {
        lastReason = at.reason;
        continue;
      }
      const bool converged = at.converged;
      if (!bestOfRestart.ok || at.logLik > bestOfRestart.logLik) bestOfRestart = std::move(at);
      if (converged) break;  // random-from-data: re-initialise only when not converged
    }
    if (bestOfRestart.ok && (!best.ok || bestOfRestart.logLik > best.logLik))
      best = std::move(bestOfRestart);
  }
  if (!best.ok) return fail(lastReason.empty() ? "the fit failed" : lastReason);

  Eigen::MatrixXd means = best.state.means.rowwise() + offset;
  auto model = GaussianMixture::create(best.state.weights, means, best.state.covs, o.form);
  if (!model) return fail("the fitted model is invalid: " + model.error().message);
  fit.model = std::move(model.value());
  fit.ok = true;
  fit.iterations = best.iterations;
  fit.converged = best.converged;
  fit.logLikelihood = best.logLik;
  fit.meanLogLikelihood = best.logLik / static_cast<double>(n);
  const double p = fit.model.parameterCount();
  fit.bic = -2.0 * best.logLik + p * std::log(static_cast<double>(n));
  fit.aic = -2.0 * best.logLik + 2.0 * p;
  fit.droppedComponents = best.dropped;
  fit.undoneIteration = best.undoneIteration;
  fit.likelihoodDrop = best.likelihoodDrop;
  fit.trace = std::move(best.trace);
  fit.warnings = varianceFloorWarnings(samples, o.varianceFloor);
  return fit;
}

}  // namespace tactile::analysis
