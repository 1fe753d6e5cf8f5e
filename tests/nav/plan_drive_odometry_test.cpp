// Plan drive's odometry rule for a blocked step, end to end (docs/navigation.md#plan-drive): the
// simulator ends a blocked step somewhere along it, and plan drive counts half of it. Two office
// maps where the robot is blocked a few times on its way are reached with that rule; counting a
// blocked step in full drives the odometry off there, and the runs end in timeouts. (The rule is
// unit-tested by PlanDrive.ABlockedStepCountsAsHalfItsCommand; this guards what it is for.)
#include <gtest/gtest.h>

#include <memory>
#include <string>

#include "nav/navigate.h"
#include "nav/navigator.h"
#include "sim/scene_source.h"

namespace tactile::nav {
namespace {

NavigateResult driveOffice(const std::string& spec, double blockedStepShare) {
  auto loaded = sim::loadScene(spec);
  EXPECT_TRUE(loaded.ok()) << (loaded.ok() ? "" : loaded.errorText());
  if (!loaded) return {};
  const auto world = std::make_shared<const sim::World>(std::move(loaded.value()));
  NavigatorConfig config;
  config.source = StatusSource::Truth;
  config.planDrive = true;
  config.blockedStepShare = blockedStepShare;
  NavigateOptions options;
  options.maxSteps = 6000;
  auto r = navigate(world, spec, world->scene().start, world->scene().goal, config, options);
  EXPECT_TRUE(r.ok()) << (r.ok() ? "" : r.errorText());
  return r.ok() ? std::move(r.value()) : NavigateResult{};
}

TEST(PlanDriveOdometry, OfficeMapsThatNeedTheHalfStepRuleAreReached) {
  const NavigatorConfig defaults;
  ASSERT_EQ(defaults.blockedStepShare, 0.5);
  for (const char* spec : {"random:office:29", "random:office:37"}) {
    SCOPED_TRACE(spec);
    const NavigateResult r = driveOffice(spec, defaults.blockedStepShare);
    EXPECT_EQ(r.outcome, RunOutcome::Success)
        << runOutcomeName(r.outcome) << " after " << r.steps << ", blocked " << r.blockedSteps;
    // The rule is in play: the robot is blocked on the way.
    EXPECT_GT(r.blockedSteps, 0u);
  }
}

}  // namespace
}  // namespace tactile::nav
