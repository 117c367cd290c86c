// Serial-arm plugin tests, the arm model: URDF loading rules, FK against the DH table and the
// product-of-exponentials chain, the Jacobian against finite differences, joint velocities by it.
// Dynamics (test_serial_dynamics.cpp), inverse kinematics and solution choice
// (test_serial_inverse.cpp) and refused URDFs (test_urdf_refusals.cpp) are beside it.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include <dispkin/serial/chain_kinematics.hpp>
#include <dispkin/serial/serial_arm.hpp>

#include "random_cases.hpp"
#include "serial_test_arms.hpp"


namespace dispkin::serial {
namespace {

using dispkin::testing::planar;
using dispkin::testing::Random;
using dispkin::testing::random_q;
using dispkin::testing::random_vector;
using dispkin::testing::ur5e;

constexpr double pi = 3.14159265358979323846;

TEST(SerialArmLoad, PlanarArmJointsLimitsAndInertias) {
  const SerialArm arm = planar();
  EXPECT_EQ(arm.robot_name(), "planar_two_link");
  EXPECT_EQ(arm.dof(), 2);
  EXPECT_EQ(arm.joint_names(), (std::vector<std::string>{"shoulder", "elbow"}));
  const JointLimits limits = arm.joint_limits();
  EXPECT_EQ(limits.lower(0), -3.0);
  EXPECT_EQ(limits.upper(0), 3.0);
  // The elbow is continuous: unbounded position.
  EXPECT_EQ(limits.lower(1), -std::numeric_limits<double>::infinity());
  EXPECT_EQ(limits.upper(1), std::numeric_limits<double>::infinity());
  EXPECT_EQ(limits.velocity(0), 2.0);
  EXPECT_EQ(limits.velocity(1), 3.0);
  EXPECT_EQ(limits.effort(0), 100.0);
  EXPECT_EQ(limits.effort(1), 50.0);

  const std::vector<BodyInertia> bodies = arm.inertias();
  ASSERT_EQ(bodies.size(), 2u);
  // Body 1 = link1 (2 kg at x 0.4, its inertial frame turned 90° about z so that ixx is the
  // inertia about link y) + the fixed 0.5 kg sensor at x 0.2.
  EXPECT_NEAR(bodies[0].mass, 2.5, 1e-12);
  EXPECT_NEAR(bodies[0].centre_of_mass.x(), 0.36, 1e-12);
  EXPECT_NEAR(bodies[0].inertia(1, 1), 0.11 + 2.0 * 0.04 * 0.04 + 0.5 * 0.16 * 0.16, 1e-12);
  EXPECT_NEAR(bodies[0].inertia(0, 0), 0.01, 1e-12);
  // Body 2 = link2 (1 kg at 0.3) + the fixed 1.5 kg payload at 0.6 beyond the tip; the 7 kg
  // prismatic finger is not rigidly attached and is left out.
  EXPECT_NEAR(bodies[1].mass, 2.5, 1e-12);
  EXPECT_NEAR(bodies[1].centre_of_mass.x(), (0.3 + 1.5 * 0.6) / 2.5, 1e-12);
}

TEST(SerialArmLoad, FixedJointsBeforeAndAfterTheJointsAreFoldedIn) {
  // Tip beyond the last joint through a fixed joint: same dynamics, tip 0.6 further along link 2.
  const SerialArm to_link2 = planar("link2");
  const SerialArm to_payload = planar("payload");
  Random random(601);
  for (int k = 0; k < 50; ++k) {
    const Eigen::VectorXd q = random_q(random, to_link2);
    const Posed a = to_link2.forward(q);
    const Posed b = to_payload.forward(q);
    EXPECT_TRUE(b.is_approx(a * Posed::unchecked(Eigen::Quaterniond::Identity(), Eigen::Vector3d(0.6, 0, 0)), 1e-14));
    const Eigen::Vector2d qd(random.uniform(-2, 2), random.uniform(-2, 2));
    const Eigen::Vector2d qdd(random.uniform(-5, 5), random.uniform(-5, 5));
    EXPECT_LE((to_link2.torques(q, qd, qdd) - to_payload.torques(q, qd, qdd)).cwiseAbs().maxCoeff(), 1e-12);
  }
  // The mount lifts everything by 0.3: at q = 0 the elbow is at (0.8, 0, 0.3).
  EXPECT_TRUE(to_link2.forward(Eigen::Vector2d::Zero()).translation().isApprox(Eigen::Vector3d(0.8, 0, 0.3), 1e-15));
}

TEST(SerialArmKinematics, PlanarForwardIsTheTextbookFormula) {
  const SerialArm arm = planar("payload");
  Random random(602);
  for (int k = 0; k < 100; ++k) {
    const Eigen::VectorXd q = random_q(random, arm);
    const double a = q(0) + q(1);
    const Eigen::Vector3d p(0.8 * std::cos(q(0)) + 0.6 * std::cos(a), 0.0,
                            0.3 + 0.8 * std::sin(q(0)) + 0.6 * std::sin(a));
    const Posed t = arm.forward(q);
    EXPECT_LE((t.translation() - p).norm(), 1e-14);
    // Axes along −y: the tool's x axis is (cos a, 0, sin a).
    EXPECT_LE((t.rotation().col(0) - Eigen::Vector3d(std::cos(a), 0, std::sin(a))).norm(), 1e-14);
  }
}

// The UR5e of arm_ur5e_dh.urdf by its standard DH table, T = Π Rz(qᵢ) Tz(dᵢ) Tx(aᵢ) Rx(αᵢ), and
// tool0 0.05 along the flange's z: independent of the URDF reading and of the product of exponentials.
Eigen::Matrix4d ur5e_dh_forward(const Eigen::VectorXd& q) {
  const double d[6] = {0.1625, 0, 0, 0.1333, 0.0997, 0.0996 + 0.05};
  const double a[6] = {0, -0.425, -0.3922, 0, 0, 0};
  const double alpha[6] = {pi / 2, 0, 0, pi / 2, -pi / 2, 0};
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  for (int i = 0; i < 6; ++i) {
    t = t * Eigen::AngleAxisd(q(i), Eigen::Vector3d::UnitZ()) * Eigen::Translation3d(a[i], 0, d[i]) *
        Eigen::AngleAxisd(alpha[i], Eigen::Vector3d::UnitX());
  }
  return t.matrix();
}

TEST(SerialArmKinematics, ForwardIsTheDhProductAndTheChainsForward) {
  const SerialArm arm = ur5e();
  Random random(603);
  double worst = 0.0;
  for (int k = 0; k < dispkin::testing::case_count(2000); ++k) {
    const Eigen::VectorXd q = random_q(random, arm);
    worst = std::max(worst, (arm.forward(q).matrix() - ur5e_dh_forward(q)).cwiseAbs().maxCoeff());
  }
  EXPECT_LE(worst, 1e-12);
  // forward() is the product of exponentials of chain(), bit for bit.
  for (const SerialArm& a : {ur5e(), planar("payload")}) {
    const RevoluteChain& chain = a.chain();
    ASSERT_EQ(chain.dof(), a.dof());
    for (int k = 0; k < 100; ++k) {
      const Eigen::VectorXd q = random_q(random, a);
      EXPECT_EQ(a.forward(q).matrix(), forward(chain, q).matrix()) << a.robot_name();
    }
  }
}

TEST(SerialArmKinematics, Ur5eAtZeroMatchesTheDhTable) {
  // With all joints at 0 the standard-DH UR5e reaches x = a2 + a3, y = −(d4 + d6), z = d1 − d5
  // (flange), and tool0 is 0.05 further along the flange's z, which points along −y.
  const Posed t = ur5e().forward(Eigen::VectorXd::Zero(6));
  EXPECT_LE((t.translation() - Eigen::Vector3d(-0.425 - 0.3922, -(0.1333 + 0.0996 + 0.05), 0.1625 - 0.0997)).norm(),
            1e-12);
}

TEST(SerialArmKinematics, JacobianIsTheTipOriginVelocityInBaseCoordinates) {
  const SerialArm arm = ur5e();
  Random random(604);
  const double h = 1e-6;
  for (int k = 0; k < 50; ++k) {
    const Eigen::VectorXd q = random_q(random, arm);
    const Eigen::MatrixXd j = arm.jacobian(q);
    const Eigen::MatrixXd jb = arm.body_jacobian(q);
    ASSERT_EQ(j.rows(), 6);
    ASSERT_EQ(j.cols(), 6);
    for (int i = 0; i < 6; ++i) {
      Eigen::VectorXd dq = Eigen::VectorXd::Zero(6);
      dq(i) = h;
      const Posed plus = arm.forward(q + dq);
      const Posed minus = arm.forward(q - dq);
      const Eigen::Vector3d v = (plus.translation() - minus.translation()) / (2 * h);
      const Eigen::Vector3d w =
          quaternion_log(Eigen::Quaterniond(plus.quaternion() * minus.quaternion().conjugate())) / (2 * h);
      EXPECT_LE((j.col(i).head<3>() - v).norm(), 1e-8);
      EXPECT_LE((j.col(i).tail<3>() - w).norm(), 1e-8);
      // Body Jacobian: the body twist of T(q)⁻¹ T(q + dq).
      const Eigen::Matrix<double, 6, 1> body = (minus.inverse() * plus).log().vector() / (2 * h);
      EXPECT_LE((jb.col(i) - body).norm(), 1e-7);
    }
  }
}

// joint_velocity solves J_b q̇ = ξ_b: it gives back the q̇ of a twist J_b q̇ (6 joints, and the
// planar arm, whose twists are a 2-D subspace), and the nearest twist's q̇ for one outside it.
TEST(SerialArmKinematics, JointVelocityInvertsTheBodyJacobian) {
  Random random(605);
  for (const SerialArm& arm : {ur5e(), planar("payload")}) {
    for (int k = 0; k < 50; ++k) {
      const Eigen::VectorXd q = random_q(random, arm);
      Eigen::VectorXd qd(arm.dof());
      for (int i = 0; i < arm.dof(); ++i) qd(i) = random.uniform(-1.0, 1.0);
      const Eigen::MatrixXd jb = arm.body_jacobian(q);
      const Eigen::Matrix<double, 6, 1> twist = jb * qd;
      EXPECT_LE((joint_velocity(arm, q, Twistd(twist)) - qd).norm(), 1e-9 * (1.0 + qd.norm())) << arm.robot_name();
    }
  }
  const SerialArm two = planar("payload");
  const Eigen::Vector2d q(0.4, -1.1);
  Eigen::Matrix<double, 6, 1> off = Eigen::Matrix<double, 6, 1>::Zero();
  off(0) = 1.0;
  off(1) = 0.5;
  off(5) = 0.25;
  const Eigen::MatrixXd jb = two.body_jacobian(q);
  const Eigen::VectorXd least_squares = jb.colPivHouseholderQr().solve(off);
  EXPECT_LE((joint_velocity(two, q, Twistd(off)) - least_squares).norm(), 1e-12);
}

TEST(SerialArmKinematics, VelocityProductIsTheRateOfTheBodyJacobian) {
  // J̇_b(q, q̇) q̇ against a central difference of J_b along q̇.
  Random random(623);
  for (const SerialArm& arm : {ur5e(), planar("payload")}) {
    for (int k = 0; k < 50; ++k) {
      const Eigen::VectorXd q = random_q(random, arm), qd = random_vector(random, arm.dof(), 2.0);
      const double h = 1e-5;
      const Eigen::Matrix<double, 6, 1> expected =
          (arm.body_jacobian(q + h * qd) - arm.body_jacobian(q - h * qd)) / (2.0 * h) * qd;
      const Eigen::Matrix<double, 6, Eigen::Dynamic> jb = arm.body_jacobian(q);
      EXPECT_LE((chain_velocity_product(jb, qd.data()).vector() - expected).cwiseAbs().maxCoeff(), 1e-7)
          << arm.robot_name();
    }
  }
}

}  // namespace
}  // namespace dispkin::serial
