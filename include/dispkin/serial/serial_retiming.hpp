//! Joint-limit prediction and re-timing of Cartesian trajectories for a serial arm: its joints
//! follow the path on the inverse-kinematics branch continuous from a start configuration, with
//! joint velocities from the body Jacobian and torques from the arm's dynamics model
//! (doc/retiming.md). The generic parts (reports, options, retime_optimal against a JointModel)
//! are in planning/retiming.hpp. The planned poses are the arm's tip (tip_link) poses in its base
//! frame.
#pragma once

#include <memory>
#include <vector>

#include <Eigen/Core>

#include "dispkin/metric_set.hpp"
#include "dispkin/path/path.hpp"
#include "dispkin/planning/planner.hpp"
#include "dispkin/planning/retiming.hpp"
#include "dispkin/profile.hpp"
#include "dispkin/serial/ptp.hpp"
#include "dispkin/serial/serial_arm.hpp"

namespace dispkin::serial {

//! Follows `trajectory` with `arm` from the configuration `q_start` (the IK solution nearest to
//! it at t = 0, then nearest to the previous sample). Throws std::invalid_argument for bad
//! options or a q_start of the wrong size, std::runtime_error naming the time and path position
//! where a pose has no IK solution, where the Jacobian is singular, or where the static torque
//! alone exceeds a joint's effort limit (the KUKA re-timing patent's "cannot be reached by slowing down").
//! A 7R arm's redundancy parameter stays at q_start's value, or with a redundancy_rule that moves
//! it follows θ(s) as FollowedTrajectory::from_start does with its default spacing
//! (doc/inverse-kinematics.md (eq. 49)), q̇ and q̈ with θ̇ and θ̈ (eq. 48).
JointLimitReport check_joint_limits(const Trajectory& trajectory, const SerialArm& arm, const Eigen::VectorXd& q_start,
                                    const JointCheckOptions& options = {},
                                    const RedundancyRule& redundancy_rule = RedundancyRule::held());

//! The joint-limit factors of a PTP move at `times` (s): FVEL and FACC (doc/retiming.md (eq. 4)
//! and (doc/retiming.md eq. 5)) of its joint line's own q, q̇ and q̈, with the torques of the arm's dynamics
//! model (its position excess is 0: both ends are inside the limits, and the range is a box).
//! Throws std::invalid_argument for a trajectory of another dof or a time that is not finite,
//! std::runtime_error where the static torque alone reaches an effort limit (doc/retiming.md eq. 6).
JointLimitReport check_joint_limits(const JointTrajectory& trajectory, const SerialArm& arm,
                                    const std::vector<double>& times);

//! Joint positions, velocities and accelerations along a trajectory; row k at times[k].
struct FollowedJoints {
  //! q, q̇, q̈: one row per time, one column per joint.
  //!@{
  Eigen::MatrixXd q, qd, qdd;
  //!@}
};

//! `arm` following `trajectory` at `times` (s) as a job's samples give it: q by follow
//! from q_start (the solutions within the limits, each nearest to the previous sample), q̇ by
//! joint_velocity of the trajectory's body twist, q̈ by central differences of q̇ over
//! ±difference_step (one-sided at the ends, doc/retiming.md (eq. 2)), each neighbour followed
//! from the sample's q. Throws what follow throws, std::invalid_argument for a
//! difference_step ≤ 0 or a time that is not finite.
FollowedJoints follow_joints(const Trajectory& trajectory, const SerialArm& arm, const Eigen::VectorXd& q_start,
                             const std::vector<double>& times, double difference_step = 1e-4);

//! Plans `path`, checks it, scales the limits by 1/FVEL and 1/FACC and re-plans until both
//! factors are ≤ 1 at every checked sample. Throws std::runtime_error if a position limit is
//! violated (slowing down cannot help), if the static torque exceeds a limit, or if
//! `max_iterations` plans do not converge. `corner_tolerance` (m, ≥ 0): continuous-path mode as
//! plan()'s, the path's corners blended (continuous_path) before the first plan. `redundancy_rule`:
//! a 7R arm's parameter as check_joint_limits takes it.
RetimeResult retime_by_scaling(const Path& path, const MetricSetd& set, const Limits& limits, ProfileKind profile,
                               const SerialArm& arm, const Eigen::VectorXd& q_start,
                               const JointCheckOptions& options = {}, int max_iterations = 20,
                               double corner_tolerance = 0.0,
                               const RedundancyRule& redundancy_rule = RedundancyRule::held());

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
//! the result is never slower than the KUKA re-timing patent's scaling loop where that keeps the limits so.
//! `redundancy_rule`: a 7R arm's parameter as check_joint_limits takes it — with a rule that moves
//! it, the grid solves the joints at θ(s) of the planned path with θ′ and θ″ in q′ and q″
//! (doc/inverse-kinematics.md (eq. 51)), and the result's report is check_joint_limits(trajectory,
//! arm, q_start, {check_samples_between}, redundancy_rule); the held rule (the default) keeps it
//! at q_start's value.
//! Throws std::invalid_argument for bad options/limits/rule, std::runtime_error where the
//! path has no IK solution or is singular, where the static torque reaches a limit, where a
//! joint leaves its position range, or if the dense check still fails after max_refinements.
OptimalRetimeResult retime_optimal(const Path& path, const MetricSetd& set, const Limits& limits, const SerialArm& arm,
                                   const Eigen::VectorXd& q_start, const OptimalRetimeOptions& options = {},
                                   const RedundancyRule& redundancy_rule = RedundancyRule::held());

//! The arm as a JointModel: joints by the continuous inverse-kinematics branch (Newton from the
//! previous solution, all analytic solutions where that fails), q′ by the body Jacobian, torque
//! coefficients by recursive Newton–Euler, and the scaling loop as a candidate; a 7R arm's
//! parameter as `redundancy_rule` moves it (along a planned path: JointModel::along). Holds a
//! reference to `arm`, which must outlive it. Throws std::invalid_argument for a bad rule.
std::unique_ptr<JointModel> joint_model(const SerialArm& arm,
                                        const RedundancyRule& redundancy_rule = RedundancyRule::held());

}  // namespace dispkin::serial
