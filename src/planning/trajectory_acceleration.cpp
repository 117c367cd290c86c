// The acceleration of a trajectory's tool (trajectory_acceleration.hpp, doc/planning.md §12, eqs. 38–39).
#include "dispkin/planning/trajectory_acceleration.hpp"

#include <algorithm>
#include <cmath>
#include <variant>

namespace dispkin {

namespace {

// A straight section. Decoupled: the pivot moves at the constant Δc (world) and the body turns
// at the constant ω_b, so with Rᵀ' = −[ω_b]ₓ Rᵀ: v_b = Rᵀ Δc − ω_b × p gives v_b′ = −ω_b × (Rᵀ Δc).
// Screw: the twist is constant.
Twistd twist_rate(const LinSection& lin, double tau) noexcept {
  if (lin.interpolation == Interpolation::screw) return Twistd();
  const Twistd xi = lin.twist(tau);
  const Eigen::Vector3d along = xi.linear + xi.angular.cross(lin.pivot);  // Rᵀ Δc
  return Twistd(-xi.angular.cross(along), Eigen::Vector3d::Zero());
}

// An arc: the orientation turns about a fixed world axis at a constant rate, so ω_b′ = 0; the
// pivot turns about the normal, c̈ = φ n × ċ, so v_b′ = −ω_b × (Rᵀ ċ) + Rᵀ c̈.
Twistd twist_rate(const ArcSection& arc, double tau) noexcept {
  const Posed at = arc.pose(tau);
  const Eigen::Vector3d c = at * arc.pivot;
  const Eigen::Vector3d c_dot = arc.angle * arc.normal.cross(c - arc.center);
  const Eigen::Vector3d c_ddot = arc.angle * arc.normal.cross(c_dot);
  const Eigen::Quaterniond to_body = at.quaternion().conjugate();
  const Eigen::Vector3d omega = to_body * (arc.rotation_angle * arc.rotation_axis);
  return Twistd(-omega.cross(to_body * c_dot) + to_body * c_ddot, Eigen::Vector3d::Zero());
}

// A pose curve R₀ exp(φ(v)), c(v), v = v0 + h τ. Per unit v, ω = J_r(φ) φ′ and
//   ω′ = J_r(φ) φ″ + (dJ_r/dv) φ′ = J_r φ″ − α̇ φ × φ′ + β̇ φ × (φ × φ′) + β φ′ × (φ × φ′)
// with α̇ = α′(θ) θ′, β̇ = β′(θ) θ′, θ′ = φ·φ′/θ (the [φ′]ₓ φ′ terms vanish). Per unit τ:
// ω_b = h ω, ω_b′ = h² ω′; v_b = Rᵀ h c′ − ω_b × p gives v_b′ = −ω_b × (Rᵀ h c′) + Rᵀ h² c″ − ω_b′ × p.
Twistd twist_rate(const CurveSection& curve, double tau) noexcept {
  const double h = curve.span(), v = curve.v0 + tau * h;
  const Eigen::Vector3d phi = curve.rotation.value(v), phi_1 = curve.rotation.first(v),
                        phi_2 = curve.rotation.second(v);
  const Eigen::Vector3d omega_rate = right_jacobian_times(phi, phi_2) + detail::right_jacobian_rate_times(phi, phi_1);
  Posed at;
  Twistd xi;
  curve.at(tau, at, xi);
  const Eigen::Quaterniond to_body = at.quaternion().conjugate();
  const Eigen::Vector3d angular_rate = h * h * omega_rate;
  const Eigen::Vector3d linear_rate = -xi.angular.cross(to_body * (h * curve.position.first(v))) +
                                      to_body * (h * h * curve.position.second(v)) - angular_rate.cross(curve.pivot);
  return Twistd(linear_rate, angular_rate);
}

// A nested-SLERP blend: its own exact rate (doc/planning.md eq. 20).
Twistd twist_rate(const SlerpBlendSection& blend, double tau) noexcept { return blend.twist_rate(tau); }

}  // namespace

Twistd section_twist_rate(const Section& section, double tau) noexcept {
  return std::visit([tau](const auto& s) { return twist_rate(s, tau); }, section);
}

Twistd section_twist_rate(const SampledPath& path, std::size_t k, double tau) noexcept {
  const SectionSource part = path.part(k);
  const double h = part.tau_end - part.tau_start;
  return section_twist_rate(path.whole_sections()[part.section], part.tau_start + tau * h) * (h * h);
}

Twistd body_acceleration(const Trajectory& trajectory, double t) noexcept {
  const TimeLaw& law = trajectory.time_law();
  if (law.size() == 0) return Twistd();
  if (!(t > 0.0)) t = 0.0;
  std::size_t piece = law.size();  // no hint: binary search
  const ProfileState state = law.state_at(t, piece);
  const SampledPath& path = trajectory.path();
  const std::size_t k = path.section_at(state.s, path.section_count());
  const double inverse_length = path.inverse_length(k);
  const double tau = std::clamp((state.s - path.section_start(k)) * inverse_length, 0.0, 1.0);
  const double rate = state.v * inverse_length;  // dτ/dt
  Posed pose;
  Twistd xi;
  path.section_state_at(k, tau, pose, xi);
  const Twistd xi_rate = section_twist_rate(path, k, tau);
  return Twistd(xi_rate.linear * (rate * rate) + xi.linear * (state.a * inverse_length),
                xi_rate.angular * (rate * rate) + xi.angular * (state.a * inverse_length));
}

}  // namespace dispkin
