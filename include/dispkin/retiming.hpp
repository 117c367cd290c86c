//! Joint-limit prediction and re-timing for serial arms (seed 004; MATH.md §6; issue 7).
//!
//! check_joint_limits follows a planned Cartesian trajectory through the arm's inverse
//! kinematics — the branch continuous from a start configuration — at the profile's
//! characteristic points (every phase boundary and phase middle of every time law: the seed's
//! P0, P1, P12, P2, P3) and at `samples_between` equidistant times between consecutive ones. At
//! each it computes q, q̇ = J_b⁻¹ ξ_b (the body Jacobian against the trajectory's body twist),
//! q̈ (central differences of those Jacobian velocities), and the torques from the dynamics
//! model, split into the static part g(q) and the dynamic rest. From them the seed's factors
//!   FVEL = maxᵢ |q̇ᵢ| / q̇maxᵢ,   FACC = maxᵢ |τdyn,ᵢ| / (τmaxᵢ − |τsta,ᵢ|).
//! retime_by_scaling is the seed's loop: divide the velocity limit by FVEL and the acceleration
//! limit by FACC, re-plan, repeat until both are ≤ 1 — and fail (never report success) if that
//! does not happen within the iteration budget.
//!
//! retime_optimal goes beyond the seed: the fastest path parameterisation that keeps the DISP
//! limits and the joint velocity, acceleration and torque limits at once, slowing down only
//! where a limit binds (reachability analysis over a grid of s, as in TOPP-RA). With a jerk
//! limit (limits.jerk) it is followed by jerk limiting: each rest-to-rest run's law is replaced
//! by its moving average over a window T ≤ 2a/j (a/j, the S-curve's, wherever the acceleration
//! does not reverse within T), whose jerk is bounded by j; the speed caps are tightened
//! beforehand to their minimum over the distance the window spans, so the DISP limits still
//! hold rigorously, and the joint limits through the same dense check and refinement.
//!
//! The planned poses are the arm's tip (tip_link) poses in its base frame.
#pragma once

#include <string>
#include <vector>

#include <Eigen/Core>

#include "dispkin/hexapod.hpp"
#include "dispkin/planner.hpp"
#include "dispkin/serial/serial_arm.hpp"

namespace dispkin {

struct JointCheckOptions {
  int samples_between = 10;  //!< equidistant samples between characteristic points, ≥ 0
  //! Time step of the central differences for q̈ (s), > 0.
  double difference_step = 1e-4;
};

//! The arm's state at one checked instant.
struct JointSample {
  double time = 0.0, s = 0.0;
  Eigen::VectorXd q, qd, qdd;
  Eigen::VectorXd static_torque, dynamic_torque;  //!< g(q); τ(q, q̇, q̈) − g(q)
};

//! What check_joint_limits found.
struct JointLimitReport {
  std::vector<JointSample> samples;
  double velocity_factor = 0.0;      //!< FVEL (0 if no joint states a velocity limit)
  double acceleration_factor = 0.0;  //!< FACC (0 if no joint states an effort limit)
  int velocity_joint = -1;           //!< the joint and sample where FVEL is reached
  std::size_t velocity_sample = 0;
  int torque_joint = -1;             //!< the joint and sample where FACC is reached
  std::size_t torque_sample = 0;
  double position_excess = 0.0;  //!< largest excursion of q outside [lower, upper] (rad), 0 if none
  int position_joint = -1;
  std::size_t position_sample = 0;

