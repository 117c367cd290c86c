// Serial-arm dynamics: torques against a hand-derived two-link model and KDL's recursive
// Newton-Euler, gravity, the energy balance, and torques from two threads.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <string>
#include <thread>
#include <vector>


#include <dispkin/serial/chain_kinematics.hpp>
#include <dispkin/serial/serial_arm.hpp>

#include "chain_dynamics.hpp"  // torques_by_kdl
#include "random_cases.hpp"
#include "serial_test_arms.hpp"


namespace dispkin::serial {
namespace {

using dispkin::testing::message_of;
using dispkin::testing::planar;
using dispkin::testing::Random;
using dispkin::testing::random_q;
using dispkin::testing::random_vector;
using dispkin::testing::ur5e;
using dispkin::testing::urdf_dir;

constexpr double pi = 3.14159265358979323846;

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

}  // namespace
}  // namespace dispkin::serial
