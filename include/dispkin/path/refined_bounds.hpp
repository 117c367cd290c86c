//! The bounds of a whole curved section (a cubic pose curve's or a nested-SLERP blend's part)
//! from the bounds of its equal pieces (doc/section-length.md §5, eqs. 25–27): the section is
//! not cut, only its bound is computed finely enough to lie within a set precision of the exact
//! peak speed. A cubic curve's pieces are bounded from the exact speeds at their ends and a jerk
//! bound (slack ∝ N⁻²), a blend's from the speed at their middles and an acceleration bound
//! (slack ∝ N⁻¹).
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

#include "dispkin/path/group_factors.hpp"

namespace dispkin {

//! A section's refined bounds, with what its pieces say of how the speed and the acceleration
//! bound vary along it (for the planner's cut, doc/planning.md §9): the least speed sampled
//! and the least acceleration bound of the pieces, per unit τ of the section.
struct RefinedBounds {
  SectionBounds bounds;       //!< the whole section's bounds
  double least_speed;         //!< the least weighted speed sampled (at the pieces' ends or middles) (m)
  double least_acceleration;  //!< the least acceleration bound of the pieces (m)
};

//! What a piece of a section bounds besides its speed, per unit τ of the piece: the acceleration
//! of every object (unweighted), the jerk of every object (weighted by its group), |ω| and |ω̇|.
struct PieceRates {
  //! ‖d²x/dτ²‖ (m), max_g w_g ‖d³x/dτ³‖ (m), |ω| (rad) and |ω̇| (rad)
  //!@{
  double acceleration, jerk, omega, omega_dot;
  //!@}
  //! The acceleration bound's formula at the piece's middle alone (m): what `acceleration`
  //! tends to as the piece shrinks, so that their gap is its slack.
  double acceleration_middle;
};

namespace detail {

//! The relative precision of a refined bound: its length exceeds the exact peak speed of the
//! section's fastest object by at most this share (doc/section-length.md eq. 27).
constexpr double refined_bound_precision = 1e-3;
//! The most pieces a section's bound is refined into; past them the bound stays rigorous, only
//! looser.
constexpr int refined_bound_max_pieces = 1 << 14;

//! `piece(t0, t1, middle_speed)` returns the bounds of the part τ ∈ [t0, t1] per unit of that
//! part's own τ (doc/section-length.md eq. 24) and its weighted middle speed. The section's bounds are the largest of
//! N equal pieces', rescaled to the section's τ (doc/section-length.md eq. 25); N doubles (at least) until the largest
//! middle speed, a lower bound of the exact peak, lies within the precision of the length (doc/section-length.md eqs.
//! 26–27).
template <class Piece>
RefinedBounds refined_bounds(const Piece& piece) {
  int n = 1;
  for (;;) {
    RefinedBounds r{
        {0.0, 0.0, 0.0, 0.0}, std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
    SectionBounds& whole = r.bounds;
    double low = 0.0;
    const double h = 1.0 / n;
    for (int i = 0; i < n; ++i) {
      double middle = 0.0;
      const SectionBounds b = piece(i * h, i + 1 == n ? 1.0 : (i + 1) * h, middle);
      // Per unit τ of the piece to per unit τ of the section: speeds × n, accelerations × n².
      whole.length = std::max(whole.length, b.length * n);
      whole.acceleration = std::max(whole.acceleration, b.acceleration * n * n);
      whole.omega = std::max(whole.omega, b.omega * n);
      whole.omega_dot = std::max(whole.omega_dot, b.omega_dot * n * n);
      low = std::max(low, middle * n);
      r.least_speed = std::min(r.least_speed, middle * n);
      r.least_acceleration = std::min(r.least_acceleration, b.acceleration * n * n);
    }
    const double gap = whole.length - low;
    if (!(gap > refined_bound_precision * whole.length) || n >= refined_bound_max_pieces) return r;
    // The slack of doc/section-length.md eq. 24 falls as 1/N (eq. 27): aim at the precision in one step, at least
    // doubling.
    const double wanted = std::ceil(1.25 * n * gap / (refined_bound_precision * whole.length));
    n = static_cast<int>(
        std::clamp(std::isfinite(wanted) ? wanted : 2.0 * n, 2.0 * n, double(refined_bound_max_pieces)));
  }
}

//! The largest value over t ∈ [0, 1] of (1 − t) w0 + t w1 + k t (1 − t) (k ≥ 0): at an end, or
//! at t = ½ + (w1 − w0)/(2k) inside, where it is (w0 + w1)/2 + k/4 + (w1 − w0)²/(4k) (doc/section-length.md
//! eq. 25).
inline double interpolation_peak(double w0, double w1, double k) noexcept {
  const double d = w1 - w0;
  if (!(k > std::abs(d))) return std::max(w0, w1);
  return 0.5 * (w0 + w1) + 0.25 * k + d * d / (4.0 * k);
}

//! The bounds of the part τ ∈ [t0, t1] of a section, per unit τ of the part, from the exact speeds
//! at the ends of N equal pieces and each piece's jerk bound (doc/section-length.md eqs. 25–27).
//! `speed(t)` returns the weighted fastest speed at τ = t per unit τ of the section, `first` and
//! `last` are its values at t0 and t1 (known to the caller: parts that meet share them);
//! `piece(a, b)` returns the PieceRates of the part τ ∈ [a, b] per unit of that part's own τ. Every
//! object's velocity differs from the chord between its end values by at most t(1 − t)/2 times its
//! jerk bound, so each piece's speed is at most the interpolation_peak of its end speeds; the
//! largest end speed is a lower bound of the exact peak, and the gap falls as N⁻²: N aims at the
//! precision in one step, at least doubling.
//! With `acceleration_precision` > 0 N also grows until the acceleration bound is within that share
//! of its formula at the pieces' middles (its slack falls as N⁻¹): the planner asks for it where
//! the curvature rule sets the speed (doc/planning.md eq. 33).
template <class Speed, class Piece>
RefinedBounds refined_bounds_from_ends(const Speed& speed, const Piece& piece, double t0, double t1, double first,
                                       double last, double acceleration_precision = 0.0) {
  // Speeds per unit τ of the section to per unit τ of the part.
  const double share = t1 - t0;
  first *= share;
  last *= share;
  int n = 1;
  for (;;) {
    RefinedBounds r{{0.0, 0.0, 0.0, 0.0}, std::min(first, last), std::numeric_limits<double>::infinity()};
    SectionBounds& whole = r.bounds;
    double low = std::max(first, last), acceleration_low = 0.0;
    double a = t0, w0 = first;
    for (int i = 0; i < n; ++i) {
      const bool end = i + 1 == n;
      const double b = end ? t1 : t0 + share * (i + 1) / n;
      const double w1 = end ? last : share * speed(b);
      const PieceRates p = piece(a, b);
      // Per unit τ of the piece to per unit τ of the part: speeds × n, accelerations × n²; the
      // chord's deviation t(1 − t)/2 · n J (J per unit τ³ of the piece) is k t(1 − t), k = n J/2.
      whole.length = std::max(whole.length, interpolation_peak(w0, w1, 0.5 * p.jerk * n));
      whole.acceleration = std::max(whole.acceleration, p.acceleration * n * n);
      whole.omega = std::max(whole.omega, p.omega * n);
      whole.omega_dot = std::max(whole.omega_dot, p.omega_dot * n * n);
      low = std::max(low, w1);
      r.least_speed = std::min(r.least_speed, w1);
      r.least_acceleration = std::min(r.least_acceleration, p.acceleration * n * n);
      acceleration_low = std::max(acceleration_low, p.acceleration_middle * n * n);
      a = b;
      w0 = w1;
    }
    const double gap = whole.length - low;
    const double acceleration_gap = acceleration_precision > 0.0 ? whole.acceleration - acceleration_low : 0.0;
    if ((!(gap > refined_bound_precision * whole.length) &&
         !(acceleration_gap > acceleration_precision * whole.acceleration)) ||
        n >= refined_bound_max_pieces)
      return r;
    const double wanted = std::max(
        std::ceil(n * std::sqrt(1.25 * gap / (refined_bound_precision * whole.length))),
        acceleration_gap > 0.0 ? std::ceil(1.25 * n * acceleration_gap / (acceleration_precision * whole.acceleration))
                               : 0.0);
    n = static_cast<int>(
        std::clamp(std::isfinite(wanted) ? wanted : 2.0 * n, 2.0 * n, double(refined_bound_max_pieces)));
  }
}

}  // namespace detail
}  // namespace dispkin
