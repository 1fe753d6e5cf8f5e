// EM throughput on the `tactile bench learn` data set (one class, D = 10): a fixed number of EM
// iterations per fit (tolerance 0), so the time per iteration can be read off directly.
//   build/bench/analysis/tactile_gmm_bench --benchmark_filter=EmIterations
#include <benchmark/benchmark.h>

#include "analysis/gmm.h"
#include "analysis/gmm_synthetic.h"
#include "analysis/kmeans.h"

namespace tactile {
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

}  // namespace
}  // namespace tactile

BENCHMARK_MAIN();
