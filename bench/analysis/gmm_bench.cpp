// EM throughput on the `tactile bench learn` data set (one class, D = 10): a fixed number of EM
// iterations per fit (tolerance 0), so the time per iteration can be read off directly.
//   build/bench/analysis/tactile_gmm_bench --benchmark_filter=EmIterations
#include <benchmark/benchmark.h>

#include <random>

#include "analysis/gmm.h"
#include "analysis/gmm_synthetic.h"
#include "analysis/kmeans.h"

namespace tactile::analysis {
namespace {

const Eigen::MatrixXd& data() {
  static const Eigen::MatrixXd x = [] {
    SyntheticTableSpec spec;
    spec.classes = 1;
    spec.rows = 100000;
    return makeSyntheticTable(spec).features;
  }();
  return x;
}

// Args: form index (kAllCovarianceForms), components, threads. 10 EM iterations per fit.
void EmIterations(benchmark::State& state) {
  GmmOptions o;
  o.form = kAllCovarianceForms[state.range(0)];
  o.components = static_cast<int>(state.range(1));
  o.threads = static_cast<int>(state.range(2));
  o.reg = Regularization::Add;
  o.varianceFloor = 0.01;
  o.tolerance = 0.0;
  o.maxIterations = 10;
  o.kmeansIterations = 0;
  for (auto _ : state) {
    GmmFit fit = fitGmm(data(), o);
    benchmark::DoNotOptimize(fit.logLikelihood);
    if (!fit.ok) state.SkipWithError(fit.reason.c_str());
  }
  state.SetLabel(std::string(covarianceFormName(o.form)));
}
BENCHMARK(EmIterations)
    ->ArgsProduct({{0, 1}, {16, 64}, {1, 2}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

void KMeansInit(benchmark::State& state) {
  const int k = static_cast<int>(state.range(0));
  for (auto _ : state) {
    Rng rng(1);
    Eigen::MatrixXd c = kmeansPlusPlus(data(), k, rng);
    std::vector<int> a;
    lloydIterations(data(), c, static_cast<int>(state.range(1)), a);
    benchmark::DoNotOptimize(c.data());
  }
}
BENCHMARK(KMeansInit)->ArgsProduct({{16, 64}, {0, 10}})->Unit(benchmark::kMillisecond);

// One E-step pass (component log-densities and log-sum-exp, no statistics) over the 100k x 10
// data, one thread, blocks of 256 rows. Args: diagonal (1) or full (0), components. The GFLOPS
// counter counts, per row and component, the arithmetic the kernels execute: diagonal 4D + 2
// (subtract, scale, square-accumulate, constant), full D^2 + 3D + 2 (subtract, the triangular
// product, square-accumulate, constant), and 35 for the log-sum-exp (max, shift, the degree-13
// polynomial as 26, reduction and scaling 6, sum). Compare with the core's peak: 16 flops per
// cycle (two 4-wide FMA pipes) times the clock.
void EStepPass(benchmark::State& state) {
  const bool diagonal = state.range(0) == 1;
  const int k = static_cast<int>(state.range(1));
  const Eigen::MatrixXd& all = data();
  const Eigen::Index n = all.rows() / 256 * 256;
  const int d = static_cast<int>(all.cols());
  const Eigen::MatrixXd x = all.topRows(n).rowwise() - all.colwise().mean();
  Eigen::VectorXd w = Eigen::VectorXd::Constant(k, 1.0 / k);
  Eigen::MatrixXd means(k, d);
  for (int i = 0; i < k; ++i)
    means.row(i) = x.row(static_cast<Eigen::Index>(i) * 997 % n);
  Eigen::MatrixXd cov = (x.transpose() * x) / static_cast<double>(n);
  if (diagonal) cov = Eigen::MatrixXd(cov.diagonal().asDiagonal());
  std::vector<Eigen::MatrixXd> covs(static_cast<std::size_t>(k), cov);
  GmmDensityCache cache;
  int bad = -1;
  if (!buildDensityCache(w, means, covs, diagonal, true, cache, &bad)) {
    state.SkipWithError("covariance not positive definite");
    return;
  }
  Eigen::VectorXd logp(256 * k), lse(256), scratch(512);
  double total = 0.0;
  for (auto _ : state) {
    for (Eigen::Index start = 0; start < n; start += 256) {
      blockComponentLogDensities(cache, x.data() + start, n, 256, logp.data(), 256);
      blockLogSumExp(logp.data(), 256, 256, k, lse.data(), nullptr, scratch.data());
      total += lse.sum();
    }
  }
  benchmark::DoNotOptimize(total);
  const double perCell = (diagonal ? 4.0 * d + 2 : 1.0 * d * d + 3.0 * d + 2) + 35.0;
  state.counters["GFLOPS"] = benchmark::Counter(
      perCell * static_cast<double>(n) * k * static_cast<double>(state.iterations()) * 1e-9,
      benchmark::Counter::kIsRate);
  state.SetLabel(diagonal ? "diagonal" : "full");
}
BENCHMARK(EStepPass)->ArgsProduct({{1, 0}, {16, 64}})->Unit(benchmark::kMillisecond);

// Component log-densities of full-covariance mixtures at the dimensions of the context features
// (12 for a corner, 30 for the front, 36 for a side): 65,536 rows, one thread. Args: dimension,
// components. The counter counts what the kernel executes per row and component: D^2 + 3D + 2.
void FullDensities(benchmark::State& state) {
  const int d = static_cast<int>(state.range(0));
  const int k = static_cast<int>(state.range(1));
  constexpr Eigen::Index n = 65536;
  std::mt19937_64 rng(5);
  std::normal_distribution<double> normal;
  Eigen::MatrixXd x(n, d);
  for (Eigen::Index i = 0; i < x.size(); ++i)
    x.data()[i] = normal(rng);
  Eigen::VectorXd w = Eigen::VectorXd::Constant(k, 1.0 / k);
  Eigen::MatrixXd means(k, d);
  std::vector<Eigen::MatrixXd> covs;
  for (int i = 0; i < k; ++i) {
    means.row(i) = x.row(i * 101);
    Eigen::MatrixXd a(d, d);
    for (Eigen::Index j = 0; j < a.size(); ++j)
      a.data()[j] = normal(rng);
    covs.push_back(a * a.transpose() / d + Eigen::MatrixXd::Identity(d, d));
  }
  GmmDensityCache cache;
  int bad = -1;
  if (!buildDensityCache(w, means, covs, false, true, cache, &bad)) {
    state.SkipWithError("covariance not positive definite");
    return;
  }
  Eigen::VectorXd logp(256 * k);
  double total = 0.0;
  for (auto _ : state) {
    for (Eigen::Index start = 0; start < n; start += 256) {
      blockComponentLogDensities(cache, x.data() + start, n, 256, logp.data(), 256);
      total += logp[0];
    }
  }
  benchmark::DoNotOptimize(total);
  const double perCell = 1.0 * d * d + 3.0 * d + 2;
  state.counters["GFLOPS"] = benchmark::Counter(
      perCell * static_cast<double>(n) * k * static_cast<double>(state.iterations()) * 1e-9,
      benchmark::Counter::kIsRate);
}
BENCHMARK(FullDensities)
    ->Args({12, 8})
    ->Args({30, 16})
    ->Args({36, 8})
    ->Unit(benchmark::kMillisecond)
    ->MeasureProcessCPUTime();

}  // namespace
}  // namespace tactile::analysis

BENCHMARK_MAIN();
