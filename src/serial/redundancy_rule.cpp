// The parameter of a redundant arm moved along a followed path (redundancy_rule.hpp): down the
// slope of a joint-limit and singularity cost along the self-motion, rate-limited
// (doc/inverse-kinematics.md (eq. 43)–(eq. 45)).
#include "redundancy_rule.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/LU>

#include "dispkin/error.hpp"

namespace dispkin::serial::detail {
namespace {

using Square = Eigen::Matrix<double, 6, 6>;

// Below this reciprocal condition number of J_b without the parameter's column the self-motion
// is not taken (the threshold of the followers' Jacobian, joint_following.cpp).
constexpr double singular_rcond = 1e-10;
// The step of the central difference of ln det(J_b^(j))² along n (doc/inverse-kinematics.md eq. 44's second term): its
// error is O(ε²) relative, its rounding O(1e-16 / ε).
constexpr double slope_step = 1e-6;

// J_b(q) without the parameter's column j: the six joints that move at a held parameter.
Square moving_jacobian(const SerialArm& arm, const Eigen::VectorXd& q, Eigen::MatrixXd& full) {
  const int locked = arm.redundancy().joint;
  full = arm.body_jacobian(q);
  Square j;
  for (int c = 0, k = 0; c < arm.dof(); ++c)
    if (c != locked) j.col(k++) = full.col(c);
  return j;
}

// ln det(J_b^(j))² (−∞ where the six moving joints are singular): the logarithm of their
// manipulability, twice over. Their singular poses, not the arm's, are where the parameter stops
// describing the self-motion and the closed form at a held θ turns joints fast (the Panda's
// q₂ = 0, axes 1 and 3 in line).
double log_manipulability(const SerialArm& arm, const Eigen::VectorXd& q) {
  Eigen::MatrixXd full;
  const double det = moving_jacobian(arm, q, full).determinant();
  return det != 0.0 ? std::log(det * det) : -std::numeric_limits<double>::infinity();
}

// The slope along n of the joint-limit term of doc/inverse-kinematics.md eq. 44, analytically: each
// joint with a finite range [l, u] adds h² / ((u − q)(q − l)), h = (u − l)/2: 1 at the range's
// centre, → ∞ at either end. NaN where a joint is at or beyond an end of its range.
double limit_slope(const JointLimits& limits, const Eigen::VectorXd& q, const Eigen::VectorXd& n) {
  double slope = 0.0;
  for (Eigen::Index i = 0; i < q.size(); ++i) {
    const double l = limits.lower(i), u = limits.upper(i);
    if (!std::isfinite(l) || !std::isfinite(u)) continue;
    const double h = 0.5 * (u - l), f = (u - q(i)) * (q(i) - l);
    if (!(f > 0.0)) return std::numeric_limits<double>::quiet_NaN();
    slope -= h * h * (u + l - 2.0 * q(i)) / (f * f) * n(i);  // d(1/f) = −f′/f²
  }
  return slope;
}

}  // namespace

std::optional<Eigen::VectorXd> self_motion(const SerialArm& arm, const Eigen::VectorXd& q) {
  const int locked = arm.redundancy().joint;
  if (locked < 0) return std::nullopt;
  Eigen::MatrixXd full;
  const Square j = moving_jacobian(arm, q, full);
  const Eigen::PartialPivLU<Square> lu(j);
  if (!(lu.rcond() >= singular_rcond)) return std::nullopt;
  const Eigen::Matrix<double, 6, 1> moving = lu.solve(-full.col(locked));
  Eigen::VectorXd n(arm.dof());
  for (int c = 0, k = 0; c < arm.dof(); ++c) n(c) = c == locked ? 1.0 : moving(k++);
  return n;
}

void require_valid(const RedundancyRule& rule) {
  require(std::isfinite(rule.gain) && rule.gain >= 0.0, "redundancy_rule.gain", rule.gain,
          "must be finite and at least 0");
  require(std::isfinite(rule.max_rate) && rule.max_rate >= 0.0, "redundancy_rule.max_rate", rule.max_rate,
          "must be finite and at least 0");
  require(std::isfinite(rule.singularity_weight) && rule.singularity_weight >= 0.0,
          "redundancy_rule.singularity_weight", rule.singularity_weight, "must be finite and at least 0");
}

double parameter_step(const SerialArm& arm, const Eigen::VectorXd& q, double travel, const RedundancyRule& rule) {
  if (!rule.move || !(travel > 0.0)) return 0.0;
  const std::optional<Eigen::VectorXd> n = self_motion(arm, q);
  if (!n) return 0.0;
  double slope = limit_slope(arm.joint_limits(), q, *n);
  if (rule.singularity_weight > 0.0) {
    const double ahead = log_manipulability(arm, q + slope_step * *n);
    const double behind = log_manipulability(arm, q - slope_step * *n);
    slope -= rule.singularity_weight * (ahead - behind) / (2.0 * slope_step);
  }
  if (!std::isfinite(slope)) return 0.0;
  const double rate = std::clamp(-rule.gain * slope, -rule.max_rate, rule.max_rate);
  return rate * travel;
}

}  // namespace dispkin::serial::detail
