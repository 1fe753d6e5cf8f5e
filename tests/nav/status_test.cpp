// The online decision of the model source and the hole memory.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>

#include "analysis/classify_run.h"
#include "analysis/training.h"
#include "nav/contact_status.h"
#include "nav/hole_memory.h"
#include "nav/navigate.h"
#include "sim/scene_source.h"
#include "sim/world.h"
#include "tests/analysis/learn_test_data.h"

namespace tactile::nav {
namespace {

// The model source decides with the learning part's online decision: step for step what
// classifyRun decides online on the same run (the command of each step goes with its values); a
// group without a model reads Wall while it touches and NoContact while it does not.
TEST(ModelStatusEstimator, DecidesAsTheOnlineClassificationOfTheRun) {
  const RunData run = testdata::makeLabelledRun(1200, 11);
  std::vector<analysis::LabelledRun> runs{{&run, analysis::labelsFromTruth(run)}};
  const analysis::GroupDataSet data =
      analysis::buildGroupDataSet(runs, SensorGroup::Right, analysis::FeatureKind::Normal);
  analysis::TrainSettings settings;
  settings.classifier.method = analysis::ClassifierMethod::Gmm;
  settings.classifier.gmm.components = 2;
  settings.classifier.gmm.seed = 5;
  analysis::GroupTrainResult trained = analysis::trainGroupModel(data, settings);
  ASSERT_TRUE(trained.ok) << trained.reason;
  auto bundle = std::make_shared<analysis::ModelBundle>();
  bundle->models.push_back(std::move(trained.model));
  const analysis::RunClassification batch =
      analysis::classifyRun(run, *bundle, analysis::ClassifyOptions{});
  const analysis::GroupClassification& right = batch.groups[groupIndex(SensorGroup::Right)];
  ASSERT_EQ(right.decided.size(), run.stepCount());

  ModelStatusEstimator estimator(bundle);
  std::size_t compared = 0;
  std::size_t leftTouching = 0;
  for (std::size_t t = 0; t < run.stepCount(); ++t) {
    std::array<double, kValuesPerStep> values{};
    const double* step = run.stepSensors(t);
    std::copy(step, step + kValuesPerStep, values.begin());
    estimator.command(run.v[t], run.omega[t]);
    const GroupClasses& out = estimator.update(values, nullptr);
    const auto r = static_cast<std::size_t>(groupIndex(SensorGroup::Right));
    if (right.decided[t]) {
      ASSERT_TRUE(out[r].has_value());
      EXPECT_EQ(*out[r], right.model->classes[static_cast<std::size_t>(*right.decided[t])])
          << "step " << t;
      ++compared;
    } else if (!groupTouches(values, SensorGroup::Right)) {
      EXPECT_EQ(out[r], ContactClass::NoContact) << "step " << t;
    }
    const auto l = static_cast<std::size_t>(groupIndex(SensorGroup::Left));
    const bool touches = groupTouches(values, SensorGroup::Left);
    leftTouching += touches ? 1 : 0;
    EXPECT_EQ(out[l], touches ? ContactClass::Wall : ContactClass::NoContact) << "step " << t;
  }
  EXPECT_GT(compared, 100u);
  EXPECT_GT(leftTouching, 0u);
}

// With the motion features at dt 0.05 the navigator's model statuses are the online decisions
// `tactile classify` takes on the recorded run (which reads the run's dt), one row later; and the
// estimator hands the step length on to its decider.
TEST(ModelStatusEstimator, NavigatorDecidesAsClassifyOnItsRunAtAnotherStepLength) {
  const RunData train = testdata::makeLabelledRun(3000, 12);
  std::vector<analysis::LabelledRun> runs{{&train, analysis::labelsFromTruth(train)}};
  auto bundle = std::make_shared<analysis::ModelBundle>();
  for (SensorGroup g : {SensorGroup::Right, SensorGroup::Left}) {
    const analysis::GroupDataSet data =
        analysis::buildGroupDataSet(runs, g, analysis::FeatureKind::Motion);
    analysis::TrainSettings settings;
    settings.features = analysis::FeatureKind::Motion;
    settings.classifier.method = analysis::ClassifierMethod::Gmm;
    settings.classifier.gmm.components = 2;
    settings.classifier.gmm.seed = 5;
    analysis::GroupTrainResult trained = analysis::trainGroupModel(data, settings);
    ASSERT_TRUE(trained.ok) << trained.reason;
    bundle->models.push_back(std::move(trained.model));
  }
  auto scene = sim::loadScene("chapter5");
  ASSERT_TRUE(scene.ok());
  auto world = std::make_shared<const sim::World>(std::move(scene.value()));
  NavigatorConfig config;
  config.source = StatusSource::Model;
  config.models = bundle;
  NavigateOptions options;
  options.maxSteps = 4000;
  options.sim.dtSeconds = 0.05;
  auto r = navigate(world, "chapter5", drawStart(world, 1), world->scene().goal, config, options);
  ASSERT_TRUE(r.ok()) << r.errorText();
  const RunData& run = r->run;
  const analysis::RunClassification batch =
      analysis::classifyRun(run, *bundle, analysis::ClassifyOptions{});
  std::size_t compared = 0;
  for (SensorGroup g : {SensorGroup::Right, SensorGroup::Left}) {
    const analysis::GroupClassification& c = batch.groups[groupIndex(g)];
    const std::string column = "x_status_" + std::string(groupInfo(g).shortName);
    const auto it = std::find(run.extraColumns.begin(), run.extraColumns.end(), column);
    ASSERT_NE(it, run.extraColumns.end()) << column;
    const auto col = static_cast<std::size_t>(it - run.extraColumns.begin());
    // Row t + 1 carries the status the navigator chose row t + 1's command by: its decision on
    // the readings of row t.
    for (std::size_t t = 0; t + 1 < run.stepCount(); ++t) {
      if (!c.decided[t]) continue;
      const std::string& recorded = run.extraValues[(t + 1) * run.extraColumns.size() + col];
      const ContactClass expected = c.model->classes[static_cast<std::size_t>(*c.decided[t])];
      // A side's status may read as a hole instead (its width); every class reading must agree.
      if (!parseContactClass(recorded)) continue;
      EXPECT_EQ(recorded, contactClassName(expected)) << column << " step " << t;
      ++compared;
    }
  }
  EXPECT_GT(compared, 30u);

  // The estimator hands the step length to its decider (non-positive: the simulator's default).
  ModelStatusEstimator estimator(bundle);
  estimator.setStepSeconds(0.05);
  EXPECT_DOUBLE_EQ(estimator.decider().stepSeconds(), 0.05);
  estimator.setStepSeconds(0.0);
  EXPECT_DOUBLE_EQ(estimator.decider().stepSeconds(), analysis::kDefaultStepSeconds);
}

TEST(HoleMemory, ReadingsOfOneOpeningMergeIntoTheMeanWidth) {
  HoleMemory m;
  const Pose2d p{0, 0, 0};
  EXPECT_EQ(m.observe(100.0, p, Vec2(0, 50), true, 1, 0), 0u);
  EXPECT_EQ(m.observe(120.0, p, Vec2(10, 50), true, 2, 0), 0u);
  EXPECT_EQ(m.observe(110.0, p, Vec2(20, 50), true, 3, 0), 0u);
  ASSERT_EQ(m.holes().size(), 1u);
  EXPECT_DOUBLE_EQ(m.holes()[0].widthUnits, 110.0);
  EXPECT_DOUBLE_EQ(m.holes()[0].centre.x(), 10.0);
  EXPECT_EQ(m.holes()[0].step, 3u);
  // Far away, or on another wall: another hole.
  EXPECT_EQ(m.observe(90.0, p, Vec2(200, 50), true, 4, 0), 1u);
  EXPECT_EQ(m.observe(150.0, p, Vec2(10, 50), true, 5, 1), 2u);
  EXPECT_EQ(m.holes().size(), 3u);
}

TEST(HoleMemory, WidestPassableSkipsNarrowTriedAndOtherWalls) {
  HoleMemory m;
  const Pose2d p{0, 0, 0};
  m.observe(90.0, p, Vec2(0, 0), true, 1, 0);     // 0: too narrow
  m.observe(110.0, p, Vec2(200, 0), true, 2, 0);  // 1
  m.observe(130.0, p, Vec2(400, 0), true, 3, 0);  // 2: widest
  m.observe(300.0, p, Vec2(600, 0), true, 4, 1);  // 3: another wall
  EXPECT_EQ(m.widestPassable(100.0, 0), 2u);
  EXPECT_EQ(m.widestPassable(100.0, -1), 3u);
  m.markTried(2);
  EXPECT_EQ(m.widestPassable(100.0, 0), 1u);
  EXPECT_TRUE(m.nearTried(Vec2(420, 0), 50.0));
  EXPECT_FALSE(m.nearTried(Vec2(200, 0), 50.0));
  m.markTried(1);
  EXPECT_FALSE(m.widestPassable(100.0, 0));
  // Exactly the threshold is not wider than it.
  HoleMemory e;
  e.observe(100.0, p, Vec2(0, 0), true, 1, 0);
  EXPECT_FALSE(e.widestPassable(100.0, 0));
}

TEST(StatusEstimators, BumperIsBinaryAndTruthIsCopied) {
  std::array<double, kValuesPerStep> v{};
  v[static_cast<std::size_t>(normalOffset(12))] = 0.01;
  v[static_cast<std::size_t>(shearOffset(33))] = -0.5;  // shear alone touches too
  BumperStatusEstimator bumper;
  const GroupClasses& b = bumper.update(v, nullptr);
  EXPECT_EQ(b[groupIndex(SensorGroup::Left)], ContactClass::Wall);
  EXPECT_EQ(b[groupIndex(SensorGroup::Right)], ContactClass::Wall);
  EXPECT_EQ(b[groupIndex(SensorGroup::Front)], ContactClass::NoContact);
  std::array<ContactClass, kGroupCount> truth{};
  truth[2] = ContactClass::Corner;
  TruthStatusEstimator t;
  EXPECT_EQ(t.update(v, &truth)[2], ContactClass::Corner);
  EXPECT_EQ(t.update(v, nullptr)[2], ContactClass::NoContact);
}

}  // namespace
}  // namespace tactile::nav
