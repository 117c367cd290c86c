// Newton's method on the full pose error, the last step of every analytic IK solver: it
// removes the rounding a chain of subproblems accumulates near singular configurations and
// turns a refined root of the offset-wrist search into an exact solution.
#include <Eigen/Geometry>
#include <Eigen/LU>
#include <Eigen/QR>

#include "ik_internal.hpp"

namespace dispkin {
namespace serial {
namespace detail {
namespace {

// The rotation angle (rad) of a unit quaternion, stable near 0.
double angle_of(const Eigen::Quaterniond& q) { return 2.0 * std::atan2(q.vec().norm(), std::abs(q.w())); }

// T(q) = e₁ ⋯ e₆ M, with the space-frame joint axes ωᵢ' and points pᵢ' at q on the way
// (matrices: one sincos per joint, no quaternion products).
Motion forward_with_axes(const RevoluteChain& chain, const Vector6d& q, Eigen::Matrix<double, 3, 6>& w,
                         Eigen::Matrix<double, 3, 6>& p) {
  Motion t;
  for (int i = 0; i < 6; ++i) {
    const auto k = static_cast<std::size_t>(i);
    w.col(i) = t.r * chain.axes[k];
    p.col(i) = t * chain.points[k];
    t = t * joint_motion(chain, i, {std::cos(q(i)), std::sin(q(i))});
  }
  return t * Motion::of(chain.tip_at_zero);
}

// Position and rotation error of the tip pose t against the target.
PoseError error_of(const Posed& t, const Posed& target) {
  PoseError e;
  e.position = (t.translation() - target.translation()).norm();
  e.rotation = angle_of(target.quaternion().conjugate() * t.quaternion());
  return e;
}

// Below this ratio of the smallest to the largest pivot of J's LU the Newton step is the
// minimum-norm one (a singular J has a zero pivot; the ratio is a cheap stand-in for the
// reciprocal condition number, whose estimate costs more than the factorisation).
constexpr double well_conditioned = 1e-5;

// min |uᵢᵢ| / max |uᵢᵢ| of a partial-pivoting LU.
double pivot_ratio(const Eigen::PartialPivLU<Eigen::Matrix<double, 6, 6>>& lu) {
  const auto pivots = lu.matrixLU().diagonal().cwiseAbs();
  return pivots.minCoeff() / pivots.maxCoeff();
}

}  // namespace

PoseError pose_error(const RevoluteChain& chain, const Vector6d& q, const Posed& target) noexcept {
  Posed t;
  for (int i = 0; i < 6; ++i) {
    const auto k = static_cast<std::size_t>(i);
    t = t * rotation_about_line(chain.axes[k], chain.points[k], q(i));
  }
  return error_of(t * chain.tip_at_zero, target);
}

PoseError polish(const RevoluteChain& chain, const Posed& target, Vector6d& q, int max_iterations) noexcept {
  Eigen::Matrix<double, 3, 6> w, p;
  Eigen::Matrix<double, 6, 6> jacobian;
  Eigen::Matrix<double, 6, 1> residual;
  Eigen::PartialPivLU<Eigen::Matrix<double, 6, 6>> lu;
  Eigen::CompleteOrthogonalDecomposition<Eigen::Matrix<double, 6, 6>> minimum_norm;
  const Motion goal = Motion::of(target);
  // One forward kinematics per q: it gives both the error and the Jacobian's axes.
  Motion t = forward_with_axes(chain, q, w, p);
  Vector6d best = q;
  PoseError best_error = motion_error(t, goal);
  for (int iteration = 0; iteration < max_iterations && best_error.worst() > 1e-15; ++iteration) {
    // Space-frame error: the tool origin must move by Δt, the frame turn by the rotation vector
    // of R_target Rᵀ; joint i moves the origin by ωᵢ' × (t − pᵢ') and turns it about ωᵢ'.
    residual.head<3>() = goal.t - t.t;
    residual.tail<3>() = quaternion_log(Eigen::Quaterniond(Eigen::Matrix3d(goal.r * t.r.transpose())));
    for (int i = 0; i < 6; ++i) {
      jacobian.block<3, 1>(0, i) = w.col(i).cross(t.t - p.col(i));
      jacobian.block<3, 1>(3, i) = w.col(i);
    }
    // Away from singular q the step is J⁻¹ e (LU); near them the minimum-norm least-squares
    // step, which leaves the free combination alone.
    lu.compute(jacobian);
    if (pivot_ratio(lu) > well_conditioned) {
      q += lu.solve(residual);
    } else {
      minimum_norm.setThreshold(1e-10);
      minimum_norm.compute(jacobian);
      q += minimum_norm.solve(residual);
    }
    for (int i = 0; i < 6; ++i) q(i) = wrap_angle(q(i));
    t = forward_with_axes(chain, q, w, p);
    const PoseError e = motion_error(t, goal);
    if (e.worst() < best_error.worst()) {
      best = q;
      best_error = e;
    } else if (iteration >= 1) {
      break;  // no progress: rounding reached, or no solution near the start
    }
  }
  q = best;
  return best_error;
}

}  // namespace detail
}  // namespace serial
}  // namespace dispkin
