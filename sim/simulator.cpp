#include "sim/simulator.h"

#include <algorithm>
#include <cmath>

namespace tactile::sim {

Simulator::Simulator(std::shared_ptr<const World> world, SimConfig config)
    : world_(std::move(world)),
      config_(config),
      domes_(domePlacements(config.geometry)),
      truth_(config.geometry) {
  const RobotGeometry& g = config_.geometry;
  cornerRadius_ = g.cornerRadiusUnits;
  innerLo_ = Vec2(g.backX() + cornerRadius_, -g.halfWidth() + cornerRadius_);
  innerHi_ = Vec2(g.frontX() - cornerRadius_, g.halfWidth() - cornerRadius_);
  double far = 0.0;
  for (double x : {innerLo_.x(), innerHi_.x()}) {
    for (double y : {innerLo_.y(), innerHi_.y()})
      far = std::max(far, std::hypot(x, y));
  }
  outlineRadius_ = far + cornerRadius_;
  candidates_.reserve(1024);
  bodyA_.reserve(1024);
  bodyB_.reserve(1024);
  truth_.reset();
  if (!reset(world_->scene().start)) {
    // A blocked start (callers check with isBlocked first): stand there anyway, blocked.
    pose_ = world_->scene().start;
    blocked_ = true;
    contact_ = evaluate(pose_);
  }
}

double Simulator::motionBound(double v, double omega) const {
  return (std::abs(v) + std::abs(omega) * outlineRadius_) * config_.dtSeconds;
}

bool Simulator::reset(const Pose2d& pose) {
  if (isBlocked(pose)) return false;
  pose_ = pose;
  pose_.theta = wrapAngle(pose_.theta);
  blocked_ = false;
  steps_ = 0;
  sensors_.fill(0.0);
  truth_.reset();
  contact_ = evaluate(pose_);
  return true;
}

void Simulator::gatherCandidates(const Pose2d& pose, double reach) {
  if (!config_.useIndex) {
    const int n = static_cast<int>(world_->edges().size());
    candidates_.resize(n);
    for (int i = 0; i < n; ++i)
      candidates_[i] = i;
    return;
  }
  // Axis-aligned box of the body at `pose`, grown by `reach`.
  const double c = std::abs(std::cos(pose.theta));
  const double s = std::abs(std::sin(pose.theta));
  const Vec2 centreBody = 0.5 * (innerLo_ + innerHi_);
  const Vec2 half = 0.5 * (innerHi_ - innerLo_);
  const Vec2 centre = bodyToWorld(pose, centreBody);
  const double ex = c * half.x() + s * half.y() + cornerRadius_ + reach;
  const double ey = s * half.x() + c * half.y() + cornerRadius_ + reach;
  world_->index().query(centre - Vec2(ex, ey), centre + Vec2(ex, ey), candidates_, scratch_);
}

void Simulator::transformCandidates(const Pose2d& pose) {
  const auto& edges = world_->edges();
  const double c = std::cos(pose.theta);
  const double s = std::sin(pose.theta);
  const std::size_t n = candidates_.size();
  bodyA_.resize(n);
  bodyB_.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const Edge& e = edges[candidates_[i]];
    const double ax = e.a.x() - pose.x, ay = e.a.y() - pose.y;
    const double bx = e.b.x() - pose.x, by = e.b.y() - pose.y;
    bodyA_[i] = Vec2(c * ax + s * ay, -s * ax + c * ay);
    bodyB_[i] = Vec2(c * bx + s * by, -s * bx + c * by);
  }
}

