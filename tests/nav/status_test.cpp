// The online decision of the model source and the hole memory.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "analysis/classify_run.h"
#include "analysis/training.h"
#include "nav/contact_status.h"
#include "nav/hole_memory.h"
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
