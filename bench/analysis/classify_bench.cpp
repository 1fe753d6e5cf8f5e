// Classifying a 1,000,000-step run with a model bundle, per decision mode: the per-step argmax
// (what `tactile classify` did before models had transitions: the baseline), the online decision
// (HMM forward filter, the models' default) and the offline one (forward-backward). Target: the
// online decision under 2 s on one core. Run it on one core: `taskset -c 0`, and the evaluation
// uses one thread (classifier threads are 1 in trained models' classifyRun path).
//
// Data: a synthetic run (tests/analysis/learn_test_data.h: every group in contact 75% of the
// steps, three contact classes); the bundle is trained with the product's default settings per
// group (order, covariance, floor, features) on 30,000 steps of another draw.
#include <benchmark/benchmark.h>

#include "analysis/classify_run.h"
#include "analysis/training.h"
#include "tests/analysis/learn_test_data.h"

namespace {

using namespace tactile;
using namespace tactile::analysis;

struct BenchData {
  RunData train;
  RunData run;
  RunData sparse;  // the same length, 15% of the steps in contact per group
  ModelBundle bundle;
  // The same settings with the motion features in every group (the synthetic run's commands move
  // the domes 0.1 units a step: every lag walks back the whole kMotionLagCap steps, the worst
  // case).
  ModelBundle motion;
  // Boosted trees in every group (100 trees, depth 6), each group's own features.
  ModelBundle trees;
};

// Never destroyed: XGBoost keeps per-thread state that the main thread's exit tears down before
// objects of static duration, so freeing a booster from a static destructor frees it twice.
const BenchData& benchData() {
  static const BenchData& d = *new BenchData([] {
    BenchData b;
    b.train = testdata::makeLabelledRun(30000, 7, 0.3);
    b.run = testdata::makeLabelledRun(1000000, 8, 0.3);
    b.sparse = testdata::makeLabelledRun(1000000, 9, 0.3, 0.15);
    TrainJob job;
    job.runs = {{&b.train, labelsFromTruth(b.train)}};
    job.settings = defaultGroupSettings();
    for (TrainSettings& s : job.settings.byGroup)
      s.classifier.gmm.restarts = 1;
    auto out = trainAndEvaluate(job);
    if (out) b.bundle = std::move(out->bundle);
    for (TrainSettings& s : job.settings.byGroup)
      s.features = FeatureKind::Motion;
    auto motion = trainAndEvaluate(job);
    if (motion) b.motion = std::move(motion->bundle);
    job.settings = defaultGroupSettings();
    for (const GroupInfo& info : kSensorGroups) {
      TrainSettings& s = job.settings.of(info.group);
      s.classifier.method = ClassifierMethod::Gbt;
      s.features = defaultFeatures(info.group, ClassifierMethod::Gbt);
      s.emissionWeight = defaultEmissionWeight(info.group, ClassifierMethod::Gbt);
    }
    auto trees = trainAndEvaluate(job);
    if (trees) b.trees = std::move(trees->bundle);
    return b;
  }());
  return d;
}

void classify(benchmark::State& state, const RunData& run, const ModelBundle& bundle) {
  ClassifyOptions options;
  options.decision = static_cast<DecisionMode>(state.range(0));
  std::size_t contact = 0;
  for (auto _ : state) {
    const RunClassification r = classifyRun(run, bundle, options);
    benchmark::DoNotOptimize(r.groups.data());
    contact = 0;
    for (const GroupClassification& g : r.groups)
      for (std::uint8_t z : g.noContactRule)
        contact += z == 0 ? 1 : 0;
  }
  state.SetLabel(std::string(decisionModeName(options.decision.value())));
  state.counters["steps"] = static_cast<double>(run.stepCount());
  state.counters["group_contact_steps"] = static_cast<double>(contact);
  state.counters["models"] = static_cast<double>(bundle.models.size());
}
void BM_ClassifyRun(benchmark::State& state) {
  classify(state, benchData().run, benchData().bundle);
}
// A run in which each group touches in 15% of the steps (a simulated wall-following run: 5-20%).
void BM_ClassifyRunSparse(benchmark::State& state) {
  classify(state, benchData().sparse, benchData().bundle);
}
// The sparse run with the motion features in every group.
void BM_ClassifyRunSparseMotion(benchmark::State& state) {
  classify(state, benchData().sparse, benchData().motion);
}
// The sparse run with boosted trees in every group.
void BM_ClassifyRunSparseTrees(benchmark::State& state) {
  classify(state, benchData().sparse, benchData().trees);
}
// Every case: one timed pass per repetition, three repetitions, the process's CPU time.
void onePassThreeTimes(benchmark::internal::Benchmark* b) {
  b->Unit(benchmark::kSecond)
      ->Iterations(1)
      ->Repetitions(3)
      ->MeasureProcessCPUTime()
      ->UseRealTime();
}
BENCHMARK(BM_ClassifyRun)
    ->Arg(static_cast<int>(DecisionMode::Step))
    ->Arg(static_cast<int>(DecisionMode::Online))
    ->Arg(static_cast<int>(DecisionMode::Offline))
    ->Apply(onePassThreeTimes);
BENCHMARK(BM_ClassifyRunSparse)
    ->Arg(static_cast<int>(DecisionMode::Step))
    ->Arg(static_cast<int>(DecisionMode::Online))
    ->Apply(onePassThreeTimes);
BENCHMARK(BM_ClassifyRunSparseTrees)
    ->Arg(static_cast<int>(DecisionMode::Step))
    ->Arg(static_cast<int>(DecisionMode::Online))
    ->Apply(onePassThreeTimes);
BENCHMARK(BM_ClassifyRunSparseMotion)
    ->Arg(static_cast<int>(DecisionMode::Online))
    ->Apply(onePassThreeTimes);

}  // namespace

BENCHMARK_MAIN();
