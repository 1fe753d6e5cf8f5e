// Sweep reports: contact patterns per cell (filled and read back), the rate series behind figures
// 4.13 / 4.14, the time-against-error Pareto front, the SVG figures and the written report with
// its figure files.
#include <gtest/gtest.h>

#include <algorithm>
#include <clocale>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <random>
#include <sstream>
#include <string>

#include "analysis/report.h"
#include "analysis/report_svg.h"
#include "analysis/sweep.h"
#include "tests/analysis/class_shorthand.h"
#include "tests/analysis/learn_test_data.h"

namespace tactile::analysis {
namespace {

// A fresh folder, removed with its contents.
class TempDir {
 public:
  TempDir()
      : path_(std::filesystem::temp_directory_path() /
              ("tactile-report-test-" + std::to_string(std::random_device{}()))) {
    std::filesystem::create_directories(path_);
  }
  ~TempDir() {
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  std::filesystem::path operator/(const std::string& name) const { return path_ / name; }

 private:
  std::filesystem::path path_;
};

// A cell with a hand-made confusion: rows of (truth, predicted, count).
SweepCellResult cellWith(SensorGroup group, int order, double floor, double seconds,
                         std::vector<std::tuple<ContactClass, ContactClass, std::size_t>> counts) {
  SweepCellResult r;
  r.cell.group = group;
  r.cell.order = order;
  r.cell.varianceFloor = floor;
  r.cell.form = CovarianceForm::NodalDiag;
  r.ok = true;
  r.fitSeconds = seconds;
  for (const auto& [t, p, n] : counts)
    r.confusion.add(t, p, n);
  r.metrics = computeMetrics(r.confusion);
  return r;
}

using shorthand::C;
using shorthand::L;
using shorthand::W;

SweepResult handSweep() {
  SweepResult s;
  s.grid.orders = {1, 2};
  s.grid.varianceFloors = {0.01, 0.1};
  // Group F: recall (Wall, Corner) per cell.
  s.cells.push_back(cellWith(SensorGroup::Front, 1, 0.01, 0.010,
                             {{W, W, 9}, {W, C, 1}, {C, C, 1}, {C, W, 1}}));  // 90, 50
  s.cells.push_back(cellWith(SensorGroup::Front, 1, 0.1, 0.020,
                             {{W, W, 8}, {W, C, 2}, {C, C, 3}, {C, W, 1}}));  // 80, 75
  s.cells.push_back(
      cellWith(SensorGroup::Front, 2, 0.01, 0.030, {{W, W, 10}, {C, C, 1}, {C, W, 3}}));  // 100, 25
  s.cells.push_back(
      cellWith(SensorGroup::Front, 2, 0.1, 0.040, {{W, W, 7}, {W, C, 3}, {C, C, 4}}));  // 70, 100
  SweepCellResult failed;
  failed.cell.group = SensorGroup::Left;
  failed.reason = "no labelled contact samples";
  s.cells.push_back(failed);
  return s;
}

TEST(ReportSeries, RateSeriesGroupsByFixedSettingAndSortsBySweptValue) {
  const SweepResult s = handSweep();
  const std::vector<RateSeries> byFloor = rateSeries(s, SweptVariable::Floor);
  ASSERT_EQ(byFloor.size(), 2u);  // orders 1 and 2; the failed cell is no point
  for (const RateSeries& r : byFloor) {
    EXPECT_EQ(r.x, (std::vector<double>{0.01, 0.1}));
    ASSERT_EQ(r.cells.size(), 2u);
    for (std::size_t i = 0; i < r.cells.size(); ++i) {
      const Metrics& m = s.cells[r.cells[i]].metrics;
      const double wall = 100.0 * *m.recallOf(W);
      const double corner = 100.0 * *m.recallOf(C);
      EXPECT_DOUBLE_EQ(r.mean[i], (wall + corner) / 2);
      EXPECT_DOUBLE_EQ(r.min[i], std::min(wall, corner));
      EXPECT_DOUBLE_EQ(r.max[i], std::max(wall, corner));
      EXPECT_DOUBLE_EQ(r.balancedAccuracy[i], 100.0 * m.balancedAccuracy);
      EXPECT_EQ(s.cells[r.cells[i]].cell.order, static_cast<int>(r.fixedValue));
    }
  }
  EXPECT_NE(byFloor[0].label.find("order 1"), std::string::npos) << byFloor[0].label;
  EXPECT_EQ(byFloor[0].mean[0], 70.0);  // cell 0: (90 + 50) / 2
  const std::vector<RateSeries> byOrder = rateSeries(s, SweptVariable::Order);
  ASSERT_EQ(byOrder.size(), 2u);  // floors 0.01 and 0.1
  EXPECT_EQ(byOrder[1].x, (std::vector<double>{1, 2}));
  EXPECT_EQ(byOrder[1].cells, (std::vector<std::size_t>{1, 3}));
  // The tables are the series, one row per point.
  EXPECT_EQ(rateAgainstFloorTable(s).rows.size(), 4u);
  EXPECT_EQ(rateAgainstOrderTable(s).rows.size(), 4u);
}

TEST(ReportSeries, ParetoFrontKeepsOnlyUnbeatenCells) {
  SweepResult s = handSweep();
  // Balanced accuracy: cell 0 70, cell 1 77.5, cell 2 62.5, cell 3 85. Times rise with the index,
  // so cell 2 (slower and worse than cell 1) is beaten; the others each trade time for error.
  EXPECT_EQ(paretoFront(s), (std::vector<std::size_t>{0, 1, 3}));
  // A copy of cell 1 equal in both is kept beside it; one equally fast but worse is not.
  s.cells.push_back(s.cells[1]);
  SweepCellResult worse = s.cells[1];
  worse.confusion = ConfusionMatrix{};
  worse.confusion.add(W, C, 5);
  worse.confusion.add(C, C, 5);
  worse.metrics = computeMetrics(worse.confusion);
  s.cells.push_back(worse);
  EXPECT_EQ(paretoFront(s), (std::vector<std::size_t>{0, 1, 5, 3}));
  EXPECT_TRUE(paretoFront(s, SensorGroup::Left).empty());
  EXPECT_TRUE(paretoFront(SweepResult{}).empty());
}

// Well-formed enough to parse: every opened element closed, in order; no NaN or inf anywhere.
void expectWellFormed(const std::string& svg) {
  ASSERT_EQ(svg.rfind("<svg", 0), 0u) << svg.substr(0, 80);
  std::vector<std::string> open;
  std::size_t i = 0;
  while ((i = svg.find('<', i)) != std::string::npos) {
    const std::size_t end = svg.find('>', i);
    ASSERT_NE(end, std::string::npos);
    const std::string tag = svg.substr(i + 1, end - i - 1);
    if (tag[0] == '/') {
      ASSERT_FALSE(open.empty()) << tag;
      EXPECT_EQ(open.back(), tag.substr(1));
      open.pop_back();
    } else if (tag.back() != '/') {
      open.push_back(tag.substr(0, tag.find(' ')));
    }
    i = end;
  }
  EXPECT_TRUE(open.empty());
  std::string lower = svg;
  std::transform(lower.begin(), lower.end(), lower.begin(), ::tolower);
  EXPECT_EQ(lower.find("nan"), std::string::npos);
  EXPECT_EQ(lower.find("inf"), std::string::npos);
}

TEST(ReportSvg, ChartsAreWellFormedAndDrawEverySeriesAndPoint) {
  SweepResult s = handSweep();
  s.cells[0].fitSeconds = std::numeric_limits<double>::quiet_NaN();  // left out, never written
  const std::string rate = rateChartSvg(rateSeries(s, SweptVariable::Floor), SweptVariable::Floor,
                                        "Rate & floor <test>");
  expectWellFormed(rate);
  EXPECT_NE(rate.find("Rate &amp; floor &lt;test&gt;"), std::string::npos);
  // One solid mean line and two dashed bound lines per series.
  auto count = [](const std::string& text, const std::string& what) {
    std::size_t n = 0;
    for (std::size_t i = text.find(what); i != std::string::npos; i = text.find(what, i + 1))
      ++n;
    return n;
  };
  EXPECT_EQ(count(rate, "<polyline"), 2u * 3u);
  const std::string time = timeErrorChartSvg(s, "Run time against error");
  expectWellFormed(time);
  EXPECT_EQ(count(time, "<title>cell "), 3u);  // cells 1..3; cell 0 has no finite time
  EXPECT_NE(time.find("group F (front: 2)"), std::string::npos);  // cells 1 and 3
  EXPECT_EQ(count(time, "r=\"6\""), 2u);                          // rings
  expectWellFormed(timeErrorChartSvg(SweepResult{}, "empty"));
  expectWellFormed(rateChartSvg({}, SweptVariable::Order, "empty"));
}

TEST(ReportSvg, NumbersIgnoreTheLocale) {
  // A decimal comma in the process's locale must not reach the figures or the CSV tables.
  const char* before = std::setlocale(LC_NUMERIC, nullptr);
  const std::string saved = before ? before : "C";
  const bool german = std::setlocale(LC_NUMERIC, "de_DE.UTF-8") != nullptr;
  const SweepResult s = handSweep();
  const std::string svg = timeErrorChartSvg(s, "t");
  const std::string csv = rateAgainstFloorTable(s).render(TableStyle::Csv);
  std::setlocale(LC_NUMERIC, saved.c_str());
  EXPECT_NE(csv.find("70.0"), std::string::npos) << csv;
  EXPECT_EQ(csv.find("70,0"), std::string::npos) << csv;
  if (!german) GTEST_SKIP() << "no de_DE locale here; checked in the C locale only";
  EXPECT_EQ(svg.find("0,5"), std::string::npos);
}

TEST(ReportPatterns, SweepCellsCountTestRowsByPatternAndKeepThemInJson) {
  const RunData a = testdata::makeLabelledRun(900, 31);
  const RunData b = testdata::makeLabelledRun(600, 32);
  const std::vector<LabelledRun> train{{&a, labelsFromTruth(a)}};
  const std::vector<LabelledRun> test{{&b, labelsFromTruth(b)}};
  SweepGrid grid;
  grid.groups = {SensorGroup::Right};
  grid.orders = {1};
  grid.forms = {CovarianceForm::NodalDiag};
  grid.varianceFloors = {0.1};
  const SweepResult r = runSweep(train, test, grid);
  ASSERT_EQ(r.cells.size(), 1u);
  const SweepCellResult& cell = r.cells[0];
  ASSERT_TRUE(cell.ok) << cell.reason;
  ASSERT_FALSE(cell.patterns.rows.empty());
  EXPECT_EQ(cell.patterns.group, SensorGroup::Right);
  // Every test row is in exactly one pattern row, with its truth and prediction.
  std::size_t total = 0;
  ConfusionMatrix fromPatterns;
  for (const ContactPatternRow& row : cell.patterns.rows) {
    EXPECT_EQ(row.pattern.size(),
              static_cast<std::size_t>(groupInfo(SensorGroup::Right).sensorCount));
    EXPECT_NE(row.pattern.find('1'), std::string::npos);  // contact rows only
    total += row.total();
    for (int c = 0; c < kContactClassCount; ++c)
      fromPatterns.add(row.truth, static_cast<ContactClass>(c),
                       row.predicted[static_cast<std::size_t>(c)]);
  }
  EXPECT_EQ(total, cell.testRows);
  EXPECT_EQ(fromPatterns, cell.confusion);
  // Written and read back.
  auto back = sweepFromJson(sweepToJson(r));
  ASSERT_TRUE(back.ok()) << back.errorText();
  ASSERT_EQ(back->cells[0].patterns.rows.size(), cell.patterns.rows.size());
  for (std::size_t i = 0; i < cell.patterns.rows.size(); ++i) {
    EXPECT_EQ(back->cells[0].patterns.rows[i].pattern, cell.patterns.rows[i].pattern);
    EXPECT_EQ(back->cells[0].patterns.rows[i].truth, cell.patterns.rows[i].truth);
    EXPECT_EQ(back->cells[0].patterns.rows[i].predicted, cell.patterns.rows[i].predicted);
  }
  // A sweep stored before patterns were kept still reads.
  nlohmann::json old = sweepToJson(r);
  old["cells"][0].erase("patterns");
  auto oldBack = sweepFromJson(old);
  ASSERT_TRUE(oldBack.ok()) << oldBack.errorText();
  EXPECT_TRUE(oldBack->cells[0].patterns.rows.empty());
  // A malformed one is an error.
  nlohmann::json bad = sweepToJson(r);
  bad["cells"][0]["patterns"] = 7;
  EXPECT_FALSE(sweepFromJson(bad).ok());
}

TEST(ReportFile, MarkdownLinksItsFigureFilesAndHtmlInlinesThem) {
  TempDir dir;
  const SweepResult s = handSweep();
  const nlohmann::json configuration = {{"label_set", "truth"},
                                        {"train_runs", {{{"name", "r1"}}, {{"name", "r2"}}}},
                                        {"test_runs", {{{"name", "r3"}}}}};
  ASSERT_TRUE(writeSweepReport(s, TableStyle::Markdown, dir / "rep.md", configuration).ok());
  std::ifstream md(dir / "rep.md");
  std::stringstream text;
  text << md.rdbuf();
  for (const SweepFigure& f : sweepFigures(s)) {
    EXPECT_NE(text.str().find("](rep_files/" + f.file + ")"), std::string::npos) << f.file;
    EXPECT_TRUE(std::filesystem::exists(dir / "rep_files" / f.file)) << f.file;
    EXPECT_FALSE(std::filesystem::exists(dir / "rep_files" / (f.file + ".partial")));
  }
  EXPECT_NE(text.str().find("| training runs | r1, r2 |"), std::string::npos);
  EXPECT_NE(text.str().find("Cell 3: "), std::string::npos);  // every fitted cell's confusion
  ASSERT_TRUE(writeSweepReport(s, TableStyle::Html, dir / "rep.html").ok());
  std::ifstream html(dir / "rep.html");
  std::stringstream page;
  page << html.rdbuf();
  std::size_t svgs = 0;
  for (std::size_t i = page.str().find("<svg"); i != std::string::npos;
       i = page.str().find("<svg", i + 1))
    ++svgs;
  EXPECT_EQ(svgs, 3u);
  // An unwritable place is an error, and nothing is left behind.
  EXPECT_FALSE(writeSweepReport(s, TableStyle::Html, dir / "no" / "such" / "r.html").ok());
}

TEST(ReportFile, MarkdownLinksSurviveSpacesInTheName) {
  TempDir dir;
  const SweepResult s = handSweep();
  const nlohmann::json configuration = {{"label_set", "truth"}, {"holdout", 0.25}};
  ASSERT_TRUE(
      writeSweepReport(s, TableStyle::Markdown, dir / "my sweep (1).md", configuration).ok());
  std::ifstream md(dir / "my sweep (1).md");
  std::stringstream text;
  text << md.rdbuf();
  for (const SweepFigure& f : sweepFigures(s)) {
    EXPECT_TRUE(std::filesystem::exists(dir / "my sweep (1)_files" / f.file)) << f.file;
    EXPECT_NE(text.str().find("](my%20sweep%20%281%29_files/" + f.file + ")"), std::string::npos)
        << f.file;
  }
  EXPECT_NE(text.str().find("| held-out share of each training run | 0.25 |"), std::string::npos);
}

// A class with fewer test steps than the minimum never decides the best cell: a cell that wins
// only on a class with 5 test steps loses to one better on the classes with enough.
TEST(ReportBest, TooFewTestStepsNeverDecide) {
  SweepResult s;
  // Wall 100 steps, Corner 100, LeavingWall 5 in both cells.
  SweepCellResult a = cellWith(SensorGroup::Front, 2, 0.1, 1.0,
                               {{W, W, 95}, {W, C, 5}, {C, C, 90}, {C, W, 10}, {L, L, 5}});
  SweepCellResult b = cellWith(SensorGroup::Front, 4, 0.1, 1.0,
                               {{W, W, 99}, {W, C, 1}, {C, C, 99}, {C, W, 1}, {L, W, 5}});
  // On every class a is better (LeavingWall 1.0 against 0); on the classes with enough, b is.
  ASSERT_GT(a.metrics.balancedAccuracy, b.metrics.balancedAccuracy);
  s.cells = {a, b};
  EXPECT_TRUE(betterCell(b, a));
  EXPECT_FALSE(betterCell(a, b));
  EXPECT_EQ(bestCells(s), (std::vector<std::size_t>{1}));
  // Counted with no minimum, a wins.
  EXPECT_TRUE(betterCell(a, b, 0));
  EXPECT_EQ(bestCells(s, 0), (std::vector<std::size_t>{0}));
  // The class-rate table marks the thin class and shows every count.
  const Table t = classRateTable({{"a", a.metrics}}, "rates");
  const auto& row = t.rows.front();
  EXPECT_NE(std::find(row.begin(), row.end(), "100.0 (only 5 test steps)"), row.end());
  EXPECT_NE(std::find(row.begin(), row.end(), "95.0 (100)"), row.end());
  const Table none = classRateTable({{"empty", Metrics{}}}, "rates");
  EXPECT_NE(std::find(none.rows[0].begin(), none.rows[0].end(), "no test data"),
            none.rows[0].end());
}

// Two cells of group F equal in balanced accuracy: the one with fewer components is the best,
// and then the faster; the best-cells table and the report's detailed section agree.
// A group whose test runs hold none of its steps: a model, but nothing scored. Every table says
// "no test data" where a rate would stand (it once said 0.0 % and macro-F1 0.000).
TEST(ReportBest, ACellScoredOnNoTestRowsSaysNoTestDataInEveryFormat) {
  SweepResult s = handSweep();
  SweepCellResult unscored = cellWith(SensorGroup::Right, 2, 0.1, 0.05, {});
  s.cells.push_back(unscored);
  const Table best = bestCellsTable(s);
  bool found = false;
  for (const std::vector<std::string>& row : best.rows) {
    if (row[0] != "R") continue;
    found = true;
    EXPECT_EQ(row[7], "no test data");  // balanced_%
    EXPECT_EQ(row[8], "no test data");  // accuracy_%
    EXPECT_EQ(row[9], "no test data");  // macro_f1
  }
  EXPECT_TRUE(found) << "the unscored group has no best-cell row";
  const Table cells = sweepCellsTable(s);
  const std::vector<std::string>& last = cells.rows.back();
  EXPECT_EQ(last[8], "yes");  // a model was fitted
  EXPECT_EQ(last[13], "no test data");
  EXPECT_EQ(last[14], "no test data");
  EXPECT_EQ(last[15], "no test data");
  for (TableStyle style :
       {TableStyle::Text, TableStyle::Markdown, TableStyle::Csv, TableStyle::Html}) {
    const std::string report = sweepReport(s, style);
    EXPECT_NE(report.find("no test data"), std::string::npos) << static_cast<int>(style);
  }
  const nlohmann::json cell = sweepCellToJson(unscored);
  EXPECT_TRUE(cell["balanced_accuracy"].is_null());
}

// Guards the unscored group reading "0.0" anywhere: every format says "no test data" in the same
// places (best cell: balanced, accuracy, macro-F1; the cell table: the same three; the class-rate
// table: accuracy and balanced), draws no empty confusion matrix for the unscored cell, and the
// JSON flags the cell as not scored with null rates.
TEST(ReportBest, NoTestDataReadsTheSameInEveryFormatAndNeverAsZero) {
  SweepResult s = handSweep();
  s.cells.push_back(cellWith(SensorGroup::Right, 2, 0.1, 0.05, {}));
  const std::size_t unscored = s.cells.size() - 1;
  auto count = [](const std::string& text, const std::string& what) {
    std::size_t n = 0;
    for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1))
      ++n;
    return n;
  };
  for (TableStyle style :
       {TableStyle::Text, TableStyle::Markdown, TableStyle::Csv, TableStyle::Html}) {
    const std::string report = sweepReport(s, style);
    EXPECT_EQ(count(report, "no test data"), 8u) << "format " << static_cast<int>(style);
    EXPECT_EQ(report.find("Cell " + std::to_string(unscored) + ":"), std::string::npos)
        << "an empty confusion matrix for the unscored cell, format " << static_cast<int>(style);
    EXPECT_EQ(report.find("Group R, gmm nodal-diag order 2 variance floor 0.1, seed 1: confusion"),
              std::string::npos)
        << "best-cell details for the unscored group, format " << static_cast<int>(style);
  }
  // The unscored row of each table: no rate cell holds a number.
  const Table cells = sweepCellsTable(s);
  for (std::size_t column : {13u, 14u, 15u})
    EXPECT_EQ(cells.rows.back()[column], "no test data") << cells.header[column];
  const Table best = bestCellsTable(s);
  ASSERT_FALSE(best.rows.empty());
  EXPECT_EQ(best.rows.back()[0], "R");
  for (std::size_t column : {7u, 8u, 9u})
    EXPECT_EQ(best.rows.back()[column], "no test data") << best.header[column];
  const nlohmann::json cell = sweepCellToJson(s.cells.back());
  EXPECT_FALSE(cell.at("scored").get<bool>());
  EXPECT_TRUE(cell.at("accuracy").is_null());
  EXPECT_TRUE(cell.at("balanced_accuracy").is_null());
  EXPECT_TRUE(cell.at("macro_f1").is_null());
  EXPECT_TRUE(sweepCellToJson(s.cells.front()).at("scored").get<bool>());
}

TEST(ReportBest, OneRuleForTheBestCellOfEachGroup) {
  SweepResult s = handSweep();
  SweepCellResult twin = s.cells[3];  // balanced accuracy as cell 3 (the best of F), order 1
  twin.cell.order = 1;
  twin.cell.varianceFloor = 0.3;
  twin.fitSeconds = 5.0;
  s.cells.push_back(twin);  // index 5
  SweepCellResult right = cellWith(SensorGroup::Right, 4, 0.1, 0.1, {{W, W, 3}, {C, W, 1}});
  s.cells.push_back(right);                         // index 6
  EXPECT_TRUE(betterCell(s.cells[5], s.cells[3]));  // fewer components
  EXPECT_FALSE(betterCell(s.cells[3], s.cells[5]));
  EXPECT_TRUE(betterCell(s.cells[3], s.cells[1]));  // higher balanced accuracy
  SweepCellResult slower = s.cells[5];
  slower.fitSeconds = 6.0;
  EXPECT_TRUE(betterCell(s.cells[5], slower));
  EXPECT_FALSE(betterCell(s.cells[5], s.cells[5]));  // not better than itself
  // Front before Right (group order); the failed Left cell gives nothing.
  EXPECT_EQ(bestCells(s), (std::vector<std::size_t>{5, 6}));
  const Table best = bestCellsTable(s);
  ASSERT_EQ(best.rows.size(), 2u);
  EXPECT_EQ(best.rows[0][4], "1");    // order
  EXPECT_EQ(best.rows[0][5], "0.3");  // floor
  const std::string report = sweepReport(s, TableStyle::Markdown);
  EXPECT_NE(report.find("Group F, gmm nodal-diag order 1 variance floor 0.3, seed 1: confusion"),
            std::string::npos);
  EXPECT_EQ(report.find("Group F, gmm nodal-diag order 2 variance floor 0.1, seed 1: confusion"),
            std::string::npos);
  EXPECT_TRUE(bestCells(SweepResult{}).empty());
}

TEST(ReportSeries, ParetoFrontPerGroupAndWithoutUnscoredCells) {
  SweepResult s = handSweep();
  // A Right cell faster than every F cell and better than all but cell 3.
  s.cells.push_back(cellWith(SensorGroup::Right, 1, 0.1, 0.005,
                             {{W, W, 4}, {W, C, 1}, {C, C, 4}, {C, W, 1}}));  // 80, 80
  // Faster still, but scored on nothing, and one with no finite time: neither is a point.
  SweepCellResult unscored = cellWith(SensorGroup::Front, 1, 0.3, 0.001, {});
  s.cells.push_back(unscored);
  SweepCellResult noTime = s.cells[3];
  noTime.fitSeconds = std::numeric_limits<double>::infinity();
  s.cells.push_back(noTime);
  // Balanced accuracy: F 70, 77.5, 62.5, 85 (cells 0..3), R 80 (cell 5). Cell 5 is faster than
  // cells 0 and 1 and better than both; only cell 3 is better still.
  const double r = s.cells[5].metrics.balancedAccuracy;
  ASSERT_GT(r, s.cells[1].metrics.balancedAccuracy);
  ASSERT_LT(r, s.cells[3].metrics.balancedAccuracy);
  EXPECT_EQ(paretoFront(s), (std::vector<std::size_t>{5, 3}));
  EXPECT_EQ(paretoFront(s, SensorGroup::Front), (std::vector<std::size_t>{0, 1, 3}));
  EXPECT_EQ(paretoFront(s, SensorGroup::Right), (std::vector<std::size_t>{5}));
  // Equal in both, whatever the order they are listed in: both kept, in cell order.
  SweepResult two;
  two.cells = {s.cells[3], s.cells[3]};
  EXPECT_EQ(paretoFront(two), (std::vector<std::size_t>{0, 1}));
  // Equal time, different error: only the better; equal error, different time: only the faster.
  two.cells[1].confusion = s.cells[1].confusion;
  two.cells[1].metrics = s.cells[1].metrics;
  EXPECT_EQ(paretoFront(two), (std::vector<std::size_t>{0}));
  two.cells[1] = s.cells[3];
  two.cells[0].fitSeconds += 1.0;
  EXPECT_EQ(paretoFront(two), (std::vector<std::size_t>{1}));
}

// The x positions of the first `n` circles of a figure (the series' dots come before the legend).
std::vector<double> circleXs(const std::string& svg, std::size_t n) {
  std::vector<double> out;
  const std::string key = "<circle cx=\"";
  for (std::size_t i = svg.find(key); i != std::string::npos && out.size() < n;
       i = svg.find(key, i + 1))
    out.push_back(std::stod(svg.substr(i + key.size())));
  return out;
}

TEST(ReportSvg, TimeChartRingsEachGroupsOwnFront) {
  SweepResult s = handSweep();
  // A Right cell faster and better than every F cell but cell 3: it does not push F's cells off
  // F's front.
  s.cells.push_back(
      cellWith(SensorGroup::Right, 1, 0.1, 0.005, {{W, W, 4}, {W, C, 1}, {C, C, 4}, {C, W, 1}}));
  const std::string svg = timeErrorChartSvg(s, "t");
  expectWellFormed(svg);
  const std::size_t fronts =
      paretoFront(s, SensorGroup::Front).size() + paretoFront(s, SensorGroup::Right).size();
  EXPECT_EQ(fronts, 4u);
  std::size_t rings = 0;
  for (std::size_t i = svg.find("r=\"6\""); i != std::string::npos; i = svg.find("r=\"6\"", i + 1))
    ++rings;
  EXPECT_EQ(rings, fronts);
  EXPECT_NE(svg.find("group F (front: 3)"), std::string::npos);
  EXPECT_NE(svg.find("group R (front: 1)"), std::string::npos);
}

TEST(ReportSvg, RateChartHasALogAxisABandPerSeriesAndReadsOnlyWholePoints) {
  RateSeries a;
  a.label = "F gmm nodal-diag floor 0.01";
  a.x = {1, 1.5, 2};
  a.mean = {50, 60, 70};
  a.min = {40, 50, 60};
  a.max = {60, 70, 80};
  const std::string svg = rateChartSvg({a}, SweptVariable::Order, "order");
  expectWellFormed(svg);
  const std::vector<double> xs = circleXs(svg, 3);
  ASSERT_EQ(xs.size(), 3u);
  // Log axis, even over a factor of only 2: 1.5 sits at log(1.5) / log(2) of the way from 1 to 2
  // (0.585; a linear axis would put it half way).
  EXPECT_GT(xs[1], xs[0]);
  EXPECT_NEAR((xs[1] - xs[0]) / (xs[2] - xs[0]), std::log(1.5) / std::log(2.0), 0.002);
  auto count = [](const std::string& text, const std::string& what) {
    std::size_t n = 0;
    for (std::size_t i = text.find(what); i != std::string::npos; i = text.find(what, i + 1))
      ++n;
    return n;
  };
  EXPECT_EQ(count(svg, "<polygon"), 1u);
  EXPECT_EQ(count(svg, "<title>"), 3u);
  EXPECT_NE(svg.find(">F gmm nodal-diag floor 0.01</text>"), std::string::npos);  // legend
  // A series whose vectors disagree in length is drawn up to the shortest; NaN points are skipped.
  RateSeries b = a;
  b.mean = {50, std::numeric_limits<double>::quiet_NaN()};
  const std::string partial = rateChartSvg({b}, SweptVariable::Order, "order");
  expectWellFormed(partial);
  EXPECT_EQ(count(partial, "<title>"), 1u);
  // With a 0 on the axis it is linear: 0 -> 1 and 1 -> 2 equally far apart.
  RateSeries c = a;
  c.x = {0, 1, 2};
  const std::vector<double> linear = circleXs(rateChartSvg({c}, SweptVariable::Floor, "f"), 3);
  ASSERT_EQ(linear.size(), 3u);
  EXPECT_NEAR(linear[1] - linear[0], linear[2] - linear[1], 0.02);
}

}  // namespace
}  // namespace tactile::analysis

