// Google Benchmark programs of the run database: import of run text into a database file, window
// loads and whole-run summaries of a 1,000,000-step run. The end-to-end import comparison with the
// sqlite3 shell is `tactile bench storage` (see docs/bench-storage.md).
#include <benchmark/benchmark.h>
#include <unistd.h>

#include <filesystem>
#include <memory>
#include <random>

#include "run/run_csv.h"
#include "storage/run_database.h"
#include "storage/synthetic_run.h"

namespace tactile::storage {
namespace {

namespace fs = std::filesystem;

fs::path benchDir() {
  static const fs::path dir = [] {
    fs::path d =
        fs::temp_directory_path() / ("tactile-storage-bench-" + std::to_string(::getpid()));
    fs::create_directories(d);
    return d;
  }();
  return dir;
}

// One shared database holding a 1,000,000-step run, built on first use.
struct BigRun {
  std::unique_ptr<RunDatabase> db;
  std::int64_t runId = 0;
  std::int64_t steps = 1000000;
};

BigRun& bigRun() {
  static BigRun big = [] {
    BigRun b;
    b.db = std::move(RunDatabase::open(benchDir() / "big.db").value());
    const auto outcome = b.db->runs().importRun(makeSyntheticRun(b.steps, 7), "big");
    if (outcome.status != ImportStatus::Imported) std::abort();
    b.runId = outcome.runId;
    return b;
  }();
  return big;
}

void BM_ImportText(benchmark::State& state) {
  const auto steps = static_cast<std::size_t>(state.range(0));
  const std::string text = formatRunCsv(makeSyntheticRun(steps, 11));
  int round = 0;
  for (auto _ : state) {
    state.PauseTiming();
    const fs::path path = benchDir() / ("import-" + std::to_string(round) + ".db");
    auto db = std::move(RunDatabase::open(path).value());
    ImportOptions options;
    options.name = "r";
    state.ResumeTiming();
    const auto outcome = db->runs().importText(text, "run.csv", options);
    if (outcome.status != ImportStatus::Imported) state.SkipWithError(outcome.message.c_str());
    state.PauseTiming();
    db.reset();
    for (const char* suffix : {"", "-wal", "-shm"})
      fs::remove(path.string() + suffix);
    ++round;
    state.ResumeTiming();
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(steps));
  state.SetBytesProcessed(state.iterations() * static_cast<std::int64_t>(text.size()));
}
BENCHMARK(BM_ImportText)->Arg(100000)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_LoadWindow10k(benchmark::State& state) {
  BigRun& big = bigRun();
  std::mt19937_64 rng(1);
  std::uniform_int_distribution<std::int64_t> pick(0, big.steps - 10000);
  for (auto _ : state) {
    auto window = big.db->runs().loadWindow(big.runId, pick(rng), 10000);
    if (!window || window->data.stepCount() != 10000) state.SkipWithError("window failed");
    benchmark::DoNotOptimize(window);
  }
  state.SetItemsProcessed(state.iterations() * 10000);
}
BENCHMARK(BM_LoadWindow10k)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_SummaryWholeRun(benchmark::State& state) {
  BigRun& big = bigRun();
  const int buckets = static_cast<int>(state.range(0));
  for (auto _ : state) {
    auto summary = big.db->runs().loadSummary(big.runId, 0, -1, buckets);
    if (!summary || summary->buckets.empty()) state.SkipWithError("summary failed");
    benchmark::DoNotOptimize(summary);
  }
}
BENCHMARK(BM_SummaryWholeRun)->Arg(2000)->Arg(200)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_SummaryNarrowRange(benchmark::State& state) {
  BigRun& big = bigRun();
  const std::int64_t length = state.range(0);
  std::mt19937_64 rng(2);
  std::uniform_int_distribution<std::int64_t> pick(0, big.steps - length);
  for (auto _ : state) {
    const std::int64_t first = pick(rng);
    auto summary = big.db->runs().loadSummary(big.runId, first, first + length - 1, 2000);
    if (!summary) state.SkipWithError("summary failed");
    benchmark::DoNotOptimize(summary);
  }
}
BENCHMARK(BM_SummaryNarrowRange)
    ->Arg(20000)
    ->Arg(60000)
    ->Arg(200000)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

}  // namespace
}  // namespace tactile::storage

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  std::error_code ec;
  std::filesystem::remove_all(tactile::storage::benchDir(), ec);
  return 0;
}
