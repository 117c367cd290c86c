//! Blend sections whose orientation follows the nested SLERP of the Mamezou trajectory article
//! (Ishii, "Algorithm 2 for Robot Manipulator Control", section "Fitting Posture"; doc/planning.md
//! §6.1, doc/planning.md eqs. 17–23): with q₁, q_m, q₂ the orientations at the two sub-points and at the corner,
//!   q(v) = Slerp(v, Slerp(v, q₁, q_m), Slerp(v, q_m, q₂)),   v ∈ [0, 1],
//! the quadratic de Casteljau (Bézier) curve on the unit quaternions with control point q_m. The
//! pivot follows the quadratic Bézier curve c₁ → c_m (control) → c₂ over the same v, so that at
//! both ends the twist is twice the neighbouring LIN's (doc/planning.md eq. 18): one blend zone for both.
//!
//! In rotation vectors (body of q₁), a = log(q₁⁻¹ q_m), b = log(q_m⁻¹ q₂):
//!   q(v) = q₁ exp(v a) exp(u(v)),  u = v c(v),  c(v) = log D(v),  D(v) = exp((1 − v) a) exp(v b)  (27)
//! whose angular velocity and its rate come in closed form from the right Jacobian (doc/planning.md eqs. 19–20),
//! and whose bounds over a part [v₀, v₁] follow from |c| ≤ (1 − v) |a| + v |b| (doc/planning.md eqs. 21–23).
#pragma once

#include <algorithm>
#include <cmath>
#include <optional>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "dispkin/disp.hpp"
#include "dispkin/metric_set.hpp"
#include "dispkin/numbers.hpp"
#include "dispkin/path/curve_section.hpp"
#include "dispkin/path/group_factors.hpp"
#include "dispkin/pose.hpp"

