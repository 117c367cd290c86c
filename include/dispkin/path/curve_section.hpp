//! Curved sections: a cubic pose curve (the pieces of SPLINE moves and of blends at via
//! points), cut into sections whose DISP length is a rigorous, tight upper bound.
//!
//! The curve runs over v ∈ [0, 1]:
//!   pivot        c(v) = c₀ + c₁ v + c₂ v² + c₃ v³                        (world)
//!   orientation  R(v) = R₀ · exp([φ(v)]ₓ),  φ(v) = φ₀ + φ₁ v + φ₂ v² + φ₃ v³  (body of R₀)
//! Its body angular velocity per unit v is J_r(φ) φ′ (J_r the right Jacobian of SO(3)), so the
//! orientation is as smooth as the polynomial φ: C¹ pieces join with continuous angular
//! velocity when their end derivatives are matched through J_r (see spline.cpp, blend.cpp).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <optional>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "dispkin/disp.hpp"
#include "dispkin/metric_set.hpp"
#include "dispkin/path/group_factors.hpp"
#include "dispkin/path/refined_bounds.hpp"
#include "dispkin/pose.hpp"

namespace dispkin {

//! A cubic polynomial in v with vector coefficients: p(v) = Σ aᵢ vⁱ.
struct Cubic3 {
  //! The coefficients a₀ … a₃.
  std::array<Eigen::Vector3d, 4> a{Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(),
                                   Eigen::Vector3d::Zero()};

  Eigen::Vector3d value(double v) const noexcept { return a[0] + v * (a[1] + v * (a[2] + v * a[3])); }  //!< p(v)
  Eigen::Vector3d first(double v) const noexcept { return a[1] + v * (2.0 * a[2] + 3.0 * v * a[3]); }   //!< p′(v)
  Eigen::Vector3d second(double v) const noexcept { return 2.0 * a[2] + 6.0 * v * a[3]; }               //!< p″(v)
  Eigen::Vector3d third() const noexcept { return 6.0 * a[3]; }  //!< p‴, constant

  //! The cubic Hermite polynomial with p(0) = p0, p′(0) = m0, p(1) = p1, p′(1) = m1.
  static Cubic3 hermite(const Eigen::Vector3d& p0, const Eigen::Vector3d& m0, const Eigen::Vector3d& p1,
                        const Eigen::Vector3d& m1) noexcept {
    Cubic3 c;
    c.a[0] = p0;
    c.a[1] = m0;
    c.a[2] = 3.0 * (p1 - p0) - 2.0 * m0 - m1;
    c.a[3] = 2.0 * (p0 - p1) + m0 + m1;
    return c;
  }
};

//! J_r(φ) u: the right Jacobian of SO(3) at φ applied to u, J_r = I − b[φ]ₓ + c[φ]ₓ² with
//! b = (1 − cos θ)/θ², c = (θ − sin θ)/θ³. For R(v) = R₀ exp(φ(v)), Rᵀ Ṙ = [J_r(φ) φ̇]ₓ.
inline Eigen::Vector3d right_jacobian_times(const Eigen::Vector3d& phi, const Eigen::Vector3d& u) noexcept {
  const double theta = phi.norm();
  const Eigen::Vector3d pu = phi.cross(u);
  return u - detail::coefficient_b(theta) * pu + detail::coefficient_c(theta) * phi.cross(pu);
}

//! The 3 × 3 matrix J_r(φ).
inline Eigen::Matrix3d right_jacobian(const Eigen::Vector3d& phi) noexcept;

namespace detail {

//! exp(φ) as a unit quaternion and J_r(φ) u, from one sine/cosine pair of θ/2 (θ = |φ|):
//! sin θ = 2 sin(θ/2) cos(θ/2) serves J_r's C(θ). The series branches are those of
//! quaternion_exp, coefficient_b and coefficient_c.
inline void exp_and_right_jacobian(const Eigen::Vector3d& phi, const Eigen::Vector3d& u, Eigen::Quaterniond& exp_phi,
                                   Eigen::Vector3d& jacobian_u) noexcept {
  const double theta = phi.norm();
  const double t2 = theta * theta;
  const double s = std::sin(0.5 * theta), c = std::cos(0.5 * theta);
  const double inverse = 1.0 / theta;  // one division for both closed forms
  const double half_sine = theta < 1e-4 ? 0.5 - t2 / 48.0 : s * inverse;
  const double b = theta < 1e-4 ? 0.5 - t2 / 24.0 : 2.0 * half_sine * half_sine;
  const double cc = theta < 1e-2 ? 1.0 / 6.0 - t2 / 120.0 + t2 * t2 / 5040.0 - t2 * t2 * t2 / 362880.0
                                 : (theta - 2.0 * s * c) * (inverse * inverse * inverse);
  exp_phi = Eigen::Quaterniond(c, half_sine * phi.x(), half_sine * phi.y(), half_sine * phi.z());
  const Eigen::Vector3d pu = phi.cross(u);
  jacobian_u = u - b * pu + cc * phi.cross(pu);
}

}  // namespace detail

//! One section of a cubic pose curve: the part v ∈ [v0, v1], run as τ = (v − v0)/(v1 − v0)
//! goes over [0, 1].
struct CurveSection {
  Eigen::Quaterniond q0 = Eigen::Quaterniond::Identity();  //!< R₀
  Cubic3 position;                                         //!< c(v), world
  Cubic3 rotation;                                         //!< φ(v), body of R₀
  //! The part of the curve, 0 ≤ v0 < v1 ≤ 1.
  //!@{
  double v0 = 0.0, v1 = 1.0;
  //!@}
  Eigen::Vector3d pivot = Eigen::Vector3d::Zero();  //!< body coordinates of the point on c(v)