namespace tactile::analysis {
namespace {

TEST(ReportRates, OneVsRestCountsFromAMultiClassConfusion) {
  ConfusionMatrix m;
  m.add(W, W, 8);
  m.add(W, C, 2);
  m.add(C, C, 3);
  m.add(C, W, 1);
  m.add(ContactClass::LeavingWall, W, 4);
  const std::vector<BinaryConfusion> b = binaryConfusions(m, {W, C});
  ASSERT_EQ(b.size(), 2u);
  EXPECT_EQ(b[0].positive, W);
  EXPECT_EQ(b[0].truePositive, 8u);
  EXPECT_EQ(b[0].falsePositive, 5u);  // Corner and LeavingWall rows said Wall
  EXPECT_EQ(b[0].falseNegative, 2u);
  EXPECT_EQ(b[0].trueNegative, 3u);
  EXPECT_EQ(b[1].truePositive, 3u);
  EXPECT_EQ(b[1].falsePositive, 2u);
  EXPECT_EQ(b[1].falseNegative, 1u);
  EXPECT_EQ(b[1].trueNegative, 12u);
  for (const BinaryConfusion& x : b)
    EXPECT_EQ(x.truePositive + x.falsePositive + x.falseNegative + x.trueNegative, m.total());
}

}  // namespace
}  // namespace tactile::analysis
