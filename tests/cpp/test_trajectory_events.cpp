// Events on planned trajectories (doc/events.md): a stop on the path, a resumption and a speed
// override keep the motion before them bit for bit, hold every limit after them (the point-set
// limit by the oracle of doc/planning.md eq. 25), keep the pose continuous and end at rest.
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include <dispkin/planning/planner.hpp>

#include "random_cases.hpp"
#include "random_paths.hpp"

namespace dispkin {
namespace {

using V = Eigen::Vector3d;
using testing::message_of;
using testing::Random;
using testing::random_limits;
using testing::random_path;
using testing::random_set;
using testing::worst_speed_ratio;

// The samples of a and b agree bit for bit at `count` times spread over [0, t).
void expect_same_before(const Trajectory& a, const Trajectory& b, double t, int count, const std::string& what) {
  for (int i = 0; i < count; ++i) {
    const double at = t * i / count;
    const TrajectorySample x = a.sample(at), y = b.sample(at);
    ASSERT_EQ(x.s, y.s) << what << " t " << at;
    ASSERT_EQ(x.s_dot, y.s_dot) << what << " t " << at;
    ASSERT_EQ(x.s_ddot, y.s_ddot) << what << " t " << at;
    ASSERT_TRUE(x.pose.matrix() == y.pose.matrix()) << what << " t " << at;
  }
}

// |s̈| ≤ a_max and |s⃛| ≤ j_max (by differences of s̈), ṡ ≥ 0, and s continuous, on [t0, end].
void expect_within_limits(const Trajectory& traj, const TimeLawLimits& limits, double t0, const std::string& what) {
  const int n = 4000;
  const double dt = (traj.duration() - t0) / n;
  if (!(dt > 0.0)) return;
  TrajectorySample before = traj.sample(t0);
  double highest_jerk = 0.0;
  for (int i = 1; i <= n; ++i) {
    const TrajectorySample x = traj.sample(t0 + i * dt);
    ASSERT_GE(x.s_dot, -1e-9 * limits.acceleration) << what;
    ASSERT_LE(std::abs(x.s_ddot), limits.acceleration * (1.0 + 1e-9)) << what << " t " << t0 + i * dt;
    ASSERT_LE(x.s - before.s, std::max(x.s_dot, before.s_dot) * dt + limits.acceleration * dt * dt + 1e-12) << what;
    if (limits.jerk) highest_jerk = std::max(highest_jerk, std::abs(x.s_ddot - before.s_ddot) / dt);
    before = x;
  }
  if (limits.jerk) {
    EXPECT_LE(highest_jerk, *limits.jerk * (1.0 + 1e-6)) << what;
  }
}

struct Case {
  MetricSetd set;
  Path path;
  Limits limits;
  ProfileKind kind;
  Trajectory traj;
};

Case random_case(Random& rnd, int i) {
  const double v = rnd.uniform(0.05, 1.0);
  MetricSetd set = random_set(rnd, v);
  Path path = random_path(rnd, i);
  const ProfileKind kind = i % 2 ? ProfileKind::scurve : ProfileKind::trapezoid;
  const Limits limits = random_limits(rnd, v, kind);
  Trajectory traj = plan(path, set, limits, kind);
  return {std::move(set), std::move(path), limits, kind, std::move(traj)};
}

TEST(TrajectoryEvents, AStopKeepsTheMotionBeforeItAndEveryLimitAfter) {
  Random rnd(3001);
  for (int i = 0; i < testing::case_count(60); ++i) {
    const Case c = random_case(rnd, i);
    const double t = rnd.uniform(0.0, c.traj.duration());
    const Trajectory stopped = c.traj.stopped_at(t);
    const std::string what = "case " + std::to_string(i);
    expect_same_before(c.traj, stopped, t, 50, what);
    ASSERT_LE(stopped.duration(), c.traj.duration() * (1.0 + 1e-12)) << what;
    ASSERT_LE(worst_speed_ratio(stopped, c.set, c.limits.velocity, 4000), 1.0 + 1e-6) << what;
    expect_within_limits(stopped, *stopped.limits(), t, what);
    const TrajectorySample end = stopped.sample(stopped.duration());
    EXPECT_LE(std::abs(end.s_dot), 1e-12 * c.limits.velocity) << what;
    EXPECT_EQ(end.s, stopped.end_position()) << what;
    EXPECT_LE(end.s, c.traj.length()) << what;
    // The stop is on the path: the pose at rest is the planned path's pose there.
    Posed pose;
    Twistd twist;
    c.traj.path_state(end.s, pose, twist);
    EXPECT_TRUE(end.pose.is_approx(pose, 1e-12)) << what;
    EXPECT_TRUE(stopped.stopped() || end.s == c.traj.length()) << what;
  }
}

// The stop's duration is the 1-DoF time-optimal one (doc/events.md eq. 3), checked in closed form
// against states of every kind: accelerating, cruising, braking, beyond the acceleration limit.
TEST(TrajectoryEvents, TheFastestStopFromAnyState) {
  const double a = 2.0, j = 10.0;
  const Limits limits{1.0, a, j};
  MetricSetd set;
  set.add_relative(V(0, 0, 0));
  set.add_relative(V(0.1, 0, 0));
  set.add_relative(V(0, 0.1, 0));
  const Trajectory traj =
      plan(Path::lin(Posed(), Posed(Eigen::Matrix3d::Identity(), V(3.0, 0, 0))), set, limits, ProfileKind::scurve);
  for (double t :
       {0.05, 0.2, 0.4, 0.7, 1.5, 2.0, traj.duration() - 0.6, traj.duration() - 0.3, traj.duration() - 0.01}) {
    const TrajectorySample x = traj.sample(t);
    const Trajectory stopped = traj.stopped_at(t);
    // Down to −a_p at −j, hold, up at +j: v0 + (a0² − 2 a_p²) / 2j − a_p T = 0.
    const double v0 = x.s_dot, a0 = x.s_ddot;
    double expected;
    if (a0 < 0.0 && v0 - a0 * a0 / (2 * j) <= 1e-12) {
      expected = -a0 / j;
    } else {
      const double peak = std::sqrt(0.5 * (2 * j * v0 + a0 * a0));
      expected = peak <= a ? (a0 + 2 * peak) / j : (a0 + a) / j + (v0 + (a0 * a0 - 2 * a * a) / (2 * j)) / a + a / j;
    }
    EXPECT_NEAR(stopped.duration() - t, expected, 1e-12 * traj.duration()) << "t " << t;
  }
}

TEST(TrajectoryEvents, AResumptionReachesTheEndFromRestOrWhileBraking) {
  Random rnd(3002);
  for (int i = 0; i < testing::case_count(40); ++i) {
    const Case c = random_case(rnd, i);
    const double t_stop = rnd.uniform(0.0, c.traj.duration());
    const Trajectory stopped = c.traj.stopped_at(t_stop);
    if (!stopped.stopped()) continue;
    // Resumed after a wait at rest, or while still braking.
    const double t = i % 3 == 0 ? rnd.uniform(t_stop, stopped.duration()) : stopped.duration() + rnd.uniform(0.0, 1.0);
    const Trajectory resumed = stopped.resumed_at(t);
    const std::string what = "case " + std::to_string(i);
    EXPECT_FALSE(resumed.stopped()) << what;
    expect_same_before(stopped, resumed, std::min(t, stopped.duration()), 50, what);
    ASSERT_LE(worst_speed_ratio(resumed, c.set, c.limits.velocity, 4000), 1.0 + 1e-6) << what;
    expect_within_limits(resumed, *resumed.limits(), std::min(t, stopped.duration()), what);
    EXPECT_TRUE(resumed.sample(resumed.duration()).pose.is_approx(c.path.end(), 1e-9)) << what;
    EXPECT_LE(std::abs(resumed.sample(resumed.duration()).s_dot), 1e-12 * c.limits.velocity) << what;
  }
}

// Under an override the motion after t keeps every limit; below 1 the point-set limit × factor
// holds from the instant ṡ first falls below factor × the curve on (the change eases onto it).
TEST(TrajectoryEvents, AnOverrideHoldsTheScaledLimitsAndComposes) {
  Random rnd(3003);
  for (int i = 0; i < testing::case_count(60); ++i) {
    const Case c = random_case(rnd, i);
    const double t = rnd.uniform(0.0, c.traj.duration());
    const double factor = i % 4 == 0 ? rnd.uniform(1.0, 2.0) : rnd.uniform(0.1, 1.0);
    const Trajectory slower = c.traj.with_override(t, factor);
    const std::string what = "case " + std::to_string(i) + " factor " + std::to_string(factor);
    EXPECT_EQ(slower.override_factor(), factor) << what;
    expect_same_before(c.traj, slower, t, 50, what);
    ASSERT_LE(worst_speed_ratio(slower, c.set, c.limits.velocity, 4000), 1.0 + 1e-6) << what;
    expect_within_limits(slower, *slower.limits(), t, what);
    EXPECT_TRUE(slower.sample(slower.duration()).pose.is_approx(c.path.end(), 1e-9)) << what;
    if (factor < 1.0) {
      // The first law after t eases onto factor × the curve (braking at once where the state
      // lies above it); from its end on, ṡ is never above factor × the curve.
      double eased = t;
      for (const TimeLaw::Piece& p : slower.time_law().pieces())
        if (p.start_time >= t) {
          eased = p.end_time;
          break;
        }
      const TrajectorySample at_t = c.traj.sample(t);
      const double carried =
          at_t.s_dot + (c.limits.jerk ? std::max(at_t.s_ddot, 0.0) * at_t.s_ddot / (2.0 * *c.limits.jerk) : 0.0);
      const int n = 4000;
      for (int k = 0; k <= n; ++k) {
        const double at = t + (slower.duration() - t) * k / n;
        const TrajectorySample x = slower.sample(at);
        double limit = 0.0;
        for (const SpeedLimit& span : slower.speed_limits())
          if (x.s >= span.start_s - 1e-9 && x.s <= span.start_s + span.length + 1e-9)
            limit = std::max(limit, factor * span.limit);
        // Above the new limit only while easing down from the state at t.
        ASSERT_LE(x.s_dot, std::max(carried, limit) * (1.0 + 1e-9)) << what << " t " << at;
        if (at >= eased) {
          ASSERT_LE(x.s_dot, limit * (1.0 + 1e-6)) << what << " t " << at;
        }
      }
      EXPECT_GT(slower.duration(), c.traj.duration() * (1.0 - 1e-9)) << what;
    }
    // An override of an override: the factor is the new one, the motion before it the same.
    const double t2 = rnd.uniform(t, slower.duration());
    const Trajectory again = slower.with_override(t2, 1.0);
    expect_same_before(slower, again, t2, 20, what);
    EXPECT_TRUE(again.sample(again.duration()).pose.is_approx(c.path.end(), 1e-9)) << what;
    EXPECT_LE(worst_speed_ratio(again, c.set, c.limits.velocity, 2000), 1.0 + 1e-6) << what;
  }
}

TEST(TrajectoryEvents, RefusedWithAClearMessage) {
  MetricSetd set;
  set.add_relative(V(0, 0, 0));
  set.add_relative(V(0.1, 0, 0));
  set.add_relative(V(0, 0.1, 0));
  const Trajectory traj = plan(Path::lin(Posed(), Posed(Eigen::Matrix3d::Identity(), V(1.0, 0, 0))), set,
                               Limits{1.0, 2.0, 10.0}, ProfileKind::scurve);
  EXPECT_NE(message_of([&] { traj.with_override(0.5, 0.0); }).find("factor = 0"), std::string::npos);
  EXPECT_NE(message_of([&] { traj.with_override(0.5, 11.0); }).find("factor = 11"), std::string::npos);
  EXPECT_NE(message_of([&] { traj.stopped_at(std::nan("")); }).find("t = nan"), std::string::npos);
  EXPECT_NE(message_of([&] { traj.resumed_at(0.5); }).find("resumes a stopped trajectory only"), std::string::npos);
  const Trajectory retimed = traj.with_time_law(traj.time_law());
  EXPECT_NE(message_of([&] { retimed.stopped_at(0.5); }).find("holds no time-law limits"), std::string::npos);
  // Where it stopped is a rest with its reason; a law that ends early without one is refused (a
  // trajectory whose section lengths were stretched would otherwise pass for a stopped one).
  const Trajectory stopped = traj.stopped_at(0.3);
  ASSERT_TRUE(stopped.stopped());
  EXPECT_EQ(stopped.stops().back().reason.rfind("stopped at t = 0.3", 0), 0u);
  EXPECT_NE(message_of([&] {
              Trajectory(stopped.path(), stopped.time_law(), stopped.speed_limits(), stopped.rest_positions(), {}, {},
                         stopped.limits());
            }).find("unless the motion stopped there"),
            std::string::npos);
  const Trajectory resumed = stopped.resumed_at(5.0);
  EXPECT_EQ(resumed.stops().size(), traj.stops().size());
  EXPECT_EQ(resumed.rest_positions(), traj.rest_positions());
  // Before the start, it stops where it is; after the end it is the same trajectory.
  EXPECT_EQ(traj.stopped_at(-1.0).duration(), 0.0);
  EXPECT_EQ(traj.stopped_at(traj.duration() + 1.0).duration(), traj.duration());
}

// A tool of three points: under a translation each moves as the tool does.
MetricSetd three_points() {
  MetricSetd set;
  set.add_relative(V(0, 0, 0));
  set.add_relative(V(0.1, 0, 0));
  set.add_relative(V(0, 0.1, 0));
  return set;
}

// A plan from a moving state (PlanOptions::start_velocity, start_acceleration; doc/events.md §3)
// starts in that state and, along a straight move under one limit, is the 1-DoF time-optimal law
// from it (Profile::from_state: its durations are Ruckig's, tests/python/test_trajectory_events.py).
TEST(TrajectoryEvents, APlanFromAMovingState) {
  const MetricSetd set = three_points();
  const Path path = Path::lin(Posed(), Posed(Eigen::Matrix3d::Identity(), V(0.8, 0, 0)));
  const Limits limits{0.5, 2.0, 20.0};
  for (const auto& [v0, a0] : {std::pair{0.3, 1.5}, std::pair{0.5, 0.0}, std::pair{0.45, -1.8}, std::pair{0.1, 2.0}}) {
    PlanOptions options;
    options.start_velocity = v0;
    options.start_acceleration = a0;
    const Trajectory traj = plan(path, set, limits, ProfileKind::scurve, options);
    const TrajectorySample start = traj.sample(0.0);
    EXPECT_NEAR(start.s_dot, v0, 1e-12);
    EXPECT_NEAR(start.s_ddot, a0, 1e-12);
    EXPECT_NEAR(traj.duration(), Profile::from_state(traj.length(), 0.5, 2.0, 20.0, v0, a0, 0.0).duration(), 1e-12);
    EXPECT_TRUE(traj.rest_positions().empty() || traj.rest_positions().front() > 0.0);
    EXPECT_TRUE(traj.sample(traj.duration()).pose.is_approx(path.end(), 1e-12));
    expect_within_limits(traj, *traj.limits(), 0.0, "from (" + std::to_string(v0) + ", " + std::to_string(a0) + ")");
    // What it was planned with at rest, run from the same state.
    const Trajectory same = plan(path, set, limits).starting_from(v0, a0);
    EXPECT_EQ(same.duration(), traj.duration());
  }
  // The trapezoid starts from a velocity only.
  PlanOptions moving;
  moving.start_velocity = 0.2;
  const Trajectory trapezoid = plan(path, set, Limits{0.5, 2.0, std::nullopt}, ProfileKind::trapezoid, moving);
  EXPECT_NEAR(trapezoid.sample(0.0).s_dot, 0.2, 1e-12);
  EXPECT_NEAR(trapezoid.duration(), Profile::trapezoid_from_state(trapezoid.length(), 0.5, 2.0, 0.2, 0.0).duration(),
              1e-12);
}

TEST(TrajectoryEvents, AMovingStartIsRefusedWithAClearMessage) {
  const MetricSetd set = three_points();
  const Path path = Path::lin(Posed(), Posed(Eigen::Matrix3d::Identity(), V(0.1, 0, 0)));
  const auto refused = [&](double v0, double a0, ProfileKind kind = ProfileKind::scurve) {
    PlanOptions options;
    options.start_velocity = v0;
    options.start_acceleration = a0;
    return message_of([&] {
      plan(path, set, kind == ProfileKind::scurve ? Limits{0.5, 2.0, 20.0} : Limits{0.5, 2.0, std::nullopt}, kind,
           options);
    });
  };
  EXPECT_NE(refused(-0.1, 0.0).find("start_velocity = -0.1"), std::string::npos);
  EXPECT_NE(refused(std::nan(""), 0.0).find("start_velocity = nan"), std::string::npos);
  EXPECT_NE(refused(0.6, 0.0).find("start_velocity = 0.6: must be at most the velocity limit at the start"),
            std::string::npos);
  EXPECT_NE(refused(0.3, 2.5).find("start_acceleration = 2.5: must be within the acceleration limit"),
            std::string::npos);
  EXPECT_NE(refused(0.2, 1.0, ProfileKind::trapezoid).find("start_acceleration = 1: is not a state of the trapezoid"),
            std::string::npos);
  // Braking at 2 m/s² with jerk 20 m/s³ needs 0.1 m/s to end before ṡ = 0.
  EXPECT_NE(refused(0.05, -2.0).find("start_acceleration = -2: brakes harder than the jerk limit"), std::string::npos);
  // 0.5 m/s does not come to rest within 3 cm at 2 m/s² (it needs over 6 cm).
  PlanOptions fast;
  fast.start_velocity = 0.5;
  const std::string short_path = message_of([&] {
    plan(Path::lin(Posed(), Posed(Eigen::Matrix3d::Identity(), V(0.03, 0, 0))), set, Limits{0.5, 2.0, 20.0},
         ProfileKind::scurve, fast);
  });
  EXPECT_NE(short_path.find("start_velocity = 0.5"), std::string::npos) << short_path;
  EXPECT_NE(short_path.find("first run of the path"), std::string::npos) << short_path;
}

// A law is checked against every span it crosses, not only against the highest: a law that runs
// at 0.9 m/s into a span of 0.5 m/s is refused, though its peak is under the first span's 1 m/s.
TEST(TrajectoryEvents, ALawAboveALowerSpanItCrossesIsRefused) {
  const MetricSetd set = three_points();
  const Trajectory traj = plan(Path::lin(Posed(), Posed(Eigen::Matrix3d::Identity(), V(2.0, 0, 0))), set,
                               Limits{1.0, 2.0, std::nullopt}, ProfileKind::trapezoid);
  TimeLaw law;
  law.append(Profile::trapezoid(2.0, 0.9, 2.0), 0.0);
  law.end_run();
  const std::vector<SpeedLimit> spans{{0.0, 1.0, 1.0}, {1.0, 1.0, 0.5}};
  EXPECT_NE(message_of([&] {
              Trajectory(traj.path(), law, spans, {0.0, 2.0});
            }).find("must keep under the velocity limit of every span"),
            std::string::npos);
  // Under the lower span's limit throughout, the same law is accepted.
  const std::vector<SpeedLimit> higher{{0.0, 1.0, 1.0}, {1.0, 1.0, 0.9}};
  EXPECT_NO_THROW(Trajectory(traj.path(), law, higher, {0.0, 2.0}));
}

}  // namespace
}  // namespace dispkin
