// The overlapped velocity method of the Mamezou trajectory article (Ishii, "Algorithm 2 for Robot
// Manipulator Control"; doc/planning.md §7): the article's formulas, continuity, and running
// through a corner without stopping.
#include <gtest/gtest.h>

#include <dispkin/planning/overlap.hpp>
#include <dispkin/shapes.hpp>

#include "random_cases.hpp"

namespace dispkin {
namespace {

using V = Eigen::Vector3d;
using testing::message_of;
using testing::Random;

MetricSetd tool() {
  MetricSetd set;
  set.add_relative(shapes::icosahedron(0.05));
  return set;
}

struct Moves {
  Trajectory before, after;
  Posed via;
};

Moves random_moves(Random& rnd, ProfileKind kind) {
  const Posed a = rnd.pose(0.5), via = rnd.nearby(a, 0.4, 1.0), b = rnd.nearby(via, 0.4, 1.0);
  Limits limits{0.2, 1.0, std::nullopt};
  if (kind == ProfileKind::scurve) limits.jerk = 10.0;
  return {plan(Path::lin(a, via), tool(), limits, kind), plan(Path::lin(via, b), tool(), limits, kind), via};
}

// P(t) = P_b(t) + P_f(t′) − P₂ and R(t) = R_f(t′) R₂⁻¹ R_b(t), recomputed from the two moves.
TEST(Overlap, ReproducesTheArticlesFormulas) {
  Random rnd(401);
  for (int i = 0; i < 200; ++i) {
    const Moves m = random_moves(rnd, i % 2 ? ProfileKind::scurve : ProfileKind::trapezoid);
    const double t_ov = rnd.uniform(0.0, 1.0) * std::min(m.before.duration(), m.after.duration());
    const OverlappedTrajectory o(m.before, m.after, t_ov);
    ASSERT_NEAR(o.duration(), m.before.duration() + m.after.duration() - t_ov, 1e-12);
    for (int k = 0; k <= 20; ++k) {
      const double t = o.overlap_start() + t_ov * k / 20.0;
      const Posed pb = m.before.sample(t).pose, pf = m.after.sample(t - o.overlap_start()).pose;
      const Posed got = o.sample(t).pose;
      const V p = pb.translation() + pf.translation() - m.via.translation();
      const Eigen::Matrix3d r = pf.rotation() * m.via.rotation().transpose() * pb.rotation();
      ASSERT_LE((got.translation() - p).norm(), 1e-12);
      ASSERT_LE((got.rotation() - r).norm(), 1e-12);
    }
  }
}

TEST(Overlap, TwistIsTheDerivativeAndThePoseIsContinuous) {
  Random rnd(402);
  for (int i = 0; i < 100; ++i) {
    const Moves m = random_moves(rnd, ProfileKind::scurve);
    const double t_ov = rnd.uniform(0.1, 0.9) * std::min(m.before.duration(), m.after.duration());
    const OverlappedTrajectory o(m.before, m.after, t_ov, rnd.vector(0.1));
    const double t = o.overlap_start() + rnd.uniform(0.05, 0.95) * t_ov, d = 1e-6;
    const Twistd numeric = (o.sample(t - d).pose.inverse() * o.sample(t + d).pose).log() * (1.0 / (2 * d));
    ASSERT_LE((numeric.vector() - o.sample(t).body_twist.vector()).norm(), 1e-6 * (1 + numeric.vector().norm()));
    for (const double edge : {o.overlap_start(), m.before.duration()}) {
      ASSERT_TRUE(o.sample(edge - 1e-9).pose.is_approx(o.sample(edge + 1e-9).pose, 1e-7)) << "jump at t = " << edge;
    }
    ASSERT_TRUE(o.sample(o.duration()).pose.is_approx(m.after.sample(m.after.duration()).pose, 1e-12));
  }
}

// Two translations at a right angle with the same trapezoid: overlapping the whole ramp, the
// path never stops, and every point's speed |ċ_b + ċ_f| ≤ ṡ_b + ṡ_f = v stays within the limit.
TEST(Overlap, RunsThroughACornerWithinTheLimit) {
  const Posed a, via(Eigen::Quaterniond::Identity(), V(0.4, 0, 0)), b(Eigen::Quaterniond::Identity(), V(0.4, 0.4, 0));
  const Limits limits{0.2, 1.0, std::nullopt};
  const Trajectory before = plan(Path::lin(a, via), tool(), limits, ProfileKind::trapezoid);
  const Trajectory after = plan(Path::lin(via, b), tool(), limits, ProfileKind::trapezoid);
  const double ramp = limits.velocity / limits.acceleration;
  const OverlappedTrajectory o(before, after, ramp);
  const MetricSetd set = tool();
  double slowest = 1e9, fastest = 0;
  for (int k = 1; k < 1000; ++k) {
    const double t = o.overlap_start() + ramp * k / 1000.0;
    const TrajectorySample s = o.sample(t);
    const double speed = max_point_speed(set, s.pose, s.body_twist);
    slowest = std::min(slowest, speed);
    fastest = std::max(fastest, speed);
  }
  EXPECT_GE(slowest, 0.7 * limits.velocity);  // √½ v at the middle of the corner
  EXPECT_LE(fastest, limits.velocity * (1 + 1e-9));
  EXPECT_LT(o.duration(), before.duration() + after.duration() - 0.99 * ramp);
}

TEST(Overlap, BadInputIsRefused) {
  Random rnd(403);
  const Moves m = random_moves(rnd, ProfileKind::trapezoid);
  const double shorter = std::min(m.before.duration(), m.after.duration());
  EXPECT_NE(message_of([&] { OverlappedTrajectory(m.before, m.after, -0.1); }).find("overlap = -0.1"),
            std::string::npos);
  EXPECT_NE(message_of([&] { OverlappedTrajectory(m.before, m.after, shorter * 1.01); }).find("shorter move"),
            std::string::npos);
  EXPECT_NE(message_of([&] { OverlappedTrajectory(m.before, m.after, std::nan("")); }).find("overlap = nan"),
            std::string::npos);
  EXPECT_NE(message_of([&] { OverlappedTrajectory(m.after, m.before, 0.0); }).find("must start where"),
            std::string::npos);
}

}  // namespace
}  // namespace dispkin
