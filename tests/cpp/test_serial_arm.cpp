// Serial-arm plugin tests: URDF loading rules, FK against the DH table and the product-of-
// exponentials chain, the Jacobian against finite differences, joint velocities by it, dynamics against a hand-derived
// two-link model, inverse kinematics (analytic family or numeric fallback), solution choice, bad URDFs.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <fstream>
#include <iterator>
#include <limits>
#include <string>
#include <thread>
#include <vector>

#include <Eigen/Geometry>

#include <dispkin/serial/chain_kinematics.hpp>
#include <dispkin/serial/serial_arm.hpp>

#include "chain_dynamics.hpp"  // torques_by_kdl
#include "random_cases.hpp"

namespace dispkin::serial {
namespace {

using dispkin::testing::message_of;
using dispkin::testing::Random;

const std::string urdf_dir = std::string(DISPKIN_SOURCE_DIR) + "/tests/data/urdf/";
constexpr double pi = 3.14159265358979323846;

SerialArm planar(const std::string& tip = "link2") {
  return SerialArm::from_urdf_file(urdf_dir + "arm_planar_two_link.urdf", "base", tip);
}
SerialArm ur5e() { return SerialArm::from_urdf_file(urdf_dir + "arm_ur5e_dh.urdf", "base_link", "tool0"); }

Eigen::VectorXd random_q(Random& random, const SerialArm& arm) {
  const JointLimits limits = arm.joint_limits();
  Eigen::VectorXd q(arm.dof());
  for (int i = 0; i < arm.dof(); ++i) {
    const double lo = std::isfinite(limits.lower(i)) ? limits.lower(i) : -pi;
    const double hi = std::isfinite(limits.upper(i)) ? limits.upper(i) : pi;
    q(i) = random.uniform(lo, hi);
  }
  return q;
}

// The set holds q (every joint within `tolerance`).
bool contains(const std::vector<Eigen::VectorXd>& set, const Eigen::VectorXd& q, double tolerance) {
  for (const Eigen::VectorXd& s : set)
    if ((s - q).cwiseAbs().maxCoeff() <= tolerance) return true;
  return false;
}

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

// The two-link arm in the vertical plane, derived by hand (Lagrange): link i has mass mᵢ,
// centre of mass cᵢ along it and inertia Iᵢ about the joint axis through the centre of mass.
Eigen::Vector2d two_link_torques(const Eigen::Vector2d& q, const Eigen::Vector2d& qd, const Eigen::Vector2d& qdd,
                                 double g) {
  const double l1 = 0.8;
  // Body 1: link1 (2 kg, c 0.4, I 0.11) + sensor (0.5 kg at 0.2).
  const double m1 = 2.5;
  const double c1 = (2.0 * 0.4 + 0.5 * 0.2) / m1;
  const double i1 = 0.11 + 2.0 * (0.4 - c1) * (0.4 - c1) + 0.5 * (0.2 - c1) * (0.2 - c1);
  // Body 2: link2 (1 kg, c 0.3, Iyy 0.05) + payload (1.5 kg at 0.6, Iyy 0.01).
  const double m2 = 2.5;
  const double c2 = (1.0 * 0.3 + 1.5 * 0.6) / m2;
  const double i2 = 0.05 + 1.0 * (0.3 - c2) * (0.3 - c2) + 0.01 + 1.5 * (0.6 - c2) * (0.6 - c2);
  const double cos2 = std::cos(q(1));
  const double m11 = i1 + m1 * c1 * c1 + i2 + m2 * (l1 * l1 + c2 * c2 + 2 * l1 * c2 * cos2);
  const double m12 = i2 + m2 * (c2 * c2 + l1 * c2 * cos2);
  const double m22 = i2 + m2 * c2 * c2;
  const double h = -m2 * l1 * c2 * std::sin(q(1));
  const double g1 = (m1 * c1 + m2 * l1) * g * std::cos(q(0)) + m2 * c2 * g * std::cos(q(0) + q(1));
  const double g2 = m2 * c2 * g * std::cos(q(0) + q(1));
  return Eigen::Vector2d(m11 * qdd(0) + m12 * qdd(1) + h * (2 * qd(0) * qd(1) + qd(1) * qd(1)) + g1,
                         m12 * qdd(0) + m22 * qdd(1) - h * qd(0) * qd(0) + g2);
}

TEST(SerialArmDynamics, TwoLinkArmMatchesTheHandDerivedModel) {
  const SerialArm arm = planar();
  Random random(605);
  for (int k = 0; k < dispkin::testing::case_count(500); ++k) {
    const Eigen::Vector2d q(random.uniform(-3, 3), random.uniform(-pi, pi));
    const Eigen::Vector2d qd(random.uniform(-3, 3), random.uniform(-3, 3));
    const Eigen::Vector2d qdd(random.uniform(-10, 10), random.uniform(-10, 10));
    const Eigen::VectorXd tau = arm.torques(q, qd, qdd);
    EXPECT_LE((tau - two_link_torques(q, qd, qdd, 9.81)).cwiseAbs().maxCoeff(), 1e-11);
    EXPECT_LE((arm.static_torques(q) - arm.torques(q, Eigen::Vector2d::Zero(), Eigen::Vector2d::Zero()))
                  .cwiseAbs()
                  .maxCoeff(),
              0.0);
    EXPECT_LE((arm.static_torques(q) - two_link_torques(q, Eigen::Vector2d::Zero(), Eigen::Vector2d::Zero(), 9.81))
                  .cwiseAbs()
                  .maxCoeff(),
              1e-11);
  }
}

TEST(SerialArmDynamics, GravityIsConfigurable) {
  SerialArm arm = planar();
  EXPECT_EQ(arm.gravity(), Eigen::Vector3d(0, 0, -9.81));
  const Eigen::Vector2d q(0.3, -0.7);
  arm.set_gravity(Eigen::Vector3d(0, 0, -3.71));  // Mars
  EXPECT_LE((arm.static_torques(q) - two_link_torques(q, Eigen::Vector2d::Zero(), Eigen::Vector2d::Zero(), 3.71))
                .cwiseAbs()
                .maxCoeff(),
            1e-12);
  // Gravity along the joint axes does no work on a planar arm.
  arm.set_gravity(Eigen::Vector3d(0, 9.81, 0));
  EXPECT_LE(arm.static_torques(q).cwiseAbs().maxCoeff(), 1e-14);
  EXPECT_NE(message_of([&] { arm.set_gravity(Eigen::Vector3d(0, 0, std::nan(""))); }).find("gravity"),
            std::string::npos);
}

TEST(SerialArmDynamics, Ur5eStaticTorquesAreTheZeroVelocityTorques) {
  const SerialArm arm = ur5e();
  Random random(606);
  for (int k = 0; k < 100; ++k) {
    const Eigen::VectorXd q = random_q(random, arm);
    const Eigen::VectorXd zero = Eigen::VectorXd::Zero(6);
    EXPECT_EQ(arm.static_torques(q), arm.torques(q, zero, zero));
    // Joint 1 turns about the vertical: gravity never loads it.
    EXPECT_LE(std::abs(arm.static_torques(q)(0)), 1e-12);
  }
}

// Every arm of tests/data/urdf with a dynamics model, with random states.
std::vector<SerialArm> arms_with_dynamics() {
  return {planar("link2"), planar("payload"), ur5e(),
          SerialArm::from_urdf_file(urdf_dir + "arm_kr6_like_dh.urdf", "base_link", "flange")};
}

Eigen::VectorXd random_vector(Random& random, int n, double scale) {
  Eigen::VectorXd x(n);
  for (int i = 0; i < n; ++i) x(i) = random.uniform(-scale, scale);
  return x;
}

TEST(SerialArmDynamics, TorquesAreKdlsRecursiveNewtonEuler) {
  // The torques run recursive Newton–Euler on the product-of-exponentials chain; KDL's
  // ChainIdSolver_RNE on the KDL chain (fixed segments and all) is the reference.
  Random random(620);
  for (SerialArm arm : arms_with_dynamics()) {
    for (const Eigen::Vector3d& gravity : {Eigen::Vector3d(0, 0, -9.81), Eigen::Vector3d(1.5, -2.0, -9.0)}) {
      arm.set_gravity(gravity);
      for (int k = 0; k < 200; ++k) {
        const Eigen::VectorXd q = random_q(random, arm), qd = random_vector(random, arm.dof(), 3.0),
                              qdd = random_vector(random, arm.dof(), 20.0);
        const Eigen::VectorXd kdl = detail::torques_by_kdl(arm, q, qd, qdd);
        EXPECT_LE((arm.torques(q, qd, qdd) - kdl).cwiseAbs().maxCoeff(), 1e-12 * (1.0 + kdl.cwiseAbs().maxCoeff()))
            << arm.robot_name() << " q " << q.transpose();
        const Eigen::VectorXd zero = Eigen::VectorXd::Zero(arm.dof());
        const Eigen::VectorXd kdl_static = detail::torques_by_kdl(arm, q, zero, zero);
        EXPECT_LE((arm.static_torques(q) - kdl_static).cwiseAbs().maxCoeff(),
                  1e-12 * (1.0 + kdl_static.cwiseAbs().maxCoeff()))
            << arm.robot_name();
      }
    }
  }
}

TEST(SerialArmDynamics, OnePassGivesTheTorqueAndTheStaticTorqueBitForBit) {
  Random random(621);
  for (const SerialArm& arm : arms_with_dynamics()) {
    for (int k = 0; k < 50; ++k) {
      const Eigen::VectorXd q = random_q(random, arm), qd = random_vector(random, arm.dof(), 3.0),
                            qdd = random_vector(random, arm.dof(), 20.0);
      Eigen::VectorXd tau, holding;
      arm.torques(q, qd, qdd, tau, holding);
      EXPECT_EQ(tau, arm.torques(q, qd, qdd));
      EXPECT_EQ(holding, arm.static_torques(q));
    }
  }
}

TEST(SerialArmDynamics, JointPowerIsTheRateOfKineticPlusPotentialEnergy) {
  // Along q(t) = q + t q̇ + t²/2 q̈ the joints' power q̇ᵀτ is d/dt of the kinetic energy
  // ½ q̇ᵀ M(q) q̇ plus the potential's rate q̇ᵀ g(q); M's columns are τ(q, 0, eₖ) − g(q). The
  // Coriolis and centripetal terms do no work, so this checks them against M.
  Random random(622);
  for (const SerialArm& arm : arms_with_dynamics()) {
    const int n = arm.dof();
    const Eigen::VectorXd zero = Eigen::VectorXd::Zero(n);
    auto kinetic_energy = [&](const Eigen::VectorXd& q, const Eigen::VectorXd& qd) {
      const Eigen::VectorXd g = arm.static_torques(q);
      Eigen::MatrixXd m(n, n);
      for (int k = 0; k < n; ++k) m.col(k) = arm.torques(q, zero, Eigen::VectorXd::Unit(n, k)) - g;
      return 0.5 * qd.dot(m * qd);
    };
    for (int k = 0; k < 50; ++k) {
      const Eigen::VectorXd q = random_q(random, arm), qd = random_vector(random, n, 2.0),
                            qdd = random_vector(random, n, 10.0);
      const double h = 1e-5;
      auto energy_at = [&](double t) { return kinetic_energy(q + t * qd + 0.5 * t * t * qdd, qd + t * qdd); };
      const double kinetic_rate = (energy_at(h) - energy_at(-h)) / (2.0 * h);
      const double power = qd.dot(arm.torques(q, qd, qdd));
      const double potential_rate = qd.dot(arm.static_torques(q));
      EXPECT_NEAR(power, kinetic_rate + potential_rate, 1e-6 * (1.0 + std::abs(power))) << arm.robot_name();
    }
  }
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

TEST(SerialArmInverse, PlanarNumericFallbackFindsTheOneSolution) {
  // A full pose fixes q₁ + q₂ (the tool's angle) and then the position fixes q₁: one solution,
  // and the continuous elbow has no 2π copies.
  const SerialArm arm = planar("payload");
  EXPECT_EQ(arm.family(), IkFamily::general);
  Random random(607);
  for (int k = 0; k < dispkin::testing::case_count(100); ++k) {
    const Eigen::VectorXd q = random_q(random, arm);
    const Posed pose = arm.forward(q);
    const InverseResult result = arm.inverse_solutions(pose);
    EXPECT_FALSE(result.complete);
    EXPECT_EQ(result.family, IkFamily::general);
    ASSERT_EQ(result.solutions.size(), 1u) << "q = " << q.transpose();
    EXPECT_LE((result.solutions[0] - q).cwiseAbs().maxCoeff(), 1e-9) << "q = " << q.transpose();
    EXPECT_TRUE(arm.forward(result.solutions[0]).is_approx(pose, inverse_tolerance));
  }
}

TEST(SerialArmInverse, SolutionsOutsideTheLimitsAreDroppedOrFlagged) {
  const SerialArm arm = planar("payload");
  // The shoulder's limits are ±3 rad, a range under 2π: q₁ = 3.1 has no copy inside.
  const Eigen::Vector2d q(3.1, 1.2);
  const Posed pose = arm.forward(q);
  EXPECT_TRUE(arm.inverse_solutions(pose).solutions.empty());
  InverseOptions options;
  options.keep_outside_limits = true;
  const InverseResult flagged = arm.inverse_solutions(pose, options);
  ASSERT_EQ(flagged.solutions.size(), 1u);
  EXPECT_FALSE(flagged.within_limits[0]);
  EXPECT_LE((flagged.solutions[0] - q).cwiseAbs().maxCoeff(), 1e-9);
  // Inside the limits the same call flags nothing.
  const InverseResult inside = arm.inverse_solutions(arm.forward(Eigen::Vector2d(2.9, 1.2)), options);
  ASSERT_EQ(inside.solutions.size(), 1u);
  EXPECT_TRUE(inside.within_limits[0]);
}

TEST(SerialArmInverse, General6RNumericFallbackFindsTheSolutions) {
  // The UR5e with joint 3's axis tilted by 0.3 rad and offset, and joint 5's tilted: no family
  // fits, the numeric search runs. It is not complete, but every returned solution holds, and
  // from 64 restarts it finds the original q (modulo 2π) in nearly every case (50 of 50 in the
  // default run; the bound below leaves room for other seeds).
  std::ifstream in(urdf_dir + "arm_ur5e_dh.urdf");
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const auto replace = [&](const std::string& from, const std::string& to) {
    const auto at = text.find(from);
    ASSERT_NE(at, std::string::npos) << from;
    text.replace(at, from.size(), to);
  };
  replace("<origin xyz=\"-0.425 0 0\" rpy=\"0 0 0\"/>", "<origin xyz=\"-0.425 0.03 0\" rpy=\"0.3 0 0\"/>");
  replace("<origin xyz=\"0 0 0.1333\" rpy=\"1.5707963267948966 0 0\"/>",
          "<origin xyz=\"0.02 0 0.1333\" rpy=\"1.3 0 0\"/>");
  const SerialArm arm = SerialArm::from_urdf_string(text, "base_link", "tool0");
  ASSERT_EQ(arm.family(), IkFamily::general);
  InverseOptions options;
  options.offer_equivalents = false;
  options.time_budget = 10.0;  // the attempts, not the clock, end the search here
  Random random(612);
  const int cases = dispkin::testing::case_count(50);
  int found = 0;
  for (int k = 0; k < cases; ++k) {
    const Eigen::VectorXd q = random_q(random, arm);
    const Posed pose = arm.forward(q);
    const InverseResult result = arm.inverse_solutions(pose, options);
    EXPECT_FALSE(result.complete);
    EXPECT_LE(result.solutions.size(), 16u);  // a 6R has at most 16
    bool has_q = false;
    for (const Eigen::VectorXd& s : result.solutions) {
      EXPECT_TRUE(arm.forward(s).is_approx(pose, inverse_tolerance));
      bool same = true;
      for (int i = 0; i < 6; ++i) same = same && std::abs(std::remainder(s(i) - q(i), 2 * pi)) <= 1e-9;
      has_q = has_q || same;
    }
    found += has_q ? 1 : 0;
  }
  EXPECT_GE(found, cases * 9 / 10);
  // One attempt: at most one solution.
  options.max_attempts = 1;
  EXPECT_LE(arm.inverse_solutions(arm.forward(random_q(random, arm)), options).solutions.size(), 1u);
}

TEST(SerialArmInverse, UnreachablePoseHasNoSolution) {
  const SerialArm arm = planar("payload");
  const Posed far = Posed::unchecked(Eigen::Quaterniond::Identity(), Eigen::Vector3d(5, 0, 0));
  EXPECT_TRUE(arm.inverse(far).empty());
}

TEST(SerialArmInverse, Ur5eSolutionsReproduceThePoseAndTheTwoPiCopiesOnRequest) {
  const SerialArm arm = ur5e();
  const JointLimits limits = arm.joint_limits();
  Random random(608);
  for (int k = 0; k < dispkin::testing::case_count(20); ++k) {
    const Eigen::VectorXd q = random_q(random, arm);
    const Posed pose = arm.forward(q);
    InverseOptions copies;
    copies.offer_equivalents = true;
    const InverseResult result = arm.inverse_solutions(pose, copies);
    EXPECT_TRUE(result.complete);
    EXPECT_EQ(result.family, IkFamily::three_parallel);
    EXPECT_TRUE(contains(result.solutions, q, 1e-9)) << "q = " << q.transpose();
    for (const Eigen::VectorXd& s : result.solutions) {
      EXPECT_TRUE(arm.forward(s).is_approx(pose, inverse_tolerance));
      EXPECT_TRUE(((s - limits.lower).array() >= -1e-10).all() && ((limits.upper - s).array() >= -1e-10).all());
      // ±2π limits: each joint value has exactly one 2π copy inside them, which is offered too.
      for (int i = 0; i < 6; ++i) {
        Eigen::VectorXd copy = s;
        copy(i) += s(i) <= 0.0 ? 2 * pi : -2 * pi;
        EXPECT_TRUE(contains(result.solutions, copy, 1e-9)) << "joint " << i << " of " << s.transpose();
      }
    }
    // By default: one joint vector per distinct solution, 2⁶ times fewer, every joint value the
    // copy nearest 0.
    const InverseResult base = arm.inverse_solutions(pose);
    EXPECT_EQ(result.solutions.size(), base.solutions.size() * 64u);
    for (const Eigen::VectorXd& s : base.solutions) EXPECT_LE(s.cwiseAbs().maxCoeff(), pi + 1e-9) << s.transpose();
  }
}

TEST(SerialArmDynamics, TorquesFromTwoThreadsAreThoseOfOne) {
  // KDL's joints keep their last pose in mutable members: two threads sharing one KDL chain got
  // each other's joint poses and wrong torques (seen as different re-timing reports from Python
  // threads). The torques keep no state now (chain_dynamics.cpp); this keeps it so.
  const SerialArm arm = ur5e();
  Random random(615);
  std::vector<std::array<Eigen::VectorXd, 3>> states;
  std::vector<Eigen::VectorXd> expected;
  for (int k = 0; k < 200; ++k) {
    std::array<Eigen::VectorXd, 3> x{random_q(random, arm), random_q(random, arm), random_q(random, arm)};
    expected.push_back(arm.torques(x[0], x[1], x[2]));
    states.push_back(std::move(x));
  }
  std::array<int, 2> differing{};
  const auto run = [&](int t) {
    for (int pass = 0; pass < 50; ++pass)
      for (std::size_t k = 0; k < states.size(); ++k)
        if (arm.torques(states[k][0], states[k][1], states[k][2]) != expected[k])
          ++differing[static_cast<std::size_t>(t)];
  };
  std::thread first(run, 0);
  std::thread second(run, 1);
  first.join();
  second.join();
  EXPECT_EQ(differing[0] + differing[1], 0);
}

TEST(SerialArmInverse, EverySolutionReproducesThePoseAndNoneRepeats) {
  // inverse_solutions checks by forward kinematics only the solutions it moves by whole turns into
  // the limits, and looks for duplicates only among the numeric search's roots: the analytic
  // families' own acceptance implies the check (doc/inverse-kinematics.md (eq. 26)) and they
  // return no duplicates. Limits of [0, 2π] on the UR5e move every negative joint value by a
  // turn, the KR6-like arm's narrower limits drop some solutions and move others.
  const SerialArm ur = ur5e();
  JointLimits shifted = ur.joint_limits();
  shifted.lower.setZero();
  shifted.upper.setConstant(2 * pi);
  const SerialArm kr6 = SerialArm::from_urdf_file(urdf_dir + "arm_kr6_like_dh.urdf", "base_link", "flange");
  Random random(614);
  for (const SerialArm& arm : {ur, ur.with_joint_limits(shifted), kr6}) {
    const JointLimits limits = arm.joint_limits();
    for (int k = 0; k < dispkin::testing::case_count(500); ++k) {
      const Posed pose = arm.forward(random_q(random, ur));
      for (const bool keep : {false, true}) {
        InverseOptions options;
        options.keep_outside_limits = keep;
        const InverseResult result = arm.inverse_solutions(pose, options);
        ASSERT_EQ(result.solutions.size(), result.within_limits.size());
        for (std::size_t a = 0; a < result.solutions.size(); ++a) {
          const Eigen::VectorXd& s = result.solutions[a];
          EXPECT_TRUE(arm.forward(s).is_approx(pose, inverse_tolerance)) << arm.robot_name() << " " << s.transpose();
          const bool inside =
              ((s - limits.lower).array() >= -1e-10).all() && ((limits.upper - s).array() >= -1e-10).all();
          EXPECT_EQ(inside, static_cast<bool>(result.within_limits[a])) << s.transpose();
          for (std::size_t b = 0; b < a; ++b) {
            double apart = 0.0;
            for (int i = 0; i < 6; ++i)
              apart = std::max(apart, std::abs(std::remainder(s(i) - result.solutions[b](i), 2 * pi)));
            EXPECT_GT(apart, 1e-7) << "solutions " << b << " and " << a << " are one: " << s.transpose();
          }
        }
      }
    }
  }
}

TEST(SerialArmInverse, WideLimitsGiveTheDistinctSolutionsNearestZero) {
  // Limits of ±1e8 and ±1e16 rad (example-robot-data's iris) once gave no solution at all: the
  // representative was the copy just above the lower limit, 1e16 rad, where no digit of the
  // angle is left. The copy nearest 0 keeps every digit whatever the limits.
  const SerialArm ur = ur5e();
  Random random(613);
  for (const double bound : {20.0, 100.0, 1e8, 1e16}) {
    JointLimits wide = ur.joint_limits();
    wide.lower.setConstant(-bound);
    wide.upper.setConstant(bound);
    const SerialArm arm = ur.with_joint_limits(wide);
    for (int k = 0; k < dispkin::testing::case_count(20); ++k) {
      const Eigen::VectorXd q = random_q(random, ur);
      const Posed pose = arm.forward(q);
      const InverseResult result = arm.inverse_solutions(pose);
      EXPECT_EQ(result.solutions.size(), ur.inverse_solutions(pose).solutions.size()) << bound;
      bool has_q = false;
      for (const Eigen::VectorXd& s : result.solutions) {
        EXPECT_TRUE(arm.forward(s).is_approx(pose, inverse_tolerance));
        EXPECT_LE(s.cwiseAbs().maxCoeff(), pi + 1e-9) << s.transpose();
        bool same = true;
        for (int i = 0; i < 6; ++i) same = same && std::abs(std::remainder(s(i) - q(i), 2 * pi)) <= 1e-9;
        has_q = has_q || same;
      }
      EXPECT_TRUE(has_q) << "bound " << bound << ", q = " << q.transpose();
    }
  }
}

TEST(SerialArmChoice, FlagsTellTheAnalyticSolutionsApart) {
  // UR (three parallel axes) and a spherical wrist: the solutions of one pose (without 2π
  // copies) have pairwise different (shoulder, elbow, wrist) flags, so the flags of q pick q.
  const SerialArm kr6 = SerialArm::from_urdf_file(urdf_dir + "arm_kr6_like_dh.urdf", "base_link", "flange");
  EXPECT_EQ(kr6.family(), IkFamily::spherical_wrist);
  InverseOptions plain;
  plain.offer_equivalents = false;
  for (const SerialArm& arm : {ur5e(), kr6}) {
    Random random(610);
    int checked = 0;
    for (int k = 0; k < dispkin::testing::case_count(500); ++k) {
      const Eigen::VectorXd q = random_q(random, arm);
      const Configuration c = arm.configuration(q);
      if (c.shoulder == 0 || c.elbow == 0 || c.wrist == 0) continue;  // on a boundary (singular)
      const InverseResult result = arm.inverse_solutions(arm.forward(q), plain);
      ASSERT_TRUE(result.complete);
      for (std::size_t a = 0; a < result.solutions.size(); ++a)
        for (std::size_t b = a + 1; b < result.solutions.size(); ++b)
          EXPECT_NE(arm.configuration(result.solutions[a]), arm.configuration(result.solutions[b]))
              << arm.robot_name() << " q = " << q.transpose();
      const std::vector<Eigen::VectorXd> picked = with_configuration(arm, result.solutions, c);
      ASSERT_EQ(picked.size(), 1u) << arm.robot_name() << " q = " << q.transpose();
      // Without copies a joint may come back as another 2π-equivalent value than q's.
      for (int i = 0; i < arm.dof(); ++i)
        EXPECT_LE(std::abs(std::remainder(picked[0](i) - q(i), 2 * pi)), 1e-9) << arm.robot_name() << " joint " << i;
      ++checked;
    }
    EXPECT_GT(checked, 0);
  }
}

TEST(SerialArmChoice, NearestConfigurationAndFollow) {
  const SerialArm arm = ur5e();
  const std::vector<Eigen::VectorXd> set{Eigen::VectorXd::Constant(6, 0.0), Eigen::VectorXd::Constant(6, 1.0),
                                         Eigen::VectorXd::Constant(6, -2.0)};
  EXPECT_EQ(nearest(set, Eigen::VectorXd::Constant(6, 0.8)), set[1]);
  EXPECT_EQ(nearest(set, Eigen::VectorXd::Constant(6, -1.1)), set[2]);
  EXPECT_NE(message_of([&] { nearest({}, Eigen::VectorXd::Zero(6)); }).find("solutions"), std::string::npos);
  EXPECT_NE(message_of([&] { nearest(set, Eigen::VectorXd::Zero(5)); }).find("q_ref"), std::string::npos);

  // Flags: q₅ → −q₅ flips the wrist, q₃ → −q₃ flips the elbow (UR: joints 2, 3, 4 parallel).
  Random random(609);
  for (int k = 0; k < 100; ++k) {
    Eigen::VectorXd q = random_q(random, arm);
    q(2) = random.uniform(0.1, 3.0);
    q(4) = random.uniform(0.1, 3.0);
    const Configuration c = arm.configuration(q);
    EXPECT_NE(c.shoulder, 0);
    EXPECT_NE(c.elbow, 0);
    EXPECT_NE(c.wrist, 0);
    Eigen::VectorXd flipped = q;
    flipped(4) = -q(4);
    EXPECT_EQ(arm.configuration(flipped).wrist, -c.wrist);
    EXPECT_EQ(arm.configuration(flipped).elbow, c.elbow);
    flipped = q;
    flipped(2) = -q(2);
    EXPECT_EQ(arm.configuration(flipped).elbow, -c.elbow);
    EXPECT_EQ(arm.configuration(flipped).wrist, c.wrist);
    const std::vector<Eigen::VectorXd> same = with_configuration(arm, {q, flipped}, c);
    ASSERT_EQ(same.size(), 1u);
    EXPECT_EQ(same[0], q);
  }
  EXPECT_NE(message_of([&] { planar().configuration(Eigen::Vector2d::Zero()); }).find("dof"), std::string::npos);

  // Continuity: a joint path sampled finely comes back as itself.
  const SerialArm two = planar("payload");
  std::vector<Posed> poses;
  std::vector<Eigen::VectorXd> joints;
  for (int k = 0; k <= 50; ++k) {
    const Eigen::Vector2d q(-1.0 + 0.03 * k, 0.5 + 0.02 * k);
    joints.push_back(q);
    poses.push_back(two.forward(q));
  }
  const std::vector<Eigen::VectorXd> path = follow(two, poses, joints.front());
  ASSERT_EQ(path.size(), joints.size());
  for (std::size_t k = 0; k < path.size(); ++k) EXPECT_LE((path[k] - joints[k]).cwiseAbs().maxCoeff(), 1e-9);
  const Posed far = Posed::unchecked(Eigen::Quaterniond::Identity(), Eigen::Vector3d(5, 0, 0));
  try {
    follow(two, {poses[0], far}, joints.front());
    ADD_FAILURE() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("poses[1]"), std::string::npos) << e.what();
  }
}

// On a 6-joint arm follow tracks the branch by Newton's method: each step lands on the solution
// that enumerating every analytic solution picks (the nearest to the previous one), for small
// steps (tracked) and for steps too large to be tracked (every solution enumerated).
TEST(SerialArmChoice, FollowTrackingPicksTheNearestAnalyticSolution) {
  const SerialArm arm = ur5e();
  InverseOptions copies;
  copies.offer_equivalents = true;
  Random random(611);
  for (const double step : {0.002, 0.05, 0.6}) {
    for (int trial = 0; trial < 5; ++trial) {
      Eigen::VectorXd q = random_q(random, arm);
      Eigen::VectorXd direction(6);
      for (int i = 0; i < 6; ++i) direction(i) = random.uniform(-1.0, 1.0);
      std::vector<Posed> poses;
      std::vector<Eigen::VectorXd> joints;
      for (int k = 1; k <= 20; ++k) {
        joints.push_back(q + k * step * direction.normalized());
        poses.push_back(arm.forward(joints.back()));
      }
      const std::vector<Eigen::VectorXd> path = follow(arm, poses, q);
      ASSERT_EQ(path.size(), poses.size());
      Eigen::VectorXd previous = q;
      for (std::size_t k = 0; k < poses.size(); ++k) {
        EXPECT_TRUE(arm.forward(path[k]).is_approx(poses[k], inverse_tolerance)) << "step " << step << " pose " << k;
        // follow() turns on into the 2π copies inside the limits: nearest among them too.
        const Eigen::VectorXd enumerated = nearest(arm.inverse_solutions(poses[k], copies).solutions, previous);
        EXPECT_LE((path[k] - enumerated).cwiseAbs().maxCoeff(), 1e-9) << "step " << step << " pose " << k;
        previous = path[k];
      }
      // Inside the limits the fine path is the joint path itself.
      if (step == 0.002) {
        bool inside = true;
        const JointLimits limits = arm.joint_limits();
        for (const Eigen::VectorXd& j : joints)
          inside = inside && (j.array() >= limits.lower.array()).all() && (j.array() <= limits.upper.array()).all();
        for (std::size_t k = 0; inside && k < poses.size(); ++k)
          EXPECT_LE((path[k] - joints[k]).cwiseAbs().maxCoeff(), 1e-9);
      }
    }
  }
}

TEST(SerialArmErrors, BadUrdfFilesAreRefusedWithTheirReason) {
  struct Case {
    const char* file;
    const char* base;
    const char* tip;
    const char* expected;  // part of the message
  };
  const Case cases[] = {
      {"arm_bad_not_xml.urdf", "base", "l1", "URDF"},
      {"arm_bad_no_robot.urdf", "base", "l1", "URDF"},
      {"arm_bad_missing_link.urdf", "base", "l2", "l2"},
      {"arm_bad_prismatic.urdf", "base", "l2", "joint \"slide\""},
      {"arm_bad_limits.urdf", "base", "l1", "joint \"j1\" limit (lower, upper)"},
      {"arm_bad_no_limit.urdf", "base", "l1", "j1"},
      {"arm_bad_zero_axis.urdf", "base", "l1", "joint \"j1\" axis"},
      {"arm_bad_nan_origin.urdf", "base", "l1", "j1"},
      {"arm_bad_negative_mass.urdf", "base", "l1", "link \"l1\" inertial mass"},
      {"arm_bad_two_roots.urdf", "base", "l1", "URDF"},
      {"arm_bad_only_fixed.urdf", "base", "l1", "no revolute or continuous joint"},
      {"arm_bad_negative_velocity.urdf", "base", "l1", "joint \"j1\" limit velocity"},
      {"no_such_file.urdf", "base", "l1", "cannot be opened"},
  };
  for (const Case& c : cases) {
    const std::string message = message_of([&] { SerialArm::from_urdf_file(urdf_dir + c.file, c.base, c.tip); });
    EXPECT_NE(message.find(c.expected), std::string::npos) << c.file << ": " << message;
  }
}

TEST(SerialArmErrors, DamagedUrdfTextIsRefusedOrLoadedNeverACrash) {
  // Every prefix of a good URDF (a file cut off anywhere), and the file with one character
  // replaced at many places: either it still describes the arm or loading throws
  // std::invalid_argument — no other exception, no crash.
  std::ifstream in(urdf_dir + "arm_ur5e_dh.urdf");
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  ASSERT_GT(text.size(), 1000u);
  int refused = 0;
  int loaded = 0;
  const auto attempt = [&](const std::string& xml) {
    try {
      const SerialArm arm = SerialArm::from_urdf_string(xml, "base_link", "tool0");
      EXPECT_EQ(arm.dof(), 6);
      ++loaded;
    } catch (const std::invalid_argument&) {
      ++refused;
    }
  };
  for (std::size_t cut = 0; cut < text.size(); cut += 7) attempt(text.substr(0, cut));
  Random random(611);
  const char garbage[] = {'<', '>', '"', '/', 'x', '-', '9', ' ', '\0'};
  for (int k = 0; k < 300; ++k) {
    std::string damaged = text;
    damaged[static_cast<std::size_t>(random.integer(0, static_cast<int>(text.size()) - 1))] =
        garbage[random.integer(0, 8)];
    attempt(damaged);
  }
  EXPECT_GT(refused, 0);
  EXPECT_GT(loaded, 0);
}

// Found by fuzzing (tests/fuzz/fuzz_urdf): urdfdom accepts a joint whose parent is its own
// child, and the walk from the tip towards the base then never ended (memory grew until killed).
TEST(SerialArmErrors, JointCycleIsRefused) {
  const std::string xml = R"(<robot name="loop">
  <link name="base_link"/> <link name="l1"/> <link name="l2"/>
  <joint name="j1" type="continuous"><parent link="base_link"/><child link="l1"/><axis xyz="0 0 1"/></joint>
  <joint name="j2" type="continuous"><parent link="l2"/><child link="l2"/><axis xyz="0 0 1"/></joint>
</robot>)";
  EXPECT_EQ(message_of([&] { SerialArm::from_urdf_string(xml, "base_link", "l2"); }),
            "link = \"l2\": is its own ancestor: the URDF's joints form a cycle \"l2\" -(j2)-> \"l2\"");
}

// A joint cycle that leaves no root link is refused by urdfdom itself, which then
// leaked the ring of links it had built (LeakSanitizer). The joint graph is read first now, so
// urdfdom never sees a cycle: under `make sanitize` this test fails if anything leaks.
TEST(SerialArmErrors, JointCycleIsRefusedBeforeUrdfdomReadsIt) {
  const std::string two = R"(<robot name="r"><link name="base_link"/><link name="tool0"/>
  <joint name="j" type="continuous"><parent link="base_link"/><child link="tool0"/><axis xyz="0 0 1"/></joint>
  <joint name="k" type="continuous"><parent link="tool0"/><child link="base_link"/></joint></robot>)";
  EXPECT_EQ(message_of([&] { SerialArm::from_urdf_string(two, "base_link", "tool0"); }),
            "link = \"base_link\": is its own ancestor: the URDF's joints form a cycle "
            "\"base_link\" -(j)-> \"tool0\" -(k)-> \"base_link\"");
  // A longer cycle hanging off a proper tree (a root exists, so urdfdom would accept it).
  const std::string branch = R"(<robot name="r">
  <link name="base_link"/><link name="a"/><link name="b"/><link name="c"/><link name="tool0"/>
  <joint name="j0" type="fixed"><parent link="base_link"/><child link="tool0"/></joint>
  <joint name="j1" type="fixed"><parent link="base_link"/><child link="a"/></joint>
  <joint name="j2" type="fixed"><parent link="a"/><child link="b"/></joint>
  <joint name="j3" type="fixed"><parent link="b"/><child link="c"/></joint>
  <joint name="j4" type="fixed"><parent link="c"/><child link="a"/></joint></robot>)";
  EXPECT_EQ(message_of([&] { SerialArm::from_urdf_string(branch, "base_link", "tool0"); }),
            "link = \"a\": is its own ancestor: the URDF's joints form a cycle "
            "\"a\" -(j2)-> \"b\" -(j3)-> \"c\" -(j4)-> \"a\"");
}

