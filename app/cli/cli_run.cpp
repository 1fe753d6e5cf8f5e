// Run-file verbs: bench io.
#include <unistd.h>
#include <algorithm>
#include <chrono>
#include <ctime>
#include <filesystem>
#include <iostream>
#include <nlohmann/json.hpp>
#include <vector>

#include "app/cli/cli_common.h"
#include "run/json_text.h"
#include "run/run_csv.h"
#include "run/synthetic_run.h"

namespace tactile::cli {
namespace {

struct Timing {
  double wallSeconds;
  double cpuSeconds;
};

template <typename Fn>
Timing timeOnce(Fn&& fn) {
  const auto wall0 = std::chrono::steady_clock::now();
  const std::clock_t cpu0 = std::clock();
  fn();
  const std::clock_t cpu1 = std::clock();
  const auto wall1 = std::chrono::steady_clock::now();
  return {std::chrono::duration<double>(wall1 - wall0).count(),
          static_cast<double>(cpu1 - cpu0) / CLOCKS_PER_SEC};
}

double median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

int benchIo(std::size_t steps, int repeats, bool json) {
  if (steps == 0 || repeats <= 0) throw UsageError("--steps and --repeats must be positive");
  const RunData run = makeSyntheticRun(steps, true, 42);
  const std::string text = formatRunCsv(run);
  const auto path = std::filesystem::temp_directory_path() /
                    ("tactile_bench_io_" + std::to_string(::getpid()) + ".csv");
  std::vector<double> parseWall, parseCpu, formatWall, formatCpu, writeWall, readWall;
  for (int r = 0; r < repeats; ++r) {
    Timing t = timeOnce([&] {
      RunCsvResult result = parseRunCsv(text, "bench.csv");
      if (!result.ok()) throw std::runtime_error(result.errorText());
    });
    parseWall.push_back(t.wallSeconds);
    parseCpu.push_back(t.cpuSeconds);
    t = timeOnce([&] {
      std::string out = formatRunCsv(run);
      if (out.size() != text.size()) throw std::runtime_error("format is not deterministic");
    });
    formatWall.push_back(t.wallSeconds);
    formatCpu.push_back(t.cpuSeconds);
    t = timeOnce([&] {
      const Status written = writeRunCsv(run, path);
      if (!written) throw std::runtime_error(written.errorText());
    });
    writeWall.push_back(t.wallSeconds);
    t = timeOnce([&] {
      RunCsvResult result = readRunCsv(path);
      if (!result.ok()) throw std::runtime_error(result.errorText());
    });
    readWall.push_back(t.wallSeconds);
  }
  std::filesystem::remove(path);
  const double mb = static_cast<double>(text.size()) / 1e6;
  nlohmann::json out = {{"steps", steps},
                        {"bytes", text.size()},
                        {"repeats", repeats},
                        {"parse_mb_s_cpu", mb / median(parseCpu)},
                        {"parse_mb_s_wall", mb / median(parseWall)},
                        {"read_file_mb_s_wall", mb / median(readWall)},
                        {"format_mb_s_cpu", mb / median(formatCpu)},
                        {"format_mb_s_wall", mb / median(formatWall)},
                        {"write_file_mb_s_wall", mb / median(writeWall)}};
  if (json) {
    std::cout << dumpJson(out) << '\n';
    return kExitOk;
  }
  std::printf("run file: %zu steps, %.1f MB of CSV, median of %d repeats\n", steps, mb, repeats);
  std::printf("  %-22s %10s %10s\n", "operation", "MB/s cpu", "MB/s wall");
  std::printf("  %-22s %10.0f %10.0f\n", "parse (in memory)", out["parse_mb_s_cpu"].get<double>(),
              out["parse_mb_s_wall"].get<double>());
  std::printf("  %-22s %10s %10.0f\n", "read file", "", out["read_file_mb_s_wall"].get<double>());
  std::printf("  %-22s %10.0f %10.0f\n", "format (in memory)", out["format_mb_s_cpu"].get<double>(),
              out["format_mb_s_wall"].get<double>());
  std::printf("  %-22s %10s %10.0f\n", "write file", "", out["write_file_mb_s_wall"].get<double>());
  return kExitOk;
}

}  // namespace

void registerRunVerbs(CLI::App& /*app*/, CLI::App& bench) {
  CLI::App* io = bench.add_subcommand("io", "Run-file reading and writing speed (MB/s of CSV)");
  auto steps = std::make_shared<std::size_t>(100000);
  auto repeats = std::make_shared<int>(5);
  auto json = std::make_shared<bool>(false);
  io->add_option("--steps", *steps, "Steps in the synthetic run")->capture_default_str();
  io->add_option("--repeats", *repeats, "Repetitions; medians are reported")->capture_default_str();
  io->add_flag("--json", *json, "Print one JSON object");
  setAction(io, [=] { return benchIo(*steps, *repeats, *json); });
}

}  // namespace tactile::cli
