// Profile::from_state: the time-optimal jerk-limited law from a moving, accelerating state
// (doc/profiles.md §7, equation numbers (16)–(24) below refer to it).
//
// The law is built as a short list of constant-jerk pieces: a brake into the limits when the
// start lies beyond them (§7.2), then one of three one-parameter families — peak laws (§7.3),
// relaxed laws (§7.4), dips through a trough (§7.5) — chosen by where S lies among their
// distances; the parameter is the root of "distance = S", found by a safeguarded root search
// (Brent's method on a bracket).
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "dispkin/error.hpp"
#include "dispkin/profile.hpp"
#include "jerk_kernels.hpp"
#include "message_number.hpp"

namespace dispkin {

using detail::number;  // message_number.hpp

namespace {

using Limits = detail::JerkLimits;
using detail::advance;
using detail::Motion;
using detail::natural_change;
using detail::Pulse;
using detail::pulse;

// --- the law as pieces -------------------------------------------------------------------------

// Constant-jerk pieces from (0, v_start, a_start), with the state at their end. Consecutive
// ramps of the same jerk (and holds at the same acceleration) are one piece: a brake into the
// limits followed by a ramp of the same sign stays within Profile::max_phases (doc/profiles.md §7.7).
struct Piece {
  double duration, jerk, a_start, a_end;
};
class Draft {
 public:
  Draft(double v_start, double a_start, const Limits& lim) : x_{0.0, v_start, a_start}, lim_(lim) {}

  const Motion& end() const { return x_; }
  int count() const { return count_; }
  const Piece& piece(int i) const { return pieces_[static_cast<std::size_t>(i)]; }
  int cruise_index() const { return cruise_; }

  //! Jerk ±j_max from the current acceleration to `a` (exactly `a` at the end).
  void ramp(double a) {
    const double j = a >= x_.a ? lim_.j_max : -lim_.j_max;
    push(std::abs(a - x_.a) * lim_.jerk_time, j, a);
  }
  //! Jerk 0 for `duration` at the current acceleration.
  void hold(double duration) { push(duration, 0.0, x_.a); }
  //! A cruise at the current velocity (acceleration 0), where the forward and backward
  //! integrations of the phases meet.
  void cruise(double duration) {
    if (duration > 0.0) cruise_ = count_;
    hold(duration);
  }
  //! (17) from the current acceleration to 0.
  void add(const Pulse& p) {
    ramp(p.sign * p.peak);
    hold(p.hold);
    ramp(0.0);
  }

 private:
  void push(double duration, double jerk, double a_end) {
    if (!(duration > 0.0)) return;
    const double a_start = x_.a;
    x_ = advance(x_, duration, jerk);
    x_.a = a_end;
    if (count_ > 0 && pieces_[static_cast<std::size_t>(count_ - 1)].jerk == jerk && cruise_ != count_ - 1) {
      Piece& last = pieces_[static_cast<std::size_t>(count_ - 1)];
      last.duration += duration;
      last.a_end = a_end;
      return;
    }
    if (count_ == static_cast<int>(pieces_.size())) {
      throw std::logic_error("Profile::from_state: more phases than the law can have (doc/profiles.md §7.7)");
    }
    pieces_[static_cast<std::size_t>(count_++)] = {duration, jerk, a_start, a_end};
  }

  std::array<Piece, Profile::max_phases> pieces_{};
  int count_ = 0;
  int cruise_ = -1;
  Motion x_;
  Limits lim_;
};

// The end state of a law without its pieces: the same steps as Draft (bit for bit the same end),
// for the root searches, which only need the distance a law covers.
class Endpoint {
 public:
  Endpoint(const Motion& x, const Limits& lim) : x_(x), lim_(lim) {}
  const Motion& end() const { return x_; }
  void ramp(double a) {
    x_ = advance(x_, std::abs(a - x_.a) * lim_.jerk_time, a >= x_.a ? lim_.j_max : -lim_.j_max);
    x_.a = a;
  }
  void hold(double duration) {
    if (duration > 0.0) x_ = advance(x_, duration, 0.0);
  }
  void cruise(double duration) { hold(duration); }
  void add(const Pulse& p) {
    ramp(p.sign * p.peak);
    hold(p.hold);
    ramp(0.0);
  }

