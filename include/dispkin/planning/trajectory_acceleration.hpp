//! The acceleration of a trajectory's tool: the time derivative of its body twist, from the
//! path's second derivative (doc/planning.md §12, eqs. 38–39). With ξ_τ the body twist per unit τ of section
//! k, L_k its length and τ = (s − s_k)/L_k, the body twist is ξ = ξ_τ ṡ/L_k, so
//!   dξ/dt = ξ′_τ (ṡ/L_k)² + ξ_τ s̈/L_k,   ξ′_τ = dξ_τ/dτ.
//! Allocation-free and noexcept, like sampling; not on the control loop's path (it visits the
//! section's definition instead of its sampling form).
#pragma once

#include "dispkin/path/path.hpp"
#include "dispkin/planning/trajectory.hpp"
#include "dispkin/pose.hpp"

namespace dispkin {

//! dξ_τ/dτ: the rate of change of the body twist per unit τ of `section` at τ (per τ²).
Twistd section_twist_rate(const Section& section, double tau) noexcept;

//! The same for section k of a sampled path, a part τ ∈ [t₀, t₁] of one of its whole sections:
//! the whole section's rate at u = t₀ + τ h times h² (h = t₁ − t₀, du/dτ; doc/planning.md eq. 40).
Twistd section_twist_rate(const SampledPath& path, std::size_t k, double tau) noexcept;

//! d/dt of the body twist (v, ω) at time t (clamped to [0, duration()]): (v̇, ω̇) in body
//! coordinates, m/s² and rad/s². The time derivative of Trajectory::sample(t).body_twist.
Twistd body_acceleration(const Trajectory& trajectory, double t) noexcept;

}  // namespace dispkin
