// Shared pieces of the analytic IK solvers (internal): the chain's special geometry, the
// three-joint positioning stage, the Newton polish on the full pose, and a de-duplicating
// solution set.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>

#include <Eigen/Core>

#include "dispkin/pose.hpp"
#include "dispkin/serial/analytic_ik.hpp"
#include "dispkin/serial/chain_kinematics.hpp"
#include "dispkin/serial/revolute_chain.hpp"
#include "ik_arm_frame.hpp"
#include "ik_newton.hpp"
#include "ik_subproblems.hpp"

namespace dispkin {
namespace serial {
namespace detail {

using Vector6d = Eigen::Matrix<double, 6, 1>;

//! A rigid motion x ↦ R x + t held as a matrix and a vector: the closed forms compose the
//! joints' motions from the cosines and sines their subproblems give, with no trigonometric
//! function (a quaternion AngleAxis or a Rodrigues matrix from an angle needs sin and cos).
struct Motion {
  Eigen::Matrix3d r = Eigen::Matrix3d::Identity();
  Eigen::Vector3d t = Eigen::Vector3d::Zero();

  static Motion of(const Posed& pose) noexcept { return {pose.rotation(), pose.translation()}; }
  EIGEN_ALWAYS_INLINE Eigen::Vector3d operator*(const Eigen::Vector3d& x) const noexcept { return r * x + t; }
  EIGEN_ALWAYS_INLINE Motion operator*(const Motion& o) const noexcept { return {r * o.r, r * o.t + t}; }
  EIGEN_ALWAYS_INLINE Motion inverse() const noexcept { return {r.transpose(), -(r.transpose() * t)}; }
};

//! The motion of joint i turned by θ (cosine and sine): x ↦ R(ωᵢ, θ)(x − pᵢ) + pᵢ.
EIGEN_ALWAYS_INLINE Motion joint_motion(const RevoluteChain& chain, int i, const CosSin& angle) noexcept {
  const auto k = static_cast<std::size_t>(i);
  Motion m;
  m.r = rotation(chain.axes[k], angle);
  m.t = chain.points[k] - m.r * chain.points[k];
  return m;
}

//! e_i(θ) X for a fixed motion X as a function of (cos θ, sin θ). With
//! R(ω, θ) = ωωᵀ + cos θ (I − ωωᵀ) + sin θ [ω]×, the motion x ↦ R (X x − p) + p splits into
//! three fixed motions, so each evaluation is two scaled sums (no matrix product).
struct JointThen {
  Motion along, normal, cross;

