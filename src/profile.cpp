// The planning side of dispkin/profile.hpp: the time-optimal trapezoid and S-curve
// (doc/profiles.md §2–4).
//
// Both laws share one structure: change the velocity from v_s up to a peak v_p, cruise at v_p,
// change it down to v_e. Every velocity change starts and ends at zero acceleration (S-curve)
// or is one constant-acceleration ramp (trapezoid). The peak is the largest v_p ≤ v_max whose
// two changes fit in S: a higher peak gives a higher velocity at every position s, and the
// time is ∫ ds / v(s). The cruise at v_p covers what the changes leave of S.
#include "dispkin/profile.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "dispkin/error.hpp"
#include "message_number.hpp"
#include "profile_checks.hpp"

namespace dispkin {

using detail::number;            // message_number.hpp
using detail::require_distance;  // profile_checks.hpp

namespace {

// --- input checks ----------------------------------------------------------------------------

// The message is built only on failure: planning stays free of string work on the good path.
void require_boundary_velocity(double v, const char* name, double v_max) {
  if (!(std::isfinite(v) && v >= 0.0 && v <= v_max)) {
    throw std::invalid_argument(describe(name, v, "must be finite and within [0, v_max = " + number(v_max) + "]"));
  }
}

// Limits far below the distance (1e-308 m/s over 1 m) give a law whose duration overflows: refused
// naming the limits. The user-facing limits (Limits, MetricSet) are kept inside dispkin's numeric
// range, where this cannot happen; the laws themselves take any positive limit (re-timing
// builds them from derived accelerations), so they check their result instead.
// j_max: NaN for the trapezoid.
void require_finite_duration(const Profile& law, double distance, double v_max, double a_max, double j_max) {
  if (std::isfinite(law.duration())) return;
  const std::string jerk = std::isnan(j_max) ? "" : ", j_max = " + number(j_max);
  throw std::invalid_argument(describe("v_max", v_max,
                                       "with a_max = " + number(a_max) + jerk + " over distance = " + number(distance) +
                                           ": the law's duration overflows the double range (limits outside "
                                           "dispkin's numeric range [1e-12, 1e12])"));
}

[[noreturn]] void throw_too_short(double distance, double needed, double v_start, double v_end,
                                  const std::string& limits, const std::string& beyond) {
  throw std::invalid_argument(
      describe("distance", distance,
               "too short to change the velocity from v_start = " + number(v_start) + " to v_end = " + number(v_end) +
                   " under " + limits + ": it needs at least " + number(needed) + beyond + "; lower v_start or v_end"));
}

// --- trapezoid -------------------------------------------------------------------------------

// Distance of a constant-acceleration ramp between velocities v and w: |w² − v²| / (2a).
// (In this order the product does not underflow for tiny velocities and accelerations.)
double ramp_distance(double v, double w, double a_max) { return std::abs(w - v) * ((w + v) / (2.0 * a_max)); }

// The trapezoid's peak: v_p² / a − (v_s² + v_e²) / (2a) = S (two ramps, no cruise), capped
// at v_max and kept ≥ max(v_s, v_e) against rounding.
double trapezoid_peak(double distance, double v_max, double a_max, double v_start, double v_end) {
  const double lowest = std::max(v_start, v_end);
  if (ramp_distance(v_start, v_max, a_max) + ramp_distance(v_end, v_max, a_max) <= distance) return v_max;
  const double square = a_max * distance + 0.5 * (v_start * v_start + v_end * v_end);
  if (std::isnormal(square)) return std::clamp(std::sqrt(square), lowest, v_max);
  // a S and v² underflowed (tiny limits far outside the numeric range, doc/profiles.md §6):
  // √a √(S + (v_s² + v_e²)/(2a)).
  const double two_a = 2.0 * a_max;
  const double peak = std::sqrt(a_max) * std::sqrt(distance + v_start * (v_start / two_a) + v_end * (v_end / two_a));
  return std::clamp(peak, lowest, v_max);
}

// The rise v_p − v from the boundary velocity v to the trapezoid's peak, w the other boundary
// velocity. Where the peak is the root of v_p² = a S + (v² + w²)/2 and a S ≪ v², the difference
// cancels; (v_p² − v²)/(v_p + v) = (a S + (w − v)(w + v)/2)/(v_p + v) does not (doc/profiles.md §6).
double trapezoid_rise(double peak, double v, double w, double distance, double v_max, double a_max) {
  if (peak >= v_max || peak <= std::max(v, w)) return peak - v;
  const double square_gap = a_max * distance + 0.5 * (w - v) * (w + v);
  if (!std::isnormal(square_gap)) return peak - v;
  return std::max(0.0, square_gap / (peak + v));
}

// --- S-curve: one velocity change ------------------------------------------------------------

// The time-optimal change of velocity by dv ≥ 0 from zero to zero acceleration: jerk ±j for
// t_j on both sides of a hold at the peak acceleration a_p for t_a. a_max is reached iff
// dv ≥ a²/j (then t_j = a/j, t_a = dv/a − a/j); otherwise t_j = √(dv/j), t_a = 0, a_p = j t_j.
struct VelocityChange {
  double jerk_time = 0.0;
  double hold_time = 0.0;
  double peak_acceleration = 0.0;
  double duration() const { return 2.0 * jerk_time + hold_time; }
};

// Whether a change by dv reaches a_max: dv ≥ a²/j, compared as times, dv/a ≥ a/j (for tiny or
// huge limits the products dv j and a² under- or overflow where the quotients do not,
// doc/profiles.md §6).
bool reaches_a_max(double dv, double a_max, double j_max) { return dv / a_max >= a_max / j_max; }

VelocityChange velocity_change(double dv, double a_max, double j_max) {
  if (reaches_a_max(dv, a_max, j_max)) {
    const double jerk_time = a_max / j_max;
    return {jerk_time, std::max(0.0, dv / a_max - jerk_time), a_max};
  }
  const double jerk_time = std::sqrt(dv / j_max);
  return {jerk_time, 0.0, j_max * jerk_time};
}

// The acceleration profile of a change is symmetric in time, so its mean velocity is the mean
// of its end velocities: distance = (v + w)/2 · duration.
double change_distance(double v, double w, double a_max, double j_max) {
  return 0.5 * (v + w) * velocity_change(std::abs(w - v), a_max, j_max).duration();
}

// D(v_p): the distance of the two changes v_s → v_p → v_e without cruise.
double changes_distance(double peak, double v_start, double v_end, double a_max, double j_max) {
  return change_distance(v_start, peak, a_max, j_max) + change_distance(peak, v_end, a_max, j_max);
}

// d/dw of a change's duration when its velocity step is dv = c + w² (c ≥ 0): 2w/a if a_max is
// reached, else d/dw 2√((c + w²)/j) = 2w / √(j (c + w²)) (= 2/√j at c = w = 0).
double change_duration_slope(double c, double w, double a_max, double j_max) {
  const double dv = c + w * w;
  if (reaches_a_max(dv, a_max, j_max)) return 2.0 * w / a_max;
  const double root = std::sqrt(j_max) * std::sqrt(dv);
  return root > 0.0 ? 2.0 * w / root : 2.0 / std::sqrt(j_max);
}

// Rest-to-rest peak, closed form (v_s = v_e = 0, D(v_p) = v_p · T_change(v_p)):
//   a_max not reached (v_p ≤ a²/j):  D = 2 v_p √(v_p/j) = S   →  v_p = ∛(j S² / 4);
//   a_max reached:                   D = v_p (v_p/a + a/j) = S →  v_p² + (a²/j) v_p − a S = 0.
double scurve_rest_peak(double distance, double v_max, double a_max, double j_max) {
  if (changes_distance(v_max, 0.0, 0.0, a_max, j_max) <= distance) return v_max;
  const double r = a_max * (a_max / j_max);  // a²/j, the velocity step that just reaches a_max
  // Where j S² leaves the normal doubles (S below 1e-154 m: the law took 0 s), ∛(j/4) ∛S².
  const double cube = j_max * distance * distance / 4.0;
  const double cube_root_s = std::cbrt(distance);
  const double no_hold = std::isnormal(cube) ? std::cbrt(cube) : std::cbrt(0.25 * j_max) * cube_root_s * cube_root_s;
  if (no_hold <= r) return std::min(no_hold, v_max);
  // The positive root of the quadratic, in the form without cancellation. Where a S or r²
  // leave the normal doubles: with q = √a √S, 2 q (q / (r + hypot(r, 2q))).
  const double a_s = a_max * distance;
  if (std::isnormal(a_s) && std::isnormal(r * r))
    return std::min(2.0 * a_s / (r + std::sqrt(r * r + 4.0 * a_s)), v_max);
  const double q = std::sqrt(a_max) * std::sqrt(distance);
  return std::min(2.0 * q * (q / (r + std::hypot(r, 2.0 * q))), v_max);
}

// A peak and the two velocity steps to it, v_p − v_s and v_p − v_e, kept apart from v_p: a
// step recomputed as a difference of velocities loses the digits a small step needs.
struct Peak {
  double velocity, rise, fall;
};

// General peak between max(v_s, v_e) and v_max with D(v_p) = S, D increasing. Solved for
// w = √(v_p − max(v_s, v_e)), in which D is smooth (in v_p it has a √ at the low end), by
// Newton's method kept inside a bracket [w_lo, w_hi] with D(w_lo) ≤ S < D(w_hi), until the
// bracket or the Newton step is at rounding level.
Peak scurve_peak(double distance, double v_max, double a_max, double j_max, double v_start, double v_end) {
  const double lowest = std::max(v_start, v_end);
  const double c_start = lowest - v_start;  // velocity steps at w = 0: one of them is exactly 0
  const double c_end = lowest - v_end;
  // D(w) with the steps c + w² (not v_p − v): S − D at the root is then at rounding level.
  auto excess = [&](double w) {
    const double peak = lowest + w * w;
    return 0.5 * (v_start + peak) * velocity_change(c_start + w * w, a_max, j_max).duration() +
           0.5 * (peak + v_end) * velocity_change(c_end + w * w, a_max, j_max).duration() - distance;
  };
  // D = Σ_k (v_k + v_p)/2 · T_k with dv_p/dw = 2w:  dD/dw = w (T_s + T_e) + Σ_k (v_k + v_p)/2 · dT_k/dw.
  auto slope = [&](double w) {
    const double peak = lowest + w * w;
    const double t_start = velocity_change(c_start + w * w, a_max, j_max).duration();
    const double t_end = velocity_change(c_end + w * w, a_max, j_max).duration();
    return w * (t_start + t_end) + 0.5 * (v_start + peak) * change_duration_slope(c_start, w, a_max, j_max) +
           0.5 * (v_end + peak) * change_duration_slope(c_end, w, a_max, j_max);
  };
  if (excess(0.0) >= 0.0) return {lowest, c_start, c_end};  // S is exactly the direct change
  double lo = 0.0;
  double hi = std::sqrt(v_max - lowest);
  double w = 0.5 * hi;
  // Newton from above converges only linearly when the root is far below hi (D(w) − S behaves
  // like w³ near a root at w ≈ 0: a factor ≈ 2/3 per step), which a root at 1e-40 (S ≈ 1e-110 m)
  // needs ≈ 230 steps for: the cap leaves room down to the smallest doubles.
  for (int iteration = 0; iteration < 4000 && hi - lo > 2.0 * std::numeric_limits<double>::epsilon() * hi;
       ++iteration) {
    const double f = excess(w);
    if (f == 0.0) break;
    (f < 0.0 ? lo : hi) = w;
    const double d = slope(w);
    double next = d > 0.0 ? w - f / d : lo - 1.0;
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);  // Newton left the bracket: bisect
    if (next == w) break;                                   // converged to rounding
    w = next;
  }
  return {lowest + w * w, c_start + w * w, c_end + w * w};
}

// The cruise at v_p that covers what the two changes leave of S. A remainder at rounding level
// (the peak is a root of D(v_p) = S computed in floating point) is no cruise: the law then
// misses S by at most 64 ε S, and state_at's end state is exactly S.
double cruise_time(double distance, double changes, double peak) {
  const double rest = distance - changes;
  if (!(peak > 0.0) || rest <= 64.0 * std::numeric_limits<double>::epsilon() * distance) return 0.0;
  return rest / peak;
}

}  // namespace

