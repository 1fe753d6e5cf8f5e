// Training glue and the sweep engine: deterministic for a seed whatever the thread count,
// cancellable inside running fits, shared data extraction, JSON round trip of every field.
#include <gtest/gtest.h>

#include <array>
#include <atomic>
#include <cmath>
#include <new>
#include <set>
#include <tuple>

#include "analysis/report.h"
#include "analysis/sweep.h"
#include "analysis/sweep_summary.h"
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
  g.varianceFloors = {0.01, 0.1};
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

TEST(Training, DefaultsAreEachGroupsOwnTunedModel) {
  const GroupSettings d = defaultGroupSettings();
  bool ordersDiffer = false;
  bool treesDiffer = false;
  for (const GroupInfo& g : kSensorGroups) {
    const TrainSettings& s = d.of(g.group);
    // The touch flags of F, L and R (alone or within the context kinds) in every group that can
    // see a dead path: the flags are the dead-path rule itself; the others choose.
    const bool seesDeadPath = g.group == SensorGroup::Front || g.group == SensorGroup::Left ||
                              g.group == SensorGroup::Right ||
                              g.group == SensorGroup::FrontLeftCorner ||
                              g.group == SensorGroup::FrontRightCorner;
    const bool flags = s.features == FeatureKind::NormalShearTouch || usesHistory(s.features);
    if (seesDeadPath) {
      EXPECT_TRUE(flags) << g.shortName;
    }
    EXPECT_TRUE(flags || s.features == FeatureKind::NormalShear) << g.shortName;
    // A model's default decision is one a navigator may use.
    EXPECT_TRUE(isCausal(s.decision)) << g.shortName;
    EXPECT_EQ(s.decision, DecisionMode::Online) << g.shortName;
    // The family that won on the selection corpus; the mixtures' settings are kept either way
    // (for --method gmm on a group of trees).
    EXPECT_TRUE(s.classifier.method == ClassifierMethod::Gmm ||
                s.classifier.method == ClassifierMethod::Gbt)
        << g.shortName;
    EXPECT_EQ(s.emissionWeight, defaultEmissionWeight(g.group, s.classifier.method)) << g.shortName;
    EXPECT_EQ(s.classifier.gmm.form, CovarianceForm::NodalFull) << g.shortName;
    EXPECT_EQ(s.classifier.gmm.restarts, 3) << g.shortName;
    EXPECT_GE(s.classifier.gmm.components, 1) << g.shortName;
    EXPECT_GT(s.classifier.gmm.varianceFloor, 0.0) << g.shortName;
    // The chain's evidence weight: the mixtures' tempered (< 1) or plain (1), never amplified;
    // the trees' plain or amplified (their scaled likelihoods span few nats), never tempered.
    const double mixtures = defaultEmissionWeight(g.group, ClassifierMethod::Gmm);
    const double trees = defaultEmissionWeight(g.group, ClassifierMethod::Gbt);
    EXPECT_GT(mixtures, 0.0) << g.shortName;
    EXPECT_LE(mixtures, 1.0) << g.shortName;
    EXPECT_GE(trees, 1.0) << g.shortName;
    EXPECT_TRUE(std::isfinite(trees)) << g.shortName;
    EXPECT_TRUE(checkGbtSettings(s.classifier.gbt).empty()) << g.shortName;
    treesDiffer |= s.classifier.gbt.trees != d.byGroup[0].classifier.gbt.trees ||
                   s.classifier.gbt.depth != d.byGroup[0].classifier.gbt.depth;
    EXPECT_EQ(s.classifier.gmm.components, defaultTrainSettings(g.group).classifier.gmm.components);
    ordersDiffer |= s.classifier.gmm.components != d.byGroup[0].classifier.gmm.components;
  }
  EXPECT_TRUE(ordersDiffer) << "the defaults are per group, not one setting for all";
  EXPECT_TRUE(treesDiffer) << "the trees' defaults are per group too";
  const GroupSettings same = GroupSettings::same(defaultTrainSettings(SensorGroup::Back));
  for (const TrainSettings& s : same.byGroup)
    EXPECT_EQ(s.classifier.gmm.components,
              defaultTrainSettings(SensorGroup::Back).classifier.gmm.components);
}

