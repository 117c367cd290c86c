// Following a Cartesian trajectory with a serial arm's joints: the inverse-kinematics branch
// continuous from a reference configuration, and joint velocities from the body Jacobian
// (joint_following.hpp).
#include "joint_following.hpp"

#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <Eigen/LU>

#include "dispkin/error.hpp"

namespace dispkin {
namespace detail {

Eigen::VectorXd continuous_solution(const serial::SerialArm& arm, const Posed& pose, const Eigen::VectorXd& q_ref,
                                    double t, double s) {
  constexpr double two_pi = 6.28318530717958647692;
  serial::InverseOptions options;
  options.offer_equivalents = false;
  options.keep_outside_limits = true;  // reported as a position excursion, not hidden
  const std::vector<Eigen::VectorXd> solutions = arm.inverse_solutions(pose, options).solutions;
  if (solutions.empty()) throw std::runtime_error("the pose at " + where(t, s) + " has no inverse-kinematics solution");
  Eigen::VectorXd best;
  double best_distance = std::numeric_limits<double>::infinity();
  for (Eigen::VectorXd q : solutions) {
    for (Eigen::Index i = 0; i < q.size(); ++i) q(i) += two_pi * std::round((q_ref(i) - q(i)) / two_pi);
    const double distance = (q - q_ref).norm();
    if (distance < best_distance) {
      best_distance = distance;
      best = q;
    }
  }
  return best;
}

Eigen::VectorXd tracked_solution(const serial::SerialArm& arm, const Posed& pose, const Eigen::VectorXd& q_ref, double t,
                                 double s, const Eigen::VectorXd* guess) {
  // Newton's method on the body-frame pose error from q_ref. Along a trajectory consecutive
  // poses are close, so it converges quadratically in two or three steps to the solution on
  // q_ref's branch — a third of the cost of enumerating every analytic solution. Anything
  // unusual (no convergence, a near-singular Jacobian, a step of more than 0.3 rad, where a
  // different branch may have been reached) falls back to the analytic nearest solution.
  constexpr double tolerance = 1e-13, largest_step = 0.3;
  Eigen::VectorXd q = guess ? *guess : q_ref;
  for (int iteration = 0; iteration < 6; ++iteration) {
    const Eigen::Matrix<double, 6, 1> error = (arm.forward(q).inverse() * pose).log().vector();
    if (error.lpNorm<Eigen::Infinity>() <= tolerance) {
      if ((q - q_ref).lpNorm<Eigen::Infinity>() <= largest_step) return q;
      break;
    }
    const Eigen::MatrixXd j = arm.body_jacobian(q);
    if (j.cols() != 6) break;
    const Eigen::Matrix<double, 6, 6> j6 = j;
    const Eigen::PartialPivLU<Eigen::Matrix<double, 6, 6>> lu(j6);
    if (!(std::abs(lu.determinant()) > 1e-9)) break;
    q += lu.solve(error);
    if (!q.allFinite()) break;
  }
  return continuous_solution(arm, pose, q_ref, t, s);
}

Eigen::VectorXd joint_velocity(const serial::SerialArm& arm, const Eigen::VectorXd& q, const Twistd& body,
                               double t, double s) {
  const Eigen::MatrixXd j = arm.body_jacobian(q);
  if (j.cols() != 6) throw std::invalid_argument(describe("arm dof", static_cast<long>(j.cols()), "must be 6 to invert the Jacobian"));
  const Eigen::FullPivLU<Eigen::MatrixXd> lu(j);
  if (lu.rcond() < 1e-10) {
    throw std::runtime_error("the arm is singular at " + where(t, s) + " (rcond of the Jacobian " + std::to_string(lu.rcond()) + ")");
  }
  return lu.solve(body.vector());
}

}  // namespace detail

}  // namespace dispkin