// --- phases ----------------------------------------------------------------------------------

void Profile::add_phase(double duration, double jerk, double a_start, double a_end) noexcept {
  if (!(duration > 0.0)) return;
  ProfilePhase& p = phases_[static_cast<std::size_t>(count_)];
  p.duration = duration;
  p.jerk = jerk;
  p.start.a = a_start;
  p.end.a = a_end;
  p.start.j = p.end.j = jerk;
  time_[static_cast<std::size_t>(count_ + 1)] = time_[static_cast<std::size_t>(count_)] + duration;
  ++count_;
}

void Profile::integrate(double v_start, double v_end, int cruise) noexcept {
  // Forward: s₁ = s₀ + v₀ d + a₀ d²/2 + j d³/6, v₁ = v₀ + a₀ d + j d²/2.
  double s = 0.0;
  double v = v_start;
  for (int i = 0; i < std::min(cruise, count_); ++i) {
    ProfilePhase& p = phases_[static_cast<std::size_t>(i)];
    const double d = p.duration;
    const double a = p.start.a;
    p.start.s = s;
    p.start.v = v;
    s += d * (v + d * (0.5 * a + p.jerk * d / 6.0));
    v += d * (a + 0.5 * p.jerk * d);
    p.end.s = s;
    p.end.v = v;
  }
  if (cruise < count_) {
    phases_[static_cast<std::size_t>(cruise)].start.s = s;
    phases_[static_cast<std::size_t>(cruise)].start.v = v;
  }
  // Backward from the end state: s₀ = s₁ − v₁ d + a₁ d²/2 − j d³/6, v₀ = v₁ − a₁ d + j d²/2.
  s = distance_;
  v = v_end;
  for (int i = count_ - 1; i >= cruise; --i) {
    ProfilePhase& p = phases_[static_cast<std::size_t>(i)];
    const double d = p.duration;
    const double a = p.end.a;
    p.end.s = s;
    p.end.v = v;
    s -= d * (v - d * (0.5 * a - p.jerk * d / 6.0));
    v -= d * (a - 0.5 * p.jerk * d);
    if (i > cruise) {
      p.start.s = s;
      p.start.v = v;
    }
  }
}

