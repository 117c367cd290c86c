// Following a Cartesian trajectory with a serial arm's joints: the inverse-kinematics branch
// continuous from a reference configuration, and joint velocities from the body Jacobian
// (joint_following.hpp).
#include "joint_following.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>

#include <Eigen/LU>

#include "branch_following.hpp"
#include "chain_dynamics.hpp"
#include "chain_pass.hpp"
#include "dispkin/error.hpp"
#include "dispkin/serial/chain_kinematics.hpp"
#include "dispkin/serial/ptp.hpp"
#include "dispkin/serial/redundancy.hpp"

namespace dispkin::serial {
namespace detail {

using dispkin::detail::where;

Eigen::VectorXd branch_solution(const SerialArm& arm, const Posed& pose, const Eigen::VectorXd& q_ref, double t,
                                double s, const Eigen::VectorXd* guess) {
  detail::BranchRule rule;
  rule.options.offer_equivalents = false;
  rule.options.keep_outside_limits = true;  // reported as a position excursion, not hidden
  rule.turns = detail::Turns::nearest;
  std::optional<Eigen::VectorXd> q = detail::solution_on_branch(arm, pose, q_ref, rule, guess);
  if (!q) {
    // A seven-joint arm is solved at one value of its parameter: say which, since another value
    // (a RedundancyRule that moves it) may reach the pose.
    const Redundancy& redundancy = arm.redundancy();
    std::ostringstream at_value;
    if (redundancy.has_parameter()) {
      at_value.precision(12);
      at_value << " with its redundancy parameter " << redundancy.joint_name << " at " << q_ref(redundancy.joint)
               << " rad";
    }
    throw std::runtime_error("the pose at " + where(t, s) + " has no inverse-kinematics solution" + at_value.str());
  }
  return std::move(*q);
}

namespace {

using BodyJacobian = Eigen::Matrix<double, 6, 6>;
// 6 × dof without heap allocation up to max_ptp_joints (a 6R or 7R arm on the real-time path).
using FullJacobian = Eigen::Matrix<double, 6, Eigen::Dynamic, 0, 6, max_ptp_joints>;

// Below this reciprocal condition number (1-norm, Eigen's estimate) the arm counts as singular.
constexpr double singular_rcond = 1e-10;

// The largest column sum of |m|: the 1-norm.
double norm_1(const BodyJacobian& m) { return m.cwiseAbs().colwise().sum().maxCoeff(); }

// ‖L⁻¹‖₁ and ‖U⁻¹‖₁ of the factors packed in `lu` (L unit lower, U upper), column by column by
// substitution (plain loops: Eigen's triangular solve with a matrix right-hand side takes its
// blocked path, slower than the estimate it is meant to spare).
void inverse_factor_norms(const BodyJacobian& lu, double& l_norm, double& u_norm) {
  constexpr int n = 6;
  l_norm = u_norm = 0.0;
  for (int k = 0; k < n; ++k) {
    double x[n] = {};
    x[k] = 1.0;
    double sum = 1.0;
    for (int i = k + 1; i < n; ++i) {
      double r = 0.0;
      for (int c = k; c < i; ++c) r -= lu(i, c) * x[c];
      x[i] = r;
      sum += std::abs(r);
    }
    l_norm = std::max(l_norm, sum);
    x[k] = 1.0 / lu(k, k);
    sum = std::abs(x[k]);
    for (int i = k - 1; i >= 0; --i) {
      double r = 0.0;
      for (int c = i + 1; c <= k; ++c) r -= lu(i, c) * x[c];
      x[i] = r / lu(i, i);
      sum += std::abs(x[i]);
    }
    u_norm = std::max(u_norm, sum);
  }
}

// Whether J clears singular_rcond, Eigen's rcond estimate computed only near the threshold. With
// J = P⁻¹ L U, ‖J⁻¹‖₁ ≤ ‖U⁻¹‖₁ ‖L⁻¹‖₁, and the estimate of ‖J⁻¹‖₁ is the norm of J⁻¹ applied
// to a unit vector, never above the true one: where the bound 1 / (‖J‖₁ ‖U⁻¹‖₁ ‖L⁻¹‖₁) clears
// the threshold (twice over, for rounding), so does the estimate, and the decision is the
// estimate's either way. The two triangular inverses cost less than the estimate's iterations.
bool clears_singularity(const BodyJacobian& j, const Eigen::PartialPivLU<BodyJacobian>& lu, double& rcond) {
  double l_norm, u_norm;
  inverse_factor_norms(lu.matrixLU(), l_norm, u_norm);
  const double bound = 1.0 / (norm_1(j) * l_norm * u_norm);
  if (bound >= 2.0 * singular_rcond) return true;  // false also for a NaN bound (a zero pivot)
  rcond = lu.rcond();
  return rcond >= singular_rcond;
}

// The square body Jacobian of the joints that move into `j` (a redundant arm: the full J_b(q), 6 × dof,
// into `full` first): all six of a 6R arm; a redundant arm's but the locked one, whose rate is 0 on a path
// at one parameter value (doc/inverse-kinematics.md (eq. 42)).
void moving_jacobian(const SerialArm& arm, const Eigen::VectorXd& q, FullJacobian& full, BodyJacobian& j,
                     detail::ChainPassRecord* record) {
  const int locked = arm.redundancy().joint;
  if (arm.dof() != 6 && locked < 0)
    throw std::invalid_argument(describe("arm dof", static_cast<long>(arm.dof()),
                                         "must be 6, or 7 with a redundancy parameter, to invert the Jacobian"));
  if (locked < 0) {
    // A 6R arm: J_b itself, computed in place (bit for bit the rates of tests/data/plan_fingerprint.txt).
    if (record) {
      detail::chain_body_jacobian(arm.chain(), q.data(), j, *record);
    } else {
      chain_body_jacobian(arm.chain(), q.data(), j);
    }
    return;
  }
  full.resize(6, arm.dof());
  if (record) {
    detail::chain_body_jacobian(arm.chain(), q.data(), full, *record);
  } else {
    chain_body_jacobian(arm.chain(), q.data(), full);
  }
  for (int c = 0, k = 0; c < arm.dof(); ++c)
    if (c != locked) j.col(k++) = full.col(c);
}

// The rates of the moving joints (`moving`, 6) as rates of all joints into `out`, `parameter` at
// the locked one (no allocation when `out` has the size already).
void all_joints(const SerialArm& arm, const Eigen::Matrix<double, 6, 1>& moving, double parameter,
                Eigen::VectorXd& out) {
  const int locked = arm.redundancy().joint;
  out.resize(arm.dof());
  for (int c = 0, k = 0; c < arm.dof(); ++c) out(c) = c == locked ? parameter : moving(k++);
}

// J_b(q) of the moving joints and its LU (partial pivoting: it is square and, where it is used,
// well conditioned), recording the pass if `record` is not null; throws naming the place near a
// singularity.
Eigen::PartialPivLU<BodyJacobian> factorised_jacobian(const SerialArm& arm, const Eigen::VectorXd& q,
                                                      FullJacobian& full, BodyJacobian& j, double t, double s,
                                                      detail::ChainPassRecord* record = nullptr) {
  moving_jacobian(arm, q, full, j, record);
  Eigen::PartialPivLU<BodyJacobian> lu(j);
  double rcond = 0.0;
  if (!clears_singularity(j, lu, rcond)) {
    throw std::runtime_error("the arm is singular at " + where(t, s) + " (rcond of the Jacobian " +
                             std::to_string(rcond) + ")");
  }
  return lu;
}

}  // namespace

Eigen::VectorXd joint_velocity(const SerialArm& arm, const Eigen::VectorXd& q, const Twistd& body, double t, double s,
                               double parameter_rate) {
  BodyJacobian j;
  FullJacobian full;
  const Eigen::PartialPivLU<BodyJacobian> lu = factorised_jacobian(arm, q, full, j, t, s);
  if (arm.dof() == 6) {
    // Solved into a fixed-size vector, as ever (bit for bit tests/data/plan_fingerprint.txt).
    const Eigen::Matrix<double, 6, 1> qd = lu.solve(body.vector());
    return qd;
  }
  // The parameter's own share of the twist moves to the right side (doc/inverse-kinematics.md eq. 47).
  const int locked = arm.redundancy().joint;
  Eigen::VectorXd qd;
  all_joints(arm, lu.solve(body.vector() - parameter_rate * full.col(locked)), parameter_rate, qd);
  return qd;
}

namespace {

void rates(const SerialArm& arm, const Eigen::VectorXd& q, const Twistd& body, const Twistd& body_rate, double t,
           double s, Eigen::VectorXd& qd, Eigen::VectorXd& qdd, ParameterRates parameter,
           detail::ChainPassRecord* record) {
  BodyJacobian j;
  FullJacobian full;
  const Eigen::PartialPivLU<BodyJacobian> lu = factorised_jacobian(arm, q, full, j, t, s, record);
  if (arm.dof() == 6) {
    qd = lu.solve(body.vector());
    const Twistd product = chain_velocity_product(j, qd.data());
    qdd = lu.solve(body_rate.vector() - product.vector());
    return;
  }
  // doc/inverse-kinematics.md eqs. 47–48: the parameter's column times θ̇ and θ̈ on the right side;
  // J̇_b q̇ takes θ̇ with the other rates.
  const auto column = full.col(arm.redundancy().joint);
  all_joints(arm, lu.solve(body.vector() - parameter.rate * column), parameter.rate, qd);
  const Twistd product = chain_velocity_product(full, qd.data());
  all_joints(arm, lu.solve(body_rate.vector() - product.vector() - parameter.acceleration * column),
             parameter.acceleration, qdd);
}

}  // namespace

void joint_rates(const SerialArm& arm, const Eigen::VectorXd& q, const Twistd& body, const Twistd& body_rate, double t,
                 double s, Eigen::VectorXd& qd, Eigen::VectorXd& qdd, ParameterRates parameter) {
  rates(arm, q, body, body_rate, t, s, qd, qdd, parameter, nullptr);
}

void joint_rates_and_torques(const SerialArm& arm, const Eigen::VectorXd& q, const Twistd& body,
                             const Twistd& body_rate, double t, double s, Eigen::VectorXd& qd, Eigen::VectorXd& qdd,
                             Eigen::VectorXd& torque, Eigen::VectorXd& static_torque, ParameterRates parameter) {
  detail::ChainPassRecord record;
  rates(arm, q, body, body_rate, t, s, qd, qdd, parameter, &record);
  detail::recorded_torques(arm, record, qd, qdd, torque, static_torque);
}

}  // namespace detail

}  // namespace dispkin::serial
