// Forward kinematics and Jacobians of a revolute chain by the product of exponentials
// (chain_kinematics.hpp; doc/inverse-kinematics.md (eq. 1) and (eq. 22)).
#include "dispkin/serial/chain_kinematics.hpp"

#include <stdexcept>
#include <string>

#include "chain_pass.hpp"
#include "dispkin/error.hpp"

namespace dispkin {
namespace serial {

Posed chain_pose(const RevoluteChain& chain, const double* q) noexcept {
  Posed t;
  const int n = chain.dof();
  for (int i = 0; i < n; ++i) {
    const auto k = static_cast<std::size_t>(i);
    t = t * rotation_about_line(chain.axes[k], chain.points[k], q[i]);
  }
  return t * chain.tip_at_zero;
}

void chain_pose_and_twist(const RevoluteChain& chain, const double* q, const double* qd, Posed& pose,
                          Twistd& body_twist, Eigen::Vector3d* axis_points) noexcept {
  // Spatial velocity field x ↦ v_s + ω_s × x: joint i adds q̇ᵢ ωᵢ′ × (x − pᵢ′) = q̇ᵢ (pᵢ′ × ωᵢ′ + ωᵢ′ × x).
  Eigen::Vector3d v_s = Eigen::Vector3d::Zero(), w_s = Eigen::Vector3d::Zero();
  const Posed t =
      detail::chain_pass(chain, q, [&](int i, const Eigen::Vector3d& w, const Eigen::Vector3d& p, const Posed&) {
        if (axis_points) axis_points[i] = p;
        v_s += qd[i] * p.cross(w);
        w_s += qd[i] * w;
      });
  pose = t * chain.tip_at_zero;
  // Body twist: ω_b = Rᵀ ω_s, v_b = Rᵀ (velocity of the tool origin o) = Rᵀ (v_s + ω_s × o).
  const Eigen::Quaterniond r_inv = pose.quaternion().conjugate();
  body_twist = Twistd(r_inv * (v_s + w_s.cross(pose.translation())), r_inv * w_s);
}

namespace {

// chain_jacobian, also filling `record` when it is not null.
Posed jacobian_pass(const RevoluteChain& chain, const double* q, ChainJacobianRef jacobian,
                    detail::ChainPassRecord* record) noexcept {
  // The same pass as chain_pose_and_twist, keeping ωᵢ′ (bottom rows) and pᵢ′ (top rows, until the
  // tool origin o is known and they become ωᵢ′ × (o − pᵢ′)).
  const int n = chain.dof();
  const Posed t =
      detail::chain_pass(chain, q, [&](int i, const Eigen::Vector3d& w, const Eigen::Vector3d& p, const Posed& motion) {
        jacobian.block<3, 1>(3, i) = w;
        jacobian.block<3, 1>(0, i) = p;
        if (record) {
          const auto k = static_cast<std::size_t>(i);
          record->axes[k] = w;
          record->points[k] = p;
          record->motions[k] = motion;
        }
      });
  if (record) record->joints = n;
  const Posed pose = t * chain.tip_at_zero;
  const Eigen::Vector3d& o = pose.translation();
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector3d w = jacobian.block<3, 1>(3, i);
    jacobian.block<3, 1>(0, i) = w.cross(o - jacobian.block<3, 1>(0, i));
  }
  return pose;
}

// J_b = diag(Rᵀ, Rᵀ) J in place.
void to_body(const Posed& pose, ChainJacobianRef jacobian, int n) noexcept {
  const Eigen::Matrix3d r_t = pose.rotation().transpose();
  for (int i = 0; i < n; ++i) {
    jacobian.block<3, 1>(0, i) = r_t * jacobian.block<3, 1>(0, i).eval();
    jacobian.block<3, 1>(3, i) = r_t * jacobian.block<3, 1>(3, i).eval();
  }
}

}  // namespace

Posed chain_jacobian(const RevoluteChain& chain, const double* q, ChainJacobianRef jacobian) noexcept {
  return jacobian_pass(chain, q, jacobian, nullptr);
}

Posed chain_body_jacobian(const RevoluteChain& chain, const double* q, ChainJacobianRef jacobian) noexcept {
  const Posed pose = jacobian_pass(chain, q, jacobian, nullptr);
  to_body(pose, jacobian, chain.dof());
  return pose;
}

namespace detail {

Posed chain_body_jacobian(const RevoluteChain& chain, const double* q, ChainJacobianRef jacobian,
                          ChainPassRecord& record) noexcept {
  const Posed pose = jacobian_pass(chain, q, jacobian, &record);
  to_body(pose, jacobian, chain.dof());
  return pose;
}

}  // namespace detail

Twistd chain_velocity_product(const Eigen::Ref<const Eigen::Matrix<double, 6, Eigen::Dynamic>>& body_jacobian,
                              const double* qd) noexcept {
  // [V, ξ] = (ω_V × v_ξ + v_V × ω_ξ, ω_V × ω_ξ) with V = (v_V, ω_V) the twist of the joints before i.
  Eigen::Vector3d v = Eigen::Vector3d::Zero(), w = Eigen::Vector3d::Zero();
  Eigen::Vector3d product_v = Eigen::Vector3d::Zero(), product_w = Eigen::Vector3d::Zero();
  for (Eigen::Index i = 0; i < body_jacobian.cols(); ++i) {
    const Eigen::Vector3d column_v = body_jacobian.block<3, 1>(0, i), column_w = body_jacobian.block<3, 1>(3, i);
    product_v += qd[i] * (w.cross(column_v) + v.cross(column_w));
    product_w += qd[i] * w.cross(column_w);
    v += qd[i] * column_v;
    w += qd[i] * column_w;
  }
  return Twistd(product_v, product_w);
}

Posed forward(const RevoluteChain& chain, const Eigen::VectorXd& q) {
  if (q.size() != chain.dof())
    throw std::invalid_argument("q: expected " + std::to_string(chain.dof()) + " joint values, got " +
                                std::to_string(q.size()));
  require_finite(q, "q");
  return chain_pose(chain, q.data());
}

}  // namespace serial
}  // namespace dispkin
