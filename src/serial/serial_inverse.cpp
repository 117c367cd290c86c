// SerialArm inverse kinematics: the analytic family when there is one, else a numeric search
// with KDL's Levenberg–Marquardt solver from random starts; then joint limits, 2π-equivalent
// values, verification by forward kinematics, and the choice among solutions.
#include <chrono>
#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include <Eigen/Geometry>
#include <kdl/chainiksolverpos_lma.hpp>
#include <kdl/jntarray.hpp>

#include "angles.hpp"
#include "dispkin/error.hpp"
#include "dispkin/serial/serial_arm.hpp"
#include "ik_newton.hpp"
#include "serial_arm_model.hpp"

namespace dispkin {
namespace serial {
namespace {

using detail::pi;
using detail::two_pi;

// Joint values this close count as one solution; numeric restarts land on the same root with
// differences of the order of their convergence tolerance.
constexpr double duplicate_tolerance = 1e-7;
// q into (−π, π].
double wrap(double q) {
  double r = std::remainder(q, two_pi);  // in [−π, π]
  if (r <= -pi) r += two_pi;
  return r;
}

// The same solution up to 2π in any joint.
bool is_duplicate(const std::vector<Eigen::VectorXd>& found, const Eigen::VectorXd& q) {
  for (const Eigen::VectorXd& f : found) {
    bool same = true;
    for (Eigen::Index i = 0; i < q.size() && same; ++i) same = std::abs(std::remainder(f(i) - q(i), two_pi)) <= duplicate_tolerance;
    if (same) return true;
  }
  return false;
}

// Newton's method on the full pose error (refine_pose), bringing a root found to 1e-6 or so
// down to rounding (minimum-norm steps where J is not square, so that a redundant arm's root
// moves least, or near singular). Whether q then reproduces the pose to inverse_tolerance.
bool polish(const SerialArm& arm, const Posed& target, Eigen::VectorXd& q) {
  detail::NewtonSettings settings;
  settings.tolerance = 0.1 * inverse_tolerance;
  settings.max_iterations = 8;
  detail::refine_pose(arm.chain(), target, q.data(), settings);
  return q.allFinite() && arm.forward(q).is_approx(target, inverse_tolerance);
}

// Whether q reproduces the pose to inverse_tolerance by forward(), the promise of inverse_solutions.
bool reproduces(const SerialArm& arm, const Eigen::VectorXd& q, const Posed& pose) {
  return arm.forward(q).is_approx(pose, inverse_tolerance);
}

}  // namespace

bool into_limits(Eigen::VectorXd& q, const JointLimits& limits) noexcept {
  bool inside = true;
  for (Eigen::Index i = 0; i < q.size(); ++i) {
    const double lo = limits.lower(i);
    const double hi = limits.upper(i);
    if (!std::isfinite(lo) || !std::isfinite(hi)) {
      q(i) = wrap(q(i));
      continue;
    }
    const double shifted = q(i) - two_pi * std::floor((q(i) - lo + limit_slack) / two_pi);
    if (shifted <= hi + limit_slack) {
      q(i) = shifted;
    } else {
      q(i) = wrap(q(i));
      inside = false;
    }
  }
  return inside;
}

InverseResult SerialArm::inverse_solutions(const Posed& pose, const InverseOptions& options) const {
  {
    const Eigen::Quaterniond& r = pose.quaternion();
    require_finite(Eigen::Vector4d(r.w(), r.x(), r.y(), r.z()), "pose quaternion (w, x, y, z)");
    require_finite(pose.translation(), "pose translation");
  }
  require(options.max_attempts > 0, "max_attempts", options.max_attempts, "must be greater than zero");
  require_positive(options.time_budget, "time_budget");

  const JointLimits& limits = model_->limits;
  const int n = dof();
  InverseResult result;
  result.family = model_->family;

  std::vector<Eigen::VectorXd> raw;
  if (model_->family != IkFamily::general) {
    raw = analytic_inverse(model_->revolute, model_->family, pose);
    result.complete = true;
  } else {
    // Numeric fallback: restarts drawn uniformly inside the limits (continuous joints in
    // [−π, π]), until the attempts or the time budget run out.
    KDL::ChainIkSolverPos_LMA solver(model_->chain, 1e-12, 500, 1e-15);
    std::mt19937_64 generator(options.seed);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const KDL::Frame goal = to_frame(pose);
    const auto start = std::chrono::steady_clock::now();
    KDL::JntArray q_init(static_cast<unsigned>(n));
    KDL::JntArray q_out(static_cast<unsigned>(n));
    for (int attempt = 0; attempt < options.max_attempts; ++attempt) {
      const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      if (elapsed > options.time_budget) break;
      for (int i = 0; i < n; ++i) {
        const double lo = std::isfinite(limits.lower(i)) ? limits.lower(i) : -pi;
        const double hi = std::isfinite(limits.upper(i)) ? limits.upper(i) : pi;
        q_init(static_cast<unsigned>(i)) = lo + (hi - lo) * unit(generator);
      }
      solver.CartToJnt(q_init, goal, q_out);  // the return code says little; FK below decides
      Eigen::VectorXd q = q_out.data;
      if (!q.allFinite()) continue;
      if (!polish(*this, pose, q)) continue;
      raw.push_back(q);
    }
    result.complete = false;
  }

  std::vector<Eigen::VectorXd> representatives;
  for (Eigen::VectorXd q : raw) {
    if (q.size() != n || !q.allFinite()) continue;
    const bool inside = into_limits(q, limits);
    if (!inside && !options.keep_outside_limits) continue;
    // Every solution is checked by forward kinematics (reproduces); one that misses by a little
    // (an analytic root rounded, a 2π shift) gets Newton steps, one that misses by more is not a solution.
    if (!reproduces(*this, q, pose) && !polish(*this, pose, q)) continue;
    // Duplicates (equal up to 2π per joint) are looked for among these representatives only:
    // the copies of different representatives are then different too.
    if (is_duplicate(representatives, q)) continue;
    representatives.push_back(q);
    // The 2π-equivalent values inside the limits: every combination.
    std::vector<Eigen::VectorXd> variants{q};
    if (inside && options.offer_equivalents) {
      for (int i = 0; i < n; ++i) {
        if (!std::isfinite(limits.lower(i)) || !std::isfinite(limits.upper(i))) continue;
        const std::size_t count = variants.size();
        for (std::size_t v = 0; v < count; ++v) {
          for (double value = variants[v](i) + two_pi; value <= limits.upper(i) + limit_slack; value += two_pi) {
            Eigen::VectorXd other = variants[v];
            other(i) = value;
            variants.push_back(other);
          }
        }
      }
    }
    for (Eigen::VectorXd& candidate : variants) {
      if (&candidate != &variants.front() && !reproduces(*this, candidate, pose) && !polish(*this, pose, candidate))
        continue;
      result.solutions.push_back(candidate);
      result.within_limits.push_back(inside);
    }
  }
  return result;
}

std::vector<Eigen::VectorXd> SerialArm::inverse(const Posed& pose) const { return inverse_solutions(pose).solutions; }

Eigen::VectorXd nearest(const std::vector<Eigen::VectorXd>& solutions, const Eigen::VectorXd& q_ref) {
  require(!solutions.empty(), "solutions", static_cast<int>(solutions.size()), "must not be empty");
  require_finite(q_ref, "q_ref");
  std::size_t best = 0;
  double best_distance = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < solutions.size(); ++k) {
    if (solutions[k].size() != q_ref.size())
      throw std::invalid_argument(describe("q_ref", q_ref, "expected " + std::to_string(solutions[k].size()) +
                                                                " joint values like the solutions, got " +
                                                                std::to_string(q_ref.size())));
    const double d = (solutions[k] - q_ref).norm();
    if (d < best_distance) {
      best_distance = d;
      best = k;
    }
  }
  return solutions[best];
}

std::vector<Eigen::VectorXd> with_configuration(const SerialArm& arm, const std::vector<Eigen::VectorXd>& solutions,
                                                const Configuration& wanted) {
  std::vector<Eigen::VectorXd> out;
  for (const Eigen::VectorXd& q : solutions)
    if (arm.configuration(q) == wanted) out.push_back(q);
  return out;
}

}  // namespace serial
}  // namespace dispkin