// TinyXML (urdfdom's XML parser, and the joint-graph check's) read past the end of a text that ends
// inside a UTF-8 sequence (here "link\xe6\xe6\xe6\xe6"); ASan saw the read beyond the buffer. The
// text is now handed over with NULs appended: refused, no overflow (under `make sanitize` an
// over-read fails this test).
TEST(SerialArmErrors, TextEndingInsideAUtf8SequenceIsRefusedWithoutOverread) {
  std::ifstream in(
      std::string(DISPKIN_SOURCE_DIR) + "/tests/fuzz/corpus/fuzz_urdf/finding_12_utf8_lead_byte_at_end.urdf",
      std::ios::binary);
  ASSERT_TRUE(in.good());
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  text = text.substr(text.find('\n') + 1);  // the fuzzer's "@base tip" line
  EXPECT_THROW(SerialArm::from_urdf_string(text, "base_link", "flange"), std::invalid_argument);
}

// A '%' in an attribute: urdfdom used the text of an attribute it could not parse as a printf
// format, so "%n" there crashed inside urdf::parseURDF. A '%' outside comments, spelled out or as a
// character reference, is refused before urdfdom sees the text; inside a comment it is harmless and
// kept.
TEST(SerialArmErrors, PercentSignOutsideCommentsIsRefused) {
  const std::string arm = R"(<robot name="r">
  <link name="base_link"/> <link name="tool0"/>
  <joint name="j1" type="continuous"><parent link="base_link"/><child link="tool0"/>
    <origin xyz="ORIGIN"/><axis xyz="0 0 1"/></joint>
</robot>)";
  auto with = [&](const std::string& origin, const std::string& before = "") {
    std::string xml = arm;
    xml.replace(xml.find("ORIGIN"), 6, origin);
    return before + xml;
  };
  EXPECT_EQ(message_of([&] { SerialArm::from_urdf_string(with("n%n 0 0"), "base_link", "tool0"); }),
            "URDF line 4, column 13, <origin> attribute \"xyz\" = \"n%n 0 0\": contains '%' (character references "
            "decoded); urdfdom would pass it to printf as a format (remove it)");
  EXPECT_NE(message_of([&] { SerialArm::from_urdf_string(with("%s%s%s 0 0"), "base_link", "tool0"); }).find("'%'"),
            std::string::npos);
  // The attribute as TinyXML decodes it, whatever the spelling of the reference: leading zeros
  // without end, a hexadecimal multiplier that wraps at 2³².
  for (const char* reference : {"&#37;n 0 0", "&#x25;n 0 0", "&#037;n 0 0", "&#00000000000000000000000000037;n 0 0",
                                "&#x100000025;n 0 0", "&#xFFFFFFFF00000025;n 0 0"}) {
    EXPECT_NE(message_of([&] {
                SerialArm::from_urdf_string(with(reference), "base_link", "tool0");
              }).find("<origin> attribute \"xyz\" = \"%n 0 0\": contains '%'"),
              std::string::npos)
        << reference;
  }
  // "&#X…;" is no reference to TinyXML (only a lower-case x marks hexadecimal): a parse error.
  EXPECT_NE(message_of([&] {
              SerialArm::from_urdf_string(with("&#X0025;s 0 0"), "base_link", "tool0");
            }).find("not a valid robot description"),
            std::string::npos);
  // In a comment (before the robot, or spanning lines) a '%' is fine; the arm loads.
  const SerialArm ok =
      SerialArm::from_urdf_string(with("0 0 0.5", "<!-- 100% \n scale: 50% -->\n"), "base_link", "tool0");
  EXPECT_EQ(ok.dof(), 1);
  EXPECT_NEAR(ok.forward(Eigen::VectorXd::Zero(1)).translation().z(), 0.5, 1e-15);
}

