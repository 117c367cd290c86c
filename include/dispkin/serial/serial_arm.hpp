//! The serial-arm plugin: a chain of revolute joints read from a URDF (urdfdom) into an Orocos
//! KDL chain, held in product-of-exponentials form (chain()) for forward kinematics, the
//! Jacobian (chain_kinematics.hpp) and the torques (recursive Newton–Euler on the same pass),
//! and solved for all inverse-kinematics
//! solutions by the analytic families of analytic_ik.hpp (or by a numeric search when no
//! family fits).
//!
//! Loading rules (from_urdf_file / from_urdf_string):
//! - the chain is the path of joints from `base_link` down to `tip_link`; `base_link` must be an
//!   ancestor of `tip_link` in the URDF tree;
//! - revolute and continuous joints are the arm's joints (q, in the order base → tip); fixed
//!   joints are folded into the chain (their transform and their child link's inertia stay);
//!   prismatic, planar and floating joints on the path are refused;
//! - position limits: a revolute joint's `<limit lower upper>` (lower < upper required); a
//!   continuous joint gets (−∞, +∞);
//! - velocity and effort limits: the `<limit>` values; a missing or zero value means "not stated"
//!   and becomes +∞;
//! - inertia: each moving body is the joint's child link plus every link rigidly attached to it
//!   (through fixed joints) that is not on the path, e.g. a tool flange after the tip. Subtrees
//!   attached through movable joints (gripper fingers) are left out. The base link's inertia
//!   does not matter (it does not move).
//! - `<mimic>` tags are ignored: every revolute / continuous joint on the path is a coordinate of q.
//!
//! The analytic IK works on chain(), a RevoluteChain taken from the KDL chain at q = 0: the
//! joint axes and a point on each in base coordinates, and the tip pose.
#pragma once

#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "dispkin/kinematics.hpp"
#include "dispkin/pose.hpp"
#include "dispkin/serial/analytic_ik.hpp"
#include "dispkin/serial/redundancy.hpp"
#include "dispkin/serial/revolute_chain.hpp"