  //! v1 − v0: dv/dτ.
  double span() const noexcept { return v1 - v0; }

  //! The pose at τ ∈ [0, 1].
  Posed pose(double tau) const noexcept {
    Posed p;
    Twistd xi;
    at(tau, p, xi);
    return p;
  }

  //! Body twist per unit τ: ω_b = h J_r(φ) φ′, v_b = Rᵀ h c′ − ω_b × p (h = v1 − v0).
  Twistd twist(double tau) const noexcept {
    Posed p;
    Twistd xi;
    at(tau, p, xi);
    return xi;
  }

  //! Pose and body twist per unit τ at τ, sharing one evaluation of the polynomials and one
  //! sine/cosine pair between exp and J_r.
  void at(double tau, Posed& pose_out, Twistd& twist_out) const noexcept {
    const double v = v0 + tau * span();
    pose_and_twist(position.value(v), position.first(v), rotation.value(v), rotation.first(v), pose_out, twist_out);
  }

  //! An upper bound of the speed of every object of the set per unit τ (never below the
  //! exact maximum) and within 0.1 % of it: the exact speeds at the ends of N equal pieces, each
  //! piece raised by how far a velocity can bend between its ends under a bound of every
  //! object's jerk, from bounds of the pivot's motion and of the angular velocity and its rates
  //! (|ω| ≤ |φ̇| as ‖J_r‖ ≤ 1, the rates of J_r bounded by the series g′, g″)
  //! (doc/section-length.md eqs. 19–27).
  double length(const MetricSetd& set, std::optional<double> system_velocity) const;

  //! A bound of the acceleration of every object of the set per unit τ² (unweighted): with
  //! L the section's length, a point accelerates at most (ṡ/L)² times this from the path's
  //! curvature alone.
  double acceleration_bound(const MetricSetd& set) const;

  //! Bounds over the section of |ċ|, |c̈|, |ω| ≤ |φ̇| and |ω̇| ≤ |φ̈| + g′(θ)|φ̇|², per unit τ.
  MotionBounds motion_bounds() const;

  //! length() and acceleration_bound() together, sharing the motion bounds and the middle
  //! pose; `factors` must be of the same set, with use_pivot(pivot) called (the planner's way:
  //! the groups' weights and reaches are per path).
  //! Exact peak to 0.1 %: the bounds of equal pieces of the section, each from the exact
  //! speeds at its ends and its jerk bound (doc/section-length.md eqs. 25–27).
  SectionBounds bounds(const GroupFactors& factors) const;

