// Profile::from_state and Profile::trapezoid_from_state (doc/profiles.md §7): seeded random
// states inside and beyond the limits, every law sampled densely against the invariants of a
// law from a state; the laws from rest against Profile::scurve; the errors. Durations against
// Ruckig: tests/python/test_profile_from_state.py.
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <optional>
#include <string>
#include <type_traits>

#include <gtest/gtest.h>

#include "dispkin/profile.hpp"
#include "random_cases.hpp"

namespace dispkin {
namespace {

using testing::case_count;
using testing::message_of;
using testing::Random;

struct State {
  double distance, v_max, a_max, j_max, v_start, a_start, v_end;
};

std::string describe_case(const State& c) {
  char text[400];
  std::snprintf(text, sizeof text,
                "distance=%.17g v_max=%.17g a_max=%.17g j_max=%.17g v_start=%.17g a_start=%.17g v_end=%.17g",
                c.distance, c.v_max, c.a_max, c.j_max, c.v_start, c.a_start, c.v_end);
  return text;
}

double log_uniform(Random& random, double lo, double hi) {
  return std::pow(10.0, random.uniform(std::log10(lo), std::log10(hi)));
}

// (16): the velocity at which the acceleration, brought to zero at full jerk, is zero.
double natural_velocity(double v, double a, double j) { return v + a * std::abs(a) / (2.0 * j); }

// A random state. `beyond`: v_start above v_max, |a_start| above a_max, or a_start carrying the
// velocity above v_max; else inside every limit (and v_n ≤ v_max). Edges occur on purpose:
// a_start = ±a_max, v_end = v_max or 0, v_start = 0, v_n = v_max exactly.
State random_state(Random& random, bool beyond) {
  State c{};
  c.distance = log_uniform(random, 1e-6, 10.0);
  c.v_max = log_uniform(random, 1e-2, 10.0);
  c.a_max = log_uniform(random, 1e-2, 100.0);
  c.j_max = log_uniform(random, 1e-1, 1e4);
  for (;;) {
    c.v_start = c.v_max * random.uniform(0.0, 1.0);
    c.a_start = c.a_max * random.uniform(-1.0, 1.0);
    c.v_end = c.v_max * random.uniform(0.0, 1.0);
    switch (random.integer(0, 6)) {
      case 0:
        c.v_end = c.v_max;
        break;
      case 1:
        c.v_end = 0.0;
        break;
      case 2:
        c.a_start = random.integer(0, 1) ? c.a_max : -c.a_max;
        break;
      case 3:
        c.v_start = 0.0;
        c.a_start = std::abs(c.a_start);
        break;
      case 4:
        c.v_start = c.v_max - c.a_start * std::abs(c.a_start) / (2.0 * c.j_max);
        break;  // v_n = v_max
      default:
        break;
    }
    if (beyond) {
      switch (random.integer(0, 2)) {
        case 0:
          c.v_start = c.v_max * random.uniform(1.0, 3.0);
          break;
        case 1:
          c.a_start = c.a_max * random.uniform(1.0, 3.0) * (random.integer(0, 1) ? 1.0 : -1.0);
          break;
        default:
          c.a_start = std::abs(c.a_start);
          c.v_start = c.v_max - c.a_start * c.a_start / c.j_max * random.uniform(0.0, 0.5);
      }
    }
    const double v_n = natural_velocity(c.v_start, c.a_start, c.j_max);
    const bool inside = v_n <= c.v_max && c.v_start <= c.v_max && std::abs(c.a_start) <= c.a_max;
    if (c.v_start >= 0.0 && (c.a_start >= 0.0 || v_n >= 0.0) && inside != beyond) return c;
  }
}

// The needed distance a too-short message names ("it needs at least X, Y more").
double needed_distance(const std::string& message) {
  const auto at = message.find("it needs at least ");
  return at == std::string::npos ? std::numeric_limits<double>::quiet_NaN() : std::atof(message.c_str() + at + 18);
}

// The invariants of a law from a state, sampled at every phase boundary (both sides) and at 2000
// times; continuity compares the states just before and at each phase boundary.
::testing::AssertionResult is_law_from_state(const Profile& p, const State& c) {
  const auto fail = [&](const std::string& what) {
    return ::testing::AssertionFailure() << what << " for " << describe_case(c);
  };
  const double T = p.duration();
  if (!(T >= 0.0 && std::isfinite(T))) return fail("duration " + std::to_string(T));
  if (p.phase_count() > Profile::max_phases) return fail("too many phases");
  const double a_bound = std::max(c.a_max, std::abs(c.a_start));
  // The velocity an a_start > 0 carries the law to before it can brake (16), and above v_max
  // only while it falls to it.
  const double v_bound = std::max({c.v_max, c.v_start, natural_velocity(c.v_start, std::max(c.a_start, 0.0), c.j_max)});
  const double v_scale = v_bound + a_bound * T;
  const double v_tol = 1e-9 * v_scale, a_tol = 1e-9 * (a_bound + c.j_max * T),
               s_tol = 1e-9 * (c.distance + v_scale * T);

  const ProfileState first = p.state_at(0.0), last = p.state_at(T);
  if (first.s != 0.0 || std::abs(first.v - c.v_start) > 1e-12 * v_scale ||
      std::abs(first.a - c.a_start) > 1e-12 * a_bound)
    return fail("start state");
  if (last.s != c.distance || last.v != c.v_end || last.a != 0.0) return fail("end state (state_at(T))");
  // The last phase reaches the end state (not only the state held after the law).
  if (p.phase_count() > 0) {
    const ProfilePhase& ph = p.phase(p.phase_count() - 1);
    const double d = ph.duration;
    const double s = ph.start.s + d * (ph.start.v + d * (0.5 * ph.start.a + ph.jerk * d / 6.0));
    const double v = ph.start.v + d * (ph.start.a + 0.5 * ph.jerk * d);
    const double a = ph.start.a + ph.jerk * d;
    if (std::abs(s - c.distance) > s_tol || std::abs(v - c.v_end) > v_tol || std::abs(a) > a_tol)
      return fail("the last phase misses the end state by s " + std::to_string(s - c.distance) + ", v " +
                  std::to_string(v - c.v_end) + ", a " + std::to_string(a));
  }
  for (int i = 1; i < p.phase_count(); ++i) {
    const double t = p.phase_start_time(i);
    const ProfileState before = p.state_at(std::nextafter(t, 0.0)), at = p.state_at(t);
    if (std::abs(before.s - at.s) > s_tol || std::abs(before.v - at.v) > v_tol || std::abs(before.a - at.a) > a_tol)
      return fail("discontinuous at phase " + std::to_string(i));
  }
  double previous_s = 0.0, highest = 0.0;
  // Once inside the limits (ṡ ≤ v_max and v_n (16) ≤ v_max), the law stays there.
  bool came_down = false;
  const int n = 2000;
  for (int k = 0; k <= n; ++k) {
    const double t = T * k / n;
    const ProfileState x = p.state_at(t);
    if (std::abs(x.j) > c.j_max * (1 + 1e-12)) return fail("|jerk| above j_max at t = " + std::to_string(t));
    if (std::abs(x.a) > a_bound + a_tol) return fail("|a| above max(a_max, |a_start|) at t = " + std::to_string(t));
    if (x.v < -v_tol) return fail("runs backwards: v = " + std::to_string(x.v) + " at t = " + std::to_string(t));
    if (x.v > v_bound + v_tol) return fail("v above its bound at t = " + std::to_string(t));
    if (x.s < previous_s - s_tol) return fail("s decreases at t = " + std::to_string(t));
    // Above v_max the velocity only falls once it has peaked (the unavoidable rise of an
    // a_start > 0 first), and once at v_max it stays there or below.
    if (came_down && x.v > c.v_max + v_tol) return fail("back above v_max at t = " + std::to_string(t));
    if (!came_down && x.v < highest - v_tol && k > 0 && x.v > c.v_max + v_tol && x.a > a_tol)
      return fail("rises again above v_max at t = " + std::to_string(t));
    highest = std::max(highest, x.v);
    came_down = came_down || (x.v <= c.v_max && natural_velocity(x.v, std::max(x.a, 0.0), c.j_max) <= c.v_max);
    previous_s = x.s;
  }
  return ::testing::AssertionSuccess();
}

// Plans c; where the distance is too short, checks that the message names the distance needed and
// the shortfall, and plans again just beyond it (or, in one case of four, far beyond it).
Profile plan(State& c, Random& random, int& refused) {
  try {
    return Profile::from_state(c.distance, c.v_max, c.a_max, c.j_max, c.v_start, c.a_start, c.v_end);
  } catch (const std::invalid_argument& e) {
    const std::string m = e.what();
    EXPECT_EQ(m.rfind("distance = ", 0), 0u) << m;
    const double needed = needed_distance(m);
    EXPECT_GT(needed, c.distance) << m;
    EXPECT_NE(m.find(" more"), std::string::npos) << m;
    ++refused;
    // The message gives 12 digits: 1e-9 above them is above the distance needed.
    c.distance = needed * (1 + 1e-9) + (random.integer(0, 3) == 0 ? c.distance : 0.0);
    return Profile::from_state(c.distance, c.v_max, c.a_max, c.j_max, c.v_start, c.a_start, c.v_end);
  }
}

TEST(ProfileFromState, InvariantsInsideTheLimits) {
  Random random(20261204);
  int refused = 0;
  for (int k = 0; k < case_count(4000); ++k) {
    State c = random_state(random, false);
    const Profile p = plan(c, random, refused);
    ASSERT_TRUE(is_law_from_state(p, c));
    // Inside the limits no law leaves them.
    const ProfileState x = p.state_at(p.duration() / 3.0);
    ASSERT_LE(x.v, c.v_max * (1 + 1e-9)) << describe_case(c);
    ASSERT_LE(std::abs(x.a), c.a_max * (1 + 1e-9)) << describe_case(c);
  }
  EXPECT_GT(refused, 0);
}

TEST(ProfileFromState, InvariantsBeyondTheLimits) {
  Random random(20261205);
  int refused = 0;
  for (int k = 0; k < case_count(4000); ++k) {
    State c = random_state(random, true);
    const Profile p = plan(c, random, refused);
    ASSERT_TRUE(is_law_from_state(p, c));
    // Back within |a| ≤ a_max at full jerk: the first phase ramps towards the limit.
    if (std::abs(c.a_start) > c.a_max) {
      ASSERT_EQ(p.phase(0).jerk, c.a_start > 0.0 ? -c.j_max : c.j_max) << describe_case(c);
    }
  }
  EXPECT_GT(refused, 0);
}

// The corners of the stated numeric range (doc/guarantees-and-measurements.md): S 1e-7 … 1e4 m,
// v 1e-6 … 1e3, a 1e-6 … 1e4, j 1e-6 … 1e6, with starts at rest, halfway, at and beyond the
// limits; a distance too short is raised to the one the message names.
TEST(ProfileFromState, InvariantsAtTheCornersOfTheNumericRange) {
  Random random(20261209);
  int planned = 0, refused = 0;
  for (const double S : {1e-7, 1e4})
    for (const double v : {1e-6, 1e3})
      for (const double a : {1e-6, 1e4})
        for (const double j : {1e-6, 1e6})
          for (const double v0 : {0.0, 0.5, 1.0, 2.0})
            for (const double a0 : {0.0, 0.5, -0.5, 1.0, -1.0, 2.0})
              for (const double v1 : {0.0, 0.5, 1.0}) {
                State c{S, v, a, j, v0 * v, a0 * a, v1 * v};
                if (natural_velocity(c.v_start, std::min(c.a_start, 0.0), j) < 0.0) continue;
                const Profile p = plan(c, random, refused);
                ASSERT_TRUE(is_law_from_state(p, c));
                ++planned;
              }
  EXPECT_GT(planned, 900);
  EXPECT_GT(refused, 0);
}

// With a_start = 0 and both velocities in [0, v_max] the law is Profile::scurve's wherever that
// one exists (§7.3 at a = 0 is §3); where scurve refuses a dip, from_state's law dips.
TEST(ProfileFromState, FromRestAccelerationItIsTheScurve) {
  Random random(20261206);
  int compared = 0;
  for (int k = 0; k < case_count(4000); ++k) {
    State c = random_state(random, false);
    c.a_start = 0.0;
    std::optional<Profile> s;
    try {
      s = Profile::scurve(c.distance, c.v_max, c.a_max, c.j_max, c.v_start, c.v_end);
    } catch (const std::invalid_argument&) {
      // scurve refuses a law that has to dip: from_state dips (§7.5), or finds no law either.
      try {
        const Profile f = Profile::from_state(c.distance, c.v_max, c.a_max, c.j_max, c.v_start, 0.0, c.v_end);
        double lowest = c.v_start;
        for (int i = 0; i <= 1000; ++i) lowest = std::min(lowest, f.state_at(f.duration() * i / 1000.0).v);
        EXPECT_LT(lowest, std::min(c.v_start, c.v_end)) << describe_case(c);
      } catch (const std::invalid_argument&) {
      }
      continue;
    }
    const Profile f = Profile::from_state(c.distance, c.v_max, c.a_max, c.j_max, c.v_start, 0.0, c.v_end);
    ASSERT_NEAR(f.duration(), s->duration(), 1e-12 * s->duration() + 1e-300) << describe_case(c);
    ++compared;
  }
  EXPECT_GT(compared, case_count(4000) / 4);
}

TEST(ProfileFromState, Shapes) {
  // Cruise at v_max between an accelerating start and the deceleration: a ramp up, hold, down.
  const Profile cruise = Profile::from_state(10.0, 1.0, 1.0, 10.0, 0.2, 0.5, 0.0);
  EXPECT_EQ(cruise.phase_count(), 7);
  EXPECT_DOUBLE_EQ(cruise.peak_velocity(), 1.0);
  // A start at exactly v_n = v_max (0.8 + 0.4²/(2·0.4) = 1): the jerk is −j from the start.
  const Profile at_once = Profile::from_state(5.0, 1.0, 1.0, 0.4, 0.8, 0.4, 0.5);
  EXPECT_EQ(at_once.phase(0).jerk, -0.4);
  EXPECT_LE(at_once.peak_velocity(), 1.0 * (1 + 1e-12));
  // Beyond: v_start = 2 > v_max = 1 brakes (−j, hold at −a_max, +j) down to v_max and cruises.
  const Profile brake = Profile::from_state(10.0, 1.0, 1.0, 10.0, 2.0, 0.0, 0.0);
  EXPECT_EQ(brake.phase(0).jerk, -10.0);
  EXPECT_EQ(brake.phase(1).jerk, 0.0);
  EXPECT_EQ(brake.phase(1).start.a, -1.0);
  EXPECT_EQ(brake.phase(3).start.a, 0.0);
  EXPECT_NEAR(brake.phase(3).start.v, 1.0, 1e-12);
  // Easing the braking (a_start < 0, v_end below v_n): the acceleration rises, falls, rises.
  const Profile eased = Profile::from_state(0.8, 2.0, 1.0, 1.0, 1.0, -0.8, 0.2);
  ASSERT_GE(eased.phase_count(), 3);
  EXPECT_GT(eased.phase(0).jerk, 0.0);
  EXPECT_LT(eased.phase(0).end.a, 0.0);
  EXPECT_LT(eased.phase(1).jerk, 0.0);
  // A dip (§7.5): 0.01 → 1 m/s at j = 1 needs 1.00509 without one; over 1.003 the velocity first
  // falls below 0.01 (Ruckig: to 0.0038), then rises to 1.
  const Profile dip = Profile::from_state(1.003, 10.0, 100.0, 1.0, 0.01, 0.0, 1.0);
  ASSERT_EQ(dip.phase_count(), 3);  // −j, then +j through the trough (both pulses' ramps), −j
  EXPECT_LT(dip.phase(0).jerk, 0.0);
  const ProfilePhase& rise = dip.phase(1);
  const double trough = rise.start.v - rise.start.a * rise.start.a / (2.0 * rise.jerk);
  EXPECT_NEAR(trough, 0.0038, 0.0001);
  EXPECT_NEAR(dip.duration(), 2.15304312, 1e-8);  // Ruckig (min_velocity = 0): 2.1530431152599823
  // Nothing to do: at v_end with zero acceleration over zero distance.
  EXPECT_EQ(Profile::from_state(0.0, 1.0, 1.0, 1.0, 0.0, 0.0, 0.0).duration(), 0.0);
  EXPECT_EQ(Profile::from_state(0.0, 1.0, 1.0, 1.0, 0.0, 0.0, 0.0).phase_count(), 0);
}

TEST(ProfileFromState, PartsMakeTheSameLaw) {
  const Profile law = Profile::from_state(8.0, 1.0, 1.0, 2.0, 1.5, 2.0, 0.25);
  const Profile copy = Profile::from_parts(law.parts());
  for (int i = -10; i <= 1010; ++i) {
    const double t = law.duration() * i / 1000.0;
    const ProfileState x = copy.state_at(t), y = law.state_at(t);
    ASSERT_EQ(x.s, y.s);
    ASSERT_EQ(x.v, y.v);
    ASSERT_EQ(x.a, y.a);
  }
  static_assert(noexcept(law.state_at(0.0)), "evaluation is noexcept");
}

TEST(ProfileFromState, TooShortNamesTheShortfall) {
  // At 1 m/s with a = 0, j = 1, a_max = 10: stopping takes 2 s at the mean velocity 0.5: 1 m.
  const std::string m = message_of([] { Profile::from_state(0.75, 2.0, 10.0, 1.0, 1.0, 0.0, 0.0); });
  EXPECT_EQ(m.rfind("distance = 0.75: too short to go from v_start = 1, a_start = 0 to v_end = 0", 0), 0u) << m;
  EXPECT_NE(m.find("it needs at least 1, 0.25 more"), std::string::npos) << m;
  EXPECT_NO_THROW(Profile::from_state(1.0, 2.0, 10.0, 1.0, 1.0, 0.0, 0.0));
  // A brake from beyond the limits counts in the distance needed.
  const std::string b = message_of([] { Profile::from_state(0.5, 1.0, 10.0, 1.0, 1.5, 0.0, 1.0); });
  EXPECT_EQ(b.rfind("distance = 0.5: too short", 0), 0u) << b;
  EXPECT_GT(needed_distance(b), 0.5);
}

TEST(ProfileFromState, BadInput) {
  const auto starts = [](const std::string& m, const std::string& prefix) { return m.rfind(prefix, 0) == 0; };
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_TRUE(starts(message_of([&] { Profile::from_state(nan, 1, 1, 1); }), "distance = nan: must be finite"));
  EXPECT_TRUE(
      starts(message_of([] { Profile::from_state(-1, 1, 1, 1); }), "distance = -1: must be finite and not negative"));
  EXPECT_TRUE(
      starts(message_of([] { Profile::from_state(1, 0, 1, 1); }), "v_max = 0: must be finite and greater than zero"));
  EXPECT_TRUE(
      starts(message_of([] { Profile::from_state(1, 1, -1, 1); }), "a_max = -1: must be finite and greater than zero"));
  EXPECT_TRUE(starts(message_of([&] { Profile::from_state(1, 1, 1, nan); }),
                     "j_max = nan: must be finite and greater than zero"));
  EXPECT_TRUE(starts(message_of([] { Profile::from_state(1, 1, 1, 1, -0.5); }),
                     "v_start = -0.5: must be finite and not negative"));
  EXPECT_TRUE(starts(message_of([&] { Profile::from_state(1, 1, 1, 1, 0.5, nan); }), "a_start = nan: must be finite"));
  EXPECT_TRUE(starts(message_of([] { Profile::from_state(1, 1, 1, 1, 0.5, 0.0, 1.5); }),
                     "v_end = 1.5: must be finite and within [0, v_max = 1]"));
  // 0.1 m/s braking at 1 m/s² under j = 1: the acceleration is back at 0 only at 0.1 − 0.5 < 0.
  const std::string m = message_of([] { Profile::from_state(1, 1, 1, 1, 0.1, -1.0, 0.0); });
  EXPECT_TRUE(starts(m, "a_start = -1: brakes too hard for v_start = 0.1")) << m;
  EXPECT_NE(m.find("-0.4"), std::string::npos) << m;
}

// --- trapezoid_from_state ---------------------------------------------------------------------

TEST(ProfileFromState, TrapezoidBelowTheLimitIsTheTrapezoid) {
  Random random(20261207);
  for (int k = 0; k < case_count(2000); ++k) {
    const double v = log_uniform(random, 1e-2, 10.0), a = log_uniform(random, 1e-2, 100.0);
    const double v0 = v * random.uniform(0.0, 1.0), v1 = v * random.uniform(0.0, 1.0);
    const double S = std::abs(v1 * v1 - v0 * v0) / (2 * a) + log_uniform(random, 1e-6, 10.0);
    const Profile t = Profile::trapezoid(S, v, a, v0, v1), f = Profile::trapezoid_from_state(S, v, a, v0, v1);
    ASSERT_EQ(t.duration(), f.duration());
  }
}

TEST(ProfileFromState, TrapezoidBrakesFromAboveTheLimit) {
  Random random(20261208);
  for (int k = 0; k < case_count(2000); ++k) {
    const double v = log_uniform(random, 1e-2, 10.0), a = log_uniform(random, 1e-2, 100.0);
    const double v0 = v * random.uniform(1.0, 4.0), v1 = v * random.uniform(0.0, 1.0);
    const double needed = (v0 * v0 - v1 * v1) / (2 * a);
    const double S = needed * (1 + 1e-12) + (random.integer(0, 3) == 0 ? 0.0 : log_uniform(random, 1e-6, 10.0));
    const Profile p = Profile::trapezoid_from_state(S, v, a, v0, v1);
    // Closed form: brake to v_max, cruise over the rest, decelerate to v_end.
    const double T = (v0 - v) / a + (S - needed) / v + (v - v1) / a;
    ASSERT_NEAR(p.duration(), T, 1e-9 * T) << S << " " << v << " " << a << " " << v0 << " " << v1;
    EXPECT_EQ(p.peak_velocity(), v0);
    double previous = v0;
    for (int i = 0; i <= 500; ++i) {
      const ProfileState x = p.state_at(p.duration() * i / 500.0);
      ASSERT_LE(x.v, previous + 1e-12 * v0);  // never speeds up again
      ASSERT_GE(x.v, v1 - 1e-9 * v0);
      ASSERT_LE(std::abs(x.a), a);
      if (p.duration() * i / 500.0 >= (v0 - v) / a * (1 + 1e-12)) {
        ASSERT_LE(x.v, v * (1 + 1e-12));
      }
      previous = x.v;
    }
    const ProfileState end = p.state_at(p.duration());
    EXPECT_EQ(end.s, S);
    EXPECT_EQ(end.v, v1);
  }
  const std::string m = message_of([] { Profile::trapezoid_from_state(1.0, 1.0, 1.0, 2.0, 0.0); });
  EXPECT_EQ(m.rfind("distance = 1: too short", 0), 0u) << m;
  EXPECT_NE(m.find("it needs at least 2, 1 more"), std::string::npos) << m;
  EXPECT_EQ(message_of([] {
              Profile::trapezoid_from_state(1.0, 1.0, 1.0, -1.0, 0.0);
            }).rfind("v_start = -1: must be finite and not negative", 0),
            0u);
}

}  // namespace
}  // namespace dispkin
