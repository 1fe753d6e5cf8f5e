// A repeated column is refused wherever it stands: the first column, the last one, and a name that
// first appears at the start of the header and again at its end. Written against the behaviour
// (refusal on the header line, a message naming the column), not against how the reader finds
// duplicates. A reader that forgot the first position (a check `> 0` for `>= 0`) accepted such a
// file and let the second column's values win.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "run/run_csv.h"
#include "run/sensor_layout.h"

namespace tactile {
namespace {
namespace run_csv_duplicate {  // its own names in a unity build

// A hand-written file of `rows` steps with the given header; every row carries the same values,
// chosen per column so that a repeated column's two copies differ.
struct HandFile {
  std::vector<std::string> columns;
  std::string text(std::size_t rows = 2) const {
    std::string out;
    for (std::size_t c = 0; c < columns.size(); ++c)
      out += (c > 0 ? "," : "") + columns[c];
    out += "\n";
    for (std::size_t r = 0; r < rows; ++r) {
      std::vector<std::string> seen;
      for (std::size_t c = 0; c < columns.size(); ++c) {
        const std::string& name = columns[c];
        bool repeat = false;
        for (const std::string& s : seen)
          repeat = repeat || s == name;
        seen.push_back(name);
        std::string value;
        if (name == "step") {
          value = std::to_string(r + (repeat ? 100 : 0));
        } else if (name == "blocked") {
          value = repeat ? "1" : "0";
        } else if ((name[0] == 'n' || name[0] == 's') && name.size() > 1 && name[1] >= '0' &&
                   name[1] <= '9') {
          value = repeat ? "2.5" : "1.25";  // sensor values lie in [0, 5]
        } else {
          value = std::to_string(c + (repeat ? 100 : 0)) + ".5";
        }
        out += (c > 0 ? "," : "") + value;
      }
      out += "\n";
    }
    return out;
  }
};

std::vector<std::string> sensorColumns() {
  std::vector<std::string> out;
  for (int s = 0; s < kSensorCount; ++s) {
    out.push_back("n" + std::to_string(s));
    out.push_back("s" + std::to_string(s));
  }
  return out;
}

// The header starting with `first`, then the other pose columns, then the sensors.
HandFile startingWith(const std::string& first) {
  HandFile f;
  f.columns.push_back(first);
  for (const char* name : {"step", "x", "y", "theta", "v", "omega", "blocked"})
    if (name != first) f.columns.emplace_back(name);
  for (const std::string& s : sensorColumns())
    f.columns.push_back(s);
  return f;
}

// Checks the refusal: on the header line (1: no metadata), naming the column, saying why.
void expectDuplicateRefused(const HandFile& file, const std::string& name) {
  const std::string text = file.text();
  for (unsigned threads : {1u, 2u}) {
    SCOPED_TRACE("threads " + std::to_string(threads));
    const RunCsvResult r = threads == 1 ? parseRunCsv(text, "dup.csv")
                                        : parseRunCsvParallel(text, "dup.csv", threads, 64);
    ASSERT_FALSE(r.ok()) << "a file repeating '" << name << "' was accepted";
    const Error& e = r.error();
    EXPECT_EQ(e.line, 1u) << e.text();
    EXPECT_NE(e.message.find("duplicate"), std::string::npos) << e.text();
    EXPECT_NE(e.message.find("'" + name + "'"), std::string::npos) << e.text();
  }
}

TEST(RunCsvDuplicates, TheHandFileWithoutARepeatIsValid) {
  // The files below differ from this one only by the repeated column.
  for (const char* first : {"step", "x", "omega"}) {
    const HandFile f = startingWith(first);
    const RunCsvResult r = parseRunCsv(f.text(), "ok.csv");
    ASSERT_TRUE(r.ok()) << first << ": " << r.errorText();
    EXPECT_EQ(r.value().stepCount(), 2u);
  }
}

TEST(RunCsvDuplicates, FirstColumnRepeatedAtTheEndIsRefused) {
  for (const char* first : {"x", "step", "omega", "n0"}) {
    SCOPED_TRACE(first);
    HandFile f = startingWith("x");
    if (std::string(first) != "x") {
      // Move `first` to the front.
      std::erase(f.columns, std::string(first));
      f.columns.insert(f.columns.begin(), first);
    }
    f.columns.emplace_back(first);
    expectDuplicateRefused(f, first);
  }
}

TEST(RunCsvDuplicates, LastColumnRepeatedIsRefused) {
  // Without truth the last column is s43; with truth, a truth column.
  HandFile f = startingWith("step");
  const std::string last = f.columns.back();
  f.columns.push_back(last);
  expectDuplicateRefused(f, last);

  HandFile t = startingWith("step");
  for (const GroupInfo& g : kSensorGroups)
    t.columns.push_back("truth_" + std::string(g.shortName));
  const std::string lastTruth = t.columns.back();
  t.columns.push_back(lastTruth);
  // The rows' values are not classes: the header must be refused before any row is read.
  expectDuplicateRefused(t, lastTruth);

  // A pose column repeated as the last one, the first copy in the middle.
  HandFile m = startingWith("step");
  m.columns.push_back("theta");
  expectDuplicateRefused(m, "theta");
}

TEST(RunCsvDuplicates, RepeatedExtraColumnIsRefused) {
  HandFile f = startingWith("step");
  f.columns.insert(f.columns.begin(), "x_note");
  f.columns.push_back("x_note");
  expectDuplicateRefused(f, "x_note");
}

}  // namespace run_csv_duplicate
}  // namespace
}  // namespace tactile
