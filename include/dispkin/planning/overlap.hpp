//! The overlapped velocity method of the Mamezou trajectory article (Ishii, "Algorithm 2 for Robot
//! Manipulator Control", section "Overlapped Velocity Method"; doc/planning.md §7): the next move
//! starts t_ov before the previous one ends, and during the overlap the two motions add up —
//! position P(t) = P_b(t) + P_f(t′) − P₂, orientation R(t) = R_f(t′) R₂⁻¹ R_b(t), with t′ the next
//! move's own time and (P₂, R₂) the via pose where one ends and the other starts.
//!
//! P is the position of the body point `pivot` (the article's tool tip; the origin by default).
//! The velocities add: ċ = ċ_b + ċ_f, ω = ω_f + R_f R₂⁻¹ ω_b (world). Overlapping the previous
//! move's deceleration with the next one's acceleration lets the path run through the via
//! point without stopping. Unlike plan(), this composition carries no speed guarantee of its
//! own: with mirrored ramps the path speeds add up to at most the cruise speed, but a point's
//! speed is the norm of a sum of two velocities — check it (peak_speed_ratio in the tests and
//! plots) before using large overlaps.
#pragma once

#include <Eigen/Core>

#include "dispkin/planning/planner.hpp"

namespace dispkin {

//! Two Cartesian moves run with an overlap t_ov: during it their motions add up (doc/planning.md
//! §7). No speed guarantee of its own: see the file's comment.
class OverlappedTrajectory {
 public:
  //! `before` must end where `after` starts (to 1e-9 m / 1e-9 rad); 0 ≤ overlap ≤ the shorter
  //! duration. Throws std::invalid_argument otherwise.
  OverlappedTrajectory(Trajectory before, Trajectory after, double overlap,
                       const Eigen::Vector3d& pivot = Eigen::Vector3d::Zero());

  //! The whole motion's duration: both moves' less the overlap (s).
  double duration() const noexcept { return before_.duration() + after_.duration() - overlap_; }
  //! When the overlap begins (the next move starts), seconds.
  double overlap_start() const noexcept { return before_.duration() - overlap_; }
  //! t_ov, the time both moves run at once (s).
  double overlap() const noexcept { return overlap_; }

  //! Pose and body twist at t (clamped to [0, duration]); s and ṡ, s̈ are the sums of both
  //! moves' (the DISP path position and speed bounds add). noexcept, allocation-free.
  TrajectorySample sample(double t) const noexcept;

 private:
  Trajectory before_, after_;
  double overlap_;
  Eigen::Vector3d pivot_;
  Posed via_;                  // (P₂, R₂) as a pose
  Eigen::Vector3d via_point_;  // P₂ = the pivot's position at the via pose
};

}  // namespace dispkin
