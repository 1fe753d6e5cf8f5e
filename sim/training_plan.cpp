#include "sim/training_plan.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <random>

#include "run/builtin_scenes.h"
#include "sim/office_scene.h"
#include "sim/scene_source.h"

namespace tactile::sim {
namespace {

// Robot body: front edge 105 units ahead of the rear axle, back edge 35 behind, 40 to each side,
// domes 6 units proud of the outline (run/robot_geometry.h).
constexpr double kFront = 105.0;
constexpr double kBack = 35.0;
constexpr double kHalfWidth = 40.0;
constexpr double kDome = 6.0;
constexpr double kAxleX = 1000.0;
constexpr double kAxleY = 1000.0;

class Draw {
 public:
  explicit Draw(std::uint64_t seed) : rng_(seed) {}
  double uniform(double lo, double hi) {
    return lo + (hi - lo) * static_cast<double>(rng_() >> 11) * 0x1.0p-53;
  }
  int integer(int lo, int hi) { return lo + static_cast<int>(uniform(0.0, hi - lo + 1 - 1e-9)); }
  bool coin() { return uniform(0.0, 1.0) < 0.5; }
  std::uint64_t next() { return rng_(); }

 private:
  std::mt19937_64 rng_;
};

Obstacle rect(double x0, double y0, double x1, double y1) {
  return Obstacle{{Vec2(x0, y0), Vec2(x1, y0), Vec2(x1, y1), Vec2(x0, y1)}};
}

// A polygon turned by `angle` about (cx, cy).
Obstacle turned(Obstacle o, double cx, double cy, double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  for (Vec2& p : o.polygon) {
    const double x = p.x() - cx, y = p.y() - cy;
    p = Vec2(cx + c * x - s * y, cy + s * x + c * y);
  }
  return o;
}

Scene openRoom(std::vector<Obstacle> obstacles) {
  Scene s;
  s.name = "training";
  s.bounds = {0, 0, 2000, 2000};
  s.obstacles = std::move(obstacles);
  s.start = {kAxleX, kAxleY, 0.0};
  s.goal = Vec2(1900, 1900);
  return s;
}

using Leg = ScriptDriver::Leg;

// Pushing into something with small turns either way, so the readings vary while blocked.
void pushAndWiggle(std::vector<Leg>& legs, Draw& draw, double v, int steps) {
  for (int done = 0; done < steps;) {
    const int n = draw.integer(5, 15);
    legs.push_back({{v, draw.uniform(-0.3, 0.3)}, n});
    done += n;
  }
}

PlannedRun wallEnd(Draw& draw, bool slow, std::size_t round) {
  // A short corridor 2 x gap wider than the robot with dome surfaces, from just behind the robot
  // to 60-200 units ahead of its front. Below a gap of about -3 the rear-corner domes touch too.
  // Each pass drives out of the far end until the whole robot is clear, turns in place, drives
  // back through the corridor and out of the near end, turns again and comes back to the start:
  // the robot leaves the walls twice a pass, always forwards (backing onto a wall's end reads
  // like leaving it but is not).
  // The gap is stratified over the plan's runs of the kind (four bands in turn), so that a few
  // runs cover its whole range.
  const double lo = slow ? -4.5 : -3.5;
  const double hi = slow ? -2.5 : 1.0;
  const double gap =
      lo + (hi - lo) * (static_cast<double>(round % 4) + draw.uniform(0.0, 1.0)) / 4.0;
  const double y = kHalfWidth + kDome + gap;
  const double near = kAxleX - kBack - 5.0;
  const double end = kAxleX + kFront + draw.uniform(60.0, 200.0);
  PlannedRun run;
  run.scene = openRoom(
      {rect(near, kAxleY - y - 60, end, kAxleY - y), rect(near, kAxleY + y, end, kAxleY + y + 60)});
  std::vector<Leg> legs;
  // Turning in place sweeps 126 units about the rear axle: clear the corridor by more.
  constexpr double kClear = 140.0;
  const int passes = slow ? draw.integer(10, 14) : draw.integer(4, 6);
  const auto forward = [&](double v, double distance) {
    legs.push_back({{v, 0.0}, static_cast<int>(std::round(distance / (v * 0.1)))});
  };
  const auto turnAround = [&] {
    const int steps = draw.integer(15, 30);
    legs.push_back({{0.0, std::numbers::pi / (steps * 0.1)}, steps});
  };
  for (int i = 0; i < passes; ++i) {
    const double v = slow ? draw.uniform(5.0, 15.0) : draw.uniform(10.0, 60.0);
    forward(v, end + kClear - kAxleX);
    turnAround();
    forward(v, (end + kClear) - (near - kClear));
    turnAround();
    forward(v, kAxleX - (near - kClear));
  }
  run.driver = std::make_unique<ScriptDriver>(std::move(legs));
  run.kind = "wall-end";
  return run;
}

PlannedRun insideCorner(Draw& draw, bool left) {
  const double side = left ? 1.0 : -1.0;
  const double ahead = draw.uniform(20.0, 150.0);
  const double beside = kHalfWidth + kDome + draw.uniform(-1.0, 30.0);
  const double fx = kAxleX + kFront + kDome + ahead;
  const double sy = kAxleY + side * beside;
  // An L: a wall across ahead and a wall along the chosen side, meeting in a concave corner.
  std::vector<Obstacle> walls{rect(fx, 300, fx + 60, 1700)};
  walls.push_back(left ? rect(300, sy, fx + 60, sy + 60) : rect(300, sy - 60, fx + 60, sy));
  PlannedRun run;
  run.scene = openRoom(std::move(walls));
  std::vector<Leg> legs;
  const int rounds = draw.integer(4, 7);
  for (int i = 0; i < rounds; ++i) {
    const double v = draw.uniform(15.0, 50.0);
    const double turn = side * draw.uniform(0.05, 0.25);
    legs.push_back({{v, turn}, static_cast<int>((ahead + 40.0) / (v * 0.1)) + 5});
    pushAndWiggle(legs, draw, v * 0.5, draw.integer(40, 90));
    legs.push_back({{-v, -turn}, static_cast<int>((ahead + 40.0) / (v * 0.1))});
  }
  run.driver = std::make_unique<ScriptDriver>(std::move(legs));
  run.kind = "inside-corner";
  return run;
}

// Plays a list of approaches to obstacles placed round the start: turn in place to a heading,
// drive (forwards or backwards) until blocked or a distance is covered, push with small turns
// either way (stopping if that slides 25 units along the obstacle), then drive back, steering
// toward the start once clear, until the start is abeam. Unlike ScriptDriver it steers by the
// pose, so every approach begins from about the start whatever the pushing did to the heading.
class ApproachDriver : public Driver {
 public:
  struct Approach {
    double heading = 0.0;    // world frame, radians
    double dir = 1.0;        // +1 front first, -1 back first
    double v = 20.0;         // units/s
    double maxTravel = 0.0;  // give the approach up after this distance without being blocked
    std::vector<Leg> push;   // played once blocked (speeds signed already)
  };
  explicit ApproachDriver(std::vector<Approach> approaches) : approaches_(std::move(approaches)) {}
  std::string name() const override { return "script"; }
  bool gaveUp() const override { return index_ >= approaches_.size(); }

