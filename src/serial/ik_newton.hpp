// Newton's method on the full pose error of a revolute chain (doc/inverse-kinematics.md (eq. 22)
// and (doc/inverse-kinematics.md eq. 23)): the one refinement of an inverse-kinematics solution in the serial plugin.
// The analytic solvers finish every candidate with it, the numeric fallback brings its roots down to rounding with it,
// and following a trajectory's branch tracks the next pose with it.
#pragma once

#include <limits>

#include "dispkin/pose.hpp"
#include "dispkin/serial/revolute_chain.hpp"

namespace dispkin {
namespace serial {
namespace detail {

//! Position error (m) and rotation error (rad) of a tool pose against a target.
struct PoseError {
  double position = 0.0;
  double rotation = 0.0;
  double worst() const noexcept { return position > rotation ? position : rotation; }
};

//! The error of `pose` against `target`: ‖t − t_target‖ and the angle of R_targetᵀ R.
PoseError pose_error(const Posed& pose, const Posed& target) noexcept;

//! How Newton's method steps and when it stops.
struct NewtonSettings {
  //! Done when the error's worst() is at most this.
  double tolerance = 1e-15;
  //! At most this many steps.
  int max_iterations = 30;
  //! A step that moves some joint by more than this (rad) ends the search: the iterate is
  //! leaving the neighbourhood of the start, where another branch may be reached.
  double largest_step = std::numeric_limits<double>::infinity();
  //! Square J: above this ratio of the smallest to the largest pivot of its LU the step is
  //! J⁻¹ e (doc/inverse-kinematics.md eq. 23). The ratio is a cheap stand-in for the reciprocal condition number.
  double well_conditioned = 1e-5;
  //! Below it (and for a J that is not square, always) the step is the minimum-norm least-
  //! squares one J⁺ e, which leaves a free combination of joints alone at a singular q; false:
  //! a square J below it ends the search instead.
  bool minimum_norm_when_singular = true;
  //! Joints brought into (−π, π] after every step.
  bool wrap = false;
};

//! Refines q (chain.dof() values, at most max_newton_joints without allocating) towards a
//! solution of T(q) = target. The iterate with the smallest error is kept in q; the search
//! stops at the tolerance, after max_iterations, at a step that is not finite or too large, at
//! a singular J that may not take the minimum-norm step, or at the first step after the first
//! that brings no progress (rounding reached, or no solution near). Returns q's error.
PoseError refine_pose(const RevoluteChain& chain, const Posed& target, double* q,
                      const NewtonSettings& settings) noexcept;

//! Chains up to this many joints are refined in fixed-size storage.
constexpr int max_newton_joints = 12;

}  // namespace detail
}  // namespace serial
}  // namespace dispkin
