// The inverse-kinematics branch followed from pose to pose (branch_following.hpp): Newton
// tracking first, the nearest of all solutions where tracking is not trusted; and serial::follow.
#include "branch_following.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "angles.hpp"
#include "dispkin/error.hpp"
#include "ik_newton.hpp"
#include "redundancy_rule.hpp"
#include "serial_arm_model.hpp"

namespace dispkin {
namespace serial {
namespace detail {
namespace {

// Tracking: converged at this pose error (m, rad); trusted within this distance (rad, every joint)
// of the reference, a fraction of the distance between two solutions of a 6R arm away from
// singular poses.
constexpr double tracking_tolerance = 1e-13;
constexpr double tracking_reach = 0.3;

// q (a solution) in the form `rule` gives its candidates, nearest to q_ref. False when that form
// is not a candidate (outside the limits while they are required).
// q moved by whole turns, joint by joint, to the copy nearest q_ref (the nearest-turn rule's form).
void nearest_turns(Eigen::VectorXd& q, const Eigen::VectorXd& q_ref) {
  for (Eigen::Index i = 0; i < q.size(); ++i) q(i) += two_pi * std::round((q_ref(i) - q(i)) / two_pi);
}

bool in_rule_form(Eigen::VectorXd& q, const Eigen::VectorXd& q_ref, const JointLimits& limits, const BranchRule& rule) {
  if (rule.turns == Turns::nearest) {
    nearest_turns(q, q_ref);
    return true;
  }
  const bool inside = into_limits(q, limits);
  if (!inside && !rule.options.keep_outside_limits) return false;
  if (!inside || !rule.options.offer_equivalents) return true;
  // The 2π copies of joint i inside the limits are q(i) + 2πk, k_lo ≤ k ≤ k_hi: the nearest to
  // q_ref(i) has the k nearest (q_ref(i) − q(i)) / 2π, in closed form however wide the limits.
  for (Eigen::Index i = 0; i < q.size(); ++i) {
    if (!std::isfinite(limits.lower(i)) || !std::isfinite(limits.upper(i))) continue;
    const double k_lo = std::ceil((limits.lower(i) - limit_slack - q(i)) / two_pi);
    const double k_hi = std::floor((limits.upper(i) + limit_slack - q(i)) / two_pi);
    const double k = std::min(std::max(std::round((q_ref(i) - q(i)) / two_pi), k_lo), k_hi);
    q(i) += two_pi * k;
  }
  return true;
}

// Newton's method from `start`: the solution of q_ref's branch, in the rule's form, or empty.
std::optional<Eigen::VectorXd> tracked(const SerialArm& arm, const Posed& pose, const Eigen::VectorXd& q_ref,
                                       const BranchRule& rule, const Eigen::VectorXd& start) {
  NewtonSettings settings;
  settings.tolerance = tracking_tolerance;
  settings.max_iterations = 6;
  settings.largest_step = tracking_reach;
  settings.well_conditioned = 1e-9;
  settings.minimum_norm_when_singular = false;  // a free combination of joints: not one branch
  Eigen::VectorXd q = start;
  if (!(refine_pose(arm.chain(), pose, q.data(), settings).worst() <= tracking_tolerance)) return std::nullopt;
  // The nearest-turn rule needs no limits: spare the copy arm.joint_limits() makes on every tracked pose.
  if (rule.turns == Turns::nearest) {
    nearest_turns(q, q_ref);
  } else if (!in_rule_form(q, q_ref, arm.joint_limits(), rule)) {
    return std::nullopt;
  }
  if (!((q - q_ref).lpNorm<Eigen::Infinity>() <= tracking_reach)) return std::nullopt;
  return q;
}

}  // namespace

std::optional<Eigen::VectorXd> solution_on_branch(const SerialArm& arm, const Posed& pose, const Eigen::VectorXd& q_ref,
                                                  const BranchRule& rule, const Eigen::VectorXd* guess) {
  // Tracking needs a square Jacobian: a redundant arm's solutions form a continuum (the nearest
  // of the search's samples is what is asked for), a short arm's pose equations are overdetermined.
  if (arm.dof() == 6) {
    if (std::optional<Eigen::VectorXd> q = tracked(arm, pose, q_ref, rule, guess ? *guess : q_ref)) return q;
  }
  // The distinct solutions; their 2π copies are the rule's, placed by in_rule_form below.
  InverseOptions options = rule.options;
  options.offer_equivalents = false;
  // A redundant arm with a parameter stays at q_ref's value unless the rule fixes one
  // (doc/inverse-kinematics.md (eq. 41)): all its solutions there, in closed form.
  if (arm.redundancy().has_parameter() && !options.redundancy) options.redundancy = q_ref(arm.redundancy().joint);
  // Without one (family general), Newton's method from q_ref first, the search where it fails
  // (doc/inverse-kinematics.md (eq. 46)).
  if (arm.family() == IkFamily::general && !options.redundancy) options.q_ref = q_ref;
  const std::vector<Eigen::VectorXd> solutions = arm.inverse_solutions(pose, options).solutions;
  if (solutions.empty()) return std::nullopt;
  const JointLimits limits = arm.joint_limits();
  Eigen::VectorXd best;
  double best_distance = std::numeric_limits<double>::infinity();
  for (Eigen::VectorXd q : solutions) {
    in_rule_form(q, q_ref, limits, rule);
    const double distance = (q - q_ref).norm();
    if (distance < best_distance) {
      best_distance = distance;
      best = q;
    }
  }
  return best;
}

}  // namespace detail

namespace {

// The argument follow() names in its errors: the translation of pose k.
std::string pose_named(std::size_t k) { return "poses[" + std::to_string(k) + "] translation"; }

}  // namespace

std::vector<Eigen::VectorXd> follow(const SerialArm& arm, const std::vector<Posed>& poses,
                                    const Eigen::VectorXd& q_start, const InverseOptions& options,
                                    const RedundancyRule& redundancy_rule) {
  if (q_start.size() != arm.dof())
    throw std::invalid_argument(
        describe("q_start", q_start,
                 "expected " + std::to_string(arm.dof()) + " joint values, got " + std::to_string(q_start.size())));
  require_finite(q_start, "q_start");
  // inverse_solutions' own checks, which tracking would skip.
  require(options.max_attempts > 0, "max_attempts", options.max_attempts, "must be greater than zero");
  require_positive(options.time_budget, "time_budget");
  detail::require_valid(redundancy_rule);
  // A branch turns on through the joints' whole range: the 2π copies inside the limits are
  // candidates whatever offer_equivalents says (found in closed form, not enumerated).
  detail::BranchRule rule{options, detail::Turns::listed};
  rule.options.offer_equivalents = true;
  // A redundant arm starts at q_start's parameter value, moves it by the rule of
  // doc/inverse-kinematics.md (eq. 45) and never jumps (eq. 41).
  const Redundancy& redundancy = arm.redundancy();
  if (redundancy.has_parameter()) rule.options.redundancy = q_start(redundancy.joint);
  std::vector<Eigen::VectorXd> path;
  path.reserve(poses.size());
  Eigen::VectorXd previous = q_start;
  for (std::size_t k = 0; k < poses.size(); ++k) {
    std::optional<Eigen::VectorXd> q = detail::solution_on_branch(arm, poses[k], previous, rule);
    if (!q)
      throw std::runtime_error(
          describe(pose_named(k), poses[k].translation(),
                   "has no inverse-kinematics solution within the joint limits" +
                       std::string(redundancy.has_parameter() ? " at the redundancy value reached" : "")));
    if (redundancy.has_parameter()) {
      // The step of doc/inverse-kinematics.md eq. 45 from the solution at the previous value; kept only where the
      // branch goes on at the new value within the joint limits (else the value stays: doc/inverse-kinematics.md eq.
      // 41).
      const double delta = detail::parameter_step(arm, *q, (*q - previous).norm(), redundancy_rule);
      const double moved = std::clamp(*rule.options.redundancy + delta, redundancy.lower, redundancy.upper);
      if (moved != *rule.options.redundancy) {
        detail::BranchRule there = rule;
        there.options.redundancy = moved;
        if (std::optional<Eigen::VectorXd> q_moved = detail::solution_on_branch(arm, poses[k], *q, there)) {
          if ((*q_moved - previous).lpNorm<Eigen::Infinity>() <= max_redundant_step) {
            q = std::move(q_moved);
            rule.options.redundancy = moved;
          }
        }
      }
      const double step = (*q - previous).lpNorm<Eigen::Infinity>();
      if (!(step <= max_redundant_step))
        throw std::runtime_error(
            describe(pose_named(k), poses[k].translation(),
                     "is reached at the redundancy value reached only by a joint step of " + std::to_string(step) +
                         " rad, more than " + std::to_string(max_redundant_step) +
                         " (the branch ends there, or the poses are too far apart: sample the path more densely)"));
    }
    previous = std::move(*q);
    path.push_back(previous);
  }
  return path;
}

}  // namespace serial
}  // namespace dispkin
