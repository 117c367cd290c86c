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
#include <optional>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "dispkin/disp.hpp"
#include "dispkin/metric_set.hpp"
#include "dispkin/pose.hpp"

namespace dispkin {

//! A cubic polynomial in v with vector coefficients: p(v) = Σ aᵢ vⁱ.
struct Cubic3 {
  std::array<Eigen::Vector3d, 4> a{Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(),
                                   Eigen::Vector3d::Zero()};

  Eigen::Vector3d value(double v) const noexcept { return a[0] + v * (a[1] + v * (a[2] + v * a[3])); }
  Eigen::Vector3d first(double v) const noexcept { return a[1] + v * (2.0 * a[2] + 3.0 * v * a[3]); }
  Eigen::Vector3d second(double v) const noexcept { return 2.0 * a[2] + 6.0 * v * a[3]; }
  Eigen::Vector3d third() const noexcept { return 6.0 * a[3]; }

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

//! Bounds over a section, per unit τ: pivot speed |ċ| and acceleration |c̈|, angular velocity
//! |ω| and angular acceleration |ω̇|.
struct MotionBounds {
  double pivot_speed, pivot_acceleration, omega, omega_dot;
};

//! A bound of the acceleration (per unit τ²) of every object of the group under motions within
//! `bounds`: a body point at distance r from the pivot accelerates at most |c̈| + (|ω̇| + |ω|²) r;
//! an absolute point at distance r seen from the body at most |c̈| + |ω̇| r + |ω||ċ| (r from
//! `pivot_middle`, the pivot's world position at the middle of the section, plus |ċ|/2).
inline double group_acceleration_bound(const MetricGroup<double>& g, const Eigen::Vector3d& pivot,
                                       const Eigen::Vector3d& pivot_middle, const MotionBounds& bounds);

}  // namespace detail

//! One section of a cubic pose curve: the part v ∈ [v0, v1], run as τ = (v − v0)/(v1 − v0)
//! goes over [0, 1].
struct CurveSection {
  Eigen::Quaterniond q0 = Eigen::Quaterniond::Identity();  //!< R₀
  Cubic3 position;                                          //!< c(v), world
  Cubic3 rotation;                                          //!< φ(v), body of R₀
  double v0 = 0.0, v1 = 1.0;
  Eigen::Vector3d pivot = Eigen::Vector3d::Zero();  //!< body coordinates of the point on c(v)

  double span() const noexcept { return v1 - v0; }

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

  //! Pose and body twist per unit τ at τ, sharing one evaluation of the polynomials and of exp.
  void at(double tau, Posed& pose_out, Twistd& twist_out) const noexcept {
    const double h = span();
    const double v = v0 + tau * h;
    const Eigen::Vector3d phi = rotation.value(v);
    const Eigen::Quaterniond q = (q0 * quaternion_exp(phi)).normalized();
    const Eigen::Vector3d omega = h * right_jacobian_times(phi, rotation.first(v));
    pose_out = Posed::unchecked(q, position.value(v) - q * pivot);
    twist_out = Twistd(q.conjugate() * (h * position.first(v)) - omega.cross(pivot), omega);
  }

  //! An upper bound of the speed of every object of the set per unit τ (never below the
  //! exact maximum): each group's exact speed at the middle τ = ½ plus half the largest rate
  //! at which that speed can change along the section, from bounds of the pivot
  //! acceleration |c̈|, the angular velocity |ω| ≤ |φ̇| (‖J_r‖ ≤ 1) and the angular acceleration
  //! |ω̇| ≤ |φ̈| + g′(θ)|φ̇|², g′(θ) = (θeᶿ − eᶿ + 1)/θ² (a bound of ‖dJ_r/dφ‖ from its series).
  //! A body point at distance r from the pivot accelerates at most |c̈| + (|ω̇| + |ω|²) r; an
  //! absolute point at distance r seen from the body at most |c̈| + |ω̇| r + |ω||ċ|.
  //! Slack: about ½ × acceleration / speed of the section, which the cutting keeps small.
  double length(const MetricSetd& set, std::optional<double> system_velocity) const;

  //! A bound of the acceleration of every object of the set per unit τ² (unweighted): with
  //! L the section's length, a point accelerates at most (ṡ/L)² times this from the path's
  //! curvature alone.
  double acceleration_bound(const MetricSetd& set) const;