namespace dispkin {
namespace serial {

//! The mass properties of one moving body of the chain (the child link of a joint plus what is
//! rigidly attached to it), in the frame of that link.
struct BodyInertia {
  double mass = 0.0;                                         //!< kg
  Eigen::Vector3d centre_of_mass = Eigen::Vector3d::Zero();  //!< m, link frame
  Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();         //!< about the centre of mass, link axes (kg·m²)
};

//! Shoulder / elbow / wrist configuration of a 6R arm, each +1 or −1 (0: on the boundary between
//! the two, within 1e-9). With ωᵢ the current axis and pᵢ a point on axis i (base coordinates at
//! q), s the point of axis 5 nearest to axis 6 and e the point of axis 4 nearest to axis 5 (both
//! the wrist centre of a spherical wrist; for a UR the 5–6 and 4–5 axis crossings):
//! - shoulder = sign((s − p₁) · (ω₂ × ω₁)): which side of the plane through axis 1 spanned by
//!   ω₁ and ω₂ the wrist is on ("front" / "back" for an industrial arm, "left" / "right" for a UR);
//! - elbow    = sign(ω₃ · ((p₃ − p₂) × (e − p₃))): which way the arm bends at joint 3;
//! - wrist    = sign(ω₅ · (ω₄ × ω₆)): the wrist flip (sin q₅ up to a sign fixed by the chain).
//! For the spherical-wrist and UR families the (up to 8) analytic solutions of a pose have
//! pairwise different flags, so the flags pick one.
struct Configuration {
  int shoulder = 0;  //!< +1 or −1 (0: on the boundary)
  int elbow = 0;     //!< +1 or −1 (0: on the boundary)
  int wrist = 0;     //!< +1 or −1 (0: on the boundary)
  //! Whether all three flags are equal.
  bool operator==(const Configuration& o) const noexcept {
    return shoulder == o.shoulder && elbow == o.elbow && wrist == o.wrist;
  }
  //! Whether a flag differs.
  bool operator!=(const Configuration& o) const noexcept { return !(*this == o); }
};

//! How inverse() searches and what it returns.
struct InverseOptions {
  bool keep_outside_limits = false;  //!< also return solutions outside the position limits (flagged)
  //! Also return every q + 2πk inside the limits of joints whose range exceeds a turn, at most
  //! input_budget::max_ik_solutions in all (more is refused: ±20 rad on a 6R arm make 5·10⁵).
  bool offer_equivalents = false;
  //! A redundant arm with a parameter (SerialArm::redundancy()): every solution at this parameter
  //! value only (finite; a value outside the parameter's range gives the solutions there, which
  //! the limits of the locked joint then keep or drop). Not with q_ref.
  std::optional<double> redundancy;
  //! The solutions at q_ref's parameter value (redundant arms with a parameter; any arm: all of
  //! them), nearest to q_ref first (Euclidean distance in joint space). Not with redundancy.
  std::optional<Eigen::VectorXd> q_ref;
  //! Family general with q_ref: also search from random starts when Newton's method from q_ref
  //! converges (without it the search runs only where Newton lands on no solution inside the limits).
  bool wide_search = false;
  // Numeric fallback (family general) only:
  int max_attempts = 64;      //!< random restarts of the KDL solver, > 0
  double time_budget = 0.05;  //!< s of wall-clock time for the restarts, > 0
  unsigned seed = 1;          //!< of the restart generator: results are reproducible
};

//! What inverse_solutions() found.
struct InverseResult {
  std::vector<Eigen::VectorXd> solutions;  //!< each reproduces the pose to ≤ 1e-10 (forward())
  std::vector<bool> within_limits;         //!< per solution; all true unless keep_outside_limits
  //! true: every solution (analytic; for a redundant arm every one at the parameter value asked
  //! for); false: what a search found, or a redundant arm's solutions at the default values.
  bool complete = false;
  IkFamily family = IkFamily::general;  //!< the method used
};

//! The pose tolerance every returned IK solution meets: rotation-matrix entries and
//! translation (m), as Pose::is_approx.
constexpr double inverse_tolerance = 1e-10;

class SerialArm;

namespace detail {
struct ArmAccess;  // the plugin's own kernels' way to the model (src/serial/serial_arm_model.hpp)
}  // namespace detail

//! A serial arm of revolute joints between a base link and a tip link of a URDF.
//!
//! Immutable after loading except for gravity; copies share the chain.
class SerialArm : public Kinematics {
 public:
  //! Reads a URDF file. Throws std::invalid_argument naming the file, the link or the joint
  //! when the file cannot be read, is not a URDF, a link is missing, `base_link` is not an
  //! ancestor of `tip_link`, a joint on the path is of an unsupported type or has bad limits.
  static SerialArm from_urdf_file(const std::string& path, const std::string& base_link, const std::string& tip_link);
  //! The same from URDF text.
  static SerialArm from_urdf_string(const std::string& xml, const std::string& base_link, const std::string& tip_link);

  const std::string& robot_name() const noexcept;  //!< the URDF's `<robot name>`
  const std::string& base_link() const noexcept;   //!< the chain's first link (the base frame)
  const std::string& tip_link() const noexcept;    //!< the chain's last link (the flange)
  //! The URDF text the arm was read from (with base_link(), tip_link(), joint_limits() and
  //! gravity() all it takes to make the same arm again).
  const std::string& urdf() const noexcept;

  // Kinematics
  int dof() const override;
  //! The tip pose in base coordinates (product of exponentials on chain()). Throws for a q of
  //! the wrong size or with non-finite values; q outside the limits is allowed.
  Posed forward(const Eigen::VectorXd& q) const override;
  //! inverse_solutions(pose).solutions with default options.
  std::vector<Eigen::VectorXd> inverse(const Posed& pose) const override;
  JointLimits joint_limits() const override;
  std::vector<std::string> joint_names() const override;
  //! The same arm with other joint limits (e.g. from MoveIt's joint_limits.yaml, which overrides
  //! the URDF's): each vector of size dof(), lower < upper (±∞ allowed for continuous joints),
  //! velocity > 0 (+∞: none), effort empty or > 0 (+∞: none). Throws std::invalid_argument
  //! naming the entry.
  SerialArm with_joint_limits(const JointLimits& limits) const;

