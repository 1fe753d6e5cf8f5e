// The online decision of the model source and the hole memory.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "analysis/temporal.h"
#include "nav/contact_status.h"
#include "nav/hole_memory.h"

namespace tactile::nav {
namespace {

// The step-by-step filter gives what the whole-run forward filter gives at every step, episode
// by episode (steps without contact restart it).
TEST(OnlineGroupDecider, MatchesTheWholeRunForwardFilter) {
  std::mt19937_64 rng(7);
  std::normal_distribution<double> noise(0.0, 3.0);
  const int steps = 60;
  const int classes = 4;
  analysis::StepLikelihoods sl;
  sl.logLik.resize(steps, classes);
  sl.observed.assign(steps, 1);
  for (int t = 0; t < steps; ++t)
    for (int c = 0; c < classes; ++c)
      sl.logLik(t, c) = noise(rng) - (c == (t / 15) % classes ? 0.0 : 2.0);
  sl.observed[20] = 0;
  sl.observed[41] = 0;
  sl.logPriors = Eigen::VectorXd::Constant(classes, -std::log(double(classes)));
  for (double stay : {0.25, 0.9, 0.99}) {
    const analysis::HmmFilterResult batch = analysis::hmmForwardFilter(sl, stay);
    OnlineGroupDecider online(sl.logPriors, stay);
    for (int t = 0; t < steps; ++t) {
      if (!sl.observed[t]) {
        online.reset();
        continue;
      }
      const int c = online.push(sl.logLik.row(t).transpose());
      ASSERT_TRUE(batch.decisions[t]);
      EXPECT_EQ(c, *batch.decisions[t]) << "stay " << stay << " step " << t;
      EXPECT_NEAR(std::log(online.confidence()), batch.logPosterior(t, c), 1e-9);
    }
  }
}

TEST(OnlineGroupDecider, UnderflowAndOneClassStayFinite) {
  OnlineGroupDecider one(Eigen::VectorXd::Zero(1), 0.9);
  EXPECT_EQ(one.push(Eigen::VectorXd::Constant(1, -1e300)), 0);
  EXPECT_DOUBLE_EQ(one.confidence(), 1.0);
  const double inf = std::numeric_limits<double>::infinity();
  OnlineGroupDecider two(Eigen::VectorXd::Constant(2, std::log(0.5)), 0.9);
  Eigen::VectorXd l(2);
  l << -inf, -inf;
  const int c = two.push(l);
  EXPECT_TRUE(c == 0 || c == 1);
  EXPECT_TRUE(std::isfinite(two.confidence()));
  l << 0.0, -5.0;
  EXPECT_EQ(two.push(l), 0);
  EXPECT_GT(two.confidence(), 0.5);
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
