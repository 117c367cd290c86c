// The arms of tests/data/urdf shared by the serial-arm tests (test_serial_arm.cpp,
// test_serial_dynamics.cpp, test_serial_inverse.cpp, test_urdf_refusals.cpp and the re-timing
// tests), and the joint vectors they draw and compare.
#pragma once

#include <cmath>
#include <string>
#include <vector>

#include <dispkin/serial/serial_arm.hpp>

#include "random_cases.hpp"

namespace dispkin::testing {

//! The folder of the test URDFs.
inline const std::string urdf_dir = std::string(DISPKIN_SOURCE_DIR) + "/tests/data/urdf/";

//! The two-link arm in the vertical plane, up to `tip`.
inline serial::SerialArm planar(const std::string& tip = "link2") {
  return serial::SerialArm::from_urdf_file(urdf_dir + "arm_planar_two_link.urdf", "base", tip);
}

//! The UR5e by its DH table.
inline serial::SerialArm ur5e() {
  return serial::SerialArm::from_urdf_file(urdf_dir + "arm_ur5e_dh.urdf", "base_link", "tool0");
}

//! Joint positions drawn uniformly within the limits (within ±π for a continuous joint).
inline Eigen::VectorXd random_q(Random& random, const serial::SerialArm& arm) {
  constexpr double pi = 3.14159265358979323846;
  const JointLimits limits = arm.joint_limits();
  Eigen::VectorXd q(arm.dof());
  for (int i = 0; i < arm.dof(); ++i) {
    const double lo = std::isfinite(limits.lower(i)) ? limits.lower(i) : -pi;
    const double hi = std::isfinite(limits.upper(i)) ? limits.upper(i) : pi;
    q(i) = random.uniform(lo, hi);
  }
  return q;
}

//! n numbers drawn uniformly from [-scale, scale] (joint velocities, accelerations).
inline Eigen::VectorXd random_vector(Random& random, int n, double scale) {
  Eigen::VectorXd x(n);
  for (int i = 0; i < n; ++i) x(i) = random.uniform(-scale, scale);
  return x;
}

//! The set holds q (every joint within `tolerance`).
inline bool contains(const std::vector<Eigen::VectorXd>& set, const Eigen::VectorXd& q, double tolerance) {
  for (const Eigen::VectorXd& s : set)
    if ((s - q).cwiseAbs().maxCoeff() <= tolerance) return true;
  return false;
}

}  // namespace dispkin::testing