  JointThen() = default;
  JointThen(const RevoluteChain& chain, int i, const Motion& x) noexcept {
    const auto k = static_cast<std::size_t>(i);
    const Eigen::Vector3d& w = chain.axes[k];
    const Eigen::Vector3d y = x.t - chain.points[k];
    along.r = w * (w.transpose() * x.r);
    along.t = w * w.dot(y) + chain.points[k];
    normal.r = x.r - along.r;
    normal.t = y - w * w.dot(y);
    for (int j = 0; j < 3; ++j) cross.r.col(j) = w.cross(x.r.col(j));
    cross.t = w.cross(y);
  }
  EIGEN_ALWAYS_INLINE Motion at(const CosSin& a) const noexcept {
    return {along.r + a.c * normal.r + a.s * cross.r, along.t + a.c * normal.t + a.s * cross.t};
  }
};

//! How the first three joints place a point: axes 2 ∥ 3 (an arm plane; q₁ by subproblem 4)
//! or axes 1, 2 meeting (a shoulder point; q₁, q₂ by subproblem 2).
enum class PositionLayout { none, parallel_23, intersecting_12 };

//! What the solvers need to know about a 6R chain's axes (base frame, q = 0).
struct ChainGeometry {
  PositionLayout layout = PositionLayout::none;
  bool axes_12_meet = false;                           //!< axes 1 and 2 meet (intersecting_12 always)
  Eigen::Vector3d shoulder = Eigen::Vector3d::Zero();  //!< axes 1 ∩ 2
  bool wrist_meets = false;                            //!< axes 4, 5, 6 meet in one point
  Eigen::Vector3d wrist_centre = Eigen::Vector3d::Zero();
  bool axes_45_meet = false;  //!< axes 4 and 5 meet (offset wrist)
  Eigen::Vector3d point_45 = Eigen::Vector3d::Zero();
  bool three_parallel = false;  //!< axes 2 ∥ 3 ∥ 4, axes 5 ∩ 6 (UR)
  Eigen::Vector3d point_56 = Eigen::Vector3d::Zero();
  IkFamily family = IkFamily::general;  //!< the recognised family
  // Per-chain constants of the closed forms, worked out once with the geometry.
  Motion tip_inverse;                                   //!< M⁻¹
  JointThen tool;                                       //!< e₆(q₆) M split into fixed parts
  Eigen::Vector3d normal_4 = Eigen::Vector3d::UnitX();  //!< a unit vector ⊥ ω₄ (x₄ of doc/inverse-kinematics.md eq. 12)
  Eigen::Vector3d normal_6 = Eigen::Vector3d::UnitX();  //!< a unit vector ⊥ ω₆ (x₆ of doc/inverse-kinematics.md eq. 11)
  //! The family's axes meet and are parallel to rounding (exact_fit_tolerance), not merely to the
  //! recognition tolerance: only then is a well-conditioned closed-form candidate exact to
  //! rounding without a check (doc/inverse-kinematics.md §8, eq. 26).
  bool exact_fit = false;
  //! Spherical wrist with ω₅ ⊥ ω₄, ω₅ ⊥ ω₆ and ω₄ ∥ ω₆ at q = 0 (exact_fit too): the wrist's
  //! second solution is the flip (q₄ + π, −q₅, q₆ + π) of its first (doc/inverse-kinematics.md (eq. 27)).
  bool wrist_flips = false;
  //! A flipping spherical wrist whose axis 1 is also ⊥ axis 2 (an ortho-parallel basis): solved in
  //! the arm frame (doc/inverse-kinematics.md §10) unless a pose is near a tangency or singularity.
  bool ortho_parallel = false;
  OrthoParallel ortho;
  //! Three parallel axes, fitting exactly, with axis 1 ⊥ axis 2: solved in the arm frame likewise.
  bool three_parallel_plane = false;
  ThreeParallelPlane plane;
  // Why a family does not fit (static strings: analysing a chain must not allocate).
  const char* why_not_spherical = "";
  const char* why_not_three_parallel = "";
  const char* why_not_offset = "";
};

//! Checks the chain (6 joints, finite unit axes and points; throws naming the argument) and
//! works out its geometry with `tolerance` (metres for distances, radians for angles).
ChainGeometry analyse(const RevoluteChain& chain, double tolerance);

//! Throws std::invalid_argument (naming `chain.axes[i]` etc.) unless the chain is well formed.
void validate_chain(const RevoluteChain& chain);

//! The positioning stage: (q₁, q₂, q₃) with e₁e₂e₃ x = y, up to four, labelled by
//! branch = 2 · (first label) + (second label); `exists[branch]` says which are defined.
struct PositionSolutions {
  std::array<std::array<CosSin, 3>, 4> q;  //!< (q₁, q₂, q₃) of each branch
  Eigen::Vector3d angles(std::size_t branch) const {
    return {q[branch][0].angle(), q[branch][1].angle(), q[branch][2].angle()};
  }
  std::array<bool, 4> exists{};
  //! How far each branch is from its end: ≥ 0 where it exists; where it does not, the most
  //! negative tangency margin of its subproblems (the search looks for islands with it).
  std::array<double, 4> margin{{-1.0, -1.0, -1.0, -1.0}};
};
PositionSolutions solve_position(const RevoluteChain& chain, const ChainGeometry& geometry, const Eigen::Vector3d& x,
                                 const Eigen::Vector3d& y) noexcept;

//! The positioning stage's first subproblem (q₁ by subproblem 4 for parallel_23, q₃ by
//! subproblem 3 for intersecting_12; the layout must be one of them): no branch exists where
//! its discriminant is negative.
Harmonic first_positioning_harmonic(const RevoluteChain& chain, const ChainGeometry& geometry, const Eigen::Vector3d& x,
                                    const Eigen::Vector3d& y) noexcept;

//! Whether the elbow subproblem (q₃ by subproblem 3) of the parallel_23 layout is an equation
//! of x and y alone: where axes 1 and 2 meet (the Jaco2). Elsewhere it depends on q₁'s branch.
bool elbow_independent_of_q1(const ChainGeometry& geometry) noexcept;

//! That elbow equation (only where elbow_independent_of_q1).
Harmonic elbow_harmonic(const RevoluteChain& chain, const ChainGeometry& geometry, const Eigen::Vector3d& x,
                        const Eigen::Vector3d& y) noexcept;

//! The closed forms (ik_closed_form.cpp): every solution of the pose into `out` (appended). They
//! take the arm-frame fast path (ik_arm_frame.hpp) where the geometry has it and the pose allows.
//! three_parallel_inverse says whether the pose is near the wrist singularity.
void spherical_wrist_inverse(const RevoluteChain& chain, const ChainGeometry& geometry, const Posed& pose,
                             IkSolutionSet& out);
bool three_parallel_inverse(const RevoluteChain& chain, const ChainGeometry& geometry, const Posed& pose,
                            IkSolutionSet& out);

//! Position error (m) and rotation error (rad) of forward(chain, q) against `target`.
inline PoseError pose_error(const RevoluteChain& chain, const Vector6d& q, const Posed& target) noexcept {
  return pose_error(chain_pose(chain, q.data()), target);
}

//! The rotation angle θ (rad) of targetᵀ r, from ‖r − target‖_F = 2√2 sin(θ/2) (one asin, no
//! quaternion).
inline double rotation_error(const Eigen::Matrix3d& r, const Eigen::Matrix3d& target) noexcept {
  const double x = (r - target).norm() / (2.0 * std::sqrt(2.0));
  // asin x = x + x³/6 + O(x⁵): for x < 1e-4 (every candidate near a solution) the first two
  // terms are asin to rounding (the next one is 3x⁵/40 < 1e-17 x), without a libm call.
  return 2.0 * (x < 1e-4 ? x + x * x * x / 6.0 : std::asin(std::min(1.0, x)));
}

//! Position (m) and rotation (rad) error of the motion `t` against `target`.
inline PoseError motion_error(const Motion& t, const Motion& target) noexcept {
  PoseError e;
  e.position = (t.t - target.t).norm();
  e.rotation = rotation_error(t.r, target.r);
  return e;
}

//! Newton's method on the full 6-D pose error (refine_pose, doc/inverse-kinematics.md (eq. 22)
//! and (doc/inverse-kinematics.md eq. 23)) to rounding, with minimum-norm steps at singular q so that it converges
//! there too. Returns the final error; q is updated in place and wrapped to (−π, π].
inline PoseError polish(const RevoluteChain& chain, const Posed& target, Vector6d& q, int max_iterations) noexcept {
  NewtonSettings settings;
  settings.tolerance = 1e-15;
  settings.max_iterations = max_iterations;
  settings.wrap = true;
  return refine_pose(chain, target, q.data(), settings);
}

//! Accept a candidate: polish it if its error exceeds `polish_above`, keep it if the error is
//! then ≤ ik_pose_tolerance, and not if it repeats a kept one (all joints within
//! ik_duplicate_tolerance mod 2π). `Store` has size(), operator[] and push(q).
//! `error`: the pose error of q already measured (the closed forms measure it from the cosines
//! and sines, to which q = atan2(s, c) agrees to an ulp — a pose difference of ~1e-16 m, far
//! below the polish threshold); a polished q is measured again by pose_error.
template <typename Store>
void offer(const RevoluteChain& chain, const Posed& target, Vector6d q, PoseError error, Store& store,
           double polish_above = 4e-15) {
  for (int i = 0; i < 6; ++i) q(i) = wrap_angle(q(i));
  PoseError e = error;
  if (e.worst() > polish_above) e = polish(chain, target, q, 30);
  if (!(e.worst() <= ik_pose_tolerance)) return;
  for (int s = 0; s < store.size(); ++s) {
    int i = 0;
    while (i < 6 && std::abs(wrap_angle(q(i) - store[s](i))) <= ik_duplicate_tolerance) ++i;
    if (i == 6) return;  // every joint agrees
  }
  store.push(q, e.worst());
}

//! offer() measuring the pose error of q by forward kinematics.
template <typename Store>
void offer(const RevoluteChain& chain, const Posed& target, Vector6d q, Store& store, double polish_above = 4e-15) {
  for (int i = 0; i < 6; ++i) q(i) = wrap_angle(q(i));
  offer(chain, target, q, pose_error(chain, q, target), store, polish_above);
}

}  // namespace detail
}  // namespace serial
}  // namespace dispkin
