// Following a Cartesian trajectory with a serial arm's joints: the inverse-kinematics branch
// continuous from a reference configuration (internal to the serial plugin; joint_following.cpp).
#pragma once

#include <string>

#include <Eigen/Core>

#include "dispkin/error.hpp"
#include "dispkin/pose.hpp"
#include "dispkin/serial/serial_arm.hpp"

namespace dispkin::detail {

//! The IK solution nearest to q_ref, each joint first moved by a multiple of 2π to the value
//! nearest to q_ref's (branch continuity for joints whose range exceeds one turn). Throws
//! std::runtime_error naming the place (where(t, s)) if the pose has no solution.
Eigen::VectorXd continuous_solution(const serial::SerialArm& arm, const Posed& pose, const Eigen::VectorXd& q_ref,
                                    double t, double s);

//! The same solution found faster when the pose is near forward(q_ref): Newton's method from
//! `guess` (q_ref if null), falling back to continuous_solution when it does not converge
//! within 0.3 rad of q_ref.
Eigen::VectorXd tracked_solution(const serial::SerialArm& arm, const Posed& pose, const Eigen::VectorXd& q_ref, double t,
                                 double s, const Eigen::VectorXd* guess = nullptr);

//! q̇ with J_b(q) q̇ = ξ_b; throws std::runtime_error naming the place near a singularity (the
//! joint speeds there are unbounded: slowing down cannot help).
Eigen::VectorXd joint_velocity(const serial::SerialArm& arm, const Eigen::VectorXd& q, const Twistd& body,
                               double t, double s);

}  // namespace dispkin::detail
