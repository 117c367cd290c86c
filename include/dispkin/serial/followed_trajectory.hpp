//! A Cartesian trajectory (a LIN, CIRC, … plan, planning/trajectory.hpp) as the joint motion of a
//! serial arm whose tip follows it on one inverse-kinematics branch: the article's "unifying to
//! one type of control trajectory" (the Mamezou trajectory article, "Overlapped Velocity Method")
//! done in joint space, where a PTP move is native (doc/ptp.md §4, eqs. 17–20).
//!
//! The joints are precomputed as functions of the path position s, not of time: per section k of
//! the path (τ = (s − s_k)/L_k ∈ [0, 1]) on nodes τ_i = i/n_k, with n_k = ⌈L_k / spacing⌉ doubled
//! until the check below passes, the IK solution on the branch q_i and its rate per τ
//! q′_i = J_b(q_i)⁻¹ ξ_τ (ξ_τ the section's body twist per unit τ). Between nodes a cubic Hermite
//! polynomial interpolates q(τ) (doc/ptp.md eq. 18). The time law s(t) is the trajectory's own, evaluated
//! exactly at sample time, so its jerk steps and the velocity steps of ds/dτ at section junctions
//! never fall inside an interpolation interval:
//!   q̇ = q′ ṡ / L_k,   q̈ = q″ (ṡ / L_k)² + q′ s̈ / L_k     (doc/ptp.md eq. 19).
//! Check (doc/ptp.md eq. 20): at every interval's middle the interpolant agrees with the branch's IK solution
//! to midpoint_tolerance (1e-10 rad); the cubic Hermite error (t−a)²(t−b)² q⁗/24 is largest
//! there, so this bounds the joint error everywhere to that order, and a branch change or a
//! near-singular spike — which no grid resolves — is refused.
//!
//! The pose of a sample is the forward kinematics of its joints (so it matches the trajectory's
//! pose to the interpolation error, ≤ 1e-9 m in the tests), the body twist that of q and q̇.
#pragma once

#include <cstddef>
#include <vector>

#include <Eigen/Core>

#include "dispkin/planning/trajectory.hpp"
#include "dispkin/serial/ptp.hpp"
#include "dispkin/serial/revolute_chain.hpp"
#include "dispkin/serial/serial_arm.hpp"

namespace dispkin::serial {

//! A Cartesian trajectory followed by a serial arm's joints on one inverse-kinematics branch,
//! precomputed along the path (doc/ptp.md §4, eqs. 17–20; see the file's comment).
class FollowedTrajectory {
 public:
  //! Default node spacing along the path, in DISP arc length (m).
  static constexpr double default_spacing = 2e-3;
  //! The largest joint error at an interval's middle the grid is refined to (rad).
  static constexpr double midpoint_tolerance = 1e-10;

  //! `trajectory` followed by `arm` from q_start (its forward kinematics must be the trajectory's
  //! start pose to 1e-9: rotation-matrix entries and m), the branch continued node by node.
  //! Throws std::invalid_argument naming the argument: q_start of the wrong size, not finite, or
  //! not at the start pose; spacing not in [1e-5, 1] m; an arm that is neither 6R nor 7R with a
  //! redundancy parameter (its Jacobian must be inverted); a trajectory whose poses leave the arm's
  //! reach, pass a singular pose, change the branch, or take a joint out of its position range; a
  //! redundancy_rule field not finite or below 0. A 7R arm's parameter stays at its value in
  //! q_start (RedundancyRule::held(), doc/inverse-kinematics.md (eq. 41), (eq. 42)), or with a rule
  //! that moves it follows θ(s) of doc/inverse-kinematics.md (eq. 49), (eq. 50): the rule of
  //! SerialArm's follow per unit of path, precomputed on the grid of `spacing`, q′ with θ′'s
  //! self-motion (doc/inverse-kinematics.md eq. 47).
  static FollowedTrajectory from_start(Trajectory trajectory, const SerialArm& arm, const Eigen::VectorXd& q_start,
                                       double spacing = default_spacing,
                                       const RedundancyRule& redundancy_rule = RedundancyRule::held());
  //! The same on the branch that ends at q_end (followed backwards from the trajectory's end pose,
  //! which FK(q_end) must be): for a Cartesian move that a PTP move starting at q_end follows.
  //! A moving parameter is moved backwards from q_end's value.
  static FollowedTrajectory to_end(Trajectory trajectory, const SerialArm& arm, const Eigen::VectorXd& q_end,
                                   double spacing = default_spacing,
                                   const RedundancyRule& redundancy_rule = RedundancyRule::held());

  double duration() const noexcept { return trajectory_.duration(); }  //!< the trajectory's duration (s)
  //! DISP arc length of the Cartesian trajectory (m).
  double length() const noexcept { return trajectory_.length(); }
  int dof() const noexcept { return static_cast<int>(start_.size()); }  //!< the number of joints
  //! The joints at t = 0 and at the end (one of them is the q given).
  //!@{
  const Eigen::VectorXd& start() const noexcept { return start_; }
  const Eigen::VectorXd& end() const noexcept { return end_; }
  //!@}
  const Trajectory& trajectory() const noexcept { return trajectory_; }  //!< the Cartesian trajectory followed
  //! The arm's joint chain (forward kinematics and Jacobian of the samples).
  const RevoluteChain& chain() const noexcept { return chain_; }
  //! Number of grid nodes (sections' junction nodes counted once per section).
  std::size_t node_count() const noexcept { return static_cast<std::size_t>(nodes_q_.cols()); }
  //! The largest joint error found at an interval's middle (rad, ≤ midpoint_tolerance).
  double midpoint_error() const noexcept { return midpoint_error_; }

  //! The state at t (clamped to [0, duration]): s, ṡ, s̈ of the trajectory's time law, q, q̇, q̈
  //! by doc/ptp.md eqs. 18–19, pose and body twist by forward kinematics of q and q̇, u = s / length. Exactly
  //! start() at t ≤ 0 (and NaN) and end() at t ≥ duration. noexcept, allocation-free.
  JointTrajectorySample sample(double t) const noexcept;

 private:
  // Nodes first … first + intervals of section k (n_k = intervals).
  struct SectionGrid {
    Eigen::Index first;
    int intervals;
  };
  FollowedTrajectory(Trajectory trajectory, const SerialArm& arm, const Eigen::VectorXd& q_given, bool backwards,
                     double spacing, const RedundancyRule& redundancy_rule);

  Trajectory trajectory_;
  RevoluteChain chain_;
  std::vector<SectionGrid> grids_;
  Eigen::MatrixXd nodes_q_, nodes_rate_;  // one column per node: q_i and q′_i = dq/dτ
  Eigen::VectorXd start_, end_;
  double midpoint_error_ = 0.0;
};

}  // namespace dispkin::serial
