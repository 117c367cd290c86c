//! Forward kinematics and Jacobians of a RevoluteChain by the product of exponentials
//! (doc/inverse-kinematics.md (eq. 1)):
//!
//!   T(q) = e^{[ξ₁]q₁} ⋯ e^{[ξₙ]qₙ} M,     e^{[ξᵢ]θ}: x ↦ R(ωᵢ, θ)(x − pᵢ) + pᵢ
//!
//! Joint i at q turns about the axis ωᵢ′ = R₍<ᵢ₎ ωᵢ through the point pᵢ′ = T₍<ᵢ₎ pᵢ, with
//! T₍<ᵢ₎ = e^{[ξ₁]q₁} ⋯ e^{[ξᵢ₋₁]qᵢ₋₁} the motion of the joints before it. A joint velocity q̇ᵢ
//! moves a point x at q̇ᵢ ωᵢ′ × (x − pᵢ′) and turns the tool at q̇ᵢ ωᵢ′, so the tool origin o
//! moves at
//!
//!   v = Σᵢ q̇ᵢ ωᵢ′ × (o − pᵢ′),    ω = Σᵢ q̇ᵢ ωᵢ′      (the columns of J: doc/inverse-kinematics.md (eq. 22))
//!
//! and the body twist (the (v, ω) of dispkin::Twist, tool coordinates) is (Rᵀ v, Rᵀ ω).
//!
//! One pass over the joints gives the pose with every axis on the way; the rotations are unit
//! quaternions (one sincos of a half angle per joint). These are the only forward kinematics of
//! the serial plugin: SerialArm::forward, jacobian and body_jacobian, the PTP sampling, the
//! analytic IK's checks and the Newton refinement all call them. noexcept and allocation-free:
//! q and q̇ point to chain.dof() values, a Jacobian has chain.dof() columns.
#pragma once

#include <Eigen/Core>

#include "dispkin/pose.hpp"
#include "dispkin/serial/revolute_chain.hpp"

namespace dispkin {
namespace serial {

//! A 6 × n Jacobian: rows (v, ω), one column per joint.
using ChainJacobianRef = Eigen::Ref<Eigen::Matrix<double, 6, Eigen::Dynamic>>;

//! The tool pose T(q).
Posed chain_pose(const RevoluteChain& chain, const double* q) noexcept;

//! The tool pose T(q) and the body twist of the joint velocities q̇; with `axis_points`
//! (chain.dof() of them) also the points pᵢ′ of the axes at q.
void chain_pose_and_twist(const RevoluteChain& chain, const double* q, const double* qd, Posed& pose,
                          Twistd& body_twist, Eigen::Vector3d* axis_points = nullptr) noexcept;

//! J(q), the geometric Jacobian: (v, ω) = J q̇ with v the velocity of the tool origin and ω the
//! angular velocity, both in base coordinates (KDL's convention). Returns T(q).
Posed chain_jacobian(const RevoluteChain& chain, const double* q, ChainJacobianRef jacobian) noexcept;

//! J_b(q) = diag(Rᵀ, Rᵀ) J(q), the body Jacobian: the same twist in tool coordinates. Returns T(q).
Posed chain_body_jacobian(const RevoluteChain& chain, const double* q, ChainJacobianRef jacobian) noexcept;

//! J̇_b(q, q̇) q̇: the part of the tool's body acceleration ξ̇_b = J_b q̈ + J̇_b q̇ that the joint
//! velocities alone give, from the body Jacobian J_b(q) (chain_body_jacobian) and q̇. Column i of
//! J_b moves with the joints before it, dJ_b,i/dt = [Σ_{j<i} J_b,j q̇_j, J_b,i] (a Lie bracket of
//! twists), so no second pass over the chain is needed (doc/retiming.md (eq. 26)).
Twistd chain_velocity_product(const Eigen::Ref<const Eigen::Matrix<double, 6, Eigen::Dynamic>>& body_jacobian,
                              const double* qd) noexcept;

}  // namespace serial
}  // namespace dispkin
