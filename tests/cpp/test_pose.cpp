// Pose: composition, inverse, matrices, XYZUVW (convention and gimbal lock), pivots, exp/log.
#include <cmath>

#include <gtest/gtest.h>
#include <unsupported/Eigen/MatrixFunctions>

#include <dispkin/pose.hpp>

#include "random_cases.hpp"

namespace dispkin {
namespace {

using testing::message_of;

using testing::Random;
using Vector6 = Eigen::Matrix<double, 6, 1>;
constexpr double pi = 3.14159265358979323846;

Eigen::Matrix3d rx(double a) { return Eigen::AngleAxisd(a, Eigen::Vector3d::UnitX()).toRotationMatrix(); }
Eigen::Matrix3d ry(double a) { return Eigen::AngleAxisd(a, Eigen::Vector3d::UnitY()).toRotationMatrix(); }
Eigen::Matrix3d rz(double a) { return Eigen::AngleAxisd(a, Eigen::Vector3d::UnitZ()).toRotationMatrix(); }

// The 4×4 twist matrix [[ω]ₓ v; 0 0], whose matrix exponential is the independent oracle.
Eigen::Matrix4d twist_matrix(const Twistd& xi) {
  Eigen::Matrix4d m = Eigen::Matrix4d::Zero();
  m.topLeftCorner<3, 3>() = detail::hat(xi.angular);
  m.topRightCorner<3, 1>() = xi.linear;
  return m;
}

double max_abs(const Eigen::Matrix4d& m) { return m.cwiseAbs().maxCoeff(); }

TEST(Pose, CompositionInverseAndMatricesAgree) {
  Random rnd(1);
  const int n = testing::case_count(10000);
  for (int i = 0; i < n; ++i) {
    const Posed a = rnd.pose(2.0);
    const Posed b = rnd.pose(2.0);
    const Eigen::Vector3d x = rnd.vector(3.0);
    ASSERT_LT(max_abs((a * b).matrix() - a.matrix() * b.matrix()), 1e-12);
    ASSERT_LT(max_abs((a * a.inverse()).matrix() - Eigen::Matrix4d::Identity()), 1e-14);
    ASSERT_LT(((a * x) - (a.matrix() * x.homogeneous()).head<3>()).norm(), 1e-13);
    ASSERT_TRUE(Posed::from_matrix(a.matrix()).is_approx(a, 1e-14));
    ASSERT_NEAR(a.quaternion().norm(), 1.0, 1e-15);
  }
}

TEST(Pose, LongCompositionChainsStayUnit) {
  Random rnd(2);
  Posed chain;
  const Posed step = rnd.pose(0.01);
  for (int i = 0; i < 100000; ++i) chain = chain * step;
  EXPECT_NEAR(chain.quaternion().norm(), 1.0, 1e-15);
}

TEST(Pose, XyzuvwConventionIsRxRyRzAboutMovingAxes) {
  const double u = 0.3, v = -0.7, w = 1.1;
  const Posed p = Posed::from_xyzuvw((Vector6() << 1, 2, 3, u, v, w).finished());
  EXPECT_LT((p.rotation() - rx(u) * ry(v) * rz(w)).cwiseAbs().maxCoeff(), 1e-15);
  EXPECT_LT((p.translation() - Eigen::Vector3d(1, 2, 3)).norm(), 1e-15);
  // Each angle alone turns about its own axis.
  EXPECT_LT((Posed::from_xyzuvw((Vector6() << 0, 0, 0, u, 0, 0).finished()).rotation() - rx(u)).norm(), 1e-15);
  EXPECT_LT((Posed::from_xyzuvw((Vector6() << 0, 0, 0, 0, v, 0).finished()).rotation() - ry(v)).norm(), 1e-15);
  EXPECT_LT((Posed::from_xyzuvw((Vector6() << 0, 0, 0, 0, 0, w).finished()).rotation() - rz(w)).norm(), 1e-15);
}

TEST(Pose, XyzuvwRoundTripsAtRandom) {
  Random rnd(3);
  const int n = testing::case_count(10000);
  for (int i = 0; i < n; ++i) {
    Vector6 x;
    x << rnd.vector(1.0), rnd.uniform(-pi, pi), rnd.uniform(-pi / 2 + 1e-3, pi / 2 - 1e-3), rnd.uniform(-pi, pi);
    const Eigen::Vector3d pivot = rnd.vector(0.5);
    const Posed p = Posed::from_xyzuvw(x, pivot);
    const Vector6 back = p.to_xyzuvw(pivot);
    ASSERT_LT((back - x).cwiseAbs().maxCoeff(), 1e-11) << "case " << i << " x = " << x.transpose();
    // And pose → xyzuvw → pose for arbitrary rotations.
    const Posed q = rnd.pose();
    ASSERT_TRUE(Posed::from_xyzuvw(q.to_xyzuvw(pivot), pivot).is_approx(q, 1e-14));
  }
}

TEST(Pose, XyzuvwGimbalLockFoldsWIntoU) {
  for (const double v : {pi / 2, -pi / 2}) {
    const double u = 0.4, w = 0.25;
    const Posed p = Posed::from_xyzuvw((Vector6() << 0, 0, 0, u, v, w).finished());
    const Vector6 back = p.to_xyzuvw();
    EXPECT_EQ(back(5), 0.0) << "W is zero at gimbal lock";
    EXPECT_NEAR(back(4), v, 1e-12);
    // V = +90°: Rx(U)Ry(90°)Rz(W) = Rx(U + W)Ry(90°); V = −90°: Rx(U − W)Ry(−90°).
    EXPECT_NEAR(back(3), v > 0 ? u + w : u - w, 1e-12);
    EXPECT_TRUE(Posed::from_xyzuvw(back).is_approx(p, 1e-15));
  }
}

TEST(Pose, XyzuvwExactGimbalLockAlwaysFoldsWIntoU) {
  Random rnd(10);
  for (int i = 0; i < testing::case_count(10000); ++i) {
    const double u = rnd.uniform(-pi / 2, pi / 2), w = rnd.uniform(-pi / 2, pi / 2);
    for (const double v : {pi / 2, -pi / 2}) {
      const Vector6 back = Posed::from_xyzuvw((Vector6() << 0, 0, 0, u, v, w).finished()).to_xyzuvw();
      ASSERT_EQ(back(5), 0.0) << "u " << u << " v " << v << " w " << w;
      ASSERT_NEAR(back(3), v > 0 ? u + w : u - w, 1e-14);
    }
  }
}

TEST(Pose, XyzuvwNearGimbalLockReproducesTheRotation) {
  Random rnd(4);
  for (const double gap : {1e-3, 1e-6, 1e-8, 1e-9, 1e-10, 1e-11, 1e-12, 1e-14, 0.0}) {
    for (const double sign : {1.0, -1.0}) {
      for (int i = 0; i < 200; ++i) {
        Vector6 x;
        x << rnd.vector(1.0), rnd.uniform(-pi, pi), sign * (pi / 2 - gap), rnd.uniform(-pi, pi);
        const Posed p = Posed::from_xyzuvw(x);
        const Vector6 back = p.to_xyzuvw();
        // Inside the lock band W = 0 moves R by at most cos V · |W|; elsewhere R is reproduced
        // to rounding.
        const double tolerance = 2e-15 + (gap < 1e-13 ? 4 * gimbal_lock_tolerance<double>() : 0.0);
        ASSERT_TRUE(Posed::from_xyzuvw(back).is_approx(p, tolerance)) << "gap " << gap << " x " << x.transpose();
        ASSERT_LE(std::abs(back(4)), pi / 2);
        ASSERT_LE(std::abs(back(3)), pi);
        ASSERT_LE(std::abs(back(5)), pi);
      }
    }
  }
}

TEST(Pose, PivotStaysPutWhenRotating) {
  Random rnd(5);
  for (int i = 0; i < 1000; ++i) {
    const Eigen::Vector3d pivot = rnd.vector(0.3);
    Vector6 x;
    x << rnd.vector(0.1), rnd.vector(1.0);
    const Posed p = Posed::from_xyzuvw(x, pivot);
    // The pivot's world position depends on XYZ only, not on UVW.
    ASSERT_LT(((p * pivot) - (pivot + x.head<3>())).norm(), 1e-14);
    const Posed turned = p.rotated_about_pivot(rnd.pose(), pivot);
    ASSERT_LT(((turned * pivot) - (p * pivot)).norm(), 1e-14);
  }
}

TEST(Pose, ExpMatchesTheMatrixExponential) {
  Random rnd(6);
  const int n = testing::case_count(10000) / 10;
  for (int i = 0; i < n; ++i) {
    const Twistd xi(rnd.vector(2.0), rnd.unit_vector() * rnd.uniform(0.0, 3.0));
    const Eigen::Matrix4d oracle = twist_matrix(xi).exp();
    ASSERT_LT(max_abs(Posed::exp(xi).matrix() - oracle), 1e-12) << xi.vector().transpose();
  }
}

TEST(Pose, ExpLogRoundTripsAtIdentitySmallAnglesAndNearPi) {
  Random rnd(7);
  const double angles[] = {0.0, 1e-300, 1e-15, 1e-12, 1e-8,      1e-6,      1e-4,      1e-3,      1e-2,
                           0.1, 1.0,    2.0,   3.0,   pi - 1e-4, pi - 1e-6, pi - 1e-8, pi - 1e-10};
  for (const double angle : angles) {
    for (int i = 0; i < 500; ++i) {
      const Twistd xi(rnd.vector(1.0), rnd.unit_vector() * angle);
      const Posed t = Posed::exp(xi);
      const Twistd back = t.log();
      const double scale = 1.0 + xi.linear.norm();
      ASSERT_LT((back.angular - xi.angular).norm(), 1e-13) << "angle " << angle;
      ASSERT_LT((back.linear - xi.linear).norm(), 1e-12 * scale) << "angle " << angle;
      ASSERT_TRUE(Posed::exp(back).is_approx(t, 1e-13 * scale)) << "angle " << angle;
      // Small angles: exp agrees with the matrix exponential, no cancellation.
      if (angle < 1e-2) {
        ASSERT_LT(max_abs(t.matrix() - twist_matrix(xi).exp()), 1e-15 * scale);
      }
    }
  }
}

TEST(Pose, LogAtExactlyPiReturnsAValidTwist) {
  Random rnd(8);
  for (int i = 0; i < 1000; ++i) {
    const Eigen::Vector3d axis = rnd.unit_vector();
    const Posed t(Eigen::Quaterniond(0.0, axis.x(), axis.y(), axis.z()), rnd.vector(1.0));
    const Twistd xi = t.log();
    ASSERT_NEAR(xi.angular.norm(), pi, 1e-14);
    ASSERT_TRUE(xi.vector().allFinite());
    ASSERT_TRUE(Posed::exp(xi).is_approx(t, 1e-14));
  }
}

TEST(Pose, LogOfRandomPosesInvertsExp) {
  Random rnd(9);
  const int n = testing::case_count(10000);
  for (int i = 0; i < n; ++i) {
    const Posed t = rnd.pose(3.0);
    ASSERT_TRUE(Posed::exp(t.log()).is_approx(t, 1e-13));
    ASSERT_LE(t.log().angular.norm(), pi + 1e-15);
  }
}

// ---- bad input: every message names the argument and its value ------------------------------

TEST(PoseBadInput, NonFiniteTranslation) {
  const double nan = std::nan("");
  const std::string m = message_of([&] { Posed(Eigen::Quaterniond::Identity(), Eigen::Vector3d(0, nan, 0)); });
  EXPECT_NE(m.find("translation"), std::string::npos) << m;
  EXPECT_NE(m.find("nan"), std::string::npos) << m;
}

TEST(PoseBadInput, InfiniteQuaternion) {
  const double inf = std::numeric_limits<double>::infinity();
  const std::string m = message_of([&] { Posed(Eigen::Quaterniond(inf, 0, 0, 0), Eigen::Vector3d::Zero()); });
  EXPECT_NE(m.find("quaternion"), std::string::npos) << m;
  EXPECT_NE(m.find("quaternion (w, x, y, z) = (inf, 0, 0, 0)"), std::string::npos) << m;
}

TEST(PoseBadInput, NonUnitQuaternion) {
  const std::string m = message_of([] { Posed(Eigen::Quaterniond(1, 1, 0, 0), Eigen::Vector3d::Zero()); });
  EXPECT_NE(m.find("quaternion (w, x, y, z) = (1, 1, 0, 0)"), std::string::npos) << m;
  EXPECT_NE(m.find("unit quaternion"), std::string::npos) << m;
  EXPECT_NE(message_of([] { Posed(Eigen::Quaterniond(0, 0, 0, 0), Eigen::Vector3d::Zero()); }).find("unit"),
            std::string::npos);
  // Within the tolerance the quaternion is normalised.
  const Posed p(Eigen::Quaterniond(1 + 5e-7, 0, 0, 0), Eigen::Vector3d::Zero());
  EXPECT_DOUBLE_EQ(p.quaternion().norm(), 1.0);
}

TEST(PoseBadInput, MatrixThatIsNotARigidTransform) {
  Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
  m(0, 0) = 2.0;
  EXPECT_NE(message_of([&] { Posed::from_matrix(m); }).find("rotation"), std::string::npos);
  m = Eigen::Matrix4d::Identity();
  m(0, 0) = -1.0;  // a reflection: orthonormal but det −1
  EXPECT_NE(message_of([&] { Posed::from_matrix(m); }).find("determinant"), std::string::npos);
  m = Eigen::Matrix4d::Identity();
  m(3, 0) = 0.5;
  EXPECT_NE(message_of([&] { Posed::from_matrix(m); }).find("last row"), std::string::npos);
  m = Eigen::Matrix4d::Identity();
  m(1, 3) = std::nan("");
  EXPECT_NE(message_of([&] { Posed::from_matrix(m); }).find("matrix"), std::string::npos);
}

TEST(PoseBadInput, NonFiniteXyzuvwAndPivot) {
  Vector6 x = Vector6::Zero();
  x(4) = std::numeric_limits<double>::infinity();
  EXPECT_NE(message_of([&] { Posed::from_xyzuvw(x); }).find("xyzuvw"), std::string::npos);
  EXPECT_NE(message_of([&] { Posed::from_xyzuvw(Vector6::Zero(), Eigen::Vector3d(std::nan(""), 0, 0)); }).find("pivot"),
            std::string::npos);
}

}  // namespace
}  // namespace dispkin

namespace dispkin {
namespace {

// Matrix → quaternion uses Eigen's largest-component (Shepperd) method: exact up to rounding
// for every rotation, including turns by π and just below it, where the trace method fails.
TEST(Pose, MatrixToQuaternionNearAHalfTurn) {
  testing::Random rnd(120);
  for (int i = 0; i < 10000; ++i) {
    const Eigen::Vector3d axis = rnd.unit_vector();
    const double angle = 3.14159265358979323846 - std::pow(10.0, -rnd.uniform(0.0, 16.0)) * (i % 7 == 0 ? 0.0 : 1.0);
    const Eigen::Matrix3d r = Eigen::AngleAxisd(angle, axis).toRotationMatrix();
    const Posed pose(r, Eigen::Vector3d::Zero());
    ASSERT_LE((pose.rotation() - r).cwiseAbs().maxCoeff(), 4e-16 * 8) << "angle " << angle;
    const Eigen::AngleAxisd back(pose.quaternion());
    ASSERT_NEAR(back.angle(), angle, 1e-7) << "angle " << angle;
  }
}

}  // namespace
}  // namespace dispkin