  Command next(const Observation& obs) override {
    // Stuck while turning or backing (the pushing moved the robot somewhere it cannot turn): end
    // the run rather than grind against the obstacle.
    stuck_ = obs.blocked && (phase_ == Phase::Turn || phase_ == Phase::Back) ? stuck_ + 1 : 0;
    if (stuck_ > kMaxStuckSteps) index_ = approaches_.size();
    while (index_ < approaches_.size()) {
      const Approach& a = approaches_[index_];
      const Vec2 at(obs.pose.x, obs.pose.y);
      const Vec2 along(std::cos(obs.pose.theta), std::sin(obs.pose.theta));
      ++phaseSteps_;
      switch (phase_) {
        case Phase::Turn: {
          const double err = std::remainder(a.heading - obs.pose.theta, 2.0 * std::numbers::pi);
          if (std::abs(err) > 1e-3 && phaseSteps_ <= kMaxPhaseSteps)
            return {0.0, std::clamp(err / obs.dtSeconds, -kTurnRate, kTurnRate)};
          enter(Phase::Drive);
          from_ = at;
          continue;
        }
        case Phase::Drive:
          if (phaseSteps_ > 1 &&
              (obs.blocked || (at - from_).norm() >= a.maxTravel || phaseSteps_ > kMaxPhaseSteps)) {
            enter(Phase::Push);
            leg_ = 0;
            legDone_ = 0;
            from_ = at;
            continue;
          }
          return {a.dir * a.v, 0.0};
        case Phase::Push:
          // A push that slides off the tip would drive on into the open: stop it 25 units on.
          if ((at - from_).norm() > kMaxSlide) leg_ = a.push.size();
          while (leg_ < a.push.size() && legDone_ >= a.push[leg_].steps) {
            ++leg_;
            legDone_ = 0;
          }
          if (leg_ < a.push.size()) {
            ++legDone_;
            return a.push[leg_].command;
          }
          enter(Phase::Back);
          continue;
        case Phase::Back: {
          // Back the way it came while the start lies ahead along the motion; once 15 units off
          // the obstacle, steer so the motion points at the start (the pushing may have turned
          // the robot), so the next turn in place happens there.
          if (phaseSteps_ == 1) from_ = at;
          const Vec2 start(obs.start.x, obs.start.y);
          const Vec2 toStart = start - at;
          const double ahead = toStart.dot(-a.dir * along);
          if (ahead > 0.5 * a.v * obs.dtSeconds && phaseSteps_ <= kMaxPhaseSteps) {
            double omega = 0.0;
            if ((at - from_).norm() > 15.0) {
              const double want =
                  std::atan2(toStart.y(), toStart.x()) + (a.dir > 0 ? std::numbers::pi : 0.0);
              omega = std::clamp(
                  2.0 * std::remainder(want - obs.pose.theta, 2.0 * std::numbers::pi), -0.5, 0.5);
            }
            return {-a.dir * a.v, omega};
          }
          enter(Phase::Turn);
          ++index_;
          continue;
        }
      }
    }
    return {};
  }

