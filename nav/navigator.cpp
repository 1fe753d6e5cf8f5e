#include "nav/navigator.h"

#include <algorithm>
#include <cmath>

#include "nav/navigator_state.h"

namespace tactile::nav {

Vec2 domeContactPoint(const DomePlacement& dome, double normalValue, double shearValue,
                      double domeRadiusUnits) {
  const Vec2 normal = toVec(dome.normal);
  const Vec2 tangent(-normal.y(), normal.x());
  const double push = std::hypot(normalValue, shearValue);
  if (!(push > 0.0) || !std::isfinite(push)) return toVec(dome.centre) + domeRadiusUnits * normal;
  const Vec2 towards = (normalValue * normal - shearValue * tangent) / push;
  return toVec(dome.centre) + std::max(domeRadiusUnits - push, 0.0) * towards;
}

Observation observe(const sim::Simulator& simulator, std::size_t step, const Pose2d& start,
                    const Vec2& goal) {
  Observation o;
  o.step = step;
  o.dtSeconds = simulator.config().dtSeconds;
  o.pose = simulator.pose();
  o.start = start;
  o.goal = goal;
  o.blocked = simulator.blocked();
  o.values = &simulator.sensors();
  o.truth = &simulator.truth();
  return o;
}

void Navigator::Impl::integrate(bool blocked) {
  if (blocked) {
    // The simulator ends a blocked step somewhere between its start and its end, where the
    // robot cannot tell. The thesis navigators count no motion; plan drive counts the share
    // cfg.blockedStepShare of the step (by default half: the estimate whose error is at most
    // half the step either way, where counting none may be wrong by the whole step).
    if (planMode() && cfg.blockedStepShare > 0.0) {
      odo = sim::integratePose(odo, cfg.blockedStepShare * last.v,
                               cfg.blockedStepShare * last.omega, dt);
      odo.theta = sim::wrapAngle(odo.theta);
    }
    return;
  }
  if (!backtracking && (last.v != 0.0 || last.omega != 0.0)) {
    moved.push_back(last);
    if (moved.size() > kBacktrackMemory) moved.pop_front();
  }
  const double theta = odo.theta;
  odo = sim::integratePose(odo, last.v, last.omega, dt);
  odo.theta = sim::wrapAngle(odo.theta);
  phaseUnits += std::abs(last.v) * dt;
  pathUnits += std::abs(last.v) * dt;
  turned += sim::wrapAngle(odo.theta - theta);
  if (sideLost) lostUnits += std::abs(last.v) * dt;
  followedUnits += std::abs(last.v) * dt;
  if (rounding) roundTurned += std::abs(sim::wrapAngle(odo.theta - theta));
}

Vec2 Navigator::Impl::domeWorld(int sensor) const {
  return sim::bodyToWorld(odo, toVec(domes[static_cast<std::size_t>(sensor)].centre));
}

double Navigator::Impl::sideMax() const {
  using G = SensorGroup;
  return wallOnLeft ? std::max({groupMax(*values, G::Left), groupMax(*values, G::FrontLeftCorner),
                                groupMax(*values, G::RearLeftCorner)})
                    : std::max({groupMax(*values, G::Right), groupMax(*values, G::FrontRightCorner),
                                groupMax(*values, G::RearRightCorner)});
}

// The front face and the far front corner (the near one touches while following).
double Navigator::Impl::aheadMax() const {
  using G = SensorGroup;
  return std::max(groupMax(*values, G::Front),
                  groupMax(*values, wallOnLeft ? G::FrontRightCorner : G::FrontLeftCorner));
}

double Navigator::Impl::frontMax() const {
  using G = SensorGroup;
  return std::max({groupMax(*values, G::Front), groupMax(*values, G::FrontLeftCorner),
                   groupMax(*values, G::FrontRightCorner)});
}

double Navigator::Impl::backMax() const {
  using G = SensorGroup;
  return std::max({groupMax(*values, G::Back), groupMax(*values, G::RearLeftCorner),
                   groupMax(*values, G::RearRightCorner)});
}

ContactStatus Navigator::Impl::groupStatus(SensorGroup g) const {
  return status[static_cast<std::size_t>(groupIndex(g))];
}

// Plan drive: whether a group touches something is its status's to say (per the source: the
// models' online decision, the simulator's truth); the readings only say where.
bool Navigator::Impl::inContact(SensorGroup g) const {
  const StatusKind k = groupStatus(g).kind;
  return k != StatusKind::NoContact && k != StatusKind::Undecided;
}

bool Navigator::Impl::anyContact(std::initializer_list<SensorGroup> groups) const {
  return std::any_of(groups.begin(), groups.end(), [&](SensorGroup g) { return inContact(g); });
}

// A front corner in contact meets something ahead (rather than grazing it beside the robot)
// when a dome of it facing ahead touches.
bool Navigator::Impl::cornerAhead(SensorGroup corner) const {
  if (!inContact(corner)) return false;
  const GroupInfo& info = groupInfo(corner);
  for (int s = info.firstSensor; s < info.firstSensor + info.sensorCount; ++s)
    if (domes[static_cast<std::size_t>(s)].normal.x > kAheadDomeCosine &&
        normalOf(*values, s) > 0.0)
      return true;
  return false;
}

void Navigator::Impl::setStrategy(Strategy s, Phase p) {
  if (s == Strategy::CheckContact && p == Phase::Back &&
      !(strategy == Strategy::CheckContact && phase == Phase::Back))
    ++checkStarts;
  strategy = s;
  phase = p;
  phaseSteps = 0;
  phaseUnits = 0.0;
  turned = 0.0;
  frontCleared = false;
  sideSteps = 0;
  failSteps = 0;
}

void Navigator::Impl::updateStatus(const Observation& obs) {
  estimator->command(last.v, last.omega);
  const GroupClasses& classes = estimator->update(*obs.values, obs.truth);
  for (std::size_t g = 0; g < kGroupCount; ++g) {
    status[g] =
        classes[g] ? ContactStatus::of(*classes[g]) : ContactStatus{StatusKind::Undecided, 0.0};
  }
  // Holes on the long sides (thesis 4.5): two fragments of contact with free domes between.
  std::array<bool, kSensorCount> contact{};
  for (int s = 0; s < kSensorCount; ++s)
    contact[static_cast<std::size_t>(s)] = normalOf(*obs.values, s) > 0.0;
  for (const analysis::SideRange& side : analysis::kSides) {
    const bool left = side.firstSensor == analysis::kSides[1].firstSensor;
    const bool right = side.firstSensor == analysis::kSides[3].firstSensor;
    if (!left && !right) continue;
    const SensorGroup sideG = left ? SensorGroup::Left : SensorGroup::Right;
    const analysis::HoleScan scan =
        analysis::scanSide(contact, side.firstSensor, side.count, domes);
    if (scan.holes.empty()) continue;
    // The widest opening of the side; its width between the two bounding domes less one dome
    // slot (the domes next to the opening may sit a radius beyond its edges).
    const analysis::Hole* best = &scan.holes.front();
    for (const analysis::Hole& h : scan.holes)
      if (h.widthUnits > best->widthUnits) best = &h;
    const double width = 0.5 * (best->widthUnits + best->freeSpanUnits);
    status[static_cast<std::size_t>(groupIndex(sideG))] = ContactStatus{StatusKind::Hole, width};
    if (wall >= 0 && (strategy == Strategy::FollowWall || strategy == Strategy::GoStraight) &&
        left == wallOnLeft) {
      const Vec2 centre =
          0.5 * (domeWorld(best->lastSensorBefore) + domeWorld(best->firstSensorAfter));
      memory.observe(width, odo, centre, left, stepIndex, wall);
    }
  }
  // The rear-most dome of the followed side on the wall: where an opening starts once the whole
  // side has lost the wall.
  const int first = wallOnLeft ? 21 : 30;
  const int stepDir = wallOnLeft ? -1 : 1;
  for (int i = 0, s = first; i < 14; ++i, s += stepDir) {
    if (normalOf(*obs.values, s) > 0.0) {
      lastRearTouch = domeWorld(s);
      break;
    }
  }
  integrated = integratedOf();
}

bool Navigator::Impl::useMap() const {
  return (cfg.touchMap || cfg.planDrive) && cfg.source != StatusSource::Bumper;
}

TouchMap Navigator::Impl::freshMap() const {
  TouchMapConfig m;
  if (planMode()) {
    m.cellUnits = kDriveCellUnits;
    m.growUnits = kDriveGrowUnits;
    m.marginUnits = kDriveMarginUnits;
    m.nearUnits = kDriveNearUnits;
    m.nearCost = kDriveNearCost;
  }
  return TouchMap(startPoint, goal, m);
}

Vec2 Navigator::Impl::bodyCentre() const {
  return bodyPoint(0.5 * (cfg.geometry.frontX() + cfg.geometry.backX()));
}

// Touching domes of the groups whose status is a contact mark their cells (the touched surface
// lies a dome radius out along the dome's normal); the body clears the cells it stands on.
void Navigator::Impl::updateMap(bool blocked) {
  if (!blocked) {
    // Plan drive clears well inside the body: a cell is up to half a cell diagonal from the
    // touch that marked it, and a mark ahead of the front must survive the back-off.
    const double radius = planMode() ? kDriveClearUnits : kClearUnits;
    const double inset = planMode() ? kDriveClearInsetUnits : kClearUnits;
    const double back = cfg.geometry.backX() + inset;
    const double front = cfg.geometry.frontX() - inset;
    for (double x : {back, 0.5 * (back + front), front})
      touch.clear(bodyPoint(x), radius);
  }
  for (int s = 0; s < kSensorCount; ++s) {
    // Plan drive: every reading dome of a group its status calls a contact marks; the thesis
    // strategies with the map: the domes above kTouching of such a group.
    if (normalOf(*values, s) <= (planMode() ? 0.0 : kTouching)) continue;
    const SensorGroup g = groupOfSensor(s);
    if (planMode() ? !inContact(g) : groupStatus(g).kind == StatusKind::NoContact) continue;
    // Plan drive: a reading that fell since the step before is a dome leaving what it touched
    // (or its value decaying after the release): where the dome is now is not where that is.
    if (planMode() && normalOf(*values, s) < previousNormal[static_cast<std::size_t>(s)]) continue;
    const DomePlacement& d = domes[static_cast<std::size_t>(s)];
    // Plan drive: where the normal and shear values put the touch; otherwise a dome radius out
    // along the dome's normal.
    const Vec2 surface =
        planMode() ? contactPoint(s)
                   : Vec2(toVec(d.centre) + cfg.geometry.domeRadiusUnits * toVec(d.normal));
    touch.mark(sim::bodyToWorld(odo, surface));
  }
  for (int s = 0; s < kSensorCount; ++s)
    previousNormal[static_cast<std::size_t>(s)] = normalOf(*values, s);
}

Vec2 Navigator::Impl::contactPoint(int sensor) const {
  return domeContactPoint(domes[static_cast<std::size_t>(sensor)], normalOf(*values, sensor),
                          (*values)[static_cast<std::size_t>(shearOffset(sensor))],
                          cfg.geometry.domeRadiusUnits);
}

// Replans when the map has changed (at most every kReplanSteps) or the plan is old; `force`
// replans now. noWay: the search found no way from an open cell near the robot to the goal.
void Navigator::Impl::updatePlan(bool force) {
  if (!useMap()) return;
  const std::size_t age = stepIndex - planStep;
  if (!force && planned && !(touch.revision() != planRevision && age >= kReplanSteps) &&
      age < kReplanIdleSteps)
    return;
  bool snapFailed = false;
  plan = touch.plan(bodyCentre(), aim(), 80.0, &snapFailed);
  planned = true;
  planRevision = touch.revision();
  planStep = stepIndex;
  noWay = !plan && !snapFailed;
  noStart = !plan && snapFailed;
}

// Where Head to Destination heads: the plan's farthest point in sight, or the goal.
Vec2 Navigator::Impl::planTarget() const {
  if (!useMap() || !plan || plan->points.size() < 2) return goal;
  if (touch.lineOpen(bodyCentre(), goal)) return goal;  // nothing touched in the way
  const Vec2 p = touch.lookAhead(*plan, bodyCentre(), kLookAheadUnits);
  if ((p - plan->points.back()).norm() < 1e-9) return goal;
  return p;
}

// The direction of the plan from the robot (unit), or nullopt without a plan.
std::optional<Vec2> Navigator::Impl::planDirection() const {
  if (!useMap() || !plan || plan->points.size() < 2) return std::nullopt;
  const Vec2 d = planTarget() - bodyCentre();
  if (d.norm() < 1e-9) return std::nullopt;
  return d / d.norm();
}

// No way on the map: start it afresh (kMapResets times), then the goal is unreachable.
bool Navigator::Impl::mapSaysUnreachable() {
  if (!useMap() || !noWay) return false;
  if (mapResets < kMapResets) {
    ++mapResets;
    touch = freshMap();
    updatePlan(true);
    return noWay;
  }
  return true;
}

// The robot's status as the panel shows it: the followed side while following; otherwise the
// most telling group (a hole, then a dead path, corner, leaving wall, wall).
ContactStatus Navigator::Impl::integratedOf() const {
  if (strategy == Strategy::FollowWall || strategy == Strategy::GoStraight) {
    const ContactStatus s = groupStatus(sideGroup());
    if (s.kind != StatusKind::NoContact) return s;
  }
  static constexpr std::array<StatusKind, 6> kOrder{StatusKind::Hole,   StatusKind::DeadPath,
                                                    StatusKind::Corner, StatusKind::LeavingWall,
                                                    StatusKind::Wall,   StatusKind::Undecided};
  for (StatusKind k : kOrder) {
    ContactStatus found{StatusKind::NoContact, 0.0};
    for (const ContactStatus& s : status)
      if (s.kind == k && (k != StatusKind::Hole || s.holeWidthUnits > found.holeWidthUnits))
        found = s;
    if (found.kind == k) return found;
  }
  return {};
}

Command Navigator::Impl::headTo(const Vec2& target) const {
  const Vec2 d = target - position();
  const double err = sim::wrapAngle(std::atan2(d.y(), d.x()) - odo.theta);
  const double turn = cfg.turnRadiansPerSecond;
  if (std::abs(err) > 0.3) return {0.0, err > 0 ? turn : -turn};
  return {cruise(), std::clamp(1.5 * err, -turn, turn)};
}

// Arrived by odometry while the run goes on: the odometry has drifted (blocked steps). Search
// round the goal on a spiral of pitch kSearchPitchUnits out to kSearchRadiusUnits (then again),
// skipping ahead on the spiral at a contact. (Plan drive searches by its plans: planSearch.)
Command Navigator::Impl::searchGoal() {
  if (escapeSteps > 0) {
    --escapeSteps;
    return escape;
  }
  if (frontMax() > kTouching || blockedStreak > 0) {
    searchAngle += 0.8;
    escape = {-0.5 * cruise(), 0.0};
    escapeSteps = 4;
    return escape;
  }
  for (int i = 0; i < 200; ++i) {
    const double r = kSearchPitchUnits * searchAngle / (2.0 * kPi);
    if (r > kSearchRadiusUnits) {
      searchAngle = 0.0;
      // With the map: the goal was not found in kMapSearchRounds spirals round where the
      // odometry puts it. The odometry took the robot through what it touched (a closed ring
      // round the goal); the goal is unreachable.
      if (useMap() && ++searchRounds >= kMapSearchRounds) {
        finished = RunOutcome::Unreachable;
        return {};
      }
    }
    const Vec2 target = goal + r * Vec2(std::cos(searchAngle), std::sin(searchAngle));
    if ((target - position()).norm() > 25.0) return headTo(target);
    searchAngle += std::max(0.05, 20.0 / std::max(r, 20.0));
  }
  return {};
}

// Escape moves tried in turn after several blocked steps, each held a few steps: back, turn
// either way, forward.
Command Navigator::Impl::nextEscape() {
  static constexpr std::array<std::array<double, 2>, 6> kMoves{
      {{-0.5, 0.0}, {0.0, 0.6}, {-0.4, -0.6}, {0.6, 0.0}, {0.0, -0.6}, {-0.4, 0.6}}};
  // Plan drive adds arcs about points of the rear axle's line close to the body (radius about
  // 20 and 40 units, forward and backward, either way): a robot wedged across a passage between
  // a front corner and the opposite rear corner frees both only by such a pivot.
  static constexpr std::array<std::array<double, 2>, 12> kDriveMoves{{{-0.5, 0.0},
                                                                      {0.0, 0.6},
                                                                      {-0.4, -0.6},
                                                                      {0.6, 0.0},
                                                                      {0.0, -0.6},
                                                                      {-0.4, 0.6},
                                                                      {0.2, 0.6},
                                                                      {-0.2, -0.6},
                                                                      {0.2, -0.6},
                                                                      {-0.2, 0.6},
                                                                      {0.4, 0.6},
                                                                      {0.4, -0.6}}};
  const auto& m = planMode()
                      ? kDriveMoves[static_cast<std::size_t>(escapeIndex++) % kDriveMoves.size()]
                      : kMoves[static_cast<std::size_t>(escapeIndex++) % kMoves.size()];
  // Turns are mirrored so the first turn goes away from the followed wall.
  escape = {m[0] * cruise(), m[1] * away() * cfg.turnRadiansPerSecond / 0.8 * 0.8};
  escapeSteps = 4;
  return escape;
}

Command Navigator::Impl::step(const Observation& obs) {
  values = obs.values;
  if (!initialised) {
    initialised = true;
    odo = obs.start;
    dt = obs.dtSeconds;
    estimator->setStepSeconds(dt);
    // The goal as the robot knows it: its offset from the start (thesis ch. 5: direction and
    // distance to the destination).
    goal = obs.goal;
    startPoint = Vec2(obs.start.x, obs.start.y);
    if (useMap()) touch = freshMap();
  } else {
    integrate(obs.blocked);
  }
  backtracking = false;
  stepIndex = obs.step;
  blockedStreak = obs.blocked ? blockedStreak + 1 : 0;
  recentBlocked[obs.step % kWedgedWindow] = obs.blocked;
  updateStatus(obs);
  if (useMap() && !finished) {
    updateMap(obs.blocked);
    updatePlan(false);
    if (!arrived && mapSaysUnreachable()) finished = RunOutcome::Unreachable;
  }
  if (finished) return last = Command{};
  if (!arrived && (goal - position()).norm() < cfg.arriveRadiusUnits) {
    arrived = true;
    searchAngle = 0.0;
    escapeSteps = 0;
  }
  if (arrived) {
    integrated = integratedOf();
    if (planMode()) {
      Command c = planSearch();
      if (finished) c = {};
      return last = c;
    }
    return last = searchGoal();
  }
  // A Check Contact that has not settled in kCheckBudgetSteps (a pocket it keeps backing out
  // of): leave it and head for the goal again; the next contact starts a new check.
  sameStrategySteps = strategy == previousStrategy ? sameStrategySteps + 1 : 0;
  previousStrategy = strategy;
  if (strategy == Strategy::CheckContact && sameStrategySteps > kCheckBudgetSteps &&
      cfg.source != StatusSource::Bumper) {
    setStrategy(Strategy::HeadToDestination);
    sameStrategySteps = 0;
    escapeSteps = 0;
    return last = nextEscape();
  }
  Command c = choose();
  if (finished) c = {};
  integrated = integratedOf();
  return last = c;
}

Command Navigator::Impl::choose() {
  backtracking = false;
  if (backtrackLeft == 0 &&
      std::count(recentBlocked.begin(), recentBlocked.end(), true) >= kWedgedBlocked) {
    backtrackLeft = std::min(kBacktrackSteps, moved.size());
    recentBlocked.fill(false);
    escapeSteps = 0;
  }
  if (backtrackLeft > 0 && !moved.empty()) {
    --backtrackLeft;
    const Command undo{-moved.back().v, -moved.back().omega};
    moved.pop_back();
    backtracking = true;
    return undo;
  }
  backtrackLeft = 0;
  if (cfg.source == StatusSource::Bumper) {
    if (blockedStreak >= kEscapeAfter + 2 || escapeSteps > 0) return escapeMove();
    return bug2();
  }
  if (blockedStreak >= kEscapeAfter + 3 || escapeSteps > 0) return escapeMove();
  if (planMode()) return planDrive();
  switch (strategy) {
    case Strategy::HeadToDestination:
      return headToDestination();
    case Strategy::CheckContact:
      return checkContact();
    case Strategy::FollowWall:
      return followWall();
    case Strategy::GoStraight:
      return goStraight();
    case Strategy::RightUTurn:
    case Strategy::LeftUTurn:
      return uTurn();
    case Strategy::MoveThroughWall:
      return moveThroughWall();
  }
  return {};
}

Command Navigator::Impl::escapeMove() {
  if (escapeSteps > 0 && blockedStreak == 0) {
    --escapeSteps;
    return escape;
  }
  if (escapeSteps > 0 && blockedStreak > 0) escapeSteps = 0;
  if (blockedStreak >= kEscapeAfter) return nextEscape();
  escapeSteps = 0;
  return {};
}

Result<std::unique_ptr<Navigator>> Navigator::create(NavigatorConfig config) {
  auto impl = std::make_unique<Impl>();
  switch (config.source) {
    case StatusSource::Model: {
      if (!config.models || config.models->models.empty())
        return Error("the model status source needs a trained model bundle");
      bool side = false;
      for (const analysis::GroupModel& m : config.models->models)
        side = side || m.group == SensorGroup::Left || m.group == SensorGroup::Right;
      if (!side) return Error("the model bundle has no model for the left or right side");
      impl->estimator = std::make_unique<ModelStatusEstimator>(config.models);
      break;
    }
    case StatusSource::Truth:
      impl->estimator = std::make_unique<TruthStatusEstimator>();
      break;
    case StatusSource::Bumper:
      impl->estimator = std::make_unique<BumperStatusEstimator>();
      break;
  }
  if (!(config.cruiseUnitsPerSecond > 0.0) || !(config.turnRadiansPerSecond > 0.0))
    return Error("speeds must be positive");
  impl->domes = domePlacements(config.geometry);
  impl->cfg = std::move(config);
  return std::unique_ptr<Navigator>(new Navigator(std::move(impl)));
}

Navigator::Navigator(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
Navigator::~Navigator() = default;

Command Navigator::step(const Observation& observation) {
  return impl_->step(observation);
}

std::string Navigator::name() const {
  return impl_->cfg.source == StatusSource::Bumper
             ? std::string("bug2-bumper")
             : "navigator-" + std::string(statusSourceName(impl_->cfg.source));
}

Command Navigator::next(const sim::Observation& observation) {
  Observation o;
  static_cast<sim::Observation&>(o) = observation;
  return impl_->step(o);
}

std::optional<RunOutcome> Navigator::finished() const {
  return impl_->finished;
}
const NavigatorConfig& Navigator::config() const {
  return impl_->cfg;
}
Strategy Navigator::strategy() const {
  return impl_->strategy;
}
const std::array<ContactStatus, kGroupCount>& Navigator::groupStatus() const {
  return impl_->status;
}
ContactStatus Navigator::integratedStatus() const {
  return impl_->integrated;
}
const std::vector<RememberedHole>& Navigator::holes() const {
  return impl_->memory.holes();
}
const Pose2d& Navigator::odometry() const {
  return impl_->odo;
}
std::size_t Navigator::checkContactStarts() const {
  return impl_->checkStarts;
}
bool Navigator::arrived() const {
  return impl_->arrived;
}
const TouchMap& Navigator::touchMap() const {
  return impl_->touch;
}
const std::optional<TouchPlan>& Navigator::plan() const {
  return impl_->plan;
}

}  // namespace tactile::nav
