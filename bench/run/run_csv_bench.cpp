// Run-file reading and writing throughput on a 100k-step synthetic run (about 70 MB of CSV).
#include <benchmark/benchmark.h>

#include <filesystem>

#include "base/file_text.h"
#include "run/run_csv.h"
#include "run/synthetic_run.h"

namespace {

constexpr std::size_t kSteps = 100000;

const tactile::RunData& sampleRun() {
  static const tactile::RunData run = tactile::makeSyntheticRun(kSteps, true, 42);
  return run;
}

const std::string& sampleText() {
  static const std::string text = tactile::formatRunCsv(sampleRun());
  return text;
}

void BM_ParseRunCsv(benchmark::State& state) {
  const std::string& text = sampleText();
  for (auto _ : state) {
    tactile::RunCsvResult result = tactile::parseRunCsv(text, "bench.csv");
    if (!result.ok()) state.SkipWithError(result.errorText().c_str());
    benchmark::DoNotOptimize(result);
  }
  state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations() * text.size()));
}
BENCHMARK(BM_ParseRunCsv)->Unit(benchmark::kMillisecond);

void BM_ReadRunCsvFile(benchmark::State& state) {
  const auto path = std::filesystem::temp_directory_path() / "tactile_bench_read.csv";
  if (const tactile::Status written = tactile::writeFileAtomically(path, sampleText()); !written) {
    state.SkipWithError(written.errorText().c_str());
    return;
  }
  for (auto _ : state) {
    tactile::RunCsvResult result = tactile::readRunCsv(path);
    if (!result.ok()) state.SkipWithError(result.errorText().c_str());
    benchmark::DoNotOptimize(result);
  }
  std::filesystem::remove(path);
  state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations() * sampleText().size()));
}
BENCHMARK(BM_ReadRunCsvFile)->Unit(benchmark::kMillisecond);

void BM_FormatRunCsv(benchmark::State& state) {
  std::size_t bytes = 0;
  for (auto _ : state) {
    std::string text = tactile::formatRunCsv(sampleRun());
    bytes = text.size();
    benchmark::DoNotOptimize(text);
  }
  state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations() * bytes));
}
BENCHMARK(BM_FormatRunCsv)->Unit(benchmark::kMillisecond);

void BM_WriteRunCsvFile(benchmark::State& state) {
  const auto path = std::filesystem::temp_directory_path() / "tactile_bench_write.csv";
  for (auto _ : state) {
    const tactile::Status written = tactile::writeRunCsv(sampleRun(), path);
    if (!written) state.SkipWithError(written.errorText().c_str());
  }
  std::filesystem::remove(path);
  state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations() * sampleText().size()));
}
BENCHMARK(BM_WriteRunCsvFile)->Unit(benchmark::kMillisecond);

}  // namespace
