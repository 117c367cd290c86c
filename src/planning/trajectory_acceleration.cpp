// The acceleration of a trajectory's tool (trajectory_acceleration.hpp, doc/planning.md §12, eqs. 25–26).
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

// The derivatives along φ of the coefficients of J_r(φ) = I − α [φ]ₓ + β [φ]ₓ², divided by θ:
// α′(θ)/θ and β′(θ)/θ with α = (1 − cos θ)/θ², β = (θ − sin θ)/θ³. Their series below 0.1 rad,
// where the closed forms cancel (next terms: θ⁶/453600 and θ⁶/3991680).
void jacobian_coefficient_rates(double theta, double& alpha_rate, double& beta_rate) noexcept {
  const double t2 = theta * theta;
  if (theta < 0.1) {
    alpha_rate = -1.0 / 12.0 + t2 * (1.0 / 180.0 - t2 / 6720.0);
    beta_rate = -1.0 / 60.0 + t2 * (1.0 / 1260.0 - t2 / 60480.0);
    return;
  }
  const double s = std::sin(theta), c = std::cos(theta), t4 = t2 * t2;
  alpha_rate = (theta * s - 2.0 * (1.0 - c)) / t4;
  beta_rate = (3.0 * s - 2.0 * theta - theta * c) / (t4 * theta);
}

// A pose curve R₀ exp(φ(v)), c(v), v = v0 + h τ. Per unit v, ω = J_r(φ) φ′ and
//   ω′ = J_r(φ) φ″ + (dJ_r/dv) φ′ = J_r φ″ − α̇ φ × φ′ + β̇ φ × (φ × φ′) + β φ′ × (φ × φ′)
// with α̇ = α′(θ) θ′, β̇ = β′(θ) θ′, θ′ = φ·φ′/θ (the [φ′]ₓ φ′ terms vanish). Per unit τ:
// ω_b = h ω, ω_b′ = h² ω′; v_b = Rᵀ h c′ − ω_b × p gives v_b′ = −ω_b × (Rᵀ h c′) + Rᵀ h² c″ − ω_b′ × p.
Twistd twist_rate(const CurveSection& curve, double tau) noexcept {
  const double h = curve.span(), v = curve.v0 + tau * h;
  const Eigen::Vector3d phi = curve.rotation.value(v), phi_1 = curve.rotation.first(v), phi_2 = curve.rotation.second(v);
  const double theta = phi.norm();
  double alpha_rate = 0.0, beta_rate = 0.0;
  jacobian_coefficient_rates(theta, alpha_rate, beta_rate);
  const double beta = detail::coefficient_c(theta);
  const double along = phi.dot(phi_1);  // θ θ′
  const Eigen::Vector3d cross = phi.cross(phi_1);
  const Eigen::Vector3d omega_rate = right_jacobian_times(phi, phi_2) - alpha_rate * along * cross +
                                     beta_rate * along * phi.cross(cross) + beta * phi_1.cross(cross);
  Posed at;
  Twistd xi;
  curve.at(tau, at, xi);
  const Eigen::Quaterniond to_body = at.quaternion().conjugate();
  const Eigen::Vector3d angular_rate = h * h * omega_rate;
  const Eigen::Vector3d linear_rate =
      -xi.angular.cross(to_body * (h * curve.position.first(v))) + to_body * (h * h * curve.position.second(v)) -
      angular_rate.cross(curve.pivot);
  return Twistd(linear_rate, angular_rate);
}

}  // namespace

Twistd section_twist_rate(const Section& section, double tau) noexcept {
  return std::visit([tau](const auto& s) { return twist_rate(s, tau); }, section);
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
  const Section& section = path.sections()[k];
  const double rate = state.v * inverse_length;  // dτ/dt
  const Twistd xi = section_twist(section, tau), xi_rate = section_twist_rate(section, tau);
  return Twistd(xi_rate.linear * (rate * rate) + xi.linear * (state.a * inverse_length),
                xi_rate.angular * (rate * rate) + xi.angular * (state.a * inverse_length));
}

}  // namespace dispkin
