// Newton's method on the full pose error (ik_newton.hpp): with the tool pose (R, t) and the
// geometric Jacobian J of one pass of the product of exponentials (chain_kinematics.hpp),
//
//   e = ( t_target − t,  log(R_target Rᵀ) ),     J_i = ( ωᵢ′ × (t − pᵢ′),  ωᵢ′ )        doc/inverse-kinematics.md (eq.
//   22) Δq = J⁻¹ e  where J is square and well conditioned,  J⁺ e  otherwise doc/inverse-kinematics.md (eq. 23)
//
// (both sides of e are space-frame quantities at the tool origin, the convention of J).
#include "ik_newton.hpp"

#include <cmath>

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <Eigen/LU>
#include <Eigen/QR>

#include "angles.hpp"
#include "dispkin/serial/chain_kinematics.hpp"

namespace dispkin {
namespace serial {
namespace detail {
namespace {

using Residual = Eigen::Matrix<double, 6, 1>;

// Below this the complete orthogonal decomposition treats a direction as singular (relative to
// the largest pivot of its QR).
constexpr double singular_threshold = 1e-10;

// The Newton step Δq of a square J (doc/inverse-kinematics.md eq. 23): J⁻¹ e by LU when its pivot ratio says it is well
// conditioned, else the minimum-norm one, if allowed. False: no step.
bool newton_step(const Eigen::Matrix<double, 6, 6>& jacobian, const Residual& residual, const NewtonSettings& settings,
                 Eigen::Matrix<double, 6, 1>& step) noexcept {
  const Eigen::PartialPivLU<Eigen::Matrix<double, 6, 6>> lu(jacobian);
  const auto pivots = lu.matrixLU().diagonal().cwiseAbs();
  if (pivots.minCoeff() / pivots.maxCoeff() > settings.well_conditioned) {
    step = lu.solve(residual);
    return true;
  }
  if (!settings.minimum_norm_when_singular) return false;
  Eigen::CompleteOrthogonalDecomposition<Eigen::Matrix<double, 6, 6>> minimum_norm;
  minimum_norm.setThreshold(singular_threshold);
  minimum_norm.compute(jacobian);
  step = minimum_norm.solve(residual);
  return true;
}

// A J that is not square (a short or a redundant chain): always the minimum-norm least-squares step.
template <typename Jacobian, typename Step>
bool newton_step(const Jacobian& jacobian, const Residual& residual, const NewtonSettings&, Step& step) noexcept {
  Eigen::CompleteOrthogonalDecomposition<Jacobian> minimum_norm;
  minimum_norm.setThreshold(singular_threshold);
  minimum_norm.compute(jacobian);
  step = minimum_norm.solve(residual);
  return true;
}

// Jacobian: a 6 × n matrix type holding the chain's J (fixed 6 × 6, bounded, or dynamic).
template <typename Jacobian>
PoseError refine(const RevoluteChain& chain, const Posed& target, double* q_out,
                 const NewtonSettings& settings) noexcept {
  using Joints = Eigen::Matrix<double, Jacobian::ColsAtCompileTime, 1, 0, Jacobian::MaxColsAtCompileTime, 1>;
  const int n = chain.dof();
  Joints q = Eigen::Map<const Eigen::VectorXd>(q_out, n);
  Jacobian jacobian;
  jacobian.resize(6, n);
  Residual residual;
  Joints step;
  // One pass of the product of exponentials per q: the pose for the error and the Jacobian.
  Posed pose = chain_jacobian(chain, q.data(), jacobian);
  Joints best = q;
  PoseError best_error = pose_error(pose, target);
  for (int iteration = 0; n > 0 && iteration < settings.max_iterations && best_error.worst() > settings.tolerance;
       ++iteration) {
    residual.head<3>() = target.translation() - pose.translation();
    residual.tail<3>() = quaternion_log(Eigen::Quaterniond(target.quaternion() * pose.quaternion().conjugate()));
    if (!newton_step(jacobian, residual, settings, step)) break;
    if (!step.allFinite() || step.cwiseAbs().maxCoeff() > settings.largest_step) break;
    q += step;
    if (settings.wrap)
      for (int i = 0; i < n; ++i) q(i) = wrap_angle(q(i));
    pose = chain_jacobian(chain, q.data(), jacobian);
    const PoseError e = pose_error(pose, target);
    if (e.worst() < best_error.worst()) {
      best = q;
      best_error = e;
    } else if (iteration >= 1) {
      break;  // no progress: rounding reached, or no solution near the start
    }
  }
  Eigen::Map<Eigen::VectorXd>(q_out, n) = best;
  return best_error;
}

}  // namespace

PoseError pose_error(const Posed& pose, const Posed& target) noexcept {
  PoseError e;
  e.position = (pose.translation() - target.translation()).norm();
  // The rotation angle of R_targetᵀ R from its quaternion, stable near 0.
  const Eigen::Quaterniond difference = target.quaternion().conjugate() * pose.quaternion();
  e.rotation = 2.0 * std::atan2(difference.vec().norm(), std::abs(difference.w()));
  return e;
}

PoseError refine_pose(const RevoluteChain& chain, const Posed& target, double* q,
                      const NewtonSettings& settings) noexcept {
  const int n = chain.dof();
  if (n == 6) return refine<Eigen::Matrix<double, 6, 6>>(chain, target, q, settings);
  if (n <= max_newton_joints)
    return refine<Eigen::Matrix<double, 6, Eigen::Dynamic, 0, 6, max_newton_joints>>(chain, target, q, settings);
  return refine<Eigen::Matrix<double, 6, Eigen::Dynamic>>(chain, target, q, settings);
}

}  // namespace detail
}  // namespace serial
}  // namespace dispkin
