//! The overlapped velocity method of the Mamezou trajectory article (Ishii, "Algorithm 2 for Robot
//! Manipulator Control", section "Overlapped Velocity Method") for PTP moves: "the same thing can
//! be done using Θ instead of P" (doc/ptp.md §4, eq. 16). The next PTP move starts t_ov before
//! the previous one ends, and during the overlap the joint displacements add,
//!   θ(t) = θ_b(t) + θ_f(t′) − θ₂,   θ̇ = θ̇_b + θ̇_f,   θ̈ = θ̈_b + θ̈_f,
//! with t′ = t − (T_b − t_ov) the next move's own time and θ₂ the via joint vector where one
//! ends and the other starts. The tool pose is the arm's forward kinematics of θ(t).
//!
//! Like OverlappedTrajectory, this composition carries no speed guarantee of its own: a point's
//! velocity is then J(θ)(θ̇_b + θ̇_f), which the two plans did not bound — check the peak speed
//! (tests/cpp/test_joint_overlap.cpp does, with the planner's chord oracle) before using large
//! overlaps.
#pragma once

#include "dispkin/serial/ptp.hpp"

namespace dispkin::serial {

//! Two PTP moves run with an overlap t_ov, their joint displacements added during it (doc/ptp.md
//! §4, doc/ptp.md eq. 16). No speed guarantee of its own: see the file's comment.
class OverlappedJointTrajectory {
 public:
  //! `before` must end where `after` starts (joint vectors equal to 1e-9 rad), both planned on
  //! the same arm, and 0 ≤ overlap ≤ the shorter duration. Throws std::invalid_argument naming
  //! the argument otherwise.
  OverlappedJointTrajectory(JointTrajectory before, JointTrajectory after, double overlap);

  //! The whole motion's duration: both moves' less the overlap (s).
  double duration() const noexcept { return before_.duration() + after_.duration() - overlap_; }
  //! When the overlap begins (the next move starts), seconds.
  double overlap_start() const noexcept { return before_.duration() - overlap_; }
  double overlap() const noexcept { return overlap_; }                //!< t_ov, the time both moves run at once (s)
  const JointTrajectory& before() const noexcept { return before_; }  //!< the first move
  const JointTrajectory& after() const noexcept { return after_; }    //!< the next move

  //! The state at t (clamped to [0, duration]): joints by doc/ptp.md eq. 16, the pose and body twist by the
  //! arm's kinematics of θ and θ̇; s, ṡ, s̈ the sums of both moves' (s continues from the first
  //! move's length after the overlap); u the first move's before the overlap, the next move's
  //! from its start on. noexcept, allocation-free.
  JointTrajectorySample sample(double t) const noexcept;

 private:
  JointTrajectory before_, after_;
  double overlap_;
  JointVector via_;  // θ₂ = θ_f(0)
};

}  // namespace dispkin::serial
