// Shared helpers of the storage tests: deterministic runs, temporary folders, bit-exact compares.
#pragma once

#include <gtest/gtest.h>

#include <libpq-fe.h>
#include <sqlite3.h>
#include <unistd.h>
#include <array>
#include <atomic>
#include <cstdlib>
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

// ---- the same tests on both backends ------------------------------------------------------------

enum class Backend { Sqlite, Postgres };

inline void PrintTo(Backend backend, std::ostream* out) {
  *out << (backend == Backend::Sqlite ? "Sqlite" : "Postgres");
}

inline std::string backendName(const ::testing::TestParamInfo<Backend>& info) {
  return info.param == Backend::Sqlite ? "Sqlite" : "Postgres";
}

// The test server's address (tests/support/pg_cluster.sh writes it to the file named by
// TACTILE_TEST_PG_FILE; ctest starts and stops that server), or empty when none was started.
inline std::string testServerAddress() {
  const char* file = std::getenv("TACTILE_TEST_PG_FILE");
  if (file == nullptr || *file == '\0') return {};
  std::ifstream in(file);
  std::string address;
  std::getline(in, address);
  return address;
}

// Runs SQL on the test server as its superuser. Fails the test on an error.
inline void serverExec(const std::string& address, const std::string& sql) {
  PGconn* conn = PQconnectdb(address.c_str());
  ASSERT_EQ(PQstatus(conn), CONNECTION_OK) << PQerrorMessage(conn);
  PGresult* result = PQexec(conn, sql.c_str());
  const ExecStatusType status = PQresultStatus(result);
  EXPECT_TRUE(status == PGRES_COMMAND_OK || status == PGRES_TUPLES_OK)
      << PQresultErrorMessage(result) << " in: " << sql;
  PQclear(result);
  PQfinish(conn);
}

// A new, empty PostgreSQL schema on the test server and the address that works in it (its name
// first on the search path), or empty when no server runs.
inline std::string freshServerSchema() {
  const std::string server = testServerAddress();
  if (server.empty()) return {};
  static std::atomic<int> counter{0};
  std::random_device device;
  const std::string schema = "t" + std::to_string(::getpid()) + "_" +
                             std::to_string(device() % 100000) + "_" + std::to_string(++counter);
  serverExec(server, "CREATE SCHEMA " + schema);
  return server + "&options=-csearch_path%3D" + schema;
}

// Where a test's database lives: a file in `dir` for SQLite, a fresh schema on the test server for
// PostgreSQL (empty when no server runs: the test skips itself).
inline std::string databaseAddress(Backend backend, const TempDir& dir, const std::string& file) {
  if (backend == Backend::Sqlite) return (dir.path() / file).string();
  return freshServerSchema();
}

}  // namespace tactile::storage::test
