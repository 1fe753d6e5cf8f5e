// Bug2 with a binary bumper: the baseline the chapter-5 navigator is compared with.
#include <algorithm>
#include <cmath>

#include "nav/navigator_state.h"

namespace tactile::nav {

Command Navigator::Impl::bug2() {
  const bool front = frontMax() > 0.0;
  const bool side = sideMax() > 0.0;
  if (strategy == Strategy::HeadToDestination) {
    if (!front && blockedStreak == 0) return headTo(goal);
    ++wall;
    wallOnLeft = false;  // left-hand rule: keep the obstacle on the right, turn left
    hitGoalDistance = (goal - position()).norm();
    hitPoint = position();
    following = true;
    farFromHit = 0.0;
    setStrategy(Strategy::CheckContact, Phase::Back);
  }
  if (circled()) {
    finished = RunOutcome::Unreachable;
    return {};
  }
  // Leave on the start-goal line, closer than the hit point, the front free.
  const Vec2 line = goal - startPoint;
  const double len = line.norm();
  const Vec2 p = position();
  const double off = len > 0.0 ? std::abs(sim::cross2(line, p - startPoint)) / len : 0.0;
  if (strategy == Strategy::FollowWall && off < 15.0 &&
      (goal - p).norm() < hitGoalDistance - kLeaveGainUnits && !front) {
    setStrategy(Strategy::HeadToDestination);
    return headTo(goal);
  }
  if (strategy == Strategy::CheckContact) {
    ++phaseSteps;
    if (phase == Phase::Back) {
      if (phaseSteps <= 3 && !(backMax() > 0.0)) return {-0.5 * cruise(), 0.0};
      phase = Phase::Turn;
    }
    if (phase == Phase::Turn) {
      phase = Phase::Forward;
      turned = 0.0;
    }
    // Turn away until nothing ahead touches and the obstacle lies along the side.
    if (front || blockedStreak > 0 || (std::abs(turned) < 1.0 && !side))
      return {0.0, away() * cfg.turnRadiansPerSecond};
    setStrategy(Strategy::FollowWall);
    roundTurned = 0.0;
  }
  if (front || blockedStreak > 0) {
    setStrategy(Strategy::CheckContact, Phase::Back);
    return {-0.5 * cruise(), 0.0};
  }
  // Binary bumper following: touching -> veer away, free -> arc back toward the wall.
  if (side) {
    roundTurned = 0.0;
    return {0.8 * cruise(), away() * 2.0 * cfg.slightTurnRadiansPerSecond};
  }
  // Nothing beside: arc back toward the obstacle on a radius of kBumperArcUnits; a full circle
  // without meeting it again: it is lost, head for the goal.
  roundTurned += std::abs(0.6 * cruise() / kBumperArcUnits) * dt;
  if (roundTurned > 2.0 * kPi) {
    setStrategy(Strategy::HeadToDestination);
    return headTo(goal);
  }
  return {0.6 * cruise(), -away() * 0.6 * cruise() / kBumperArcUnits};
}

}  // namespace tactile::nav
