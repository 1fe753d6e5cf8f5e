#include "sim/truth.h"

#include <cmath>
#include <numbers>

#include "sim/simulator.h"
#include "sim/world.h"

namespace tactile::sim {

void TruthTracker::reset() {
  classes_.fill(ContactClass::NoContact);
  history_.fill(GroupHistory{});
  step_ = 0;
}

void TruthTracker::update(const World& world, const PoseContact& contact, const double* values) {
  const auto& edges = world.edges();
  std::array<int, kGroupCount> touching{};
  for (int d = 0; d < kSensorCount; ++d) {
    if (contact.domes[d].edge >= 0) ++touching[groupIndex(groupOfSensor(d))];
  }
  const auto touches = [&](SensorGroup g) { return touching[groupIndex(g)] > 0; };
  const bool pocket =
      touches(SensorGroup::Front) && touches(SensorGroup::Left) && touches(SensorGroup::Right);
  const double flatCos = std::cos(kFlatVertexDegrees * std::numbers::pi / 180.0);

  for (const GroupInfo& info : kSensorGroups) {
    const int g = groupIndex(info.group);
    GroupHistory& h = history_[g];
    ContactClass cls = ContactClass::Wall;
    bool anyValue = false;
    for (int d = info.firstSensor; d < info.firstSensor + info.sensorCount; ++d) {
      anyValue = anyValue || values[normalOffset(d)] != 0.0 || values[shearOffset(d)] != 0.0;
    }
    const int count = touching[g];
    const bool frontOrSide = info.group != SensorGroup::Back &&
                             info.group != SensorGroup::RearLeftCorner &&
                             info.group != SensorGroup::RearRightCorner;
    const bool recentWall = step_ - h.lastWallStep <= kLeavingWallSteps && h.wallEdge >= 0;
    if (!anyValue) {
      cls = ContactClass::NoContact;
    } else if (count == 0) {
      // Released, values still decaying: leaving what it touched. A fading wall contact is
      // LeavingWall; a fading corner or dead path keeps its class.
      const ContactClass previous = classes_[g];
      cls = (previous == ContactClass::Corner || previous == ContactClass::DeadPath)
                ? previous
                : ContactClass::LeavingWall;
    } else if (pocket && frontOrSide) {
      cls = ContactClass::DeadPath;
    } else {
      bool vertex = false;
      bool offWallEnd = false;
      bool twoDirections = false;
      bool onlyWallEdge = recentWall;
      int firstEdge = -1;
      int deepestEdge = -1;
      double deepest = -1.0;
      for (int d = info.firstSensor; d < info.firstSensor + info.sensorCount; ++d) {
        const DomeContact& dc = contact.domes[d];
        if (dc.edge < 0) continue;
        if (recentWall) {
          const Edge& wall = edges[h.wallEdge];
          const bool onWall =
              dc.edge == h.wallEdge ||
              (dc.vertex >= 0 && (dc.vertex == wall.vertexA || dc.vertex == wall.vertexB));
          onlyWallEdge = onlyWallEdge && onWall;
          if (onWall && dc.vertex >= 0 && world.vertexKind(dc.vertex) == VertexKind::Convex) {
            offWallEnd = true;
          }
        }
        if (dc.vertex >= 0 && world.vertexKind(dc.vertex) != VertexKind::Flat) vertex = true;
        if (firstEdge < 0) {
          firstEdge = dc.edge;
        } else if (std::abs(edges[firstEdge].dir.dot(edges[dc.edge].dir)) < flatCos) {
          twoDirections = true;
        }
        if (dc.normal > deepest) {
          deepest = dc.normal;
          deepestEdge = dc.edge;
        }
      }
      const bool stillLeaving = h.leavingCount >= 0 && count <= h.leavingCount;
      if (onlyWallEdge && (offWallEnd || stillLeaving)) {
        cls = ContactClass::LeavingWall;
      } else if (vertex || twoDirections) {
        cls = ContactClass::Corner;
      } else {
        cls = ContactClass::Wall;
        const bool streak = h.lastWallStep == step_ - 1;
        h.wallCount = streak ? std::max(h.wallCount, count) : count;
        h.lastWallStep = step_;
        h.wallEdge = deepestEdge;
      }
    }
    h.leavingCount = cls == ContactClass::LeavingWall ? count : -1;
    classes_[g] = cls;
  }
  ++step_;
}

}  // namespace tactile::sim
