#include "sim/truth.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "sim/simulator.h"
#include "sim/world.h"

namespace tactile::sim {
namespace {

// A vertex that moved less than this along the robot's axis since the previous step stood still.
constexpr double kStillUnits = 0.25;

bool mayLeaveWall(SensorGroup g) {
  return g == SensorGroup::Left || g == SensorGroup::Right || g == SensorGroup::RearLeftCorner ||
         g == SensorGroup::RearRightCorner;
}

bool mayBeDeadPath(SensorGroup g) {
  return g == SensorGroup::Front || g == SensorGroup::FrontLeftCorner ||
         g == SensorGroup::FrontRightCorner || g == SensorGroup::Left || g == SensorGroup::Right;
}

// A world point in the robot's body frame (x forward).
double bodyX(const Pose2d& pose, const Vec2& p) {
  return std::cos(pose.theta) * (p.x() - pose.x) + std::sin(pose.theta) * (p.y() - pose.y);
}

}  // namespace

TruthTracker::TruthTracker(const RobotGeometry& geometry)
    : geometry_(geometry), domes_(domePlacements(geometry)) {
  reset();
}

void TruthTracker::reset() {
  classes_.fill(ContactClass::NoContact);
  lastTouching_.fill(ContactClass::NoContact);
  previousPose_.reset();
}

ContactClass TruthTracker::touching(const World& world, const Pose2d& pose,
                                    const PoseContact& contact, const GroupInfo& info,
                                    ContactClass previous) const {
  const auto& edges = world.edges();
  const double flatCos = std::cos(kFlatVertexDegrees * std::numbers::pi / 180.0);
  // The wall: the edge of the most compressed dome touching an edge's interior (a dome on a
  // vertex touches both edges there, so its edge says nothing about direction); the most
  // compressed dome of all when every dome is on a vertex.
  int wall = -1;
  double deepest = -1.0;
  int interiorWall = -1;
  double interiorDeepest = -1.0;
  bool twoDirections = false;
  int firstEdge = -1;
  for (int d = info.firstSensor; d < info.firstSensor + info.sensorCount; ++d) {
    const DomeContact& dc = contact.domes[d];
    if (dc.edge < 0) continue;
    if (dc.normal > deepest) {
      deepest = dc.normal;
      wall = dc.edge;
    }
    if (dc.vertex >= 0) continue;
    if (dc.normal > interiorDeepest) {
      interiorDeepest = dc.normal;
      interiorWall = dc.edge;
    }
    if (firstEdge < 0) {
      firstEdge = dc.edge;
    } else if (std::abs(edges[firstEdge].dir.dot(edges[dc.edge].dir)) < flatCos) {
      twoDirections = true;
    }
  }
  if (interiorWall >= 0) wall = interiorWall;
  if (twoDirections) return ContactClass::Corner;

  // A dome whose closest point is a non-flat vertex sits on it: the group feels a corner there.
  bool feltVertex = false;
  int frontTouching = -1;  // the group's front-most touching dome (largest body x)
  for (int d = info.firstSensor; d < info.firstSensor + info.sensorCount; ++d) {
    const DomeContact& dc = contact.domes[d];
    if (dc.edge < 0) continue;
    if (dc.vertex >= 0 && world.vertexKind(dc.vertex) != VertexKind::Flat) feltVertex = true;
    if (frontTouching < 0 || domes_[d].centre.x > domes_[frontTouching].centre.x) frontTouching = d;
  }
  // Leaving a wall (L, R, RLC, RRC). The group lies along wall e, which runs along the robot
  // (within kFlatVertexDegrees of its heading), and touches nothing but e and its ends; a convex
  // end v of e has reached the group's front-most touching dome (that dome is on v, or v lies
  // between it and the next dome of the group ahead, which has lost the wall); and the group's
  // front-most dome is off the wall or on v. The group enters LeavingWall from Wall when v moves
  // rearward in the robot's frame (the robot slides off the end) while a dome of the group is
  // still on e's interior; it stays LeavingWall while the end stays so and a dome of the group is
  // still on e's interior, however the robot moves.
  if (mayLeaveWall(info.group) &&
      (previous == ContactClass::Wall || previous == ContactClass::LeavingWall)) {
    int front = info.firstSensor;
    for (int d = info.firstSensor; d < info.firstSensor + info.sensorCount; ++d)
      if (domes_[d].centre.x > domes_[front].centre.x) front = d;
    const Vec2 heading(std::cos(pose.theta), std::sin(pose.theta));
    const double frontX = domes_[frontTouching].centre.x;
    double nextX = std::numeric_limits<double>::infinity();
    for (int d = info.firstSensor; d < info.firstSensor + info.sensorCount; ++d) {
      if (domes_[d].centre.x > frontX) nextX = std::min(nextX, domes_[d].centre.x);
    }
    const int onFront = contact.domes[frontTouching].vertex;
    const auto leavesWall = [&](int e) {
      const Edge& w = edges[e];
      if (std::abs(w.dir.dot(heading)) < flatCos) return false;
      bool onInterior = false;
      for (int d = info.firstSensor; d < info.firstSensor + info.sensorCount; ++d) {
        const DomeContact& dc = contact.domes[d];
        if (dc.edge < 0) continue;
        if (dc.edge != e && dc.vertex != w.vertexA && dc.vertex != w.vertexB)
          return false;  // touches something besides this wall and its ends
        if (dc.vertex < 0) onInterior = true;
      }
      for (const auto& [vertex, at] : {std::pair{w.vertexA, w.a}, std::pair{w.vertexB, w.b}}) {
        if (world.vertexKind(vertex) != VertexKind::Convex) continue;
        const DomeContact& fc = contact.domes[front];
        if (fc.edge >= 0 && fc.vertex != vertex) continue;
        const double x = bodyX(pose, at);
        if (onFront != vertex && !(std::isfinite(nextX) && x > frontX && x < nextX)) continue;
        // The group still lies along the wall behind the end: a dome of it is on e's interior.
        // Without one, the group feels nothing but the end itself, which reads the same as any
        // convex vertex passing along the side (a tip met side-on): that is a corner (rule 6).
        if (!onInterior) continue;
        if (previous == ContactClass::LeavingWall) return true;
        if (previousPose_ && bodyX(*previousPose_, at) - x > kStillUnits) return true;
      }
      return false;
    };
    if (leavesWall(wall)) return ContactClass::LeavingWall;
  }
  if (feltVertex) return ContactClass::Corner;
  // A group that felt a corner stays Corner while a non-flat end of an edge it touches is still
  // within a dome radius of a touching dome's centre: a robot working round a corner keeps
  // rolling on and off its vertex.
  if (previous == ContactClass::Corner) {
    const double reach = geometry_.domeRadiusUnits;
    for (int d = info.firstSensor; d < info.firstSensor + info.sensorCount; ++d) {
      const DomeContact& dc = contact.domes[d];
      if (dc.edge < 0) continue;
      const Vec2 centre = bodyToWorld(pose, Vec2(domes_[d].centre.x, domes_[d].centre.y));
      const Edge& e = edges[dc.edge];
      for (const auto& [vertex, at] : {std::pair{e.vertexA, e.a}, std::pair{e.vertexB, e.b}}) {
        if (world.vertexKind(vertex) != VertexKind::Flat && (at - centre).norm() < reach)
          return ContactClass::Corner;
      }
    }
  }
  return ContactClass::Wall;
}

void TruthTracker::update(const World& world, const Pose2d& pose, const PoseContact& contact,
                          const double* values) {
  std::array<int, kGroupCount> count{};
  for (int d = 0; d < kSensorCount; ++d) {
    if (contact.domes[d].edge >= 0) ++count[groupIndex(groupOfSensor(d))];
  }
  const auto touches = [&](SensorGroup g) { return count[groupIndex(g)] > 0; };
  const bool pocket =
      touches(SensorGroup::Front) && touches(SensorGroup::Left) && touches(SensorGroup::Right);

  for (const GroupInfo& info : kSensorGroups) {
    const int g = groupIndex(info.group);
    bool anyValue = false;
    for (int d = info.firstSensor; d < info.firstSensor + info.sensorCount; ++d)
      anyValue = anyValue || values[normalOffset(d)] != 0.0 || values[shearOffset(d)] != 0.0;
    ContactClass cls = ContactClass::NoContact;
    if (!anyValue) {
      cls = ContactClass::NoContact;
    } else if (count[g] == 0) {
      // A decay tail after release: what the group was touching. Values without any touch
      // before (not possible from a reset) read as Wall.
      cls = lastTouching_[g] == ContactClass::NoContact ? ContactClass::Wall : lastTouching_[g];
    } else if (pocket && mayBeDeadPath(info.group)) {
      cls = ContactClass::DeadPath;
    } else {
      cls = touching(world, pose, contact, info, classes_[g]);
    }
    if (count[g] > 0) lastTouching_[g] = cls;
    classes_[g] = cls;
  }
  previousPose_ = pose;
}

void smoothTruth(std::vector<ContactClass>& truth, std::size_t steps) {
  if (truth.size() != steps * kGroupCount) return;
  const auto at = [&](std::size_t k, int g) -> ContactClass& {
    return truth[k * kGroupCount + static_cast<std::size_t>(g)];
  };
  for (int g = 0; g < kGroupCount; ++g) {
    std::size_t k = 0;
    while (k < steps) {
      if (at(k, g) == ContactClass::NoContact) {
        ++k;
        continue;
      }
      // One contact episode [k, end): segments after the first that are too short merge back.
      std::size_t end = k;
      while (end < steps && at(end, g) != ContactClass::NoContact)
        ++end;
      ContactClass before = at(k, g);
      std::size_t s = k;
      while (s < end) {
        const ContactClass cls = at(s, g);
        std::size_t e = s;
        while (e < end && at(e, g) == cls)
          ++e;
        if (s > k && e - s < static_cast<std::size_t>(kMinTruthSegmentSteps)) {
          for (std::size_t i = s; i < e; ++i)
            at(i, g) = before;
        } else {
          before = cls;
        }
        s = e;
      }
      // A short first segment has no segment before it: it takes the class of the one after.
      std::size_t first = k;
      while (first < end && at(first, g) == at(k, g))
        ++first;
      if (first < end && first - k < static_cast<std::size_t>(kMinTruthSegmentSteps)) {
        const ContactClass next = at(first, g);
        for (std::size_t i = k; i < first; ++i)
          at(i, g) = next;
      }
      k = end;
    }
  }
}

}  // namespace tactile::sim
