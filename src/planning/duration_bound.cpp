// A duration no jerk-limited law under a staircase can beat (velocity_limit.hpp;
// doc/profiles.md §8.5, eqs. 34–37).
#include <algorithm>
#include <array>
#include <cstddef>
#include <vector>

#include "dispkin/planning/velocity_limit.hpp"
#include "staircase_input.hpp"

namespace dispkin {
namespace {

// The bounds of one window: its end limits, the largest limit and acceleration inside, the jerk.
struct Window {
  double c_start, c_end, top, a, j;
};

// G(t) of doc/profiles.md eq. 35: the most velocity gained in time t by an acceleration that
// ends at zero.
double rise_to_rest(double t, double a, double j) {
  return t <= a / j ? 0.5 * j * t * t : 0.5 * a * a / j + a * (t - a / j);
}

// P(T) of doc/profiles.md eq. 35, over-estimated by the bracket of the bisection: the highest
// velocity a law on the window can reach in time T.
double peak_velocity(const Window& w, double T) {
  double lo = 0.0, hi = T;
  for (int i = 0; i < 60; ++i) {
    const double mid = 0.5 * (lo + hi);
    (w.c_start + rise_to_rest(mid, w.a, w.j) < w.c_end + rise_to_rest(T - mid, w.a, w.j) ? lo : hi) = mid;
  }
  const double inside = std::min(w.c_start + rise_to_rest(hi, w.a, w.j), w.c_end + rise_to_rest(T - lo, w.a, w.j));
  const double at_end = std::max(std::min(w.c_start, w.c_end + w.a * T), std::min(w.c_end, w.c_start + w.a * T));
  return std::min(w.top, std::max(inside, at_end));
}

// D(T) of doc/profiles.md eq. 34: the integral of a piecewise-linear envelope, exact by the
// trapezoid rule between its kinks.
double covered_distance(const Window& w, double T) {
  const double p = peak_velocity(w, T);
  std::array<double, 5> kinks{0.0, T, (p - w.c_start) / w.a, T - (p - w.c_end) / w.a,
                              0.5 * (w.c_end - w.c_start + w.a * T) / w.a};
  for (std::size_t i = 2; i < kinks.size(); ++i) kinks[i] = std::clamp(kinks[i], 0.0, T);
  std::sort(kinks.begin(), kinks.end());
  const auto envelope = [&](double t) { return std::min({w.c_start + w.a * t, w.c_end + w.a * (T - t), p}); };
  double sum = 0.0;
  for (std::size_t i = 0; i + 1 < kinks.size(); ++i)
    sum += 0.5 * (envelope(kinks[i]) + envelope(kinks[i + 1])) * (kinks[i + 1] - kinks[i]);
  return sum;
}

// τ of doc/profiles.md eq. 36: the longest time in which the window's length cannot be covered.
double least_window_time(const Window& w, double length) {
  double lo = 0.0, hi = length / w.top;
  while (covered_distance(w, hi) < length) hi *= 2.0;
  for (int i = 0; i < 60 && hi - lo > 1e-15 * hi; ++i) {
    const double mid = 0.5 * (lo + hi);
    (covered_distance(w, mid) < length ? lo : hi) = mid;
  }
  return lo;
}

}  // namespace

double jerk_limited_duration_bound(const std::vector<LimitedSegment>& segments, double a_max, double j_max,
                                   double v_start, double v_end) {
  detail::require_staircase(segments, a_max, j_max, v_start, v_end);
  constexpr std::size_t widest = 32;  // W of doc/profiles.md eq. 37
  const std::size_t n = segments.size();
  std::vector<double> edge(n + 1, 0.0), boundary_limit(n + 1, v_start), best(n + 1, 0.0);
  boundary_limit[n] = v_end;
  for (std::size_t k = 0; k < n; ++k) edge[k + 1] = edge[k] + segments[k].length;
  for (std::size_t k = 1; k < n; ++k) boundary_limit[k] = std::min(segments[k - 1].limit, segments[k].limit);
  // The longest path of doc/profiles.md eq. 37 over windows [i, k) of at most `widest` segments.
  for (std::size_t k = 1; k <= n; ++k) {
    Window w{0.0, boundary_limit[k], 0.0, 0.0, j_max};
    for (std::size_t i = k; i-- > 0 && k - i <= widest;) {
      w.c_start = boundary_limit[i];
      w.top = std::max(w.top, segments[i].limit);
      w.a = std::max(w.a, detail::segment_acceleration(segments[i], a_max));
      best[k] = std::max(best[k], best[i] + least_window_time(w, edge[k] - edge[i]));
    }
  }
  return best[n];
}

}  // namespace dispkin