namespace dispkin {
namespace detail {

//! J_r(φ)⁻¹ w = w + ½ φ × w + γ(θ) φ × (φ × w), γ = 1/θ² − cot(θ/2)/(2θ) (θ = |φ| < 2π);
//! γ by its series 1/12 + θ²/720 + θ⁴/30240 + θ⁶/1209600 below 0.1 rad, where the closed form
//! cancels (the next term, θ⁸/47900160, is below 10⁻¹⁶ relative there).
inline Eigen::Vector3d right_jacobian_inverse_times(const Eigen::Vector3d& phi, const Eigen::Vector3d& w) noexcept {
  const double theta = phi.norm(), t2 = theta * theta;
  const double gamma = theta < 0.1 ? 1.0 / 12.0 + t2 * (1.0 / 720.0 + t2 * (1.0 / 30240.0 + t2 / 1209600.0))
                                   : 1.0 / t2 - std::cos(0.5 * theta) / (2.0 * theta * std::sin(0.5 * theta));
  const Eigen::Vector3d pw = phi.cross(w);
  return w + 0.5 * pw + gamma * phi.cross(pw);
}

//! The derivatives along φ of the coefficients of J_r(φ) = I − α [φ]ₓ + β [φ]ₓ², divided by θ:
//! α′(θ)/θ and β′(θ)/θ with α = (1 − cos θ)/θ², β = (θ − sin θ)/θ³. Their series below 0.1 rad,
//! where the closed forms cancel (next terms: θ⁶/453600 and θ⁶/3991680).
inline void jacobian_coefficient_rates(double theta, double& alpha_rate, double& beta_rate) noexcept {
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

//! dJ_r(φ)[δ] δ, the rate of J_r(φ(v)) δ along φ′ = δ (doc/planning.md eq. 39; the [δ]ₓ δ terms
//! vanish): −α′ θ′ φ × δ + β′ θ′ φ × (φ × δ) + β δ × (φ × δ), θ θ′ = φ · δ.
inline Eigen::Vector3d right_jacobian_rate_times(const Eigen::Vector3d& phi, const Eigen::Vector3d& delta) noexcept {
  double alpha_rate = 0.0, beta_rate = 0.0;
  const double theta = phi.norm();
  jacobian_coefficient_rates(theta, alpha_rate, beta_rate);
  const double along = phi.dot(delta);  // θ θ′
  const Eigen::Vector3d cross = phi.cross(delta);
  return -alpha_rate * along * cross + beta_rate * along * phi.cross(cross) + coefficient_c(theta) * delta.cross(cross);
}

//! ‖J_r(φ)⁻¹‖ = (θ/2)/sin(θ/2) (J_r is normal; its smallest singular value is 2 sin(θ/2)/θ).
inline double right_jacobian_inverse_norm(double theta) noexcept {
  if (theta < 1e-4) return 1.0 + theta * theta / 24.0;
  return 0.5 * theta / std::sin(0.5 * theta);
}

//! The nested SLERP of doc/planning.md eq. 17 relative to q₁: exp(v a) exp(u(v)), its body angular velocity per
//! unit v (doc/planning.md eq. 19) and, if asked, that velocity's rate (eq. 20).
struct NestedSlerp {
  Eigen::Vector3d a = Eigen::Vector3d::Zero(), b = Eigen::Vector3d::Zero();

  void at(double v, Eigen::Quaterniond& turn, Eigen::Vector3d& omega,
          Eigen::Vector3d* omega_rate = nullptr) const noexcept {
    // D = exp((1 − v) a) exp(v b) and its body angular velocity ω_D = b − exp(v b)⁻¹ a.
    const Eigen::Quaterniond along_b = quaternion_exp(Eigen::Vector3d(v * b));
    const Eigen::Quaterniond d = quaternion_exp(Eigen::Vector3d((1.0 - v) * a)) * along_b;
    const Eigen::Vector3d c = quaternion_log(d);
    const Eigen::Vector3d a_seen = along_b.conjugate() * a;
    const Eigen::Vector3d omega_d = b - a_seen;
    const Eigen::Vector3d c_dot = right_jacobian_inverse_times(c, omega_d);  // J_r(c) ċ = ω_D
    // u = v c, u̇ = c + v ċ; E₂ = exp(u) turns a into the body: ω = E₂⁻¹ a + J_r(u) u̇.
    const Eigen::Vector3d u = v * c, u_dot = c + v * c_dot;
    Eigen::Quaterniond e2;
    Eigen::Vector3d omega_2;
    exp_and_right_jacobian(u, u_dot, e2, omega_2);
    turn = quaternion_exp(Eigen::Vector3d(v * a)) * e2;
    const Eigen::Vector3d a_body = e2.conjugate() * a;
    omega = a_body + omega_2;
    if (!omega_rate) return;
    // ω̇_D = b × (exp(v b)⁻¹ a); c̈ = J_r(c)⁻¹ (ω̇_D − dJ_r(c)[ċ] ċ); ü = 2ċ + v c̈;
    // ω̇ = (E₂⁻¹ a) × (J_r(u) u̇) + dJ_r(u)[u̇] u̇ + J_r(u) ü.
    const Eigen::Vector3d omega_d_rate = b.cross(a_seen);
    const Eigen::Vector3d c_ddot = right_jacobian_inverse_times(c, omega_d_rate - right_jacobian_rate_times(c, c_dot));
    const Eigen::Vector3d u_ddot = 2.0 * c_dot + v * c_ddot;
    *omega_rate = a_body.cross(omega_2) + right_jacobian_rate_times(u, u_dot) + right_jacobian_times(u, u_ddot);
  }

  //! Bounds over v ∈ [v0, v1] (0 ≤ v0 ≤ v1 ≤ 1) of |ω| and |ω̇| per unit v (doc/planning.md eqs. 21–23).
  void bounds(double v0, double v1, double& omega_bound, double& omega_rate_bound) const noexcept {
    const double alpha = a.norm(), beta = b.norm(), twist = a.cross(b).norm();
    // |c| ≤ (1 − v) α + v β (the triangle inequality on SO(3)), at most π; largest at an end.
    const double c_max = std::min(pi, std::max((1.0 - v0) * alpha + v0 * beta, (1.0 - v1) * alpha + v1 * beta));
    // ω_D = b − R a, R = exp(−v[b]) turns about b: |a − R a| ≤ v |a × b| and |ω̇_D| = |b × R a| = |a × b|
    // (doc/planning.md eq. 21).
    const double omega_d = std::min(alpha + beta, (b - a).norm() + v1 * twist);
    const double k = right_jacobian_inverse_norm(c_max);
    const double c_dot = k * omega_d;
    // |dJ_r(φ)[δ] δ| ≤ |φ × δ| |δ| j(θ) (doc/planning.md eq. 22), with |c × ċ| ≤ |c| |ċ|.
    const double c_ddot = k * (twist + c_max * c_dot * c_dot * jacobian_rate_along_bound(c_max));
    // u = v c: u̇ = c + v ċ, ü = 2ċ + v c̈, u × u̇ = v² c × ċ (doc/planning.md eq. 23).
    const double u_dot = c_max + v1 * c_dot, u_ddot = 2.0 * c_dot + v1 * c_ddot;
    const double u_cross = v1 * v1 * c_max * c_dot;
    omega_bound = alpha + u_dot;
    omega_rate_bound = alpha * u_dot + u_cross * u_dot * jacobian_rate_along_bound(v1 * c_max) + u_ddot;
  }

  //! j(θ) = θ/12 + θ²/60 + 1/6 ≥ |α′(θ)| + θ |β′(θ)| + β(θ) for θ < 3.8 (alternating series whose
  //! first terms bound them: α′ = −θ/12 + …, β′ = −θ/60 + …, β = 1/6 − …), so that
  //! |dJ_r(φ)[δ] δ| ≤ |φ × δ| |δ| j(θ) (doc/planning.md eq. 22).
  static double jacobian_rate_along_bound(double theta) noexcept {
    return theta / 12.0 + theta * theta / 60.0 + 1.0 / 6.0;
  }
};

}  // namespace detail

//! One section of a nested-SLERP blend: the part v ∈ [v0, v1] of the blend's curve, run as
//! τ = (v − v0)/(v1 − v0) goes over [0, 1]. Built by Path::then with OrientationBlend::nested_slerp.
struct SlerpBlendSection {
  Eigen::Quaterniond q_start = Eigen::Quaterniond::Identity();  //!< q₁, the orientation at v = 0
  Eigen::Vector3d a = Eigen::Vector3d::Zero();  //!< log(q₁⁻¹ q_m): q₁ to the corner (body of q₁)
  Eigen::Vector3d b = Eigen::Vector3d::Zero();  //!< log(q_m⁻¹ q₂): the corner to q₂ (body of q_m)
  Cubic3 position;                              //!< c(v), world: the quadratic Bézier (a₃ = 0)
  //! The part of the blend's curve, 0 ≤ v0 < v1 ≤ 1.
  //!@{
  double v0 = 0.0, v1 = 1.0;
  //!@}
  Eigen::Vector3d pivot = Eigen::Vector3d::Zero();  //!< body coordinates of the point on c(v)

