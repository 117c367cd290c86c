// The overlapped velocity method for a PTP move and a Cartesian move (mixed_overlap.hpp,
// doc/ptp.md eq. 21).
#include "dispkin/serial/mixed_overlap.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include "dispkin/error.hpp"
#include "dispkin/serial/chain_kinematics.hpp"
#include "same_chain.hpp"

namespace dispkin {

OverlappedMixedTrajectory::OverlappedMixedTrajectory(JointTrajectory before, FollowedTrajectory after, double overlap)
    : ptp_(std::move(before)), cartesian_(std::move(after)), ptp_first_(true), overlap_(overlap) {
  check(overlap);
  via_ = cartesian_.start();
}

OverlappedMixedTrajectory::OverlappedMixedTrajectory(FollowedTrajectory before, JointTrajectory after, double overlap)
    : ptp_(std::move(after)), cartesian_(std::move(before)), ptp_first_(false), overlap_(overlap) {
  check(overlap);
  via_ = ptp_.start();
}

void OverlappedMixedTrajectory::check(double overlap) const {
  // The Cartesian move's joints are the `after` argument when the PTP move comes first.
  const char* cartesian = ptp_first_ ? "after" : "before";
  require(ptp_.dof() == cartesian_.dof(), cartesian, static_cast<long>(cartesian_.dof()),
          "joints: must move as many joints as the PTP move (" + std::to_string(ptp_.dof()) + ")");
  require(serial::detail::same_chain(ptp_.chain(), cartesian_.chain()), cartesian, static_cast<long>(cartesian_.dof()),
          "joints: must be followed on the arm the PTP move was planned on");
  const double shorter = std::min(ptp_.duration(), cartesian_.duration());
  require(std::isfinite(overlap) && overlap >= 0.0 && overlap <= shorter, "overlap", overlap,
          "must be between 0 and the shorter move's duration (" + std::to_string(shorter) + " s)");
  const Eigen::VectorXd& first_end = ptp_first_ ? ptp_.end() : cartesian_.end();
  const Eigen::VectorXd& next_start = ptp_first_ ? cartesian_.start() : ptp_.start();
  const double gap = (first_end - next_start).cwiseAbs().maxCoeff();
  require(gap <= 1e-9, "after", next_start,
          "must start where `before` ends (largest joint gap " + std::to_string(gap) + " rad)");
}

JointTrajectorySample OverlappedMixedTrajectory::sample(double t) const noexcept {
  const double begin = overlap_start();
  if (!(t > begin)) return before_at(t);  // also t ≤ 0 and NaN: the start
  if (t >= before_duration()) {
    // Only the next move runs; its s continues from the first move's length.
    JointTrajectorySample out = after_at(t >= duration() ? after_duration() : t - begin);
    out.s += before_length();
    return out;
  }
  const JointTrajectorySample b = before_at(t), f = after_at(t - begin);
  JointTrajectorySample out;
  // θ = θ_b + θ_f − θ₂, θ₂ = θ_f(0) = θ_b(T_b); the rates add (eq. 21). Inline vectors: no heap.
  out.q = b.q + f.q - via_;
  out.qd = b.qd + f.qd;
  out.qdd = b.qdd + f.qdd;
  out.s = b.s + f.s;
  out.s_dot = b.s_dot + f.s_dot;
  out.s_ddot = b.s_ddot + f.s_ddot;
  out.u = f.u;
  serial::chain_pose_and_twist(ptp_.chain(), out.q.data(), out.qd.data(), out.pose, out.body_twist);
  return out;
}

}  // namespace dispkin
