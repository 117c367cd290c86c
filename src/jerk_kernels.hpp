// Kernels of jerk-limited laws shared by Profile::from_state and the staircase law that carries
// acceleration (internal): one constant-jerk piece (doc/profiles.md eq. 12), the natural velocity
// change (doc/profiles.md eq. 16) and the fastest change of velocity to zero acceleration, the pulse (eq. 17).
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

namespace dispkin::detail {

struct JerkLimits {
  double v_max, a_max, j_max;
  double jerk_time;  //!< 1/j_max: seconds per unit of acceleration at full jerk (products, not divisions)
};

// --- kernels -----------------------------------------------------------------------------------

// (16) The velocity change while the acceleration a returns to zero at full jerk: a|a|/(2j).
// v + natural_change(a) is the velocity every law from (v, a) passes through first or must
// overshoot; it is constant along a ramp that moves the acceleration towards zero.
inline double natural_change(double a, const JerkLimits& lim) { return a * (std::abs(a) * (0.5 * lim.jerk_time)); }

// (12) One constant-jerk piece: s, v, a after `d` seconds of jerk `j`.
struct Motion {
  double s, v, a;
};
inline Motion advance(const Motion& x, double d, double j) {
  return {x.s + d * (x.v + d * (0.5 * x.a + j * d / 6.0)), x.v + d * (x.a + 0.5 * j * d), x.a + j * d};
}

// (17) The time-optimal change of velocity by dv from acceleration a to acceleration 0: a ramp
// to ±p, a hold at ±p (only at p = a_max), a ramp to 0. Its direction is up when
// dv ≥ natural_change(a); mirrored (a → σa, dv → σdv) it is an increase with
//   p² = a²/2 + j dv   (no hold),   else  p = a_max,  hold = dv/p − p/j + a²/(2 j p).
struct Pulse {
  double sign;  //!< +1: the acceleration first rises (up), −1: first falls (down)
  double peak;  //!< p ≥ 0, the acceleration reached is sign · p
  double hold;  //!< time at sign · p
};
inline Pulse pulse(double a, double dv, const JerkLimits& lim) {
  const double sign = dv >= natural_change(a, lim) ? 1.0 : -1.0;
  const double am = sign * a, dm = sign * dv;
  // p² is a difference when a < 0: below its rounding error (a few ε a²) it is 0, else a
  // rounding-level velocity step would add two vanishing ramps.
  const double square = 0.5 * am * am + lim.j_max * dm;
  double peak = square > 4.0 * std::numeric_limits<double>::epsilon() * am * am ? std::sqrt(square) : 0.0;
  peak = std::max(peak, std::max(am, 0.0));  // p ≥ a in exact arithmetic: rounding only
  double hold = 0.0;
  if (peak > lim.a_max) {
    peak = lim.a_max;
    hold = std::max(0.0, dm / peak - peak / lim.j_max + am * (am / (2.0 * lim.j_max * peak)));
  }
  return {sign, peak, hold};
}

}  // namespace dispkin::detail