// Blocked rule at one pose: the rigid body (inner box grown by the corner radius rc) overlaps an
// edge when dist(edge, inner box) < rc; a dome is compressed past full compression when an edge
// comes closer to its centre than r - 5.
bool Simulator::blockedAt(const Pose2d& pose) {
  transformCandidates(pose);
  const double rc2 = cornerRadius_ * cornerRadius_;
  const double minGap = config_.geometry.domeRadiusUnits - kMaxNormal;
  const double minGap2 = minGap * minGap;
  const double domeReach = cornerRadius_ + std::max(minGap, 0.0);
  const double domeReach2 = domeReach * domeReach;
  for (std::size_t i = 0; i < candidates_.size(); ++i) {
    const Vec2& a = bodyA_[i];
    const Vec2& b = bodyB_[i];
    const double d2 = segmentBoxDistance2(a, b, innerLo_, innerHi_);
    if (d2 < rc2) return true;
    if (d2 < domeReach2) {
      for (const DomePlacement& dome : domes_) {
        if (pointSegmentDistance2(Vec2(dome.centre.x, dome.centre.y), a, b) < minGap2) return true;
      }
    }
  }
  return false;
}

bool Simulator::isBlocked(const Pose2d& pose) {
  gatherCandidates(pose, config_.geometry.domeRadiusUnits);
  return blockedAt(pose);
}

PoseContact Simulator::evaluate(const Pose2d& pose) {
  PoseContact out;
  gatherCandidates(pose, config_.geometry.domeRadiusUnits);
  evaluateInto(pose, out);
  return out;
}

// Dome model (docs/domain.md#dome-model, thesis 2.1): q = closest obstacle point to the dome centre
// c; if d = |c - q| < r the dome is pushed back by D = (r - d) (c - q) / d. Its normal component is
// n = -D . normal (compression, >= 0) and its shear s = D . t with t = normal rotated +90 degrees
// (counter-clockwise tangent). Ties between equally close edges go to the lowest edge id, so the
// result does not depend on the order candidates arrive in (index and brute force agree exactly).
void Simulator::evaluateInto(const Pose2d& pose, PoseContact& out) {
  transformCandidates(pose);
  const double r = config_.geometry.domeRadiusUnits;
  const double rc2 = cornerRadius_ * cornerRadius_;
  const double reach = cornerRadius_ + r;
  const double reach2 = reach * reach;
  const double minGap = r - kMaxNormal;
  std::array<double, kSensorCount> best;
  best.fill(r * r);
  std::array<double, kSensorCount> bestT{};
  std::array<int, kSensorCount> bestEdge;
  bestEdge.fill(-1);
  std::array<int, kSensorCount> bestSlot{};
  double minBody2 = std::numeric_limits<double>::infinity();
  bool blocked = false;
  for (std::size_t i = 0; i < candidates_.size(); ++i) {
    const Vec2& a = bodyA_[i];
    const Vec2& b = bodyB_[i];
    const double d2 = segmentBoxDistance2(a, b, innerLo_, innerHi_);
    minBody2 = std::min(minBody2, d2);
    if (d2 < rc2) blocked = true;
    if (d2 >= reach2) continue;
    const int id = candidates_[i];
    for (int k = 0; k < kSensorCount; ++k) {
      const Vec2 c(domes_[k].centre.x, domes_[k].centre.y);
      const double t = closestParameter(c, a, b);
      const double dd = (c - (a + t * (b - a))).squaredNorm();
      if (dd < best[k] || (dd == best[k] && bestEdge[k] >= 0 && id < bestEdge[k])) {
        best[k] = dd;
        bestT[k] = t;
        bestEdge[k] = id;
        bestSlot[k] = static_cast<int>(i);
      }
    }
  }
  out.clearanceUnits = std::sqrt(minBody2) - cornerRadius_;
  const auto& edges = world_->edges();
  for (int k = 0; k < kSensorCount; ++k) {
    DomeContact& dc = out.domes[k];
    dc = DomeContact{};
    if (bestEdge[k] < 0) continue;
    const double d = std::sqrt(best[k]);
    if (d < minGap) {
      blocked = true;
      continue;
    }
    const Vec2& a = bodyA_[bestSlot[k]];
    const Vec2& b = bodyB_[bestSlot[k]];
    const Vec2 q = a + bestT[k] * (b - a);
    const Vec2 c(domes_[k].centre.x, domes_[k].centre.y);
    const Vec2 nrm(domes_[k].normal.x, domes_[k].normal.y);
    const Vec2 D = (r - d) / d * (c - q);
    dc.normal = std::clamp(-D.dot(nrm), 0.0, kMaxNormal);
    dc.shear = std::clamp(D.dot(Vec2(-nrm.y(), nrm.x())), -kMaxShear, kMaxShear);
    dc.edge = bestEdge[k];
    const Edge& e = edges[bestEdge[k]];
    dc.vertex = bestT[k] <= 0.0 ? e.vertexA : (bestT[k] >= 1.0 ? e.vertexB : -1);
  }
  out.blocked = blocked;
}