 private:
  Motion x_;
  Limits lim_;
};

// --- §7.2 the brake into the limits ------------------------------------------------------------

// (18)–(19): back within |a| ≤ a_max at full jerk, and, where v + natural_change(a) > v_max,
// braking at −j (then −a_max) until it equals v_max: along a ramp at −j from (v, a) to a_b,
//   v + natural_change = v + a²/(2j) − a_b²/j  ⇒  a_b = −√(a²/2 + j (v − v_max)),
// and along the hold at −a_max it falls at the rate a_max. Returns whether the velocity was braked
// (v_n = v_max after it).
bool brake_into_limits(Draft& law, const Limits& lim) {
  if (law.end().a < -lim.a_max) law.ramp(-lim.a_max);
  const Motion& x = law.end();
  if (x.v + natural_change(x.a, lim) > lim.v_max) {
    const double a_b = -std::sqrt(0.5 * x.a * x.a + lim.j_max * (x.v - lim.v_max));
    if (a_b >= -lim.a_max) {
      law.ramp(a_b);
    } else {
      law.ramp(-lim.a_max);
      const double natural = law.end().v + natural_change(-lim.a_max, lim);
      law.hold(std::max(0.0, (natural - lim.v_max) / lim.a_max));
    }
    return true;
  }
  if (x.a > lim.a_max) law.ramp(lim.a_max);
  return false;
}

// --- §7.3–7.5: the three families -----------------------------------------------------------

// The start of the families: the state after the brake, and the velocities (16) that bound them.
// Each family appends its pieces to either a Draft (the law returned, holding the brake) or an
// Endpoint (the distance only, for the root searches).
struct Start {
  Motion braked;   //!< the state after the brake into the limits (the start state if none)
  double natural;  //!< v_n = v + natural_change(a) ≤ v_max
  double lowest;   //!< v_lo = max(v_n, v_end), the lowest peak of the family (20)
  double v_end;
  Limits lim;

