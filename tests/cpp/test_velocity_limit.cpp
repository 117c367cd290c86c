// Time laws under a velocity-limit curve and the planner's curvature rule (doc/profiles.md §5,
// doc/planning.md §4).
#include <gtest/gtest.h>

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

TEST(VelocityLimit, LawsKeepEveryLimitAndJoin) {
  Random rnd(502);
  for (int i = 0; i < 2000; ++i) {
    const auto segments = random_segments(rnd);
    const double a = rnd.uniform(0.2, 5.0);
    const std::optional<double> j = i % 2 ? std::optional<double>(rnd.uniform(1.0, 100.0)) : std::nullopt;
    const std::vector<Profile> laws = velocity_limited_law(segments, a, j);
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
  EXPECT_NE(message_of([] { velocity_limited_law({{1.0, -1.0}}, 1.0, std::nullopt); }).find("segments[0].limit = -1"), std::string::npos);
  EXPECT_NE(message_of([] { velocity_limited_law({{1.0, 1.0}, {0.0, 1.0}}, 1.0, std::nullopt); }).find("segments[1].length = 0"), std::string::npos);
  EXPECT_NE(message_of([] { velocity_limited_law({{1.0, 1.0}}, 0.0, std::nullopt); }).find("a_max = 0"), std::string::npos);
  EXPECT_NE(message_of([] { velocity_limited_law({{1.0, 1.0}}, 1.0, std::nan("")); }).find("j_max = nan"), std::string::npos);
  EXPECT_NE(message_of([] { velocity_limited_law({{1.0, 1.0}}, 1.0, std::nullopt, 2.0); }).find("v_start = 2"), std::string::npos);
  EXPECT_NE(message_of([] { velocity_limited_law({{0.01, 1.0}}, 1.0, std::nullopt, 1.0, 0.0); }).find("cannot be reached"), std::string::npos);
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
