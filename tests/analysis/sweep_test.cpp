// Training glue and the sweep engine: deterministic for a seed whatever the thread count,
// cancellable, shared data extraction, JSON round trip.
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>

#include "analysis/report.h"
#include "analysis/sweep.h"
#include "analysis/training.h"
#include "tests/analysis/learn_test_data.h"

namespace tactile::analysis {
namespace {

struct Fixture {
  RunData a = testdata::makeLabelledRun(1200, 21);
  RunData b = testdata::makeLabelledRun(800, 22);
  std::vector<LabelledRun> runs{{&a, labelsFromTruth(a)}, {&b, labelsFromTruth(b)}};
};

const Fixture& fixture() {
  static const Fixture f;
  return f;
}

SweepGrid smallGrid() {
  SweepGrid g;
  g.groups = {SensorGroup::Right, SensorGroup::FrontLeftCorner};
  g.orders = {1, 2, 4};
  g.forms = {CovarianceForm::NodalDiag, CovarianceForm::GrandFull};
  g.floors = {0.01, 0.1};
  g.maxIterations = 30;
  return g;
}

TEST(Training, SplitKeepsTimeOrderAndPartitionsLabels) {
  const Fixture& f = fixture();
  std::vector<LabelledRun> train, test;
  splitLabelledRuns(f.runs, 0.25, train, test);
  ASSERT_EQ(train.size(), 2u);
  const std::size_t cut = 900;  // 75% of 1200
  for (std::size_t t = 0; t < f.a.stepCount(); ++t) {
    const std::size_t i = t * kGroupCount;
    EXPECT_EQ(train[0].labels[i].has_value(), t < cut);
    EXPECT_EQ(test[0].labels[i].has_value(), t >= cut);
  }
}

TEST(Training, SeparableDataIsClassifiedWell) {
  const Fixture& f = fixture();
  std::vector<LabelledRun> train, test;
  splitLabelledRuns(f.runs, 0.3, train, test);
  const GroupDataSet trainSet = buildGroupDataSet(train, SensorGroup::Right, FeatureKind::Normal);
  const GroupDataSet testSet = buildGroupDataSet(test, SensorGroup::Right, FeatureKind::Normal);
  TrainSettings s;
  s.classifier.gmm.components = 2;
  s.classifier.gmm.floor = 0.01;
  const GroupTrainResult r = trainGroupModel(trainSet, s);
  ASSERT_TRUE(r.ok) << r.reason;
  const std::vector<ContactClass> expected{ContactClass::Wall, ContactClass::Corner,
                                           ContactClass::LeavingWall};
  EXPECT_EQ(r.model.classes, expected);
  const GroupEvaluation ev = evaluateGroupModel(r.model, testSet, &test);
  EXPECT_EQ(ev.metrics.total, testSet.size());
  EXPECT_GT(ev.metrics.accuracy, 0.95);
  ASSERT_TRUE(ev.meanLogLikelihood.has_value());
  EXPECT_TRUE(std::isfinite(*ev.meanLogLikelihood));
  // Every test row appears in exactly one pattern row.
  std::size_t patterned = 0;
  for (const ContactPatternRow& row : ev.patterns.rows)
    patterned += row.total();
  EXPECT_EQ(patterned, testSet.size());
}

TEST(Training, RareClassIsNotModelledAndCountsAsError) {
  const Fixture& f = fixture();
  std::vector<LabelledRun> runs = f.runs;
  // Relabel three contact steps of R as DeadPath: present, but fewer samples than dimensions.
  int relabelled = 0;
  for (std::size_t t = 0; t < f.a.stepCount() && relabelled < 3; ++t) {
    if (!groupIsZero(f.a, t, SensorGroup::Right)) {
      runs[0].labels[t * kGroupCount + groupIndex(SensorGroup::Right)] = ContactClass::DeadPath;
      ++relabelled;
    }
  }
  const GroupDataSet data = buildGroupDataSet(runs, SensorGroup::Right, FeatureKind::Normal);
  const ClassSelection sel = selectClasses(data);
  ASSERT_EQ(sel.unmodelled.size(), 1u);
  EXPECT_EQ(sel.unmodelled[0], ContactClass::DeadPath);
  TrainSettings s;
  s.classifier.gmm.components = 1;
  const GroupTrainResult r = trainGroupModel(data, s);
  ASSERT_TRUE(r.ok) << r.reason;
  const GroupEvaluation ev = evaluateGroupModel(r.model, data);
  EXPECT_EQ(ev.confusion.trueCount(ContactClass::DeadPath), 3u);
  EXPECT_EQ(ev.confusion.count(ContactClass::DeadPath, ContactClass::DeadPath), 0u);
}

TEST(Training, GroupWithoutSamplesIsAnErrorNotACrash) {
  const Fixture& f = fixture();
  std::vector<LabelledRun> runs{
      {&f.a, std::vector<std::optional<ContactClass>>(f.a.stepCount() * kGroupCount)}};
  const GroupDataSet data = buildGroupDataSet(runs, SensorGroup::Back, FeatureKind::Normal);
  const GroupTrainResult r = trainGroupModel(data, TrainSettings{});
  EXPECT_FALSE(r.ok);
  EXPECT_NE(r.reason.find("no labelled contact samples"), std::string::npos);
}

TEST(Training, GaussianEvaluationFillsOneVsRestTable) {
  const Fixture& f = fixture();
  const GroupDataSet data = buildGroupDataSet(f.runs, SensorGroup::Left, FeatureKind::Normal);
  TrainSettings s;
  s.classifier.method = ClassifierMethod::Gaussian;
  s.classifier.gmm.floor = 0.01;
  const GroupTrainResult r = trainGroupModel(data, s);
  ASSERT_TRUE(r.ok) << r.reason;
  const GroupEvaluation ev = evaluateGroupModel(r.model, data);
  ASSERT_EQ(ev.oneVsRest.size(), 3u);
  for (const BinaryConfusion& b : ev.oneVsRest) {
    EXPECT_EQ(b.truePositive + b.falsePositive + b.falseNegative + b.trueNegative, data.size());
    EXPECT_EQ(b.truePositive + b.falseNegative,
              data.classCounts()[static_cast<std::size_t>(b.positive)]);
  }
}

TEST(Sweep, ExpandGridCountsCellsAndDedupesGaussian) {
  SweepGrid g;  // default: 8 groups x 7 orders x 4 forms x 3 floors
  EXPECT_EQ(expandGrid(g).size(), 8u * 7u * 4u * 3u);
  g.methods = {ClassifierMethod::Gaussian, ClassifierMethod::Gmm};
  g.groups = {SensorGroup::Right};
  // Gaussian: one cell per floor; GMM: 7 x 4 x 3.
  EXPECT_EQ(expandGrid(g).size(), 3u + 7u * 4u * 3u);
}

TEST(Sweep, ResultsDoNotDependOnThreadCount) {
  const Fixture& f = fixture();
  std::vector<LabelledRun> train, test;
  splitLabelledRuns(f.runs, 0.3, train, test);
  SweepOptions one, two;
  one.threads = 1;
  two.threads = 2;
  const SweepResult a = runSweep(train, test, smallGrid(), one);
  const SweepResult b = runSweep(train, test, smallGrid(), two);
  ASSERT_EQ(a.cells.size(), expandGrid(smallGrid()).size());
  ASSERT_EQ(a.cells.size(), b.cells.size());
  EXPECT_EQ(b.threads, 2);
  for (std::size_t i = 0; i < a.cells.size(); ++i) {
    const SweepCellResult& x = a.cells[i];
    const SweepCellResult& y = b.cells[i];
    EXPECT_EQ(x.cell.order, y.cell.order);
    EXPECT_EQ(x.cell.floor, y.cell.floor);
    EXPECT_EQ(x.ok, y.ok) << x.reason << " / " << y.reason;
    EXPECT_EQ(x.confusion, y.confusion);
    EXPECT_EQ(x.iterations, y.iterations);
    EXPECT_EQ(x.meanLogLikelihood, y.meanLogLikelihood);  // bit for bit
  }
}

TEST(Sweep, CellsRecordMetricsAndTimes) {
  const Fixture& f = fixture();
  std::vector<LabelledRun> train, test;
  splitLabelledRuns(f.runs, 0.3, train, test);
  const SweepResult r = runSweep(train, test, smallGrid());
  ASSERT_FALSE(r.cells.empty());
  ASSERT_EQ(r.data.size(), 2u);
  for (const SweepCellResult& c : r.cells) {
    ASSERT_TRUE(c.ok) << c.reason;
    EXPECT_GT(c.iterations, 0);
    EXPECT_GE(c.fitSeconds, 0.0);
    EXPECT_EQ(c.metrics.total, c.testRows);
    EXPECT_EQ(c.confusion.total(), c.testRows);
    EXPECT_GE(c.metrics.balancedAccuracy, 0.0);
    EXPECT_LE(c.metrics.balancedAccuracy, 1.0);
    ASSERT_TRUE(c.meanLogLikelihood.has_value());
    EXPECT_TRUE(std::isfinite(*c.meanLogLikelihood));
  }
}

TEST(Sweep, GroupWithoutDataGivesFailedCellsWithReason) {
  const Fixture& f = fixture();
  std::vector<LabelledRun> train = f.runs;
  for (LabelledRun& lr : train) {
    for (std::size_t t = 0; t < lr.run->stepCount(); ++t) {
      lr.labels[t * kGroupCount + groupIndex(SensorGroup::Back)].reset();
    }
  }
  SweepGrid g = smallGrid();
  g.groups = {SensorGroup::Back};
  const SweepResult r = runSweep(train, f.runs, g);
  ASSERT_EQ(r.cells.size(), expandGrid(g).size());
  for (const SweepCellResult& c : r.cells) {
    EXPECT_FALSE(c.ok);
    EXPECT_FALSE(c.reason.empty());
  }
}

TEST(Sweep, ProgressCanCancel) {
  const Fixture& f = fixture();
  std::atomic<int> calls{0};
  SweepOptions o;
  o.threads = 2;
  const SweepResult r =
      runSweep(f.runs, f.runs, smallGrid(), o, [&](std::size_t done, std::size_t total) {
        ++calls;
        EXPECT_LE(done, total);
        return done < 2;
      });
  EXPECT_TRUE(r.cancelled);
  EXPECT_LT(r.cells.size(), expandGrid(smallGrid()).size());
  EXPECT_GE(r.cells.size(), 2u);
}

TEST(Sweep, CancelBeforeStartRunsNothing) {
  const Fixture& f = fixture();
  const SweepResult r =
      runSweep(f.runs, f.runs, smallGrid(), {}, [](std::size_t, std::size_t) { return false; });
  EXPECT_TRUE(r.cancelled);
  EXPECT_TRUE(r.cells.empty());
}

TEST(Sweep, JsonRoundTripKeepsCellsForReports) {
  const Fixture& f = fixture();
  std::vector<LabelledRun> train, test;
  splitLabelledRuns(f.runs, 0.3, train, test);
  SweepGrid g = smallGrid();
  g.groups = {SensorGroup::Right};
  const SweepResult r = runSweep(train, test, g);
  const nlohmann::json j = nlohmann::json::parse(sweepToJson(r).dump());
  SweepResult back;
  ASSERT_EQ(sweepFromJson(j, back), "");
  ASSERT_EQ(back.cells.size(), r.cells.size());
  for (std::size_t i = 0; i < r.cells.size(); ++i) {
    EXPECT_EQ(back.cells[i].confusion, r.cells[i].confusion);
    EXPECT_EQ(back.cells[i].cell.form, r.cells[i].cell.form);
    EXPECT_EQ(back.cells[i].meanLogLikelihood, r.cells[i].meanLogLikelihood);
    EXPECT_EQ(back.cells[i].metrics.balancedAccuracy, r.cells[i].metrics.balancedAccuracy);
  }
  // The report tables render both the live and the re-read result the same way.
  EXPECT_EQ(sweepReport(back, TableStyle::Csv).find("nan"), std::string::npos);
  EXPECT_EQ(rateAgainstOrderTable(back).rows.size(), rateAgainstOrderTable(r).rows.size());
}

TEST(Sweep, NotASweepFileIsAnError) {
  SweepResult out;
  EXPECT_FALSE(sweepFromJson(nlohmann::json{{"format", "tactile-model"}}, out).empty());
  EXPECT_FALSE(
      sweepFromJson(nlohmann::json{{"format", "tactile-sweep"}, {"version", 1}}, out).empty());
}

}  // namespace
}  // namespace tactile::analysis
