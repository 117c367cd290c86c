// The largest velocity reachable within a distance (internal to the staircase laws:
// velocity_limit.cpp, law_from_state.cpp; doc/profiles.md §5).
#pragma once

#include <algorithm>
#include <optional>

#include "dispkin/planning/velocity_limit.hpp"

namespace dispkin::detail {

// The largest w ≤ cap reachable from u within `distance` (a change up or down): bisection on
// the monotone velocity_change_distance, shrunk by a relative 1e-9 so that the profile built
// on it fits with room for rounding.
inline double reachable_velocity(double u, double cap, double distance, double a, std::optional<double> j) {
  if (velocity_change_distance(u, cap, a, j) <= distance * (1.0 - 1e-9)) return cap;
  double lo = std::min(u, cap), hi = cap;
  for (int i = 0; i < 200 && hi - lo > 1e-15 * hi; ++i) {
    const double mid = 0.5 * (lo + hi);
    (velocity_change_distance(u, mid, a, j) <= distance * (1.0 - 1e-9) ? lo : hi) = mid;
  }
  return lo;
}

}  // namespace dispkin::detail
