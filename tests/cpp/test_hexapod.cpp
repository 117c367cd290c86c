// Hexapod: inverse kinematics against a direct computation, the leg Jacobian against finite
// differences, forward(inverse(T)) = T, symmetric layouts, pivots, workspace check, failures,
// the JSON description and every kind of bad input.
#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include <dispkin/hexapod/hexapod.hpp>
#include <dispkin/path/path.hpp>
#include <dispkin/planning/planner.hpp>

#include "random_cases.hpp"

namespace dispkin {
namespace {

using hexapod::Hexapod;
using hexapod::LegExcursion;
using hexapod::TrajectoryCheck;
using hexapod::WorkspaceCheck;
using hexapod::xyzuvw_for_new_pivot;
using testing::message_of;
using testing::Random;
using testing::runtime_message_of;
using Legs = Hexapod::Legs;
using Vector6 = Eigen::Matrix<double, 6, 1>;
constexpr double pi = 3.14159265358979323846;

// A desktop hexapod: base radius 150 mm, platform radius 100 mm, joints in pairs 20° apart.
Hexapod test_hexapod() { return Hexapod::symmetric(0.15, 20 * pi / 180, 0.10, 20 * pi / 180, 0.20, 0.15, 0.32, 0.01); }

// A random pose around home whose legs are all in range.
Posed reachable_pose(const Hexapod& h, Random& rnd) {
  for (;;) {
    const Posed pose = h.home() * Posed::exp(Twistd(rnd.vector(0.04), rnd.unit_vector() * rnd.uniform(0.0, 0.25)));
    if (h.check(pose).reachable()) return pose;
  }
}

Eigen::Matrix3d rx(double a) { return Eigen::AngleAxisd(a, Eigen::Vector3d::UnitX()).toRotationMatrix(); }
Eigen::Matrix3d ry(double a) { return Eigen::AngleAxisd(a, Eigen::Vector3d::UnitY()).toRotationMatrix(); }
Eigen::Matrix3d rz(double a) { return Eigen::AngleAxisd(a, Eigen::Vector3d::UnitZ()).toRotationMatrix(); }

TEST(Hexapod, InverseMatchesDirectComputationWithHomogeneousMatrices) {
  const Hexapod h = test_hexapod();
  Random rnd(501);
  for (int n = 0; n < testing::case_count(10000); ++n) {
    const Posed pose = rnd.pose(0.5);
    const Eigen::Matrix4d m = pose.matrix();
    const Legs legs = h.leg_lengths(pose);
    for (int i = 0; i < 6; ++i) {
      const Eigen::Vector4d p(h.platform_joints()(0, i), h.platform_joints()(1, i), h.platform_joints()(2, i), 1.0);
      const double expected = ((m * p).head<3>() - h.base_joints().col(i)).norm();
      ASSERT_NEAR(legs(i), expected, 1e-14) << "leg " << i;
    }
  }
}

TEST(Hexapod, InverseOfXyzuvwRotatesAboutThePivot) {
  const Hexapod h = test_hexapod();
  Random rnd(502);
  for (int n = 0; n < testing::case_count(10000); ++n) {
    Vector6 v;
    v << rnd.vector(0.05), rnd.vector(0.3);
    v(2) += 0.2;
    const Eigen::Vector3d pivot = rnd.vector(0.1);
    // x_base = Rx(U) Ry(V) Rz(W) (p − pivot) + pivot + XYZ, written out independently.
    const Eigen::Matrix3d r = rx(v(3)) * ry(v(4)) * rz(v(5));
    const Legs legs = h.leg_lengths(v, pivot);
    for (int i = 0; i < 6; ++i) {
      const Eigen::Vector3d x = r * (h.platform_joints().col(i) - pivot) + pivot + v.head<3>();
      ASSERT_NEAR(legs(i), (x - h.base_joints().col(i)).norm(), 1e-14);
    }
  }
}

TEST(Hexapod, LegJacobianMatchesFiniteDifferencesOfBodyTwists) {
  const Hexapod h = test_hexapod();
  Random rnd(503);
  const double step = 1e-6;
  for (int n = 0; n < testing::case_count(1000); ++n) {
    const Posed pose = reachable_pose(h, rnd);
    const Hexapod::Jacobian j = h.leg_jacobian(pose);
    for (int k = 0; k < 6; ++k) {
      Vector6 e = Vector6::Zero();
      e(k) = step;
      const Legs plus = h.leg_lengths(pose * Posed::exp(Twistd(e)));
      const Legs minus = h.leg_lengths(pose * Posed::exp(Twistd(Vector6(-e))));
      const Legs numeric = (plus - minus) / (2 * step);
      ASSERT_LT((j.col(k) - numeric).cwiseAbs().maxCoeff(), 1e-8) << "column " << k;
    }
  }
}

TEST(Hexapod, ForwardOfInverseIsThePoseFromANearbyStart) {
  const Hexapod h = test_hexapod();
  Random rnd(504);
  const int n = testing::case_count(10000);
  for (int c = 0; c < n; ++c) {
    const Posed pose = reachable_pose(h, rnd);
    const Legs legs = h.leg_lengths(pose);
    const Posed guess = rnd.nearby(pose, 0.01, 0.05);
    const Posed found = h.forward(legs, guess);
    ASSERT_TRUE(found.is_approx(pose, 1e-12)) << "case " << c << "\n" << found.matrix() << "\n" << pose.matrix();
    ASSERT_LT((h.leg_lengths(found) - legs).cwiseAbs().maxCoeff(), 1e-12);
  }
}

TEST(Hexapod, InverseOfForwardIsTheLegsFromHome) {
  const Hexapod h = test_hexapod();
  Random rnd(505);
  const Legs home_legs = h.leg_lengths(h.home());
  for (int c = 0; c < testing::case_count(10000); ++c) {
    Legs legs;
    for (int i = 0; i < 6; ++i) legs(i) = home_legs(i) + rnd.uniform(-0.01, 0.01);
    const Posed pose = h.forward(legs);
    ASSERT_LT((h.leg_lengths(pose) - legs).cwiseAbs().maxCoeff(), 1e-12) << "case " << c;
  }
}

TEST(Hexapod, SymmetricSixSixLayoutHasTheJointsAtTheStatedAngles) {
  const double gb = 0.3, gp = 0.2;
  const Hexapod h = Hexapod::symmetric(0.2, gb, 0.1, gp, 0.25, 0.1, 0.5, 0.02);
  for (int k = 0; k < 3; ++k) {
    const double c = 2 * pi / 3 * k;
    const double base_angle[2] = {c - gb / 2, c + gb / 2};
    const double platform_angle[2] = {c - pi / 3 + gp / 2, c + pi / 3 - gp / 2};
    for (int j = 0; j < 2; ++j) {
      const int i = 2 * k + j;
      EXPECT_LT(
          (h.base_joints().col(i) - Eigen::Vector3d(0.2 * std::cos(base_angle[j]), 0.2 * std::sin(base_angle[j]), 0))
              .norm(),
          1e-15);
      EXPECT_LT((h.platform_joints().col(i) -
                 Eigen::Vector3d(0.1 * std::cos(platform_angle[j]), 0.1 * std::sin(platform_angle[j]), 0))
                    .norm(),
                1e-15);
    }
  }
  // Leg 1 (base at +gb/2) and leg 2 (base at 120° − gb/2) end at the same platform pair.
  EXPECT_NEAR((h.platform_joints().col(1) - h.platform_joints().col(2)).norm(), 2 * 0.1 * std::sin(gp / 2), 1e-15);
  EXPECT_TRUE(h.home().is_approx(Posed(Eigen::Quaterniond::Identity(), Eigen::Vector3d(0, 0, 0.25)), 0.0));
  // By symmetry all legs have the same length at home.
  const Legs l = h.leg_lengths(h.home());
  EXPECT_LT((l.array() - l(0)).abs().maxCoeff(), 1e-15);
  EXPECT_EQ(h.leg_min(), Legs::Constant(0.1));
  EXPECT_EQ(h.leg_max(), Legs::Constant(0.5));
  EXPECT_EQ(h.leg_speed(), Legs::Constant(0.02));
}

TEST(Hexapod, SymmetricSixThreeLayoutJoinsPlatformJointsInPairs) {
  const Hexapod h = Hexapod::symmetric(0.2, 0.3, 0.1, 0.0, 0.25, 0.1, 0.5, 0.02);
  EXPECT_LT((h.platform_joints().col(1) - h.platform_joints().col(2)).norm(), 1e-16);
  EXPECT_LT((h.platform_joints().col(3) - h.platform_joints().col(4)).norm(), 1e-16);
  EXPECT_LT((h.platform_joints().col(5) - h.platform_joints().col(0)).norm(), 1e-15);
  EXPECT_LT((h.platform_joints().col(1) - Eigen::Vector3d(0.1 * std::cos(pi / 3), 0.1 * std::sin(pi / 3), 0)).norm(),
            1e-15);
  EXPECT_LT((h.platform_joints().col(0) - Eigen::Vector3d(0.1 * std::cos(-pi / 3), 0.1 * std::sin(-pi / 3), 0)).norm(),
            1e-15);
  // A 6-3 hexapod is not singular at home: forward kinematics still converges.
  const Posed target =
      h.home() * Posed::exp(Twistd(Eigen::Vector3d(0.01, -0.005, 0.01), Eigen::Vector3d(0.02, 0.01, -0.03)));
  EXPECT_TRUE(h.forward(h.leg_lengths(target)).is_approx(target, 1e-12));
}

TEST(Hexapod, NewPivotKeepsThePlatformPose) {
  Random rnd(506);
  for (int n = 0; n < testing::case_count(10000); ++n) {
    Vector6 v;
    v << rnd.vector(0.1), rnd.vector(1.0);
    const Eigen::Vector3d old_pivot = rnd.vector(0.2), new_pivot = rnd.vector(0.2);
    const Vector6 w = xyzuvw_for_new_pivot(v, old_pivot, new_pivot);
    ASSERT_TRUE(Posed::from_xyzuvw(w, new_pivot).is_approx(Posed::from_xyzuvw(v, old_pivot), 1e-14));
    ASSERT_EQ(w.tail<3>(), v.tail<3>());
  }
  // At U = V = W = 0 (where PI controllers allow a pivot change) XYZ does not change.
  Vector6 v;
  v << 0.01, 0.02, 0.03, 0, 0, 0;
  EXPECT_EQ(xyzuvw_for_new_pivot(v, Eigen::Vector3d(0.1, 0, 0), Eigen::Vector3d(0, 0.2, 0.3)), v);
  // Elsewhere it does: the same XYZUVW about another pivot is another pose.
  v(3) = 0.1;
  EXPECT_GT((xyzuvw_for_new_pivot(v, Eigen::Vector3d::Zero(), Eigen::Vector3d(0, 0, 0.1)) - v).norm(), 1e-3);
}

TEST(Hexapod, CheckNamesTheLegOutOfRangeAndByHowMuch) {
  const Hexapod s = test_hexapod();
  const double home_length = s.leg_lengths(s.home())(0);
  Legs lo = Legs::Constant(0.1), hi = Legs::Constant(0.5);
  hi(3) = home_length - 0.01;  // leg 3 too long at home by 10 mm
  lo(5) = home_length + 0.02;  // leg 5 too short at home by 20 mm
  hi(5) = 0.5;
  const Hexapod h(s.base_joints(), s.platform_joints(), lo, hi, s.leg_speed(), s.home());
  const WorkspaceCheck c = h.check(h.home());
  ASSERT_FALSE(c.reachable());
  ASSERT_EQ(c.violations.size(), 2u);
  EXPECT_EQ(c.violations[0].leg, 3);
  EXPECT_NEAR(c.violations[0].excess, 0.01, 1e-15);
  EXPECT_EQ(c.violations[0].upper, hi(3));
  EXPECT_EQ(c.violations[1].leg, 5);
  EXPECT_NEAR(c.violations[1].excess, 0.02, 1e-15);
  EXPECT_EQ(c.lengths, h.leg_lengths(h.home()));
  const std::string m = message_of([&] { h.require_reachable(h.home()); });
  EXPECT_NE(m.find("leg 3 length = "), std::string::npos) << m;
  EXPECT_NE(m.find("by 0.01"), std::string::npos) << m;
  EXPECT_TRUE(s.check(s.home()).reachable());
  EXPECT_NO_THROW(s.require_reachable(s.home()));
}

// Legs outside their ranges are refused before any iteration.
TEST(Hexapod, ForwardRefusesLegsOutOfRange) {
  const Hexapod h = test_hexapod();
  Legs legs = h.leg_lengths(h.home());
  legs(5) = 5.0;
  const std::string m = message_of([&] { h.forward(legs); });
  EXPECT_NE(m.find("legs[5] is outside its length range"), std::string::npos) << m;
}

// A hexapod with wide leg ranges, so that forward() gets to Newton's method and reports its failures.
Hexapod wide_hexapod() { return Hexapod::symmetric(0.15, 20 * pi / 180, 0.10, 20 * pi / 180, 0.20, 0.0, 10.0, 0.01); }

TEST(Hexapod, ForwardReportsUnreachableLegLengths) {
  const Hexapod h = wide_hexapod();
  Legs legs = h.leg_lengths(h.home());
  legs(5) = 5.0;  // no pose has one leg 5 m long and the others 0.2 m
  const std::string m = runtime_message_of([&] { h.forward(legs); });
  EXPECT_NE(m.find("Hexapod::forward"), std::string::npos) << m;
  EXPECT_NE(m.find("residual"), std::string::npos) << m;
  EXPECT_TRUE(m.find("iterations") != std::string::npos) << m;
}

TEST(Hexapod, ForwardReportsASingularJacobian) {
  const Hexapod h = wide_hexapod();
  // Platform in the base plane: every leg horizontal, no leg can lift the platform.
  const Posed flat;
  Legs legs = h.leg_lengths(flat);
  legs.array() += 1e-3;
  const std::string m = runtime_message_of([&] { h.forward(legs, flat); });
  EXPECT_NE(m.find("singular leg Jacobian"), std::string::npos) << m;
  EXPECT_NE(m.find("after 0 iterations"), std::string::npos) << m;
}

TEST(Hexapod, ForwardRefusesNonFiniteLegs) {
  const Hexapod h = test_hexapod();
  Legs legs = h.leg_lengths(h.home());
  legs(2) = std::nan("");
  EXPECT_EQ(message_of([&] { h.forward(legs); }).rfind("legs[2] = nan: must be finite and greater than zero", 0), 0u);
}

TEST(Hexapod, ForwardRefusesNonPositiveLegs) {
  const Hexapod h = test_hexapod();
  Legs legs = h.leg_lengths(h.home());
  legs(4) = -0.1;
  EXPECT_EQ(message_of([&] { h.forward(legs); }).rfind("legs[4] = -0.1: must be finite and greater than zero", 0), 0u);
}

TEST(Hexapod, ImplementsTheKinematicsInterface) {
  const Hexapod h = test_hexapod();
  const Kinematics& k = h;
  EXPECT_EQ(k.dof(), 6);
  const Posed pose = h.home() * Posed::exp(Twistd(Eigen::Vector3d(0.01, 0, 0), Eigen::Vector3d(0, 0.05, 0)));
  const std::vector<Eigen::VectorXd> q = k.inverse(pose);
  ASSERT_EQ(q.size(), 1u);
  EXPECT_EQ(Legs(q[0]), h.leg_lengths(pose));
  EXPECT_TRUE(k.forward(q[0]).is_approx(pose, 1e-12));
  const JointLimits limits = k.joint_limits();
  EXPECT_EQ(Legs(limits.lower), h.leg_min());
  EXPECT_EQ(Legs(limits.upper), h.leg_max());
  EXPECT_EQ(Legs(limits.velocity), h.leg_speed());
  EXPECT_EQ(k.joint_names(), (std::vector<std::string>{"leg1", "leg2", "leg3", "leg4", "leg5", "leg6"}));
  EXPECT_NE(message_of([&] { k.forward(Eigen::VectorXd::Constant(5, 0.2)); }).find("q size = 5"), std::string::npos);
}

// --- leg speed along planned trajectories ------------------------------------------------------

TEST(HexapodTrajectory, LegSpeedGroupHoldsEveryLegToItsSpeedLimit) {
  const Hexapod h = test_hexapod();
  Random rnd(508);
  double largest_ratio = 0.0;
  for (int c = 0; c < testing::case_count(200) / 4 + 1; ++c) {
    MetricSetd set;
    set.add_relative(Eigen::Vector3d(0.0, 0.0, 0.05));  // a tool point, group 0
    set.add_relative(Eigen::Vector3d(0.02, 0.0, 0.05));
    set.add_relative(Eigen::Vector3d(0.0, 0.02, 0.05));
    h.add_leg_speed_group(set, 1);
    ASSERT_EQ(set.find_group(1)->speed_limit, h.leg_speed().minCoeff());
    const Posed a = reachable_pose(h, rnd), b = reachable_pose(h, rnd);
    const Path path = c % 2 ? Path::lin(a, b) : Path::lin(a, b, Interpolation::screw);
    // System velocity 10× the leg speed: only the leg group holds the trajectory back.
    const Trajectory trajectory = plan(path, set, Limits{0.1, 1.0, 20.0});
    const TrajectoryCheck check = h.check_trajectory(trajectory, trajectory.duration() / 2000);
    for (int i = 0; i < 6; ++i) {
      ASSERT_LE(check.max_speed(i), h.leg_speed()(i) * (1 + 1e-9)) << "case " << c << " leg " << i;
      largest_ratio = std::max(largest_ratio, check.max_speed(i) / h.leg_speed()(i));
    }
    // The analytic leg speed J ξ agrees with finite differences of the leg lengths.
    const double t = rnd.uniform(0.1, 0.9) * trajectory.duration(), dt = 1e-6;
    const Legs numeric =
        (h.leg_lengths(trajectory.sample(t + dt).pose) - h.leg_lengths(trajectory.sample(t - dt).pose)) / (2 * dt);
    const TrajectorySample s = trajectory.sample(t);
    ASSERT_LT((h.leg_jacobian(s.pose) * s.body_twist.vector() - numeric).cwiseAbs().maxCoeff(), 1e-9);
  }
  // The bound is not vacuous: some leg comes close to its limit.
  EXPECT_GT(largest_ratio, 0.5);
}

TEST(HexapodTrajectory, WithoutTheGroupLegsAreTooFastAndTheCheckSaysWhich) {
  const Hexapod h = test_hexapod();
  MetricSetd set;
  set.add_relative(Eigen::Vector3d(0.0, 0.0, 0.05));
  set.add_relative(Eigen::Vector3d(0.02, 0.0, 0.05));
  set.add_relative(Eigen::Vector3d(0.0, 0.02, 0.05));
  const Posed a = h.home() * Posed::exp(Twistd(Eigen::Vector3d(0, 0, -0.02), Eigen::Vector3d::Zero()));
  const Posed b = h.home() * Posed::exp(Twistd(Eigen::Vector3d(0, 0, 0.02), Eigen::Vector3d::Zero()));
  const Trajectory trajectory = plan(Path::lin(a, b), set, Limits{0.1, 1.0, 20.0});
  const TrajectoryCheck check = h.check_trajectory(trajectory, 1e-3);
  ASSERT_EQ(check.excursions.size(), 6u);  // a vertical move drives all legs equally
  for (int i = 0; i < 6; ++i) {
    const LegExcursion& e = check.excursions[static_cast<std::size_t>(i)];
    EXPECT_EQ(e.kind, LegExcursion::Kind::speed);
    EXPECT_EQ(e.leg, i);
    EXPECT_GT(e.start_time, 0.0);
    EXPECT_LT(e.end_time, trajectory.duration());
    EXPECT_NEAR(e.excess, e.worst_value - h.leg_speed()(i), 1e-15);
    EXPECT_GT(e.worst_value, 5 * h.leg_speed()(i));
  }
}

TEST(HexapodTrajectory, MoveBetweenReachablePosesThroughAnUnreachableOneIsReported) {
  const Hexapod s = test_hexapod();
  // Sideways across the base: a leg's length ‖a + τ d‖ is convex in τ, so it is shortest
  // inside the move. Limits just below the shorter end length of each leg.
  const Posed a = s.home() * Posed::exp(Twistd(Eigen::Vector3d(0.08, 0, 0), Eigen::Vector3d::Zero()));
  const Posed b = s.home() * Posed::exp(Twistd(Eigen::Vector3d(-0.08, 0, 0), Eigen::Vector3d::Zero()));
  const Legs lo = s.leg_lengths(a).cwiseMin(s.leg_lengths(b)).array() - 1e-3;
  const Hexapod h(s.base_joints(), s.platform_joints(), lo, Legs::Constant(0.5), Legs::Constant(1.0), s.home());
  ASSERT_TRUE(h.check(a).reachable());
  ASSERT_TRUE(h.check(b).reachable());
  MetricSetd set;
  h.add_leg_speed_group(set, 0);
  const Trajectory trajectory = plan(Path::lin(a, b), set, Limits{0.01, 0.1, 2.0});
  const TrajectoryCheck check = h.check_trajectory(trajectory, trajectory.duration() / 10000);
  ASSERT_FALSE(check.ok());
  for (const LegExcursion& e : check.excursions) {
    EXPECT_EQ(e.kind, LegExcursion::Kind::length);
    EXPECT_GT(e.start_time, 0.0);
    EXPECT_LT(e.end_time, trajectory.duration());
    EXPECT_LE(e.start_time, e.worst_time);
    EXPECT_LE(e.worst_time, e.end_time);
    // The reported length is the leg's length at the reported time.
    EXPECT_EQ(e.worst_value, h.leg_lengths(trajectory.sample(e.worst_time).pose)(e.leg));
    EXPECT_NEAR(e.excess, lo(e.leg) - e.worst_value, 1e-15);
    EXPECT_FALSE(h.check(trajectory.sample(e.worst_time).pose).reachable());
  }
  // Every leg that dips below its range inside the move is reported, and only those.
  for (int i = 0; i < 6; ++i) {
    bool reported = false;
    for (const LegExcursion& e : check.excursions) reported = reported || e.leg == i;
    EXPECT_EQ(reported, check.min_length(i) < lo(i)) << "leg " << i;
  }
}

// --- leg speed, rule (b): the joint-space metric ------------------------------------------------

// A tool: three points 5 cm above the platform, group 0.
MetricSetd tool_points() {
  MetricSetd set;
  set.add_relative(Eigen::Vector3d(0.0, 0.0, 0.05));
  set.add_relative(Eigen::Vector3d(0.02, 0.0, 0.05));
  set.add_relative(Eigen::Vector3d(0.0, 0.02, 0.05));
  return set;
}

// A random path of each kind between reachable poses: decoupled LIN about a random pivot,
// screw LIN, CIRC.
Path random_hexapod_path(const Hexapod& h, Random& rnd, int family) {
  const Posed a = reachable_pose(h, rnd), b = reachable_pose(h, rnd);
  if (family % 4 == 0) return Path::lin(a, b, Interpolation::decoupled, rnd.vector(0.1));
  if (family % 4 == 1) return Path::lin(a, b, Interpolation::screw);
  if (family % 4 == 3) return Path::spline({a, reachable_pose(h, rnd), b}, rnd.vector(0.05), 1e-2);
  const Posed via = h.home() * Posed::exp(Twistd(rnd.vector(0.02), Eigen::Vector3d::Zero()));
  return Path::circ(a, Posed(a.quaternion(), via.translation()), b, rnd.vector(0.05), 0.05);
}

// At most `count` sections of the path, spread over it.
std::vector<Section> some_sections(const Path& path, std::size_t count) {
  std::vector<Section> out;
  const std::size_t step = std::max<std::size_t>(1, path.size() / count);
  for (std::size_t k = 0; k < path.size(); k += step) out.push_back(path.sections()[k]);
  return out;
}

// max over τ of |dℓ_i/dτ| on a dense grid, dℓ/dτ = J ξ (the quantity leg_rate_bounds bounds).
Legs dense_leg_rates(const Hexapod& h, const Section& section, int n) {
  Legs best = Legs::Zero();
  for (int k = 0; k <= n; ++k) {
    const double tau = static_cast<double>(k) / n;
    best =
        best.cwiseMax((h.leg_jacobian(section_pose(section, tau)) * section_twist(section, tau).vector()).cwiseAbs());
  }
  return best;
}

TEST(HexapodJointMetric, LegRateIsTheDerivativeOfTheLegLengthAlongTheSection) {
  const Hexapod h = test_hexapod();
  Random rnd(520);
  for (int c = 0; c < 30; ++c) {
    const Path path = random_hexapod_path(h, rnd, c);
    for (const Section& section : some_sections(path, 10)) {
      const double tau = rnd.uniform(0.01, 0.99), d = 1e-6;
      const Legs numeric =
          (h.leg_lengths(section_pose(section, tau + d)) - h.leg_lengths(section_pose(section, tau - d))) / (2 * d);
      const Legs exact = h.leg_jacobian(section_pose(section, tau)) * section_twist(section, tau).vector();
      ASSERT_LT((exact - numeric).cwiseAbs().maxCoeff(), 1e-8) << "case " << c;
    }
  }
}

TEST(HexapodJointMetric, BoundIsNeverBelowTheDenseMaximumAndWithinTheTolerance) {
  const Hexapod h = test_hexapod();
  Random rnd(521);
  const double tolerance = 1e-3;
  int sections = 0;
  // 20000 dense samples per section make each case costly (minutes under the sanitizers at the
  // sweep counts), so this oracle runs a sixteenth of the requested count, 20 to 40 cases.
  for (int c = 0; c < std::min(testing::case_count(200) / 16 + 8, 40); ++c) {
    const Path path = random_hexapod_path(h, rnd, c);
    for (const Section& section : some_sections(path, 10)) {
      const Legs bound = h.leg_rate_bounds(section, tolerance);
      const Legs dense = dense_leg_rates(h, section, 20000);
      const double demand = (dense.array() / h.leg_speed().array()).maxCoeff();
      for (int i = 0; i < 6; ++i) {
        ASSERT_GE(bound(i), dense(i)) << "case " << c << " leg " << i;
        // Tight: within the stated tolerance of the section's demand (plus what 20000 samples miss).
        ASSERT_LE(bound(i), dense(i) + tolerance * demand * h.leg_speed()(i) * (1 + 1e-3) + 1e-12)
            << "case " << c << " leg " << i;
      }
      ++sections;
    }
  }
  EXPECT_GT(sections, 100);
}

TEST(HexapodJointMetric, BoundOfAStandingSectionIsZero) {
  const Hexapod h = test_hexapod();
  EXPECT_EQ(h.leg_rate_bounds(Section(LinSection{h.home(), h.home()})), Legs::Zero());
}

TEST(HexapodJointMetric, SectionLengthsScaleWithTheSystemVelocity) {
  const Hexapod h = test_hexapod();
  Random rnd(522);
  const Path path = random_hexapod_path(h, rnd, 2);
  const std::vector<double> slow = h.leg_section_lengths(path, 0.05), fast = h.leg_section_lengths(path, 0.1);
  ASSERT_EQ(slow.size(), path.size());
  for (std::size_t k = 0; k < path.size(); ++k) {
    EXPECT_NEAR(fast[k], 2 * slow[k], 1e-15 * fast[k]);
    EXPECT_NEAR(slow[k], 0.05 * (h.leg_rate_bounds(path.sections()[k]).array() / h.leg_speed().array()).maxCoeff(),
                1e-15);
  }
  // A single section: joint_metric's lengths are exactly the leg lengths.
  const Path lin = Path::lin(reachable_pose(h, rnd), reachable_pose(h, rnd));
  EXPECT_EQ(h.joint_metric(lin, Limits{0.1, 1.0, 20.0}).min_section_lengths, h.leg_section_lengths(lin, 0.1));
}

// Along a CIRC the lengths are raised to one common speed: the planner runs through the arc
// without stopping, and the legs stay within their speed.
TEST(HexapodJointMetric, CircIsOnePieceAndKeepsTheLegs) {
  const Hexapod h = test_hexapod();
  const auto shifted = [&](double x, double y) {
    return h.home() * Posed::exp(Twistd(Eigen::Vector3d(x, y, 0.0), Eigen::Vector3d(0.0, 0.0, 0.05)));
  };
  const Path arc =
      Path::circ(shifted(0.02, 0.0), shifted(0.0, 0.02), shifted(-0.02, 0.0), Eigen::Vector3d::Zero(), 0.01);
  ASSERT_GT(arc.size(), 5u);
  const Limits limits{0.1, 1.0, 20.0};
  const PlanOptions options = h.joint_metric(arc, limits);
  const std::vector<double> needed = h.leg_section_lengths(arc, limits.velocity);
  for (std::size_t k = 0; k < arc.size(); ++k) ASSERT_GE(options.min_section_lengths[k], needed[k]);
  const Trajectory trajectory = plan(arc, tool_points(), limits, ProfileKind::scurve, options);
  EXPECT_EQ(trajectory.piece_count(), 1u);
  const TrajectoryCheck check = h.check_trajectory(trajectory, trajectory.duration() / 20000);
  EXPECT_TRUE(check.ok());
  EXPECT_LE(check.max_speed.maxCoeff(), h.leg_speed().maxCoeff() * (1 + 1e-9));
  MetricSetd with_group = tool_points();
  h.add_leg_speed_group(with_group, 1);
  const Trajectory rule_a = plan(arc, with_group, limits);
  std::printf("CIRC of %zu sections: rule (b) %.3f s, rule (a) %.3f s\n", arc.size(), trajectory.duration(),
              rule_a.duration());
}

// PlanOptions::joint_metric is evaluated on the path as planned: with corners blended it plans
// exactly what the joint metric of the blended path does, and the corners left keep the blend's
// reason for stopping.
TEST(HexapodJointMetric, OptionsEvaluateItOnTheBlendedPath) {
  const Hexapod h = test_hexapod();
  const auto shifted = [&](double x, double y) {
    return h.home() * Posed::exp(Twistd(Eigen::Vector3d(x, y, 0.0), Eigen::Vector3d::Zero()));
  };
  // A right-angle corner (blended) and a reversal (not blendable).
  Path path = Path::lin(shifted(0.0, 0.0), shifted(0.02, 0.0));
  path.then(Path::lin(shifted(0.02, 0.0), shifted(0.02, 0.02)))
      .then(Path::lin(shifted(0.02, 0.02), shifted(0.02, 0.0)));
  const Limits limits{0.1, 1.0, 20.0};
  PlanOptions options;
  options.corner_tolerance = 0.005;
  options.joint_metric = h.joint_metric();
  const Trajectory planned = plan(path, tool_points(), limits, ProfileKind::scurve, options);
  const Path blended = path.blended(options.corner_tolerance);
  const Trajectory reference =
      plan(blended, tool_points(), limits, ProfileKind::scurve, h.joint_metric(blended, limits));
  EXPECT_EQ(planned.duration(), reference.duration());
  EXPECT_EQ(planned.section_lengths(), reference.section_lengths());
  ASSERT_EQ(planned.stops().size(), 1u);
  EXPECT_NE(planned.stops()[0].reason.find("reverses"), std::string::npos) << planned.stops()[0].reason;
  // Its lengths and min_section_lengths are one or the other.
  options.min_section_lengths.assign(path.size(), 0.0);
  options.corner_tolerance = 0.0;
  EXPECT_NE(
      message_of([&] { plan(path, tool_points(), limits, ProfileKind::scurve, options); }).find("with a joint_metric"),
      std::string::npos);
}

TEST(HexapodJointMetric, PlannedTrajectoriesKeepEveryLegWithinItsSpeed) {
  const Hexapod h = test_hexapod();
  Random rnd(523);
  const MetricSetd set = tool_points();  // no leg group: rule (b) alone holds the legs
  const Limits limits{0.1, 1.0, 20.0};   // system velocity 10× the leg speed
  double fastest_without = 0.0;
  for (int c = 0; c < testing::case_count(200) / 10 + 3; ++c) {
    const Path path = random_hexapod_path(h, rnd, c);
    const Trajectory trajectory = plan(path, set, limits, ProfileKind::scurve, h.joint_metric(path, limits));
    const TrajectoryCheck check = h.check_trajectory(trajectory, trajectory.duration() / 20000);
    for (int i = 0; i < 6; ++i)
      ASSERT_LE(check.max_speed(i), h.leg_speed()(i) * (1 + 1e-9)) << "case " << c << " leg " << i;
    for (const LegExcursion& e : check.excursions) ASSERT_NE(e.kind, LegExcursion::Kind::speed) << "case " << c;
    fastest_without = std::max(fastest_without, h.check_trajectory(plan(path, set, limits), 1e-3).max_speed.maxCoeff());
  }
  // Without rule (b) the same plans drive legs far beyond their limit.
  EXPECT_GT(fastest_without, 3 * h.leg_speed().maxCoeff());
}

TEST(HexapodJointMetric, LegSpeedDominatedMoveReachesTheLegLimit) {
  // A move whose fastest leg (leg 3) peaks in the middle, where the trajectory cruises.
  const Hexapod h = test_hexapod();
  Vector6 va, vb;
  va << -0.011, 0.021, 0.162, -0.032, -0.077, -0.014;
  vb << -0.030, -0.022, 0.205, -0.067, 0.175, 0.063;
  const Path path = Path::lin(Posed::from_xyzuvw(va), Posed::from_xyzuvw(vb));
  const Limits limits{0.1, 1.0, 20.0};
  const Trajectory trajectory = plan(path, tool_points(), limits, ProfileKind::scurve, h.joint_metric(path, limits));
  const TrajectoryCheck check = h.check_trajectory(trajectory, trajectory.duration() / 20000);
  ASSERT_TRUE(check.ok());
  const double ratio = (check.max_speed.array() / h.leg_speed().array()).maxCoeff();
  EXPECT_GE(ratio, 0.99);
  EXPECT_LE(ratio, 1.0 + 1e-9);
}

// Rule (b) never plans slower than rule (a) on a single section: r_i ≤ V, the joints' speed
// bound that rule (a) uses, and every leg's limit is at least the group's (the smallest). On
// screws. A decoupled LIN under rule (a) is cut into pieces (doc/planning.md §9) whose joint
// speeds are bounded piece by piece, while rule (b)'s leg bound is one per section: there
// rule (b) can be the slower (by up to 1.6 % in 2000 random moves), and only the ratio is printed.
TEST(HexapodJointMetric, NeverSlowerThanTheLegSpeedGroupOnSingleMoves) {
  const Hexapod h = test_hexapod();
  Random rnd(524);
  const Limits limits{0.1, 1.0, 20.0};
  double sum_ratio = 0.0, smallest = 1e300, largest = 0.0;
  const int n = testing::case_count(200) / 4 + 3;
  for (int c = 0; c < n; ++c) {
    const Path path = Path::lin(reachable_pose(h, rnd), reachable_pose(h, rnd),
                                c % 2 ? Interpolation::screw : Interpolation::decoupled);
    MetricSetd with_group = tool_points();
    h.add_leg_speed_group(with_group, 1);
    const double a = plan(path, with_group, limits).duration();
    const double b = plan(path, tool_points(), limits, ProfileKind::scurve, h.joint_metric(path, limits)).duration();
    if (c % 2) ASSERT_LE(b, a * (1 + 1e-12)) << "case " << c;
    sum_ratio += b / a;
    smallest = std::min(smallest, b / a);
    largest = std::max(largest, b / a);
  }
  std::printf("rule (b) / rule (a) duration over %d random LIN moves: mean %.4f, min %.4f, max %.4f\n", n,
              sum_ratio / n, smallest, largest);
}

TEST(HexapodJointMetricBadInput, ToleranceAndSystemVelocity) {
  const Hexapod h = test_hexapod();
  const Path path =
      Path::lin(h.home(), h.home() * Posed::exp(Twistd(Eigen::Vector3d(0, 0, 0.01), Eigen::Vector3d::Zero())));
  EXPECT_NE(
      message_of([&] { h.leg_rate_bounds(path.sections().front(), 0.0); }).find("tolerance = 0: must be in (0, 1]"),
      std::string::npos);
  EXPECT_NE(message_of([&] { h.leg_rate_bounds(path.sections().front(), std::nan("")); }).find("tolerance = nan"),
            std::string::npos);
  EXPECT_NE(message_of([&] { h.leg_rate_bounds(path.sections().front(), 2.0); }).find("tolerance = 2"),
            std::string::npos);
  EXPECT_NE(message_of([&] { h.leg_section_lengths(path, 0.0); }).find("system_velocity = 0"), std::string::npos);
  EXPECT_NE(message_of([&] { h.leg_section_lengths(path, -1.0); }).find("system_velocity = -1"), std::string::npos);
  EXPECT_NE(message_of([&] {
              h.joint_metric(path, Limits{std::nan(""), 1.0, 1.0});
            }).find("system_velocity = nan"),
            std::string::npos);
}

// --- description files -----------------------------------------------------------------------

std::string temp_path(const std::string& name) { return ::testing::TempDir() + "dispkin_" + name; }

void write(const std::string& path, const std::string& text) { std::ofstream(path) << text; }

TEST(HexapodJson, SaveAndLoadRoundTripExactly) {
  Random rnd(507);
  Hexapod::Joints base = Hexapod::Joints::Random(), platform = Hexapod::Joints::Random();
  Legs lo, hi, speed;
  for (int i = 0; i < 6; ++i) {
    lo(i) = rnd.uniform(0.0, 0.3);
    hi(i) = lo(i) + rnd.uniform(0.01, 0.3);
    speed(i) = rnd.uniform(0.001, 0.1);
  }
  const Hexapod h(base, platform, lo, hi, speed, rnd.pose(0.3));
  const std::string path = temp_path("roundtrip.json");
  h.save(path);
  const Hexapod g = Hexapod::load(path);
  EXPECT_EQ(g.base_joints(), h.base_joints());
  EXPECT_EQ(g.platform_joints(), h.platform_joints());
  EXPECT_EQ(g.leg_min(), h.leg_min());
  EXPECT_EQ(g.leg_max(), h.leg_max());
  EXPECT_EQ(g.leg_speed(), h.leg_speed());
  EXPECT_EQ(g.home().translation(), h.home().translation());
  EXPECT_EQ(g.home().quaternion().coeffs(), h.home().quaternion().coeffs());
  std::remove(path.c_str());
}

// The description of test_hexapod() with `edit` applied to its text.
std::string edited(const std::string& from, const std::string& to) {
  std::string text = test_hexapod().to_json();
  const std::size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return text.replace(at, from.size(), to);
}

TEST(HexapodJson, MissingKeyIsNamed) {
  const std::string text = edited("\"min\": 0.15,", "");
  EXPECT_NE(message_of([&] { Hexapod::from_json(text); }).find("legs[0].min = \"<missing>\": required key is missing"),
            std::string::npos)
      << message_of([&] { Hexapod::from_json(text); });
}

TEST(HexapodJson, MisspeltKeyIsNamed) {
  const std::string text = edited("\"speed\"", "\"sped\"");
  EXPECT_EQ(message_of([&] {
              Hexapod::from_json(text);
            }).rfind("legs[0].sped = 0.01: unknown key (allowed here: base, platform, min, max, speed)", 0),
            0u)
      << message_of([&] { Hexapod::from_json(text); });
}

TEST(HexapodJson, WrongTypeIsNamed) {
  const std::string text = edited("\"min\": 0.15", "\"min\": \"short\"");
  EXPECT_NE(message_of([&] { Hexapod::from_json(text); }).find("legs[0].min = \"short\": must be a number"),
            std::string::npos)
      << message_of([&] { Hexapod::from_json(text); });
}

TEST(HexapodJson, WrongVectorLengthIsNamed) {
  std::string text = test_hexapod().to_json();
  const std::size_t at = text.find("\"translation\": [");
  text.insert(at + std::string("\"translation\": [").size(), "1.0, ");
  EXPECT_NE(message_of([&] { Hexapod::from_json(text); }).find("home.translation = "), std::string::npos);
}

TEST(HexapodJson, WrongLegCountIsNamed) {
  const std::string text = R"({"format": "dispkin.hexapod", "version": 1, "legs": []})";
  EXPECT_NE(message_of([&] { Hexapod::from_json(text); }).find("legs = \"[]\": must be an array of 6"),
            std::string::npos);
}

TEST(HexapodJson, WrongFormatIsNamed) {
  EXPECT_EQ(message_of([&] { Hexapod::from_json(edited("dispkin.hexapod", "robot")); }),
            "format = \"robot\": must be \"dispkin.hexapod\"");
}

TEST(HexapodJson, UnknownVersionIsNamed) {
  EXPECT_NE(message_of([&] { Hexapod::from_json(edited("\"version\": 1", "\"version\": 2")); }).find("version = \"2\""),
            std::string::npos);
}

TEST(HexapodJson, DescriptionThatIsNotAnObjectIsRefused) {
  EXPECT_EQ(
      message_of([&] { Hexapod::from_json("[1, 2]"); }).rfind("description = \"[1,2]\": must be a JSON object", 0), 0u);
}

TEST(HexapodJson, TextThatIsNotJsonIsRefused) {
  EXPECT_NE(message_of([&] { Hexapod::from_json("{\"legs\": [1, 2"); }).find("is not JSON"), std::string::npos);
}

// Found by fuzzing (tests/fuzz/fuzz_hexapod_json): nlohmann/json reports a number beyond the
// double range as out_of_range, not parse_error; it escaped as a foreign exception type.
TEST(HexapodJson, NumberBeyondDoubleRangeIsRefused) {
  const std::string m = message_of([&] { Hexapod::from_json(edited("\"speed\": 0.01", "\"speed\": 1e999")); });
  EXPECT_NE(m.find("description = \"<text>\": is not JSON"), std::string::npos) << m;
  EXPECT_NE(m.find("1e999"), std::string::npos) << m;
}

TEST(HexapodJson, BadGeometryInAFileIsNamedWithThePath) {
  const std::string path = temp_path("bad_speed.json");
  write(path, edited("\"speed\": 0.01", "\"speed\": -0.01"));
  const std::string m = message_of([&] { Hexapod::load(path); });
  EXPECT_NE(m.find(path + ": leg_speed[0] = -0.01"), std::string::npos) << m;
  std::remove(path.c_str());
}

TEST(HexapodJson, UnreadableFileIsNamed) {
  EXPECT_NE(
      message_of([&] { Hexapod::load("/nonexistent/hexapod.json"); }).find("path = \"/nonexistent/hexapod.json\""),
      std::string::npos);
}

// --- bad geometry, one kind per test ------------------------------------------------------------

struct Geometry {
  Hexapod::Joints base = test_hexapod().base_joints();
  Hexapod::Joints platform = test_hexapod().platform_joints();
  Legs lo = Legs::Constant(0.15), hi = Legs::Constant(0.32), speed = Legs::Constant(0.01);
  std::string error() const {
    return message_of([&] { Hexapod(base, platform, lo, hi, speed); });
  }
};

TEST(HexapodGeometry, TheTestGeometryIsValid) { EXPECT_EQ(Geometry().error(), "<no exception>"); }

TEST(HexapodGeometry, NonFiniteJointIsRefused) {
  Geometry g;
  g.platform(1, 4) = std::numeric_limits<double>::infinity();
  EXPECT_EQ(g.error().rfind("platform_joints = ", 0), 0u) << g.error();
  EXPECT_NE(g.error().find("must be finite"), std::string::npos);
}

TEST(HexapodGeometry, CollinearBaseJointsAreRefused) {
  Geometry g;
  for (int i = 0; i < 6; ++i) g.base.col(i) = Eigen::Vector3d(0.1 * i, 0.05 * i, 0.0);
  EXPECT_EQ(g.error().rfind("base_joints = ", 0), 0u) << g.error();
  EXPECT_NE(g.error().find("collinear"), std::string::npos);
}

TEST(HexapodGeometry, CoincidentPlatformJointsAreRefused) {
  Geometry g;
  g.platform.colwise() = Eigen::Vector3d(0.01, 0.02, 0.0);
  EXPECT_EQ(g.error().rfind("platform_joints = ", 0), 0u) << g.error();
}

TEST(HexapodGeometry, NegativeLegMinimumIsRefused) {
  Geometry g;
  g.lo(1) = -0.1;
  EXPECT_EQ(g.error().rfind("leg_min[1] = -0.1: ", 0), 0u) << g.error();
}

TEST(HexapodGeometry, LegMaximumNotAboveMinimumIsRefused) {
  Geometry g;
  g.hi(2) = g.lo(2);
  EXPECT_EQ(g.error().rfind("leg_max[2] = 0.15: must be finite and greater than leg_min[2]", 0), 0u) << g.error();
}

TEST(HexapodGeometry, NonPositiveLegSpeedIsRefused) {
  Geometry g;
  g.speed(4) = 0.0;
  EXPECT_EQ(g.error().rfind("leg_speed[4] = 0: ", 0), 0u) << g.error();
}

TEST(HexapodGeometry, SymmetricGeneratorRefusesANonPositiveRadius) {
  EXPECT_EQ(
      message_of([] { Hexapod::symmetric(-0.1, 0.2, 0.1, 0.2, 0.2, 0.1, 0.3, 0.01); }).rfind("base_radius = -0.1", 0),
      0u);
  EXPECT_EQ(
      message_of([] { Hexapod::symmetric(0.1, 0.2, 0.0, 0.2, 0.2, 0.1, 0.3, 0.01); }).rfind("platform_radius = 0", 0),
      0u);
}

TEST(HexapodGeometry, SymmetricGeneratorRefusesAGapOutsideZeroTo120Degrees) {
  EXPECT_EQ(message_of([] { Hexapod::symmetric(0.1, 2.1, 0.1, 0.2, 0.2, 0.1, 0.3, 0.01); }).rfind("base_gap = 2.1", 0),
            0u);
  EXPECT_EQ(
      message_of([] { Hexapod::symmetric(0.1, 0.2, 0.1, -0.2, 0.2, 0.1, 0.3, 0.01); }).rfind("platform_gap = -0.2", 0),
      0u);
}

TEST(HexapodGeometry, SymmetricGeneratorRefusesANonPositiveHeight) {
  EXPECT_EQ(message_of([] { Hexapod::symmetric(0.1, 0.2, 0.1, 0.2, 0.0, 0.1, 0.3, 0.01); }).rfind("height = 0", 0), 0u);
}

TEST(HexapodGeometry, SymmetricGeneratorRefusesTheThreeThreeLayout) {
  EXPECT_EQ(message_of([] {
              Hexapod::symmetric(0.1, 0.0, 0.1, 0.0, 0.2, 0.1, 0.3, 0.01);
            }).rfind("base_gap = 0: and platform_gap = 0 would make a 3-3 hexapod", 0),
            0u);
}

TEST(HexapodGeometry, SymmetricGeneratorChecksTheLegLimits) {
  EXPECT_EQ(
      message_of([] { Hexapod::symmetric(0.1, 0.2, 0.1, 0.2, 0.2, 0.3, 0.3, 0.01); }).rfind("leg_max[0] = 0.3", 0), 0u);
  EXPECT_EQ(
      message_of([] { Hexapod::symmetric(0.1, 0.2, 0.1, 0.2, 0.2, 0.1, 0.3, -0.01); }).rfind("leg_speed[0] = -0.01", 0),
      0u);
}

}  // namespace
}  // namespace dispkin