// Options of one family without a method train that family; both families' options without a
// method are refused; a method given always wins.
TEST(Training, OptionsOfOneFamilyImplyIt) {
  constexpr auto kGmm = ClassifierMethod::Gmm;
  constexpr auto kTrees = ClassifierMethod::Gbt;
  constexpr auto kGaussian = ClassifierMethod::Gaussian;
  EXPECT_EQ(impliedMethod(std::nullopt, false, false, kTrees).value(), kTrees);
  EXPECT_EQ(impliedMethod(std::nullopt, false, false, kGmm).value(), kGmm);
  EXPECT_EQ(impliedMethod(std::nullopt, true, false, kTrees).value(), kGmm);
  EXPECT_EQ(impliedMethod(std::nullopt, true, false, kGmm).value(), kGmm);
  EXPECT_EQ(impliedMethod(std::nullopt, false, true, kGmm).value(), kTrees);
  EXPECT_EQ(impliedMethod(kGaussian, true, true, kTrees).value(), kGaussian);
  const auto both = impliedMethod(std::nullopt, true, true, kGmm);
  ASSERT_FALSE(both.ok());
  EXPECT_NE(both.errorText().find("say which"), std::string::npos) << both.errorText();
}

// The table of docs/learning.md#training-defaults, group by group: the family, the features, the
// mixtures' order, floor and chain weight, and the trees' rounds, depth and chain weight, as chosen
// on the selection corpus.
TEST(Training, DefaultsAreTheDocumentedTable) {
  struct Row {
    SensorGroup group;
    ClassifierMethod method;
    FeatureKind features;
    int order;
    double floor;
    double mixtureWeight;
    FeatureKind treeFeatures;
    int trees;
    int depth;
    double treeWeight;
  };
  constexpr ClassifierMethod kTrees = ClassifierMethod::Gbt;
  constexpr ClassifierMethod kGmm = ClassifierMethod::Gmm;
  constexpr FeatureKind kContext = FeatureKind::Context;
  constexpr FeatureKind kNeighbours = FeatureKind::Neighbours;
  constexpr FeatureKind kMotion = FeatureKind::Motion;
  const std::array<Row, 8> table{{
      {SensorGroup::Front, kTrees, kContext, 8, 0.01, 0.3, kNeighbours, 200, 6, 3.0},
      {SensorGroup::FrontLeftCorner, kTrees, kNeighbours, 8, 0.01, 1.0, kNeighbours, 100, 6, 3.0},
      {SensorGroup::Left, kTrees, kNeighbours, 8, 0.01, 0.3, kContext, 200, 6, 2.0},
      {SensorGroup::RearLeftCorner, kGmm, kNeighbours, 16, 0.01, 1.0, kContext, 100, 4, 1.5},
      {SensorGroup::Back, kTrees, FeatureKind::NormalShear, 4, 0.01, 0.3, kMotion, 100, 4, 1.0},
      {SensorGroup::RearRightCorner, kTrees, kContext, 8, 0.01, 0.3, kContext, 100, 4, 2.0},
      {SensorGroup::Right, kTrees, kNeighbours, 8, 0.01, 0.1, kNeighbours, 200, 6, 2.0},
      {SensorGroup::FrontRightCorner, kTrees, kNeighbours, 16, 0.01, 1.0, kMotion, 100, 6, 4.0},
  }};
  for (const Row& r : table) {
    const TrainSettings s = defaultTrainSettings(r.group);
    const std::string_view name = groupInfo(r.group).shortName;
    EXPECT_EQ(s.classifier.method, r.method) << name;
    // Each family has its own feature kind; the default model takes its family's.
    EXPECT_EQ(defaultFeatures(r.group, kGmm), r.features) << name;
    EXPECT_EQ(defaultFeatures(r.group, kTrees), r.treeFeatures) << name;
    EXPECT_EQ(s.features, r.method == kTrees ? r.treeFeatures : r.features) << name;
    EXPECT_EQ(s.classifier.gmm.components, r.order) << name;
    EXPECT_DOUBLE_EQ(s.classifier.gmm.varianceFloor, r.floor) << name;
    EXPECT_DOUBLE_EQ(defaultEmissionWeight(r.group, kGmm), r.mixtureWeight) << name;
    EXPECT_DOUBLE_EQ(defaultEmissionWeight(r.group, kTrees), r.treeWeight) << name;
    EXPECT_DOUBLE_EQ(s.emissionWeight, r.method == kTrees ? r.treeWeight : r.mixtureWeight) << name;
    EXPECT_EQ(s.classifier.gbt.trees, r.trees) << name;
    EXPECT_EQ(s.classifier.gbt.depth, r.depth) << name;
    // Learning rate and min child weight are the method's defaults in every group.
    EXPECT_DOUBLE_EQ(s.classifier.gbt.learningRate, GbtSettings{}.learningRate) << name;
    EXPECT_DOUBLE_EQ(s.classifier.gbt.minChildWeight, GbtSettings{}.minChildWeight) << name;
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
  s.classifier.gmm.varianceFloor = 0.01;
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
  s.classifier.gmm.varianceFloor = 0.01;
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

// Boosted trees have neither order, form nor floor: one cell per combination of their own
// settings, seed and decision, whatever the mixtures' lists hold.
TEST(Sweep, TreeCellsSweepTheirOwnSettings) {
  SweepGrid g;
  g.groups = {SensorGroup::Right, SensorGroup::Front};
  g.methods = {ClassifierMethod::Gbt};
  g.treeCounts = {50, 100, 200};
  g.depths = {4, 6, 8};
  g.learningRates = {0.1, 0.3};
  g.seeds = {1, 2};
  g.decisions = {DecisionMode::Step, DecisionMode::Online};
  const std::vector<SweepCell> cells = expandGrid(g);
  ASSERT_EQ(cells.size(), 2u * 3u * 3u * 2u * 1u * 2u * 2u);
  std::set<std::tuple<int, int, int, double, std::uint64_t, DecisionMode>> distinct;
  for (const SweepCell& c : cells) {
    EXPECT_EQ(c.method, ClassifierMethod::Gbt);
    EXPECT_EQ(c.order, 1);
    EXPECT_EQ(c.varianceFloor, 0.0);
    EXPECT_EQ(c.minChildWeight, 1.0);
    distinct.insert({groupIndex(c.group), c.trees, c.depth, c.learningRate, c.seed, c.decision});
    const GbtSettings s = cellTreeSettings(c);
    EXPECT_EQ(s.trees, c.trees);
    EXPECT_EQ(s.depth, c.depth);
    EXPECT_EQ(s.seed, c.seed);
    const ClassifierOptions o = cellClassifierOptions(g, c);
    EXPECT_EQ(o.method, ClassifierMethod::Gbt);
    EXPECT_EQ(o.gbt.learningRate, c.learningRate);
    EXPECT_EQ(o.gmm.seed, c.seed);
  }
  EXPECT_EQ(distinct.size(), cells.size());
  // Cells differing only in the decision share one fit.
  EXPECT_EQ(fitJobs(cells).size(), cells.size() / 2);
  // Deeper and longer boosting costs more in the scheduler's units.
  SweepCell small = cells.front(), big = cells.front();
  big.trees = 200;
  big.depth = 8;
  EXPECT_GT(sweepCellUnits(big, 1000, 100), sweepCellUnits(small, 1000, 100));
  // The mixtures' lists do not multiply the trees' cells.
  g.orders = {1, 2, 4, 8};
  g.varianceFloors = {0.01, 0.1};
  EXPECT_EQ(expandGrid(g).size(), cells.size());
  // Gaussian cells are scored with every decision mode too.
  g.methods = {ClassifierMethod::Gaussian};
  EXPECT_EQ(expandGrid(g).size(), 2u * 2u * 2u * 2u);
}

TEST(Sweep, BadTreeSettingsAreRefusedByTheGridCheck) {
  SweepGrid g;
  g.methods = {ClassifierMethod::Gbt};
  EXPECT_TRUE(checkSweepGrid(g).ok());
  g.depths = {6, 0};
  const Status bad = checkSweepGrid(g);
  ASSERT_FALSE(bad.ok());
  EXPECT_NE(bad.errorText().find("depth"), std::string::npos) << bad.errorText();
  g.depths = {6};
  g.learningRates = {};
  EXPECT_FALSE(checkSweepGrid(g).ok());
  // Floors are the mixtures' setting: a trees-only grid needs none.
  g.learningRates = {0.1};
  g.varianceFloors = {};
  EXPECT_TRUE(checkSweepGrid(g).ok());
  g.methods.push_back(ClassifierMethod::Gmm);
  EXPECT_FALSE(checkSweepGrid(g).ok());
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
    EXPECT_EQ(x.cell.varianceFloor, y.cell.varianceFloor);
    EXPECT_EQ(x.ok, y.ok) << x.reason << " / " << y.reason;
    EXPECT_EQ(x.confusion, y.confusion);
    EXPECT_EQ(x.iterations, y.iterations);
    EXPECT_EQ(x.meanLogLikelihood, y.meanLogLikelihood);  // bit for bit
  }
}

// An exception in a worker thread (out of memory, here thrown by the progress callback the
// workers call after the first call, which the calling thread makes before they start) reaches the
// caller instead of ending the process.
TEST(Sweep, AnExceptionInAWorkerReachesTheCaller) {
  const Fixture& f = fixture();
  std::vector<LabelledRun> train, test;
  splitLabelledRuns(f.runs, 0.3, train, test);
  SweepOptions two;
  two.threads = 2;
  std::atomic<int> calls{0};
  const ProgressFn progress = [&](std::size_t, std::size_t) -> bool {
    if (calls++ == 0) return true;
    throw std::bad_alloc();
  };
  EXPECT_THROW((void)runSweep(train, test, smallGrid(), two, progress), std::bad_alloc);
  EXPECT_GE(calls.load(), 2);
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

// An online cell is scored with the class chain weighing the evidence as the group's trained
// models do (its default emission weight), so a model trained with the cell's settings scores
// exactly as the cell. On noisy data the weight changes the online decisions (checked here, so
// the test can tell a sweep that leaves the weight at 1 from one that uses the default).
TEST(Sweep, OnlineCellsDecideWithTheGroupsDefaultEmissionWeight) {
  RunData a = testdata::makeLabelledRun(1500, 31, 2.0);
  RunData b = testdata::makeLabelledRun(1500, 32, 2.0);
  std::vector<LabelledRun> runs{{&a, labelsFromTruth(a)}, {&b, labelsFromTruth(b)}};
  std::vector<LabelledRun> train, test;
  splitLabelledRuns(runs, 0.4, train, test);
  SweepGrid grid;
  grid.groups = {SensorGroup::Right};
  grid.orders = {1};
  grid.forms = {CovarianceForm::NodalDiag};
  grid.varianceFloors = {0.1};
  grid.decisions = {DecisionMode::Online};
  grid.maxIterations = 30;
  const double weight = defaultEmissionWeight(SensorGroup::Right, ClassifierMethod::Gmm);
  ASSERT_NE(weight, 1.0) << "the test needs a group whose mixtures' default weight is not 1";
  const SweepResult r = runSweep(train, test, grid);
  ASSERT_EQ(r.cells.size(), 1u);
  const SweepCellResult& cell = r.cells.front();
  ASSERT_TRUE(cell.ok) << cell.reason;

  TrainSettings settings;
  settings.features = cell.cell.features;
  settings.classifier = cellClassifierOptions(grid, cell.cell);
  const GroupDataSet trainData = buildGroupDataSet(train, SensorGroup::Right, settings.features);
  const GroupDataSet testData = buildGroupDataSet(test, SensorGroup::Right, settings.features);
  const auto online = static_cast<std::size_t>(DecisionMode::Online);
  // The evaluation needs a trained model: a failed training stops the test (ASSERT_).
  auto onlineConfusion = [&](double w, ConfusionMatrix& out) {
    settings.emissionWeight = w;
    const GroupTrainResult trained = trainGroupModel(trainData, settings);
    ASSERT_TRUE(trained.ok) << trained.reason;
    out = evaluateGroupModel(trained.model, testData).byDecision[online];
  };
  ConfusionMatrix withDefault;
  ConfusionMatrix withOne;
  ASSERT_NO_FATAL_FAILURE(onlineConfusion(weight, withDefault));
  ASSERT_NO_FATAL_FAILURE(onlineConfusion(1.0, withOne));
  ASSERT_NE(withDefault, withOne) << "the data does not tell the weights apart";
  EXPECT_EQ(cell.confusion, withDefault);
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

// A grid whose cells cover failed cells (no data in group B), the Gaussian method, warnings (a
// variance floor far above the features' variance) and several seeds.
SweepResult mixedSweep() {
  const Fixture& f = fixture();
  std::vector<LabelledRun> train, test;
  splitLabelledRuns(f.runs, 0.3, train, test);
  for (LabelledRun& lr : train) {
    for (std::size_t t = 0; t < lr.run->stepCount(); ++t)
      lr.labels[t * kGroupCount + groupIndex(SensorGroup::Back)].reset();
  }
  SweepGrid g;
  g.groups = {SensorGroup::Right, SensorGroup::Back};
  g.methods = {ClassifierMethod::Gaussian, ClassifierMethod::Gmm, ClassifierMethod::Gbt};
  g.orders = {1, 2};
  g.forms = {CovarianceForm::NodalDiag, CovarianceForm::GrandFull};
  g.varianceFloors = {0.01, 1000.0};
  g.treeCounts = {3, 8};
  g.depths = {2};
  g.learningRates = {0.3};
  g.minChildWeights = {0.5};
  g.seeds = {1, 7};
  g.regularization = Regularization::Add;
  g.init = GmmInit::RandomFromData;
  g.restarts = 2;
  g.maxIterations = 25;
  g.tolerance = 1e-4;
  g.priors = PriorMode::Empirical;
  SweepResult r = runSweep(train, test, g);
  r.cancelled = true;  // so the flag is written as true too
  return r;
}

// sweepFromJson reads back everything sweepToJson writes.
TEST(Sweep, JsonRoundTripReadsBackEveryField) {
  const SweepResult r = mixedSweep();
  bool anyFailed = false, anyWarning = false;
  for (const SweepCellResult& c : r.cells) {
    anyFailed = anyFailed || !c.ok;
    anyWarning = anyWarning || !c.warnings.empty();
  }
  ASSERT_TRUE(anyFailed);
  ASSERT_TRUE(anyWarning);
  const nlohmann::json j = nlohmann::json::parse(sweepToJson(r).dump());
  const Result<SweepResult> read = sweepFromJson(j);
  ASSERT_TRUE(read.ok()) << read.errorText();
  const SweepResult& back = read.value();
  // Grid.
  const SweepGrid &g = r.grid, &h = back.grid;
  EXPECT_EQ(h.groups, g.groups);
  EXPECT_EQ(h.methods, g.methods);
  EXPECT_EQ(h.orders, g.orders);
  EXPECT_EQ(h.forms, g.forms);
  EXPECT_EQ(h.varianceFloors, g.varianceFloors);
  EXPECT_EQ(h.treeCounts, g.treeCounts);
  EXPECT_EQ(h.depths, g.depths);
  EXPECT_EQ(h.learningRates, g.learningRates);
  EXPECT_EQ(h.minChildWeights, g.minChildWeights);
  EXPECT_EQ(h.features, g.features);
  EXPECT_EQ(h.seeds, g.seeds);
  EXPECT_EQ(h.regularization, g.regularization);
  EXPECT_EQ(h.init, g.init);
  EXPECT_EQ(h.restarts, g.restarts);
  EXPECT_EQ(h.maxIterations, g.maxIterations);
  EXPECT_EQ(h.tolerance, g.tolerance);
  EXPECT_EQ(h.priors, g.priors);
  // Run.
  EXPECT_EQ(back.threads, r.threads);
  EXPECT_EQ(back.wallSeconds, r.wallSeconds);
  EXPECT_EQ(back.extractSeconds, r.extractSeconds);
  EXPECT_EQ(back.cancelled, r.cancelled);
  // Data summaries.
  ASSERT_EQ(back.data.size(), r.data.size());
  for (std::size_t i = 0; i < r.data.size(); ++i) {
    const SweepDataSummary &x = r.data[i], &y = back.data[i];
    EXPECT_EQ(y.group, x.group);
    EXPECT_EQ(y.features, x.features);
    EXPECT_EQ(y.trainRows, x.trainRows);
    EXPECT_EQ(y.testRows, x.testRows);
    EXPECT_EQ(y.trainCounts, x.trainCounts);
    EXPECT_EQ(y.testCounts, x.testCounts);
    EXPECT_EQ(y.trainZeroRows, x.trainZeroRows);
    EXPECT_EQ(y.testZeroRows, x.testZeroRows);
  }
  // Cells.
  ASSERT_EQ(back.cells.size(), r.cells.size());
  for (std::size_t i = 0; i < r.cells.size(); ++i) {
    const SweepCellResult &x = r.cells[i], &y = back.cells[i];
    EXPECT_EQ(y.cell.group, x.cell.group);
    EXPECT_EQ(y.cell.method, x.cell.method);
    EXPECT_EQ(y.cell.order, x.cell.order);
    EXPECT_EQ(y.cell.form, x.cell.form);
    EXPECT_EQ(y.cell.varianceFloor, x.cell.varianceFloor);
    EXPECT_EQ(y.cell.features, x.cell.features);
    EXPECT_EQ(y.cell.seed, x.cell.seed);
    EXPECT_TRUE(y.cell == x.cell);  // the trees' settings too
    EXPECT_EQ(y.ok, x.ok);
    EXPECT_EQ(y.reason, x.reason);
    EXPECT_EQ(y.classes, x.classes);
    EXPECT_EQ(y.unmodelled, x.unmodelled);
    EXPECT_EQ(y.trainRows, x.trainRows);
    EXPECT_EQ(y.testRows, x.testRows);
    EXPECT_EQ(y.fitSeconds, x.fitSeconds);
    EXPECT_EQ(y.predictSeconds, x.predictSeconds);
    EXPECT_EQ(y.iterations, x.iterations);
    EXPECT_EQ(y.maxIterations, x.maxIterations);
    EXPECT_EQ(y.converged, x.converged);
    EXPECT_EQ(y.confusion, x.confusion);
    EXPECT_EQ(y.metrics.total, x.metrics.total);
    EXPECT_EQ(y.metrics.accuracy, x.metrics.accuracy);
    EXPECT_EQ(y.metrics.balancedAccuracy, x.metrics.balancedAccuracy);
    EXPECT_EQ(y.metrics.macroF1, x.metrics.macroF1);
    EXPECT_EQ(y.meanLogLikelihood, x.meanLogLikelihood);
    EXPECT_EQ(y.negInfRows, x.negInfRows);
    EXPECT_EQ(y.droppedComponents, x.droppedComponents);
    EXPECT_EQ(y.warnings, x.warnings);
  }
  // Written again, the re-read result gives the same file.
  EXPECT_EQ(sweepToJson(back), sweepToJson(r));
  // The report tables render both the live and the re-read result the same way.
  EXPECT_EQ(sweepReport(back, TableStyle::Csv), sweepReport(r, TableStyle::Csv));
  EXPECT_EQ(sweepReport(back, TableStyle::Csv).find("nan"), std::string::npos);
}

// The families side by side: each group's best cell of each method, the trees' settings in their
// own column (empty for the mixtures, whose order and floor are empty for the trees), squares for
// the trees in the run time against error figure.
TEST(Sweep, ReportsPutTheFamiliesSideBySide) {
  const SweepResult r = mixedSweep();
  bool treesFitted = false;
  for (const SweepCellResult& c : r.cells)
    treesFitted = treesFitted || (c.ok && c.cell.method == ClassifierMethod::Gbt);
  ASSERT_TRUE(treesFitted);
  ASSERT_TRUE(mixesMethods(r));
  const Table t = bestCellsByMethodTable(r);
  const auto column = [&t](const std::string& name) {
    return static_cast<std::size_t>(std::find(t.header.begin(), t.header.end(), name) -
                                    t.header.begin());
  };
  ASSERT_LT(column("trees"), t.header.size());
  std::set<std::string> methodsOfRight;
  for (const auto& row : t.rows) {
    if (row[column("group")] != "R") continue;
    methodsOfRight.insert(row[column("method")]);
    const bool trees = row[column("method")] == "gbt";
    EXPECT_EQ(row[column("trees")].empty(), !trees);
    EXPECT_EQ(row[column("order")].empty(), trees);
    EXPECT_EQ(row[column("floor")].empty(), trees);
  }
  EXPECT_EQ(methodsOfRight, (std::set<std::string>{"gaussian", "gbt", "gmm"}));
  const std::string report = sweepReport(r, TableStyle::Markdown);
  EXPECT_NE(report.find("Best cell per group and method"), std::string::npos);
  EXPECT_NE(report.find("3 trees, depth 2, rate 0.3, min child weight 0.5"), std::string::npos);
  const std::vector<SweepFigure> figures = sweepFigures(r);
  const SweepFigure& timeError = figures.back();
  EXPECT_NE(timeError.svg.find("width=\"6\" height=\"6\""), std::string::npos);
  EXPECT_NE(timeError.svg.find("squares: boosted trees"), std::string::npos);
  // The rate figures are over orders and floors, which trees do not have.
  for (const RateSeries& series : rateSeries(r, SweptVariable::Order))
    EXPECT_NE(series.method, ClassifierMethod::Gbt);
}

// Cancellation reaches the running fits: progress is consulted after every EM iteration, so a
// cancel returned while the first cell is fitting stops it at once and nothing is kept.
TEST(Sweep, CancelStopsARunningFitWithinOneIteration) {
  const Fixture& f = fixture();
  SweepGrid g = smallGrid();
  g.groups = {SensorGroup::Right};
  g.tolerance = 0.0;
  g.maxIterations = 500;
  SweepOptions o;
  o.threads = 1;
  int calls = 0;
  std::size_t lastDone = 0;
  const SweepResult r = runSweep(f.runs, f.runs, g, o, [&](std::size_t done, std::size_t) {
    lastDone = done;
    return ++calls < 10;  // call 1 is the start; calls 2..10 come from the first cell's fits
  });
  EXPECT_TRUE(r.cancelled);
  EXPECT_EQ(calls, 10);  // nothing consulted after the cancel
  EXPECT_EQ(lastDone, 0u);
  EXPECT_TRUE(r.cells.empty());
}

// Cells finished before a cancel are kept (and were reported through onCell); the cell whose fit
// was running is stopped within one iteration and is not a result.
TEST(Sweep, CancelKeepsFinishedCells) {
  const Fixture& f = fixture();
  SweepGrid g = smallGrid();
  g.groups = {SensorGroup::Right};
  g.tolerance = 0.0;
  g.maxIterations = 500;
  SweepOptions o;
  o.threads = 1;
  std::vector<SweepCellResult> reported;
  o.onCell = [&](const SweepCellResult& c) { reported.push_back(c); };
  int callsAfterFirstCell = 0;
  const SweepResult r = runSweep(f.runs, f.runs, g, o, [&](std::size_t done, std::size_t) {
    if (done == 0) return true;
    EXPECT_EQ(done, 1u);
    return ++callsAfterFirstCell < 3;  // cancel inside the second cell's fits
  });
  EXPECT_TRUE(r.cancelled);
  EXPECT_EQ(callsAfterFirstCell, 3);
  ASSERT_EQ(r.cells.size(), 1u);
  EXPECT_TRUE(r.cells[0].ok);
  ASSERT_EQ(reported.size(), 1u);
  EXPECT_EQ(reported[0].cell.order, r.cells[0].cell.order);
  EXPECT_EQ(reported[0].cell.form, r.cells[0].cell.form);
  EXPECT_EQ(reported[0].confusion, r.cells[0].confusion);
}

// onCell sees every cell once, as it finishes, with the result that ends up in the sweep.
TEST(Sweep, OnCellReportsEveryCellAsItFinishes) {
  const Fixture& f = fixture();
  std::vector<LabelledRun> train, test;
  splitLabelledRuns(f.runs, 0.3, train, test);
  SweepOptions o;
  o.threads = 2;
  std::vector<SweepCellResult> reported;
  std::size_t doneWhenReported = 0;
  bool inOrder = true;
  o.onCell = [&](const SweepCellResult& c) { reported.push_back(c); };
  const SweepResult r = runSweep(train, test, smallGrid(), o, [&](std::size_t done, std::size_t) {
    // Progress for a finished cell comes right after its onCell call.
    if (done > doneWhenReported) {
      inOrder = inOrder && done == reported.size();
      doneWhenReported = done;
    }
    return true;
  });
  EXPECT_TRUE(inOrder);
  ASSERT_EQ(reported.size(), r.cells.size());
  std::size_t matched = 0;
  for (const SweepCellResult& c : reported) {
    for (const SweepCellResult& x : r.cells) {
      if (x.cell.group == c.cell.group && x.cell.order == c.cell.order &&
          x.cell.form == c.cell.form && x.cell.varianceFloor == c.cell.varianceFloor) {
        EXPECT_EQ(x.confusion, c.confusion);
        EXPECT_EQ(x.meanLogLikelihood, c.meanLogLikelihood);
        ++matched;
      }
    }
  }
  EXPECT_EQ(matched, r.cells.size());
}

// A held-out row with zero density is counted in neg_inf_rows and left out of the mean, the same
// way as `tactile fit` (one definition, heldOutLogLikelihood).
TEST(Training, NegInfRowsAreCountedNotAveraged) {
  const Fixture& f = fixture();
  const GroupDataSet data = buildGroupDataSet(f.runs, SensorGroup::Right, FeatureKind::Normal);
  TrainSettings s;
  s.classifier.gmm.components = 2;
  const GroupTrainResult r = trainGroupModel(data, s);
  ASSERT_TRUE(r.ok) << r.reason;
  GroupDataSet test = data;
  const GroupEvaluation clean = evaluateGroupModel(r.model, test);
  EXPECT_EQ(clean.negInfRows, 0u);
  test.x(0, 0) = 1e200;
  const GroupEvaluation ev = evaluateGroupModel(r.model, test);
  EXPECT_EQ(ev.negInfRows, 1u);
  ASSERT_TRUE(ev.meanLogLikelihood.has_value());
  EXPECT_TRUE(std::isfinite(*ev.meanLogLikelihood));
  // The model file's metrics carry the count.
  GroupModel m = r.model;
  m.evaluation.negInfRows = ev.negInfRows;
  m.evaluation.meanLogLikelihood = ev.meanLogLikelihood;
  EXPECT_EQ(evaluationToJson(m)["neg_inf_rows"], 1);
}

TEST(Sweep, NotASweepFileIsAnError) {
  const auto model = sweepFromJson(nlohmann::json{{"format", "tactile-model"}});
  ASSERT_FALSE(model.ok());
  EXPECT_NE(model.errorText().find("not a sweep file"), std::string::npos);
  EXPECT_FALSE(sweepFromJson(nlohmann::json{{"format", "tactile-sweep"}, {"version", 1}}).ok());
}

}  // namespace
}  // namespace tactile::analysis
