// Profiles (doc/profiles.md; doc/planning.md §8 item 8): seeded sweeps per family check the end
// state by an independent forward integration of the phases, every limit at the phase boundaries
// and densely, monotone s, continuity across phases, and the duration against the textbook closed
// forms. Durations against Ruckig: tests/python/test_profile.py.
#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <string>

#include <gtest/gtest.h>

#include "dispkin/profile.hpp"
#include "random_cases.hpp"

namespace dispkin {
namespace {

using testing::case_count;
using testing::message_of;
using testing::Random;

constexpr double kLimitTolerance = 1e-12;  // limits, relative
constexpr double kEndTolerance = 1e-9;     // final state, relative
constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

struct Limits {
  double distance, v_max, a_max, j_max, v_start, v_end;
};

::testing::AssertionResult fails(const Limits& c, const std::string& what) {
  return ::testing::AssertionFailure() << what << " for distance=" << c.distance << " v_max=" << c.v_max
                                       << " a_max=" << c.a_max << " j_max=" << c.j_max << " v_start=" << c.v_start
                                       << " v_end=" << c.v_end;
}

// 10^u, u uniform: limits and distances spanning decades.
double log_uniform(Random& random, double lo, double hi) {
  return std::pow(10.0, random.uniform(std::log10(lo), std::log10(hi)));
}

Limits random_limits(Random& random, bool boundary_velocities) {
  Limits c{};
  c.distance = log_uniform(random, 1e-6, 10.0);
  c.v_max = log_uniform(random, 1e-2, 10.0);
  c.a_max = log_uniform(random, 1e-2, 100.0);
  c.j_max = log_uniform(random, 1e-1, 1e4);
  if (boundary_velocities) {
    // Each boundary velocity 0, v_max or anywhere between, so the edges of [0, v_max] occur.
    auto boundary = [&] {
      const int k = random.integer(0, 4);
      return k == 0 ? 0.0 : k == 1 ? c.v_max : c.v_max * random.uniform(0.0, 1.0);
    };
    c.v_start = boundary();
    c.v_end = boundary();
  }
  return c;
}

// The state at the end of phase i from its start state (the same Taylor polynomial state_at
// uses from the start of a phase).
ProfileState end_from_start(const ProfilePhase& p) {
  const double d = p.duration;
  const ProfileState& x = p.start;
  return {x.s + x.v * d + x.a * d * d / 2 + p.jerk * d * d * d / 6, x.v + x.a * d + p.jerk * d * d / 2,
          x.a + p.jerk * d, p.jerk};
}

// The checks every profile of every family must pass.
::testing::AssertionResult satisfies_limits(const Profile& p, const Limits& c, bool scurve) {
  const double T = p.duration();
  const double v_tol = kLimitTolerance * c.v_max;
  const double a_tol = kLimitTolerance * c.a_max;
  const double s_scale = std::max(c.distance, p.peak_velocity() * T);  // ≤ 2 S for these laws
  if (!(T >= 0.0) || !std::isfinite(T)) return fails(c, "duration " + std::to_string(T));
  if (p.phase_count() > (scurve ? 7 : 3)) return fails(c, "too many phases");

  // 1. End state by an independent forward integration (long double) of durations and jerks:
  //    the S-curve's acceleration is integrated from 0, the trapezoid's is each phase's own.
  long double s = 0, v = c.v_start, a = 0, t = 0;
  for (int i = 0; i < p.phase_count(); ++i) {
    const ProfilePhase& ph = p.phase(i);
    const long double d = ph.duration, j = ph.jerk;
    if (!(ph.duration > 0.0)) return fails(c, "phase of zero or negative duration");
    if (!scurve) {
      if (ph.jerk != 0.0) return fails(c, "trapezoid phase with jerk");
      a = ph.start.a;
      if (!(a == c.a_max || a == 0.0 || a == -c.a_max)) return fails(c, "trapezoid acceleration not 0 or ±a_max");
    } else if (std::abs(ph.jerk) != c.j_max && ph.jerk != 0.0) {
      return fails(c, "S-curve jerk not 0 or ±j_max");
    }
    s += d * (v + d * (a / 2 + j * d / 6));
    v += d * (a + j * d / 2);
    a += j * d;
    t += d;
    if (std::abs(static_cast<double>(a)) > c.a_max + a_tol) return fails(c, "integrated acceleration exceeds a_max");
  }
  if (std::abs(static_cast<double>(t) - T) > 1e-12 * T) return fails(c, "phase durations do not sum to T");
  if (std::abs(static_cast<double>(s) - c.distance) > kEndTolerance * c.distance)
    return fails(c, "integrated end position " + std::to_string(static_cast<double>(s)));
  if (std::abs(static_cast<double>(v) - c.v_end) > kEndTolerance * c.v_max)
    return fails(c, "integrated end velocity " + std::to_string(static_cast<double>(v)));
  if (scurve && std::abs(static_cast<double>(a)) > kEndTolerance * c.a_max)
    return fails(c, "integrated end acceleration " + std::to_string(static_cast<double>(a)));

  // 2. Phase boundaries: limits at both ends of every phase; continuity of s, v (and a) from
  //    one phase's polynomial into the next phase's start; the ends of the law.
  auto within_limits = [&](const ProfileState& x) {
    return x.v >= -v_tol && x.v <= c.v_max + v_tol && std::abs(x.a) <= c.a_max + a_tol &&
           (!scurve || std::abs(x.j) <= c.j_max * (1 + kLimitTolerance)) && x.s >= -kLimitTolerance * s_scale &&
           x.s <= c.distance + kLimitTolerance * s_scale;
  };
  ProfileState previous{0.0, c.v_start, 0.0, 0.0};
  for (int i = 0; i < p.phase_count(); ++i) {
    const ProfilePhase& ph = p.phase(i);
    if (!within_limits(ph.start) || !within_limits(ph.end)) return fails(c, "limit exceeded at a phase boundary");
    const ProfileState at_start = p.state_at(p.phase_start_time(i));
    if (std::abs(previous.s - at_start.s) > kLimitTolerance * s_scale) return fails(c, "s jumps at a phase boundary");
    if (std::abs(previous.v - at_start.v) > v_tol) return fails(c, "v jumps at a phase boundary");
    if (scurve && std::abs(previous.a - at_start.a) > a_tol) return fails(c, "a jumps at a phase boundary");
    const ProfileState left = end_from_start(ph);
    if (std::abs(left.s - ph.end.s) > kLimitTolerance * s_scale || std::abs(left.v - ph.end.v) > v_tol ||
        std::abs(left.a - ph.end.a) > a_tol)
      return fails(c, "a phase's end state differs from its polynomial");
    previous = ph.end;
  }
  const ProfileState end = p.state_at(T);
  if (std::abs(previous.s - end.s) > kLimitTolerance * s_scale || std::abs(previous.v - end.v) > v_tol)
    return fails(c, "the last phase does not end at the end state");
  if (end.s != c.distance || end.v != c.v_end || end.a != 0.0 || end.j != 0.0) return fails(c, "end state");
  const ProfileState before = p.state_at(-1.0);
  if (before.s != 0.0 || before.v != c.v_start || before.a != 0.0) return fails(c, "start state");

  // 3. Densely: limits, s monotone (exactly: no rounding slack), s within [0, S].
  constexpr int kSamples = 256;
  double last_s = 0.0;
  for (int k = 0; k <= kSamples; ++k) {
    const ProfileState x = p.state_at(T * k / kSamples);
    if (!within_limits(x)) return fails(c, "limit exceeded at t = " + std::to_string(T * k / kSamples));
    if (x.s < last_s) return fails(c, "s decreases at t = " + std::to_string(T * k / kSamples));
    last_s = x.s;
  }
  return ::testing::AssertionSuccess();
}

// Textbook durations, rest to rest (e.g. Biagiotti & Melchiorri, Trajectory Planning for
// Automatic Machines and Robots, §3.2 and §3.4), written independently of the implementation.
double trapezoid_rest_duration(double S, double v, double a) {
  return S >= v * v / a ? S / v + v / a : 2.0 * std::sqrt(S / a);
}

double scurve_rest_duration(double S, double v, double a, double j) {
  // v_max reached: T = S/v + (v/a + a/j) if a_max is reached on the way to v, else S/v + 2√(v/j).
  if (v * j >= a * a) {
    if (S >= v * (v / a + a / j)) return S / v + v / a + a / j;
  } else if (S >= 2.0 * v * std::sqrt(v / j)) {
    return S / v + 2.0 * std::sqrt(v / j);
  }
  // v_max not reached: a_max reached iff S ≥ 2a³/j²; then T = a/j + √((a/j)² + 4S/a), else ∛(32 S/j).
  if (S >= 2.0 * a * a * a / (j * j)) return a / j + std::sqrt(a * a / (j * j) + 4.0 * S / a);
  return std::cbrt(32.0 * S / j);
}

// Trapezoid with boundary velocities: v_p = min(v_max, √(a S + (v_s² + v_e²)/2)),
// T = (v_p − v_s)/a + (v_p − v_e)/a + cruise.
double trapezoid_duration(const Limits& c) {
  const double a = c.a_max;
  const double peak = std::min(c.v_max, std::sqrt(a * c.distance + (c.v_start * c.v_start + c.v_end * c.v_end) / 2));
  const double ramps = (2 * peak * peak - c.v_start * c.v_start - c.v_end * c.v_end) / (2 * a);
  return (2 * peak - c.v_start - c.v_end) / a + (peak > 0 ? (c.distance - ramps) / peak : 0.0);
}

// The distance of the time-optimal change from v_start to v_end with zero acceleration at both
// ends (textbook: Δv/a + a/j if a_max is reached, i.e. Δv ≥ a²/j, else 2√(Δv/j), at the mean
// velocity): below it no accelerate-cruise-decelerate law exists.
double direct_change_distance(const Limits& c) {
  const double dv = std::abs(c.v_end - c.v_start);
  const double a = c.a_max, j = c.j_max;
  const double time = dv >= a * a / j ? dv / a + a / j : 2.0 * std::sqrt(dv / j);
  return 0.5 * (c.v_start + c.v_end) * time;
}

bool close(double x, double y, double tolerance) {
  return std::abs(x - y) <= tolerance * std::max(std::abs(y), 1e-300);
}

// --- sweeps ------------------------------------------------------------------------------------

TEST(Profile, TrapezoidRestToRestSweep) {
  Random random(401);
  const int n = case_count(10000);
  for (int i = 0; i < n; ++i) {
    const Limits c = random_limits(random, false);
    const Profile p = Profile::trapezoid(c.distance, c.v_max, c.a_max);
    ASSERT_TRUE(satisfies_limits(p, c, false)) << "case " << i;
    ASSERT_TRUE(close(p.duration(), trapezoid_rest_duration(c.distance, c.v_max, c.a_max), 1e-12))
        << "case " << i << ": " << p.duration() << " vs " << trapezoid_rest_duration(c.distance, c.v_max, c.a_max);
  }
}

TEST(Profile, ScurveRestToRestSweep) {
  Random random(402);
  const int n = case_count(10000);
  int a_reached = 0, v_reached = 0;
  for (int i = 0; i < n; ++i) {
    const Limits c = random_limits(random, false);
    const Profile p = Profile::scurve(c.distance, c.v_max, c.a_max, c.j_max);
    ASSERT_TRUE(satisfies_limits(p, c, true)) << "case " << i;
    const double expected = scurve_rest_duration(c.distance, c.v_max, c.a_max, c.j_max);
    ASSERT_TRUE(close(p.duration(), expected, 1e-12)) << "case " << i << ": " << p.duration() << " vs " << expected;
    a_reached += p.phase_count() == 7 || (p.phase_count() == 6 && p.phase(1).jerk == 0.0);
    v_reached += p.peak_velocity() == c.v_max;
  }
  // The sweep covers every structure (each in a fair share of the cases).
  EXPECT_GT(a_reached, n / 20);
  EXPECT_GT(v_reached, n / 20);
  EXPECT_GT(n - v_reached, n / 20);
}

TEST(Profile, TrapezoidBoundaryVelocitySweep) {
  Random random(403);
  const int n = case_count(10000);
  for (int i = 0; i < n; ++i) {
    Limits c = random_limits(random, true);
    // Keep the move feasible: S at least the ramp between the boundary velocities.
    c.distance += std::abs(c.v_end * c.v_end - c.v_start * c.v_start) / (2 * c.a_max);
    const Profile p = Profile::trapezoid(c.distance, c.v_max, c.a_max, c.v_start, c.v_end);
    ASSERT_TRUE(satisfies_limits(p, c, false)) << "case " << i;
    ASSERT_TRUE(close(p.duration(), trapezoid_duration(c), 1e-9)) << "case " << i;
  }
}

// The time law of a boundary-velocity S-curve must be tight: it either cruises at v_max or has
// no cruise at all (a longer peak would not fit). Optimality itself: against Ruckig in Python.
TEST(Profile, ScurveBoundaryVelocitySweep) {
  Random random(404);
  const int n = case_count(10000);
  int planned = 0, refused = 0;
  for (int i = 0; i < n; ++i) {
    Limits c = random_limits(random, true);
    const double needed = direct_change_distance(c);
    // Three cases in four made feasible (S ≥ the direct change); the rest as drawn.
    if (random.integer(0, 3) > 0) c.distance += needed;
    Profile p = Profile::trapezoid(0.0, 1.0, 1.0);
    try {
      p = Profile::scurve(c.distance, c.v_max, c.a_max, c.j_max, c.v_start, c.v_end);
    } catch (const std::invalid_argument& e) {
      ++refused;
      ASSERT_NE(std::string(e.what()).find("too short"), std::string::npos) << e.what();
      // Refused only when even the direct change v_start → v_end does not fit.
      ASSERT_LT(c.distance, needed * (1 + 1e-12)) << "case " << i << " refused: " << e.what();
      continue;
    }
    ++planned;
    ASSERT_TRUE(satisfies_limits(p, c, true)) << "case " << i;
    ASSERT_GE(p.peak_velocity(), std::max(c.v_start, c.v_end)) << "case " << i;
    bool cruises = false;
    double cruise_time = 0.0;
    for (int k = 0; k < p.phase_count(); ++k) {
      const ProfilePhase& ph = p.phase(k);
      if (ph.jerk == 0.0 && ph.start.a == 0.0) {
        cruises = true;
        cruise_time = ph.duration;
      }
    }
    ASSERT_TRUE(!cruises || p.peak_velocity() == c.v_max || p.peak_velocity() == std::max(c.v_start, c.v_end))
        << "case " << i << ": cruises " << cruise_time << " s below v_max, peak " << p.peak_velocity() << ", T "
        << p.duration() << ", S " << c.distance << " v " << c.v_start << " " << c.v_end << " " << c.v_max << " a "
        << c.a_max << " j " << c.j_max;
  }
  EXPECT_GT(planned, n / 2);
  EXPECT_GT(refused, 0);
}

// --- degenerate cases ------------------------------------------------------------------------------

TEST(Profile, ZeroDistanceAtRest) {
  for (const Profile& p : {Profile::trapezoid(0.0, 1.0, 2.0), Profile::scurve(0.0, 1.0, 2.0, 3.0)}) {
    EXPECT_EQ(p.duration(), 0.0);
    EXPECT_EQ(p.phase_count(), 0);
    const ProfileState x = p.state_at(0.0);
    EXPECT_EQ(x.s, 0.0);
    EXPECT_EQ(x.v, 0.0);
    EXPECT_EQ(x.a, 0.0);
    EXPECT_EQ(p.state_at(1.0).s, 0.0);
  }
}

TEST(Profile, ZeroDistanceAtEqualBoundaryVelocities) {
  const Profile p = Profile::scurve(0.0, 1.0, 2.0, 3.0, 0.5, 0.5);
  EXPECT_EQ(p.duration(), 0.0);
  EXPECT_EQ(p.state_at(0.0).v, 0.5);
  EXPECT_NE(message_of([] { Profile::scurve(0.0, 1.0, 2.0, 3.0, 0.5, 0.4); }).find("too short"), std::string::npos);
}

TEST(Profile, TinyDistance) {
  for (double S : {1e-15, 1e-12, 1e-9}) {
    const Limits c{S, 1.0, 1.0, 1.0, 0.0, 0.0};
    const Profile t = Profile::trapezoid(S, 1.0, 1.0);
    EXPECT_TRUE(satisfies_limits(t, c, false));
    EXPECT_EQ(t.phase_count(), 2);  // triangle
    EXPECT_NEAR(t.duration(), 2.0 * std::sqrt(S), 1e-15 * std::sqrt(S));
    const Profile s = Profile::scurve(S, 1.0, 1.0, 1.0);
    EXPECT_TRUE(satisfies_limits(s, c, true));
    EXPECT_EQ(s.phase_count(), 4);  // no constant acceleration, no cruise
    EXPECT_NEAR(s.duration(), std::cbrt(32.0 * S), 1e-15 * std::cbrt(32.0 * S));
  }
}

// The invariants a law keeps whatever its scale: finite duration; every phase boundary and 4096
// samples within 0 ≤ ṡ ≤ v, |s̈| ≤ a, |s⃛| ≤ j (1e-12 relative), 0 ≤ s ≤ S; s never decreasing;
// the end state exact; the phases' own integration (long double) ending at S to 1e-8 of the
// law's scale. Not checked, unlike satisfies_limits: continuity of state_at across a phase
// boundary, which at t = 1e10 s (one ulp 2e-6 s) cannot resolve a jerk phase of 1e-12 s.
::testing::AssertionResult keeps_invariants_at_scale(const Profile& p, const Limits& c) {
  const double T = p.duration();
  if (!(T >= 0.0) || !std::isfinite(T)) return fails(c, "duration " + std::to_string(T));
  const double s_scale = std::max(c.distance, p.peak_velocity() * T);
  auto within = [&](const ProfileState& x) {
    return x.v >= -kLimitTolerance * c.v_max && x.v <= c.v_max * (1 + kLimitTolerance) &&
           std::abs(x.a) <= c.a_max * (1 + kLimitTolerance) && std::abs(x.j) <= c.j_max * (1 + kLimitTolerance) &&
           x.s >= 0.0 && x.s <= c.distance * (1 + kLimitTolerance);
  };
  long double s = 0, v = c.v_start, a = 0;
  for (int i = 0; i < p.phase_count(); ++i) {
    const ProfilePhase& ph = p.phase(i);
    if (!(ph.duration > 0.0)) return fails(c, "phase of zero or negative duration");
    if (!within(ph.start) || !within(ph.end)) return fails(c, "limit exceeded at a phase boundary");
    const long double d = ph.duration, j = ph.jerk;
    if (p.kind() == ProfileKind::trapezoid) a = ph.start.a;
    s += d * (v + d * (a / 2 + j * d / 6));
    v += d * (a + j * d / 2);
    a += j * d;
  }
  if (std::abs(static_cast<double>(s) - c.distance) > 1e-8 * s_scale)
    return fails(c, "integrated end position " + std::to_string(static_cast<double>(s)));
  const ProfileState end = p.state_at(T);
  if (end.s != c.distance || end.v != c.v_end) return fails(c, "end state");
  double last_s = 0.0;
  for (int k = 0; k <= 4096; ++k) {
    const ProfileState x = p.state_at(T * k / 4096);
    if (!within(x)) return fails(c, "limit exceeded at t = " + std::to_string(T * k / 4096));
    if (x.s < last_s) return fails(c, "s decreases at t = " + std::to_string(T * k / 4096));
    last_s = x.s;
  }
  return ::testing::AssertionSuccess();
}

// The stated numeric range (README, "Numeric range"): distances 1e-7 … 1e4 m, speeds 1e-6 …
// 1e3 m/s, accelerations 1e-6 … 1e4 m/s², jerks 1e-6 … 1e6 m/s³ (durations up to 1e10 s). At
// every corner of that box, rest to rest and between boundary velocities, both laws keep their
// invariants (keeps_invariants_at_scale).
TEST(Profile, InvariantsHoldAtTheCornersOfTheNumericRange) {
  int laws = 0;
  double longest = 0.0;
  for (const double S : {1e-7, 1e4})
    for (const double v : {1e-6, 1e3})
      for (const double a : {1e-6, 1e4})
        for (const double j : {1e-6, 1e6})
          for (const double boundary : {0.0, 0.5}) {
            const double u = boundary * v;
            const Limits c{S, v, a, j, u, u};
            for (const bool scurve : {false, true}) {
              std::optional<Profile> law;
              try {
                law = scurve ? Profile::scurve(S, v, a, j, u, u) : Profile::trapezoid(S, v, a, u, u);
              } catch (const std::invalid_argument& e) {
                ASSERT_GT(u, 0.0) << e.what();  // rest to rest always fits
                ASSERT_NE(std::string(e.what()).find("too short"), std::string::npos) << e.what();
                continue;
              }
              ASSERT_TRUE(keeps_invariants_at_scale(*law, c)) << (scurve ? "S-curve" : "trapezoid");
              ++laws;
              longest = std::max(longest, law->duration());
            }
          }
  EXPECT_GE(laws, 32);      // every rest-to-rest corner at least
  EXPECT_GT(longest, 1e9);  // 1e4 m at 1e-6 m/s: 1e10 s
  EXPECT_TRUE(std::isfinite(longest));
}

// Far below the stated range (S = 1e-110 m, v_end = S) the S-curve's peak search stopped after 200
// Newton steps, far from its root, and the law overshot S by 4e3 S.
TEST(Profile, ScurvePeakSearchConvergesForTinyDistancesWithBoundaryVelocities) {
  for (const double S : {1e-110, 1e-150}) {
    for (const double u : {S, 0.5 * S}) {
      const Limits c{S, 1.0, 1.0, 1.0, 0.0, u};
      ASSERT_TRUE(satisfies_limits(Profile::scurve(S, 1.0, 1.0, 1.0, 0.0, u), c, true)) << S;
      const Limits d{S, 1.0, 1.0, 1.0, u, 0.0};
      ASSERT_TRUE(satisfies_limits(Profile::scurve(S, 1.0, 1.0, 1.0, u, 0.0), d, true)) << S;
    }
  }
}

// Outside the numeric range a law whose duration would overflow is refused, naming the limits
// (10 m at 1e-308 m/s: 1e309 s). Tiny accelerations and jerks alone do not overflow: the
// duration grows like their inverse square or cube root.
TEST(Profile, OverflowingDurationsAreRefused) {
  EXPECT_EQ(message_of([] { Profile::trapezoid(10.0, 1e-308, 1.0); }),
            "v_max = 1e-308: with a_max = 1 over distance = 10: the law's duration overflows the double range "
            "(limits outside dispkin's numeric range [1e-12, 1e12])");
  EXPECT_NE(message_of([] { Profile::trapezoid(1e300, 1e-12, 1.0); }).find("duration overflows"), std::string::npos);
  EXPECT_NE(
      message_of([] { Profile::scurve(10.0, 1e-308, 1.0, 1.0); }).find("v_max = 1e-308: with a_max = 1, j_max = 1"),
      std::string::npos);
  EXPECT_TRUE(std::isfinite(Profile::scurve(1.0, 1.0, 1e-308, 1e-308).duration()));
}

// Tiny and huge inputs far outside the numeric range (doc/profiles.md §6): the laws' formulas
// squared tiny or huge numbers (S², v², a S, dv j ≥ a²) and gave wrong laws — S = 7.7e-315 m took
// 6.7e7 s instead of 0.36 s, S = 1e-300 m at unit limits 0 s. Reordered (∛(j/4) ∛S², √a √S,
// dv/a ≥ a/j, |w − v| ((w + v) / 2a)), every case matches its textbook duration: with a
// cruise S/v + 2√(v/j) (a not reached), triangles 2√(S/a), four jerk phases ∛(32 S / j).
TEST(Profile, LawsFarOutsideTheNumericRangeMatchTheClosedForms) {
  struct Case {
    double S, v, a, j, trapezoid, scurve, tolerance;
  };
  // Subnormal S and v carry 32 significant bits or fewer, and so do the products of the law
  // that fall below 2.2e-308: those durations hold to 1e-8, the others to 1e-14.
  const double tiny = std::numeric_limits<double>::denorm_min();
  const double S10 = 7.7088128343660283e-315, v10 = 2.1220284314121648e-314;
  const double a10 = 4.780652035286447e-299, j10 = 2.848099973644035e-306;
  const double a2 = 8.2060724175491349e-304, j2 = 5.0781206641779257e-299;
  const Case cases[] = {
      {S10, v10, a10, j10, S10 / v10 + v10 / a10, S10 / v10 + 2.0 * std::sqrt(v10 / j10), 1e-8},  // S = 7.7e-315 m
      {tiny, 9.4978603296971489e-227, a2, j2, 2.0 * std::sqrt(tiny / a2), std::cbrt(32.0 * (tiny / j2)), 1e-8},
      {1e-300, 1.0, 1.0, 1.0, 2e-150, std::cbrt(32.0) * 1e-100, 1e-14},
      {1e-300, 1e300, 1e-300, 1e300, 2.0, 2.0, 1e-14},
      {1e200, 1.0, 1.0, 1.0, 1e200, 1e200, 1e-14},
  };
  const double resolution = 64.0 * tiny;
  for (const Case& c : cases) {
    const Profile t = Profile::trapezoid(c.S, c.v, c.a);
    const Profile s = Profile::scurve(c.S, c.v, c.a, c.j);
    EXPECT_NEAR(t.duration(), c.trapezoid, c.tolerance * c.trapezoid) << c.S;
    EXPECT_NEAR(s.duration(), c.scurve, c.tolerance * c.scurve) << c.S;
    for (const Profile* law : {&t, &s}) {
      double last = 0.0;
      for (int k = 0; k <= 1000; ++k) {
        const ProfileState x = law->state_at(law->duration() * k / 1000);
        ASSERT_GE(x.s, last - resolution) << c.S << " k = " << k;  // s never decreases
        ASSERT_LE(x.s, c.S * (1 + 1e-12) + resolution) << c.S << " k = " << k;
        ASSERT_GE(x.v, -resolution) << c.S << " k = " << k;
        ASSERT_LE(x.v, c.v * (1 + 1e-9) + resolution) << c.S << " k = " << k;
        ASSERT_LE(std::abs(x.a), c.a * (1 + 1e-12) + resolution) << c.S << " k = " << k;
        last = x.s;
      }
      EXPECT_EQ(law->state_at(law->duration()).s, c.S);
    }
  }
}

TEST(Profile, ScurveStructures) {
  // Every combination: v_max reached or not × a_max reached or not; a_max unreachable (v < a²/j).
  struct Expected {
    double distance, v_max, a_max, j_max;
    int phases;
  };
  for (const Expected& e : {Expected{10.0, 1.0, 1.0, 1.0, 5},     // v reached, a just reached (v = a²/j): no hold
                            Expected{10.0, 1.0, 0.5, 1.0, 7},     // v and a reached
                            Expected{1.0, 1.0, 0.5, 1.0, 6},      // a reached, v not
                            Expected{0.1, 1.0, 1.0, 1.0, 4},      // neither
                            Expected{10.0, 0.1, 1.0, 1.0, 5}}) {  // v reached, a never (v < a²/j)
    const Profile p = Profile::scurve(e.distance, e.v_max, e.a_max, e.j_max);
    EXPECT_EQ(p.phase_count(), e.phases) << e.distance << " " << e.v_max << " " << e.a_max;
    EXPECT_TRUE(satisfies_limits(p, {e.distance, e.v_max, e.a_max, e.j_max, 0.0, 0.0}, true));
    EXPECT_NEAR(p.duration(), scurve_rest_duration(e.distance, e.v_max, e.a_max, e.j_max), 1e-12);
  }
  // S = 1, v = a = j = 1: the textbook 4 ∛(S/2j) = 3.1748021039363987 (Ruckig gives the same).
  EXPECT_NEAR(Profile::scurve(1.0, 1.0, 1.0, 1.0).duration(), 3.1748021039363987, 1e-15);
}

TEST(Profile, CruiseOnlyAndOneSidedMoves) {
  const Profile cruise = Profile::scurve(2.0, 1.0, 1.0, 1.0, 1.0, 1.0);
  EXPECT_EQ(cruise.phase_count(), 1);
  EXPECT_DOUBLE_EQ(cruise.duration(), 2.0);
  // Exactly the distance of a velocity change from 0 to v_max: accelerate only, no peak above.
  const double S = 0.5 * 1.0 * (1.0 / 1.0 + 1.0 / 1.0);  // (v_s + v_e)/2 · (Δv/a + a/j)
  const Profile up = Profile::scurve(S, 1.0, 1.0, 1.0, 0.0, 1.0);
  EXPECT_TRUE(satisfies_limits(up, {S, 1.0, 1.0, 1.0, 0.0, 1.0}, true));
  EXPECT_NEAR(up.duration(), 2.0, 1e-15);
  const Profile down = Profile::trapezoid(0.5, 1.0, 1.0, 1.0, 0.0);
  EXPECT_EQ(down.phase_count(), 1);
  EXPECT_DOUBLE_EQ(down.duration(), 1.0);
}

TEST(Profile, StateAtOutsideTheLaw) {
  const Profile p = Profile::scurve(1.0, 1.0, 1.0, 1.0, 0.25, 0.5);
  const ProfileState before = p.state_at(-3.0), nan = p.state_at(kNaN), after = p.state_at(p.duration() + 7.0);
  EXPECT_EQ(before.s, 0.0);
  EXPECT_EQ(before.v, 0.25);
  EXPECT_EQ(nan.v, 0.25);
  EXPECT_EQ(after.s, 1.0);
  EXPECT_EQ(after.v, 0.5);
  EXPECT_EQ(after.a, 0.0);
  EXPECT_EQ(p.state_at(kInf).s, 1.0);
  // t = 0 belongs to the first phase: jerk +j.
  EXPECT_EQ(p.state_at(0.0).j, 1.0);
}

TEST(Profile, SampleMatchesStateAt) {
  const Profile p = Profile::scurve(3.0, 1.0, 2.0, 5.0);
  double times[5] = {-1.0, 0.0, 0.3, 1.7, 10.0};
  ProfileState out[5];
  p.sample(times, out, 5);
  for (int i = 0; i < 5; ++i) {
    EXPECT_EQ(out[i].s, p.state_at(times[i]).s);
    EXPECT_EQ(out[i].v, p.state_at(times[i]).v);
  }
}

// A law that would need the velocity to dip below both boundary velocities is refused as not
// supported: v_s = 0.01 → v_e = 1 (j = 1) needs 1.00509 without a dip; at S = 1.003 Ruckig
// finds a law whose velocity drops to 0.0038 first (tests/python/test_profile.py).
TEST(Profile, VelocityDipIsRefused) {
  const std::string m = message_of([] { Profile::scurve(1.003, 10.0, 100.0, 1.0, 0.01, 1.0); });
  EXPECT_EQ(m.rfind("distance = 1.003: too short", 0), 0u) << m;
  EXPECT_NE(m.find("not supported"), std::string::npos) << m;
  EXPECT_NO_THROW(Profile::scurve(1.006, 10.0, 100.0, 1.0, 0.01, 1.0));
}

}  // namespace
}  // namespace dispkin