  //! Bounds over the section of |ċ|, |c̈|, |ω| ≤ |φ̇| and |ω̇| ≤ |φ̈| + g′(θ)|φ̇|², per unit τ.
  detail::MotionBounds motion_bounds() const;
};

// --- definitions (inline: the hexapod plugin uses curved sections without the umbrella) ---
namespace detail {

// g′(θ) = (θeᶿ − eᶿ + 1)/θ² = Σₖ≥₁ k θᵏ⁻¹/(k + 1)!: with ‖[φ]ₓᵏ‖ = θᵏ, the series of J_r
// gives ‖dJ_r(φ)[u]‖ ≤ g′(θ)|u|. Its own series below 10⁻³ (the closed form cancels).
inline double jacobian_rate_bound(double theta) {
  if (theta < 1e-3) return 0.5 + theta / 3.0 + theta * theta / 8.0;
  return (theta * std::exp(theta) - std::exp(theta) + 1.0) / (theta * theta);
}

// Bounds of |p′| and |p″| of a cubic over [m − δ, m + δ], by Taylor at the middle m (exact
// expansion: p′ is quadratic, p″ linear).
struct DerivativeBounds {
  double first, second;
};
inline DerivativeBounds derivative_bounds(const Cubic3& p, double m, double delta) {
  const double third = p.third().norm();
  const double second_mid = p.second(m).norm();
  return {p.first(m).norm() + second_mid * delta + 0.5 * third * delta * delta, second_mid + third * delta};
}

}  // namespace detail

inline Eigen::Matrix3d right_jacobian(const Eigen::Vector3d& phi) noexcept {
  const double theta = phi.norm();
  const Eigen::Matrix3d w = detail::hat(phi);
  return Eigen::Matrix3d::Identity() - detail::coefficient_b(theta) * w + detail::coefficient_c(theta) * (w * w);
}

inline double CurveSection::length(const MetricSetd& set, std::optional<double> system_velocity) const {
  set.require_well_formed();
  const double m = 0.5 * (v0 + v1);
  const detail::MotionBounds motion = motion_bounds();
  Posed middle;
  Twistd twist_middle;
  at(0.5, middle, twist_middle);
  const Eigen::Vector3d pivot_middle = position.value(m);

  double best = 0.0;
  for (const auto& g : set.groups()) {
    const double rate = detail::group_acceleration_bound(g, pivot, pivot_middle, motion);
    const double speed = detail::group_max_speed(g, middle, twist_middle);
    best = std::max(best, g.weight(system_velocity) * (speed + 0.5 * rate));
  }
  return best;
}

inline detail::MotionBounds CurveSection::motion_bounds() const {
  const double h = span();
  const double m = 0.5 * (v0 + v1);
  const double delta = 0.5 * h;
  const detail::DerivativeBounds c = detail::derivative_bounds(position, m, delta);
  const detail::DerivativeBounds phi = detail::derivative_bounds(rotation, m, delta);
  const double theta_max = rotation.value(m).norm() + phi.first * delta;
  return {h * c.first, h * h * c.second, h * phi.first,
          h * h * (phi.second + detail::jacobian_rate_bound(theta_max) * phi.first * phi.first)};
}

inline double CurveSection::acceleration_bound(const MetricSetd& set) const {
  const detail::MotionBounds motion = motion_bounds();
  const Eigen::Vector3d pivot_middle = position.value(0.5 * (v0 + v1));
  double best = 0.0;
  for (const auto& g : set.groups()) best = std::max(best, detail::group_acceleration_bound(g, pivot, pivot_middle, motion));
  return best;
}

namespace detail {

inline double group_acceleration_bound(const MetricGroup<double>& g, const Eigen::Vector3d& pivot,
                                const Eigen::Vector3d& pivot_middle, const MotionBounds& b) {
  // The largest distance of the group's body objects from the pivot, and of its absolute
  // objects from the pivot anywhere on the section (at most |ċ|/2 from the middle).
  double r_relative = 0.0, r_absolute = 0.0;
  for (const auto& p : g.relative_points) r_relative = std::max(r_relative, (p - pivot).norm());
  for (const auto& s : g.relative_spheres) r_relative = std::max(r_relative, (s.center - pivot).norm() + s.radius);
  bool has_absolute = false;
  for (const auto& p : g.absolute_points) {
    r_absolute = std::max(r_absolute, (p - pivot_middle).norm());
    has_absolute = true;
  }
  for (const auto& s : g.absolute_spheres) {
    r_absolute = std::max(r_absolute, (s.center - pivot_middle).norm() + s.radius);
    has_absolute = true;
  }
  r_absolute += 0.5 * b.pivot_speed;
  double rate = b.pivot_acceleration + (b.omega_dot + b.omega * b.omega) * r_relative;
  if (has_absolute) rate = std::max(rate, b.pivot_acceleration + b.omega_dot * r_absolute + b.omega * b.pivot_speed);
  return rate;
}

}  // namespace detail

}  // namespace dispkin