TEST(SerialArmErrors, BadLinksAndArguments) {
  const std::string file = urdf_dir + "arm_planar_two_link.urdf";
  EXPECT_NE(message_of([&] { SerialArm::from_urdf_file(file, "nowhere", "link2"); }).find("base_link = \"nowhere\""),
            std::string::npos);
  EXPECT_NE(message_of([&] { SerialArm::from_urdf_file(file, "base", "nowhere"); }).find("tip_link = \"nowhere\""),
            std::string::npos);
  EXPECT_NE(message_of([&] { SerialArm::from_urdf_file(file, "link2", "link1"); }).find("not an ancestor"),
            std::string::npos);
  EXPECT_NE(message_of([&] { SerialArm::from_urdf_file(file, "link1", "link1"); }).find("must differ"),
            std::string::npos);
  // A prismatic joint off the path is fine; on the path it is refused.
  EXPECT_NE(message_of([&] { SerialArm::from_urdf_file(file, "base", "finger"); }).find("finger_joint"),
            std::string::npos);
  EXPECT_NE(message_of([&] { SerialArm::from_urdf_string("", "base", "link2"); }).find("URDF"), std::string::npos);

  const SerialArm arm = planar();
  EXPECT_NE(message_of([&] { arm.forward(Eigen::VectorXd::Zero(3)); }).find("expected 2 joint values, got 3"),
            std::string::npos);
  EXPECT_NE(message_of([&] { arm.forward(Eigen::Vector2d(0, std::nan(""))); }).find("q = "), std::string::npos);
  EXPECT_NE(message_of([&] { arm.jacobian(Eigen::VectorXd::Zero(1)); }).find("q = "), std::string::npos);
  EXPECT_NE(message_of([&] {
              arm.torques(Eigen::Vector2d::Zero(), Eigen::VectorXd::Zero(1), Eigen::Vector2d::Zero());
            }).find("qd = "),
            std::string::npos);
  EXPECT_NE(message_of([&] {
              arm.torques(Eigen::Vector2d::Zero(), Eigen::Vector2d::Zero(), Eigen::Vector2d(INFINITY, 0));
            }).find("qdd = "),
            std::string::npos);
  InverseOptions options;
  options.max_attempts = 0;
  EXPECT_NE(message_of([&] { arm.inverse_solutions(Posed(), options); }).find("max_attempts"), std::string::npos);
  options = InverseOptions();
  options.time_budget = -1;
  EXPECT_NE(message_of([&] { arm.inverse_solutions(Posed(), options); }).find("time_budget"), std::string::npos);
}

}  // namespace
}  // namespace dispkin::serial
