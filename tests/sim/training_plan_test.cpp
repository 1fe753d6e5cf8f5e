#include <gtest/gtest.h>

#include <memory>
#include <string>

#include "sim/recorder.h"
#include "sim/training_plan.h"
#include "sim/truth_stats.h"
#include "sim/world.h"

namespace tactile::sim {
namespace {

RunData simulatePlanned(std::uint64_t seed, std::size_t index) {
  PlannedRun planned = planTrainingRun(seed, index);
  auto world = std::make_shared<const World>(std::move(planned.scene));
  RunResult result = simulateRunWith(world, "test", *planned.driver, planned.options);
  EXPECT_TRUE(result.ok()) << (result.ok() ? "" : result.errorText());
  return result.ok() ? std::move(result->run) : RunData{};
}

TEST(TrainingPlan, SameSeedAndIndexGiveTheSameRun) {
  for (std::size_t i : {2u, 3u, 6u}) {
    const RunData a = simulatePlanned(7, i);
    const RunData b = simulatePlanned(7, i);
    ASSERT_GT(a.stepCount(), 0u);
    EXPECT_TRUE(a == b) << "run " << i;
  }
  // Another seed gives another run of the same kind.
  EXPECT_EQ(planTrainingRun(7, 2).kind, planTrainingRun(8, 2).kind);
  EXPECT_FALSE(simulatePlanned(7, 2) == simulatePlanned(8, 2));
}

TEST(TrainingPlan, KindsComeInTurn) {
  EXPECT_EQ(planTrainingRun(1, 0).kind, "wall-follow");
  EXPECT_EQ(planTrainingRun(1, 1).kind, "cluttered");
  EXPECT_EQ(planTrainingRun(1, 2).kind, "wall-end");
  EXPECT_EQ(planTrainingRun(1, 6).kind, "pocket");
  EXPECT_EQ(planTrainingRun(1, kTrainingPlanKinds).kind, "wall-follow");
  // Generated scenes have no name to resolve; built-in and procedural ones do.
  EXPECT_EQ(planTrainingRun(1, 0).sceneName, "room1");
  EXPECT_TRUE(planTrainingRun(1, 1).sceneName.starts_with("random:"));
  EXPECT_TRUE(planTrainingRun(1, 2).sceneName.empty());
}

TEST(TrainingPlan, ThePocketRunShowsDeadPathInFrontAndSideGroups) {
  const RunData run = simulatePlanned(1, 6);
  TruthStats stats;
  stats.add(run);
  for (SensorGroup g : {SensorGroup::Front, SensorGroup::FrontLeftCorner,
                        SensorGroup::FrontRightCorner, SensorGroup::Left, SensorGroup::Right}) {
    EXPECT_GT(stats.classSteps[static_cast<std::size_t>(groupIndex(g))]
                              [static_cast<std::size_t>(ContactClass::DeadPath)],
              20)
        << groupInfo(g).shortName;
  }
  EXPECT_EQ(stats.classSteps[static_cast<std::size_t>(groupIndex(SensorGroup::Back))]
                            [static_cast<std::size_t>(ContactClass::DeadPath)],
            0);
}

TEST(TruthStats, CountsClassesChangesAndBlockedStepsWithoutReadings) {
  RunData run;
  std::array<double, kValuesPerStep> zero{};
  std::array<double, kValuesPerStep> touch{};
  touch[normalOffset(33)] = 2.0;  // a dome of R
  std::array<ContactClass, kGroupCount> t{};
  // R: Wall, Wall, LeavingWall, NoContact, Corner: one change between contact classes.
  const ContactClass r[] = {ContactClass::Wall, ContactClass::Wall, ContactClass::LeavingWall,
                            ContactClass::NoContact, ContactClass::Corner};
  const bool blocked[] = {false, true, true, false, false};
  for (int k = 0; k < 5; ++k) {
    t.fill(ContactClass::NoContact);
    t[static_cast<std::size_t>(groupIndex(SensorGroup::Right))] = r[k];
    run.appendStep(0, 0, 0, 0, 0, blocked[k], k == 2 ? zero.data() : touch.data(), t.data());
  }
  TruthStats stats;
  stats.add(run);
  const auto R = static_cast<std::size_t>(groupIndex(SensorGroup::Right));
  EXPECT_EQ(stats.classSteps[R][static_cast<std::size_t>(ContactClass::Wall)], 2);
  EXPECT_EQ(stats.contactSteps(SensorGroup::Right), 4);
  EXPECT_EQ(stats.contactChanges[R], 1);
  EXPECT_DOUBLE_EQ(stats.changesPer100ContactSteps(SensorGroup::Right), 25.0);
  EXPECT_EQ(stats.blockedSteps, 2);
  EXPECT_EQ(stats.blockedWithoutReadings, 1);
  EXPECT_DOUBLE_EQ(stats.blockedWithoutReadingsShare(), 0.5);
  EXPECT_DOUBLE_EQ(stats.changesPer100ContactSteps(SensorGroup::Back), 0.0);  // no contact
}

}  // namespace
}  // namespace tactile::sim