  //! v1 − v0: dv/dτ.
  double span() const noexcept { return v1 - v0; }

  //! Whether `other` is a part of the same blend: the same coefficients, bit for bit.
  bool same_blend(const SlerpBlendSection& other) const noexcept {
    return detail::same_bits(q_start.coeffs().data(), other.q_start.coeffs().data(), 4) &&
           detail::same_bits(a.data(), other.a.data(), 3) && detail::same_bits(b.data(), other.b.data(), 3) &&
           detail::same_bits(position.a[0].data(), other.position.a[0].data(), 12) &&
           detail::same_bits(pivot.data(), other.pivot.data(), 3);
  }

  //! The pose at τ ∈ [0, 1].
  Posed pose(double tau) const noexcept {
    Posed p;
    Twistd xi;
    at(tau, p, xi);
    return p;
  }

  //! Body twist per unit τ: ω_b = h ω(v), v_b = Rᵀ h c′ − ω_b × p (h = v1 − v0).
  Twistd twist(double tau) const noexcept {
    Posed p;
    Twistd xi;
    at(tau, p, xi);
    return xi;
  }

  //! Pose and body twist per unit τ at τ. noexcept, allocation-free.
  void at(double tau, Posed& pose_out, Twistd& twist_out) const noexcept {
    const double h = span();
    at_curve(v0 + tau * h, h, pose_out, twist_out);
  }

  //! Pose and body twist per unit τ at curve parameter v, for a part of the curve of span
  //! h = dv/dτ (SectionMotions samples every part of a blend from the one section).
  void at_curve(double v, double h, Posed& pose_out, Twistd& twist_out) const noexcept {
    Eigen::Quaterniond turn;
    Eigen::Vector3d omega;
    detail::NestedSlerp{a, b}.at(v, turn, omega);
    const Eigen::Quaterniond q = q_start * turn;
    pose_out = Posed::unchecked(q, position.value(v) - q * pivot);
    omega *= h;
    twist_out = Twistd(q.conjugate() * (h * position.first(v)) - omega.cross(pivot), omega);
  }

