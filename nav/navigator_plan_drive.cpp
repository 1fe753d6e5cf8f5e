// Plan drive: following the touch map's plan, backing off contacts ahead, and the search round
// the goal once arrived by odometry.
#include <algorithm>
#include <cmath>

#include "nav/navigator_state.h"

namespace tactile::nav {

// Follows the touch map's plan: Head to Destination while driving, Check Contact while backing
// off a contact ahead.
Command Navigator::Impl::planDrive() {
  ++phaseSteps;
  if (strategy == Strategy::CheckContact) {
    // Moving off the contact: stopped by a contact or a blocked step the way it moves.
    const bool stop = driveAway < 0.0
                          ? anyContact({SensorGroup::Back, SensorGroup::RearLeftCorner,
                                        SensorGroup::RearRightCorner}) ||
                                (blockedStreak > 0 && last.v < 0.0)
                          : anyContact({SensorGroup::Front, SensorGroup::FrontLeftCorner,
                                        SensorGroup::FrontRightCorner}) ||
                                (blockedStreak > 0 && last.v > 0.0);
    if (phaseUnits < driveBack && !stop && phaseSteps < 60)
      return {driveAway * 0.5 * cruise(), 0.0};
    setStrategy(Strategy::HeadToDestination);
    updatePlan(true);
  }
  strategy = Strategy::HeadToDestination;
  using G = SensorGroup;
  const bool ahead = inContact(G::Front) || cornerAhead(G::FrontLeftCorner) ||
                     cornerAhead(G::FrontRightCorner) || (blockedStreak > 0 && last.v >= 0.0);
  if (ahead && !arrived && goalBehindContact()) {
    // As near as the odometry lets it come: search round the goal from here.
    arrived = true;
    searchAngle = 0.0;
    escapeSteps = 0;
    return planSearch();
  }
  if (ahead) return driveBackOff();
  if (noStart && !moved.empty()) {
    // Hemmed in on the map (no open cell near the robot to plan from): retrace the last moves
    // (each lands on a pose the robot has been in), then replan.
    driveRepeats = 0;
    noStart = false;
    driveSpin = 0.0;
    backtrackLeft = std::min(kBacktrackSteps, moved.size()) - 1;
    const Command undo{-moved.back().v, -moved.back().omega};
    moved.pop_back();
    backtracking = true;
    planned = false;
    return undo;
  }
  const Vec2 target = driveTarget();
  const Vec2 d = target - position();
  const double err = sim::wrapAngle(std::atan2(d.y(), d.x()) - odo.theta);
  const double turn = cfg.turnRadiansPerSecond;
  if (std::abs(err) > kDriveTurnRadians) {
    // Turning in place keeps the way it turned on the step before (the plan's target can flip
    // between the two ways round an obstacle as the body turns); after a contact while turning,
    // the other way.
    double omega = err > 0.0 ? turn : -turn;
    if (driveSpin != 0.0)
      omega = driveSpin;
    else if (spinStep + 1 == stepIndex)
      omega = spinOmega;
    spinStep = stepIndex;
    spinOmega = omega;
    return {0.0, omega};
  }
  driveSpin = 0.0;
  Command c{std::abs(err) < 0.2 ? cruise() : 0.6 * cruise(), std::clamp(2.0 * err, -turn, turn)};
  // A side or a front corner brushing something: ease away from it.
  const bool l = anyContact({G::Left, G::RearLeftCorner, G::FrontLeftCorner});
  const bool r = anyContact({G::Right, G::RearRightCorner, G::FrontRightCorner});
  const double ease = 2.0 * cfg.slightTurnRadiansPerSecond;
  if (l && !r) c.omega = std::min(c.omega, -ease);
  if (r && !l) c.omega = std::max(c.omega, ease);
  return c;
}

// A contact ahead with the goal (where the odometry puts it) close by and on cells closed by
// what was touched: the goal lies at or behind the touched surface, where the robot cannot
// stand; its odometry has drifted (or the goal is walled in).
bool Navigator::Impl::goalBehindContact() const {
  if ((goal - bodyCentre()).norm() > kGoalBehindUnits) return false;
  if (touch.closed(goal)) return true;
  // Or the contacts keep stopping the robot at one place there: as near as it comes.
  return (position() - driveHitAt).norm() < kDriveRepeatUnits &&
         driveRepeats + 1 >= kGoalBehindRepeats;
}

// The plan's farthest point in clear sight (or the goal when nothing touched is in the way).
Vec2 Navigator::Impl::driveTarget() const {
  if (!plan || plan->points.size() < 2) return aim();
  const Vec2 p = touch.lookAhead(*plan, bodyCentre(), kDriveLookAheadUnits);
  if ((p - plan->points.back()).norm() < 1e-9) return aim();
  return p;
}

// Plan drive, arrived by odometry while the run goes on: search round the goal on the spiral
// (pitch kSearchPitchUnits, out to kSearchRadiusUnits) by driving to its points one after the
// other on plans of the touch map, as to the goal. A point on a closed cell, one the plan finds
// no way to, and one not reached in kSearchPointSteps steps are passed over; kMapSearchRounds
// spirals without the goal end the run as unreachable.
Command Navigator::Impl::planSearch() {
  for (int i = 0; i < 2000; ++i) {
    const double r = kSearchPitchUnits * searchAngle / (2.0 * kPi);
    if (r > kSearchRadiusUnits) {
      searchAngle = 0.0;
      searchAim.reset();
      if (++searchRounds >= kMapSearchRounds) {
        finished = RunOutcome::Unreachable;
        return {};
      }
      continue;
    }
    const Vec2 point = goal + r * Vec2(std::cos(searchAngle), std::sin(searchAngle));
    const bool current = searchAim && (*searchAim - point).norm() < 1e-9;
    bool pass = (point - bodyCentre()).norm() < kSearchReachUnits || touch.closed(point);
    if (!pass && current)
      pass = (noWay && !noStart) || stepIndex - searchAimStep > kSearchPointSteps;
    if (!pass && !current) {
      searchAim = point;
      searchAimStep = stepIndex;
      updatePlan(true);
      pass = noWay && !noStart;
    }
    if (!pass) break;
    searchAngle += std::max(0.05, kSearchSpacingUnits / std::max(r, 20.0));
  }
  return choose();
}

// A contact ahead: its domes are marked (updateMap); back off, the further the more often the
// robot meets something at the same place, then replan. A contact while turning in place makes
// the next turn go the other way.
Command Navigator::Impl::driveBackOff() {
  const Vec2 p = position();
  driveRepeats = (p - driveHitAt).norm() < kDriveRepeatUnits ? driveRepeats + 1 : 0;
  driveHitAt = p;
  if (driveRepeats >= kFrontRepeats) {
    // Met here again and again: the marks so far leave the plan a line into it (a dome touching
    // a corner marks a point; the plan passes it within half a body width). Mark the front edge,
    // a dome radius out, from side to side.
    const double x = cfg.geometry.frontX() + cfg.geometry.domeRadiusUnits;
    const double w = cfg.geometry.halfWidth();
    const int n = static_cast<int>(std::ceil(2.0 * w / kDriveCellUnits));
    for (int i = 0; i <= n; ++i)
      touch.mark(sim::bodyToWorld(odo, Vec2(x, -w + 2.0 * w * i / n)));
  }
  driveBack = std::min(kDriveBackUnits + kDriveBackMoreUnits * driveRepeats, kDriveBackMaxUnits);
  if (last.v == 0.0 && last.omega != 0.0) driveSpin = -last.omega;
  // Off the contact: back off from what is ahead; forward from what the back alone touches (a
  // turn in place blocked by the back corners sweeping into a wall behind).
  using G = SensorGroup;
  driveAway = anyContact({G::Back, G::RearLeftCorner, G::RearRightCorner}) &&
                      !anyContact({G::Front, G::FrontLeftCorner, G::FrontRightCorner})
                  ? 1.0
                  : -1.0;
  setStrategy(Strategy::CheckContact, Phase::Back);
  ++phaseSteps;
  return {driveAway * 0.5 * cruise(), 0.0};
}

}  // namespace tactile::nav
