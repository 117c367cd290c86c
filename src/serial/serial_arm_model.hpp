// The data behind a SerialArm (private to src/serial: keeps KDL and urdfdom out of the public
// headers). Built once by the URDF loader, then shared read-only by every copy of the arm.
#pragma once

#include <string>
#include <vector>

#include <Eigen/Core>
#include <kdl/chain.hpp>
#include <kdl/frames.hpp>

#include "dispkin/kinematics.hpp"
#include "dispkin/pose.hpp"
#include "dispkin/serial/analytic_ik.hpp"
#include "dispkin/serial/redundancy.hpp"
#include "dispkin/serial/revolute_chain.hpp"
#include "dispkin/serial/serial_arm.hpp"
#include "chain_dynamics.hpp"

namespace dispkin {
namespace serial {

struct SerialArm::Model {
  std::string robot_name;
  std::string base_link;
  std::string tip_link;
  std::string urdf;                      // the text read: an arm is stored (pickled) as its URDF and its options
  KDL::Chain chain;                      // fixed segments included; one movable joint per q entry
  std::vector<std::string> joint_names;  // order of q
  JointLimits limits;                    // lower/upper ±∞ for continuous joints, velocity/effort +∞ if unstated
  std::vector<BodyInertia> inertias;     // per joint, in its child link's frame
  // Empty, or why a link of the chain has no rigid body's inertia (named): the dynamics refuse
  // such a model, kinematics do not need the inertias.
  std::string impossible_inertia;
  // The same bodies placed at q = 0 in base coordinates, for the torques (chain_dynamics.hpp).
  std::vector<detail::ChainBody> bodies;
  RevoluteChain revolute;  // chain at q = 0 in product-of-exponentials form
  IkFamily family = IkFamily::general;
  // A 7R arm of family locked_joint: the joint locked and the 6R chain left (redundancy.hpp),
  // and the parameter as the arm reports it.
  LockedJoint lock;
  Redundancy redundancy;
  // Configuration flags, base coordinates at q = 0: the point of axis 4 nearest to axis 5
  // and the point of axis 5 nearest to axis 6 (both the wrist centre of a spherical wrist).
  Eigen::Vector3d elbow_point = Eigen::Vector3d::Zero();
  Eigen::Vector3d shoulder_point = Eigen::Vector3d::Zero();
};

namespace detail {

// SerialArm's one friend: the model and the checks of an arm for the plugin's kernels that are
// not its members (recorded_torques, torques_by_kdl; chain_dynamics.hpp), so that the public
// header names none of them.
struct ArmAccess {
  static const SerialArm::Model& model(const SerialArm& arm) noexcept { return *arm.model_; }
  static void require_joint_vector(const SerialArm& arm, const Eigen::VectorXd& q, const char* name) {
    arm.require_joint_vector(q, name);
  }
  static void require_dynamics(const SerialArm& arm) { arm.require_dynamics(); }
};

}  // namespace detail

// KDL ↔ dispkin conversions.
inline Posed to_pose(const KDL::Frame& f) {
  Eigen::Matrix3d r;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) r(i, j) = f.M(i, j);
  Eigen::Quaterniond q(r);
  q.normalize();
  return Posed::unchecked(q, Eigen::Vector3d(f.p.x(), f.p.y(), f.p.z()));
}

inline KDL::Frame to_frame(const Posed& pose) {
  const Eigen::Quaterniond& q = pose.quaternion();
  const Eigen::Vector3d& t = pose.translation();
  return KDL::Frame(KDL::Rotation::Quaternion(q.x(), q.y(), q.z(), q.w()), KDL::Vector(t.x(), t.y(), t.z()));
}

inline Eigen::Vector3d to_eigen(const KDL::Vector& v) { return Eigen::Vector3d(v.x(), v.y(), v.z()); }

// A joint value this far beyond a position limit still counts as inside: an analytic solution
// at a limit (e.g. exactly π) comes back off by rounding.
constexpr double limit_slack = 1e-10;

// q brought into the limits by ±2π where possible (each joint to its equivalent value nearest 0
// inside them; joints without limits, and those that do not fit, into (−π, π]): the form in
// which inverse_solutions returns a solution. Whether every joint fits.
bool into_limits(Eigen::Ref<Eigen::VectorXd> q, const JointLimits& limits) noexcept;

// The lock and the redundancy of an arm of this chain, family, joint names and limits (the
// parameter's range follows the locked joint's limits).
void describe_redundancy(const RevoluteChain& chain, IkFamily family, const std::vector<std::string>& joint_names,
                         const JointLimits& limits, LockedJoint& lock, Redundancy& redundancy);

// The product-of-exponentials form of a KDL chain of revolute (and fixed) segments, at q = 0.
RevoluteChain revolute_chain_of(const KDL::Chain& chain);

// The frame of each movable joint's segment tip (its child link) at q = 0, base coordinates.
std::vector<Posed> link_frames_at_zero(const KDL::Chain& chain);

}  // namespace serial
}  // namespace dispkin
