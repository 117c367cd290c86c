// Following a Cartesian trajectory with a serial arm's joints: the inverse-kinematics branch
// continuous from a reference configuration, and joint velocities from the body Jacobian
// (joint_following.hpp).
#include "joint_following.hpp"

#include <optional>
#include <stdexcept>
#include <string>

#include <Eigen/LU>

#include "branch_following.hpp"
#include "dispkin/error.hpp"
#include "dispkin/serial/chain_kinematics.hpp"

namespace dispkin {
namespace detail {

Eigen::VectorXd branch_solution(const serial::SerialArm& arm, const Posed& pose, const Eigen::VectorXd& q_ref, double t,
                                double s, const Eigen::VectorXd* guess) {
  serial::detail::BranchRule rule;
  rule.options.offer_equivalents = false;
  rule.options.keep_outside_limits = true;  // reported as a position excursion, not hidden
  rule.turns = serial::detail::Turns::nearest;
  std::optional<Eigen::VectorXd> q = serial::detail::solution_on_branch(arm, pose, q_ref, rule, guess);
  if (!q) throw std::runtime_error("the pose at " + where(t, s) + " has no inverse-kinematics solution");
  return std::move(*q);
}

namespace {

using BodyJacobian = Eigen::Matrix<double, 6, 6>;

// J_b(q) and its LU; throws naming the place near a singularity.
Eigen::FullPivLU<BodyJacobian> factorised_jacobian(const serial::SerialArm& arm, const Eigen::VectorXd& q,
                                                   BodyJacobian& j, double t, double s) {
  if (arm.dof() != 6) throw std::invalid_argument(describe("arm dof", static_cast<long>(arm.dof()), "must be 6 to invert the Jacobian"));
  serial::chain_body_jacobian(arm.chain(), q.data(), j);
  Eigen::FullPivLU<BodyJacobian> lu(j);
  if (lu.rcond() < 1e-10) {
    throw std::runtime_error("the arm is singular at " + where(t, s) + " (rcond of the Jacobian " + std::to_string(lu.rcond()) + ")");
  }
  return lu;
}

}  // namespace

Eigen::VectorXd joint_velocity(const serial::SerialArm& arm, const Eigen::VectorXd& q, const Twistd& body,
                               double t, double s) {
  BodyJacobian j;
  const Eigen::Matrix<double, 6, 1> qd = factorised_jacobian(arm, q, j, t, s).solve(body.vector());
  return qd;
}

void joint_rates(const serial::SerialArm& arm, const Eigen::VectorXd& q, const Twistd& body, const Twistd& body_rate,
                 double t, double s, Eigen::VectorXd& qd, Eigen::VectorXd& qdd) {
  BodyJacobian j;
  const Eigen::FullPivLU<BodyJacobian> lu = factorised_jacobian(arm, q, j, t, s);
  qd = lu.solve(body.vector());
  const Twistd product = serial::chain_velocity_product(j, qd.data());
  qdd = lu.solve(body_rate.vector() - product.vector());
}

}  // namespace detail

}  // namespace dispkin
