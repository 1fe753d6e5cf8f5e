// The motion feature kinds: context taken over how far the domes moved, not over steps, and
// without the robot's speed (docs/analysis.md#features-featuresh).
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "analysis/classify_run.h"
#include "analysis/features.h"
#include "analysis/model_file.h"
#include "analysis/online_decider.h"
#include "analysis/training.h"
#include "tests/analysis/learn_test_data.h"

namespace tactile::analysis {
namespace {

constexpr SensorGroup kRight = SensorGroup::Right;

// Where the motion kinds' feature blocks begin in a group's row.
struct Layout {
  int change = 0;   // first of sensorCount scaled changes
  int into = 0;     // direction of motion: into what the group touches
  int along = 0;    // direction of motion: along the outline, counter-clockwise
  int contact = 0;  // contact travel / cap
};
Layout layoutOf(SensorGroup g) {
  const int n = groupInfo(g).sensorCount;
  Layout l;
  l.change = 2 * n + kTouchFlags;
  l.into = l.change + n;
  l.along = l.into + 1;
  l.contact = l.along + 1;
  return l;
}

// A run in which the right group's domes read n = slope * (units the group has travelled), with
// the command (v, omega) at every step; dt from the run's metadata when given.
RunData rampRun(std::size_t steps, double v, double omega, double slope, double dt = 0.0) {
  RunData run;
  if (dt > 0.0) run.setMeta("dt", std::to_string(dt));
  const double stepDt = dt > 0.0 ? dt : kDefaultStepSeconds;
  const GroupInfo& info = groupInfo(kRight);
  double travelled = 0.0;
  for (std::size_t t = 0; t < steps; ++t) {
    travelled += groupStepMotion(kRight, v, omega, stepDt);
    auto values = testdata::zeroStep();
    for (int i = 0; i < info.sensorCount; ++i) {
      values[static_cast<std::size_t>(normalOffset(info.firstSensor + i))] =
          0.5 + slope * travelled;
      values[static_cast<std::size_t>(shearOffset(info.firstSensor + i))] = 0.1;
    }
    run.appendStep(0, 0, 0, v, omega, false, values.data(), nullptr);
  }
  return run;
}

std::vector<double> featuresAt(const RunData& run, std::size_t t, SensorGroup g, FeatureKind k) {
  std::vector<double> row(static_cast<std::size_t>(featureDimension(g, k)));
  groupFeatures(run, t, g, k, row.data());
  return row;
}

TEST(MotionFeatures, NamesDimensionsAndVersions) {
  EXPECT_EQ(featureKindName(FeatureKind::Motion), "normal+shear+touch+motion");
  EXPECT_EQ(featureKindName(FeatureKind::MotionNeighbours), "normal+shear+touch+motion+neighbours");
  EXPECT_EQ(parseFeatureKind("normal+shear+touch+motion"), FeatureKind::Motion);
  for (const GroupInfo& info : kSensorGroups) {
    EXPECT_EQ(featureDimension(info.group, FeatureKind::Motion),
              featureDimension(info.group, FeatureKind::Context));
    EXPECT_EQ(featureDimension(info.group, FeatureKind::MotionNeighbours),
              featureDimension(info.group, FeatureKind::Neighbours));
  }
  EXPECT_TRUE(usesHistory(FeatureKind::Motion));
  EXPECT_TRUE(usesNeighbours(FeatureKind::MotionNeighbours));
  EXPECT_FALSE(usesMotion(FeatureKind::Context));
  EXPECT_EQ(modelVersionFor(FeatureKind::Motion), 4);
  EXPECT_EQ(modelVersionFor(FeatureKind::MotionNeighbours), 4);
  EXPECT_EQ(modelVersionFor(FeatureKind::Neighbours), 3);
}

// A body point's speed under (v, omega): every group moves v dt driving straight; turning in place
// it moves omega * (its distance from the rear axle) * dt; turning left while driving, the left
// side moves slower than the right.
TEST(MotionFeatures, GroupMotionFollowsTheBody) {
  for (const GroupInfo& info : kSensorGroups) {
    EXPECT_DOUBLE_EQ(groupStepMotion(info.group, 20.0, 0.0, 0.1), 2.0) << info.shortName;
    EXPECT_DOUBLE_EQ(groupStepMotion(info.group, -20.0, 0.0, 0.1), 2.0) << info.shortName;
    EXPECT_DOUBLE_EQ(groupStepMotion(info.group, 0.0, 0.0, 0.1), 0.0);
    EXPECT_NEAR(groupStepMotion(info.group, 0.0, -0.5, 0.1), 0.05 * groupLeverArm(info.group),
                1e-12);
    EXPECT_EQ(groupStepMotion(info.group, NAN, 0.0, 0.1), 0.0);
    EXPECT_EQ(groupStepMotion(info.group, 1.0, INFINITY, 0.1), 0.0);
    EXPECT_EQ(groupStepMotion(info.group, 1.0, 0.0, 0.0), 0.0);
  }
  // The front's domes sit on the front edge, 105 units ahead of the rear axle; the back's 35
  // behind it.
  EXPECT_GE(groupLeverArm(SensorGroup::Front), 105.0);
  EXPECT_LT(groupLeverArm(SensorGroup::Front), std::hypot(105.0, 40.0));
  EXPECT_GE(groupLeverArm(SensorGroup::Back), 35.0);
  EXPECT_LT(groupLeverArm(SensorGroup::Back), std::hypot(35.0, 40.0));
  EXPECT_LT(groupStepMotion(SensorGroup::Left, 10.0, 0.2, 0.1),
            groupStepMotion(SensorGroup::Right, 10.0, 0.2, 0.1));
}

// The point of the kind: the same wall passed at 10 and at 50 units/s gives the same features
// (the change per kMotionSpan units of travel, the direction, the travel since contact), where
// the context kind's change grows with the speed.
TEST(MotionFeatures, TheSameContactAtAnySpeedReadsTheSame) {
  const double slope = 0.05;                           // n per unit travelled
  const RunData slow = rampRun(60, 10.0, 0.0, slope);  // 1 unit a step
  const RunData fast = rampRun(60, 50.0, 0.0, slope);  // 5 units a step
  const RunData mid = rampRun(60, 40.0, 0.0, slope);   // 4 units a step
  const Layout l = layoutOf(kRight);
  const int n = groupInfo(kRight).sensorCount;
  for (std::size_t t = 25; t < 60; ++t) {
    const auto a = featuresAt(slow, t, kRight, FeatureKind::Motion);
    const auto b = featuresAt(fast, t / 5, kRight, FeatureKind::Motion);
    const auto c = featuresAt(mid, t, kRight, FeatureKind::Motion);
    for (int i = 0; i < n; ++i) {
      EXPECT_NEAR(a[static_cast<std::size_t>(l.change + i)], slope * kMotionSpan, 1e-9) << t;
      EXPECT_NEAR(c[static_cast<std::size_t>(l.change + i)], slope * kMotionSpan, 1e-9) << t;
    }
    // Driving forward, the right side's domes move along its outline (counter-clockwise), not
    // into the wall.
    EXPECT_NEAR(a[static_cast<std::size_t>(l.into)], 0.0, 1e-12);
    EXPECT_NEAR(a[static_cast<std::size_t>(l.along)], 1.0, 1e-12);
    EXPECT_EQ(b[static_cast<std::size_t>(l.along)], a[static_cast<std::size_t>(l.along)]);
    // 20 units travelled: the contact travel is at its cap.
    EXPECT_EQ(a[static_cast<std::size_t>(l.contact)], 1.0);
    EXPECT_EQ(c[static_cast<std::size_t>(l.contact)], 1.0);
    if (t / 5 >= 5) {
      for (int i = 0; i < n; ++i)
        EXPECT_NEAR(b[static_cast<std::size_t>(l.change + i)], slope * kMotionSpan, 1e-9) << t;
      EXPECT_EQ(b[static_cast<std::size_t>(l.contact)], 1.0);
    }
  }
  // Early in the contact: travel since contact began, in units (slow: 1 a step; fast: 5).
  EXPECT_NEAR(featuresAt(slow, 6, kRight, FeatureKind::Motion)[static_cast<std::size_t>(l.contact)],
              6.0 / kMotionContactCap, 1e-12);
  EXPECT_NEAR(featuresAt(fast, 2, kRight, FeatureKind::Motion)[static_cast<std::size_t>(l.contact)],
              10.0 / kMotionContactCap, 1e-12);
  // The context kind reads the speed: its change over 3 steps is five times as large.
  const auto ctxSlow = featuresAt(slow, 30, kRight, FeatureKind::Context);
  const auto ctxFast = featuresAt(fast, 30, kRight, FeatureKind::Context);
  EXPECT_NEAR(ctxFast[static_cast<std::size_t>(l.change)],
              5.0 * ctxSlow[static_cast<std::size_t>(l.change)], 1e-9);
}

// Standing still: the lag is kMotionLagCap steps, the change unscaled, the direction and the
// contact travel 0; nothing is NaN.
TEST(MotionFeatures, StandingStill) {
  RunData run;
  const GroupInfo& info = groupInfo(kRight);
  for (std::size_t t = 0; t < 40; ++t) {
    auto values = testdata::zeroStep();
    for (int i = 0; i < info.sensorCount; ++i)
      values[static_cast<std::size_t>(normalOffset(info.firstSensor + i))] =
          1.0 + 0.01 * static_cast<double>(t);
    run.appendStep(0, 0, 0, 0.0, 0.0, false, values.data(), nullptr);
  }
  const Layout l = layoutOf(kRight);
  for (std::size_t t = 0; t < 40; ++t) {
    const auto f = featuresAt(run, t, kRight, FeatureKind::Motion);
    for (double x : f)
      ASSERT_TRUE(std::isfinite(x)) << t;
    // Before the run's first step the values count as zero.
    const double before =
        t >= kMotionLagCap ? 1.0 + 0.01 * static_cast<double>(t - kMotionLagCap) : 0.0;
    EXPECT_NEAR(f[static_cast<std::size_t>(l.change)], 1.0 + 0.01 * static_cast<double>(t) - before,
                1e-12)
        << t;
    EXPECT_EQ(f[static_cast<std::size_t>(l.into)], 0.0);
    EXPECT_EQ(f[static_cast<std::size_t>(l.along)], 0.0);
    EXPECT_EQ(f[static_cast<std::size_t>(l.contact)], 0.0);
  }
}

// Turning in place: the direction is the group point's (its arc's tangent), opposite for the
// opposite turn, and the lag is the steps the group's domes take to travel kMotionSpan on their
// arc. The front moves purely along its face turning in place and purely into what it touches
// driving forward; backing off reverses the direction.
TEST(MotionFeatures, TurningInPlaceAndBackingOff) {
  const Layout l = layoutOf(kRight);
  std::array<double, 2> left{};
  for (double omega : {0.8, -0.8}) {
    const double perStep = groupStepMotion(kRight, 0.0, omega, kDefaultStepSeconds);
    ASSERT_GT(perStep, 0.0);
    const RunData run = rampRun(40, 0.0, omega, 0.02);
    const auto f = featuresAt(run, 30, kRight, FeatureKind::Motion);
    const double into = f[static_cast<std::size_t>(l.into)];
    const double along = f[static_cast<std::size_t>(l.along)];
    EXPECT_NEAR(into * into + along * along, 1.0, 1e-12);
    if (omega > 0) {
      // Turning left, the right side swings away from what it touches and forward.
      EXPECT_LT(into, -0.3);
      EXPECT_GT(along, 0.3);
      left = {into, along};
    } else {
      EXPECT_DOUBLE_EQ(into, -left[0]);
      EXPECT_DOUBLE_EQ(along, -left[1]);
    }
    const auto lagSteps = static_cast<int>(std::ceil(kMotionSpan / perStep - 1e-9));
    const double travel = lagSteps * perStep;
    EXPECT_NEAR(f[static_cast<std::size_t>(l.change)],
                0.02 * travel * kMotionSpan / std::max(travel, kMotionSpan), 1e-9);
    const StepContext c = stepContextOf(run, 30, kRight, FeatureKind::Motion);
    EXPECT_EQ(c.laggedValues, run.stepSensors(30 - static_cast<std::size_t>(lagSteps)));
  }
  const auto turnF = groupMotionDirection(SensorGroup::Front, 0.0, 0.5);
  EXPECT_NEAR(turnF[0], 0.0, 1e-12);
  EXPECT_NEAR(turnF[1], 1.0, 1e-12);
  const auto driveF = groupMotionDirection(SensorGroup::Front, 30.0, 0.0);
  EXPECT_NEAR(driveF[0], 1.0, 1e-12);
  EXPECT_NEAR(driveF[1], 0.0, 1e-12);
  const auto backF = groupMotionDirection(SensorGroup::Front, -30.0, 0.0);
  EXPECT_NEAR(backF[0], -1.0, 1e-12);
  EXPECT_EQ(groupMotionDirection(SensorGroup::Front, 0.0, 0.0), (std::array<double, 2>{0.0, 0.0}));
  EXPECT_EQ(groupMotionDirection(SensorGroup::Front, NAN, 0.0), (std::array<double, 2>{0.0, 0.0}));
  const RunData back = rampRun(30, -20.0, 0.0, 0.02);
  const auto f = featuresAt(back, 20, kRight, FeatureKind::Motion);
  EXPECT_NEAR(f[static_cast<std::size_t>(l.along)], -1.0, 1e-12);
  // A slight steer while driving turns the direction slightly: the direction does not blow small
  // corrections up.
  const auto steer = groupMotionDirection(kRight, 30.0, 0.1);
  EXPECT_GT(steer[1], 0.99);
  EXPECT_LT(std::abs(steer[0]), 0.15);
}

// The run's dt: 20 units/s at dt 0.05 moves the domes as far per step as 10 at 0.1.
TEST(MotionFeatures, StepLengthFromTheRun) {
  const RunData a = rampRun(40, 10.0, 0.0, 0.03, 0.1);
  const RunData b = rampRun(40, 20.0, 0.0, 0.03, 0.05);
  EXPECT_EQ(stepSecondsOf(b), 0.05);
  EXPECT_EQ(stepSecondsOf(RunData{}), kDefaultStepSeconds);
  for (std::size_t t = 0; t < 40; ++t) {
    const auto fa = featuresAt(a, t, kRight, FeatureKind::Motion);
    const auto fb = featuresAt(b, t, kRight, FeatureKind::Motion);
    ASSERT_EQ(fa.size(), fb.size());
    for (std::size_t j = 0; j < fa.size(); ++j)
      EXPECT_NEAR(fa[j], fb[j], 1e-9) << t << " " << j;
  }
}

// A labelled run whose command changes every few steps among standing still, slow and fast
// driving, backing off, turning in place and arcs.
RunData movingLabelledRun(std::size_t steps, std::uint64_t seed) {
  RunData run = testdata::makeLabelledRun(steps, seed, 0.3, 0.8);
  std::mt19937_64 rng(seed + 1);
  std::uniform_int_distribution<int> pick(0, 6), length(1, 25);
  const double commands[7][2] = {{0, 0},   {10, 0},   {50, 0},  {-15, 0},
                                 {0, 0.8}, {0, -0.6}, {30, 0.3}};
  std::size_t t = 0;
  while (t < steps) {
    const int c = pick(rng);
    for (int k = length(rng); k > 0 && t < steps; --k, ++t) {
      run.v[t] = commands[c][0];
      run.omega[t] = commands[c][1];
    }
  }
  return run;
}

TrainSettings quickSettings(FeatureKind kind) {
  TrainSettings s;
  s.features = kind;
  s.classifier.method = ClassifierMethod::Gmm;
  s.classifier.gmm.components = 2;
  s.classifier.gmm.form = CovarianceForm::NodalFull;
  s.classifier.gmm.varianceFloor = 0.01;
  s.classifier.gmm.maxIterations = 15;
  s.classifier.gmm.restarts = 1;
  return s;
}

ModelBundle trainMotion(FeatureKind kind, const RunData& train) {
  TrainJob job;
  job.runs = {{&train, labelsFromTruth(train)}};
  job.settings = GroupSettings::same(quickSettings(kind));
  job.groups = {SensorGroup::Front, SensorGroup::FrontLeftCorner, SensorGroup::Right,
                SensorGroup::Back};
  auto out = trainAndEvaluate(job);
  EXPECT_TRUE(out.ok()) << out.errorText();
  return std::move(out->bundle);
}

// The stream form (the online decider fed step by step, what the navigator uses) computes the
// same feature rows as the run form, bit for bit, and decides what classify decides online; the
// run form equals the per-step context built by hand.
TEST(MotionFeatures, RunAndStreamAgree) {
  const RunData train = movingLabelledRun(2500, 31);
  for (FeatureKind kind : {FeatureKind::Motion, FeatureKind::MotionNeighbours}) {
    const ModelBundle bundle = trainMotion(kind, train);
    ASSERT_EQ(bundle.models.size(), 4u);
    for (double dt : {0.1, 0.05}) {
      RunData run = movingLabelledRun(900, 77);
      run.setMeta("dt", dt == 0.1 ? "0.1" : "0.05");
      OnlineDecider decider(bundle);
      decider.setStepSeconds(dt);
      ClassifyOptions options;
      options.decision = DecisionMode::Online;
      const RunClassification whole = classifyRun(run, bundle, options);
      std::size_t contact = 0, scaled = 0;
      for (std::size_t t = 0; t < run.stepCount(); ++t) {
        decider.update(run.stepSensors(t), run.v[t], run.omega[t]);
        for (const GroupModel& m : bundle.models) {
          const OnlineGroupState& s = decider.state(m.group);
          const auto expected = featuresAt(run, t, m.group, kind);
          const GroupClassification& gc =
              whole.groups[static_cast<std::size_t>(groupIndex(m.group))];
          ASSERT_EQ(std::string(contactClassName(*decider.decided(m.group))), gc.className(t)) << t;
          if (groupIsZero(run, t, m.group)) {
            EXPECT_EQ(s.features.size(), 0) << t;
            continue;
          }
          ++contact;
          ASSERT_EQ(s.features.size(), static_cast<Eigen::Index>(expected.size()));
          for (std::size_t j = 0; j < expected.size(); ++j)
            ASSERT_EQ(s.features(static_cast<Eigen::Index>(j)), expected[j]) << t << " " << j;
          // The lag was scaled (one step travelled more than kMotionSpan) at some steps.
          const StepContext c = stepContextOf(run, t, m.group, kind);
          scaled += c.laggedTravel > kMotionSpan ? 1 : 0;
        }
      }
      EXPECT_GT(contact, 1000u);
      EXPECT_GT(scaled, 100u);
    }
  }
}

// A model on the motion features is written as version 4 and reads back the same; a version-3
// file that names the kind is refused by name; a bundle takes the highest version.
TEST(MotionFeatures, ModelFileVersionFour) {
  const RunData train = movingLabelledRun(1500, 12);
  std::vector<LabelledRun> runs{{&train, labelsFromTruth(train)}};
  for (FeatureKind kind : {FeatureKind::Motion, FeatureKind::MotionNeighbours}) {
    const GroupDataSet data = buildGroupDataSet(runs, kRight, kind);
    ASSERT_GT(data.size(), 100u);
    for (Eigen::Index i = 0; i < data.x.rows(); ++i)
      ASSERT_TRUE(data.x.row(i).allFinite()) << i;
    GroupTrainResult r = trainGroupModel(data, quickSettings(kind));
    ASSERT_TRUE(r.ok) << r.reason;
    const nlohmann::json j = modelToJson(r.model);
    EXPECT_EQ(j["version"], 4);
    EXPECT_EQ(j["features"], std::string(featureKindName(kind)));
    const Result<ModelBundle> read = parseModelJson(j.dump(1), "m.json");
    ASSERT_TRUE(read.ok()) << read.errorText();
    EXPECT_EQ(read->models[0].features, kind);
    EXPECT_EQ(modelToJson(read->models[0]).dump(), j.dump());
    EXPECT_EQ(read->models[0].classifier.predict(data.x), r.model.classifier.predict(data.x));
    for (int older : {2, 3}) {
      nlohmann::json old = j;
      old["version"] = older;
      const Result<ModelBundle> refused = parseModelJson(old.dump(1), "old.json");
      ASSERT_FALSE(refused.ok());
      EXPECT_NE(refused.errorText().find(std::string(featureKindName(kind)) + " needs version 4"),
                std::string::npos)
          << refused.errorText();
    }
    ModelBundle bundle;
    bundle.models.push_back(std::move(r.model));
    EXPECT_EQ(bundleToJson(bundle)["version"], 4);
  }
}

}  // namespace
}  // namespace tactile::analysis
