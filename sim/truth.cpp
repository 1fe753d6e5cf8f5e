#include "sim/truth.h"

#include <cmath>
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
  const double reach = geometry_.domeRadiusUnits + kFeatureMarginUnits;
  const double reach2 = reach * reach;
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

  // Non-flat vertices (ends of touched edges) within reach of a touching dome.
  bool nearVertex = false;
  bool leaving = false;
  bool approaching = false;
  bool onlyThisWall = true;
  const Edge& w = edges[wall];
  for (int d = info.firstSensor; d < info.firstSensor + info.sensorCount; ++d) {
    const DomeContact& dc = contact.domes[d];
    if (dc.edge < 0) continue;
    if (dc.edge != wall && dc.vertex != w.vertexA && dc.vertex != w.vertexB) onlyThisWall = false;
    const Vec2 centre = bodyToWorld(pose, Vec2(domes_[d].centre.x, domes_[d].centre.y));
    const Edge& e = edges[dc.edge];
    for (const auto& [vertex, at] : {std::pair{e.vertexA, e.a}, std::pair{e.vertexB, e.b}}) {
      if (world.vertexKind(vertex) == VertexKind::Flat) continue;
      if ((at - centre).squaredNorm() >= reach2) continue;
      nearVertex = true;
      // Sliding off the end of the wall: a convex end of the wall moving rearward.
      const bool endOfWall = vertex == w.vertexA || vertex == w.vertexB;
      if (!endOfWall) onlyThisWall = false;
      if (endOfWall && world.vertexKind(vertex) == VertexKind::Convex && previousPose_) {
        const double rearward = bodyX(*previousPose_, at) - bodyX(pose, at);
        if (rearward > kStillUnits) leaving = true;
        if (rearward < -kStillUnits) approaching = true;
      }
    }
  }
  if (mayLeaveWall(info.group) && onlyThisWall) {
    // Leaving a wall is what a group does that was on the wall: one coming from a corner is
    // moving round that corner.
    const bool fromWall = previous == ContactClass::Wall || previous == ContactClass::LeavingWall;
    if (leaving && !approaching && fromWall) return ContactClass::LeavingWall;
    // Once leaving, the group stays so while it touches nothing but that wall and its end,
    // whichever way the robot moves there (stopped, turning, or backing off a blocked step).
    if (nearVertex && previous == ContactClass::LeavingWall) return ContactClass::LeavingWall;
  }
  if (nearVertex) return ContactClass::Corner;
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
      k = end;
    }
  }
}

}  // namespace tactile::sim
