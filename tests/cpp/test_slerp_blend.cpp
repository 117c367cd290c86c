// Nested-SLERP blends at via points (the Mamezou trajectory article's "Fitting Posture",
// doc/planning.md §6.1): the article's formula, the joins, the exact derivatives and the rigorous
// bounds of doc/planning.md eqs. 19–23, the planner's guarantee along blended chains, bad input.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include <dispkin/path/path.hpp>
#include <dispkin/planning/planner.hpp>
#include <dispkin/planning/trajectory_acceleration.hpp>
#include <dispkin/shapes.hpp>

#include "random_cases.hpp"
#include "random_paths.hpp"

namespace dispkin {
namespace {

using V = Eigen::Vector3d;
using testing::message_of;
using testing::Random;

double turn_between(const Eigen::Quaterniond& p, const Eigen::Quaterniond& q) {
  return quaternion_log(Eigen::Quaterniond(p.conjugate() * q)).norm();
}

std::vector<const SlerpBlendSection*> blend_sections(const Path& path) {
  std::vector<const SlerpBlendSection*> out;
  for (const Section& s : path.sections())
    if (const auto* b = std::get_if<SlerpBlendSection>(&s)) out.push_back(b);
  return out;
}

double direction_jump(const Section& a, const Section& b) {
  const auto out = section_twist(a, 1.0).vector().normalized(), in = section_twist(b, 0.0).vector().normalized();
  return (out - in).norm();
}

// The article: q[m]1 = Slerp(1 − w, q[m−1], q[m]), q[m]2 = Slerp(w, q[m], q[m+1]); then
// q1 = Slerp(t, q[m]1, q[m]), q2 = Slerp(t, q[m], q[m]2), q = Slerp(t, q1, q2) — evaluated with
// Eigen's own slerp. The pivot: the quadratic Bézier through the corner as control point.
TEST(SlerpBlend, ReproducesTheArticlesNestedSlerpAndTheQuadraticBezier) {
  Random rnd(4101);
  double worst_q = 0.0, worst_c = 0.0;
  for (int i = 0; i < 200; ++i) {
    const V pivot = rnd.vector(0.1);
    const Posed a = rnd.pose(0.5);
    const Posed via = rnd.nearby(a, 0.4, 1.5), b = rnd.nearby(via, 0.4, 1.5);
    const double w = rnd.uniform(0.05, 0.5);
    Path path = Path::lin(a, via, Interpolation::decoupled, pivot);
    path.then_weighted(Path::lin(via, b, Interpolation::decoupled, pivot), w, OrientationBlend::nested_slerp);
    const Eigen::Quaterniond qm = via.quaternion();
    const Eigen::Quaterniond q1 = a.quaternion().slerp(1.0 - w, qm), q2 = qm.slerp(w, b.quaternion());
    const V c1 = (a * pivot) + (1.0 - w) * ((via * pivot) - (a * pivot)), cm = via * pivot;
    const V c2 = (via * pivot) + w * ((b * pivot) - (via * pivot));
    const auto blend = blend_sections(path);
    ASSERT_FALSE(blend.empty());
    for (const SlerpBlendSection* s : blend) {
      for (int j = 0; j <= 8; ++j) {
        const double tau = j / 8.0, t = s->v0 + tau * s->span();
        const Eigen::Quaterniond q = q1.slerp(t, qm).slerp(t, qm.slerp(t, q2));
        const Posed pose = s->pose(tau);
        worst_q = std::max(worst_q, turn_between(pose.quaternion(), q));
        const V c = (1 - t) * (1 - t) * c1 + 2 * t * (1 - t) * cm + t * t * c2;
        worst_c = std::max(worst_c, ((pose * pivot) - c).norm());
      }
    }
    ASSERT_LE(worst_q, 1e-12) << "case " << i;
    ASSERT_LE(worst_c, 1e-12) << "case " << i;
    ASSERT_TRUE(path.end().is_approx(b, 1e-12));
  }
  std::printf("nested SLERP vs the article's formula: %.3g rad, pivot %.3g m\n", worst_q, worst_c);
}

// Both joins keep the twist's direction (doc/planning.md eq. 18): no kink anywhere along the path, and the
// planner runs from start to end without a stop.
TEST(SlerpBlend, JoinsKeepTheTwistDirectionAndThePlannerDoesNotStop) {
  Random rnd(4102);
  MetricSetd set;
  set.add_relative(shapes::icosahedron(0.05));
  for (int i = 0; i < 50; ++i) {
    const V pivot = rnd.vector(0.1);
    const Posed a = rnd.pose(0.5);
    const Posed b = rnd.nearby(a, 0.4, 1.2), c = rnd.nearby(b, 0.4, 1.2), d = rnd.nearby(c, 0.4, 1.2);
    Path path = Path::lin(a, b, Interpolation::decoupled, pivot);
    path.then_weighted(Path::lin(b, c, Interpolation::decoupled, pivot), rnd.uniform(0.1, 0.5),
                       OrientationBlend::nested_slerp)
        .then_weighted(Path::lin(c, d, Interpolation::decoupled, pivot), rnd.uniform(0.1, 0.5),
                       OrientationBlend::nested_slerp);
    const auto& s = path.sections();
    for (std::size_t k = 0; k + 1 < s.size(); ++k) {
      ASSERT_TRUE(section_end(s[k]).is_approx(section_start(s[k + 1]), 1e-12)) << "gap after section " << k;
      ASSERT_LE(direction_jump(s[k], s[k + 1]), 1e-9) << "case " << i << ": kink after section " << k;
    }
    const Trajectory traj = plan(path, set, Limits{0.2, 1.0, 10.0});
    ASSERT_EQ(traj.piece_count(), 1u) << "case " << i;
    ASSERT_TRUE(traj.stops().empty()) << "case " << i << ": " << traj.stops().front().reason;
    ASSERT_TRUE(traj.sample(traj.duration()).pose.is_approx(d, 1e-9));
  }
}

// A random blend curve with turns a, b up to π/2 (a blend takes at most half of a LIN's turn).
SlerpBlendSection random_blend(Random& rnd, double max_turn = 0.5 * pi) {
  SlerpBlendSection s;
  s.q_start = rnd.rotation();
  s.a = rnd.unit_vector() * rnd.uniform(0.0, max_turn);
  s.b = rnd.unit_vector() * rnd.uniform(0.0, max_turn);
  const V c1 = rnd.vector(0.5), cm = rnd.vector(0.5), c2 = rnd.vector(0.5);
  s.position.a[0] = c1;
  s.position.a[1] = 2.0 * (cm - c1);
  s.position.a[2] = c1 - 2.0 * cm + c2;
  s.pivot = rnd.vector(0.1);
  return s;
}

// The body twist by central differences of the pose; its rate by central differences of the twist.
Twistd twist_by_differences(const SlerpBlendSection& s, double tau, double h) {
  return (s.pose(tau - h).inverse() * s.pose(tau + h)).log() * (0.5 / h);
}

TEST(SlerpBlend, TwistAndItsRateAreExact) {
  Random rnd(4103);
  double worst_twist = 0.0, worst_rate = 0.0;
  for (int i = 0; i < 300; ++i) {
    SlerpBlendSection s = random_blend(rnd);
    s.v0 = rnd.uniform(0.0, 0.5);
    s.v1 = rnd.uniform(s.v0 + 0.1, 1.0);
    for (int j = 1; j < 10; ++j) {
      const double tau = j / 10.0;
      const Twistd exact = s.twist(tau), rate = s.twist_rate(tau);
      const double scale = 1.0 + exact.vector().norm();
      worst_twist =
          std::max(worst_twist, (twist_by_differences(s, tau, 1e-5).vector() - exact.vector()).norm() / scale);
      const Eigen::Matrix<double, 6, 1> rate_fd =
          (s.twist(tau + 1e-5).vector() - s.twist(tau - 1e-5).vector()) * (0.5 / 1e-5);
      worst_rate = std::max(worst_rate, (rate_fd - rate.vector()).norm() / (1.0 + rate.vector().norm()));
      // The trajectory's acceleration takes the same rate.
      ASSERT_EQ(section_twist_rate(Section(s), tau).vector(), rate.vector());
    }
  }
  std::printf("twist vs differences: %.3g, rate: %.3g (relative)\n", worst_twist, worst_rate);
  EXPECT_LE(worst_twist, 1e-8);
  EXPECT_LE(worst_rate, 1e-7);
}

// A blend without rotation (and turns down to 10⁻¹²) has a finite, exact angular motion: ω = 0
// where nothing turns, no NaN from the logarithms.
TEST(SlerpBlend, NoRotationGivesZeroAngularVelocity) {
  Random rnd(4104);
  SlerpBlendSection s = random_blend(rnd);
  s.a.setZero();
  s.b.setZero();
  for (int j = 0; j <= 10; ++j) {
    const Twistd xi = s.twist(j / 10.0), rate = s.twist_rate(j / 10.0);
    ASSERT_TRUE(xi.vector().allFinite() && rate.vector().allFinite());
    ASSERT_EQ(xi.angular, V::Zero());
    ASSERT_EQ(rate.angular, V::Zero());
    ASSERT_TRUE(s.pose(j / 10.0).quaternion().isApprox(s.q_start, 1e-15));
  }
  const MotionBounds b = s.motion_bounds();
  EXPECT_EQ(b.omega, 0.0);
  EXPECT_EQ(b.omega_dot, 0.0);
  for (const double tiny : {1e-12, 1e-8, 1e-4}) {
    s.a = rnd.unit_vector() * tiny;
    s.b = rnd.unit_vector() * tiny;
    for (int j = 0; j <= 10; ++j) {
      const Twistd xi = s.twist(j / 10.0), rate = s.twist_rate(j / 10.0);
      ASSERT_TRUE(xi.vector().allFinite() && rate.vector().allFinite()) << tiny;
      ASSERT_LE(xi.angular.norm(), 4.0 * tiny) << tiny;
    }
  }
}

// The motion bounds (doc/planning.md eqs. 21–23) against dense samples of the exact motion on random curves and
// parts: never below, and within a stated factor.
TEST(SlerpBlend, MotionBoundsAreRigorousAndTight) {
  Random rnd(4105);
  double loosest_omega = 0.0, loosest_rate = 0.0, loosest_short = 0.0;
  for (int i = 0; i < 400; ++i) {
    SlerpBlendSection s = random_blend(rnd);
    const bool whole = i % 2 == 0;
    s.v0 = whole ? 0.0 : rnd.uniform(0.0, 0.9);
    s.v1 = whole ? 1.0 : std::min(1.0, s.v0 + rnd.uniform(0.01, 0.1));
    const MotionBounds b = s.motion_bounds();
    double omega = 0.0, rate = 0.0, c_dot = 0.0, c_ddot = 0.0;
    constexpr int n = 1000;
    for (int j = 0; j <= n; ++j) {
      const double tau = double(j) / n;
      const Twistd xi = s.twist(tau), xi_rate = s.twist_rate(tau);
      omega = std::max(omega, xi.angular.norm());
      rate = std::max(rate, xi_rate.angular.norm());
      const double v = s.v0 + tau * s.span();
      c_dot = std::max(c_dot, s.span() * s.position.first(v).norm());
      c_ddot = std::max(c_ddot, s.span() * s.span() * s.position.second(v).norm());
    }
    ASSERT_GE(b.omega, omega * (1 - 1e-12)) << "case " << i;
    ASSERT_GE(b.omega_dot, rate * (1 - 1e-12)) << "case " << i;
    ASSERT_GE(b.pivot_speed, c_dot * (1 - 1e-12)) << "case " << i;
    ASSERT_GE(b.pivot_acceleration, c_ddot * (1 - 1e-12)) << "case " << i;
    if (omega > 1e-9 * s.span()) loosest_omega = std::max(loosest_omega, b.omega / omega);
    if (rate > 1e-3 * s.span() * s.span()) loosest_rate = std::max(loosest_rate, b.omega_dot / rate);
    if (!whole && omega > 1e-3 * s.span()) loosest_short = std::max(loosest_short, b.omega / omega);
  }
  std::printf("bound / dense max: |w| %.3g (short parts %.3g), |w'| %.3g\n", loosest_omega, loosest_short,
              loosest_rate);
  // Turns up to π/2 each (the largest a blend makes): |ω| within 2.2× on whole blends and 1.6×
  // on parts up to a tenth (the middle value + half a part at the rate bound), |ω̇| within 12×
  // (measured 2.09, 1.54, 10.4). The rate bound costs sections, not speed: see CutSectionsAreTight.
  EXPECT_LE(loosest_omega, 2.2);
  EXPECT_LE(loosest_short, 1.6);
  EXPECT_LE(loosest_rate, 12.0);
}

// The section length bounds every object's speed (dense differences of the section's motion).
TEST(SlerpBlend, SectionLengthBoundsEverySpeed) {
  Random rnd(4106);
  double loosest = 0.0;
  for (int i = 0; i < 200; ++i) {
    SlerpBlendSection s = random_blend(rnd);
    s.v0 = rnd.uniform(0.0, 0.9);
    s.v1 = std::min(1.0, s.v0 + rnd.uniform(0.01, 0.1));
    const MetricSetd set = rnd.metric_set(false);
    const double length = s.length(set, std::nullopt);
    double fastest = 0.0;
    constexpr int n = 400;
    const double dt = 1.0 / n;
    for (int j = 0; j < n; ++j) {
      const Posed p = s.pose(j * dt), q = s.pose((j + 1) * dt);
      for (const auto& g : set.groups()) {
        for (const V& r : g.relative_points) fastest = std::max(fastest, ((q * r) - (p * r)).norm() / dt);
        for (const V& x : g.absolute_points)
          fastest = std::max(fastest, ((q.inverse() * x) - (p.inverse() * x)).norm() / dt);
      }
    }
    ASSERT_GE(length, fastest * (1 - 1e-9)) << "case " << i;
    if (fastest > 0.0) loosest = std::max(loosest, length / fastest);
  }
  std::printf("section length / fastest point: at most %.4g\n", loosest);
}

// On the sections a blend is cut into (tolerance 10⁻³ of the velocity), the length exceeds the
// fastest point's speed by at most a few times the tolerance: the bounds are tight where used.
TEST(SlerpBlend, CutSectionsAreTight) {
  Random rnd(4109);
  double loosest = 0.0;
  std::size_t count = 0;
  for (int i = 0; i < 20; ++i) {
    const Path path = testing::random_slerp_blended_chain(rnd, 1e-3);
    MetricSetd set;
    set.add_relative(shapes::icosahedron(0.05));
    for (const auto* s : blend_sections(path)) {
      ++count;
      double fastest = 0.0;
      constexpr int n = 50;
      for (int j = 0; j <= n; ++j) {
        const Posed p = s->pose(double(j) / n);
        const Twistd xi = s->twist(double(j) / n);
        for (const V& r : set.groups()[0].relative_points)
          fastest = std::max(fastest, (xi.linear + xi.angular.cross(r)).norm());
      }
      loosest = std::max(loosest, s->length(set, std::nullopt) / fastest);
    }
  }
  std::printf("cut blend sections: %zu, length / fastest point at most %.6g\n", count, loosest);
  // For comparison: the sections of the same chains' rotation-vector blends.
  Random again(4109);
  std::size_t cubic = 0;
  for (int i = 0; i < 20; ++i) {
    const Posed a = again.pose(0.5);
    const V pivot = again.vector(0.1);
    const Posed b = again.nearby(a, 0.3, 1.0), c = again.nearby(b, 0.3, 1.0), d = again.nearby(c, 0.3, 1.0);
    Path path = Path::lin(a, b, Interpolation::decoupled, pivot);
    path.then_weighted(Path::lin(b, c, Interpolation::decoupled, pivot), again.uniform(0.1, 0.5),
                       OrientationBlend::rotation_vector, 1e-3)
        .then_weighted(Path::lin(c, d, Interpolation::decoupled, pivot), again.uniform(0.1, 0.5),
                       OrientationBlend::rotation_vector, 1e-3);
    for (const Section& s : path.sections()) cubic += std::holds_alternative<CurveSection>(s);
  }
  std::printf("the same chains with rotation-vector blends: %zu sections\n", cubic);
  EXPECT_LE(loosest, 1.01);
}

// The DISP guarantee along planned chains of LINs blended by nested SLERP (as the planner
// tests do for the other families): every point within its limit to 10⁻⁶, by dense chords.
TEST(SlerpBlend, PlannedChainsKeepTheGuarantee) {
  Random rnd(4107);
  double worst = 0.0;
  for (int i = 0; i < 30; ++i) {
    const double v = rnd.uniform(0.05, 1.0);
    const MetricSetd set = testing::random_set(rnd, v);
    const Path path = testing::random_slerp_blended_chain(rnd);
    const ProfileKind kind = rnd.integer(0, 1) ? ProfileKind::scurve : ProfileKind::trapezoid;
    const Trajectory traj = plan(path, set, testing::random_limits(rnd, v, kind), kind);
    const double ratio = testing::worst_speed_ratio(traj, set, v, 2000);
    worst = std::max(worst, ratio);
    ASSERT_LE(ratio, 1.0 + 1e-6) << "case " << i;
    ASSERT_EQ(traj.piece_count(), 1u) << "case " << i;
  }
  std::printf("nested-SLERP chains: worst speed / limit %.9g\n", worst);
}

TEST(SlerpBlend, BadInputIsRefused) {
  auto at = [](double x, double y, double angle) {
    return Posed(Eigen::Quaterniond(Eigen::AngleAxisd(angle, V::UnitZ())), V(x, y, 0.0));
  };
  const Posed a = at(0, 0, 0), via = at(0.2, 0, 0.3), b = at(0.2, 0.2, 0.6), c = at(0.4, 0.3, 0.2);
  const auto nested = OrientationBlend::nested_slerp;
  Path path = Path::lin(a, via);
  EXPECT_NE(message_of([&] { path.then_weighted(Path::lin(via, b), 0.0, nested); }).find("weight = 0"),
            std::string::npos);
  EXPECT_NE(message_of([&] { path.then_weighted(Path::lin(via, b), 0.6, nested); }).find("weight = 0.6"),
            std::string::npos);
  EXPECT_NE(message_of([&] { path.then_weighted(Path::lin(via, b), std::nan(""), nested); }).find("weight = nan"),
            std::string::npos);
  EXPECT_NE(message_of([&] { path.then_weighted(Path::circ(via, b, c), 0.3, nested); }).find("next"),
            std::string::npos);
  EXPECT_NE(message_of([&] {
              path.then_weighted(Path::lin(via, b, Interpolation::screw), 0.3, nested);
            }).find("decoupled LIN"),
            std::string::npos);
  EXPECT_NE(message_of([&] {
              path.then_weighted(Path::lin(via, b, Interpolation::decoupled, V(0.01, 0, 0)), 0.3, nested);
            }).find("another pivot"),
            std::string::npos);
  Path arc = Path::circ(a, at(0.1, 0.05, 0.1), via);
  EXPECT_NE(message_of([&] { arc.then_weighted(Path::lin(via, b), 0.3, nested); }).find("orientation_blend"),
            std::string::npos);
  EXPECT_NE(message_of([&] { path.then(Path::lin(via, b), 0.5, 0.01, 1e-3, nested); }).find("before"),
            std::string::npos);
  EXPECT_NE(message_of([&] { orientation_blend_from_string("slerp"); }).find("orientation_blend = \"slerp\""),
            std::string::npos);
  EXPECT_EQ(path.size(), 1u);  // a refused blend leaves the path as it was
  EXPECT_EQ(orientation_blend_from_string("nested_slerp"), nested);
  EXPECT_EQ(orientation_blend_from_string(to_string(OrientationBlend::rotation_vector)),
            OrientationBlend::rotation_vector);
}

// A path with nested-SLERP blends made again from its sections (what a pickle keeps) is the same.
TEST(SlerpBlend, FromSectionsRoundTrip) {
  Random rnd(4108);
  const Path path = testing::random_slerp_blended_chain(rnd);
  const Path again = Path::from_sections(path.sections(), path.first_move_size(), path.last_move_size(),
                                         path.section_limits(), path.move_starts());
  ASSERT_EQ(again.size(), path.size());
  for (int j = 0; j <= 100; ++j) {
    const Posed p = again.sample(j / 100.0), q = path.sample(j / 100.0);
    ASSERT_EQ(p.translation(), q.translation());
    ASSERT_EQ(p.quaternion().coeffs(), q.quaternion().coeffs());
  }
}

}  // namespace
}  // namespace dispkin
