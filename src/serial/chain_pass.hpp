// The one pass of the product of exponentials over a revolute chain (chain_kinematics.hpp,
// doc/inverse-kinematics.md (eq. 1)), shared by the forward kinematics and Jacobians
// (chain_kinematics.cpp) and the recursive Newton–Euler torques (chain_dynamics.cpp), so that
// both see the same axes and motions to the last bit.
#pragma once

#include <array>
#include <cstddef>

#include <Eigen/Core>

#include "dispkin/pose.hpp"
#include "dispkin/serial/revolute_chain.hpp"

namespace dispkin {
namespace serial {
namespace detail {

//! Walks the joints base → tip: visit(i, ωᵢ′, pᵢ′, T₍≤ᵢ₎) with ωᵢ′ = R₍<ᵢ₎ ωᵢ and pᵢ′ = T₍<ᵢ₎ pᵢ
//! the axis of joint i at q and T₍≤ᵢ₎ = e^{[ξ₁]q₁} ⋯ e^{[ξᵢ]qᵢ}, the motion of the body it turns
//! (its frame at q is T₍≤ᵢ₎ times its frame at q = 0). Returns the motion of the last joint.
template <typename Visit>
inline Posed chain_pass(const RevoluteChain& chain, const double* q, Visit&& visit) noexcept {
  Posed t;
  const int n = chain.dof();
  for (int i = 0; i < n; ++i) {
    const auto k = static_cast<std::size_t>(i);
    const Eigen::Vector3d w = t.quaternion() * chain.axes[k];
    const Eigen::Vector3d p = t * chain.points[k];
    t = t * rotation_about_line(chain.axes[k], chain.points[k], q[i]);
    visit(i, w, p, t);
  }
  return t;
}

//! A pass kept for later kernels at the same q (chain.dof() ≤ max_recorded_joints): what
//! chain_pass visits, joint by joint, so that the torques after a Jacobian (chain_dynamics.hpp)
//! need no second pass.
constexpr int max_recorded_joints = 16;
struct ChainPassRecord {
  int joints = 0;
  std::array<Eigen::Vector3d, max_recorded_joints> axes, points;
  std::array<Posed, max_recorded_joints> motions;
};

//! chain_body_jacobian (chain_kinematics.hpp) that also fills `record`.
Posed chain_body_jacobian(const RevoluteChain& chain, const double* q,
                          Eigen::Ref<Eigen::Matrix<double, 6, Eigen::Dynamic>> jacobian,
                          ChainPassRecord& record) noexcept;

}  // namespace detail
}  // namespace serial
}  // namespace dispkin