void Simulator::step(double v, double omega) {
  if (!std::isfinite(v)) v = 0.0;
  if (!std::isfinite(omega)) omega = 0.0;
  v = std::clamp(v, -kMaxSpeedUnits, kMaxSpeedUnits);
  omega = std::clamp(omega, -kMaxTurnRate, kMaxTurnRate);
  const double dt = config_.dtSeconds;
  const double motion = motionBound(v, omega);
  const double r = config_.geometry.domeRadiusUnits;
  // One query covers the whole swept area plus dome reach.
  gatherCandidates(pose_, motion + r);
  const double envelope = std::max(r - kMaxNormal, 0.0);
  Pose2d target = integratePose(pose_, v, omega, dt);
  // A blocked step moves as far as is free: to the last sub-pose before the first blocked one,
  // so the run records the contact that stopped the robot (sub-poses are at most
  // maxSubstepUnits apart, so the robot ends within that distance of the blocking pose).
  bool blocked = false;
  Pose2d lastFree = pose_;
  bool moved = false;
  if (motion > 0.0) {
    // Sub-steps unless the whole motion fits in the clearance around the body.
    transformCandidates(pose_);
    double minBody2 = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < candidates_.size(); ++i) {
      minBody2 = std::min(minBody2, segmentBoxDistance2(bodyA_[i], bodyB_[i], innerLo_, innerHi_));
    }
    const double clearance = std::sqrt(minBody2) - cornerRadius_;
    if (!(motion + envelope < clearance)) {
      const int sub = std::max(1, static_cast<int>(std::ceil(motion / config_.maxSubstepUnits)));
      for (int i = 1; i < sub && !blocked; ++i) {
        const Pose2d at = integratePose(pose_, v, omega, dt * i / sub);
        if (blockedAt(at)) {
          blocked = true;
        } else {
          lastFree = at;
          moved = true;
        }
      }
    }
  }
  PoseContact next;
  if (!blocked) {
    evaluateInto(target, next);
    blocked = next.blocked;
  }
  if (!blocked) {
    blocked_ = false;
    target.theta = wrapAngle(target.theta);
    pose_ = target;
    contact_ = next;
  } else {
    blocked_ = true;
    if (moved) {
      // The sub-poses share the candidates gathered for the whole sweep.
      lastFree.theta = wrapAngle(lastFree.theta);
      pose_ = lastFree;
      evaluateInto(pose_, contact_);
    }
    // Otherwise the very first sub-pose was blocked: the pose and its contact are kept.
  }
  // Spring-damper c x' + k x = k u, implicit Euler: x += a (u - x), a = dt / (tau + dt).
  const double a = dt / (config_.filterTauSeconds + dt);
  const double zero = config_.zeroBelowUnits;
  for (int k = 0; k < kSensorCount; ++k) {
    double& n = sensors_[normalOffset(k)];
    double& s = sensors_[shearOffset(k)];
    n += a * (contact_.domes[k].normal - n);
    s += a * (contact_.domes[k].shear - s);
    n = std::clamp(n, 0.0, kMaxNormal);
    s = std::clamp(s, -kMaxShear, kMaxShear);
    if (contact_.domes[k].edge < 0 && std::abs(n) < zero && std::abs(s) < zero) n = s = 0.0;
  }
  truth_.update(*world_, pose_, contact_, sensors_.data());
  ++steps_;
}

}  // namespace tactile::sim
