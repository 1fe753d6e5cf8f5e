#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <mutex>
#include <set>
#include <string>

#include "run/builtin_scenes.h"
#include "sim/office_scene.h"
#include "sim/recorder.h"
#include "sim/scene_source.h"
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

// The plan index of the j-th run of the numbered kinds (the runs that are not office drives).
std::size_t numbered(std::size_t j) {
  for (std::size_t index = 0;; ++index) {
    const PlanSlot slot = trainingPlanSlot(index);
    if (slot.kind == PlanSlot::Kind::Numbered && slot.number == j) return index;
  }
}

TEST(TrainingPlan, SameSeedAndIndexGiveTheSameRun) {
  for (std::size_t i : {numbered(2), numbered(3), numbered(6), std::size_t{1}, std::size_t{5}}) {
    const RunData a = simulatePlanned(7, i);
    const RunData b = simulatePlanned(7, i);
    ASSERT_GT(a.stepCount(), 0u);
    EXPECT_TRUE(a == b) << "run " << i;
  }
  // Another seed gives another run of the same kind.
  EXPECT_EQ(planTrainingRun(7, numbered(2)).kind, planTrainingRun(8, numbered(2)).kind);
  EXPECT_FALSE(simulatePlanned(7, numbered(2)) == simulatePlanned(8, numbered(2)));
}

TEST(TrainingPlan, KindsComeInTurn) {
  EXPECT_EQ(planTrainingRun(1, numbered(0)).kind, "wall-follow");
  EXPECT_EQ(planTrainingRun(1, numbered(1)).kind, "cluttered");
  EXPECT_EQ(planTrainingRun(1, numbered(2)).kind, "wall-end");
  EXPECT_EQ(planTrainingRun(1, numbered(6)).kind, "pocket");
  EXPECT_EQ(planTrainingRun(1, numbered(kTrainingPlanKinds)).kind, "wall-follow");
  // Generated scenes have no name to resolve; built-in and procedural ones do.
  EXPECT_EQ(planTrainingRun(1, numbered(0)).sceneName, "room1");
  EXPECT_TRUE(planTrainingRun(1, numbered(1)).sceneName.starts_with("random:"));
  EXPECT_TRUE(planTrainingRun(1, numbered(2)).sceneName.empty());
}

// Every second run is an extra: two office drives (left, then right, in turn over the drives) and
// then a pocket. The numbered kinds between them are counted on their own.
TEST(TrainingPlan, EverySecondRunIsAnOfficeDriveOrAnExtraPocket) {
  // The documented size holds the first 40 numbered runs and an extra after the last of them.
  EXPECT_EQ(numbered(39), static_cast<std::size_t>(kTrainingPlanRuns) - 2);
  EXPECT_NE(trainingPlanSlot(static_cast<std::size_t>(kTrainingPlanRuns) - 1).kind,
            PlanSlot::Kind::Numbered);
  int left = 0, right = 0, pockets = 0;
  for (std::size_t index = 0; index < 24; ++index) {
    const PlannedRun run = planTrainingRun(3, index);
    const PlanSlot slot = trainingPlanSlot(index);
    if (index % 2 == 0) {
      EXPECT_EQ(slot.kind, PlanSlot::Kind::Numbered) << index;
      EXPECT_EQ(slot.number, index / 2) << index;
      EXPECT_FALSE(run.kind.starts_with("office drive") || run.kind == kExtraPocketKind) << index;
      continue;
    }
    if ((index / 2) % 3 == 2) {
      EXPECT_EQ(slot.kind, PlanSlot::Kind::ExtraPocket) << index;
      EXPECT_EQ(run.kind, kExtraPocketKind) << index;
      EXPECT_TRUE(run.sceneName.empty()) << index;
      ++pockets;
      continue;
    }
    ASSERT_EQ(slot.kind, PlanSlot::Kind::OfficeDrive) << index;
    const bool onLeft = slot.number % 2 == 0;
    EXPECT_EQ(run.kind, onLeft ? kOfficeDriveKindLeft : kOfficeDriveKindRight) << index;
    ASSERT_TRUE(run.options.followSide.has_value()) << index;
    EXPECT_EQ(*run.options.followSide, onLeft ? FollowSide::Left : FollowSide::Right);
    EXPECT_EQ(run.driver->name(), "wall-follow");
    EXPECT_TRUE(run.sceneName.starts_with("random:office:")) << run.sceneName;
    left += onLeft;
    right += !onLeft;
  }
  EXPECT_EQ(left, 4);
  EXPECT_EQ(right, 4);
  EXPECT_EQ(pockets, 4);
}

