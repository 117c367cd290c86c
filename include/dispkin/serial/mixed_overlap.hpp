//! The overlapped velocity method of the Mamezou trajectory article for a PTP move and a
//! Cartesian move (LIN, CIRC, …) in either order: "when one section is CP control and the other
//! is PTP control, this method can be applied after unifying to one type of control trajectory"
//! (doc/ptp.md §4, eq. 21). The Cartesian move is unified to joint space as a FollowedTrajectory
//! (the arm's IK branch that starts where the PTP move ends, or ends where it starts), and then
//! the joint displacements add during the overlap as for two PTP moves (doc/ptp.md eq. 16):
//!   θ(t) = θ_b(t) + θ_f(t′) − θ₂,   θ̇ = θ̇_b + θ̇_f,   θ̈ = θ̈_b + θ̈_f,   t′ = t − (T_b − t_ov),
//! each move's own joint motion outside the overlap; the pose and twist are the arm's forward
//! kinematics of θ and θ̇.
//!
//! Like the other overlaps, this carries no speed guarantee of its own: during the overlap a
//! point moves at J(θ)(θ̇_b + θ̇_f), which neither plan bounded (tests/cpp/test_mixed_overlap.cpp
//! prints the peak point speed over the limit).
#pragma once

#include "dispkin/serial/followed_trajectory.hpp"
#include "dispkin/serial/ptp.hpp"

namespace dispkin::serial {

//! A PTP move and a Cartesian move, in either order, run with an overlap t_ov in joint space
//! (doc/ptp.md §4, eq. 21). No speed guarantee of its own: see the file's comment.
class OverlappedMixedTrajectory {
 public:
  //! A PTP move, then a Cartesian one followed from its end (FollowedTrajectory::from_start with
  //! before.end()). `before` must end where `after` starts (joint vectors equal to 1e-9 rad), both
  //! on the same arm, 0 ≤ overlap ≤ the shorter duration; std::invalid_argument naming the
  //! argument otherwise.
  OverlappedMixedTrajectory(JointTrajectory before, FollowedTrajectory after, double overlap);
  //! A Cartesian move followed to the start of the PTP move after it (FollowedTrajectory::to_end
  //! with after.start()), with the same conditions.
  OverlappedMixedTrajectory(FollowedTrajectory before, JointTrajectory after, double overlap);

  //! The whole motion's duration: both moves' less the overlap (s).
  double duration() const noexcept { return before_duration() + after_duration() - overlap_; }
  //! When the overlap begins (the next move starts), seconds.
  double overlap_start() const noexcept { return before_duration() - overlap_; }
  double overlap() const noexcept { return overlap_; }  //!< t_ov, the time both moves run at once (s)
  //! True for PTP → Cartesian, false for Cartesian → PTP.
  bool ptp_first() const noexcept { return ptp_first_; }
  const JointTrajectory& ptp() const noexcept { return ptp_; }                 //!< the PTP move
  const FollowedTrajectory& cartesian() const noexcept { return cartesian_; }  //!< the Cartesian move, in joint space

  //! The state at t (clamped to [0, duration]): joints by doc/ptp.md eq. 21, the pose and body twist by the
  //! arm's kinematics of θ and θ̇; s, ṡ, s̈ the sums of both moves' (s continues from the first
  //! move's length after the overlap); u the first move's before the overlap, the next move's
  //! from its start on. Exactly the first move's start at t ≤ 0 and the second's end at
  //! t ≥ duration. noexcept, allocation-free.
  JointTrajectorySample sample(double t) const noexcept;

 private:
  void check(double overlap) const;
  double before_duration() const noexcept { return ptp_first_ ? ptp_.duration() : cartesian_.duration(); }
  double after_duration() const noexcept { return ptp_first_ ? cartesian_.duration() : ptp_.duration(); }
  double before_length() const noexcept { return ptp_first_ ? ptp_.length() : cartesian_.length(); }
  JointTrajectorySample before_at(double t) const noexcept {
    return ptp_first_ ? ptp_.sample(t) : cartesian_.sample(t);
  }
  JointTrajectorySample after_at(double t) const noexcept { return ptp_first_ ? cartesian_.sample(t) : ptp_.sample(t); }

  JointTrajectory ptp_;
  FollowedTrajectory cartesian_;
  bool ptp_first_;
  double overlap_;
  JointVector via_;  // θ₂: the joints where the first move ends and the next starts
};

}  // namespace dispkin::serial
