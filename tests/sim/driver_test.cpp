#include <gtest/gtest.h>

#include <algorithm>
#include <initializer_list>

#include "run/run_csv.h"
#include "sim/driver.h"
#include "sim/recorder.h"
#include "sim_test_util.h"

namespace tactile::sim {
namespace {

using Values = std::array<double, kValuesPerStep>;

// Sets the normal values of the first domes of group g (the rest of the step stays as it is).
void press(Values& values, SensorGroup g, std::initializer_list<double> normals) {
  int d = groupInfo(g).firstSensor;
  for (double n : normals)
    values[normalOffset(d++)] = n;
}

Values pressed(SensorGroup g, std::initializer_list<double> normals) {
  Values values{};
  press(values, g, normals);
  return values;
}

TEST(FollowWallAction, LargestValueAboveFourTurnsAway) {
  // Mean of the touching domes 1.875 would turn toward; the maximum wins.
  EXPECT_EQ(followWallAction(pressed(SensorGroup::Right, {4.5, 1.0, 1.0, 1.0}), true),
            FollowAction::Away);
}

TEST(FollowWallAction, TouchingMeanAboveThreeTurnsAway) {
  EXPECT_EQ(followWallAction(pressed(SensorGroup::Right, {3.9, 3.1}), true), FollowAction::Away);
}

TEST(FollowWallAction, LargestValueBelowHalfTurnsToward) {
  EXPECT_EQ(followWallAction(pressed(SensorGroup::Right, {0.4, 0.4, 0.3}), true),
            FollowAction::Toward);
}

TEST(FollowWallAction, TouchingMeanBelowTwoTurnsToward) {
  EXPECT_EQ(followWallAction(pressed(SensorGroup::Right, {1.9, 1.1}), true), FollowAction::Toward);
}

TEST(FollowWallAction, NothingTouchingTurnsToward) {
  EXPECT_EQ(followWallAction(Values{}, true), FollowAction::Toward);
  EXPECT_EQ(followWallAction(Values{}, false), FollowAction::Toward);
}

TEST(FollowWallAction, ModeratePressureGoesStraight) {
  // Max 3.0, mean of the two touching domes 2.5; the eight untouched domes of R do not count.
  EXPECT_EQ(followWallAction(pressed(SensorGroup::Right, {3.0, 2.0}), true),
            FollowAction::Straight);
}

TEST(FollowWallAction, ThresholdsAreStrict) {
  // Exactly 4 is not above 4, exactly 3 is not above 3, exactly 2 is not below 2.
  EXPECT_EQ(followWallAction(pressed(SensorGroup::Right, {4.0, 2.0}), true),
            FollowAction::Straight);
  EXPECT_EQ(followWallAction(pressed(SensorGroup::Right, {3.0, 3.0}), true),
            FollowAction::Straight);
  EXPECT_EQ(followWallAction(pressed(SensorGroup::Right, {2.0, 2.0}), true),
            FollowAction::Straight);
}

TEST(FollowWallAction, LeftSideUsesTheLeftGroupsOnly) {
  Values values = pressed(SensorGroup::Left, {3.0, 2.0});
  press(values, SensorGroup::Right, {4.8, 4.8});
  press(values, SensorGroup::FrontRightCorner, {4.9});
  EXPECT_EQ(followWallAction(values, false), FollowAction::Straight);
  // The same step read for a wall on the right sees only the pressed right side.
  EXPECT_EQ(followWallAction(values, true), FollowAction::Away);
}

TEST(FollowWallAction, RightSideIgnoresTheLeftGroups) {
  Values values = pressed(SensorGroup::Right, {3.0, 2.0});
  press(values, SensorGroup::Left, {0.2});
  press(values, SensorGroup::FrontLeftCorner, {4.9, 4.9});
  EXPECT_EQ(followWallAction(values, true), FollowAction::Straight);
  EXPECT_EQ(followWallAction(values, false), FollowAction::Away);
}

TEST(FollowWallAction, CornerGroupsBelongToTheirSide) {
  // A pressed front-right corner alone turns away from a wall on the right ...
  EXPECT_EQ(followWallAction(pressed(SensorGroup::FrontRightCorner, {4.5}), true),
            FollowAction::Away);
  // ... and the rear-left corner's light touch pulls the left side's mean below 2.
  Values values = pressed(SensorGroup::Left, {2.5, 2.5});
  EXPECT_EQ(followWallAction(values, false), FollowAction::Straight);
  press(values, SensorGroup::RearLeftCorner, {0.2, 0.2});
  EXPECT_EQ(followWallAction(values, false), FollowAction::Toward);
}

// Observation of a robot far from its goal that sees `values` and is blocked or not.
Observation observe(const Values& values, bool blocked, std::size_t step) {
  Observation obs;
  obs.step = step;
  obs.pose = {500, 500, 0};
  obs.start = {100, 500, 0};
  obs.goal = Vec2(1900, 500);
  obs.blocked = blocked;
  obs.values = &values;
  return obs;
}

TEST(WallFollowDriver, BlockedStepsTryAPlainForwardEscape) {
  // Regression: the escape list had no plain forward move, so a robot wedged at the edge of a
  // hole with the way ahead free stayed wedged for thousands of steps.
  const Values values = pressed(SensorGroup::Front, {1.0});
  WallFollowDriver driver(7);
  driver.next(observe(values, true, 0));  // first blocked step: not an escape yet
  bool forward = false;
  Command previous{1e9, 1e9};
  for (std::size_t k = 1; k <= 8; ++k) {
    const Command c = driver.next(observe(values, true, k));
    forward = forward || (c.v > 0.0 && c.omega == 0.0);
    // Each blocked step tries the next manoeuvre.
    EXPECT_FALSE(c.v == previous.v && c.omega == previous.omega) << k;
    previous = c;
  }
  EXPECT_TRUE(forward);
}

TEST(WallFollowDriver, EveryStepAfterTheFirstContactCountsTowardGivingUp) {
  const Values values = pressed(SensorGroup::Front, {1.0});
  WallFollowDriver driver(3);
  std::size_t k = 0;
  driver.next(observe(values, true, k++));  // the first contact
  for (; k <= WallFollowDriver::kGiveUpSteps - 1; ++k) {
    driver.next(observe(values, k % 3 == 0, k));
    ASSERT_FALSE(driver.finished().has_value()) << k;
  }
  driver.next(observe(values, true, k));
  EXPECT_TRUE(driver.gaveUp());
  EXPECT_FALSE(driver.unreachable());
  EXPECT_EQ(driver.finished(), RunOutcome::GaveUp);
  const Command after = driver.next(observe(values, false, k + 1));
  EXPECT_EQ(after.v, 0.0);
  EXPECT_EQ(after.omega, 0.0);
}

TEST(WallFollowDriver, FinishedStaysEmptyWithoutContact) {
  const Values values{};
  WallFollowDriver driver(1);
  for (std::size_t k = 0; k < WallFollowDriver::kGiveUpSteps + 100; ++k) {
    driver.next(observe(values, false, k));
  }
  EXPECT_FALSE(driver.finished().has_value());
}

TEST(RunOutcome, UnreachableHasAFileName) {
  EXPECT_EQ(runOutcomeName(RunOutcome::Unreachable), "unreachable");
  EXPECT_EQ(parseRunOutcome("unreachable"), RunOutcome::Unreachable);
  EXPECT_EQ(parseRunOutcome("timeout"), RunOutcome::Timeout);
}

// A 1200 x 800 room cut in two by a wall from the bottom to the top bound: the robot starts in
// the west half, the goal lies in the east half.
Scene splitRoom() {
  Scene s;
  s.name = "split";
  s.bounds = {0, 0, 1200, 800};
  s.obstacles = {test::box(600, 0, 620, 800)};
  s.start = {200, 400, 0};
  s.goal = Vec2(1000, 400);
  return s;
}

TEST(WallFollowRun, WalkingRoundAClosedRoomEndsUnreachable) {
  const auto world = std::make_shared<const World>(splitRoom());
  bool sawLeft = false;
  bool sawRight = false;
  for (std::uint64_t seed = 1; seed <= 6; ++seed) {
    RunOptions options;
    options.maxSteps = 8000;
    options.seed = seed;
    RunResult r = simulateRun(world, "split", options);
    ASSERT_TRUE(r.ok()) << r.errorText();
    EXPECT_EQ(r->outcome, RunOutcome::Unreachable) << "seed " << seed;
    EXPECT_LT(r->run.stepCount(), options.maxSteps) << "seed " << seed;
    ASSERT_NE(r->run.meta("outcome"), nullptr);
    EXPECT_EQ(*r->run.meta("outcome"), "unreachable");
    // The outcome survives the run file.
    RunCsvResult back = parseRunCsv(formatRunCsv(r->run), "split.csv");
    ASSERT_TRUE(back.ok()) << back.errorText();
    EXPECT_EQ(back.value().outcome(), RunOutcome::Unreachable);
    (WallFollowDriver(seed).wallOnRight() ? sawRight : sawLeft) = true;
  }
  // Both following sides walk round the room.
  EXPECT_TRUE(sawLeft);
  EXPECT_TRUE(sawRight);
}

// Contact steps of a group over a run.
std::size_t contactSteps(const RunData& run, SensorGroup g) {
  const GroupInfo& info = groupInfo(g);
  std::size_t n = 0;
  for (std::size_t k = 0; k < run.stepCount(); ++k) {
    for (int d = info.firstSensor; d < info.firstSensor + info.sensorCount; ++d) {
      if (run.normal(k, d) > 0.0) {
        ++n;
        break;
      }
    }
  }
  return n;
}

TEST(FollowSide, NamesRoundTrip) {
  for (FollowSide side : {FollowSide::Left, FollowSide::Right})
    EXPECT_EQ(parseFollowSide(followSideName(side)), side);
  EXPECT_FALSE(parseFollowSide("Left").has_value());
  EXPECT_FALSE(parseFollowSide("").has_value());
}

// A given side overrides the seed's; the seed's other draws stay: a run with the side the seed
// would have drawn anyway is the default run, step for step.
TEST(FollowSide, OverridesTheSeedAndNothingElse) {
  const auto world = std::make_shared<const World>(splitRoom());
  for (std::uint64_t seed = 1; seed <= 6; ++seed) {
    for (FollowSide side : {FollowSide::Left, FollowSide::Right}) {
      WallFollowDriver::Options o;
      o.side = side;
      EXPECT_EQ(WallFollowDriver(seed, o).wallOnRight(), side == FollowSide::Right) << seed;
      const bool own = WallFollowDriver(seed).wallOnRight() == (side == FollowSide::Right);
      for (const char* driver : {"wall-follow", "bug"}) {
        RunOptions options;
        options.maxSteps = 1500;
        options.seed = seed;
        options.driver = driver;
        options.followSide = side;
        RunResult forced = simulateRun(world, "split", options);
        ASSERT_TRUE(forced.ok()) << forced.errorText();
        options.followSide.reset();
        RunResult drawn = simulateRun(world, "split", options);
        ASSERT_TRUE(drawn.ok()) << drawn.errorText();
        if (std::string(driver) == "wall-follow") {
          EXPECT_EQ(formatRunCsv(forced->run) == formatRunCsv(drawn->run), own)
              << driver << " seed " << seed;
        }
        // The followed side's group touches the wall, the other side's hardly.
        const RunData& run = forced->run;
        const SensorGroup near = side == FollowSide::Left ? SensorGroup::Left : SensorGroup::Right;
        const SensorGroup far = side == FollowSide::Left ? SensorGroup::Right : SensorGroup::Left;
        EXPECT_GT(contactSteps(run, near), 200u) << driver << " seed " << seed;
        EXPECT_GT(contactSteps(run, near), 5 * contactSteps(run, far))
            << driver << " seed " << seed;
      }
    }
  }
}

TEST(FollowSide, OnlyTheWallFollowersTakeASide) {
  EXPECT_NE(makeDriver("wall-follow", 1, FollowSide::Left), nullptr);
  EXPECT_NE(makeDriver("bug", 1, FollowSide::Right), nullptr);
  EXPECT_EQ(makeDriver("random", 1, FollowSide::Left), nullptr);
  EXPECT_NE(makeDriver("random", 1, std::nullopt), nullptr);
  RunOptions options;
  options.driver = "random";
  options.followSide = FollowSide::Left;
  RunResult r = simulateRun(std::make_shared<const World>(splitRoom()), "split", options);
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.errorText().find("follows no wall"), std::string::npos) << r.errorText();
}

TEST(WallFollowRun, ARobotThatKeepsBeingBlockedGivesUpInsteadOfTimingOut) {
  // A closed slot barely longer and wider than the robot: it can neither turn nor get out, and
  // never gets far from where it first touched, so only the step budget ends the run.
  Scene s = test::roomWith({test::box(300, 300, 670, 400), test::box(300, 510, 670, 610),
                            test::box(300, 400, 400, 510), test::box(570, 400, 670, 510)},
                           Pose2d{444, 455, 0});
  s.goal = Vec2(1800, 1800);
  RunOptions options;
  options.maxSteps = 8000;
  RunResult r = simulateRun(std::make_shared<const World>(s), "slot", options);
  ASSERT_TRUE(r.ok()) << r.errorText();
  EXPECT_EQ(r->outcome, RunOutcome::GaveUp);
  EXPECT_GE(r->run.stepCount(), WallFollowDriver::kGiveUpSteps);
  EXPECT_LT(r->run.stepCount(), options.maxSteps);
  std::size_t blocked = 0;
  for (std::uint8_t b : r->run.blocked)
    blocked += b;
  EXPECT_GT(blocked, r->run.stepCount() / 10);
}

TEST(BugDriver, IsSelectableByName) {
  const auto names = autonomousDriverNames();
  EXPECT_NE(std::find(names.begin(), names.end(), "bug"), names.end());
  const std::unique_ptr<Driver> d = makeDriver("bug", 3);
  ASSERT_NE(d, nullptr);
  EXPECT_EQ(d->name(), "bug");
}

// A wall across the middle of the room with the start-goal line through it; the wall ends 300
// units short of the top and bottom bounds, so following it either way leads round it.
TEST(BugRun, GoesRoundAWallToTheGoal) {
  Scene s;
  s.name = "wall";
  s.bounds = {0, 0, 1600, 1600};
  s.obstacles = {test::box(780, 300, 820, 1300)};
  s.start = {300, 800, 0};
  s.goal = Vec2(1300, 800);
  const auto world = std::make_shared<const World>(s);
  for (std::uint64_t seed = 1; seed <= 6; ++seed) {
    RunOptions options;
    options.maxSteps = 6000;
    options.seed = seed;
    options.driver = "bug";
    RunResult r = simulateRun(world, "wall", options);
    ASSERT_TRUE(r.ok()) << r.errorText();
    EXPECT_EQ(r->outcome, RunOutcome::Success) << "seed " << seed;
    EXPECT_EQ(*r->run.meta("driver"), "bug");
    // It touched the wall on the way.
    std::size_t touching = 0;
    for (std::size_t k = 0; k < r->run.stepCount(); ++k) {
      for (int d = 0; d < kSensorCount; ++d) {
        if (r->run.normal(k, d) > 0.0) {
          ++touching;
          break;
        }
      }
    }
    EXPECT_GT(touching, 50u) << "seed " << seed;
  }
}

// In the split room the Bug driver walks round the room once on one side, once on the other,
// then ends unreachable: later than the wall follower with the same seed, never by the step limit.
TEST(BugRun, AClosedRoomIsWalkedRoundBothWaysThenUnreachable) {
  const auto world = std::make_shared<const World>(splitRoom());
  for (std::uint64_t seed = 1; seed <= 4; ++seed) {
    RunOptions options;
    options.maxSteps = 20000;
    options.seed = seed;
    options.driver = "bug";
    RunResult bug = simulateRun(world, "split", options);
    ASSERT_TRUE(bug.ok()) << bug.errorText();
    EXPECT_EQ(bug->outcome, RunOutcome::Unreachable) << "seed " << seed;
    options.driver = "wall-follow";
    RunResult follower = simulateRun(world, "split", options);
    ASSERT_TRUE(follower.ok()) << follower.errorText();
    ASSERT_EQ(follower->outcome, RunOutcome::Unreachable) << "seed " << seed;
    EXPECT_GT(bug->run.stepCount(), follower->run.stepCount() * 3 / 2) << "seed " << seed;
  }
}

}  // namespace
}  // namespace tactile::sim