// The drives keep the wall on the side they are given: the left drives touch with L far more than
// with R, the right ones the other way round. The extra pockets show DeadPath like the numbered.
TEST(TrainingPlan, OfficeDrivesFollowTheWallOnTheirSideAndExtraPocketsShowDeadPath) {
  TruthStats left, right, pockets;
  for (std::size_t index = 1; index < 24; index += 2) {
    const PlanSlot slot = trainingPlanSlot(index);
    if (slot.kind == PlanSlot::Kind::ExtraPocket) {
      pockets.add(simulatePlanned(1, index));
    } else {
      (slot.number % 2 == 0 ? left : right).add(simulatePlanned(1, index));
    }
  }
  EXPECT_GT(left.contactSteps(SensorGroup::Left), 5 * left.contactSteps(SensorGroup::Right));
  EXPECT_GT(right.contactSteps(SensorGroup::Right), 5 * right.contactSteps(SensorGroup::Left));
  for (SensorGroup g : {SensorGroup::Front, SensorGroup::Left, SensorGroup::Right}) {
    EXPECT_GT(pockets.classSteps[static_cast<std::size_t>(groupIndex(g))]
                                [static_cast<std::size_t>(ContactClass::DeadPath)],
              4 * 20)
        << groupInfo(g).shortName;
  }
}

TEST(TrainingPlan, OfficeRunsDriveInGeneratedOfficesWithSeedsBelowTheBenchmarkRange) {
  EXPECT_EQ(planTrainingRun(1, numbered(10)).kind, "office bug");
  EXPECT_EQ(planTrainingRun(1, numbered(11)).kind, "office wall-follow");
  std::set<std::string> scenes;
  std::size_t officeRuns = 0;
  for (std::uint64_t seed : {1ull, 2ull, 99ull}) {
    for (std::size_t index = 0; index < 120; ++index) {
      const PlannedRun run = planTrainingRun(seed, index);
      if (!run.sceneName.starts_with("random:")) continue;
      // The scene seed: the last number of random:N:SEED or random:office:SEED.
      const std::uint64_t sceneSeed =
          std::stoull(run.sceneName.substr(run.sceneName.rfind(':') + 1));
      EXPECT_LT(sceneSeed, kFirstBenchmarkSceneSeed) << run.sceneName;
      if (run.kind.starts_with("office")) {
        ASSERT_TRUE(run.sceneName.starts_with("random:office:")) << run.sceneName;
        EXPECT_EQ(run.driver->name(), run.kind == "office bug" ? "bug" : "wall-follow");
        EXPECT_EQ(sceneToJson(run.scene), sceneToJson(generateOfficeScene(sceneSeed).scene));
        scenes.insert(run.sceneName);
        ++officeRuns;
      }
    }
  }
  // Every office run of these plans (bug, wall-follow and the drives) has a map of its own.
  EXPECT_GT(officeRuns, 3u * 20u);
  EXPECT_EQ(scenes.size(), officeRuns);
}