  Endpoint endpoint() const { return Endpoint(braked, lim); }
};

// (20) Accelerate to a peak v_p = v_lo + w² ≥ v_lo with acceleration 0 there, cruise, decelerate
// to v_end: two pulses (17). The velocity steps are carried as c + w² (c exact), not as
// differences of velocities: a small step keeps its digits.
template <class Law>
void peak_law(Law& law, const Start& start, double w, double cruise) {
  const Motion& x = start.braked;
  const bool natural_above = start.natural >= start.v_end;
  const double c_up = natural_above ? natural_change(x.a, start.lim) : start.v_end - x.v;
  const double c_down = natural_above ? start.natural - start.v_end : 0.0;
  law.add(pulse(x.a, c_up + w * w, start.lim));
  law.cruise(cruise);
  law.add(pulse(0.0, -(c_down + w * w), start.lim));
}

// (22) Relax the acceleration from a towards zero, to a₁ (between a and 0), then the direct
// pulse (17) to v_end. Exists where the direct pulse and peak_law at w = 0 differ: a < 0 with
// v_end < v_n (ease the braking, brake again), a > 0 with v_end > v_n (ease the acceleration,
// accelerate again).
template <class Law>
void relaxed_law(Law& law, const Start& start, double a1) {
  law.ramp(a1);
  law.add(pulse(a1, start.v_end - law.end().v, start.lim));
}

// (24) Dip through a trough: a pulse down to (v_t, 0), v_t = v_hi − u² ≤ v_hi = min(v_n, v_end),
// then a pulse up to v_end — the velocity falls below the velocities the law starts from and ends
// at, and recovers. At u = 0 it is the shortest law of (20)–(22).
template <class Law>
void trough_law(Law& law, const Start& start, double u) {
  const Motion& x = start.braked;
  const bool natural_below = start.natural <= start.v_end;
  const double c_down = natural_below ? natural_change(x.a, start.lim) : start.v_end - x.v;
  const double c_up = natural_below ? start.v_end - start.natural : 0.0;
  law.add(pulse(x.a, c_down - u * u, start.lim));
  law.add(pulse(0.0, c_up + u * u, start.lim));
}

// The distances the root searches compare with S.
double peak_distance(const Start& start, double w) {
  Endpoint law = start.endpoint();
  peak_law(law, start, w, 0.0);
  return law.end().s;
}
double relaxed_distance(const Start& start, double a1) {
  Endpoint law = start.endpoint();
  relaxed_law(law, start, a1);
  return law.end().s;
}
double trough_distance(const Start& start, double u) {
  Endpoint law = start.endpoint();
  trough_law(law, start, u);
  return law.end().s;
}

// (20'') The peak of the peak law whose two pulses both hold ±a_max, in closed form: then
//   D(v_p) = v_p²/A + v_p A/j + C,   C = d₁ + (e c₁ − c₁²)/(2A) − A³/(6j²) − v_e²/(2A) + v_e A/(2j),
// e = A²/j, c₁ = v + e − a²/(2j) (the peak at which pulse 1 holds for no time), d₁ = the position
// at the end of its first ramp (a → A). The root of D = S; NaN unless both pulses really hold
// (v_p ≥ c₁ and v_p ≥ v_e + e). A starting point for the root search, exact in its case.
double held_peak(const Start& start, double distance) {
  const Limits& lim = start.lim;
  const Motion& x = start.braked;
  const double A = lim.a_max, e = A * A * lim.jerk_time, v_e = start.v_end;
  const double d1 = advance(x, (A - x.a) * lim.jerk_time, lim.j_max).s;
  const double c1 = x.v + e - 0.5 * x.a * x.a * lim.jerk_time;
  const double C = d1 + (e * c1 - c1 * c1) / (2.0 * A) - A * e * lim.jerk_time / 6.0 - v_e * v_e / (2.0 * A) +
                   0.5 * v_e * A * lim.jerk_time;
  const double q = distance - C;
  const double b = A * lim.jerk_time;  // v_p²/A + b v_p − q = 0
  const double peak = 2.0 * q / (b + std::sqrt(b * b + 4.0 * q / A));
  return peak >= c1 && peak >= v_e + e ? peak : std::numeric_limits<double>::quiet_NaN();
}

// --- safeguarded root search -------------------------------------------------------------------

// The root of an increasing f on [lo, hi] with f(lo) < 0 < f(hi): Brent's method (inverse
// quadratic interpolation and secant steps, bisection whenever they do not shrink the bracket
// fast enough), to a bracket of a few ulps or |f| ≤ f_tol (f is a distance minus S: once it is at
// rounding level, further steps change nothing the law can show).
template <class F>
double increasing_root(F f, double lo, double hi, double f_lo, double f_hi, double f_tol) {
  double a = lo, b = hi, fa = f_lo, fb = f_hi;
  double c = a, fc = fa, d = b - a, e = d;
  for (int iteration = 0; iteration < 200; ++iteration) {
    if ((fb > 0.0) == (fc > 0.0)) {
      c = a;
      fc = fa;
      d = e = b - a;
    }
    if (std::abs(fc) < std::abs(fb)) {
      a = b;
      b = c;
      c = a;
      fa = fb;
      fb = fc;
      fc = fa;
    }
    const double tol =
        2.0 * std::numeric_limits<double>::epsilon() * std::abs(b) + std::numeric_limits<double>::denorm_min();
    const double m = 0.5 * (c - b);
    if (std::abs(m) <= tol || std::abs(fb) <= f_tol) break;
    if (std::abs(e) >= tol && std::abs(fa) > std::abs(fb)) {
      const double s = fb / fa;
      double p, q;
      if (a == c) {
        p = 2.0 * m * s;
        q = 1.0 - s;
      } else {
        const double qa = fa / fc, r = fb / fc;
        p = s * (2.0 * m * qa * (qa - r) - (b - a) * (r - 1.0));
        q = (qa - 1.0) * (r - 1.0) * (s - 1.0);
      }
      if (p > 0.0)
        q = -q;
      else
        p = -p;
      if (2.0 * p < std::min(3.0 * m * q - std::abs(tol * q), std::abs(e * q))) {
        e = d;
        d = p / q;
      } else {
        d = e = m;
      }
    } else {
      d = e = m;
    }
    a = b;
    fa = fb;
    b += std::abs(d) > tol ? d : (m > 0.0 ? tol : -tol);
    fb = f(b);
  }
  return b;
}

// The rounding level of a distance S: a root search stops when the law's distance is within it.
double rounding(double distance) { return 4.0 * std::numeric_limits<double>::epsilon() * distance; }

// --- input checks ------------------------------------------------------------------------------

void check_input(double distance, const Limits& lim, double v_start, double a_start, double v_end) {
  require(std::isfinite(distance) && distance >= 0.0, "distance", distance, "must be finite and not negative");
  require_positive(lim.v_max, "v_max");
  require_positive(lim.a_max, "a_max");
  require_positive(lim.j_max, "j_max");
  require(std::isfinite(v_start) && v_start >= 0.0, "v_start", v_start, "must be finite and not negative");
  require_finite(a_start, "a_start");
  if (!(std::isfinite(v_end) && v_end >= 0.0 && v_end <= lim.v_max)) {
    throw std::invalid_argument(
        describe("v_end", v_end, "must be finite and within [0, v_max = " + number(lim.v_max) + "]"));
  }
  // (16) with a < 0: the acceleration returns to zero at full jerk at v + natural_change(a);
  // below zero the law would run backwards whatever it does.
  const double lowest = v_start + natural_change(std::min(a_start, 0.0), lim);
  if (lowest < 0.0) {
    throw std::invalid_argument(
        describe("a_start", a_start,
                 "brakes too hard for v_start = " + number(v_start) + " under j_max = " + number(lim.j_max) +
                     ": the velocity falls to " + number(lowest) +
                     " < 0 before the acceleration can return to zero (the law would run backwards)"));
  }
}

[[noreturn]] void throw_too_short(double distance, double needed, double v_start, double a_start, double v_end,
                                  const Limits& lim) {
  throw std::invalid_argument(describe(
      "distance", distance,
      "too short to go from v_start = " + number(v_start) + ", a_start = " + number(a_start) +
          " to v_end = " + number(v_end) + " under v_max = " + number(lim.v_max) + ", a_max = " + number(lim.a_max) +
          ", j_max = " + number(lim.j_max) + ": it needs at least " + number(needed) + ", " +
          number(needed - distance) + " more (even stopping on the way: no law reaches v_end in a shorter distance)"));
}

// (24) Below the shortest law without a dip (of distance `shortest` > S): the trough law with the
// highest trough v_t whose distance is S. From u = 0 (a law without a dip, longer than S) its
// distance rises for a shallow dip and may fall for a deeper one, to the stop-and-go law at
// v_t = 0; if that is at most S, S is crossed once on the way down. Else no law fits.
void dip(Draft& law, const Start& start, double shortest, double distance, double v_start, double a_start) {
  const double u_max = std::sqrt(std::max(0.0, std::min(start.natural, start.v_end)));
  const double deepest = trough_distance(start, u_max);
  if (deepest > distance) {
    throw_too_short(distance, std::min(shortest, deepest), v_start, a_start, start.v_end, start.lim);
  }
  auto shortfall = [&](double u) { return distance - trough_distance(start, u); };
  const double u = increasing_root(shortfall, 0.0, u_max, shortfall(0.0), distance - deepest, rounding(distance));
  trough_law(law, start, u);
}

// --- §7.6 choosing the law ---------------------------------------------------------------------

// (23) The law of §7 over `distance` (the brake's distance included), appended to `law` (the
// brake): peak_law with the largest feasible peak if it fits, else relaxed_law, else a dip, else
// too short (throws).
void solve(Draft& law, const Start& start, double distance, double v_start, double a_start) {
  const double w_max = std::sqrt(std::max(0.0, start.lim.v_max - start.lowest));
  // (21) v_p = v_max with a cruise over the rest.
  const double top = peak_distance(start, w_max);
  if (top <= distance) return peak_law(law, start, w_max, (distance - top) / start.lim.v_max);
  const double low = peak_distance(start, 0.0);
  if (low <= distance) {
    // (20) D(w) increasing from D(0) ≤ S to D(w_max) > S; the closed form (20'') narrows the
    // bracket, and is the root where both pulses hold a_max.
    auto excess = [&](double w) { return peak_distance(start, w) - distance; };
    double lo = 0.0, hi = w_max, f_lo = low - distance, f_hi = top - distance;
    const double held = held_peak(start, distance);
    if (held > start.lowest && held < start.lim.v_max) {
      const double w = std::sqrt(held - start.lowest);
      const double f = excess(w);
      if (std::abs(f) <= rounding(distance)) return peak_law(law, start, w, 0.0);
      if (f < 0.0) {
        lo = w;
        f_lo = f;
      } else {
        hi = w;
        f_hi = f;
      }
    }
    const double w = increasing_root(excess, lo, hi, f_lo, f_hi, rounding(distance));
    return peak_law(law, start, w, 0.0);
  }
  // (22) a₁ between a and 0: D increasing in a₁ up to D(0) of peak_law (> S).
  const double a = start.braked.a;
  const double v_n = start.natural;
  const bool relaxes = (a < 0.0 && start.v_end < v_n) || (a > 0.0 && start.v_end > v_n);
  if (!relaxes) return dip(law, start, low, distance, v_start, a_start);
  // The relaxed end a₁ = min(a, 0) is the shorter one for most starts, not for all (relaxing
  // takes longer, at lower velocities): only then do the relaxed laws fill (R(a_lo), D(0)).
  const double a_lo = std::min(a, 0.0), a_hi = std::max(a, 0.0);
  const double shortest = relaxed_distance(start, a_lo);
  if (shortest > distance) return dip(law, start, std::min(shortest, low), distance, v_start, a_start);
  auto excess = [&](double a1) { return relaxed_distance(start, a1) - distance; };
  const double a1 = increasing_root(excess, a_lo, a_hi, shortest - distance, low - distance, rounding(distance));
  relaxed_law(law, start, a1);
}

}  // namespace

Profile Profile::from_state(double distance, double v_max, double a_max, double j_max, double v_start, double a_start,
                            double v_end) {
  const Limits lim{v_max, a_max, j_max, 1.0 / j_max};
  check_input(distance, lim, v_start, a_start, v_end);

  Draft law(v_start, a_start, lim);
  const bool braked_to_limit = brake_into_limits(law, lim);
  const Motion braked = law.end();
  // After a brake v_n = v_max in exact arithmetic: taken as such (not a rounding-level peak above
  // it that would add vanishing phases).
  const double natural = braked_to_limit ? v_max : std::min(braked.v + natural_change(braked.a, lim), v_max);
  const Start start{braked, natural, std::max(natural, v_end), v_end, lim};
  // The brake alone may overrun S: then every family is too short.
  solve(law, start, distance, v_start, a_start);

  Profile p;
  p.kind_ = ProfileKind::scurve;
  p.distance_ = distance;
  p.start_ = {0.0, v_start, a_start, 0.0};
  p.end_ = {distance, v_end, 0.0, 0.0};
  int split = law.count() / 2;
  for (int i = 0; i < law.count(); ++i) {
    const Piece& piece = law.piece(i);
    if (i == law.cruise_index()) split = p.count_;
    p.add_phase(piece.duration, piece.jerk, piece.a_start, piece.a_end);
  }
  p.integrate(v_start, v_end, split);
  // The highest velocity: at the ends of the phases, or inside one where a crosses zero.
  double peak = std::max(v_start, v_end);
  for (int i = 0; i < p.count_; ++i) {
    const ProfilePhase& phase = p.phases_[static_cast<std::size_t>(i)];
    peak = std::max({peak, phase.start.v, phase.end.v});
    if (phase.start.a > 0.0 && phase.end.a < 0.0) {
      peak = std::max(peak, phase.start.v + phase.start.a * (phase.start.a / (-2.0 * phase.jerk)));
    }
  }
  p.peak_velocity_ = peak;
  if (!std::isfinite(p.duration())) {
    throw std::invalid_argument(describe("v_max", v_max,
                                         "with a_max = " + number(a_max) + ", j_max = " + number(j_max) +
                                             " over distance = " + number(distance) +
                                             ": the law's duration overflows the double range (limits outside "
                                             "dispkin's numeric range [1e-12, 1e12])"));
  }
  return p;
}

}  // namespace dispkin