  //! bounds() with how the speed and the acceleration bound vary along the section: the exact
  //! speeds at the ends of N equal pieces and each piece's jerk bound (doc/section-length.md eqs. 25–27).
  RefinedBounds refined(const GroupFactors& factors) const;

  //! refined() of the part τ ∈ [t0, t1] (cut as detail::cut_parameter), per unit τ of the part,
  //! given the weighted speeds w0 = weighted_speed(factors, t0) and w1 = weighted_speed(factors, t1):
  //! parts that meet share their ends' speeds.
  //! With `acceleration_precision` > 0 the acceleration bound is refined to that share too.
  RefinedBounds refined_part(const GroupFactors& factors, double t0, double t1, double w0, double w1,
                             double acceleration_precision = 0.0) const;

  //! The weighted fastest speed of the set at τ per unit τ, max_g w_g V_g(τ) (doc/section-length.md eq. 26).
  double weighted_speed(const GroupFactors& factors, double tau) const;

  //! The acceleration, jerk, |ω| and |ω̇| bounds of the section as one piece (doc/section-length.md
  //! eqs. 19, 22 and 25).
  PieceRates piece_rates(const GroupFactors& factors) const;

  //! The bounds of the section as one piece (doc/section-length.md eq. 24), with its weighted middle speed.
  SectionBounds piece_bounds(const GroupFactors& factors, double& middle_speed) const;