// --- the two laws ----------------------------------------------------------------------------

Profile Profile::trapezoid(double distance, double v_max, double a_max, double v_start, double v_end) {
  require_distance(distance);
  require_positive(v_max, "v_max");
  require_positive(a_max, "a_max");
  require_boundary_velocity(v_start, "v_start", v_max);
  require_boundary_velocity(v_end, "v_end", v_max);
  const double needed = ramp_distance(v_start, v_end, a_max);
  // A change of velocity needs a positive distance, even where `needed` underflowed to 0.
  if (distance < needed || (distance == 0.0 && v_start != v_end)) {
    throw_too_short(distance, needed, v_start, v_end, "a_max = " + number(a_max), "");
  }

  Profile p;
  p.distance_ = distance;
  p.start_ = {0.0, v_start, 0.0, 0.0};
  p.end_ = {distance, v_end, 0.0, 0.0};
  const double peak = trapezoid_peak(distance, v_max, a_max, v_start, v_end);
  p.peak_velocity_ = peak;
  // Ramps (v_p − v)/a at ±a, each covering (v_p − v)(v_p + v)/(2a) (doc/profiles.md eq. 3); the cruise covers the
  // rest at v_p.
  const double up = trapezoid_rise(peak, v_start, v_end, distance, v_max, a_max);
  const double down = trapezoid_rise(peak, v_end, v_start, distance, v_max, a_max);
  const double ramps = up * ((peak + v_start) / (2.0 * a_max)) + down * ((peak + v_end) / (2.0 * a_max));
  const double cruise = cruise_time(distance, ramps, peak);
  p.add_phase(up / a_max, 0.0, a_max, a_max);
  const int cruise_index = p.count_;
  p.add_phase(cruise, 0.0, 0.0, 0.0);
  p.add_phase(down / a_max, 0.0, -a_max, -a_max);
  p.integrate(v_start, v_end, cruise_index);
  require_finite_duration(p, distance, v_max, a_max, std::numeric_limits<double>::quiet_NaN());
  p.require_consistent();
  return p;
}

