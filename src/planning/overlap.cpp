// The overlapped velocity method (overlap.hpp).
#include "dispkin/planning/overlap.hpp"

#include <algorithm>
#include <string>

#include "dispkin/error.hpp"

namespace dispkin {

OverlappedTrajectory::OverlappedTrajectory(Trajectory before, Trajectory after, double overlap,
                                           const Eigen::Vector3d& pivot)
    : before_(std::move(before)), after_(std::move(after)), overlap_(overlap), pivot_(pivot) {
  require_translation(pivot, "pivot");
  const double shorter = std::min(before_.duration(), after_.duration());
  require(std::isfinite(overlap) && overlap >= 0.0 && overlap <= shorter, "overlap", overlap,
          "must be between 0 and the shorter move's duration (" + std::to_string(shorter) + " s)");
  via_ = before_.sample(before_.duration()).pose;
  const Posed start = after_.sample(0.0).pose;
  const double gap = (via_.translation() - start.translation()).norm();
  const double turn = quaternion_log(Eigen::Quaterniond(via_.quaternion().conjugate() * start.quaternion())).norm();
  if (gap > 1e-9 || turn > 1e-9) {
    throw std::invalid_argument(describe(
        "after", start.translation(),
        "must start where `before` ends (gap " + std::to_string(gap) + " m, " + std::to_string(turn) + " rad)"));
  }
  via_point_ = via_ * pivot_;
}

TrajectorySample OverlappedTrajectory::sample(double t) const noexcept {
  const double begin = overlap_start();
  if (!(t > begin)) return before_.sample(t);  // also t ≤ 0 and NaN: the start
  if (t >= before_.duration()) {
    // After the overlap only the next move runs; its s continues from the previous length.
    TrajectorySample out = after_.sample(t - begin);
    out.s += before_.length();
    return out;
  }
  const TrajectorySample b = before_.sample(t), f = after_.sample(t - begin);
  // R = R_f R₂⁻¹ R_b, c = c_b + c_f − c₂; ω = ω_f + R_f R₂⁻¹ ω_b, ċ = ċ_b + ċ_f (world).
  const Eigen::Quaterniond turn_f = f.pose.quaternion() * via_.quaternion().conjugate();
  const Eigen::Quaterniond q = (turn_f * b.pose.quaternion()).normalized();
  const Eigen::Vector3d c = (b.pose * pivot_) + (f.pose * pivot_) - via_point_;
  const Eigen::Vector3d omega_b = b.pose.quaternion() * b.body_twist.angular;
  const Eigen::Vector3d omega_f = f.pose.quaternion() * f.body_twist.angular;
  const Eigen::Vector3d c_dot_b = b.pose.quaternion() * (b.body_twist.linear + b.body_twist.angular.cross(pivot_));
  const Eigen::Vector3d c_dot_f = f.pose.quaternion() * (f.body_twist.linear + f.body_twist.angular.cross(pivot_));
  const Eigen::Vector3d omega = omega_f + turn_f * omega_b;

  TrajectorySample out;
  out.pose = Posed::unchecked(q, c - q * pivot_);
  const Eigen::Quaterniond q_inv = q.conjugate();
  out.body_twist.angular = q_inv * omega;
  out.body_twist.linear = q_inv * (c_dot_b + c_dot_f) - out.body_twist.angular.cross(pivot_);
  out.s = b.s + f.s;
  out.s_dot = b.s_dot + f.s_dot;
  out.s_ddot = b.s_ddot + f.s_ddot;
  return out;
}

}  // namespace dispkin
