// Jerk limiting by a moving average (jerk_filter.hpp).
#include "jerk_filter.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace dispkin::detail {
namespace {

// The interval holding t: the last knot ≤ t (clamped to [0, N − 1]).
std::size_t interval_at(const AccelerationSteps& law, double t) {
  const std::size_t n = law.acceleration.size();
  const auto next = std::upper_bound(law.time.begin(), law.time.end(), t);
  const std::size_t i = next == law.time.begin() ? 0 : static_cast<std::size_t>(next - law.time.begin()) - 1;
  return std::min(i, n - 1);
}

// u(t): zero outside [t_0, t_N).
double acceleration_at(const AccelerationSteps& law, double t) {
  if (!(t >= law.time.front()) || t >= law.time.back()) return 0.0;
  return law.acceleration[interval_at(law, t)];
}

// p(t) and ṗ(t), held at the ends.
void state_at(const AccelerationSteps& law, double t, double& p, double& v) {
  if (t <= law.time.front()) {
    p = law.position.front();
    v = 0.0;
    return;
  }
  if (t >= law.time.back()) {
    p = law.position.back();
    v = 0.0;
    return;
  }
  const std::size_t i = interval_at(law, t);
  const double dt = t - law.time[i], u = law.acceleration[i];
  p = law.position[i] + dt * (law.speed[i] + 0.5 * u * dt);
  v = law.speed[i] + u * dt;
}

// ∫_a^b (p(τ) − p(t_0)) dτ, a ≤ b, piece by piece.
double integral(const AccelerationSteps& law, double a, double b) {
  const double t0 = law.time.front(), tn = law.time.back(), p0 = law.position.front();
  double sum = 0.0;
  if (b > tn) {  // held at the end
    sum += (b - std::max(a, tn)) * (law.position.back() - p0);
    b = std::max(a, tn);
  }
  a = std::max(a, t0);  // before the start the integrand is 0
  if (!(b > a)) return sum;
  for (std::size_t i = interval_at(law, a); i < law.acceleration.size() && law.time[i] < b; ++i) {
    const double lo = std::max(a, law.time[i]) - law.time[i], hi = std::min(b, law.time[i + 1]) - law.time[i];
    if (!(hi > lo)) continue;
    const double u = law.acceleration[i], v = law.speed[i], p = law.position[i] - p0;
    // ∫ p + v τ + u τ²/2 dτ from lo to hi.
    auto antiderivative = [&](double tau) { return tau * (p + tau * (0.5 * v + u * tau / 6.0)); };
    sum += antiderivative(hi) - antiderivative(lo);
  }
  return sum;
}

// The knots of the law averaged over `window`: the law's knots and the same shifted by it, sorted.
std::vector<double> averaged_knots(const AccelerationSteps& law, double window) {
  std::vector<double> knots;
  knots.reserve(2 * law.time.size());
  for (const double t : law.time) {
    knots.push_back(t);
    knots.push_back(t + window);
  }
  std::sort(knots.begin(), knots.end());
  return knots;
}

// u(t) at non-decreasing t: the interval found by walking on from the last one, as interval_at
// finds it (the last knot ≤ t, at most N − 1), zero outside [t_0, t_N).
class AccelerationWalk {
 public:
  explicit AccelerationWalk(const AccelerationSteps& law) : law_(law) {}
  double at(double t) {
    if (!(t >= law_.time.front()) || t >= law_.time.back()) return 0.0;
    const std::size_t n = law_.acceleration.size();
    while (i_ + 1 < n && law_.time[i_ + 1] <= t) ++i_;
    return law_.acceleration[i_];
  }

