// Time laws under a velocity-limit curve and the planner's curvature rule (doc/profiles.md §5,
// doc/planning.md §4).
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>

#include <dispkin/planning/planner.hpp>
#include <dispkin/shapes.hpp>
#include <dispkin/planning/velocity_limit.hpp>

#include "random_cases.hpp"

namespace dispkin {
namespace {

using testing::message_of;
using testing::Random;

std::vector<LimitedSegment> random_segments(Random& rnd) {
  std::vector<LimitedSegment> segments;
  for (int k = rnd.integer(1, 6); k > 0; --k) segments.push_back({rnd.uniform(0.01, 1.0), rnd.uniform(0.05, 1.0)});
  return segments;
}

// The oracle for the trapezoid: the time-optimal velocity on a fine grid of s by the two
// passes v² ≤ v_prev² + 2a ds (forward and backward) under the limit; duration ∫ ds / v.
double grid_duration(const std::vector<LimitedSegment>& segments, double a) {
  double total = 0;
  for (const auto& g : segments) total += g.length;
  const int n = 200000;
  const double ds = total / n;
  std::vector<double> limit(n + 1), v(n + 1);
  for (int i = 0; i <= n; ++i) {
    // The limit at a grid node is the smaller one of the segments it touches.
    double s = i * ds, begin = 0, lim = 1e9;
    for (const auto& g : segments) {
      if (s >= begin - 1e-12 && s <= begin + g.length + 1e-12) lim = std::min(lim, g.limit);
      begin += g.length;
    }
    limit[i] = lim;
  }
  v[0] = 0;
  for (int i = 1; i <= n; ++i) v[i] = std::min(limit[i], std::sqrt(v[i - 1] * v[i - 1] + 2 * a * ds));
  v[n] = 0;
  for (int i = n; i-- > 0;) v[i] = std::min(v[i], std::sqrt(v[i + 1] * v[i + 1] + 2 * a * ds));
  double t = 0;
  for (int i = 0; i < n; ++i) t += 2 * ds / (v[i] + v[i + 1]);  // exact for constant acceleration
  return t;
}

TEST(VelocityLimit, TrapezoidChainIsTimeOptimal) {
  Random rnd(501);
  for (int i = 0; i < 100; ++i) {
    const auto segments = random_segments(rnd);
    const double a = rnd.uniform(0.2, 5.0);
    double duration = 0;
    for (const Profile& p : velocity_limited_law(segments, a, std::nullopt)) duration += p.duration();
    ASSERT_NEAR(duration, grid_duration(segments, a), 2e-4 * duration) << "case " << i;
  }
}

double total_duration(const std::vector<Profile>& laws) {
  double sum = 0.0;
  for (const Profile& p : laws) sum += p.duration();
  return sum;
}

// Checks a law under the staircase densely: laws in order, each within one segment; s, ṡ, s̈
// continuous where laws meet; 0 ≤ ṡ ≤ V_k, |s̈| ≤ A_k, |s⃛| ≤ j inside segment k; ends at rest.
void expect_within_staircase(const std::vector<Profile>& laws, const std::vector<LimitedSegment>& segments, double a,
                             double j, const std::string& where) {
  std::size_t k = 0;
  double s = 0.0, segment_end = segments[0].length, total = 0.0;
  for (const LimitedSegment& g : segments) total += g.length;
  ProfileState before{};
  for (std::size_t n = 0; n < laws.size(); ++n) {
    const Profile& p = laws[n];
    while (k + 1 < segments.size() && s >= segment_end - 1e-12 * total) segment_end += segments[++k].length;
    ASSERT_LE(s + p.distance(), segment_end + 1e-9 * total) << where << ": law " << n << " leaves segment " << k;
    const double a_k = segments[k].acceleration > 0.0 ? std::min(segments[k].acceleration, a) : a;
    const ProfileState first = p.state_at(0.0);
    ASSERT_NEAR(first.v, before.v, 1e-9) << where << ": velocity jumps before law " << n;
    ASSERT_NEAR(p.phase_count() > 0 ? p.phase(0).start.a : 0.0, before.a, 1e-6 * a)
        << where << ": acceleration jumps before law " << n;
    for (int m = 0; m <= 64; ++m) {
      const ProfileState st = p.state_at(p.duration() * m / 64.0);
      ASSERT_LE(st.v, segments[k].limit * (1 + 1e-9)) << where << ": law " << n << " in segment " << k;
      ASSERT_GE(st.v, -1e-12) << where;
      ASSERT_LE(std::abs(st.a), a_k * (1 + 1e-9)) << where << ": law " << n << " in segment " << k;
      ASSERT_LE(std::abs(st.j), j * (1 + 1e-12)) << where;
    }
    before = p.state_at(p.duration());
    if (p.phase_count() > 0) before.a = p.phase(p.phase_count() - 1).end.a;
    s += p.distance();
  }
  ASSERT_NEAR(s, total, 1e-9 * total) << where;
  ASSERT_NEAR(before.v, 0.0, 1e-9) << where;
}

// doc/profiles.md §8: the S-curve law carries acceleration across boundaries; on random
// staircases (lengths over three decades, per-segment accelerations) it keeps every limit densely
// and is never slower than the chain at rest boundaries.
TEST(VelocityLimit, CarriedAccelerationKeepsEveryLimitAndIsNeverSlower) {
  Random rnd(503);
  int faster = 0;
  const int count = 400;
  for (int i = 0; i < count; ++i) {
    std::vector<LimitedSegment> segments;
    for (int k = rnd.integer(1, 12); k > 0; --k) {
      const double own = rnd.uniform(0.0, 1.0) < 0.2 ? rnd.uniform(0.3, 3.0) : 0.0;
      segments.push_back({std::pow(10.0, rnd.uniform(-3.0, -0.5)), rnd.uniform(0.02, 0.5), own});
    }
    const double a = rnd.uniform(0.5, 3.5), j = std::pow(10.0, rnd.uniform(0.5, 3.0));
    const std::vector<Profile> laws = velocity_limited_law(segments, a, j);
    const double chain = total_duration(velocity_limited_chain(segments, a, j));
    const double law = total_duration(laws);
    // (the chain's laws cut in their cruises add their durations in another order: rounding)
    ASSERT_LE(law, chain * (1 + 1e-12)) << "case " << i;
    faster += law < chain * (1 - 1e-6);
    expect_within_staircase(laws, segments, a, j, "case " + std::to_string(i));
  }
  // The law is not the chain under another name: most staircases gain.
  EXPECT_GT(faster, count / 2);
}

// Where no limit binds, the time-optimal law is the one rest-to-rest S-curve over the whole
// staircase (doc/profiles.md §3): the law carrying acceleration is that law, whatever the
// boundaries — it holds a_max through them instead of returning to zero acceleration at each —
// to the resolution of its edges (10⁻⁹ a/j, doc/profiles.md eq. 31) in nearly every case. Where
// the rounding of the phases lets the last one reach the end of the path a hair before rest, the
// law creeps the rest of the way in three short phases (∝ ∛(δ/j)): within 0.2 % (doc/profiles.md §8.4).
TEST(VelocityLimit, WhereNoLimitBindsTheLawIsOneSCurve) {
  Random rnd(505);
  int checked = 0, exact = 0;
  for (int i = 0; i < 200; ++i) {
    std::vector<LimitedSegment> segments;
    double total = 0.0;
    for (int k = rnd.integer(2, 8); k > 0; --k) {
      segments.push_back({std::pow(10.0, rnd.uniform(-2.5, -1.0)), rnd.uniform(0.05, 1.0)});
      total += segments.back().length;
    }
    const double a = rnd.uniform(0.5, 3.0), j = std::pow(10.0, rnd.uniform(0.7, 2.5));
    const Profile one = Profile::scurve(total, 1e3, a, j);
    // Only staircases whose every limit the one law keeps (sampled densely) can be compared.
    bool under = true;
    for (int q = 0; q <= 2000 && under; ++q) {
      const ProfileState x = one.state_at(one.duration() * q / 2000.0);
      double begin = 0.0;
      for (const LimitedSegment& g : segments) {
        if (x.s >= begin - 1e-9 && x.s <= begin + g.length + 1e-9) under = under && x.v <= g.limit * (1.0 - 1e-3);
        begin += g.length;
      }
    }
    if (!under) continue;
    ++checked;
    const double law = total_duration(velocity_limited_law(segments, a, j));
    EXPECT_LE(law, one.duration() * 1.002) << "case " << i;
    exact += law <= one.duration() + 1e-8 * a / j;
  }
  EXPECT_GT(checked, 20);
  EXPECT_GE(exact, checked - checked / 20) << "of " << checked;
}

// A run that ends in the cruise of a long low segment (doc/profiles.md §8.3) is settled there
// exactly: a braking acceleration left over from the pulse into it, a rounding remainder, is
// brought back to zero instead of being held to the end of the run.
TEST(VelocityLimit, ARunSettlesInTheCruiseItEndsIn) {
  const std::vector<LimitedSegment> segments{{0.070116576226056021, 0.39905856061033707},
                                             {0.0068835232713444355, 0.18507482821005145},
                                             {0.064614526792126079, 0.05236938705450863},
                                             {0.053931515902718545, 0.40868124293842079}};
  const double a = 1.669837382109302, j = 12.414869387811136;
  const double chain = total_duration(velocity_limited_chain(segments, a, j));
  const std::vector<Profile> laws = velocity_limited_law(segments, a, j);
  expect_within_staircase(laws, segments, a, j, "settling run");
  EXPECT_LT(total_duration(laws), 0.98 * chain);
}

// A segment far shorter than its neighbours, crossed at speed (a staircase cut at nearly equal
// positions): its trapezoid rises by a S/(2v) ≪ v, which the ramps must not lose to cancellation
// (doc/profiles.md §6), and every law over the staircase is built and keeps its limits.
TEST(VelocityLimit, TinySegmentCrossedAtSpeed) {
  for (const double tiny : {1e-19, 1e-16, 1e-13, 1e-10}) {
    const Profile p = Profile::trapezoid(tiny, 0.0225, 1.0, 0.0219, 0.0219);
    EXPECT_NEAR(p.duration(), tiny / 0.0219, 1e-6 * tiny / 0.0219) << tiny;
    EXPECT_NO_THROW(Profile::trapezoid(tiny, 0.0225, 1.0, 0.0219, 0.0219 + 0.5 * tiny)) << tiny;
    std::vector<LimitedSegment> segments;
    for (int k = 0; k < 25; ++k) segments.push_back({2e-5, 0.002 + 0.0008 * k});
    segments.push_back({tiny, 0.0225});
    for (int k = 0; k < 25; ++k) segments.push_back({2e-5, 0.0225 + 0.0004 * k});
    EXPECT_NO_THROW(velocity_limited_law(segments, 1.0, std::nullopt)) << tiny;
    expect_within_staircase(velocity_limited_law(segments, 1.0, 10.0), segments, 1.0, 10.0,
                            "tiny " + std::to_string(tiny));
  }
}

// No law under a staircase beats the duration bound of doc/profiles.md §8.5: neither the law
// that carries acceleration nor the chain, with per-segment accelerations and moving ends.
TEST(VelocityLimit, NoLawBeatsTheDurationBound) {
  Random rnd(504);
  for (int i = 0; i < 300; ++i) {
    std::vector<LimitedSegment> segments;
    for (int k = rnd.integer(1, 12); k > 0; --k) {
      const double own = rnd.uniform(0.0, 1.0) < 0.2 ? rnd.uniform(0.3, 3.0) : 0.0;
      segments.push_back({std::pow(10.0, rnd.uniform(-3.0, -0.5)), rnd.uniform(0.02, 0.5), own});
    }
    const double a = rnd.uniform(0.5, 3.5), j = std::pow(10.0, rnd.uniform(0.5, 3.0));
    const double bound = jerk_limited_duration_bound(segments, a, j);
    ASSERT_GT(bound, 0.0) << "case " << i;
    ASSERT_GE(total_duration(velocity_limited_law(segments, a, j)), bound * (1 - 1e-12)) << "case " << i;
    // Moving ends: the chain from v_start to v_end (half the end limits, reachable when the
    // staircase is long enough; otherwise refused, and skipped).
    const double v0 = 0.5 * segments.front().limit, v1 = 0.5 * segments.back().limit;
    std::vector<Profile> chain;
    try {
      chain = velocity_limited_chain(segments, a, j, v0, v1);
    } catch (const std::invalid_argument&) {
      continue;
    }
    ASSERT_GE(total_duration(chain), jerk_limited_duration_bound(segments, a, j, v0, v1) * (1 - 1e-12)) << "case " << i;
  }
}

// The bound is doc/profiles.md eqs. 34–36: on one segment between two equal end limits c, with
// an acceleration limit A that lets the peak P = c + j T²/8 be reached at T/2, the envelope is
// cut by two ramps of slope A, D(T) = P T − (P − c)²/A, and τ is its root D(τ) = d.
TEST(VelocityLimit, DurationBoundOfOneWindowIsTheRootOfItsDistance) {
  for (const double c : {0.0, 0.05, 0.3}) {
    const double d = 0.01, j = 20.0;
    const double a = 1e3;
    const double bound = jerk_limited_duration_bound({{d, 10.0}}, a, j, c, c);
    const double peak = c + j * bound * bound / 8.0;
    EXPECT_NEAR(peak * bound - (peak - c) * (peak - c) / a, d, 1e-12 * d) << "c = " << c;
  }
}

// Where no law can reach the limit between two low ones — 8 mm moves at 0.2 m/s between blends
// held at 0.05 m/s, j = 20 m/s³ — the bound proves every jerk-limited law at least 10 % slower
// than the trapezoid law, however it carries its acceleration.
TEST(VelocityLimit, DurationBoundShowsWhatJerkCosts) {
  std::vector<LimitedSegment> segments;
  for (int k = 0; k < 20; ++k) {
    segments.push_back({0.008, 0.2});
    segments.push_back({0.002, 0.05});
  }
  const double a = 2.0, j = 20.0;
  const double bound = jerk_limited_duration_bound(segments, a, j);
  const double trapezoid = total_duration(velocity_limited_law(segments, a, std::nullopt));
  EXPECT_GT(bound, 1.1 * trapezoid);
  EXPECT_GE(total_duration(velocity_limited_law(segments, a, j)), bound);
}

// A smooth dip of the limit cut into many short segments: the chain, which must reach zero
// acceleration in each, can hardly change speed and crawls; the law that carries acceleration
// follows the dip within a few tens of percent of the trapezoid (the jerk-free optimum).
TEST(VelocityLimit, CarriedAccelerationFollowsAFinelyCutDip) {
  for (const int n : {100, 1000}) {
    std::vector<LimitedSegment> segments;
    for (int i = 0; i < n; ++i) {
      const double s = (i + 0.5) * 0.1 / n;
      segments.push_back({0.1 / n, 0.2 - 0.15 * std::exp(-std::pow((s - 0.05) / 0.01, 2))});
    }
    const double a = 2.0, j = 20.0;
    const std::vector<Profile> laws = velocity_limited_law(segments, a, j);
    expect_within_staircase(laws, segments, a, j, "dip of " + std::to_string(n));
    const double law = total_duration(laws), chain = total_duration(velocity_limited_chain(segments, a, j));
    const double trapezoid = total_duration(velocity_limited_law(segments, a, std::nullopt));
    EXPECT_LT(law, 0.5 * chain) << n << " segments";
    EXPECT_LT(law, 1.2 * trapezoid) << n << " segments";
  }
}

TEST(VelocityLimit, ChainKeepsEveryLimitAndJoins) {
  Random rnd(502);
  for (int i = 0; i < 2000; ++i) {
    const auto segments = random_segments(rnd);
    const double a = rnd.uniform(0.2, 5.0);
    const std::optional<double> j = i % 2 ? std::optional<double>(rnd.uniform(1.0, 100.0)) : std::nullopt;
    const std::vector<Profile> laws = velocity_limited_chain(segments, a, j);
    ASSERT_EQ(laws.size(), segments.size());
    double v_before = 0;
    for (std::size_t k = 0; k < laws.size(); ++k) {
      const Profile& p = laws[k];
      ASSERT_NEAR(p.distance(), segments[k].length, 1e-12);
      ASSERT_NEAR(p.state_at(0).v, v_before, 1e-9) << "velocity jumps at segment " << k;
      for (int m = 0; m <= 100; ++m) {
        const ProfileState st = p.state_at(p.duration() * m / 100.0);
        ASSERT_LE(st.v, segments[k].limit * (1 + 1e-12));
        ASSERT_LE(std::abs(st.a), a * (1 + 1e-12));
        if (j) {
          ASSERT_LE(std::abs(st.j), *j * (1 + 1e-12));
        }
      }
      const ProfileState end = p.state_at(p.duration());
      ASSERT_NEAR(end.s, segments[k].length, 1e-9);
      if (j) {
        ASSERT_NEAR(end.a, 0.0, 1e-9);
      }
      v_before = end.v;
    }
    ASSERT_NEAR(v_before, 0.0, 1e-9);
  }
}

TEST(VelocityLimit, BadInputIsRefused) {
  EXPECT_NE(message_of([] { velocity_limited_law({}, 1.0, std::nullopt); }).find("segments"), std::string::npos);
  EXPECT_NE(message_of([] {
              velocity_limited_law({{1.0, -1.0}}, 1.0, std::nullopt);
            }).find("segments[0].limit = -1"),
            std::string::npos);
  EXPECT_NE(message_of([] {
              velocity_limited_law({{1.0, 1.0}, {0.0, 1.0}}, 1.0, std::nullopt);
            }).find("segments[1].length = 0"),
            std::string::npos);
  EXPECT_NE(message_of([] {
              velocity_limited_law({{1.0, 1.0}}, 0.0, std::nullopt);
            }).find("a_max = 0"),
            std::string::npos);
  EXPECT_NE(message_of([] {
              velocity_limited_law({{1.0, 1.0}}, 1.0, std::nan(""));
            }).find("j_max = nan"),
            std::string::npos);
  EXPECT_NE(message_of([] {
              velocity_limited_law({{1.0, 1.0}}, 1.0, std::nullopt, 2.0);
            }).find("v_start = 2"),
            std::string::npos);
  EXPECT_NE(message_of([] {
              velocity_limited_law({{0.01, 1.0}}, 1.0, std::nullopt, 1.0, 0.0);
            }).find("cannot be reached"),
            std::string::npos);
}

// The curvature rule: in a tight blend the path slows down, and no point of the set then
// accelerates faster than 2a (s̈ ≤ a plus ṡ² times the curvature ≤ a), measured by central
// differences of the points' velocities away from section junctions.
TEST(VelocityLimit, TightBlendsSlowDownAndPointAccelerationsStayBounded) {
  using V = Eigen::Vector3d;
  const Posed a, via(Eigen::Quaterniond::Identity(), V(0.4, 0, 0)), b(Eigen::Quaterniond::Identity(), V(0.4, 0.4, 0));
  Path path = Path::lin(a, via);
  path.then(Path::lin(via, b), 0.01);
  MetricSetd set;
  set.add_relative(shapes::icosahedron(0.02));
  const Limits limits{0.5, 1.0, 20.0};
  const Trajectory traj = plan(path, set, limits);
  EXPECT_EQ(traj.piece_count(), 1u);
  EXPECT_GT(traj.law_count(), 1u);
  // In the blend's middle ṡ is well below v: the curvature radius is ≈ 7 mm, so √(a r) ≈ 0.09 m/s.
  double slowest_cruise = 1e9;
  std::vector<double> starts(traj.section_lengths().size());
  for (std::size_t k = 1; k < starts.size(); ++k) starts[k] = starts[k - 1] + traj.section_lengths()[k - 1];
  const auto crosses_junction = [&](double s0, double s1) {
    return std::upper_bound(starts.begin(), starts.end(), s0) != std::upper_bound(starts.begin(), starts.end(), s1);
  };
  // Central differences with a step far below the sections' duration (the blend's sections are
  // ~30 µm long), over the whole trajectory; windows across a junction are skipped.
  const double dt = 2e-6;
  double worst = 0;
  int measured = 0;
  for (double t = dt; t + dt < traj.duration(); t += (t > 0.7 && t < 1.3) ? dt : 1e-3) {
    const TrajectorySample p = traj.sample(t - dt), c = traj.sample(t), n = traj.sample(t + dt);
    if (c.s > 0.39 && c.s < 0.41) slowest_cruise = std::min(slowest_cruise, c.s_dot);
    if (crosses_junction(p.s, n.s)) continue;
    ++measured;
    for (const V& x : set.groups().front().relative_points) {
      const auto velocity = [&](const TrajectorySample& s) {
        return V(s.pose.quaternion() * (s.body_twist.linear + s.body_twist.angular.cross(x)));
      };
      worst = std::max(worst, (velocity(n) - velocity(p)).norm() / (2 * dt));
    }
  }
  EXPECT_GT(measured, 100000);
  EXPECT_LT(slowest_cruise, 0.2 * limits.velocity);
  EXPECT_LE(worst, 2 * limits.acceleration * 1.01);
}

}  // namespace
}  // namespace dispkin
