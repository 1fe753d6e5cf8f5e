// Seeded mutation test: >= 100,000 mutated run files through the importer. No crash, and a run is
// either stored completely (equal to what the reader parsed) or not at all.
#include <gtest/gtest.h>

#include <random>

#include "run/run_csv.h"
#include "storage_test_util.h"

namespace tactile::storage {
namespace {

std::vector<std::string> seedTexts() {
  std::vector<std::string> texts;
  texts.push_back(formatRunCsv(test::makeRun(4, true, 1, 2)));
  RunData extra = test::makeRun(3, false, 2);
  extra.extraColumns = {"x_note"};
  extra.extraValues = {"a", "b", "c"};
  texts.push_back(formatRunCsv(extra));
  std::string crlf;
  for (char c : formatRunCsv(test::makeRun(3, true, 3))) {
    if (c == '\n') crlf += '\r';
    crlf += c;
  }
  texts.push_back(crlf);
  return texts;
}

std::string mutate(std::string text, std::mt19937_64& rng) {
  static const std::string kInteresting = ",\n\r-+e.0159#: xNaI\xEF";
  auto pick = [&](std::size_t n) {
    return std::uniform_int_distribution<std::size_t>(0, n - 1)(rng);
  };
  const int mutations = 1 + static_cast<int>(pick(3));
  for (int m = 0; m < mutations && !text.empty(); ++m) {
    const std::size_t at = pick(text.size());
    switch (pick(7)) {
      case 0:  // flip a bit
        text[at] = static_cast<char>(text[at] ^ (1 << pick(8)));
        break;
      case 1:  // insert an interesting character
        text.insert(at, 1, kInteresting[pick(kInteresting.size())]);
        break;
      case 2:  // delete a character
        text.erase(at, 1);
        break;
      case 3:  // replace with an interesting character
        text[at] = kInteresting[pick(kInteresting.size())];
        break;
      case 4:  // truncate
        text.resize(at);
        break;
      case 5: {  // duplicate a line
        const std::size_t begin =
            text.rfind('\n', at) == std::string::npos ? 0 : text.rfind('\n', at) + 1;
        const std::size_t end = text.find('\n', at);
        if (end != std::string::npos) text.insert(begin, text.substr(begin, end - begin + 1));
        break;
      }
      default: {  // delete a line
        const std::size_t begin =
            text.rfind('\n', at) == std::string::npos ? 0 : text.rfind('\n', at) + 1;
        const std::size_t end = text.find('\n', at);
        text.erase(begin, end == std::string::npos ? std::string::npos : end - begin + 1);
        break;
      }
    }
  }
  return text;
}

TEST(Mutation, HundredThousandMutatedFilesStoreAllOrNothing) {
  auto db = test::openDb(":memory:");
  ASSERT_NE(db, nullptr);
  const std::vector<std::string> seeds = seedTexts();
  std::mt19937_64 rng(20261122);
  constexpr int kFiles = 100000;
  int imported = 0;
  int failed = 0;
  for (int i = 0; i < kFiles; ++i) {
    const std::string text = mutate(seeds[static_cast<std::size_t>(i) % seeds.size()], rng);
    // Most files in one chunk; some cut into chunks of a few rows, some of a few bytes, so that
    // a bad row can come after steps that were already written.
    ImportOptions options;
    options.chunkBytes = i % 4 == 1 ? 700 : i % 4 == 3 ? 50 : 0;
    const ImportOutcome outcome = db->runs().importText(text, "m.csv", options);
    if (outcome.status == ImportStatus::Imported) {
      ++imported;
      // Stored completely: equal to what the reader makes of the same text.
      RunCsvResult parsed = parseRunCsv(text, "m.csv");
      ASSERT_TRUE(parsed.ok()) << "stored a file the reader rejects: " << i;
      auto loaded = db->runs().load(outcome.runId);
      ASSERT_TRUE(loaded.ok()) << loaded.errorText();
      ASSERT_TRUE(loaded.value() == parsed.value()) << "file " << i;
      ASSERT_TRUE(db->runs().remove(outcome.runId).ok());
    } else {
      ++failed;
      ASSERT_EQ(outcome.status, ImportStatus::Failed) << outcome.message;
      ASSERT_EQ(outcome.message.rfind("m.csv", 0), 0u) << outcome.message;
      // Stored not at all (foreign keys make orphan steps or truth rows impossible).
      auto runs = db->runs().list();
      ASSERT_TRUE(runs.ok());
      ASSERT_TRUE(runs->empty()) << "file " << i << " left a partial run";
    }
  }
  EXPECT_EQ(imported + failed, kFiles);
  EXPECT_GT(failed, kFiles / 2);  // the mutations do break most files
  EXPECT_GT(imported, 100);       // and some survive, so the store path is exercised too
  const IntegrityReport report = db->check();
  EXPECT_TRUE(report.ok) << (report.problems.empty() ? "" : report.problems[0]);
  EXPECT_EQ(report.steps, 0);
}

}  // namespace
}  // namespace tactile::storage
