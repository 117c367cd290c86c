// Laws from a moving state of a planned trajectory (law_from_state.hpp; doc/events.md).
#include "law_from_state.hpp"

#include "staircase_input.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "dispkin/error.hpp"
#include "reachable_velocity.hpp"

namespace dispkin::detail {

std::optional<Profile> fastest_stop(double v0, double a0, double a_max, std::optional<double> j_max) {
  require(std::isfinite(v0) && v0 >= 0.0, "v0", v0, "must be finite and not negative");
  require_finite(a0, "a0");
  if (!j_max) {
    // Without a jerk limit: decelerate at a_max, over v0² / 2a (doc/events.md eq. 4).
    if (v0 == 0.0) return std::nullopt;
    // Over v0² / 2a and four roundings more: Profile::trapezoid checks the distance with its own.
    const double distance = v0 * v0 / (2.0 * a_max);
    return Profile::trapezoid(distance * (1.0 + 4.0 * std::numeric_limits<double>::epsilon()), v0, a_max, v0, 0.0);
  }
  if (v0 == 0.0 && a0 == 0.0) return std::nullopt;
  const double j = *j_max;
  // Where ṡ ends up if s̈ went back to 0 at once, at full jerk (doc/events.md eq. 1).
  const double released = v0 + a0 * std::abs(a0) / (2.0 * j);
  std::array<double, 3> durations{}, jerks{};
  int count = 0;
  const auto phase = [&](double duration, double jerk) {
    if (duration > 0.0) {
      durations[static_cast<std::size_t>(count)] = duration;
      jerks[static_cast<std::size_t>(count++)] = jerk;
    }
  };
  if (a0 < 0.0 && released <= 0.0) {
    // Already braking as hard as it may: releasing at once ends at rest. Below the release curve
    // (released < 0) it would run backwards; the laws of a trajectory reach such states only by
    // rounding (ṡ within 1e-8 of their speed scale around ṡ = 0), and the stop then starts on the
    // curve, at ṡ = s̈²/2j: one velocity step of that size, where an exception would leave a feed
    // hold undone.
    v0 = std::max(v0, a0 * a0 / (2.0 * j));
    phase(-a0 / j, j);
  } else {
    // Down to the peak deceleration a_p (doc/events.md eq. 2): with no hold, a_p² = (2 j v0 + a0²) / 2; held
    // at a_max for T = (v0 + (a0² − 2 a_max²) / 2j) / a_max (doc/events.md eq. 3) where that a_p exceeds it. A
    // state below −a_max first rises to it at full jerk.
    const double peak = std::sqrt(0.5 * (2.0 * j * v0 + a0 * a0));
    if (peak <= a_max && a0 >= -peak) {
      phase((a0 + peak) / j, -j);
      phase(peak / j, j);
    } else {
      const double v_at_max = v0 + (a0 * a0 - a_max * a_max) / (2.0 * j) * (a0 >= -a_max ? 1.0 : -1.0);
      const double hold = (v_at_max - a_max * a_max / (2.0 * j)) / a_max;
      phase(std::abs(a0 + a_max) / j, a0 >= -a_max ? -j : j);
      phase(hold, 0.0);
      phase(a_max / j, j);
    }
  }
  // The distance, integrated phase by phase as the law will be.
  double s = 0.0, v = v0, a = a0;
  for (int i = 0; i < count; ++i) {
    const double d = durations[static_cast<std::size_t>(i)], jk = jerks[static_cast<std::size_t>(i)];
    s += d * (v + d * (0.5 * a + jk * d / 6.0));
    v += d * (a + 0.5 * jk * d);
    a += jk * d;
  }
  return Profile::from_phases(durations.data(), jerks.data(), count, v0, a0, std::max(s, 0.0), 0.0, 0.0);
}

std::vector<Profile> stop_then_staircase(const std::vector<LimitedSegment>& segments, double a_max,
                                         std::optional<double> j_max, double v0, double a0, double tolerance) {
  require(!segments.empty(), "segments", 0L, "is empty: nothing to move along");
  double distance = 0.0, a = a_max;
  for (const LimitedSegment& g : segments) {
    distance += g.length;
    if (g.acceleration > 0.0) a = std::min(a, g.acceleration);
  }
  std::optional<Profile> stop = fastest_stop(v0, a0, a, j_max);
  const double stop_distance = stop ? stop->distance() : 0.0;
  require(stop_distance <= distance + tolerance, "v0", v0,
          "cannot come to rest within the run of " + std::to_string(distance) + " m");
  std::vector<Profile> laws;
  if (stop) laws.push_back(std::move(*stop));
  if (stop_distance < distance - tolerance) {
    std::vector<LimitedSegment> rest;
    double s = 0.0;
    for (const LimitedSegment& g : segments) {
      const double from = std::max(s, stop_distance);
      if (s + g.length > from) rest.push_back({s + g.length - from, g.limit, g.acceleration});
      s += g.length;
    }
    for (Profile& law : velocity_limited_law(rest, a_max, j_max)) laws.push_back(std::move(law));
  }
  return laws;
}

std::vector<Profile> staircase_law_from_state(const std::vector<LimitedSegment>& segments, double a_max,
                                              std::optional<double> j_max, double v0, double a0, double tolerance) {
  require(!segments.empty(), "segments", 0L, "is empty: nothing to move along");
  const std::size_t n = segments.size();
  const auto accel = [&](std::size_t i) { return detail::segment_acceleration(segments[i], a_max); };
  // The backward pass of the chain (doc/profiles.md §5): u[i], the highest ṡ at the start of
  // segment i from which the rest of the run comes to rest within its limits.
  std::vector<double> u(n + 1, 0.0);
  for (std::size_t i = n; i-- > 1;)
    u[i] = reachable_velocity(u[i + 1], std::min(segments[i - 1].limit, segments[i].limit), segments[i].length,
                              accel(i), j_max);
  // The first law takes segments [0, m] as one, under their lowest limits, to u[m + 1]: the
  // fewest segments in which it fits (doc/profiles.md eq. 6).
  double distance = 0.0, v_max = segments[0].limit, a = accel(0);
  for (std::size_t m = 0; m < n; ++m) {
    distance += segments[m].length;
    v_max = std::min(v_max, segments[m].limit);
    a = std::min(a, accel(m));
    const double v_end = std::min(u[m + 1], v_max);
    try {
      Profile first = j_max ? Profile::from_state(distance, v_max, a, *j_max, v0, a0, v_end)
                            : Profile::trapezoid_from_state(distance, v_max, a, v0, v_end);
      std::vector<Profile> laws{std::move(first)};
      if (m + 1 < n) {
        const std::vector<LimitedSegment> rest(segments.begin() + static_cast<std::ptrdiff_t>(m + 1), segments.end());
        for (Profile& law : velocity_limited_law(rest, a_max, j_max, v_end, 0.0)) laws.push_back(std::move(law));
      }
      return laws;
    } catch (const std::invalid_argument&) {
      if (m + 1 < n) continue;
      // Not even over the whole run: the state brakes onto its end, or releases its braking onto
      // rest before it (ṡ = s̈²/2j, where a law that goes on at once would dip below ṡ = 0 by
      // rounding).
      return stop_then_staircase(segments, a_max, j_max, v0, a0, tolerance);
    }
  }
  return {};  // not reached: the last attempt returns or throws
}

}  // namespace dispkin::detail
