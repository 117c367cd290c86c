// Hexapod kinematics: inverse kinematics against a direct computation, the leg Jacobian against
// finite differences, forward(inverse(T)) = T, symmetric layouts, pivots, workspace check,
// failures. Leg speeds (test_hexapod_leg_speed.cpp) and descriptions
// (test_hexapod_description.cpp) are beside it.
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include <dispkin/hexapod/hexapod.hpp>
#include <dispkin/planning/planner.hpp>

#include "hexapod_test_rig.hpp"
#include "random_cases.hpp"

namespace dispkin {
namespace {

using hexapod::Hexapod;
using hexapod::WorkspaceCheck;
using hexapod::xyzuvw_for_new_pivot;
using testing::message_of;
using testing::Random;
using testing::reachable_pose;
using testing::runtime_message_of;
using testing::test_hexapod;
using Legs = Hexapod::Legs;
using Vector6 = Eigen::Matrix<double, 6, 1>;
constexpr double pi = 3.14159265358979323846;

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

}  // namespace
}  // namespace dispkin