 private:
  enum class Phase { Turn, Drive, Push, Back };
  static constexpr int kMaxPhaseSteps = 600;
  static constexpr int kMaxStuckSteps = 20;
  static constexpr double kMaxSlide = 25.0;
  static constexpr double kTurnRate = 1.0;  // rad/s
  void enter(Phase p) {
    phase_ = p;
    phaseSteps_ = 0;
  }
  std::vector<Approach> approaches_;
  std::size_t index_ = 0;
  Phase phase_ = Phase::Turn;
  int phaseSteps_ = 0;
  Vec2 from_ = Vec2::Zero();
  std::size_t leg_ = 0;
  int legDone_ = 0;
  int stuck_ = 0;
};

PlannedRun tips(Draw& draw, std::size_t round) {
  // Five convex tips (squares turned 45 degrees, each turned again about its tip) round the start,
  // their tips 140-165 units from the rear axle, clear of the 126 units a turn in place sweeps.
  // Each tip sits off the ray from the start by its own lateral offset; the offsets are stratified
  // over five bands of -45..45, so one run meets tips on every part of the front and the back, and
  // on the corners. The robot turns to each tip in turn (heading jittered by up to 0.1 rad), drives
  // into it front first, pushes with small turns, comes back to the start, then does the same
  // with the back.
  constexpr int kTips = 5;
  const double first = draw.uniform(0.0, 2.0 * std::numbers::pi);
  std::array<int, kTips> band{0, 1, 2, 3, 4};
  std::rotate(band.begin(), band.begin() + static_cast<long>(round % kTips), band.end());
  for (int i = kTips - 1; i > 0; --i)
    std::swap(band[static_cast<std::size_t>(i)],
              band[static_cast<std::size_t>(draw.integer(0, i))]);
  PlannedRun run;
  std::vector<Obstacle> obstacles;
  std::array<double, kTips> ray{}, reach{};
  for (int k = 0; k < kTips; ++k) {
    const std::size_t ks = static_cast<std::size_t>(k);
    ray[ks] = first + 2.0 * std::numbers::pi * k / kTips;
    reach[ks] = draw.uniform(140.0, 165.0);
    const double lateral = -45.0 + 18.0 * (band[ks] + draw.uniform(0.0, 1.0));
    const double half = draw.uniform(35.0, 65.0);
    const Vec2 u(std::cos(ray[ks]), std::sin(ray[ks]));
    const Vec2 n(-u.y(), u.x());
    const Vec2 tip = Vec2(kAxleX, kAxleY) + reach[ks] * u + lateral * n;
    const Vec2 c = tip + half * u;
    Obstacle d{{tip, c + half * n, c + half * u, c - half * n}};
    obstacles.push_back(turned(d, tip.x(), tip.y(), draw.uniform(-0.25, 0.25)));
  }
  run.scene = openRoom(std::move(obstacles));
  // Front and back in turn, so a run that ends early (stuck) has met tips with both.
  std::vector<ApproachDriver::Approach> approaches;
  for (int k = 0; k < kTips; ++k) {
    for (const double dir : {1.0, -1.0}) {
      const std::size_t ks = static_cast<std::size_t>(k);
      ApproachDriver::Approach a;
      a.dir = dir;
      a.heading = ray[ks] + (dir > 0 ? 0.0 : std::numbers::pi) + draw.uniform(-0.1, 0.1);
      a.v = draw.uniform(10.0, 40.0);
      a.maxTravel = reach[ks] - (dir > 0 ? kFront : kBack) - kDome + 30.0;
      pushAndWiggle(a.push, draw, dir * a.v * 0.4, draw.integer(50, 100));
      approaches.push_back(std::move(a));
    }
  }
  run.driver = std::make_unique<ApproachDriver>(std::move(approaches));
  run.kind = "tips";
  run.options.maxSteps = 6000;
  return run;
}

PlannedRun reverse(Draw& draw, int corner) {
  const double gap = draw.uniform(10.0, 120.0);
  const double bx = kAxleX - kBack - kDome - gap;
  std::vector<Obstacle> walls{rect(bx - 60, 300, bx, 1700)};
  if (corner != 0) {
    // A concave corner behind: a side wall along the back half of one side.
    const double side = corner > 0 ? 1.0 : -1.0;
    const double sy = kAxleY + side * (kHalfWidth + kDome + draw.uniform(-4.5, 1.0));
    walls.push_back(side > 0 ? rect(bx - 60, sy, kAxleX + 20, sy + 60)
                             : rect(bx - 60, sy - 60, kAxleX + 20, sy));
  }
  // With a corner, the back wall is turned so that its end at the side wall is the nearer one:
  // the corner group is then what backs into it, pressed on both walls. Turned the other way,
  // or by less than about 0.03 rad, the middle of the back met the wall first in 5 of 10 such runs
  // and the corner group never felt the corner.
  const double turn =
      corner == 0 ? draw.uniform(-0.1, 0.1) : (corner > 0 ? -1.0 : 1.0) * draw.uniform(0.03, 0.1);
  PlannedRun run;
  run.scene = openRoom({turned(walls[0], bx, kAxleY, turn)});
  for (std::size_t i = 1; i < walls.size(); ++i)
    run.scene.obstacles.push_back(walls[i]);
  std::vector<Leg> legs;
  const int rounds = draw.integer(6, 9);
  for (int i = 0; i < rounds; ++i) {
    const double v = draw.uniform(10.0, 40.0);
    legs.push_back({{-v, draw.uniform(-0.1, 0.1)}, static_cast<int>((gap + 20.0) / (v * 0.1))});
    pushAndWiggle(legs, draw, -v * 0.5, draw.integer(50, 100));
    legs.push_back({{v, 0.0}, static_cast<int>((gap + 10.0) / (v * 0.1))});
  }
  run.driver = std::make_unique<ScriptDriver>(std::move(legs));
  run.kind = "reverse";
  return run;
}

PlannedRun pocket(Draw& draw, std::size_t round) {
  // A U open towards the robot, a few units wider than the robot with its domes.
  // The side domes press the pocket's sides (by 0.5 to 3 units), so F, L and R all touch at its
  // end.
  // The press is stratified over the plan's pocket runs (four bands of 0.5..3 in turn), so a few
  // runs already cover the whole range instead of whatever a few draws give.
  const double band = static_cast<double>(round % 4);
  const double inner = kHalfWidth + kDome - (0.5 + 2.5 * (band + draw.uniform(0.0, 1.0)) / 4.0);
  const double mouth = kAxleX + kFront - draw.uniform(40.0, 100.0);  // the robot starts inside
  const double depth = draw.uniform(150.0, 300.0);
  const double endX = mouth + depth;
  PlannedRun run;
  run.scene = openRoom({rect(mouth, kAxleY - inner - 60, endX + 60, kAxleY - inner),
                        rect(mouth, kAxleY + inner, endX + 60, kAxleY + inner + 60),
                        rect(endX, kAxleY - inner, endX + 60, kAxleY + inner)});
  std::vector<Leg> legs;
  const int rounds = draw.integer(3, 5);
  const double room = endX - (kAxleX + kFront + kDome);
  for (int i = 0; i < rounds; ++i) {
    const double v = draw.uniform(15.0, 50.0);
    legs.push_back({{v, 0.0}, static_cast<int>(room / (v * 0.1)) + 5});
    pushAndWiggle(legs, draw, v * 0.5, draw.integer(50, 100));
    legs.push_back({{-v, 0.0}, static_cast<int>(std::min(room, 120.0) / (v * 0.1))});
  }
  run.driver = std::make_unique<ScriptDriver>(std::move(legs));
  run.kind = "pocket";
  return run;
}

PlannedRun sideTips(Draw& draw) {
  // Rows of convex tips (squares turned 45 degrees) along both sides, each pressing the side
  // domes by its own 0.5..4.5 units (past about 2.2 the corner groups' side domes touch it too).
  // The robot drives past them and back: side and corner groups roll over a vertex met side-on.
  PlannedRun run;
  const int perSide = draw.integer(3, 5);
  double span = 0.0;
  for (const double side : {1.0, -1.0}) {
    double x = kAxleX + kFront + kDome + draw.uniform(20.0, 80.0);
    for (int i = 0; i < perSide; ++i) {
      const double half = draw.uniform(30.0, 70.0);
      const double tipY = kAxleY + side * (kHalfWidth + kDome - draw.uniform(1.5, 4.5));
      const double cy = tipY + side * half;
      Obstacle d{{Vec2(x - half, cy), Vec2(x, cy - half), Vec2(x + half, cy), Vec2(x, cy + half)}};
      run.scene.obstacles.push_back(turned(d, x, cy, draw.uniform(-0.15, 0.15)));
      span = std::max(span, x - kAxleX);
      x += draw.uniform(150.0, 260.0);
    }
  }
  const auto obstacles = std::move(run.scene.obstacles);
  run.scene = openRoom(obstacles);
  std::vector<Leg> legs;
  const int passes = draw.integer(3, 5);
  const double travel = span + kBack + 40.0;
  for (int i = 0; i < passes; ++i) {
    const double v = draw.uniform(10.0, 40.0);
    const int steps = static_cast<int>(std::ceil(travel / (v * 0.1)));
    legs.push_back({{v, 0.0}, steps});
    legs.push_back({{-v, 0.0}, steps});
  }
  run.driver = std::make_unique<ScriptDriver>(std::move(legs));
  run.kind = "side tip";
  return run;
}

}  // namespace

Command ScriptDriver::next(const Observation&) {
  while (leg_ < legs_.size() && done_ >= legs_[leg_].steps) {
    ++leg_;
    done_ = 0;
  }
  if (leg_ >= legs_.size()) return {};
  ++done_;
  return legs_[leg_].command;
}

std::size_t ScriptDriver::totalSteps() const {
  std::size_t n = 0;
  for (const Leg& l : legs_)
    n += static_cast<std::size_t>(std::max(0, l.steps));
  return n;
}

PlanSlot trainingPlanSlot(std::size_t index) {
  if (index % 2 == 0) return {PlanSlot::Kind::Numbered, index / 2};
  const std::size_t extra = index / 2;
  if (extra % 3 == 2) return {PlanSlot::Kind::ExtraPocket, extra / 3};
  return {PlanSlot::Kind::OfficeDrive, extra / 3 * 2 + extra % 3};
}

namespace {

// The wall follower in a generated office map of its own, on the side given: driving as a robot
// in use drives, walls on the followed side most of the time, the front meeting walls and
// furniture at an angle while it turns, wall ends passed at the driver's own speed.
PlannedRun officeDrive(std::uint64_t seed, std::size_t number) {
  Draw draw(seed * 0x9E3779B97F4A7C15ull + number * 0xD1B54A32D192ED03ull + 0x6A09E667F3BCC909ull);
  PlannedRun run;
  run.sceneName = "random:office:" + std::to_string(draw.next() % kFirstBenchmarkSceneSeed);
  auto loaded = loadScene(run.sceneName);
  if (loaded) run.scene = std::move(loaded.value());
  const std::uint64_t driverSeed = draw.next();
  const FollowSide side = number % 2 == 0 ? FollowSide::Left : FollowSide::Right;
  run.driver = makeDriver("wall-follow", driverSeed, side);
  run.options.seed = driverSeed;
  run.options.followSide = side;
  run.options.maxSteps = 4000;
  run.kind = side == FollowSide::Left ? kOfficeDriveKindLeft : kOfficeDriveKindRight;
  return run;
}

}  // namespace

PlannedRun planTrainingRun(std::uint64_t seed, std::size_t planIndex) {
  const PlanSlot slot = trainingPlanSlot(planIndex);
  if (slot.kind == PlanSlot::Kind::OfficeDrive) return officeDrive(seed, slot.number);
  if (slot.kind == PlanSlot::Kind::ExtraPocket) {
    // Its own stream; the extra pockets take the four press bands in turn, as the numbered ones
    // do.
    Draw draw(seed * 0x9E3779B97F4A7C15ull + slot.number * 0xD1B54A32D192ED03ull +
              0xBB67AE8584CAA73Bull);
    PlannedRun run = pocket(draw, slot.number);
    run.kind = kExtraPocketKind;
    const auto* script = static_cast<const ScriptDriver*>(run.driver.get());
    run.options.maxSteps = script->totalSteps();
    run.options.stopAtGoal = false;
    return run;
  }
  const std::size_t index = slot.number;
  // One stream per run, so a run does not depend on how many came before it.
  Draw draw(seed * 0x9E3779B97F4A7C15ull + index * 0xD1B54A32D192ED03ull + 1);
  const int kind = static_cast<int>(index % kTrainingPlanKinds);
  // Which pass of the recipe this is: alternates sides and positions between passes.
  const std::size_t round = index / kTrainingPlanKinds;
  PlannedRun run;
  switch (kind) {
    case 0:
    case 1: {
      static constexpr std::array<const char*, 4> kScenes{"room1", "room2", "room3", "chapter5"};
      run.sceneName = kind == 0 ? kScenes[round % kScenes.size()]
                                : "random:" + std::to_string(draw.integer(20, 60)) + ":" +
                                      std::to_string(draw.next() % 100000);
      auto loaded = loadScene(run.sceneName);
      if (loaded) run.scene = std::move(loaded.value());
      const std::uint64_t driverSeed = draw.next();
      run.driver = makeDriver("wall-follow", driverSeed);
      run.options.seed = driverSeed;
      run.options.maxSteps = 3000;
      run.kind = kind == 0 ? "wall-follow" : "cluttered";
      return run;
    }
    case 10:
    case 11: {
      // Driving in a generated office map: the Bug-2 driver or the wall follower heads for the
      // map's goal, meeting walls, door jambs, bumps and furniture on the way. Map seeds stay
      // below kFirstBenchmarkSceneSeed, which benchmarks keep for themselves.
      run.sceneName = "random:office:" + std::to_string(draw.next() % kFirstBenchmarkSceneSeed);
      auto loaded = loadScene(run.sceneName);
      if (loaded) run.scene = std::move(loaded.value());
      const std::uint64_t driverSeed = draw.next();
      run.driver = makeDriver(kind == 10 ? "bug" : "wall-follow", driverSeed);
      run.options.seed = driverSeed;
      run.options.maxSteps = 4000;
      run.kind = kind == 10 ? "office bug" : "office wall-follow";
      return run;
    }
    case 2:
      run = wallEnd(draw, false, round);
      break;
    case 3:
      run = insideCorner(draw, round % 2 == 0);
      break;
    case 4:
      return tips(draw, round);
    case 5:
      run = reverse(draw, std::array{1, -1, 0}[round % 3]);
      break;
    case 6:
      run = pocket(draw, round);
      break;
    case 7:
      run = wallEnd(draw, true, round);
      break;
    case 8:
      return tips(draw, round + 2);
    default:  // 9
      run = sideTips(draw);
      break;
  }
  const auto* script = static_cast<const ScriptDriver*>(run.driver.get());
  run.options.maxSteps = script->totalSteps();
  run.options.stopAtGoal = false;
  return run;
}

}  // namespace tactile::sim
