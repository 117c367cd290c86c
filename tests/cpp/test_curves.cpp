// Curved paths: SPLINE moves and blends at via points, and their sections' lengths.
#include <gtest/gtest.h>

#include <dispkin/path/path.hpp>
#include <dispkin/planning/planner.hpp>
#include <dispkin/shapes.hpp>

#include "random_cases.hpp"

namespace dispkin {
namespace {

using V = Eigen::Vector3d;
using testing::message_of;
using testing::Random;

constexpr double metres_per_radian = 0.1;

double angle_between(const Posed& a, const Posed& b) {
  return quaternion_log(Eigen::Quaterniond(a.quaternion().conjugate() * b.quaternion())).norm();
}

std::vector<Posed> random_keys(Random& rnd, int count) {
  std::vector<Posed> keys{rnd.pose(0.5)};
  while (static_cast<int>(keys.size()) < count) keys.push_back(rnd.nearby(keys.back(), 0.3, 1.2));
  return keys;
}

// The sections that start a new curve piece (v0 = 0), in order.
std::vector<const CurveSection*> piece_starts(const Path& path) {
  std::vector<const CurveSection*> starts;
  for (const Section& s : path.sections())
    if (const auto* c = std::get_if<CurveSection>(&s); c && c->v0 == 0.0) starts.push_back(c);
  return starts;
}

TEST(Spline, PassesThroughEveryKeyPose) {
  Random rnd(301);
  for (int i = 0; i < 200; ++i) {
    const std::vector<Posed> keys = random_keys(rnd, rnd.integer(3, 7));
    const V pivot = rnd.vector(0.1);
    const Path path = Path::spline(keys, pivot);
    const auto starts = piece_starts(path);
    ASSERT_EQ(starts.size(), keys.size() - 1);
    for (std::size_t k = 0; k + 1 < keys.size(); ++k) {
      ASSERT_TRUE(starts[k]->pose(0.0).is_approx(keys[k], 1e-12)) << "key " << k;
      CurveSection end = *starts[k];
      end.v0 = 0.0;
      end.v1 = 1.0;
      ASSERT_TRUE(end.pose(1.0).is_approx(keys[k + 1], 1e-12)) << "key " << k + 1;
    }
    ASSERT_TRUE(path.start().is_approx(keys.front(), 1e-12));
    ASSERT_TRUE(path.end().is_approx(keys.back(), 1e-12));
  }
}

// C² in position and C¹ in orientation through every key, per unit of the knot parameter
// (pieces are spaced by their geometric size h, which the test recomputes from the keys).
TEST(Spline, PositionIsC2AndAngularVelocityContinuousAtKeys) {
  Random rnd(302);
  for (int i = 0; i < 200; ++i) {
    const std::vector<Posed> keys = random_keys(rnd, rnd.integer(3, 7));
    const V pivot = rnd.vector(0.1);
    const Path path = Path::spline(keys, pivot);
    const auto starts = piece_starts(path);
    auto h = [&](std::size_t k) {
      return ((keys[k + 1] * pivot) - (keys[k] * pivot)).norm() +
             metres_per_radian * angle_between(keys[k], keys[k + 1]);
    };
    for (std::size_t k = 0; k + 2 < keys.size(); ++k) {
      const CurveSection& a = *starts[k];
      const CurveSection& b = *starts[k + 1];
      const double ha = h(k), hb = h(k + 1);
      const V velocity_out = a.position.first(1.0) / ha, velocity_in = b.position.first(0.0) / hb;
      const V curvature_out = a.position.second(1.0) / (ha * ha), curvature_in = b.position.second(0.0) / (hb * hb);
      ASSERT_LE((velocity_out - velocity_in).norm(), 1e-9 * (1 + velocity_in.norm()));
      ASSERT_LE((curvature_out - curvature_in).norm(), 1e-7 * (1 + curvature_in.norm()));
      const V omega_out = right_jacobian_times(a.rotation.value(1.0), a.rotation.first(1.0)) / ha;
      const V omega_in = right_jacobian_times(b.rotation.value(0.0), b.rotation.first(0.0)) / hb;
      ASSERT_LE((omega_out - omega_in).norm(), 1e-9 * (1 + omega_in.norm())) << "key " << k + 1;
    }
    // Natural ends: no curvature at the first and last key.
    const CurveSection& first = *starts.front();
    const CurveSection& last = *starts.back();
    EXPECT_LE(first.position.second(0.0).norm(), 1e-9 * (1 + first.position.first(0.0).norm()));
    EXPECT_LE(last.position.second(1.0).norm(), 1e-9 * (1 + last.position.first(1.0).norm()));
  }
}

TEST(Spline, AntipodalKeyQuaternionsDoNotFlip) {
  const Eigen::Quaterniond q(Eigen::AngleAxisd(0.3, V::UnitZ()));
  const Posed a(q, V(0, 0, 0)), b(Eigen::Quaterniond(-q.coeffs()), V(0.2, 0.1, 0)), c(q, V(0.4, 0, 0));
  const Path path = Path::spline({a, b, c});
  double largest_turn = 0;
  for (const Section& s : path.sections())
    largest_turn = std::max(largest_turn, angle_between(section_start(s), section_end(s)));
  EXPECT_LT(largest_turn, 1e-9);  // the orientation never moves: −q is the same rotation
}

// The section twist is the derivative of the section pose (central differences).
// Found by fuzzing (tests/fuzz/fuzz_path_plan): key poses so far apart that a knot spacing
// overflowed to infinity reached the sparse LU, whose solve() then wrote past its buffers.
// Such poses are now refused by the Pose constructor (translations beyond ±1e12 m, the numeric
// range); the spline's own check still stops unchecked ones.
TEST(Spline, KeyPosesBeyondDoubleRangeAreRefused) {
  const Eigen::Quaterniond q = Eigen::Quaterniond::Identity();
  EXPECT_NE(message_of([&] { Posed(q, V(1e200, 0, 0)); }).find("must have coordinates within ±1e12 m"),
            std::string::npos);
  const std::string m = message_of([&] {
    Path::spline(
        {Posed::unchecked(q, V(1e200, 0, 0)), Posed::unchecked(q, V(0, 0, 0)), Posed::unchecked(q, V(0, 1e200, 0))});
  });
  EXPECT_EQ(m, "poses[1] = (0, 0, 0): is too far from the key pose before it: their distance overflows");
}

TEST(CurveSection, TwistIsTheDerivativeOfThePose) {
  Random rnd(303);
  for (int i = 0; i < 100; ++i) {
    const Path path = Path::spline(random_keys(rnd, 4), rnd.vector(0.1), 1e-2);
    const auto& sections = path.sections();
    const Section& s = sections[rnd.integer(0, static_cast<int>(sections.size()) - 1)];
    const double tau = rnd.uniform(0.1, 0.9), d = 1e-6;
    const Twistd numeric = (section_pose(s, tau - d).inverse() * section_pose(s, tau + d)).log() * (1.0 / (2 * d));
    const Twistd exact = section_twist(s, tau);
    ASSERT_LE((numeric.vector() - exact.vector()).norm(), 1e-6 * (1 + exact.vector().norm()));
  }
}

// doc/section-length.md eqs. 23–24 for curved sections: L is never below the fastest object's speed
// anywhere on the section, and for objects near the pivot it is tight to about the cutting
// tolerance.
TEST(CurveSection, LengthBoundsEverySpeedAndIsTight) {
  Random rnd(304);
  const int n = std::max(50, testing::case_count(10000) / 20);
  double worst_slack = 0;
  for (int i = 0; i < n; ++i) {
    const MetricSetd set = rnd.metric_set();
    const double v_sys = 0.5;
    const Path path = Path::spline(random_keys(rnd, 3), rnd.vector(0.1), 1e-2);
    const auto& sections = path.sections();
    const Section& s = sections[rnd.integer(0, static_cast<int>(sections.size()) - 1)];
    const double length = section_length(s, set, v_sys);
    double fastest = 0;
    for (int k = 0; k <= 200; ++k) {
      const double tau = k / 200.0;
      fastest = std::max(fastest, max_point_speed(set, section_pose(s, tau), section_twist(s, tau), v_sys));
    }
    ASSERT_GE(length, fastest * (1 - 1e-12)) << "case " << i;
    worst_slack = std::max(worst_slack, length / fastest - 1);
  }
  // Sets reach 0.5–1.2 m from the pivot (the cutting assumes 0.1 m): slack well under 20×.
  EXPECT_LT(worst_slack, 0.2);
}

TEST(CurveSection, TightForAToolNearThePivot) {
  Random rnd(305);
  MetricSetd set;
  set.add_relative(shapes::icosahedron(0.05));
  for (int i = 0; i < 50; ++i) {
    const Path path = Path::spline(random_keys(rnd, 4));
    for (const Section& s : path.sections()) {
      double fastest = 0;
      for (int k = 0; k <= 20; ++k)
        fastest = std::max(fastest, max_point_speed(set, section_pose(s, k / 20.0), section_twist(s, k / 20.0)));
      ASSERT_LE(section_length(s, set), fastest * (1 + 3e-3));
    }
  }
}

// The points whose motion a piece's rates bound: every point of the set, and points on the
// spheres' surfaces, with their group and whether they are fixed in the body.
struct ProbePoint {
  V x;
  std::size_t group;
  bool relative;
};
std::vector<ProbePoint> probe_points(const MetricSetd& set, Random& rnd) {
  std::vector<ProbePoint> points;
  for (std::size_t i = 0; i < set.groups().size(); ++i) {
    const auto& g = set.groups()[i];
    for (const V& r : g.relative_points) points.push_back({r, i, true});
    for (const V& a : g.absolute_points) points.push_back({a, i, false});
    for (int k = 0; k < 8; ++k) {
      for (const auto& s : g.relative_spheres) points.push_back({s.center + s.radius * rnd.unit_vector(), i, true});
      for (const auto& s : g.absolute_spheres) points.push_back({s.center + s.radius * rnd.unit_vector(), i, false});
    }
  }
  return points;
}

// The velocity of a probe point per unit τ (world): a body point's R (v + ω × r), the velocity an
// absolute point sees v_s + ω_s × x (doc/section-length.md eq. 10).
V probe_velocity(const CurveSection& piece, const ProbePoint& p, double tau) {
  Posed pose;
  Twistd twist;
  piece.at(tau, pose, twist);
  if (p.relative) return pose.quaternion() * (twist.linear + twist.angular.cross(p.x));
  const Twistd world = detail::world_view(pose, twist);
  return world.linear + world.angular.cross(p.x);
}

// doc/section-length.md eq. 25: a piece's acceleration and jerk bounds are never below the
// acceleration and the jerk of any object of the set anywhere on the piece (central differences
// of the exact velocities), for pieces short and long, near θ = 0 and turning far.
TEST(CurveSection, PieceRatesBoundEveryObjectsAccelerationAndJerk) {
  Random rnd(306);
  double worst_acceleration = 0.0, worst_jerk = 0.0;
  for (int i = 0; i < 200; ++i) {
    const MetricSetd set = rnd.metric_set();
    const std::vector<ProbePoint> points = probe_points(set, rnd);
    const Path path = Path::spline(random_keys(rnd, 4), rnd.vector(0.1), i % 2 ? 1e-2 : 0.1);
    const auto& sections = path.sections();
    const auto& section = std::get<CurveSection>(sections[rnd.integer(0, static_cast<int>(sections.size()) - 1)]);
    // A piece of the section: the whole, or a part as short as 10⁻³ of it.
    const double share = i % 3 == 0 ? 1.0 : std::pow(10.0, rnd.uniform(-3.0, 0.0));
    const double t0 = rnd.uniform(0.0, 1.0 - share);
    CurveSection piece = section;
    piece.v0 = section.v0 + t0 * section.span();
    piece.v1 = piece.v0 + share * section.span();
    GroupFactors factors(set, 0.5);
    factors.use_pivot(piece.pivot);
    const PieceRates rates = piece.piece_rates(factors);
    const double d = 1e-3;
    for (int k = 0; k <= 40; ++k) {
      const double tau = d + (1.0 - 2.0 * d) * k / 40.0;
      for (const ProbePoint& p : points) {
        const V before = probe_velocity(piece, p, tau - d), at = probe_velocity(piece, p, tau),
                after = probe_velocity(piece, p, tau + d);
        const double acceleration = ((after - before) / (2.0 * d)).norm();
        const double jerk = factors.weight(p.group) * ((after - 2.0 * at + before) / (d * d)).norm();
        // The differences' rounding: about 10⁻¹⁶ of the velocity over d² (the truncation, d² x⁽⁵⁾/12, is
        // within the relative 10⁻⁶).
        const double rounding = 1e-9 * factors.weight(p.group) * at.norm();
        ASSERT_LE(acceleration, rates.acceleration * (1 + 1e-6) + rounding) << "case " << i << " τ " << tau;
        ASSERT_LE(jerk, rates.jerk * (1 + 1e-6) + rounding) << "case " << i << " τ " << tau;
        worst_acceleration = std::max(worst_acceleration, acceleration / rates.acceleration);
        if (rounding < 1e-4 * rates.jerk) worst_jerk = std::max(worst_jerk, jerk / rates.jerk);
      }
    }
  }
  // The bounds are not loose everywhere: somewhere they are approached (measured: 0.95 and 0.96).
  EXPECT_GT(worst_acceleration, 0.5);
  EXPECT_GT(worst_jerk, 0.5);
}

// doc/section-length.md eqs. 26–27: a section's length is never below the fastest speed of its
// set anywhere on it and at most 0.1 % above the exact peak (here the best of 2001 samples).
TEST(CurveSection, LengthIsThePeakSpeedToATenthOfAPercent) {
  Random rnd(307);
  for (int i = 0; i < 60; ++i) {
    const MetricSetd set = rnd.metric_set();
    const Path path = Path::spline(random_keys(rnd, 3), rnd.vector(0.1), i % 2 ? 1e-2 : 0.1);
    const auto& sections = path.sections();
    const Section& s = sections[rnd.integer(0, static_cast<int>(sections.size()) - 1)];
    const double length = section_length(s, set, 0.5);
    double fastest = 0;
    for (int k = 0; k <= 2000; ++k) {
      const double tau = k / 2000.0;
      fastest = std::max(fastest, max_point_speed(set, section_pose(s, tau), section_twist(s, tau), 0.5));
    }
    ASSERT_GE(length, fastest * (1 - 1e-12)) << "case " << i;
    ASSERT_LE(length, fastest * (1 + 1e-3 + 1e-5)) << "case " << i;
  }
}

// --- blends -------------------------------------------------------------------------------

Posed at(double x, double y, double z, double angle = 0.0, const V& axis = V::UnitZ()) {
  return Posed(Eigen::Quaterniond(Eigen::AngleAxisd(angle, axis)), V(x, y, z));
}

// The unit direction of the twist per unit τ at the end of section k and at the start of k+1.
double direction_jump(const Section& a, const Section& b) {
  const auto out = section_twist(a, 1.0).vector().normalized(), in = section_twist(b, 0.0).vector().normalized();
  return (out - in).norm();
}

TEST(Blend, StaysNearTheCornerAndJoinsWithoutKinks) {
  Random rnd(306);
  for (int i = 0; i < 200; ++i) {
    const Posed a = rnd.pose(0.5);
    const Posed via = rnd.nearby(a, 0.4, 1.0), b = rnd.nearby(via, 0.4, 1.0);
    const Path second = Path::lin(via, b);
    const double limit =
        0.5 * std::min((via.translation() - a.translation()).norm() + metres_per_radian * angle_between(a, via),
                       (b.translation() - via.translation()).norm() + metres_per_radian * angle_between(via, b));
    const double before = rnd.uniform(0.05, 1.0) * limit, after = rnd.uniform(0.05, 1.0) * limit;
    Path path = Path::lin(a, via);
    path.then(second, before, after);
    ASSERT_TRUE(path.start().is_approx(a, 1e-12));
    ASSERT_TRUE(path.end().is_approx(b, 1e-12));
    const auto& s = path.sections();
    for (std::size_t k = 0; k + 1 < s.size(); ++k) {
      ASSERT_TRUE(section_end(s[k]).is_approx(section_start(s[k + 1]), 1e-12)) << "gap after section " << k;
      ASSERT_LE(direction_jump(s[k], s[k + 1]), 1e-9) << "kink after section " << k;
      if (std::holds_alternative<CurveSection>(s[k])) {
        // Within the blend the pivot stays within max(before, after) of the corner.
        for (int j = 0; j <= 10; ++j)
          ASSERT_LE((section_pose(s[k], j / 10.0).translation() - via.translation()).norm(),
                    std::max(before, after) * (1 + 1e-9));
      }
    }
  }
}

TEST(Blend, ViaPointThatOnlyRotates) {
  const Posed a = at(0, 0, 0), via = at(0, 0, 0, 1.0, V::UnitZ()),
              b = at(0, 0, 0, 1.0, V::UnitZ()) * at(0, 0, 0, 1.0, V::UnitX());
  Path path = Path::lin(a, via);
  path.then(Path::lin(via, b), 0.02);
  ASSERT_TRUE(path.end().is_approx(b, 1e-12));
  for (std::size_t k = 0; k + 1 < path.size(); ++k)
    ASSERT_LE(direction_jump(path.sections()[k], path.sections()[k + 1]), 1e-9);
  for (const Section& s : path.sections()) ASSERT_LE(section_pose(s, 0.5).translation().norm(), 1e-12);
}

TEST(Blend, TooLargeOrNotPositiveIsRefused) {
  const Posed a = at(0, 0, 0), via = at(0.2, 0, 0), b = at(0.2, 0.1, 0);
  Path path = Path::lin(a, via);
  EXPECT_NE(message_of([&] { path.then(Path::lin(via, b), 0.06); }).find("half of the move after"), std::string::npos);
  EXPECT_NE(message_of([&] { path.then(Path::lin(via, b), 0.11, 0.04); }).find("half of the move before"),
            std::string::npos);
  EXPECT_NE(message_of([&] { path.then(Path::lin(via, b), -0.01); }).find("before"), std::string::npos);
  EXPECT_NE(message_of([&] { path.then(Path::lin(via, b), std::nan("")); }).find("before = nan"), std::string::npos);
  EXPECT_NE(message_of([&] { path.then(Path::lin(b, a), 0.01); }).find("must start where the path ends"),
            std::string::npos);
  EXPECT_EQ(path.size(), 1u);  // a refused blend leaves the path as it was
}

TEST(Spline, BadInputIsRefused) {
  const Posed a = at(0, 0, 0), b = at(0.1, 0, 0), c = at(0.2, 0.1, 0);
  EXPECT_NE(message_of([&] { Path::spline({a, b}); }).find("at least three"), std::string::npos);
  EXPECT_NE(message_of([&] { Path::spline({a, b, b, c}); }).find("poses[2]"), std::string::npos);
  EXPECT_NE(message_of([&] { Path::spline({a, b, c}, V::Zero(), 0.0); }).find("tolerance"), std::string::npos);
  EXPECT_NE(message_of([&] { Path::spline({a, b, c}, V(std::nan(""), 0, 0)); }).find("pivot"), std::string::npos);
}

// A blended LIN – CIRC – LIN runs through both blends without stopping: one rest-to-rest piece.
TEST(Blend, PlannerRunsThroughBlendsWithoutStopping) {
  const Posed a = at(0, 0, 0), p1 = at(0.3, 0, 0, 0.2), via = at(0.4, 0.1, 0, 0.3), p2 = at(0.3, 0.2, 0, 0.4),
              b = at(0.0, 0.2, 0, 0.5);
  Path path = Path::lin(a, p1);
  path.then(Path::circ(p1, via, p2), 0.05).then(Path::lin(p2, b), 0.05);
  MetricSetd set;
  set.add_relative(shapes::icosahedron(0.05));
  const Limits limits{0.2, 1.0, 10.0};
  const Trajectory traj = plan(path, set, limits);
  EXPECT_EQ(traj.piece_count(), 1u);
  EXPECT_TRUE(traj.sample(traj.duration()).pose.is_approx(b, 1e-9));
}

}  // namespace
}  // namespace dispkin
