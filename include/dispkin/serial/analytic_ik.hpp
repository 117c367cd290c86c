//! Analytic inverse kinematics of 6R chains: all solutions, no initial guess.
//!
//! The family is recognised from the joint axes of a RevoluteChain (doc/inverse-kinematics.md §4):
//! - spherical_wrist: the last three axes meet in one point (Pieper; KUKA KR6, ABB IRB 120);
//! - three_parallel:  three consecutive parallel axes with the UR layout (UR3/5/10, e and non-e);
//! - offset_wrist:    a 6R chain of neither kind whose IK is a one-dimensional search
//!                    (Kinova Jaco2 j2n6s300);
//! - locked_joint:    a 7R chain whose first or last joint, locked, leaves a 6R chain of a closed
//!                    form (Franka Panda, KUKA iiwa): solved per value of that joint (redundancy.hpp);
//! - general:         no analytic method applies (the caller uses the numeric fallback).
//!
//! Every solver is built from the Paden–Kahan subproblems in product-of-exponentials form
//! (no DH conversion). A candidate whose subproblems are all well inside their solvable range,
//! on a chain whose axes fit its family to rounding, is exact to rounding and kept as it is
//! (doc/inverse-kinematics.md (eq. 26)); every other one ends with a Newton polish on the full
//! pose and a check by forward kinematics. A returned solution reproduces the pose to
//! ik_pose_tolerance.
//!
//! Singular poses, where a joint is free, return a representative set (never an empty one):
//! - spherical wrist, axes 4 and 6 aligned (q₅ = 0): q₄ = 0 and q₆ takes the whole turn;
//! - spherical wrist, wrist centre on axis 1: q₁ = 0;
//! - three parallel, axes 2, 3, 4, 6 parallel (UR, q₅ = 0): the q₆ (two of them) that puts the
//!   elbow mid-way in its reachable range, q₂…q₄ solved for it.
//! Near a singularity the joints it couples are determined only to ≈ 1e-16 / |sin q₅| rad.
//! Within ~1e-6 rad of the UR wrist singularity, if the closed form's candidates do not polish
//! to 1e-10, the offset-wrist search (which fits the UR layout) is run as a fallback.
#pragma once

#include <array>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "dispkin/pose.hpp"
#include "dispkin/serial/revolute_chain.hpp"

namespace dispkin {
namespace serial {

//! The analytic families of 6R chains (see the file's comment); general: none applies;
//! locked_joint: a seven-joint chain with one end joint locked at a value (its redundancy,
//! doc/inverse-kinematics.md §11), whose six other joints are one of the families above.
enum class IkFamily { spherical_wrist, three_parallel, offset_wrist, general, locked_joint };

//! Every returned solution reproduces the pose to this: position error (m) and rotation
//! error (rad) both ≤ 1e-10.
constexpr double ik_pose_tolerance = 1e-10;

//! Two solutions whose joints all agree to this (rad, modulo 2π) are one solution.
constexpr double ik_duplicate_tolerance = 1e-7;

//! Up to eight solutions without heap allocation (the closed-form families have at most 8).
struct IkSolutionSet {
  std::array<Eigen::Matrix<double, 6, 1>, 8> q;  //!< q[0 .. count−1], each joint in (−π, π]
  //! The pose error of q[i] as the solver measured it (the larger of position, m, and rotation,
  //! rad; ≤ ik_pose_tolerance); 0 for a candidate exact to rounding, which is not measured
  //! (doc/inverse-kinematics.md (eq. 26)).
  std::array<double, 8> error{};
  int count = 0;  //!< number of solutions held

  int size() const noexcept { return count; }  //!< the number of solutions held
  //! Solution i, 0 ≤ i < size().
  const Eigen::Matrix<double, 6, 1>& operator[](int i) const noexcept { return q[static_cast<std::size_t>(i)]; }
  //! Appends q with its measured error (ignored when the set is full: a 6R closed form never has
  //! a ninth).
  void push(const Eigen::Matrix<double, 6, 1>& solution, double measured_error = 0.0) noexcept {
    if (count < 8) {
      error[static_cast<std::size_t>(count)] = measured_error;
      q[static_cast<std::size_t>(count++)] = solution;
    }
  }
};

//! "spherical_wrist", "three_parallel", "offset_wrist", "general", "locked_joint".
std::string to_string(IkFamily family);

//! The family of `chain`, from its axes (geometric tolerance `tolerance`, metres / radians).
IkFamily recognise(const RevoluteChain& chain, double tolerance = 1e-9);

//! Every joint vector q (each component in (−π, π]) with forward(chain, q) = pose to ≤ 1e-10,
//! by the closed form or search of `family`. No joint limits are applied here. Throws
//! std::invalid_argument if the family does not fit the chain or is `general` or `locked_joint`
//! (which needs a value of the locked joint: locked_joint_inverse in redundancy.hpp).
std::vector<Eigen::VectorXd> analytic_inverse(const RevoluteChain& chain, IkFamily family, const Posed& pose);

//! The closed forms (spherical_wrist, three_parallel) without heap allocation: the solutions
//! are written into `out` (its previous content is discarded). For the real-time path; the
//! same checks and results as analytic_inverse. (Exception: the near-singular UR fallback
//! above allocates its search table.) Throws std::invalid_argument for another
//! family or a chain that does not fit (only then does it allocate, for the message).
void analytic_inverse(const RevoluteChain& chain, IkFamily family, const Posed& pose, IkSolutionSet& out);

//! Settings of the offset-wrist search (doc/inverse-kinematics.md §7).
struct OffsetWristOptions {
  //! Samples of the circle parameter q₆ over one turn (≥ 16), besides one in every gap or
  //! island of the positioning stage that they would miss (its ends are found exactly where
  //! they are roots of a trigonometric polynomial in q₆). Between samples the search follows
  //! branch ends, gaps and islands and narrow root pairs (doc/inverse-kinematics.md §7); 180 recovered the
  //! original q in all of 10⁷ random round trips on the Jaco2, 120, 90 and 60 in all of 10⁵
  //! (doc/inverse-kinematics.md §7).
  int samples = 180;
};

//! The offset-wrist search with explicit settings (analytic_inverse uses the defaults).
std::vector<Eigen::VectorXd> offset_wrist_inverse(const RevoluteChain& chain, const Posed& pose,
                                                  const OffsetWristOptions& options);

}  // namespace serial
}  // namespace dispkin
