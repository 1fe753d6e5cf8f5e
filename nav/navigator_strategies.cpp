// The chapter-5 strategies (Head to Destination, Check Contact, Follow Wall, Go Straight, the U
// turns, Move through Wall) and the wall episodes they share: the thesis's navigator.
#include <algorithm>
#include <cmath>

#include "nav/navigator_state.h"

namespace tactile::nav {

void Navigator::Impl::startEpisode() {
  ++wall;
  using G = SensorGroup;
  // The wall goes on the side that touched first: front-left contact means turning right.
  double left = groupMax(*values, G::FrontLeftCorner) + groupMax(*values, G::Left);
  double right = groupMax(*values, G::FrontRightCorner) + groupMax(*values, G::Right);
  for (int s = 0; s < 8; ++s)
    (s < 4 ? right : left) += normalOf(*values, s);
  std::optional<double> planTurn;
  if (useMap()) {
    updatePlan(true);
    if (auto d = planDirection()) {
      const double err = sim::wrapAngle(std::atan2(d->y(), d->x()) - odo.theta);
      if (std::abs(err) > 0.05) planTurn = err;
    }
  }
  if (planTurn) {
    wallOnLeft = *planTurn < 0.0;  // the plan goes round to the right: the wall on the left
  } else if (sidePreference) {
    wallOnLeft = *sidePreference;
  } else if (left == right) {
    const Vec2 g = goal - position();
    const double err = sim::wrapAngle(std::atan2(g.y(), g.x()) - odo.theta);
    wallOnLeft = err < 0.0;  // turn toward the goal's side
  } else {
    wallOnLeft = left > right;
  }
  following = false;
  reversing = false;
  farFromHit = 0.0;
  hitGoalDistance = (goal - position()).norm();
  sideLost = false;
  rounding = false;
  sideWasTouching = false;
  setStrategy(Strategy::CheckContact, Phase::Back);
}

// A hit within kLoopUnits of an earlier one, no closer to the goal (by kLeaveGainUnits), after
// kLoopPathUnits of odometry path: the robot is going round in a loop. Records the hit.
bool Navigator::Impl::loopAtHit() {
  const Vec2 p = position();
  const double d = (goal - p).norm();
  bool loop = false;
  for (const Hit& h : hits) {
    if ((p - h.at).norm() < kLoopUnits && pathUnits - h.path > kLoopPathUnits &&
        d > h.goalDistance - kLeaveGainUnits)
      loop = true;
  }
  if (loop) hits.clear();
  hits.push_back({p, d, pathUnits});
  return loop;
}

void Navigator::Impl::beginFollowing() {
  if (!following) {
    following = true;
    hitPoint = position();
    farFromHit = 0.0;
    followedUnits = 0.0;
  }
  sideLost = false;
  rounding = false;
  setStrategy(Strategy::FollowWall);
}

// The goal lies away from the followed wall and closer than where the wall was hit. With the
// touch map: the plan heads away from the wall.
bool Navigator::Impl::mayLeave() const {
  if (useMap() && plan) {
    const auto d = planDirection();
    if (!d || followedUnits < kMapLeaveUnits) return false;
    if ((planTarget() - bodyCentre()).norm() < kMapLeaveClearUnits) return false;
    return d->dot(intoWall()) < kLeaveCosine && aheadMax() <= kTouching;
  }
  const Vec2 g = goal - position();
  const double d = g.norm();
  if (d <= 0.0 || d > hitGoalDistance - kLeaveGainUnits) return false;
  const Vec2 into = wallOnLeft ? Vec2(-std::sin(odo.theta), std::cos(odo.theta))
                               : Vec2(std::sin(odo.theta), -std::cos(odo.theta));
  return g.dot(into) / d < kLeaveCosine && aheadMax() <= kTouching;
}

// The unit direction from the robot into the followed wall.
Vec2 Navigator::Impl::intoWall() const {
  return wallOnLeft ? Vec2(-std::sin(odo.theta), std::cos(odo.theta))
                    : Vec2(std::sin(odo.theta), -std::cos(odo.theta));
}

// With the touch map: the plan heads back along the wall (behind the robot, not away from the
// wall) after kMapReverseUnits of following: U turn, then head to the plan.
bool Navigator::Impl::mayReverse() const {
  if (!useMap() || !plan || followedUnits < kMapReverseUnits) return false;
  const auto d = planDirection();
  if (!d) return false;
  const Vec2 forward(std::cos(odo.theta), std::sin(odo.theta));
  return d->dot(forward) < kMapReverseCosine && d->dot(intoWall()) >= kLeaveCosine;
}

Command Navigator::Impl::reverse() {
  target.reset();
  following = false;
  reversing = true;
  setStrategy(wallOnLeft ? Strategy::RightUTurn : Strategy::LeftUTurn, Phase::Back);
  return uTurn();
}

// Back where following started, having been away: the obstacle was walked round.
bool Navigator::Impl::circled() {
  if (!following || useMap()) return false;
  const double d = (position() - hitPoint).norm();
  farFromHit = std::max(farFromHit, d);
  return farFromHit > kDepartUnits && d < kReturnUnits;
}

// The wall is exhausted: go for the widest passable hole left, or give up.
Command Navigator::Impl::wallExhausted(bool needUTurn) {
  if (auto h = memory.widestPassable(cfg.passableWidthUnits, -1)) {
    beginHole(*h);
    // Back along the wall: following it again later starts a new circuit from there.
    following = false;
    if (needUTurn)
      setStrategy(wallOnLeft ? Strategy::RightUTurn : Strategy::LeftUTurn, Phase::Back);
    return {};
  }
  finished = RunOutcome::Unreachable;
  return {};
}

void Navigator::Impl::beginHole(std::size_t index) {
  target = index;
  const RememberedHole& h = memory.holes()[index];
  holeCentre = h.centre;
  inward = h.onLeft ? Vec2(-std::sin(h.pose.theta), std::cos(h.pose.theta))
                    : Vec2(std::sin(h.pose.theta), -std::cos(h.pose.theta));
  setStrategy(Strategy::MoveThroughWall, Phase::Approach);
}

void Navigator::Impl::failHole() {
  if (target) memory.markTried(*target);
  target.reset();
  setStrategy(Strategy::CheckContact, Phase::Back);
}

Command Navigator::Impl::headToDestination() {
  if (frontMax() > kTouching || blockedStreak > 0) {
    if (!useMap() && loopAtHit()) {
      // Hit again where it was hit before, no closer to the goal, after a long way round: a
      // loop. Follow walls on the other side from then on; at the kLoopsToGiveUp-th loop the
      // walls are exhausted (the widest passable hole left, or unreachable).
      if (++loops >= kLoopsToGiveUp) return wallExhausted(false);
      sidePreference = !wallOnLeft;
    }
    startEpisode();
    return checkContact();
  }
  Command c = headTo(planTarget());
  // With the map, turning in place toward the plan keeps the way it turned on the step before:
  // the body centre (the plan's start) moves as the robot turns, and the plan's target can flip
  // between the two ways round an obstacle from one step to the next; without this the robot
  // turns back and forth on the spot for the rest of its run.
  if (useMap() && c.v == 0.0 && c.omega != 0.0) {
    if (spinStep + 1 == stepIndex && (c.omega > 0.0) != (spinOmega > 0.0)) c.omega = spinOmega;
    spinStep = stepIndex;
    spinOmega = c.omega;
  }
  // A side brushing something while the way ahead is free: ease away from it.
  const double l = std::max(groupMax(*values, SensorGroup::Left),
                            groupMax(*values, SensorGroup::RearLeftCorner));
  const double r = std::max(groupMax(*values, SensorGroup::Right),
                            groupMax(*values, SensorGroup::RearRightCorner));
  if (c.v > 0.0 && l > kTouching && r <= kTouching) c.omega = -cfg.slightTurnRadiansPerSecond;
  if (c.v > 0.0 && r > kTouching && l <= kTouching) c.omega = cfg.slightTurnRadiansPerSecond;
  return c;
}

// Thesis 5.2 (3): back off what is ahead, turn away by a slight angle past a clear front, move
// on arcing gently toward the wall until the side follows it (status Wall or Corner).
Command Navigator::Impl::checkContact() {
  ++phaseSteps;
  switch (phase) {
    case Phase::Back:
    case Phase::None:
      if (phase == Phase::None) setStrategy(Strategy::CheckContact, Phase::Back);
      if (phaseSteps == 1) pressedSide = sideMax() > kPressedSide;
      // Back off straight: a little from a wall met head-on, further from a concave corner
      // (the side pressed), where turning in place would swing the rear corner into the side.
      if (phaseUnits < (pressedSide ? kCornerBackUnits : kBackOffUnits) &&
          groupMax(*values, SensorGroup::Back) <= kTouching && blockedStreak < 2 &&
          phaseSteps < 40 &&
          (pressedSide || frontMax() > 0.5 || phaseUnits < 0.4 * kBackOffUnits)) {
        return {-0.5 * cruise(), 0.0};
      }
      setStrategy(Strategy::CheckContact, Phase::Turn);
      [[fallthrough]];
    case Phase::Turn: {
      if (blockedStreak >= 2) {
        setStrategy(Strategy::CheckContact, Phase::Back);
        pressedSide = true;
        return {-0.5 * cruise(), 0.0};
      }
      if (!frontCleared && aheadMax() <= 0.0 && frontMax() <= kTouching) {
        frontCleared = true;
        turned = 0.0;
      }
      if ((frontCleared && std::abs(turned) >= kCheckExtraTurn) ||
          (pressedSide && std::abs(turned) >= kCornerArcRadians)) {
        setStrategy(Strategy::CheckContact, Phase::Forward);
      } else {
        if (phaseSteps > 120) {  // turned round without clearing: a pocket
          setStrategy(Strategy::CheckContact, Phase::Forward);
        }
        // Beside a pressed side: an arc away (the rear corner swings out about a unit).
        if (pressedSide) {
          if (aheadMax() > kTouching) {
            setStrategy(Strategy::CheckContact, Phase::Back);
            return {-0.5 * cruise(), 0.0};
          }
          return {0.6 * cruise(), away() * 0.6 * cruise() / kCornerArcRadiusUnits};
        }
        return {0.0, away() * cfg.turnRadiansPerSecond};
      }
      [[fallthrough]];
    }
    case Phase::Forward: {
      if (aheadMax() > kTouching || blockedStreak >= 2) {
        setStrategy(Strategy::CheckContact, Phase::Back);
        return {-0.5 * cruise(), 0.0};
      }
      const double side = sideMax();
      if (side > 0.0) {
        ++sideSteps;
        const StatusKind k = groupStatus(sideGroup()).kind;
        if (k == StatusKind::Wall || k == StatusKind::Corner || k == StatusKind::Hole ||
            sideSteps >= kCheckMaxSideSteps) {
          beginFollowing();
          return followWall();
        }
        // Touching on the side but not yet judged: line up with the wall by the follow-wall
        // rule rather than arc on into it (the near front corner would hit it head on).
        switch (sim::followWallAction(*values, !wallOnLeft)) {
          case sim::FollowAction::Away:
            return {0.5 * cruise(), away() * 2.0 * cfg.slightTurnRadiansPerSecond};
          case sim::FollowAction::Toward:
            return {0.6 * cruise(), -away() * cfg.slightTurnRadiansPerSecond};
          case sim::FollowAction::Straight:
            return {0.6 * cruise(), 0.0};
        }
      }
      if (phaseUnits > kCheckLostUnits) {
        // Nothing found beside: the obstacle was small; head for the goal again.
        setStrategy(Strategy::HeadToDestination);
        return headTo(planTarget());
      }
      // Straight first (thesis: move straight, turn a slight angle when stopped); then arc
      // gently toward the wall side to find it.
      if (phaseUnits < kCheckStraightUnits) return {0.6 * cruise(), 0.0};
      return {0.6 * cruise(), -away() * 2.0 * cfg.slightTurnRadiansPerSecond};
    }
    default:
      break;
  }
  setStrategy(Strategy::CheckContact, Phase::Back);
  return {};
}

// Thesis 5.2 (4): keep the side on the wall with the 4 / 3 / 0.5 / 2 rule.
Command Navigator::Impl::followWall() {
  if (circled()) return wallExhausted(false);
  if (mayLeave()) {
    setStrategy(Strategy::HeadToDestination);
    return headTo(planTarget());
  }
  if (mayReverse()) return reverse();
  const StatusKind front = groupStatus(SensorGroup::Front).kind;
  if (aheadMax() > kTouching || front == StatusKind::DeadPath) {
    // The end of this wall: a wall ahead. With a passable hole behind, go back to the widest
    // one (thesis 5.3.2); else turn along the next wall.
    if (memory.widestPassable(cfg.passableWidthUnits, wall)) return wallExhausted(true);
    setStrategy(Strategy::CheckContact, Phase::Back);
    return checkContact();
  }
  if (blockedStreak > 0) return {0.0, away() * 0.5 * cfg.turnRadiansPerSecond};
  const double side = sideMax();
  const StatusKind s = groupStatus(sideGroup()).kind;
  if (side <= 0.0 || s == StatusKind::LeavingWall) {
    setStrategy(Strategy::GoStraight);
    return goStraight();
  }
  switch (sim::followWallAction(*values, !wallOnLeft)) {
    case sim::FollowAction::Away:
      return {0.7 * cruise(), away() * cfg.slightTurnRadiansPerSecond};
    case sim::FollowAction::Toward:
      return {0.8 * cruise(), -away() * cfg.slightTurnRadiansPerSecond};
    case sim::FollowAction::Straight:
      break;
  }
  return {cruise(), 0.0};
}

// Thesis 5.2 (1), used to cross what the side has lost (a hole, a door) while checking the
// wall; the width of the opening is measured by odometry from the last dome on the wall before
// it to the first dome on the wall after it.
Command Navigator::Impl::goStraight() {
  if (circled()) return wallExhausted(false);
  if (mayLeave()) {
    setStrategy(Strategy::HeadToDestination);
    return headTo(planTarget());
  }
  if (aheadMax() > kTouching) {
    if (memory.widestPassable(cfg.passableWidthUnits, wall)) return wallExhausted(true);
    setStrategy(Strategy::CheckContact, Phase::Back);
    return checkContact();
  }
  const double side = sideMax();
  // Re-contact after rounding a wall's end is the next face, not the far side of an opening.
  if (side > 0.0 && sideLost && !rounding) {
    // The next fragment: the opening between the last contact and this one.
    const int first = wallOnLeft ? 8 : 43;
    const int step = wallOnLeft ? 1 : -1;
    for (int i = 0, s = first; i < 14; ++i, s += step) {
      if (normalOf(*values, s) > 0.0) {
        const Vec2 end = domeWorld(s);
        memory.observe((end - gapStart).norm(), odo, 0.5 * (end + gapStart), wallOnLeft, stepIndex,
                       wall);
        break;
      }
    }
    sideLost = false;
    rounding = false;
  }
  if (side > 0.0) {
    if (groupStatus(sideGroup()).kind != StatusKind::LeavingWall) {
      beginFollowing();
      return followWall();
    }
    return {cruise(), 0.0};
  }
  if (!sideLost) {
    sideLost = true;
    lostUnits = 0.0;
    gapStart = lastRearTouch;
  }
  if (lostUnits > kGapProbeUnits || rounding) {
    // The wall has ended (or turned away): round its end, as a wall follower does.
    if (!rounding) {
      rounding = true;
      roundTurned = 0.0;
    }
    if (roundTurned > 2.0 * kPi) {
      setStrategy(Strategy::HeadToDestination);
      return headTo(planTarget());
    }
    return {0.6 * cruise(), -away() * kRoundTurnFraction * cfg.turnRadiansPerSecond};
  }
  return {cruise(), 0.0};
}

// Thesis 5.2 (6): turn 180 degrees away from the wall, after backing off what is ahead.
Command Navigator::Impl::uTurn() {
  ++phaseSteps;
  const double dir = strategy == Strategy::RightUTurn ? -1.0 : 1.0;
  if (phase == Phase::Back) {
    // Back off along the wall, then arc away from it before spinning: in place beside the wall
    // the rear corner would swing into it.
    if (phaseUnits < kCornerBackUnits && groupMax(*values, SensorGroup::Back) <= kTouching &&
        blockedStreak < 2 && phaseSteps < 40) {
      return {-0.5 * cruise(), 0.0};
    }
    phase = Phase::Forward;
    turned = 0.0;
  }
  if (phase == Phase::Forward) {
    if (std::abs(turned) < 0.6 && aheadMax() <= kTouching && blockedStreak < 2 && phaseSteps < 80) {
      return {0.6 * cruise(), dir * 0.6 * cruise() / kCornerArcRadiusUnits};
    }
    phase = Phase::Turn;
  }
  if (std::abs(turned) >= kPi - 0.05 || phaseSteps > 250) {
    if (target) {
      const std::size_t t = *target;
      beginHole(t);
      return moveThroughWall();
    }
    if (reversing) {
      reversing = false;
      setStrategy(Strategy::HeadToDestination);
      return headTo(planTarget());
    }
    setStrategy(Strategy::CheckContact, Phase::Forward);
    return {};
  }
  if (blockedStreak >= 2) return {(phaseSteps / 4) % 2 ? 0.3 * cruise() : -0.3 * cruise(), 0.0};
  return {0.0, dir * cfg.turnRadiansPerSecond};
}

// Thesis 5.2 (5): go to a point in front of the remembered hole, face it, move through.
Command Navigator::Impl::moveThroughWall() {
  ++phaseSteps;
  const Vec2 approach = holeCentre - kApproachUnits * inward;
  const Vec2 through = holeCentre + kThroughUnits * inward;
  if (blockedStreak >= 3 ||
      (phase != Phase::Enter && groupMax(*values, SensorGroup::Front) > 1.0)) {
    if (++failSteps > 3 || phase == Phase::Enter) {
      failHole();
      return checkContact();
    }
  }
  if (phase == Phase::Approach) {
    if ((approach - position()).norm() < 12.0 || phaseSteps > 800) {
      phase = Phase::Face;
    } else {
      Command c = headTo(approach);
      const double l = std::max(groupMax(*values, SensorGroup::Left),
                                groupMax(*values, SensorGroup::FrontLeftCorner));
      const double r = std::max(groupMax(*values, SensorGroup::Right),
                                groupMax(*values, SensorGroup::FrontRightCorner));
      if (l > kTouching && r <= kTouching) c = {0.5 * cruise(), -cfg.turnRadiansPerSecond * 0.5};
      if (r > kTouching && l <= kTouching) c = {0.5 * cruise(), cfg.turnRadiansPerSecond * 0.5};
      return c;
    }
  }
  if (phase == Phase::Face) {
    const Vec2 d = through - position();
    const double err = sim::wrapAngle(std::atan2(d.y(), d.x()) - odo.theta);
    if (std::abs(err) > 0.04)
      return {0.0, err > 0 ? cfg.turnRadiansPerSecond : -cfg.turnRadiansPerSecond};
    phase = Phase::Enter;
    phaseUnits = 0.0;
  }
  // Enter: straight through, easing away from a jamb a front corner or a side touches.
  if ((position() - holeCentre).dot(inward) > kThroughUnits - 30.0) {
    if (target) memory.markTried(*target);
    target.reset();
    following = false;
    setStrategy(Strategy::HeadToDestination);
    return headTo(goal);
  }
  if (groupMax(*values, SensorGroup::Front) > 1.5 ||
      phaseUnits > 3.0 * kThroughUnits + kApproachUnits) {
    failHole();
    return checkContact();
  }
  using G = SensorGroup;
  const double l = std::max(groupMax(*values, G::FrontLeftCorner), groupMax(*values, G::Left));
  const double r = std::max(groupMax(*values, G::FrontRightCorner), groupMax(*values, G::Right));
  const Vec2 d = through - position();
  const double err = sim::wrapAngle(std::atan2(d.y(), d.x()) - odo.theta);
  double omega = std::clamp(err, -0.3, 0.3);
  if (l > kTouching && l > r) omega = -0.4;
  if (r > kTouching && r > l) omega = 0.4;
  return {0.5 * cruise(), omega};
}

}  // namespace tactile::nav
