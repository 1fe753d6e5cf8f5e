// Kills a process that streams label edits (SIGKILL at an arbitrary moment) and checks that the
// database is intact and lost at most the edit in flight.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <random>
#include <set>

#include "storage_test_util.h"

namespace tactile::storage {
namespace {

// Starts the helper, lets it commit at least `minEdits` edits, kills it, and returns every edit
// number it reported as committed.
std::vector<long long> runAndKill(const std::filesystem::path& db, long long firstEdit,
                                  int minEdits) {
  int pipeFds[2];
  if (::pipe(pipeFds) != 0) return {};
  const pid_t pid = ::fork();
  if (pid == 0) {
    ::dup2(pipeFds[1], STDOUT_FILENO);
    ::close(pipeFds[0]);
    ::close(pipeFds[1]);
    const std::string first = std::to_string(firstEdit);
    ::execl(TACTILE_STORAGE_KILL_HELPER, TACTILE_STORAGE_KILL_HELPER, db.c_str(), first.c_str(),
            static_cast<char*>(nullptr));
    ::_exit(127);
  }
  ::close(pipeFds[1]);
  std::vector<long long> reported;
  std::string pending;
  char buffer[4096];
  bool killed = false;
  while (true) {
    const ssize_t n = ::read(pipeFds[0], buffer, sizeof buffer);
    if (n <= 0) break;
    pending.append(buffer, static_cast<std::size_t>(n));
    std::size_t newline = 0;
    while ((newline = pending.find('\n')) != std::string::npos) {
      reported.push_back(std::stoll(pending.substr(0, newline)));
      pending.erase(0, newline + 1);
    }
    if (!killed && static_cast<int>(reported.size()) >= minEdits) {
      ::kill(pid, SIGKILL);  // while it is inside its next edit, most likely mid-transaction
      killed = true;
    }
  }
  ::close(pipeFds[0]);
  int status = 0;
  ::waitpid(pid, &status, 0);
  EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL)
      << "helper was not killed (exit status " << status << ")";
  return reported;
}

TEST(KillTest, KilledWriterLosesAtMostTheEditInFlight) {
  test::TempDir dir;
  const auto path = dir / "kill.db";
  {
    auto db = test::openDb(path);
    ASSERT_NE(db, nullptr);
    ASSERT_EQ(db->runs().importRun(test::makeRun(5000, false), "victim").status,
              ImportStatus::Imported);
    ASSERT_TRUE(db->labels().create("kill").ok());
  }
  std::mt19937 rng(11);
  long long nextEdit = 0;
  for (int round = 0; round < 4; ++round) {
    SCOPED_TRACE("round " + std::to_string(round));
    const int minEdits = std::uniform_int_distribution<int>(20, 400)(rng);
    const std::vector<long long> reported = runAndKill(path, nextEdit, minEdits);
    ASSERT_GE(static_cast<int>(reported.size()), minEdits);
    const long long lastAcknowledged = reported.back();

    auto db = test::openDb(path);
    ASSERT_NE(db, nullptr);
    const IntegrityReport report = db->check();
    EXPECT_TRUE(report.ok) << (report.problems.empty() ? "" : report.problems[0]);
    auto set = db->labels().find("kill");
    ASSERT_TRUE(set.ok());
    const auto segments = db->labels().segments(set->id).value();
    std::set<long long> stored;
    for (const LabelSegment& s : segments) {
      stored.insert(s.firstStep * kGroupCount + groupIndex(s.group));
    }
    // Every acknowledged edit is there; beyond them at most the one in flight.
    for (long long edit = 0; edit <= lastAcknowledged; ++edit) {
      ASSERT_TRUE(stored.count(edit)) << "acknowledged edit " << edit << " was lost";
    }
    const long long total = static_cast<long long>(stored.size());
    EXPECT_GE(total, lastAcknowledged + 1);
    EXPECT_LE(total, lastAcknowledged + 2);
    EXPECT_EQ(*stored.rbegin(), total - 1);  // no gaps: edits are contiguous
    nextEdit = total;
  }
}

}  // namespace
}  // namespace tactile::storage
