//! The bounds of a whole curved section (a cubic pose curve's or a nested-SLERP blend's part)
//! from the bounds of its equal pieces (doc/section-length.md §5, eqs. 25–27): the section is
//! not cut, only its bound is computed finely enough to lie within a set precision of the exact
//! peak speed.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

#include "dispkin/path/group_factors.hpp"

namespace dispkin {

//! A section's refined bounds, with what its pieces say of how the speed and the acceleration
//! bound vary along it (for the planner's cut, doc/planning.md §9): the least middle speed
//! and the least acceleration bound of the pieces, per unit τ of the section.
struct RefinedBounds {
  SectionBounds bounds;       //!< the whole section's bounds
  double least_middle_speed;  //!< the least weighted middle speed of the pieces (m)
  double least_acceleration;  //!< the least acceleration bound of the pieces (m)
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
      r.least_middle_speed = std::min(r.least_middle_speed, middle * n);
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

}  // namespace detail
}  // namespace dispkin
