// θ(s) of a seven-joint arm along a planned path (redundancy_schedule.hpp): the rule of
// doc/inverse-kinematics.md eq. 45 taken per unit of path, integrated node by node (eq. 49) and
// interpolated by cubic Hermite polynomials (eq. 50).
#include "redundancy_schedule.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "cubic_hermite.hpp"
#include "joint_following.hpp"
#include "redundancy_rule.hpp"

namespace dispkin::serial::detail {

RedundancySchedule::RedundancySchedule(const SampledPath& path, const SerialArm& arm, const Eigen::VectorXd& q_given,
                                       bool backwards, double spacing, const RedundancyRule& rule) {
  const Redundancy& redundancy = arm.redundancy();
  if (!rule.move || !redundancy.has_parameter()) return;
  joint_ = redundancy.joint;
  const std::size_t count = path.section_count();
  sections_.resize(count);
  std::size_t total = 0;
  for (std::size_t k = 0; k < count; ++k) {
    const double length = path.section_lengths()[k];
    const int n = std::max(1, static_cast<int>(std::min(std::ceil(length / spacing), 1e6)));
    sections_[k] = {path.section_start(k), length, total, n};
    total += static_cast<std::size_t>(n) + 1;
  }
  value_.resize(total);
  rate_.resize(total);
  constexpr double no_time = std::numeric_limits<double>::quiet_NaN();
  const double direction = backwards ? -1.0 : 1.0;
  Eigen::VectorXd q = q_given;
  double theta = q_given(joint_);
  for (std::size_t done = 0; done < count; ++done) {
    const std::size_t k = backwards ? count - 1 - done : done;
    const SectionNodes& section = sections_[k];
    const double h = section.length / section.intervals;  // in s
    for (int m = 0; m <= section.intervals; ++m) {
      const int i = backwards ? section.intervals - m : m;
      const double tau = static_cast<double>(i) / section.intervals;
      const double s = section.start + tau * section.length;
      Posed pose;
      Twistd per_tau;
      path.section_state_at(k, tau, pose, per_tau);
      // q at θ on the branch of the previous node (of q_given at the first).
      q = branch_solution(arm, pose, reference(q, theta), no_time, s);
      // The joints' travel per unit of path at a held θ (doc/inverse-kinematics.md eq. 42), and θ's
      // rate per unit of that travel in the direction the path is run (doc/inverse-kinematics.md eq. 49).
      const Eigen::VectorXd held = joint_velocity(arm, q, per_tau, no_time, s) / section.length;
      double slope = parameter_step(arm, q, held.norm(), rule);
      // θ stays in its range: the last step onto an end is shortened (a Hermite piece from a
      // slope Δ/h to 0 is monotone, so θ never overshoots between the nodes either).
      const double next = std::clamp(theta + slope * h, redundancy.lower, redundancy.upper);
      if (m < section.intervals) slope = (next - theta) / h;
      const std::size_t node = section.first + static_cast<std::size_t>(i);
      value_[node] = theta;
      rate_[node] = direction * slope;
      if (m < section.intervals) theta = next;
    }
  }
}

RedundancySchedule::State RedundancySchedule::at(std::size_t k, double tau) const noexcept {
  const SectionNodes& section = sections_[std::min(k, sections_.size() - 1)];
  const double x = std::clamp(tau, 0.0, 1.0) * section.intervals;
  const int i = std::min(static_cast<int>(x), section.intervals - 1);
  const double h = section.length / section.intervals;
  const Hermite piece{x - i, h};
  const std::size_t a = section.first + static_cast<std::size_t>(i), b = a + 1;
  // Per unit τ of the piece: Hermite's span h is in s, so its derivatives are per unit s.
  return {piece.value(value_[a], rate_[a], value_[b], rate_[b]), piece.rate(value_[a], rate_[a], value_[b], rate_[b]),
          piece.curvature(value_[a], rate_[a], value_[b], rate_[b])};
}

RedundancySchedule::State RedundancySchedule::at(double s) const noexcept {
  const auto after = std::upper_bound(sections_.begin(), sections_.end(), s,
                                      [](double x, const SectionNodes& n) { return x < n.start; });
  const std::size_t k = after == sections_.begin() ? 0 : static_cast<std::size_t>(after - sections_.begin()) - 1;
  const SectionNodes& section = sections_[k];
  return at(k, (s - section.start) / section.length);
}

Eigen::VectorXd RedundancySchedule::reference(const Eigen::VectorXd& q, double theta) const {
  Eigen::VectorXd out = q;
  out(joint_) = theta;
  return out;
}

}  // namespace dispkin::serial::detail
