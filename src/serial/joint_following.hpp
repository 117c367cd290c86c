// Following a Cartesian trajectory with a serial arm's joints (internal to the serial plugin;
// joint_following.cpp): the inverse-kinematics branch continuous from a reference configuration
// and the joint velocities of the trajectory's body twist (doc/retiming.md §1).
#pragma once

#include <string>

#include <Eigen/Core>

#include "dispkin/error.hpp"
#include "dispkin/pose.hpp"
#include "dispkin/serial/serial_arm.hpp"

namespace dispkin::serial::detail {

//! The IK solution on q_ref's branch (detail::solution_on_branch with the re-timing
//! rule: solutions outside the limits kept, to be reported as position excursions, and each joint
//! moved by the multiple of 2π nearest to q_ref's, doc/retiming.md (eq. 1)), tracked by Newton's
//! method from `guess` (q_ref if null). Throws std::runtime_error naming the place (where(t, s))
//! if the pose has no solution.
Eigen::VectorXd branch_solution(const SerialArm& arm, const Posed& pose, const Eigen::VectorXd& q_ref, double t,
                                double s, const Eigen::VectorXd* guess = nullptr);

//! q̇ with J_b(q) q̇ = ξ_b; throws std::runtime_error naming the place near a singularity (the
//! joint speeds there are unbounded: slowing down cannot help). A redundant arm's parameter joint
//! turns at `parameter_rate` θ̇ and the others take the rest of ξ_b (doc/inverse-kinematics.md
//! eq. 47); ignored for a 6R arm.
Eigen::VectorXd joint_velocity(const SerialArm& arm, const Eigen::VectorXd& q, const Twistd& body, double t, double s,
                               double parameter_rate = 0.0);

//! θ̇ and θ̈ of a redundant arm's parameter where the path moves it (doc/inverse-kinematics.md
//! eqs. 47–48); zero where it is held at one value.
struct ParameterRates {
  double rate = 0.0, acceleration = 0.0;
};

//! q̇ as joint_velocity gives it and, from the same factorisation of J_b(q), the joint
//! acceleration of the body acceleration `body_rate`: J_b q̈ = ξ̇_b − J̇_b(q, q̇) q̇ (doc/retiming.md
//! (doc/retiming.md eq. 27)). Per unit of path instead of time (ξ′, ξ″) it gives q′ and q″ (eq. 28). A
//! redundant arm's parameter moves at `parameter` (doc/inverse-kinematics.md eqs. 47–48). Throws as
//! joint_velocity.
void joint_rates(const SerialArm& arm, const Eigen::VectorXd& q, const Twistd& body, const Twistd& body_rate, double t,
                 double s, Eigen::VectorXd& qd, Eigen::VectorXd& qdd, ParameterRates parameter = {});

//! joint_rates followed by the torques τ(q, q̇, q̈) and g(q) (SerialArm::torques) on the pass that
//! gave J_b: one pass over the chain for all of them.
void joint_rates_and_torques(const SerialArm& arm, const Eigen::VectorXd& q, const Twistd& body,
                             const Twistd& body_rate, double t, double s, Eigen::VectorXd& qd, Eigen::VectorXd& qdd,
                             Eigen::VectorXd& torque, Eigen::VectorXd& static_torque, ParameterRates parameter = {});

}  // namespace dispkin::serial::detail
