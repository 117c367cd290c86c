// Continuous motion at full speed (doc/planning.md §9–§11): corners blended within a
// tolerance, LIN sections cut so that a cruise runs at the limit, per-move limits and the
// rotational limit — each checked against the guarantee's oracle (finite differences of the
// planned motion, doc/planning.md eq. 25).
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include <dispkin/planning/planner.hpp>
#include <dispkin/shapes.hpp>

#include "random_cases.hpp"
#include "random_paths.hpp"

namespace dispkin {
namespace {

using V = Eigen::Vector3d;
using testing::chord_speed_ratio;
using testing::message_of;
using testing::Random;
using testing::random_set;
using testing::worst_speed_ratio;

// |ω| of the motion over [t, t + dt], by the chord.
double chord_angular_speed(const Trajectory& traj, double t, double dt) {
  const Posed p = traj.sample(t).pose, q = traj.sample(t + dt).pose;
  return quaternion_log(Eigen::Quaterniond(p.quaternion().conjugate() * q.quaternion())).norm() / dt;
}

// The instants of a trajectory where it cruises: ṡ at the level of the velocity-limit curve and
// no path acceleration, away from the ends of each law (by `margin` of the duration).
std::vector<double> cruise_times(const Trajectory& traj, int steps) {
  std::vector<double> times;
  const double dt = traj.duration() / steps;
  for (int i = 1; i < steps - 1; ++i) {
    const double t = i * dt;
    const TrajectorySample a = traj.sample(t), b = traj.sample(t + dt);
    double level = 0.0;
    for (const SpeedLimit& l : traj.speed_limits())
      if (a.s >= l.start_s && a.s < l.start_s + l.length) level = l.limit;
    if (a.s_ddot == 0.0 && b.s_ddot == 0.0 && a.s_dot >= level * (1.0 - 1e-12) && b.s_dot >= level * (1.0 - 1e-12))
      times.push_back(t);
  }
  return times;
}

std::vector<Posed> random_pose_list(Random& rnd, int count, double step, double angle) {
  std::vector<Posed> poses{rnd.pose(0.5)};
  while (static_cast<int>(poses.size()) < count) poses.push_back(rnd.nearby(poses.back(), step, angle));
  return poses;
}

Path lins_through(const std::vector<Posed>& poses, const V& pivot = V::Zero()) {
  Path path = Path::lin(poses[0], poses[1], Interpolation::decoupled, pivot);
  for (std::size_t i = 2; i < poses.size(); ++i)
    path.then(Path::lin(poses[i - 1], poses[i], Interpolation::decoupled, pivot));
  return path;
}

// Every rotating decoupled LIN cruises with its fastest point at ≥ 99.5 % of the limit (it is
// cut where that point's speed varies), never above it.
TEST(ContinuousMotion, RotatingLinsCruiseAtTheLimit) {
  Random rnd(1801);
  const int n = std::max(50, testing::case_count(10000) / 10);
  int cruising = 0;
  for (int i = 0; i < n; ++i) {
    const double v = rnd.uniform(0.05, 0.5);
    const MetricSetd set = random_set(rnd, v);
    const Posed a = rnd.pose(0.5);
    const Path path = Path::lin(a, rnd.nearby(a, 0.4, 2.0), Interpolation::decoupled, rnd.vector(0.1));
    // An acceleration high enough for a long cruise (the curvature rule does not bind).
    const Limits limits{v, 50.0 * v, std::nullopt};
    const Trajectory traj = plan(path, set, limits, ProfileKind::trapezoid);
    ASSERT_EQ(traj.piece_count(), 1u) << "case " << i;
    ASSERT_LE(worst_speed_ratio(traj, set, v, 2000), 1.0 + 1e-6) << "case " << i;
    const std::vector<double> times = cruise_times(traj, 400);
    for (const double t : times) {
      const double s_dot = traj.sample(t).s_dot;
      const double ratio = chord_speed_ratio(traj, set, v, t, traj.duration() * 1e-6) * v / s_dot;
      ASSERT_GE(ratio, 0.995) << "case " << i << " t " << t << " of " << traj.duration();
      ASSERT_LE(ratio, 1.0 + 1e-6) << "case " << i;
    }
    cruising += !times.empty();
  }
  EXPECT_GT(cruising, n * 9 / 10);
}

// A list of poses with corner_tolerance: one continuous run, the guarantee, at most 1.15× the
// duration of the spline through the same poses.
TEST(ContinuousMotion, BlendedPoseListIsOneContinuousRun) {
  Random rnd(1802);
  const int n = std::max(8, testing::case_count(10000) / 500);
  for (int i = 0; i < n; ++i) {
    const double v = rnd.uniform(0.05, 0.3);
    const MetricSetd set = random_set(rnd, v);
    const std::vector<Posed> poses = random_pose_list(rnd, 21, 0.3, 0.8);
    double shortest = 1e300;
    for (std::size_t k = 1; k < poses.size(); ++k)
      shortest = std::min(shortest, (poses[k].translation() - poses[k - 1].translation()).norm());
    const Path path = lins_through(poses);
    const ProfileKind kind = i % 2 ? ProfileKind::scurve : ProfileKind::trapezoid;
    Limits limits{v, rnd.uniform(0.5, 3.0), std::nullopt};
    if (kind == ProfileKind::scurve) limits.jerk = rnd.uniform(5.0, 50.0);
    PlanOptions options;
    options.corner_tolerance = 0.1 * shortest;
    const Trajectory traj = plan(path, set, limits, kind, options);
    ASSERT_EQ(traj.piece_count(), 1u) << "case " << i << ": " << (traj.stops().empty() ? "" : traj.stops()[0].reason);
    ASSERT_TRUE(traj.stops().empty());
    ASSERT_LE(worst_speed_ratio(traj, set, v, 20000), 1.0 + 1e-6) << "case " << i;
    ASSERT_TRUE(traj.sample(traj.duration()).pose.is_approx(poses.back(), 1e-9));
    const Trajectory spline = plan(Path::spline(poses), set, limits, kind);
    EXPECT_LE(traj.duration(), 1.15 * spline.duration()) << "case " << i;
    // Without blending every corner stops, and says so.
    const Trajectory stopping = plan(path, set, limits, kind);
    EXPECT_EQ(stopping.stops().size(), poses.size() - 2);
    EXPECT_GT(stopping.duration(), traj.duration());
  }
}

// Distance from x to the polyline through `points`.
double polyline_distance(const V& x, const std::vector<V>& points) {
  double best = 1e300;
  for (std::size_t k = 1; k < points.size(); ++k) {
    const V d = points[k] - points[k - 1];
    const double t = std::clamp((x - points[k - 1]).dot(d) / d.squaredNorm(), 0.0, 1.0);
    best = std::min(best, (x - (points[k - 1] + t * d)).norm());
  }
  return best;
}

// A CAM-style polyline of 10³ points on a circle: blended with a tolerance of 1e-4 R it takes at
// most 1.05× the CIRC's duration and stays within the tolerance of the polyline.
TEST(ContinuousMotion, PolylineOfACircleRunsLikeTheCirc) {
  const double radius = 0.2;
  const int count = 1000;
  const Eigen::Quaterniond q = Eigen::Quaterniond::Identity();
  std::vector<Posed> poses;
  std::vector<V> points;
  for (int k = 0; k <= count; ++k) {
    const double angle = 1.5 * pi * k / count;  // three quarters of a circle
    points.emplace_back(radius * std::cos(angle), radius * std::sin(angle), 0.0);
    poses.push_back(Posed(q, points.back()));
  }
  MetricSetd set;
  set.add_relative(shapes::icosahedron(0.05));
  const Limits limits{0.1, 1.0, 10.0};
  PlanOptions options;
  options.corner_tolerance = 1e-4 * radius;
  const Trajectory traj = plan(lins_through(poses), set, limits, ProfileKind::scurve, options);
  EXPECT_EQ(traj.piece_count(), 1u) << (traj.stops().empty() ? "" : traj.stops()[0].reason);
  const Trajectory circ =
      plan(Path::circ(poses.front(), poses[count / 2], poses.back()), set, limits, ProfileKind::scurve);
  EXPECT_LE(traj.duration(), 1.05 * circ.duration());
  double deviation = 0.0;
  for (int i = 0; i <= 20000; ++i) {
    deviation =
        std::max(deviation, polyline_distance(traj.sample(traj.duration() * i / 20000).pose.translation(), points));
  }
  EXPECT_LE(deviation, options.corner_tolerance * (1.0 + 1e-9));
  EXPECT_LE(worst_speed_ratio(traj, set, limits.velocity, 20000), 1.0 + 1e-6);
}

// Corners the blends cannot round stop, and say why; a rotation-only junction is blended.
TEST(ContinuousMotion, StopsWhereNoBlendFits) {
  MetricSetd set;
  set.add_relative(shapes::icosahedron(0.05));
  const Limits limits{0.1, 1.0, std::nullopt};
  const Eigen::Quaterniond q = Eigen::Quaterniond::Identity();
  const Posed a(q, V::Zero()), b(q, V(0.3, 0, 0)), c(q, V(0.1, 0, 0));
  Path reversal = Path::lin(a, b);
  reversal.then(Path::lin(b, c));
  PlanOptions options;
  options.corner_tolerance = 0.01;
  const Trajectory traj = plan(reversal, set, limits, ProfileKind::trapezoid, options);
  ASSERT_EQ(traj.stops().size(), 1u);
  EXPECT_NEAR(traj.stops()[0].s, traj.rest_positions()[1], 0.0);
  EXPECT_NE(traj.stops()[0].reason.find("reverses"), std::string::npos) << traj.stops()[0].reason;

  // A turn on the spot between two translations: blended, no stop.
  const Posed turned(Eigen::Quaterniond(Eigen::AngleAxisd(1.0, V::UnitZ())), b.translation());
  Path spin = Path::lin(a, b);
  spin.then(Path::lin(b, turned)).then(Path::lin(turned, Posed(turned.quaternion(), V(0.3, 0.3, 0))));
  const Trajectory spun = plan(spin, set, limits, ProfileKind::trapezoid, options);
  EXPECT_TRUE(spun.stops().empty()) << spun.stops()[0].reason;
  EXPECT_LE(worst_speed_ratio(spun, set, limits.velocity, 20000), 1.0 + 1e-6);

  // corner_tolerance = 0 keeps the exact stop, with its reason.
  const Trajectory exact = plan(spin, set, limits, ProfileKind::trapezoid);
  ASSERT_EQ(exact.stops().size(), 2u);
  EXPECT_NE(exact.stops()[0].reason.find("corner_tolerance = 0"), std::string::npos);
}

// Each move's own speed holds on that move and binds there; the trajectory slows down before a
// slower move and speeds up after it.
TEST(ContinuousMotion, PerMoveLimitsHoldAndBind) {
  Random rnd(1803);
  for (int i = 0; i < 20; ++i) {
    MetricSetd set;
    set.add_relative(shapes::icosahedron(0.05));
    const double v = 0.2;
    const V x = rnd.unit_vector();
    const Eigen::Quaterniond q = rnd.rotation();
    std::vector<Posed> poses;
    for (int k = 0; k < 4; ++k) poses.push_back(Posed(q, x * (0.3 * k)));
    const double slow = rnd.uniform(0.02, 0.15), slower = rnd.uniform(0.01, 0.1);
    Path path = Path::lin(poses[0], poses[1]);
    path.then(Path::lin(poses[1], poses[2]).with_limits({slow, 0.3}))
        .then(Path::lin(poses[2], poses[3]).with_limits({slower, std::nullopt}));
    const Trajectory traj = plan(path, set, Limits{v, 1.0, std::nullopt}, ProfileKind::trapezoid);
    EXPECT_EQ(traj.piece_count(), 1u);  // collinear moves: no stop at the speed changes
    const double limits_of_move[] = {v, slow, slower};
    double peak[3] = {0, 0, 0};
    const int steps = 20000;
    const double dt = traj.duration() / steps;
    for (int k = 0; k < steps; ++k) {
      const TrajectorySample at = traj.sample(k * dt);
      const int move = std::min(2, static_cast<int>(std::floor(at.s / 0.3)));
      const double next_s = traj.sample((k + 1) * dt).s;
      if (std::min(2, static_cast<int>(std::floor(next_s / 0.3))) != move) continue;
      const double speed = chord_speed_ratio(traj, set, 1.0, k * dt, dt);
      ASSERT_LE(speed, limits_of_move[move] * (1.0 + 1e-6)) << "case " << i << " move " << move;
      peak[move] = std::max(peak[move], speed);
    }
    for (int m = 0; m < 3; ++m) EXPECT_GE(peak[m], 0.995 * limits_of_move[m]) << "case " << i << " move " << m;
  }
}

// The rotational limit: |ω| never above it, points never above theirs, and in a cruise one of
// the two binds.
TEST(ContinuousMotion, RotationalLimitHoldsAndBinds) {
  Random rnd(1804);
  for (int i = 0; i < 200; ++i) {
    const double v = rnd.uniform(0.05, 0.3);
    const MetricSetd set = random_set(rnd, v);
    const Posed a = rnd.pose(0.5);
    const Path path = i % 2 ? Path::lin(a, rnd.nearby(a, 0.4, 2.0), Interpolation::decoupled)
                            : Path::spline({a, rnd.nearby(a, 0.3, 1.0), rnd.nearby(a, 0.3, 1.0)});
    Limits limits{v, 50.0 * v, std::nullopt};
    limits.angular_velocity = rnd.uniform(0.05, 1.0);
    const Trajectory traj = plan(path, set, limits, ProfileKind::trapezoid);
    const int steps = 4000;
    const double dt = traj.duration() / steps;
    for (int k = 0; k < steps; ++k)
      ASSERT_LE(chord_angular_speed(traj, k * dt, dt), *limits.angular_velocity * (1.0 + 1e-6)) << i;
    ASSERT_LE(worst_speed_ratio(traj, set, v, steps), 1.0 + 1e-6) << "case " << i;
    if (i % 2) {
      for (const double t : cruise_times(traj, 400)) {
        const double h = traj.duration() * 1e-6;
        const double binding =
            std::max(chord_speed_ratio(traj, set, v, t, h), chord_angular_speed(traj, t, h) / *limits.angular_velocity);
        ASSERT_GE(binding, 0.995) << "case " << i;
      }
    }
  }
}

// The rotational limit on a pure rotation: the angular speed cruises at it exactly.
TEST(ContinuousMotion, PureRotationCruisesAtTheAngularLimit) {
  MetricSetd set;
  set.add_relative(shapes::icosahedron(0.01));
  const Posed a;
  const Posed b(Eigen::Quaterniond(Eigen::AngleAxisd(2.0, V(1, 2, 3).normalized())), V::Zero());
  Limits limits{0.2, 10.0, std::nullopt};
  limits.angular_velocity = 0.5;
  limits.angular_acceleration = 2.0;
  const Trajectory traj = plan(Path::lin(a, b), set, limits, ProfileKind::trapezoid);
  const double dt = traj.duration() * 1e-5;
  double peak = 0.0, peak_rate = 0.0, previous = 0.0;
  for (int k = 0; k < 100000; ++k) {
    const double w = chord_angular_speed(traj, k * dt, dt);
    peak = std::max(peak, w);
    if (k > 0) peak_rate = std::max(peak_rate, std::abs(w - previous) / dt);
    previous = w;
  }
  EXPECT_LE(peak, 0.5 * (1.0 + 1e-6));
  EXPECT_GE(peak, 0.5 * (1.0 - 1e-6));
  EXPECT_LE(peak_rate, 2.0 * (1.0 + 1e-3));
}

// A tool-centre point and a rotational limit (a controller's TCP speed and rotation limits): the
// set does not see a turn about the point, the angular limit does; without it the set is refused.
TEST(ContinuousMotion, ToolCentrePointWithARotationalLimit) {
  MetricSetd tcp;
  tcp.add_relative(V::Zero());
  const Posed a, b(Eigen::Quaterniond(Eigen::AngleAxisd(1.5, V(0.2, 0.3, 1.0).normalized())), V(0.2, 0.1, 0.0));
  Limits limits{0.2, 2.0, std::nullopt};
  EXPECT_NE(message_of([&] { plan(Path::lin(a, b), tcp, limits, ProfileKind::trapezoid); }).find("not well-formed"),
            std::string::npos);
  limits.angular_velocity = 0.5;
  for (const Path& path : {Path::lin(a, b), Path::lin(a, Posed(b.quaternion(), V::Zero()))}) {
    const Trajectory traj = plan(path, tcp, limits, ProfileKind::trapezoid);
    const double dt = traj.duration() / 20000;
    double peak = 0.0;
    for (int k = 0; k < 20000; ++k) {
      const double w = chord_angular_speed(traj, k * dt, dt);
      ASSERT_LE(w, 0.5 * (1.0 + 1e-6));
      peak = std::max({peak, w / 0.5, chord_speed_ratio(traj, tcp, 0.2, k * dt, dt)});
    }
    EXPECT_LE(worst_speed_ratio(traj, tcp, 0.2, 20000), 1.0 + 1e-6);
    EXPECT_GE(peak, 0.995);
  }
  EXPECT_NE(message_of([&] { plan(Path::lin(a, b), MetricSetd(), limits, ProfileKind::trapezoid); }).find("empty"),
            std::string::npos);
}

TEST(ContinuousMotionBadInput, NamesTheArgument) {
  MetricSetd set;
  set.add_relative(shapes::icosahedron(0.05));
  const Posed a, b(Eigen::Quaterniond::Identity(), V(0.3, 0, 0));
  const Path path = Path::lin(a, b);
  PlanOptions options;
  for (const double bad : {-1.0, std::nan(""), std::numeric_limits<double>::infinity()}) {
    options.corner_tolerance = bad;
    EXPECT_NE(message_of([&] {
                plan(path, set, Limits{0.1, 1.0, std::nullopt}, ProfileKind::trapezoid, options);
              }).find("corner_tolerance"),
              std::string::npos);
  }
  for (const double bad : {0.0, -0.1, std::nan("")}) {
    Path p = Path::lin(a, b);
    EXPECT_NE(message_of([&] { p.with_limits({bad, std::nullopt}); }).find("velocity"), std::string::npos);
    EXPECT_NE(message_of([&] { p.with_limits({std::nullopt, bad}); }).find("acceleration"), std::string::npos);
    Limits limits{0.1, 1.0, std::nullopt};
    limits.angular_velocity = bad;
    EXPECT_NE(message_of([&] { plan(path, set, limits, ProfileKind::trapezoid); }).find("angular_velocity"),
              std::string::npos);
    limits.angular_velocity.reset();
    limits.angular_acceleration = bad;
    EXPECT_NE(message_of([&] { plan(path, set, limits, ProfileKind::trapezoid); }).find("angular_acceleration"),
              std::string::npos);
  }
}

}  // namespace
}  // namespace dispkin
