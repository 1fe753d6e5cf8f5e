// Metrics and report tables (thesis tables 4.19 and 4.39, figures 4.13/14).
#include <gtest/gtest.h>

#include <cmath>

#include "analysis/metrics.h"
#include "analysis/report.h"
#include "tests/analysis/class_shorthand.h"
#include "tests/analysis/learn_test_data.h"

namespace tactile::analysis {
namespace {

using shorthand::C;
using shorthand::L;
using shorthand::W;

ConfusionMatrix example() {
  // truth W W W C C L, predicted W W C C W L
  return confusionOf({W, W, W, C, C, L}, {W, W, C, C, W, L});
}

TEST(Metrics, ConfusionCountsAndRowPercent) {
  const ConfusionMatrix m = example();
  EXPECT_EQ(m.total(), 6u);
  EXPECT_EQ(m.count(W, W), 2u);
  EXPECT_EQ(m.count(W, C), 1u);
  EXPECT_EQ(m.count(C, W), 1u);
  EXPECT_EQ(m.trueCount(W), 3u);
  EXPECT_EQ(m.predictedCount(W), 3u);
  EXPECT_NEAR(*m.percent(W, W), 100.0 * 2 / 3, 1e-12);
  EXPECT_NEAR(*m.percent(C, W), 50.0, 1e-12);
  EXPECT_FALSE(m.percent(ContactClass::DeadPath, W).has_value());
  const std::vector<ContactClass> active{W, C, L};
  EXPECT_EQ(m.activeClasses(), active);
}

TEST(Metrics, AccuracyBalancedAccuracyMacroF1) {
  const Metrics r = computeMetrics(example());
  EXPECT_EQ(r.total, 6u);
  EXPECT_NEAR(r.accuracy, 4.0 / 6.0, 1e-15);
  const double recallW = 2.0 / 3.0, recallC = 0.5, recallL = 1.0;
  EXPECT_NEAR(r.balancedAccuracy, (recallW + recallC + recallL) / 3.0, 1e-15);
  // F1 = 2tp / (2tp + fp + fn): W 4/6, C 2/4, L 1.
  EXPECT_NEAR(r.macroF1, (4.0 / 6.0 + 0.5 + 1.0) / 3.0, 1e-15);
  ASSERT_EQ(r.perClass.size(), 3u);
  EXPECT_NEAR(*r.perClass[0].precision, 2.0 / 3.0, 1e-15);
  EXPECT_NEAR(*r.recallOf(C), 0.5, 1e-15);
}

// Two raters, 50 samples: po = 35/50 = 0.7; pe = (25*30 + 25*20) / 50^2 = 0.5; kappa = 0.4.
TEST(Metrics, CohensKappaKnownAnswer) {
  ConfusionMatrix c;
  c.add(ContactClass::Wall, ContactClass::Wall, 20);
  c.add(ContactClass::Wall, ContactClass::Corner, 5);
  c.add(ContactClass::Corner, ContactClass::Wall, 10);
  c.add(ContactClass::Corner, ContactClass::Corner, 15);
  ASSERT_TRUE(cohensKappa(c).has_value());
  EXPECT_NEAR(*cohensKappa(c), 0.4, 1e-12);
}

TEST(Metrics, CohensKappaPerfectAndChanceAndDegenerate) {
  ConfusionMatrix perfect;
  perfect.add(ContactClass::Wall, ContactClass::Wall, 7);
  perfect.add(ContactClass::NoContact, ContactClass::NoContact, 3);
  EXPECT_DOUBLE_EQ(*cohensKappa(perfect), 1.0);
  // Agreement no better than chance: kappa 0.
  ConfusionMatrix chance;
  for (ContactClass t : {ContactClass::Wall, ContactClass::Corner})
    for (ContactClass p : {ContactClass::Wall, ContactClass::Corner})
      chance.add(t, p, 10);
  EXPECT_NEAR(*cohensKappa(chance), 0.0, 1e-12);
  // No samples, and both raters using one class throughout: undefined, never NaN.
  EXPECT_FALSE(cohensKappa(ConfusionMatrix{}).has_value());
  ConfusionMatrix single;
  single.add(ContactClass::Wall, ContactClass::Wall, 12);
  EXPECT_FALSE(cohensKappa(single).has_value());
}

TEST(Metrics, EmptyConfusionHasNoNaN) {
  const Metrics r = computeMetrics(ConfusionMatrix());
  EXPECT_EQ(r.total, 0u);
  EXPECT_EQ(r.accuracy, 0.0);
  EXPECT_EQ(r.balancedAccuracy, 0.0);
  EXPECT_EQ(r.macroF1, 0.0);
  EXPECT_TRUE(r.perClass.empty());
}

TEST(Metrics, ClassPredictedButNeverTrueHasNoRecall) {
  const Metrics r = computeMetrics(confusionOf({W, W}, {W, C}));
  ASSERT_EQ(r.perClass.size(), 2u);
  EXPECT_FALSE(r.recallOf(C).has_value());
  EXPECT_EQ(r.perClass[1].f1, 0.0);
  EXPECT_NEAR(r.balancedAccuracy, 0.5, 1e-15);  // only W has support
  EXPECT_NEAR(r.macroF1, (2.0 / 3.0 + 0.0) / 2.0, 1e-15);
}

TEST(Metrics, ClassNeverPredictedHasNoPrecision) {
  const Metrics r = computeMetrics(confusionOf({W, C}, {W, W}));
  EXPECT_FALSE(r.perClass[1].precision.has_value());
  EXPECT_EQ(*r.recallOf(C), 0.0);
}

TEST(Metrics, MergeAddsCounts) {
  ConfusionMatrix a = example();
  a.merge(example());
  EXPECT_EQ(a.total(), 12u);
  EXPECT_EQ(a.count(W, W), 4u);
}

// Thesis table 4.1 ("Wall" classifier, front side): Wall predicted for 34 true Wall and 5 true
// No Wall; No Wall predicted for 2 Wall and 25 No Wall. Table 4.19 reports 87.1% / 92.6%.
TEST(Metrics, OneVsRestCorrectRateIsThesisTable419Definition) {
  std::vector<ContactClass> truth;
  std::vector<std::uint8_t> says;
  auto add = [&](ContactClass t, bool s, int n) {
    for (int i = 0; i < n; ++i) {
      truth.push_back(t);
      says.push_back(s ? 1 : 0);
    }
  };
  add(W, true, 34);
  add(C, true, 5);
  add(W, false, 2);
  add(C, false, 25);
  const BinaryConfusion b = binaryConfusionOf(W, truth, says);
  EXPECT_EQ(b.truePositive, 34u);
  EXPECT_EQ(b.falsePositive, 5u);
  EXPECT_EQ(b.falseNegative, 2u);
  EXPECT_EQ(b.trueNegative, 25u);
  EXPECT_NEAR(100.0 * *b.classRate(), 87.1, 0.1);
  EXPECT_NEAR(100.0 * *b.restRate(), 92.6, 0.1);
}

TEST(Metrics, OneVsRestNeverPredictedHasNoRate) {
  const BinaryConfusion b = binaryConfusionOf(W, {W, C}, {0, 0});
  EXPECT_FALSE(b.classRate().has_value());
  EXPECT_NEAR(*b.restRate(), 0.5, 1e-15);
}

TEST(ContactPatterns, PatternMarksSensorsInIndexOrder) {
  RunData run;
  auto values = testdata::zeroStep();
  values[static_cast<std::size_t>(normalOffset(41))] = 1.0;  // last sensor of R
  values[static_cast<std::size_t>(shearOffset(33))] = -0.5;  // second sensor of R, shear only
  run.appendStep(0, 0, 0, 0, 0, false, values.data(), nullptr);
  EXPECT_EQ(contactPattern(run, 0, SensorGroup::Right), "0100000001");
  EXPECT_EQ(contactPattern(run, 0, SensorGroup::Left), "0000000000");
}

TEST(ContactPatterns, TableCountsAndSorts) {
  ContactPatternTable t;
  t.group = SensorGroup::Right;
  t.add("0000000011", L, C);
  t.add("0000000001", L, C);
  t.add("0000000001", L, L);
  t.add("0000000001", L, C);
  t.sortRows();
  ASSERT_EQ(t.rows.size(), 2u);
  EXPECT_EQ(t.rows[0].pattern, "0000000001");
  EXPECT_EQ(t.rows[0].predicted[static_cast<std::size_t>(C)], 2u);
  EXPECT_EQ(t.rows[0].predicted[static_cast<std::size_t>(L)], 1u);
  EXPECT_EQ(t.rows[0].total(), 3u);
  EXPECT_EQ(t.rows[0].errors(), 2u);
  const Table table = contactPatternTable(t);
  const std::string csv = table.render(TableStyle::Csv);
  EXPECT_NE(csv.find("0000000001,LeavingWall,2,1,3,2"), std::string::npos) << csv;
}

TEST(Report, ConfusionTablePercentRowsSumTo100) {
  const Table t = confusionTable(example(), true, "x");
  ASSERT_EQ(t.rows.size(), 3u);
  for (const auto& row : t.rows) {
    double sum = 0.0;
    for (std::size_t i = 1; i + 1 < row.size(); ++i)
      sum += std::stod(row[i]);
    EXPECT_NEAR(sum, 100.0, 0.02);
  }
}

TEST(Report, OneVsRestTableLeavesMissingClassesEmpty) {
  BinaryConfusion wall{W, 34, 5, 2, 25};
  BinaryConfusion lw{L, 18, 13, 89, 1055};
  const Table t =
      oneVsRestRateTable({{SensorGroup::Front, {wall}}, {SensorGroup::Right, {wall, lw}}});
  ASSERT_EQ(t.header.size(), 5u);  // group, Wall, No Wall, LeavingWall, No LeavingWall
  EXPECT_EQ(t.rows[0][3], "");
  EXPECT_EQ(t.rows[1][1], "87.2");
  EXPECT_EQ(t.rows[1][3], "58.1");  // thesis table 4.19, left side LW: 18 / 31
}

SweepCellResult cell(int order, double floor, std::vector<ContactClass> truth,
                     std::vector<ContactClass> predicted) {
  SweepCellResult r;
  r.cell.group = SensorGroup::Right;
  r.cell.order = order;
  r.cell.varianceFloor = floor;
  r.ok = true;
  r.confusion = confusionOf(truth, predicted);
  r.metrics = computeMetrics(r.confusion);
  return r;
}

TEST(Report, RateAgainstFloorGivesMeanMinMaxOverClasses) {
  SweepResult s;
  s.cells.push_back(cell(4, 0.1, {W, W, C, C}, {W, W, C, W}));   // rates 100, 50
  s.cells.push_back(cell(4, 0.01, {W, W, C, C}, {W, C, C, C}));  // rates 50, 100... then 100
  const Table t = rateAgainstFloorTable(s);
  ASSERT_EQ(t.rows.size(), 2u);
  // Sorted by floor within the series: 0.01 first.
  EXPECT_EQ(t.rows[0][5], "0.01");
  EXPECT_EQ(t.rows[1][5], "0.1");
  EXPECT_EQ(t.rows[1][7], "75.0");
  EXPECT_EQ(t.rows[1][8], "50.0");
  EXPECT_EQ(t.rows[1][9], "100.0");
}

TEST(Report, RateAgainstOrderSortsByOrder) {
  SweepResult s;
  s.cells.push_back(cell(16, 0.03, {W, C}, {W, C}));
  s.cells.push_back(cell(2, 0.03, {W, C}, {W, W}));
  SweepCellResult failed = cell(8, 0.03, {W}, {W});
  failed.ok = false;
  s.cells.push_back(failed);
  const Table t = rateAgainstOrderTable(s);
  ASSERT_EQ(t.rows.size(), 2u);  // the failed cell is not plotted
  EXPECT_EQ(t.rows[0][5], "2");
  EXPECT_EQ(t.rows[1][5], "16");
  EXPECT_EQ(t.rows[1][7], "100.0");
}

TEST(Report, CsvEscapesAndTextAligns) {
  Table t;
  t.header = {"a", "b"};
  t.rows = {{"x,y", "1.5"}, {"long name", "10.25"}};
  EXPECT_NE(t.render(TableStyle::Csv).find("\"x,y\",1.5"), std::string::npos);
  const std::string text = t.render(TableStyle::Text);
  // "x,y" padded to the widest cell (9), two spaces, "1.5" right-aligned in 5.
  EXPECT_NE(text.find("x,y" + std::string(6 + 2 + 2, ' ') + "1.5"), std::string::npos) << text;
}

}  // namespace
}  // namespace tactile::analysis
