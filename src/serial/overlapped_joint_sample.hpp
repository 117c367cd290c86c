// The overlapped velocity method in joint space, one sample (doc/ptp.md eqs. 16 and 21; internal
// to the serial plugin): the first move alone until the next starts `overlap` before its end,
// then θ = θ_b + θ_f − θ₂ with the rates and path positions adding, then the next move alone.
// Shared by OverlappedJointTrajectory and OverlappedMixedTrajectory. noexcept, no heap.
#pragma once

#include "dispkin/serial/chain_kinematics.hpp"
#include "dispkin/serial/ptp.hpp"
#include "dispkin/serial/revolute_chain.hpp"

namespace dispkin::serial::detail {

// `before_at(t)` and `after_at(t)` sample the two moves at their own times; `before_duration` and
// `before_length` are the first move's, `duration` the whole motion's, θ₂ = `via`.
template <typename Before, typename After>
JointTrajectorySample overlapped_joint_sample(double t, double overlap, double before_duration, double before_length,
                                              double after_duration, double duration, const JointVector& via,
                                              const RevoluteChain& chain, const Before& before_at,
                                              const After& after_at) noexcept {
  const double begin = before_duration - overlap;
  if (!(t > begin)) return before_at(t);  // also t ≤ 0 and NaN: the start
  if (t >= before_duration || t >= duration) {
    // Only the next move runs; its s continues from the first move's length. At and past the end
    // exactly the next move's end (t − begin may round below its duration; and where the whole
    // next move overlaps the first, the sum of the durations may round below the first one's).
    JointTrajectorySample out = after_at(t >= duration ? after_duration : t - begin);
    out.s += before_length;
    return out;
  }
  const JointTrajectorySample b = before_at(t), f = after_at(t - begin);
  JointTrajectorySample out;
  // θ = θ_b + θ_f − θ₂; the rates add. Fixed-capacity vectors: no heap.
  out.q = b.q + f.q - via;
  out.qd = b.qd + f.qd;
  out.qdd = b.qdd + f.qdd;
  out.s = b.s + f.s;
  out.s_dot = b.s_dot + f.s_dot;
  out.s_ddot = b.s_ddot + f.s_ddot;
  out.u = f.u;
  chain_pose_and_twist(chain, out.q.data(), out.qd.data(), out.pose, out.body_twist);
  return out;
}

}  // namespace dispkin::serial::detail