 private:
  // Pose and body twist per unit τ where the curve has c, c′, φ, φ′ (per unit v).
  void pose_and_twist(const Eigen::Vector3d& c, const Eigen::Vector3d& c_slope, const Eigen::Vector3d& phi,
                      const Eigen::Vector3d& phi_slope, Posed& pose_out, Twistd& twist_out) const noexcept {
    const double h = span();
    Eigen::Quaterniond turn;
    Eigen::Vector3d omega;
    detail::exp_and_right_jacobian(phi, phi_slope, turn, omega);
    omega *= h;
    // A product of unit quaternions: unit to rounding without normalising.
    const Eigen::Quaterniond q = q0 * turn;
    pose_out = Posed::unchecked(q, c - q * pivot);
    twist_out = Twistd(q.conjugate() * (h * c_slope) - omega.cross(pivot), omega);
  }
};

// --- definitions (inline: the hexapod plugin uses curved sections without the umbrella) ---
namespace detail {

// g′(θ) = (θeᶿ − eᶿ + 1)/θ² = Σₖ≥₁ k θᵏ⁻¹/(k + 1)!: with ‖[φ]ₓᵏ‖ = θᵏ, the series of J_r
// gives ‖dJ_r(φ)[u]‖ ≤ g′(θ)|u|. Its own series below 10⁻³ (the closed form cancels).
inline double jacobian_rate_bound(double theta) {
  if (theta < 1e-3) return 0.5 + theta / 3.0 + theta * theta / 8.0;
  const double e = std::exp(theta);  // once: with errno semantics the compiler calls exp twice
  return (theta * e - e + 1.0) / (theta * theta);
}

// g′(θ) as jacobian_rate_bound and g″(θ) = Σₖ≥₂ k(k − 1) θᵏ⁻²/(k + 1)! = (θ²eᶿ − 2θeᶿ + 2eᶿ − 2)/θ³,
// which bounds ‖d²J_r(φ)[u, u]‖ / |u|² (doc/section-length.md eq. 25), from one exponential. Below
// 10⁻² both by their series (the closed forms cancel), each tail raised to an upper bound: past
// θ³ the tail of g′ is θ⁴/144 + θ⁵/840 + … ≤ θ⁴/140, that of g″ θ⁴/168 + θ⁵/960 + … ≤ θ⁴/160.
inline void jacobian_rate_bounds(double theta, double& first, double& second) {
  if (theta < 1e-2) {
    first = 0.5 + theta * (1.0 / 3.0 + theta * (1.0 / 8.0 + theta * (1.0 / 30.0 + theta / 140.0)));
    second = 1.0 / 3.0 + theta * (0.25 + theta * (0.1 + theta * (1.0 / 36.0 + theta / 160.0)));
    return;
  }
  const double e = std::exp(theta), t2 = theta * theta;
  first = (theta * e - e + 1.0) / t2;
  second = (e * (t2 - 2.0 * theta + 2.0) - 2.0) / (t2 * theta);
}

// Bounds of |p′| and |p″| of a cubic over [m − δ, m + δ], by Taylor at the middle m (exact
// expansion: p′ is quadratic, p″ linear).
struct DerivativeBounds {
  double first, second;
};

// A cubic's value and derivatives at one parameter, evaluated once for all that needs them.
struct CubicAt {
  Eigen::Vector3d value, first, second;
  double third_norm;
};
inline CubicAt cubic_at(const Cubic3& p, double v) noexcept {
  return {p.value(v), p.first(v), p.second(v), p.third().norm()};
}

inline DerivativeBounds derivative_bounds(const CubicAt& at, double delta) noexcept {
  const double second_mid = at.second.norm();
  return {at.first.norm() + second_mid * delta + 0.5 * at.third_norm * delta * delta,
          second_mid + at.third_norm * delta};
}
inline DerivativeBounds derivative_bounds(const Cubic3& p, double m, double delta) noexcept {
  return derivative_bounds(cubic_at(p, m), delta);
}

// The motion bounds of a section of span h from the curve at its middle (position c, rotation φ).
inline MotionBounds motion_bounds_at_middle(const CubicAt& c, const CubicAt& phi, double h) {
  const double delta = 0.5 * h;
  const DerivativeBounds dc = derivative_bounds(c, delta);
  const DerivativeBounds dphi = derivative_bounds(phi, delta);
  const double theta_max = phi.value.norm() + dphi.first * delta;
  return {h * dc.first, h * h * dc.second, h * dphi.first,
          h * h * (dphi.second + jacobian_rate_bound(theta_max) * dphi.first * dphi.first)};
}

// The motion bounds of a piece of span h from the curve at its middle, with the third
// derivatives: |c⃛| = h³ |c‴| and |ω̈| ≤ h³ (|φ‴| + 3 g′(θ) P₁(φ) P₂(φ) + g″(θ) P₁(φ)³), from
// ω″ = J_r φ‴ + 2 dJ_r[φ′] φ″ + dJ_r[φ″] φ′ + d²J_r[φ′, φ′] φ′ (doc/section-length.md eq. 25).
// `middle` receives the same bounds with the half-span δ taken as 0: the motion at the middle.
inline MotionBounds motion_bounds_with_jerk(const CubicAt& c, const CubicAt& phi, double h, MotionJerkBounds& jerk,
                                            MotionBounds& middle) {
  const double delta = 0.5 * h;
  const DerivativeBounds dc = derivative_bounds(c, delta);
  const DerivativeBounds dphi = derivative_bounds(phi, delta);
  double g1 = 0.0, g2 = 0.0;
  jacobian_rate_bounds(phi.value.norm() + dphi.first * delta, g1, g2);
  const double h2 = h * h, h3 = h2 * h;
  jerk = {h3 * c.third_norm,
          h3 * (phi.third_norm + dphi.first * (3.0 * g1 * dphi.second + g2 * dphi.first * dphi.first))};
  const double phi_first = phi.first.norm();
  middle = {h * c.first.norm(), h2 * c.second.norm(), h * phi_first,
            h2 * (phi.second.norm() + g1 * phi_first * phi_first)};
  return {h * dc.first, h2 * dc.second, h * dphi.first, h2 * (dphi.second + g1 * dphi.first * dphi.first)};
}

}  // namespace detail

inline Eigen::Matrix3d right_jacobian(const Eigen::Vector3d& phi) noexcept {
  const double theta = phi.norm();
  const Eigen::Matrix3d w = detail::hat(phi);
  return Eigen::Matrix3d::Identity() - detail::coefficient_b(theta) * w + detail::coefficient_c(theta) * (w * w);
}

inline double CurveSection::length(const MetricSetd& set, std::optional<double> system_velocity) const {
  set.require_well_formed();
  GroupFactors factors(set, system_velocity);
  factors.use_pivot(pivot);
  return bounds(factors).length;
}

inline SectionBounds CurveSection::piece_bounds(const GroupFactors& factors, double& middle_speed) const {
  // The polynomials at the middle, once: the motion bounds, the middle pose and twist and the
  // pivot's middle position all come from them.
  const double m = 0.5 * (v0 + v1);
  const detail::CubicAt c = detail::cubic_at(position, m), phi = detail::cubic_at(rotation, m);
  const MotionBounds motion = detail::motion_bounds_at_middle(c, phi, span());
  Posed middle;
  Twistd twist_middle;
  pose_and_twist(c.value, c.first, phi.value, phi.first, middle, twist_middle);
  // |ω| = |J_r(φ) φ′| ≤ |φ′| (the right Jacobian's singular values are at most 1).
  return detail::bounds_from_middle(factors, middle, twist_middle, c.value, motion, middle_speed);
}

inline SectionBounds CurveSection::bounds(const GroupFactors& factors) const { return refined(factors).bounds; }

inline PieceRates CurveSection::piece_rates(const GroupFactors& factors) const {
  const double m = 0.5 * (v0 + v1);
  const detail::CubicAt c = detail::cubic_at(position, m), phi = detail::cubic_at(rotation, m);
  MotionJerkBounds jerk{0.0, 0.0};
  MotionBounds middle{0.0, 0.0, 0.0, 0.0};
  const MotionBounds motion = detail::motion_bounds_with_jerk(c, phi, span(), jerk, middle);
  const MetricSetd& set = factors.set();
  PieceRates rates{0.0, 0.0, motion.omega, motion.omega_dot, 0.0};
  for (std::size_t i = 0; i < set.groups().size(); ++i) {
    const GroupRates g = detail::group_rate_bounds(set.groups()[i], factors.reach(i), c.value, motion, jerk);
    rates.acceleration = std::max(rates.acceleration, g.acceleration);
    rates.jerk = std::max(rates.jerk, factors.weight(i) * g.jerk);
    rates.acceleration_middle =
        std::max(rates.acceleration_middle,
                 detail::group_acceleration_bound(set.groups()[i], factors.reach(i), c.value, middle));
  }
  return rates;
}

inline double CurveSection::weighted_speed(const GroupFactors& factors, double tau) const {
  Posed pose;
  Twistd twist;
  at(tau, pose, twist);
  const MetricSetd& set = factors.set();
  double best = 0.0;
  for (std::size_t i = 0; i < set.groups().size(); ++i)
    best = std::max(best, factors.weight(i) * detail::group_max_speed(set.groups()[i], pose, twist));
  return best;
}

inline RefinedBounds CurveSection::refined(const GroupFactors& factors) const {
  return refined_part(factors, 0.0, 1.0, weighted_speed(factors, 0.0), weighted_speed(factors, 1.0));
}

inline RefinedBounds CurveSection::refined_part(const GroupFactors& factors, double t0, double t1, double w0, double w1,
                                                double acceleration_precision) const {
  // The part bounded by its pieces (doc/section-length.md eq. 25): the exact speeds at their
  // ends, the jerk bound of each.
  CurveSection piece = *this;
  const double h = span();
  return detail::refined_bounds_from_ends([&](double t) { return weighted_speed(factors, t); },
                                          [&](double a, double b) {
                                            piece.v0 = v0 + a * h;
                                            piece.v1 = b >= 1.0 ? v1 : v0 + b * h;
                                            return piece.piece_rates(factors);
                                          },
                                          t0, t1, w0, w1, acceleration_precision);
}

inline MotionBounds CurveSection::motion_bounds() const {
  const double m = 0.5 * (v0 + v1);
  return detail::motion_bounds_at_middle(detail::cubic_at(position, m), detail::cubic_at(rotation, m), span());
}

inline double CurveSection::acceleration_bound(const MetricSetd& set) const {
  const MotionBounds motion = motion_bounds();
  const Eigen::Vector3d pivot_middle = position.value(0.5 * (v0 + v1));
  double best = 0.0;
  for (const auto& g : set.groups())
    best = std::max(best, detail::group_acceleration_bound(g, pivot, pivot_middle, motion));
  return best;
}


}  // namespace dispkin
