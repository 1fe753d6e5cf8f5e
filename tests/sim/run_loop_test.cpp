// The step-at-a-time run loop (the simulator window's) against simulateRunWith, and start/goal
// drawing for experiment runs.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "sim/recorder.h"
#include "sim/scene_source.h"
#include "sim/start_goal.h"
#include "sim/training_plan.h"
#include "tests/run_compare.h"

namespace tactile::sim {
namespace {

std::shared_ptr<const World> worldOf(const char* spec) {
  Result<Scene> r = loadScene(spec);
  EXPECT_TRUE(r.ok()) << r.errorText();
  return std::make_shared<const World>(std::move(r.value()));
}

TEST(RunLoop, SteppedWithADriverEqualsSimulateRun) {
  RunOptions options;
  options.maxSteps = 700;
  options.seed = 3;
  options.driver = "wall-follow";
  auto world = worldOf("room1");
  RunResult whole = simulateRun(world, "room1", options);
  ASSERT_TRUE(whole.ok());
  auto loop = RunLoop::start(world, "room1", "wall-follow", options);
  ASSERT_TRUE(loop.ok());
  WallFollowDriver driver(options.seed);
  loop.value()->recorder().setMeta("driver", "wall-follow");
  loop.value()->recorder().setMeta("seed", "3");
  std::size_t steps = 0;
  while (!loop.value()->ended()) {
    loop.value()->step(driver);
    ++steps;
  }
  EXPECT_EQ(steps, whole->run.stepCount());
  EXPECT_EQ(loop.value()->outcome(), whole->outcome);
  RunData stepped = loop.value()->take();
  test_support::expectSameRun(stepped, whole->run);
}

TEST(RunLoop, GivenCommandsEqualAScriptDriverReplayingThem) {
  auto world = worldOf("practice");
  RunOptions options;
  options.maxSteps = 300;
  std::vector<Command> commands;
  for (int k = 0; k < 300; ++k)
    commands.push_back({k < 150 ? 60.0 : -20.0, k % 40 < 20 ? 0.3 : -0.25});
  auto loop = RunLoop::start(world, "practice", "manual", options);
  ASSERT_TRUE(loop.ok());
  for (const Command& c : commands)
    loop.value()->step(c);
  std::vector<ScriptDriver::Leg> legs;
  for (const Command& c : commands)
    legs.push_back({c, 1});
  ScriptDriver script(std::move(legs));
  RunResult replay = simulateRunWith(world, "practice", script, options);
  ASSERT_TRUE(replay.ok());
  RunData a = loop.value()->take();
  ASSERT_EQ(a.stepCount(), replay->run.stepCount());
  EXPECT_EQ(a.x, replay->run.x);
  EXPECT_EQ(a.theta, replay->run.theta);
  EXPECT_EQ(a.blocked, replay->run.blocked);
  EXPECT_EQ(a.sensors, replay->run.sensors);
  EXPECT_EQ(a.truth, replay->run.truth);
  // Something happened: the robot touched the box or the walls.
  EXPECT_NE(std::count(a.blocked.begin(), a.blocked.end(), 1), 0);
}

TEST(RunLoop, EndsOnceWithTheGivenOutcomeAndStepsNoMore) {
  RunOptions options;
  options.maxSteps = 50;
  auto loop = RunLoop::start(worldOf("practice"), "practice", "manual", options);
  ASSERT_TRUE(loop.ok());
  loop.value()->step(Command{20, 0});
  loop.value()->end(RunOutcome::GaveUp);
  EXPECT_EQ(loop.value()->step(Command{20, 0}), RunOutcome::GaveUp);
  loop.value()->end(RunOutcome::Success);  // no effect once ended
  RunData run = loop.value()->take();
  EXPECT_EQ(run.stepCount(), 1u);
  EXPECT_EQ(run.outcome(), RunOutcome::GaveUp);
  // The time limit: maxSteps steps then timeout.
  auto timed = RunLoop::start(worldOf("practice"), "practice", "manual", options);
  std::optional<RunOutcome> last;
  for (int k = 0; k < 50; ++k)
    last = timed.value()->step(Command{0, 0.1});
  EXPECT_EQ(last, RunOutcome::Timeout);
}

TEST(StartGoal, DrawnFromTheSeedInFreeSpaceFarApart) {
  for (const char* spec : {"room1", "room3", "chapter5", "random:40:2"}) {
    Result<Scene> scene = loadScene(spec);
    ASSERT_TRUE(scene.ok());
    Result<Scene> a = drawStartGoal(scene.value(), 7);
    Result<Scene> b = drawStartGoal(scene.value(), 7);
    Result<Scene> c = drawStartGoal(scene.value(), 8);
    ASSERT_TRUE(a.ok() && b.ok() && c.ok()) << spec;
    EXPECT_EQ(a->start.x, b->start.x);
    EXPECT_EQ(a->goal, b->goal);
    EXPECT_NE(a->start.x, c->start.x);
    const auto& bd = scene->bounds;
    const double diagonal = std::hypot(bd.xmax - bd.xmin, bd.ymax - bd.ymin);
    EXPECT_GE((a->goal - Vec2(a->start.x, a->start.y)).norm(), diagonal / 3.0) << spec;
    // The robot stands there touching nothing, and the drawn scene passes the scene checks.

    Simulator sim(std::make_shared<const World>(a.value()));
    const PoseContact contact = sim.evaluate(a->start);
    EXPECT_FALSE(contact.blocked);
    for (const DomeContact& d : contact.domes)
      EXPECT_EQ(d.edge, -1) << spec;
    EXPECT_TRUE(validateSceneGeometry(a.value()).ok()) << spec;
    EXPECT_TRUE(checkStartPose(a.value()).ok()) << spec;
  }
}

TEST(StartGoal, FailsClearlyWhenTheRoomHasNoSpace) {
  Scene tiny;
  tiny.name = "tiny";
  tiny.bounds = {0, 0, 150, 150};
  tiny.start = {20, 75, 0};
  tiny.goal = Vec2(100, 75);
  Result<Scene> drawn = drawStartGoal(tiny, 1);
  ASSERT_FALSE(drawn.ok());
  EXPECT_NE(drawn.errorText().find("tiny"), std::string::npos);
}

}  // namespace
}  // namespace tactile::sim
