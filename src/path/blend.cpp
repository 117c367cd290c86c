// Blending at via points (doc/planning.md §6): the boundary smoothing of the Mamezou trajectory
// article (Ishii, "Algorithm 2 for Robot Manipulator Control", section "Smooth Position/Posture
// Trajectory Fitting Method"), with the orientation blended jointly with the position.
//
// The article fits a cubic F₀ between the sub-points Q₁, Q₂ with the neighbours' tangents, and
// blends the orientation separately by nested SLERP over its own zone (weight w ≈ 0.3). Under
// the DISP metric the planner sees one 6-D twist, and two separate zones would make its
// direction jump at each zone's ends (the planner would have to stop there). So here one zone
// serves both: the pivot follows the article's cubic, the orientation a cubic in the rotation
// vector whose end angular velocities are the neighbours', scaled by the same factors as the
// pivot tangents — at both joins the twist keeps its direction.
#include <algorithm>
#include <cmath>
#include <string>

#include <Eigen/LU>

#include "dispkin/path/path.hpp"
#include "path_geometry.hpp"

namespace dispkin {
namespace {

using detail::metres_per_radian;
using detail::section_part;

// World pivot velocity ċ = R (v_b + ω_b × p) of a body twist at `pose`.
Eigen::Vector3d pivot_velocity(const Posed& pose, const Twistd& body, const Eigen::Vector3d& pivot) {
  return pose.quaternion() * (body.linear + body.angular.cross(pivot));
}

Eigen::Vector3d pivot_of(const Section& section) {
  return std::visit([](const auto& s) { return s.pivot; }, section);
}

}  // namespace

Path& Path::then(const Path& next, double before, double after, double tolerance) {
  require(std::isfinite(before) && before > 0.0, "before", before, "must be a positive distance (m)");
  require(std::isfinite(after) && after > 0.0, "after", after, "must be a positive distance (m)");
  require(std::isfinite(tolerance) && tolerance > 0.0 && tolerance <= 0.1, "tolerance", tolerance, "must be in (0, 0.1]");
  require_joins(next);
  require(before <= 0.5 * last_move_size_ * (1.0 + 1e-12), "before", before,
          "exceeds half of the move before the via point (" + std::to_string(0.5 * last_move_size_) +
              " m of geometric size): shrink the blend");
  require(after <= 0.5 * next.first_move_size_ * (1.0 + 1e-12), "after", after,
          "exceeds half of the move after the via point (" + std::to_string(0.5 * next.first_move_size_) +
              " m of geometric size): shrink the blend");

  // Sub-point KP₁ at `before` ahead of the corner: cut the section holding it, drop the rest.
  const double total = cumulative_.back();
  std::size_t k = sections_.size() - 1;
  while (k > 0 && total - cumulative_[k - 1] < before) --k;
  const double k_begin = k == 0 ? 0.0 : cumulative_[k - 1];
  const double tau_in = std::clamp((total - before - k_begin) / (cumulative_[k] - k_begin), 0.0, 1.0);
  const Section incoming = section_part(sections_[k], 0.0, tau_in);
  sections_.resize(k);
  cumulative_.resize(k);
  if (tau_in > 0.0) append(incoming);

  // Sub-point KP₂ at `after` past the corner, in the first move of `next`.
  std::size_t j = 0;
  while (j + 1 < next.sections_.size() && next.cumulative_[j] < after) ++j;
  const double j_begin = j == 0 ? 0.0 : next.cumulative_[j - 1];
  const double tau_out = std::clamp((after - j_begin) / (next.cumulative_[j] - j_begin), 0.0, 1.0);
  const Section outgoing = section_part(next.sections_[j], tau_out, 1.0);

  // The joins: poses and velocities of the neighbours there (per unit of their own τ; only
  // their directions matter, the scale is set below).
  const Eigen::Vector3d pivot = pivot_of(incoming);
  const Posed a = section_pose(incoming, 1.0), b = section_pose(outgoing, 0.0);
  const Twistd twist_a = section_twist(incoming, 1.0), twist_b = section_twist(outgoing, 0.0);
  const Eigen::Vector3d c_dot_a = pivot_velocity(a, twist_a, pivot), c_dot_b = pivot_velocity(b, twist_b, pivot);
  const Eigen::Vector3d turn = quaternion_log(Eigen::Quaterniond(a.quaternion().conjugate() * b.quaternion()));

  // Tangent lengths equal to the geometric chord of the blend (the usual Hermite choice: no
  // loops, no flat spots), the same factor for the pivot and the rotation of each end.
  const double chord = ((b * pivot) - (a * pivot)).norm() + metres_per_radian * turn.norm();
  const double speed_a = c_dot_a.norm() + metres_per_radian * twist_a.angular.norm();
  const double speed_b = c_dot_b.norm() + metres_per_radian * twist_b.angular.norm();
  require(speed_a > 0.0 && speed_b > 0.0 && chord > 0.0, "blend", before,
          "meets a neighbour where it stands still: nothing to blend");
  const double scale_a = chord / speed_a, scale_b = chord / speed_b;
  const Cubic3 position = Cubic3::hermite(a * pivot, scale_a * c_dot_a, b * pivot, scale_b * c_dot_b);
  const Eigen::Vector3d end_slope = right_jacobian(turn).partialPivLu().solve(scale_b * twist_b.angular);
  const Cubic3 rotation = Cubic3::hermite(Eigen::Vector3d::Zero(), scale_a * twist_a.angular, turn, end_slope);
  cut_curve(a.quaternion(), position, rotation, pivot, tolerance);

  if (tau_out < 1.0) append(outgoing);
  for (std::size_t i = j + 1; i < next.sections_.size(); ++i) append(next.sections_[i]);
  last_move_size_ = next.last_move_size_;
  return *this;
}

}  // namespace dispkin
