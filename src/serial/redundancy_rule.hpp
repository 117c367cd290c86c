// The rule that moves a redundant arm's parameter along a followed path (doc/inverse-kinematics.md
// §12; internal to the serial plugin): the self-motion at a joint vector, the cost's slope along it
// and the parameter's step from one pose to the next.
#pragma once

#include <optional>

#include <Eigen/Core>

#include "dispkin/serial/serial_arm.hpp"

namespace dispkin::serial::detail {

//! The self-motion n of q (doc/inverse-kinematics.md eq. 43): J_b(q) n = 0 with n_j = 1 at the parameter's joint j, the
//! joint velocity per unit rate of the parameter that keeps the tip still. Empty where J_b without
//! column j is singular (there the parameter does not describe the self-motion).
std::optional<Eigen::VectorXd> self_motion(const SerialArm& arm, const Eigen::VectorXd& q);

//! The parameter's step Δθ of doc/inverse-kinematics.md eq. 45 at the joint vector q reached at the previous parameter
//! value after `travel` radians of joint motion (‖q − q_previous‖₂): the cost's slope along the
//! self-motion, times the gain, bounded by the rate, times the travel. 0 where the slope is not
//! defined (a singular pose) or rule.move is false.
double parameter_step(const SerialArm& arm, const Eigen::VectorXd& q, double travel, const RedundancyRule& rule);

//! Throws std::invalid_argument naming the field of `rule` that is not finite or below 0.
void require_valid(const RedundancyRule& rule);

}  // namespace dispkin::serial::detail