  bool within_limits() const noexcept {
    return velocity_factor <= 1.0 && acceleration_factor <= 1.0 && position_excess == 0.0;
  }
};

//! Follows `trajectory` with `arm` from the configuration `q_start` (the IK solution nearest to
//! it at t = 0, then nearest to the previous sample). Throws std::invalid_argument for bad
//! options or a q_start of the wrong size, std::runtime_error naming the time and path position
//! where a pose has no IK solution, where the Jacobian is singular, or where the static torque
//! alone exceeds a joint's effort limit (the seed's "cannot be reached by slowing down").
JointLimitReport check_joint_limits(const Trajectory& trajectory, const serial::SerialArm& arm,
                                    const Eigen::VectorXd& q_start, const JointCheckOptions& options = {});

//! The same for a hexapod, whose legs are its joints: q = the leg lengths (its inverse kinematics,
//! unique), q̇ = J_leg ξ_b, q̈ by central differences; velocity_factor against leg_speed(),
//! position_excess against [leg_min, leg_max]. No dynamics model: the torques stay empty and
//! acceleration_factor 0. Throws std::invalid_argument for bad options.
JointLimitReport check_joint_limits(const Trajectory& trajectory, const Hexapod& hexapod,
                                    const JointCheckOptions& options = {});

//! The result of the seed's re-timing loop.
struct RetimeResult {
  Trajectory trajectory;
  Limits limits;              //!< the scaled limits it was planned with
  int iterations = 0;         //!< plans made (1: the original already fits)
  JointLimitReport report;    //!< of the final trajectory: within_limits() is true
};

//! Plans `path`, checks it, scales the limits by 1/FVEL and 1/FACC and re-plans until both
//! factors are ≤ 1 at every checked sample. Throws std::runtime_error if a position limit is
//! violated (slowing down cannot help), if the static torque exceeds a limit, or if
//! `max_iterations` plans do not converge.
RetimeResult retime_by_scaling(const Path& path, const MetricSetd& set, const Limits& limits, ProfileKind profile,
                               const serial::SerialArm& arm, const Eigen::VectorXd& q_start,
                               const JointCheckOptions& options = {}, int max_iterations = 20);

//! Options of retime_optimal.
struct OptimalRetimeOptions {
  //! Grid intervals over the whole path (≥ 2; each rest-to-rest run gets a share proportional
  //! to its length, at least 2). Limits are imposed at both ends of every interval.
  int grid_intervals = 100;
  //! Joint acceleration limits q̈maxᵢ (rad/s² or m/s², each > 0, +∞ for none); empty: none
  //! (URDF states none; MoveIt's joint_limits.yaml does).
  Eigen::VectorXd joint_acceleration;
  //! Keep |τᵢ| ≤ the effort limit where the arm states one.
  bool torque_limits = true;
  //! Step of the central differences for q″(s), as a fraction of the run's grid interval, > 0.
  double difference_step = 1e-3;
  //! The dense check of the result: samples between its characteristic points (≥ 0).
  int check_samples_between = 3;
  //! Re-solves with tightened limits when the dense check finds an overshoot between grid
  //! points (≥ 0); if the last one still overshoots, retime_optimal throws.
  int max_refinements = 6;
};

//! What retime_optimal produced.
struct OptimalRetimeResult {
  //! The re-timed trajectory: the same path, one constant-acceleration law per grid interval
  //! (with a jerk limit: constant-jerk laws of at most seven phases each).
  Trajectory trajectory;
  //! The dense check of `trajectory` (check_joint_limits at check_samples_between).
  JointLimitReport report;
  //! Largest |q̇ᵢ|/q̇maxᵢ, |q̈ᵢ|/q̈maxᵢ and |τᵢ|/τmaxᵢ at the checked samples (each ≤ 1; 0 where no
  //! limit applies). τ is the whole torque, static plus dynamic.
  double velocity_ratio = 0.0, acceleration_ratio = 0.0, torque_ratio = 0.0;
  //! The fraction by which the joint limits were tightened on the grid so that they hold between
  //! grid points too (0: not needed), and the re-solves that took.
  double margin = 0.0;
  int refinements = 0;
  //! The grid positions s (m) and ṡ there (m/s) (with a jerk limit: of the law before its
  //! moving average).
  std::vector<double> grid_s, grid_speed;
  //! With a jerk limit: the longest moving-average window T (s) of the rest-to-rest runs, the
  //! time each run grew by; 0 without, and 0 when the trajectory is the plain S-curve plan or
  //! the seed's scaling with the S-curve (either keeps every joint limit and is faster than the
  //! average).
  double jerk_window = 0.0;
};

//! The fastest parameterisation of `path` (planned with plan(path, set, limits, trapezoid): the
//! DISP velocity-limit curve and its rests are kept, and |s̈| ≤ limits.acceleration) under the
//! arm's joint velocity limits, `options.joint_acceleration` and the effort limits, followed
//! from q_start. Without limits.jerk the time laws are piecewise-constant s̈ (one per grid
//! interval and section). With limits.jerk they are piecewise-constant s⃛ with |s⃛| ≤ j inside
//! every section (at a tangent junction ṡ steps with the section's ds/dσ, ≤ 1 %, as without a
//! jerk limit; the motion itself is smooth there): each run is the jerk-free result, re-solved
//! with speed caps tightened over the window's reach and its lowest acceleration cap, then
//! averaged over a window T (jerk_window), so it takes T longer per run than that re-solve.
//! If plan(path, set, limits, scurve) or, for an arm, retime_by_scaling(path, set, limits, scurve,
//! arm, q_start) keeps every joint limit 0.1 % clear at a dense check (at least 10 samples between
//! characteristic points) and is faster, the fastest of them is returned instead (jerk_window 0):
//! the result is never slower than the seed's scaling where that keeps the limits so.
//! Throws std::invalid_argument for bad options/limits, std::runtime_error where the
//! path has no IK solution or is singular, where the static torque reaches a limit, where a
//! joint leaves its position range, or if the dense check still fails after max_refinements.
OptimalRetimeResult retime_optimal(const Path& path, const MetricSetd& set, const Limits& limits,
                                   const serial::SerialArm& arm, const Eigen::VectorXd& q_start,
                                   const OptimalRetimeOptions& options = {});

//! The same for a hexapod: the legs are the joints (leg_speed() and options.joint_acceleration
//! as their limits; no torques), and a leg that leaves its length range is an error naming it.
OptimalRetimeResult retime_optimal(const Path& path, const MetricSetd& set, const Limits& limits, const Hexapod& hexapod,
                                   const OptimalRetimeOptions& options = {});

}  // namespace dispkin