TEST(TrainingPlan, ThePocketRunShowsDeadPathInFrontAndSideGroups) {
  const RunData run = simulatePlanned(1, numbered(6));
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

// A tips run meets five tips round the start with the front and then with the back, each at its
// own lateral offset: every approach ends in contact, and between approaches the robot comes back
// to the start, so the tips' reach (140 units and more) stays clear of a turn in place.
TEST(TrainingPlan, TipsRunsMeetEveryTipWithTheFrontAndTheBack) {
  for (std::size_t index : {numbered(4), numbered(8)}) {
    ASSERT_EQ(planTrainingRun(1, index).kind, "tips");
    const RunData run = simulatePlanned(1, index);
    int episodes = 0;
    bool touching = false;
    double farthest = 0.0;
    for (std::size_t k = 0; k < run.stepCount(); ++k) {
      bool any = false;
      for (int d = 0; d < kSensorCount; ++d)
        any = any || run.normal(k, d) > 0.0;
      episodes += any && !touching;
      touching = any;
      if (run.v[k] == 0.0 && run.omega[k] != 0.0) {  // turning in place
        const double dx = run.x[k] - run.x[0], dy = run.y[k] - run.y[0];
        farthest = std::max(farthest, std::hypot(dx, dy));
      }
    }
    // Ten approaches; a push with wiggles may lift off and touch again.
    EXPECT_GE(episodes, 10) << index;
    // Turns in place happen near the start: 140 units of reach less 126 swept leave 14.
    EXPECT_LT(farthest, 14.0) << index;
  }
}

// The reverse runs with a corner behind turn the back wall so that its end at the side wall is
// the nearer: the corner group backs into the concave corner, both its domes pressed.
TEST(TrainingPlan, ReverseRunsWithACornerPressTheCornerGroupOnBothWalls) {
  const RunData run = simulatePlanned(1, numbered(5));  // the first reverse run: corner on the left
  int both = 0;
  for (std::size_t k = 0; k < run.stepCount(); ++k) {
    both += run.truthAt(k, SensorGroup::RearLeftCorner) == ContactClass::Corner &&
            run.normal(k, 20) > 0.0 && run.normal(k, 21) > 0.0;
  }
  EXPECT_GT(both, 30);
}

// The corpus recipe at its documented size (the first 40 numbered runs and the drives between
// them): every group has at least 1,000 contact steps of each class it
// shows, and DeadPath at least 300 in the groups that can see it; F, FLC and FRC never leave a
// wall, and only L, R, RLC and RRC may.
TEST(TrainingPlan, TheDocumentedRecipeShowsEachClassOfEveryGroupAThousandTimes) {
  TruthStats stats;
  for (std::size_t i = 0; i < static_cast<std::size_t>(kTrainingPlanRuns); ++i)
    stats.add(simulatePlanned(1, i));
  for (const GroupInfo& info : kSensorGroups) {
    const auto& row = stats.classSteps[static_cast<std::size_t>(groupIndex(info.group))];
    const auto steps = [&](ContactClass c) { return row[static_cast<std::size_t>(c)]; };
    EXPECT_GE(steps(ContactClass::Wall), 1000) << info.shortName;
    EXPECT_GE(steps(ContactClass::Corner), 1000) << info.shortName;
    const bool sees = info.group == SensorGroup::Front ||
                      info.group == SensorGroup::FrontLeftCorner ||
                      info.group == SensorGroup::FrontRightCorner ||
                      info.group == SensorGroup::Left || info.group == SensorGroup::Right;
    if (sees) {
      EXPECT_GE(steps(ContactClass::DeadPath), 300) << info.shortName;
    } else {
      EXPECT_EQ(steps(ContactClass::DeadPath), 0) << info.shortName;
    }
    if (info.group == SensorGroup::Left || info.group == SensorGroup::Right) {
      EXPECT_GE(steps(ContactClass::LeavingWall), 1000) << info.shortName;
    } else if (info.group != SensorGroup::RearLeftCorner &&
               info.group != SensorGroup::RearRightCorner) {
      EXPECT_EQ(steps(ContactClass::LeavingWall), 0) << info.shortName;
    }
  }
}

// Wall-following runs in the built-in scenes: fewer than 2 changes between two contact classes
// per 100 contact steps in every group.
TEST(TruthStats, WallFollowingRunsChangeClassLessThanTwicePerHundredContactSteps) {
  TruthStats all;
  std::mutex mutex;
  for (const char* name : {"room1", "room2", "room3", "chapter5"}) {
    auto scene = loadScene(name);
    ASSERT_TRUE(scene.ok()) << name;
    auto world = std::make_shared<const World>(std::move(scene.value()));
    RunOptions options;
    options.maxSteps = 5000;
    options.seed = 1;
    const Status status =
        simulateBatch(world, name, options, 8, 0, [&](std::size_t, SimulatedRun& result) -> Status {
          std::lock_guard lock(mutex);
          all.add(result.run);
          return {};
        });
    ASSERT_TRUE(status.ok()) << name;
  }
  for (const GroupInfo& info : kSensorGroups) {
    EXPECT_GT(all.contactSteps(info.group), 0) << info.shortName;
    EXPECT_LT(all.changesPer100ContactSteps(info.group), 2.0) << info.shortName;
  }
  EXPECT_EQ(all.blockedWithoutReadings, 0);
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