  //! All IK solutions: the analytic family of chain() when there is one (complete), else the
  //! numeric fallback (KDL ChainIkSolverPos_LMA from random starts inside the limits, within
  //! options.max_attempts and options.time_budget, which bounds the search's wall-clock time;
  //! not complete). Each distinct solution comes once, every joint value the 2π-equivalent
  //! nearest to 0 inside the limits (continuous joints: in (−π, π]), however wide the limits
  //! (±1e16 rad included); duplicates (equal up to 2π, every joint within 1e-7) are removed.
  //! options.offer_equivalents adds the 2π copies inside the limits, and throws
  //! std::invalid_argument when they would be more than input_budget::max_ik_solutions.
  //! An unreachable pose gives none. For a
  //! redundant arm (dof() > 6) the solutions form a continuum: with a parameter (redundancy(),
  //! family locked_joint) every solution at options.redundancy, at q_ref's value (options.q_ref),
  //! or with neither at each of redundancy().default_values() (doc/inverse-kinematics.md (eq. 40));
  //! without one the search returns samples. Family general with options.q_ref: Newton's method
  //! from q_ref first (minimum-norm steps, doc/inverse-kinematics.md (eq. 46)), its solution alone
  //! when it converges inside the limits, the search as well only with options.wide_search.
  //! options.redundancy on an arm without a parameter,
  //! or together with q_ref, throws std::invalid_argument.
  //! Every solution (each 2π copy too) reproduces the pose to inverse_tolerance by forward():
  //! a closed-form one as the solver measured it (doc/inverse-kinematics.md eq. 25, which implies it:
  //! doc/inverse-kinematics.md doc/inverse-kinematics.md eq. 28) or kept it exact to rounding (eq. 26), every other one
  //! checked by forward(). Thread safety: const and without shared mutable state (the KDL solvers are made per call on
  //! a copy of the KDL chain, whose joints cache their last pose; the analytic IK caches its chain analysis per
  //! thread), so one arm may be used from several threads at once.
  InverseResult inverse_solutions(const Posed& pose, const InverseOptions& options = {}) const;

  //! The geometric Jacobian J(q) (6 × dof, product of exponentials on chain()): rows (v, ω),
  //! the linear velocity of the tip frame's origin and the angular velocity, both in base
  //! coordinates, for q̇: (v, ω) = J q̇.
  Eigen::MatrixXd jacobian(const Eigen::VectorXd& q) const;
  //! The body Jacobian: the same twist in tip coordinates, the (v, ω) of dispkin::Twist.
  Eigen::MatrixXd body_jacobian(const Eigen::VectorXd& q) const;

  //! Joint torques τ = M(q) q̈ + C(q, q̇) q̇ + g(q) (N·m) by recursive Newton–Euler on chain()
  //! (the pass of forward() and jacobian(); it agrees with KDL's ChainIdSolver_RNE to rounding),
  //! no external wrenches. Throws std::invalid_argument naming the link when a link of the chain
  //! has an inertia no rigid body has (not positive semidefinite, or breaking the triangle
  //! inequality): such a URDF loads for kinematics only.
  Eigen::VectorXd torques(const Eigen::VectorXd& q, const Eigen::VectorXd& qd, const Eigen::VectorXd& qdd) const;
  //! τ(q, q̇, q̈) into `tau` and the static part g(q) (static_torques(q), bit for bit) into
  //! `holding`, in one pass: what a joint-limit check needs at each instant. Throws as torques().
  void torques(const Eigen::VectorXd& q, const Eigen::VectorXd& qd, const Eigen::VectorXd& qdd, Eigen::VectorXd& tau,
               Eigen::VectorXd& holding) const;
  //! The static part g(q) = torques(q, 0, 0): what holding the arm still costs.
  Eigen::VectorXd static_torques(const Eigen::VectorXd& q) const;

