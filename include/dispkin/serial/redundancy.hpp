//! The redundancy of a seven-joint arm as a locked joint (doc/inverse-kinematics.md §11).
//!
//! A 7R chain reaches a pose along a one-dimensional continuum of joint vectors. Fixing the first
//! or the last joint at a value θ leaves a 6R chain (the same one for every θ: only the pose it
//! must reach depends on θ), and when that chain — or the chain read from the tip back, for arms
//! whose first three axes meet (Franka Panda, KUKA iiwa) — has a closed form (spherical_wrist or
//! three_parallel), every solution at θ comes from it, exact to rounding
//! (doc/inverse-kinematics.md (eq. 37)–(eq. 39)). The Panda's classic parameter q₇ (He & Liu, ICCMA
//! 2021) is what this finds for it; an SRS arm such as the iiwa gets q₇ too (a locked joint, not
//! Shimizu's arm angle).
#pragma once

#include <string>
#include <vector>

#include <Eigen/Core>

#include "dispkin/pose.hpp"
#include "dispkin/serial/analytic_ik.hpp"
#include "dispkin/serial/revolute_chain.hpp"

namespace dispkin {
namespace serial {

//! How a 7R chain is solved with one joint locked: which joint, and the 6R chain left.
struct LockedJoint {
  int joint = -1;                       //!< the locked joint (0 or 6); −1: no lock gives a closed form
  bool reversed = false;                //!< the 6R chain is read from the tip back (doc/inverse-kinematics.md eq. 39)
  RevoluteChain rest;                   //!< the 6R chain solved for each value (reversed if so)
  IkFamily family = IkFamily::general;  //!< its closed form (spherical_wrist or three_parallel)

  //! Whether a lock leaves a closed form (joint ≥ 0).
  bool found() const noexcept { return joint >= 0; }
};

//! The first lock of a 7R chain that leaves a closed form, tried in the order: last joint, first
//! joint; each with the 6R chain read from the base, then from the tip. None (joint −1) for a
//! chain of another length or without one.
LockedJoint find_locked_joint(const RevoluteChain& chain);

//! Every solution of `pose` with the locked joint at `value` (rad, finite): the 6R closed form of
//! lock.rest for the pose doc/inverse-kinematics.md eq. 37 or 38 gives, its solutions as 7-joint vectors (the locked
//! joint `value` itself, the others in [−π, π]). Up to 8; no allocation but the result's. Throws std::invalid_argument
//! for a value that is not finite.
void locked_joint_inverse(const RevoluteChain& chain, const LockedJoint& lock, double value, const Posed& pose,
                          std::vector<Eigen::VectorXd>& out);

//! What a SerialArm's redundancy parameter is (SerialArm::redundancy()).
struct Redundancy {
  //! "locked_joint" for a 7R arm solved along a locked joint; "none" otherwise (a 6R arm, or a
  //! redundant one with no closed form, solved by the numeric search).
  std::string kind = "none";
  int joint = -1;          //!< the locked joint's index in q (−1: none)
  std::string joint_name;  //!< its name in the URDF
  double lower = 0.0;      //!< the parameter's range: the locked joint's limits, or [−π, π]
  double upper = 0.0;      //!<   for a continuous joint
  int dof = 0;             //!< the arm's joints

  //! Whether the arm has a redundancy parameter (a locked joint).
  bool has_parameter() const noexcept { return joint >= 0; }
  //! The parameter value of the joint vector q: q[joint]. Throws std::invalid_argument when there
  //! is no parameter, or for a q of the wrong size (not `dof` entries) or not finite.
  double value(const Eigen::VectorXd& q) const;
  //! The parameter values inverse_solutions uses when given neither a value nor q_ref:
  //! default_value_count values at the centres of equal parts of [lower, upper] (doc/inverse-kinematics.md eq. 40).
  std::vector<double> default_values() const;
  //! How many values default_values() gives.
  static constexpr int default_value_count = 16;
};

//! How follow() moves a redundant arm's parameter along a path (doc/inverse-kinematics.md §12):
//! from q_start's value, down the gradient of a cost that grows towards the joint limits and
//! the singular poses (doc/inverse-kinematics.md eq. 44), at a rate bounded per radian the other joints travel
//! (doc/inverse-kinematics.md eq. 45).
struct RedundancyRule {
  //! false: the parameter stays at q_start's value (doc/inverse-kinematics.md eq. 41).
  bool move = true;
  //! g of doc/inverse-kinematics.md eq. 45: the parameter's rate per unit of the cost's slope (rad² per unit of cost),
  //! ≥ 0.
  double gain = 0.05;
  //! ρ of doc/inverse-kinematics.md eq. 45: the largest change of the parameter (rad) per radian the joints travel at a
  //! fixed parameter from one pose to the next, ≥ 0; it keeps the parameter from jumping.
  double max_rate = 0.5;
  //! μ of doc/inverse-kinematics.md eq. 44: the weight of the singularity term against the joint-limit term, ≥ 0.
  double singularity_weight = 0.1;

  //! The rule that holds the parameter at its value in q_start (move false): what the followers of
  //! a Cartesian trajectory use unless given another (doc/inverse-kinematics.md eq. 41).
  static RedundancyRule held() noexcept {
    RedundancyRule rule;
    rule.move = false;
    return rule;
  }
};

}  // namespace serial
}  // namespace dispkin