  //! The body twist's rate per unit τ² (doc/planning.md eq. 38): ω_b′ = h² ω′ (eq. 20),
  //! v_b′ = −ω_b × (Rᵀ h c′) + Rᵀ h² c″ − ω_b′ × p.
  Twistd twist_rate(double tau) const noexcept {
    const double h = span(), v = v0 + tau * h;
    Eigen::Quaterniond turn;
    Eigen::Vector3d omega, omega_rate;
    detail::NestedSlerp{a, b}.at(v, turn, omega, &omega_rate);
    const Eigen::Quaterniond to_body = (q_start * turn).conjugate();
    const Eigen::Vector3d angular = h * omega, angular_rate = h * h * omega_rate;
    return Twistd(-angular.cross(to_body * (h * position.first(v))) + to_body * (h * h * position.second(v)) -
                      angular_rate.cross(pivot),
                  angular_rate);
  }

  //! Bounds over the section of |ċ|, |c̈|, |ω| and |ω̇| per unit τ: the pivot's from the
  //! polynomial (as CurveSection), the orientation's from doc/planning.md eqs. 21–23, |ω| also at most its
  //! value at the middle plus half a section at the rate bound.
  MotionBounds motion_bounds() const noexcept {
    const double h = span(), m = 0.5 * (v0 + v1);
    const detail::DerivativeBounds dc = detail::derivative_bounds(position, m, 0.5 * h);
    double omega = 0.0, omega_rate = 0.0;
    detail::NestedSlerp{a, b}.bounds(std::clamp(v0, 0.0, 1.0), std::clamp(v1, 0.0, 1.0), omega, omega_rate);
    Eigen::Quaterniond turn;
    Eigen::Vector3d omega_middle;
    detail::NestedSlerp{a, b}.at(m, turn, omega_middle);
    omega = std::min(omega, omega_middle.norm() + 0.5 * h * omega_rate);
    return {h * dc.first, h * h * dc.second, h * omega, h * h * omega_rate};
  }

  //! An upper bound of the speed of every object of the set per unit τ: each group's exact
  //! speed at the middle plus half the bound of the rate at which it can change (as
  //! CurveSection::length, doc/section-length.md eqs. 23–24).
  double length(const MetricSetd& set, std::optional<double> system_velocity) const {
    set.require_well_formed();
    GroupFactors factors(set, system_velocity);
    factors.use_pivot(pivot);
    return bounds(factors).length;
  }

  //! A bound of the acceleration of every object of the set per unit τ² (unweighted).
  double acceleration_bound(const MetricSetd& set) const {
    const MotionBounds motion = motion_bounds();
    const Eigen::Vector3d pivot_middle = position.value(0.5 * (v0 + v1));
    double best = 0.0;
    for (const auto& g : set.groups())
      best = std::max(best, detail::group_acceleration_bound(g, pivot, pivot_middle, motion));
    return best;
  }

  //! length() and acceleration_bound() together; `factors` of the same set, with
  //! use_pivot(pivot) called.
  //! Exact peak to 0.1 % (doc/section-length.md eqs. 25–27), as CurveSection::bounds.
  SectionBounds bounds(const GroupFactors& factors) const { return refined(factors).bounds; }

  //! bounds() with how the speed and the acceleration bound vary along the section.
  RefinedBounds refined(const GroupFactors& factors) const {
    SlerpBlendSection part = *this;
    const double h = span();
    return detail::refined_bounds([&](double t0, double t1, double& middle_speed) {
      part.v0 = v0 + t0 * h;
      part.v1 = t1 >= 1.0 ? v1 : v0 + t1 * h;
      return part.piece_bounds(factors, middle_speed);
    });
  }

  //! The bounds of the section as one piece (doc/section-length.md eq. 24), with its weighted middle speed.
  SectionBounds piece_bounds(const GroupFactors& factors, double& middle_speed) const {
    const MotionBounds motion = motion_bounds();
    Posed middle;
    Twistd twist_middle;
    at(0.5, middle, twist_middle);
    return detail::bounds_from_middle(factors, middle, twist_middle, position.value(0.5 * (v0 + v1)), motion,
                                      middle_speed);
  }
};

}  // namespace dispkin
