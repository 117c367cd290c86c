// θ(s) of a seven-joint arm along a planned path (redundancy_schedule.hpp): the rule of
// doc/inverse-kinematics.md eq. 45 taken per unit of path, integrated node by node by Heun's
// method (doc/inverse-kinematics.md eq. 49) and interpolated by Hermite pieces (eq. 50).
#include "redundancy_schedule.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "cubic_hermite.hpp"
#include "joint_following.hpp"
#include "redundancy_rule.hpp"

namespace dispkin::serial::detail {

namespace {

// θ′ of doc/inverse-kinematics.md eq. 49 at τ of section k with the parameter at θ: q (in, the
// previous joints; out, the solution at θ on their branch), the joints' travel per unit of path at
// a held θ (doc/inverse-kinematics.md eq. 42), the rule's rate per unit of that travel
// (doc/inverse-kinematics.md eq. 45).
double rule_slope(const SampledPath& path, const SerialArm& arm, const RedundancyRule& rule, std::size_t k, double tau,
                  Eigen::VectorXd& q, double theta) {
  constexpr double no_time = std::numeric_limits<double>::quiet_NaN();
  const double length = path.section_lengths()[k], s = path.section_start(k) + tau * length;
  Posed pose;
  Twistd per_tau;
  path.section_state_at(k, tau, pose, per_tau);
  Eigen::VectorXd reference = q;
  reference(arm.redundancy().joint) = theta;
  q = branch_solution(arm, pose, reference, no_time, s);
  const Eigen::VectorXd held = joint_velocity(arm, q, per_tau, no_time, s) / length;
  return parameter_step(arm, q, held.norm(), rule);
}

}  // namespace

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
  const double direction = backwards ? -1.0 : 1.0;
  Eigen::VectorXd q = q_given;
  double theta = q_given(joint_), slope = 0.0;  // slope: dθ per unit of path in the direction run
  for (std::size_t done = 0; done < count; ++done) {
    const std::size_t k = backwards ? count - 1 - done : done;
    const SectionNodes& section = sections_[k];
    const double h = section.length / section.intervals;  // in s
    const auto node = [&](int m) {
      return section.first + static_cast<std::size_t>(backwards ? section.intervals - m : m);
    };
    // The section's first node: q at θ on the branch of the previous one (of q_given at the
    // path's first), the slope with this section's twist.
    slope = rule_slope(path, arm, rule, k, backwards ? 1.0 : 0.0, q, theta);
    for (int m = 0;; ++m) {
      value_[node(m)] = theta;
      rate_[node(m)] = direction * slope;
      if (m == section.intervals) break;
      // Heun's step of doc/inverse-kinematics.md eq. 49: the slope at the node ahead reached by
      // Euler's, then the mean of both. The values then agree with the Hermite pieces' end slopes
      // (Δθ = h (θ′_i + θ′_{i+1}) / 2), so each piece of doc/inverse-kinematics.md eq. 50
      // is a parabola.
      const double tau = static_cast<double>(backwards ? section.intervals - m - 1 : m + 1) / section.intervals;
      const double ahead = std::clamp(theta + h * slope, redundancy.lower, redundancy.upper);
      const double slope_ahead = rule_slope(path, arm, rule, k, tau, q, ahead);
      const double next = std::clamp(theta + 0.5 * h * (slope + slope_ahead), redundancy.lower, redundancy.upper);
      if (next == redundancy.lower || next == redundancy.upper) {
        // Onto an end of the range: the piece from slope Δ/h to 0 is monotone, so θ does not
        // pass the end between the nodes either.
        rate_[node(m)] = direction * (next - theta) / h;
        slope = 0.0;
      } else {
        slope = slope_ahead;
      }
      theta = next;
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

void RedundancySchedule::piece_at(double s, std::size_t& k, int& i) const noexcept {
  const auto after = std::upper_bound(sections_.begin(), sections_.end(), s,
                                      [](double x, const SectionNodes& n) { return x < n.start; });
  k = after == sections_.begin() ? 0 : static_cast<std::size_t>(after - sections_.begin()) - 1;
  const SectionNodes& section = sections_[k];
  const double x = std::clamp((s - section.start) / section.length, 0.0, 1.0) * section.intervals;
  i = std::min(static_cast<int>(x), section.intervals - 1);
}

void RedundancySchedule::curvature_range(double s0, double s1, double& low, double& high) const noexcept {
  low = std::numeric_limits<double>::infinity();
  high = -low;
  std::size_t k0, k1;
  int i0, i1;
  piece_at(s0, k0, i0);
  piece_at(s1, k1, i1);
  for (std::size_t k = k0; k <= k1; ++k) {
    const SectionNodes& section = sections_[k];
    const double h = section.length / section.intervals;
    for (int i = k == k0 ? i0 : 0; i <= (k == k1 ? i1 : section.intervals - 1); ++i) {
      const std::size_t a = section.first + static_cast<std::size_t>(i), b = a + 1;
      // θ″ is linear on a piece (constant on Heun's parabolas): its ends bound it.
      for (const double x : {0.0, 1.0}) {
        const double c = Hermite{x, h}.curvature(value_[a], rate_[a], value_[b], rate_[b]);
        low = std::min(low, c);
        high = std::max(high, c);
      }
    }
  }
}

Eigen::VectorXd RedundancySchedule::reference(const Eigen::VectorXd& q, double theta) const {
  Eigen::VectorXd out = q;
  out(joint_) = theta;
  return out;
}

}  // namespace dispkin::serial::detail
