// Full default sweep (8 groups x 7 orders x 4 covariance forms x 3 floors = 672 cells) on 100k
// labelled steps, on all cores, and a sweep of boosted trees' settings on the same steps. Target:
// each under 1 minute on 2 cores.
//
// Data: 10 synthetic runs of 10,000 steps (tests/analysis/learn_test_data.h), sensor noise 0.5,
// each group in contact for the given percentage of steps (argument); the last 30% of each run is
// held out for scoring, as `tactile sweep` does by default.
#include <benchmark/benchmark.h>

#include <deque>
#include <map>
#include <thread>

#include "analysis/sweep.h"
#include "analysis/training.h"
#include "tests/analysis/learn_test_data.h"

namespace {

using namespace tactile;
using namespace tactile::analysis;

struct BenchData {
  std::deque<RunData> runs;
  std::vector<LabelledRun> train, test;
};

const BenchData& benchData(int contactPercent) {
  static std::map<int, BenchData> cache;
  auto it = cache.find(contactPercent);
  if (it != cache.end()) return it->second;
  BenchData& d = cache[contactPercent];
  std::vector<LabelledRun> all;
  for (int r = 0; r < 10; ++r) {
    d.runs.push_back(testdata::makeLabelledRun(10000, 100 + static_cast<std::uint64_t>(r), 0.5,
                                               contactPercent / 100.0));
    all.push_back({&d.runs.back(), labelsFromTruth(d.runs.back())});
  }
  splitLabelledRuns(all, 0.3, d.train, d.test);
  return d;
}

void BM_FullDefaultSweep(benchmark::State& state) {
  const BenchData& data = benchData(static_cast<int>(state.range(0)));
  SweepOptions options;
  options.threads = 0;  // all cores
  SweepResult result;
  for (auto _ : state) {
    result = runSweep(data.train, data.test, SweepGrid{}, options);
    benchmark::DoNotOptimize(result.cells.data());
  }
  std::size_t ok = 0, trainRows = 0;
  double fitSeconds = 0.0;
  for (const SweepCellResult& c : result.cells) {
    ok += c.ok ? 1 : 0;
    fitSeconds += c.fitSeconds;
  }
  for (const SweepDataSummary& s : result.data)
    trainRows += s.trainRows;
  state.counters["cells"] = static_cast<double>(result.cells.size());
  state.counters["fitted"] = static_cast<double>(ok);
  state.counters["threads"] = result.threads;
  state.counters["train_rows_all_groups"] = static_cast<double>(trainRows);
  state.counters["sum_fit_s"] = fitSeconds;
  state.counters["extract_s"] = result.extractSeconds;
}
BENCHMARK(BM_FullDefaultSweep)
    ->Arg(30)
    ->Arg(75)
    ->Unit(benchmark::kSecond)
    ->Iterations(1)
    ->Repetitions(3)
    ->ReportAggregatesOnly(false)
    ->MeasureProcessCPUTime()
    ->UseRealTime();

// Runs `grid` on all cores over the data of state.range(0) % contact, with its counters: cells,
// fitted cells, threads, and the summed fit seconds of the step cells (one per fit).
void sweepGrid(benchmark::State& state, const SweepGrid& grid) {
  const BenchData& data = benchData(static_cast<int>(state.range(0)));
  SweepOptions options;
  options.threads = 0;  // all cores
  SweepResult result;
  for (auto _ : state) {
    result = runSweep(data.train, data.test, grid, options);
    benchmark::DoNotOptimize(result.cells.data());
  }
  std::size_t ok = 0;
  double fitSeconds = 0.0;
  for (const SweepCellResult& c : result.cells) {
    ok += c.ok ? 1 : 0;
    fitSeconds += c.cell.decision == DecisionMode::Step ? c.fitSeconds : 0.0;
  }
  state.counters["cells"] = static_cast<double>(result.cells.size());
  state.counters["fitted"] = static_cast<double>(ok);
  state.counters["threads"] = result.threads;
  state.counters["sum_fit_s"] = fitSeconds;
}

// The same full default sweep scoring every decision mode (step, online, offline): cells that
// differ only in the decision share one fit, so this is 672 fits scored three ways (2,016 cells).
// Target: under 1 minute on 2 cores.
void BM_FullDefaultSweepWithDecisions(benchmark::State& state) {
  SweepGrid grid;
  grid.decisions = {DecisionMode::Step, DecisionMode::Online, DecisionMode::Offline};
  sweepGrid(state, grid);
}
BENCHMARK(BM_FullDefaultSweepWithDecisions)
    ->Arg(30)
    ->Unit(benchmark::kSecond)
    ->Iterations(1)
    ->Repetitions(3)
    ->ReportAggregatesOnly(false)
    ->MeasureProcessCPUTime()
    ->UseRealTime();

// Boosted trees: 8 groups x 3 tree counts x 3 depths (72 fits, learning rate 0.1, min child weight
// 1) on the same 100k steps, scored step, online and offline (216 cells). Target: under 1 minute on
// 2 cores.
void BM_TreeSweep(benchmark::State& state) {
  SweepGrid grid;
  grid.methods = {ClassifierMethod::Gbt};
  grid.treeCounts = {50, 100, 200};
  grid.depths = {4, 6, 8};
  grid.decisions = {DecisionMode::Step, DecisionMode::Online, DecisionMode::Offline};
  sweepGrid(state, grid);
}
BENCHMARK(BM_TreeSweep)
    ->Arg(30)
    ->Unit(benchmark::kSecond)
    ->Iterations(1)
    ->Repetitions(3)
    ->ReportAggregatesOnly(false)
    ->MeasureProcessCPUTime()
    ->UseRealTime();

// The shared data extraction alone (8 groups, train and test sets).
void BM_SweepDataExtraction(benchmark::State& state) {
  const BenchData& data = benchData(30);
  for (auto _ : state) {
    for (const GroupInfo& g : kSensorGroups) {
      GroupDataSet a = buildGroupDataSet(data.train, g.group, FeatureKind::Normal);
      benchmark::DoNotOptimize(a.x.data());
    }
  }
}
BENCHMARK(BM_SweepDataExtraction)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
