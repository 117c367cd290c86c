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
//! The planned poses are the arm's tip (tip_link) poses in its base frame.
#pragma once

#include <string>
#include <vector>

#include <Eigen/Core>

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

}  // namespace dispkin
