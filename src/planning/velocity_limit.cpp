// Time-optimal laws under a piecewise-constant velocity limit (velocity_limit.hpp).
#include "dispkin/planning/velocity_limit.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "carried_acceleration.hpp"
#include "dispkin/error.hpp"

namespace dispkin {
namespace {

// The largest w ≤ cap reachable from u within `distance` (a change up or down): bisection on
// the monotone velocity_change_distance, shrunk by a relative 1e-9 so that the profile built
// on it fits with room for rounding.
double reachable(double u, double cap, double distance, double a, std::optional<double> j) {
  if (velocity_change_distance(u, cap, a, j) <= distance * (1.0 - 1e-9)) return cap;
  double lo = std::min(u, cap), hi = cap;
  for (int i = 0; i < 200 && hi - lo > 1e-15 * hi; ++i) {
    const double mid = 0.5 * (lo + hi);
    (velocity_change_distance(u, mid, a, j) <= distance * (1.0 - 1e-9) ? lo : hi) = mid;
  }
  return lo;
}

}  // namespace

double velocity_change_distance(double u, double w, double a, std::optional<double> j) noexcept {
  const double delta = std::abs(w - u);
  if (!j) return std::abs(w * w - u * u) / (2.0 * a);
  const double time = delta >= a * a / *j ? delta / a + a / *j : 2.0 * std::sqrt(delta / *j);
  return 0.5 * (u + w) * time;
}

std::vector<Profile> velocity_limited_chain(const std::vector<LimitedSegment>& segments, double a_max,
                                            std::optional<double> j_max, double v_start, double v_end) {
  require(!segments.empty(), "segments", 0L, "is empty: nothing to move along");
  require_positive(a_max, "a_max");
  if (j_max) require_positive(*j_max, "j_max");
  for (std::size_t i = 0; i < segments.size(); ++i) {
    // The message is only formatted when a value is refused.
    if (!(segments[i].length > 0.0 && std::isfinite(segments[i].length)))
      require_positive(segments[i].length, "segments[" + std::to_string(i) + "].length");
    if (!(segments[i].limit > 0.0 && std::isfinite(segments[i].limit)))
      require_positive(segments[i].limit, "segments[" + std::to_string(i) + "].limit");
    if (!(segments[i].acceleration >= 0.0 && std::isfinite(segments[i].acceleration)))
      require(false, "segments[" + std::to_string(i) + "].acceleration", segments[i].acceleration,
              "must be finite and not negative");
  }
  // Each segment's own acceleration limit.
  auto accel = [&](std::size_t i) {
    const double own = segments[i].acceleration;
    return own > 0.0 ? std::min(own, a_max) : a_max;
  };
  require(std::isfinite(v_start) && v_start >= 0.0 && v_start <= segments.front().limit, "v_start", v_start,
          "must be in [0, limit of the first segment]");
  require(std::isfinite(v_end) && v_end >= 0.0 && v_end <= segments.back().limit, "v_end", v_end,
          "must be in [0, limit of the last segment]");

  // Boundary velocities: u[0] = v_start, u[n] = v_end, inner ones capped by both limits.
  const std::size_t n = segments.size();
  std::vector<double> u(n + 1);
  u[0] = v_start;
  u[n] = v_end;
  for (std::size_t i = 1; i < n; ++i) u[i] = std::min(segments[i - 1].limit, segments[i].limit);
  for (std::size_t i = n; i-- > 0;) u[i] = std::min(u[i], reachable(u[i + 1], u[i], segments[i].length, accel(i), j_max));
  for (std::size_t i = 0; i < n; ++i) u[i + 1] = std::min(u[i + 1], reachable(u[i], u[i + 1], segments[i].length, accel(i), j_max));
  if (std::abs(u[0] - v_start) > 1e-12 * std::max(1.0, v_start) || std::abs(u[n] - v_end) > 1e-12 * std::max(1.0, v_end)) {
    throw std::invalid_argument(describe("v_end", v_end, "cannot be reached from v_start = " + std::to_string(v_start) +
                                                             " within the segments' length"));
  }

  std::vector<Profile> laws;
  laws.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    const LimitedSegment& g = segments[i];
    laws.push_back(j_max ? Profile::scurve(g.length, g.limit, accel(i), *j_max, u[i], u[i + 1])
                         : Profile::trapezoid(g.length, g.limit, accel(i), u[i], u[i + 1]));
  }
  return laws;
}

std::vector<Profile> velocity_limited_law(const std::vector<LimitedSegment>& segments, double a_max,
                                          std::optional<double> j_max, double v_start, double v_end) {
  std::vector<Profile> laws = velocity_limited_chain(segments, a_max, j_max, v_start, v_end);
  if (!j_max || v_end != 0.0) return laws;
  // The jerk-limited chain returns to zero acceleration at every boundary; the law that carries
  // acceleration across them (doc/profiles.md §8), built forwards and, from rest, backwards,
  // replaces it wherever it is faster.
  const auto total = [](const std::vector<Profile>& chain) {
    double sum = 0.0;
    for (const Profile& p : chain) sum += p.duration();
    return sum;
  };
  double duration = total(laws);
  std::vector<double> accelerations(segments.size());
  for (std::size_t i = 0; i < segments.size(); ++i) {
    const double own = segments[i].acceleration;
    accelerations[i] = own > 0.0 ? std::min(own, a_max) : a_max;
  }
  const auto keep_if_faster = [&](std::vector<Profile> candidate) {
    const double d = total(candidate);
    if (d < duration) {
      laws = std::move(candidate);
      duration = d;
    }
  };
  if (auto forward = detail::carried_acceleration_law(segments, accelerations, *j_max, v_start)) keep_if_faster(std::move(*forward));
  if (v_start == 0.0) {
    // Built from the end and run backwards, it enters the lower limits ahead with zero
    // acceleration where the forward law brakes late and undershoots them.
    const std::vector<LimitedSegment> reversed(segments.rbegin(), segments.rend());
    const std::vector<double> reversed_accelerations(accelerations.rbegin(), accelerations.rend());
    if (auto backward = detail::carried_acceleration_law(reversed, reversed_accelerations, *j_max, 0.0))
      keep_if_faster(detail::reversed_in_time(*backward));
  }
  return laws;
}

}  // namespace dispkin