 private:
  const AccelerationSteps& law_;
  std::size_t i_ = 0;
};

// max_t |u(t) − u(t−T)|, a step function whose steps are at the averaged law's knots (the law's
// knots and the same shifted by T), and how far T may move before that changes. Both knot lists
// are sorted, so they are merged in one walk and u is looked up by walking on. The steps depend
// on T only through the merged order of the knots: while T moves by less than half the smallest
// gap next to a shifted knot (less a rounding allowance) the same pairs of steps meet, and the
// largest difference is the same number (doc/retiming.md eq. 30).
struct StepScan {
  double largest;  // max_t |u(t) − u(t−T)|
  double steady;   // |T′ − T| below this: the same largest step
};

StepScan scan_steps(const AccelerationSteps& law, double window) {
  const std::vector<double>& time = law.time;
  const std::size_t m = time.size();
  AccelerationWalk now(law), earlier(law);
  std::size_t a = 0, b = 0;  // the next knot of the law and of the law shifted by T
  bool shifted = false;      // whether the knot just taken is a shifted one
  auto next_knot = [&] {
    shifted = !(b == m || (a < m && time[a] <= time[b] + window));
    return shifted ? time[b++] + window : time[a++];
  };
  double largest = 0.0, nearest = std::numeric_limits<double>::infinity();
  double previous = next_knot();
  bool previous_shifted = shifted;
  while (a < m || b < m) {
    const double t = next_knot();
    if (shifted || previous_shifted) nearest = std::min(nearest, t - previous);
    if (t > previous) {
      const double middle = 0.5 * (previous + t);
      largest = std::max(largest, std::abs(now.at(middle) - earlier.at(middle - window)));
    }
    previous = t;
    previous_shifted = shifted;
  }
  const double rounding = 16.0 * std::numeric_limits<double>::epsilon() * (std::abs(time.back()) + window);
  return {largest, std::max(0.0, 0.5 * nearest - rounding)};
}

}  // namespace

double smallest_window(const AccelerationSteps& law, double jerk, double upper) {
  double lo = 0.0, hi = upper;
  // The last scan serves every window within its steady range: once the bracket is narrower than
  // the gaps between knots, the bisection's remaining steps compare one number.
  double scanned = std::numeric_limits<double>::quiet_NaN();
  StepScan scan{0.0, 0.0};
  while (hi - lo > 1e-9 * upper) {
    const double mid = 0.5 * (lo + hi);
    if (!(std::abs(mid - scanned) < scan.steady)) {
      scan = scan_steps(law, mid);
      scanned = mid;
    }
    (scan.largest <= jerk * mid ? hi : lo) = mid;
  }
  return hi;
}

std::vector<JerkPhase> moving_average(const AccelerationSteps& law, double window, double& end_time) {
  const double t0 = law.time.front();
  end_time = law.time.back() + window;
  // The knots of the averaged law; those closer than rounding to the previous one merge.
  const std::vector<double> knots = averaged_knots(law, window);
  const double merge = 1e-12 * (end_time - t0);
  std::vector<double> kept;
  kept.reserve(knots.size());
  for (const double t : knots) {
    if (kept.empty() || t - kept.back() > merge) kept.push_back(t);
  }
  kept.back() = end_time;  // the last knot is the end (a merged neighbour must not move it)
  std::vector<JerkPhase> phases;
  phases.reserve(kept.size());
  const double p0 = law.position.front();
  for (std::size_t k = 0; k + 1 < kept.size(); ++k) {
    const double t = kept[k], d = kept[k + 1] - t, middle = t + 0.5 * d;
    double p, v, p_before, v_before;
    state_at(law, t, p, v);
    state_at(law, t - window, p_before, v_before);
    JerkPhase phase;
    phase.duration = d;
    phase.jerk = (acceleration_at(law, middle) - acceleration_at(law, middle - window)) / window;
    phase.position = k == 0 ? p0 : p0 + integral(law, t - window, t) / window;
    phase.speed = k == 0 ? 0.0 : (p - p_before) / window;
    phase.acceleration = k == 0 ? 0.0 : (v - v_before) / window;
    phases.push_back(phase);
  }
  return phases;
}

}  // namespace dispkin::detail
