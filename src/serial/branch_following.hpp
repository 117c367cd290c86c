// Following the inverse-kinematics branch of a serial arm from pose to pose (doc/retiming.md §1):
// the one follower behind serial::follow and the joint-limit check and re-timing of a Cartesian
// trajectory.
#pragma once

#include <optional>

#include <Eigen/Core>

#include "dispkin/pose.hpp"
#include "dispkin/serial/serial_arm.hpp"

namespace dispkin {
namespace serial {
namespace detail {

//! Which 2π-equivalent joint values count as different solutions of a pose.
enum class Turns {
  //! The solutions as inverse_solutions lists them: every joint in its limits' representative
  //! range, and with options.offer_equivalents the 2π copies inside the limits of the joints
  //! whose range exceeds a turn (serial::follow).
  listed,
  //! Every joint of every solution moved by the multiple of 2π that brings it nearest to the
  //! reference, limits or not (doc/retiming.md (eq. 1)): a joint whose range exceeds a turn
  //! keeps turning the same way (re-timing).
  nearest,
};

//! The candidates of a pose: inverse_solutions(pose, options), with `turns` for the 2π-equivalents.
struct BranchRule {
  InverseOptions options;
  Turns turns = Turns::listed;
};

//! The solution of `pose` on q_ref's branch: the candidate nearest to q_ref (Euclidean distance
//! in joint space). A 6-joint arm first tracks it by Newton's method on the pose error from
//! `guess` (q_ref if null): along a path consecutive poses are close, so it converges in two or
//! three steps to the solution of q_ref's branch, far cheaper than enumerating every analytic
//! solution. It is taken when it converges to 1e-13 and, in the rule's form, lies within 0.3 rad
//! of q_ref in every joint; otherwise (no convergence, a near-singular Jacobian, a step or a
//! landing more than 0.3 rad away, where another branch may have been reached) every solution
//! is enumerated. Empty when the pose has none.
std::optional<Eigen::VectorXd> solution_on_branch(const SerialArm& arm, const Posed& pose, const Eigen::VectorXd& q_ref,
                                                  const BranchRule& rule, const Eigen::VectorXd* guess = nullptr);

}  // namespace detail
}  // namespace serial
}  // namespace dispkin
