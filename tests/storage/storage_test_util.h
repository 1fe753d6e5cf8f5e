// Shared helpers of the storage tests: deterministic runs, temporary folders, bit-exact compares.
#pragma once

#include <gtest/gtest.h>

#include <sqlite3.h>
#include <unistd.h>
#include <array>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>
#include <string>

#include "run/run.h"
#include "storage/run_database.h"
#include "tests/run_compare.h"

namespace tactile::storage::test {

// The bytes of a file, as they are on disk.
inline std::string readBytes(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// Runs SQL with the plain C API (as another program would).
inline void sqliteExec(const std::filesystem::path& path, const std::string& sql) {
  sqlite3* db = nullptr;
  ASSERT_EQ(sqlite3_open(path.c_str(), &db), SQLITE_OK);
  char* error = nullptr;
  const int rc = sqlite3_exec(db, sql.c_str(), nullptr, nullptr, &error);
  EXPECT_EQ(rc, SQLITE_OK) << (error != nullptr ? error : "");
  sqlite3_free(error);
  sqlite3_close(db);
}

// A run whose values need full double precision, mostly-zero sensors as in simulated runs, a
// -0.0 and piecewise-constant truth (segments of `truthRun` steps).
inline RunData makeRun(std::size_t steps, bool withTruth, unsigned seed = 1,
                       std::size_t truthRun = 7) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  RunData run;
  run.metadata = {{"format", "tactile-run 1"}, {"scene", "practice"},
                  {"subject", "sim"},          {"dt", "0.1"},
                  {"outcome", "success"},      {"operator", "test"}};
  run.reserve(steps, withTruth);
  std::array<double, kValuesPerStep> values{};
  std::array<ContactClass, kGroupCount> truth{};
  for (std::size_t i = 0; i < steps; ++i) {
    for (int s = 0; s < kSensorCount; ++s) {
      const bool touching = unit(rng) < 0.2;
      values[normalOffset(s)] = touching ? 5.0 * unit(rng) : 0.0;
      values[shearOffset(s)] = touching ? 10.0 * unit(rng) - 5.0 : 0.0;
    }
    for (int g = 0; g < kGroupCount; ++g) {
      truth[g] = static_cast<ContactClass>(((i / truthRun) + g) % kContactClassCount);
    }
    run.appendStep(1000 * unit(rng), i == 0 ? -0.0 : -1e-7 * unit(rng), 6.283 * unit(rng) - 3.14,
                   20 * unit(rng), unit(rng) - 0.5, (i % 17) == 3, values.data(),
                   withTruth ? truth.data() : nullptr);
  }
  return run;
}

using test_support::bitEqual;
using test_support::expectSameRun;

// A fresh temporary folder, removed with its contents at the end of the test.
class TempDir {
 public:
  TempDir() {
    std::random_device device;
    path_ = std::filesystem::temp_directory_path() /
            ("tactile-storage-test-" + std::to_string(::getpid()) + "-" + std::to_string(device()));
    std::filesystem::create_directories(path_);
  }
  ~TempDir() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  const std::filesystem::path& path() const { return path_; }
  std::filesystem::path operator/(const std::string& name) const { return path_ / name; }

 private:
  std::filesystem::path path_;
};

inline std::unique_ptr<RunDatabase> openDb(const std::filesystem::path& path) {
  auto db = RunDatabase::open(path);
  EXPECT_TRUE(db.ok()) << (db.ok() ? "" : db.errorText());
  return db.ok() ? std::move(db.value()) : nullptr;
}

}  // namespace tactile::storage::test
