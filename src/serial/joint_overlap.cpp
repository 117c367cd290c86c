// The overlapped velocity method for PTP moves (joint_overlap.hpp, doc/ptp.md eq. 16).
#include "dispkin/serial/joint_overlap.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "dispkin/error.hpp"
#include "dispkin/serial/chain_kinematics.hpp"
#include "same_chain.hpp"

namespace dispkin {

OverlappedJointTrajectory::OverlappedJointTrajectory(JointTrajectory before, JointTrajectory after, double overlap)
    : before_(std::move(before)), after_(std::move(after)), overlap_(overlap) {
  require(before_.dof() == after_.dof(), "after", static_cast<long>(after_.dof()),
          "joints: must move as many joints as `before` (" + std::to_string(before_.dof()) + ")");
  require(serial::detail::same_chain(before_.chain(), after_.chain()), "after", static_cast<long>(after_.dof()),
          "joints: must be planned on the same arm as `before`");
  const double shorter = std::min(before_.duration(), after_.duration());
  require(std::isfinite(overlap) && overlap >= 0.0 && overlap <= shorter, "overlap", overlap,
          "must be between 0 and the shorter move's duration (" + std::to_string(shorter) + " s)");
  const double gap = (before_.end() - after_.start()).cwiseAbs().maxCoeff();
  require(gap <= 1e-9, "after", after_.start(),
          "must start where `before` ends (largest joint gap " + std::to_string(gap) + " rad)");
  via_ = after_.start();
}

JointTrajectorySample OverlappedJointTrajectory::sample(double t) const noexcept {
  const double begin = overlap_start();
  if (!(t > begin)) return before_.sample(t);  // also t ≤ 0 and NaN: the start
  if (t >= before_.duration()) {
    // After the overlap only the next move runs; its s continues from the previous length.
    // At and past the end exactly the next move's end (t − begin may round below its duration).
    JointTrajectorySample out = after_.sample(t >= duration() ? after_.duration() : t - begin);
    out.s += before_.length();
    return out;
  }
  const JointTrajectorySample b = before_.sample(t), f = after_.sample(t - begin);
  JointTrajectorySample out;
  // θ = θ_b + θ_f − θ₂ with θ₂ = θ_f(0); the rates add (eq. 16). Fixed-capacity vectors: no heap.
  out.q = b.q + f.q - via_;
  out.qd = b.qd + f.qd;
  out.qdd = b.qdd + f.qdd;
  out.s = b.s + f.s;
  out.s_dot = b.s_dot + f.s_dot;
  out.s_ddot = b.s_ddot + f.s_ddot;
  out.u = f.u;
  serial::chain_pose_and_twist(after_.chain(), out.q.data(), out.qd.data(), out.pose, out.body_twist);
  return out;
}

}  // namespace dispkin
