//! The kinematics plugin interface: what a planner needs to know about a machine.
//!
//! Implemented by dispkin::hexapod::Hexapod and dispkin::serial::SerialArm. Planning side: the
//! functions may allocate and throw std::invalid_argument / std::runtime_error.
#pragma once

#include <cmath>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "dispkin/error.hpp"
#include "dispkin/pose.hpp"

namespace dispkin {

//! Joint-space limits, one entry per joint (vectors of size dof(); `effort` may be empty).
struct JointLimits {
  Eigen::VectorXd lower;     //!< smallest joint position (m or rad)
  Eigen::VectorXd upper;     //!< largest joint position, > lower
  Eigen::VectorXd velocity;  //!< largest joint speed (m/s or rad/s), > 0
  Eigen::VectorXd effort;    //!< largest joint force / torque (N or N·m), > 0; empty if the machine states none
};

//! What joint limits of `n` joints satisfy: lower, upper and velocity of size n, effort of size n
//! or 0; for each joint lower < upper (±inf for a continuous joint; no NaN), velocity and effort
//! > 0 (+inf: none). `joint_name(i)` names joint i in messages. Throws std::invalid_argument.
template <typename JointName>
void require_joint_limits(const JointLimits& limits, Eigen::Index n, JointName joint_name) {
  const auto sized = [n](const Eigen::VectorXd& v, const std::string& name, bool may_be_empty) {
    require(v.size() == n || (may_be_empty && v.size() == 0), name + " size", static_cast<long>(v.size()),
            "must be the dof " + std::to_string(n) + (may_be_empty ? " (or 0: none)" : ""));
  };
  sized(limits.lower, "lower", false);
  sized(limits.upper, "upper", false);
  sized(limits.velocity, "velocity", false);
  sized(limits.effort, "effort", true);
  for (Eigen::Index i = 0; i < n; ++i) {
    const std::string joint = joint_name(i) + " ";
    require(!std::isnan(limits.lower(i)) && !std::isnan(limits.upper(i)) && limits.lower(i) < limits.upper(i),
            joint + "(lower, upper)", Eigen::Vector2d(limits.lower(i), limits.upper(i)), "must have lower < upper");
    require(limits.velocity(i) > 0.0, joint + "velocity", limits.velocity(i), "must be > 0 (+inf: none)");
    if (limits.effort.size())
      require(limits.effort(i) > 0.0, joint + "effort", limits.effort(i), "must be > 0 (+inf: none)");
  }
}

//! Forward and inverse kinematics plus joint limits of one machine.
class Kinematics {
 public:
  virtual ~Kinematics() = default;

  //! Number of joints (the size of a configuration vector q).
  virtual int dof() const = 0;
  //! The platform / tool pose for the joint positions q (size dof()).
  virtual Posed forward(const Eigen::VectorXd& q) const = 0;
  //! Every configuration q with forward(q) = pose; a hexapod has exactly one.
  virtual std::vector<Eigen::VectorXd> inverse(const Posed& pose) const = 0;
  //! Position and velocity limits of the joints.
  virtual JointLimits joint_limits() const = 0;
  //! A name per joint, in the order of q ("leg1"…, "joint1"…).
  virtual std::vector<std::string> joint_names() const = 0;
};

}  // namespace dispkin
