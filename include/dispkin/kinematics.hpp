//! The kinematics plugin interface: what a planner needs to know about a machine.
//!
//! Implemented by dispkin::hexapod (Hexapod) and, later, dispkin::serial. Planning side: the
//! functions may allocate and throw std::invalid_argument / std::runtime_error.
#pragma once

#include <string>
#include <vector>

#include <Eigen/Core>

#include "dispkin/pose.hpp"

namespace dispkin {

//! Joint-space limits, one entry per joint (vectors of size dof(); `effort` may be empty).
struct JointLimits {
  Eigen::VectorXd lower;     //!< smallest joint position (m or rad)
  Eigen::VectorXd upper;     //!< largest joint position, > lower
  Eigen::VectorXd velocity;  //!< largest joint speed (m/s or rad/s), > 0
  Eigen::VectorXd effort;    //!< largest joint force / torque (N or N·m), > 0; empty if the machine states none
};

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