  //! Gravitational acceleration in base coordinates (m/s²), default (0, 0, −9.81); set_gravity
  //! takes finite coordinates within ±1e12 m/s².
  //!@{
  const Eigen::Vector3d& gravity() const noexcept { return gravity_; }
  void set_gravity(const Eigen::Vector3d& gravity);
  //!@}

  //! The moving bodies' mass properties, one per joint (order of q).
  std::vector<BodyInertia> inertias() const;

  //! The chain in product-of-exponentials form (axes and points at q = 0, base coordinates),
  //! on which forward(), jacobian() and the analytic IK work: forward(chain(), q) is forward(q).
  const RevoluteChain& chain() const noexcept;
  //! The analytic family recognised for chain().
  IkFamily family() const noexcept;
  //! The redundancy parameter of a 7R arm of family locked_joint (redundancy.hpp); kind "none"
  //! for any other arm.
  const Redundancy& redundancy() const noexcept;

  //! The shoulder / elbow / wrist flags of q (see Configuration); needs dof() == 6.
  Configuration configuration(const Eigen::VectorXd& q) const;

 private:
  struct Model;
  explicit SerialArm(std::shared_ptr<const Model> model);
  void require_joint_vector(const Eigen::VectorXd& q, const char* name) const;
  void require_dynamics() const;
  friend struct detail::ArmAccess;

  std::shared_ptr<const Model> model_;
  Eigen::Vector3d gravity_{0.0, 0.0, -9.81};
};

//! The solution closest to q_ref (Euclidean distance in joint space, no wrapping: 2π-equivalent
//! values are separate solutions). Throws std::invalid_argument if `solutions` is empty or
//! sizes differ.
Eigen::VectorXd nearest(const std::vector<Eigen::VectorXd>& solutions, const Eigen::VectorXd& q_ref);

//! The solutions of `arm` whose configuration() equals `wanted`, in their order.
std::vector<Eigen::VectorXd> with_configuration(const SerialArm& arm, const std::vector<Eigen::VectorXd>& solutions,
                                                const Configuration& wanted);

//! The largest joint step (rad, any joint) follow() takes between consecutive poses on a redundant arm.
constexpr double max_redundant_step = 0.3;

//! Continuity along a path: for each pose in turn the solution nearest to the previous one
//! among all solutions and their 2π copies inside the limits (found in closed form, never
//! enumerated; options.offer_equivalents is not needed for them), starting from q_start (on a 6-joint arm tracked by
//! Newton's method from the previous one first, where that converges close by). Throws std::runtime_error naming the
//! index of a pose without a solution. A redundant arm with a parameter (redundancy()) starts at q_start's parameter
//! value (options.redundancy is ignored) and moves it by `redundancy_rule` away from the joint limits and singular
//! poses, at most redundancy_rule.max_rate rad per radian the other joints travel (doc/inverse-kinematics.md (eq. 45);
//! with redundancy_rule.move false it stays); the first joint vector of a path that starts at forward(q_start) is
//! q_start to rounding (no travel, no move); a step of more than max_redundant_step in any joint from one pose to the
//! next throws std::runtime_error naming the pose instead of jumping (doc/inverse-kinematics.md eq. 41). Throws
//! std::invalid_argument for a negative or non-finite value of the rule.
std::vector<Eigen::VectorXd> follow(const SerialArm& arm, const std::vector<Posed>& poses,
                                    const Eigen::VectorXd& q_start, const InverseOptions& options = {},
                                    const RedundancyRule& redundancy_rule = {});

//! The joint velocities q̇ that give the body twist ξ_b = J_b(q) q̇ (the (v, ω) of dispkin::Twist):
//! the minimum-norm least-squares solution, singular values below 6 ε of the largest taken as
//! zero (exact for a 6-joint arm away from singularities; the nearest twist for a shorter arm).
//! An arm with a redundancy parameter keeps its locked joint still (rate 0) and solves for the
//! others (doc/inverse-kinematics.md (eq. 42)), as its paths at one parameter value move.
//! Throws std::invalid_argument for a q of the wrong size or not finite.
Eigen::VectorXd joint_velocity(const SerialArm& arm, const Eigen::VectorXd& q, const Twistd& body_twist);

}  // namespace serial
}  // namespace dispkin