// doc/profiles.md §7.8: above v_max the law brakes at −a_max to v_max first. The direct
// deceleration v_start → v_end is then the shortest law, and any distance beyond it is cruised
// at v_max (the brake ends there, and the deceleration to v_end starts there).
Profile Profile::trapezoid_from_state(double distance, double v_max, double a_max, double v_start, double v_end) {
  require_distance(distance);
  require_positive(v_max, "v_max");
  require_positive(a_max, "a_max");
  require(std::isfinite(v_start) && v_start >= 0.0, "v_start", v_start, "must be finite and not negative");
  require_boundary_velocity(v_end, "v_end", v_max);
  if (v_start <= v_max) return trapezoid(distance, v_max, a_max, v_start, v_end);
  const double needed = ramp_distance(v_start, v_end, a_max);
  if (distance < needed) {
    throw_too_short(
        distance, needed, v_start, v_end, "a_max = " + number(a_max),
        ", " + number(needed - distance) + " more (braking at a_max from above v_max = " + number(v_max) + ")");
  }

  Profile p;
  p.distance_ = distance;
  p.start_ = {0.0, v_start, 0.0, 0.0};
  p.end_ = {distance, v_end, 0.0, 0.0};
  p.peak_velocity_ = v_start;
  p.add_phase((v_start - v_max) / a_max, 0.0, -a_max, -a_max);
  const int cruise_index = p.count_;
  p.add_phase(cruise_time(distance, needed, v_max), 0.0, 0.0, 0.0);
  p.add_phase((v_max - v_end) / a_max, 0.0, -a_max, -a_max);
  p.integrate(v_start, v_end, cruise_index);
  require_finite_duration(p, distance, v_max, a_max, std::numeric_limits<double>::quiet_NaN());
  return p;
}

