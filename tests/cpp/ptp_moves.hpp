// The serial test arms loaded from their URDFs and random PTP moves inside their joint ranges,
// shared by the PTP tests and the sweeps.
#pragma once

#include <algorithm>
#include <string>

#include <dispkin/path/path.hpp>
#include <dispkin/serial/serial_arm.hpp>

#include "random_cases.hpp"

namespace dispkin {
namespace testing {

inline serial::SerialArm ur5e_arm() {
  return serial::SerialArm::from_urdf_file(std::string(DISPKIN_SOURCE_DIR) + "/tests/data/urdf/arm_ur5e_dh.urdf",
                                           "base_link", "tool0");
}
inline serial::SerialArm kr6_arm() {
  return serial::SerialArm::from_urdf_file(std::string(DISPKIN_SOURCE_DIR) + "/tests/data/urdf/arm_kr6_like_dh.urdf",
                                           "base_link", "flange");
}

// Uniform joint values inside the arm's limits, clipped to [−π, π] (wider ranges add nothing new).
inline Eigen::VectorXd random_joints(Random& rnd, const serial::SerialArm& arm) {
  const JointLimits l = arm.joint_limits();
  Eigen::VectorXd q(arm.dof());
  for (int i = 0; i < arm.dof(); ++i) q(i) = rnd.uniform(std::max(l.lower(i), -3.14159), std::min(l.upper(i), 3.14159));
  return q;
}

// A random PTP move: both ends random, or (one case in four) a short move near one end.
inline JointPath random_ptp(Random& rnd, const serial::SerialArm& arm) {
  const Eigen::VectorXd q_a = random_joints(rnd, arm);
  Eigen::VectorXd q_b = random_joints(rnd, arm);
  if (rnd.integer(0, 3) == 0) q_b = q_a + rnd.uniform(0.01, 0.2) * (q_b - q_a);
  return JointPath(q_a, q_b);
}

}  // namespace testing
}  // namespace dispkin
