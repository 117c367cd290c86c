// Curved sections: the right Jacobian and the rigorous length bound (curve_section.hpp).
#include "dispkin/curve_section.hpp"

#include <algorithm>
#include <cmath>

#include "dispkin/disp.hpp"

namespace dispkin {
namespace {

// g′(θ) = (θeᶿ − eᶿ + 1)/θ² = Σₖ≥₁ k θᵏ⁻¹/(k + 1)!: with ‖[φ]ₓᵏ‖ = θᵏ, the series of J_r
// gives ‖dJ_r(φ)[u]‖ ≤ g′(θ)|u|. Its own series below 10⁻³ (the closed form cancels).
double jacobian_rate_bound(double theta) {
  if (theta < 1e-3) return 0.5 + theta / 3.0 + theta * theta / 8.0;
  return (theta * std::exp(theta) - std::exp(theta) + 1.0) / (theta * theta);
}

// Bounds of |p′| and |p″| of a cubic over [m − δ, m + δ], by Taylor at the middle m (exact
// expansion: p′ is quadratic, p″ linear).
struct DerivativeBounds {
  double first, second;
};
DerivativeBounds derivative_bounds(const Cubic3& p, double m, double delta) {
  const double third = p.third().norm();
  const double second_mid = p.second(m).norm();
  return {p.first(m).norm() + second_mid * delta + 0.5 * third * delta * delta, second_mid + third * delta};
}

}  // namespace

Eigen::Matrix3d right_jacobian(const Eigen::Vector3d& phi) noexcept {
  const double theta = phi.norm();
  const Eigen::Matrix3d w = detail::hat(phi);
  return Eigen::Matrix3d::Identity() - detail::coefficient_b(theta) * w + detail::coefficient_c(theta) * (w * w);
}

double CurveSection::length(const MetricSetd& set, std::optional<double> system_velocity) const {
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

detail::MotionBounds CurveSection::motion_bounds() const {
  const double h = span();
  const double m = 0.5 * (v0 + v1);
  const double delta = 0.5 * h;
  const DerivativeBounds c = derivative_bounds(position, m, delta);
  const DerivativeBounds phi = derivative_bounds(rotation, m, delta);
  const double theta_max = rotation.value(m).norm() + phi.first * delta;
  return {h * c.first, h * h * c.second, h * phi.first,
          h * h * (phi.second + jacobian_rate_bound(theta_max) * phi.first * phi.first)};
}

double CurveSection::acceleration_bound(const MetricSetd& set) const {
  const detail::MotionBounds motion = motion_bounds();
  const Eigen::Vector3d pivot_middle = position.value(0.5 * (v0 + v1));
  double best = 0.0;
  for (const auto& g : set.groups()) best = std::max(best, detail::group_acceleration_bound(g, pivot, pivot_middle, motion));
  return best;
}

namespace detail {

double group_acceleration_bound(const MetricGroup<double>& g, const Eigen::Vector3d& pivot,
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