Profile Profile::scurve(double distance, double v_max, double a_max, double j_max, double v_start, double v_end) {
  require_distance(distance);
  require_positive(v_max, "v_max");
  require_positive(a_max, "a_max");
  require_positive(j_max, "j_max");
  require_boundary_velocity(v_start, "v_start", v_max);
  require_boundary_velocity(v_end, "v_end", v_max);
  const double lowest = std::max(v_start, v_end);
  const double needed = changes_distance(lowest, v_start, v_end, a_max, j_max);
  if (distance < needed || (distance == 0.0 && v_start != v_end)) {
    throw_too_short(distance, needed, v_start, v_end, "a_max = " + number(a_max) + ", j_max = " + number(j_max),
                    " with the accelerate-cruise-decelerate law (a shorter law would have to dip below both boundary "
                    "velocities, which is not supported, or does not exist)");
  }

  Profile p;
  p.kind_ = ProfileKind::scurve;
  p.distance_ = distance;
  p.start_ = {0.0, v_start, 0.0, 0.0};
  p.end_ = {distance, v_end, 0.0, 0.0};
  Peak peak;
  if (v_start == 0.0 && v_end == 0.0) {
    const double v = scurve_rest_peak(distance, v_max, a_max, j_max);
    peak = {v, v, v};
  } else if (changes_distance(v_max, v_start, v_end, a_max, j_max) <= distance) {
    peak = {v_max, v_max - v_start, v_max - v_end};
  } else {
    peak = scurve_peak(distance, v_max, a_max, j_max, v_start, v_end);
  }
  p.peak_velocity_ = peak.velocity;
  const VelocityChange up = velocity_change(peak.rise, a_max, j_max);
  const VelocityChange down = velocity_change(peak.fall, a_max, j_max);
  const double changes =
      0.5 * (v_start + peak.velocity) * up.duration() + 0.5 * (peak.velocity + v_end) * down.duration();
  const double cruise = cruise_time(distance, changes, peak.velocity);
  const double ua = up.peak_acceleration;
  const double da = down.peak_acceleration;
  // Phases 1–3: jerk +j to a_p, hold, jerk −j to 0.  4: cruise.  5–7: the mirror, down to v_e.
  p.add_phase(up.jerk_time, j_max, 0.0, ua);
  p.add_phase(up.hold_time, 0.0, ua, ua);
  p.add_phase(up.jerk_time, -j_max, ua, 0.0);
  const int cruise_index = p.count_;
  p.add_phase(cruise, 0.0, 0.0, 0.0);
  p.add_phase(down.jerk_time, -j_max, 0.0, -da);
  p.add_phase(down.hold_time, 0.0, -da, -da);
  p.add_phase(down.jerk_time, j_max, -da, 0.0);
  p.integrate(v_start, v_end, cruise_index);
  require_finite_duration(p, distance, v_max, a_max, j_max);
  p.require_consistent();
  return p;
}

}  // namespace dispkin
