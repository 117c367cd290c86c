// SerialArm inverse kinematics: the analytic family when there is one, else a numeric search
// with KDL's Levenberg–Marquardt solver from random starts; then joint limits, 2π-equivalent
// values, verification by forward kinematics, and the choice among solutions.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <Eigen/Geometry>
#include <kdl/chainiksolverpos_lma.hpp>
#include <kdl/jntarray.hpp>

#include "angles.hpp"
#include "dispkin/error.hpp"
#include "dispkin/input_budget.hpp"
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
constexpr double duplicate_tolerance = ik_duplicate_tolerance;
// The numeric search's Levenberg–Marquardt iterations per start: lma_runs runs of lma_run_length.
constexpr int lma_run_length = 25;
constexpr int lma_runs = 20;
// The same solution up to 2π in any joint.
template <typename Vector>
bool is_duplicate(const std::vector<Eigen::VectorXd>& found, const Eigen::MatrixBase<Vector>& q) {
  for (const Eigen::VectorXd& f : found) {
    bool same = true;
    for (Eigen::Index i = 0; i < q.size() && same; ++i)
      same = std::abs(detail::wrap_angle(f(i) - q(i))) <= duplicate_tolerance;
    if (same) return true;
  }
  return false;
}

// An analytic solution whose measured pose error is at most this (a tenth of inverse_tolerance,
// so far below it that the FK check's own rounding cannot matter) and whose joints into_limits
// left as they were already reproduces the pose to inverse_tolerance: forward() would only
// repeat the solver's check (is_approx compares entries, each at most the position error or
// the rotation angle).
constexpr double checked_by_solver = 0.1 * inverse_tolerance;

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

// Newton's method on the full pose error from a start q near a solution (doc/inverse-kinematics.md eq. 46):
// minimum-norm steps, so a redundant arm lands on the solution of its continuum nearest the start (to first order),
// none longer than half a radian in any joint (a start farther away is not "near"). Whether q then reproduces the pose
// to inverse_tolerance.
bool polish_from(const SerialArm& arm, const Posed& target, Eigen::VectorXd& q) {
  detail::NewtonSettings settings;
  settings.tolerance = 0.1 * inverse_tolerance;
  settings.max_iterations = 20;
  settings.largest_step = 0.5;
  settings.well_conditioned = 1.0;  // every step minimum-norm: square or not, singular or not
  detail::refine_pose(arm.chain(), target, q.data(), settings);
  return q.allFinite() && arm.forward(q).is_approx(target, inverse_tolerance);
}

// Whether q reproduces the pose to inverse_tolerance by forward(), the promise of inverse_solutions.
bool reproduces(const SerialArm& arm, const Eigen::VectorXd& q, const Posed& pose) {
  return arm.forward(q).is_approx(pose, inverse_tolerance);
}

}  // namespace

bool into_limits(Eigen::Ref<Eigen::VectorXd> q, const JointLimits& limits) noexcept {
  bool inside = true;
  for (Eigen::Index i = 0; i < q.size(); ++i) {
    const double w = detail::wrap_angle(q(i));  // exact: ±1e16 rad keeps every digit below
    const double lo = limits.lower(i);
    const double hi = limits.upper(i);
    if (!std::isfinite(lo) || !std::isfinite(hi) || (lo - limit_slack <= w && w <= hi + limit_slack)) {
      q(i) = w;  // no limits, or w itself inside them: k = 0 below
      continue;
    }
    // The copies w + 2πk inside the limits are k_lo ≤ k ≤ k_hi; the one nearest 0 has the k
    // nearest 0 (|w| ≤ π). Computed from w, never by stepping through the range, and never
    // from the limits' end, so ±1e16 rad keeps every digit of the angle.
    const double k_lo = std::ceil((lo - limit_slack - w) / two_pi);
    const double k_hi = std::floor((hi + limit_slack - w) / two_pi);
    if (k_lo > k_hi) {
      q(i) = w;
      inside = false;
      continue;
    }
    q(i) = w + two_pi * std::min(std::max(0.0, k_lo), k_hi);
  }
  return inside;
}

namespace {

// The whole turns k that keep q + 2πk inside [lo, hi] (with limit_slack): [first, last], k = 0
// among them when q is inside; {0, 0} for a joint without limits.
struct TurnRange {
  double first = 0.0, last = 0.0;
  double count() const { return last - first + 1.0; }
};

TurnRange turns_within(double q, double lo, double hi) {
  if (!std::isfinite(lo) || !std::isfinite(hi)) return {};
  return {std::ceil((lo - limit_slack - q) / two_pi), std::floor((hi + limit_slack - q) / two_pi)};
}

// Every 2π copy of q inside the limits, q first: the product of the joints' turn ranges.
std::vector<Eigen::VectorXd> copies_within(const Eigen::VectorXd& q, const JointLimits& limits) {
  std::vector<Eigen::VectorXd> variants{q};
  for (Eigen::Index i = 0; i < q.size(); ++i) {
    const TurnRange turns = turns_within(q(i), limits.lower(i), limits.upper(i));
    const std::size_t count = variants.size();
    for (double k = turns.first; k <= turns.last; ++k) {
      if (k == 0.0) continue;
      for (std::size_t v = 0; v < count; ++v) {
        Eigen::VectorXd other = variants[v];
        other(i) = q(i) + two_pi * k;
        variants.push_back(std::move(other));
      }
    }
  }
  return variants;
}

// How many solutions the copies of `representatives` are, counted before any is made (a
// double: ±100 rad on six joints make 10¹⁰ per solution). One outside the limits has none.
double copy_count(const std::vector<Eigen::VectorXd>& representatives, const std::vector<bool>& inside,
                  const JointLimits& limits) {
  double total = 0.0;
  for (std::size_t r = 0; r < representatives.size(); ++r) {
    const Eigen::VectorXd& q = representatives[r];
    double product = 1.0;
    for (Eigen::Index i = 0; inside[r] && i < q.size(); ++i)
      product *= turns_within(q(i), limits.lower(i), limits.upper(i)).count();
    total += product;
  }
  return total;
}

// KDL's Levenberg–Marquardt solver from q_init, its 500 iterations run in runs of 25 so that the
// time budget is looked at between them (one run of 500 on a 10⁴-joint chain takes seconds).
// False when the deadline passed first.
bool solve_before(KDL::ChainIkSolverPos_LMA& solver, const KDL::Frame& goal, KDL::JntArray& q_init,
                  KDL::JntArray& q_out, std::chrono::steady_clock::time_point deadline) {
  for (int run = 0; run < lma_runs; ++run) {
    if (std::chrono::steady_clock::now() > deadline) return false;
    if (solver.CartToJnt(q_init, goal, q_out) != KDL::SolverI::E_MAX_ITERATIONS_EXCEEDED) return true;
    q_init = q_out;
  }
  return true;
}

// The solutions (and their flags) ordered by distance to q_ref, nearest first; ties keep their order.
void nearest_first(InverseResult& result, const Eigen::VectorXd& q_ref) {
  std::vector<std::size_t> order(result.solutions.size());
  std::vector<double> distance(order.size());
  for (std::size_t k = 0; k < order.size(); ++k) {
    order[k] = k;
    distance[k] = (result.solutions[k] - q_ref).norm();
  }
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return distance[a] < distance[b]; });
  InverseResult sorted;
  for (const std::size_t k : order) {
    sorted.solutions.push_back(std::move(result.solutions[k]));
    sorted.within_limits.push_back(result.within_limits[k]);
  }
  result.solutions = std::move(sorted.solutions);
  result.within_limits = std::move(sorted.within_limits);
}

// The distinct solutions kept so far (representatives of their 2π copies) and whether each is
// inside the joint limits.
struct Representatives {
  std::vector<Eigen::VectorXd> q;
  std::vector<bool> inside;
};

// The closed forms (spherical wrist, three parallel axes): no allocation but the result's, and
// no second check of what the solver has checked; their solutions are distinct modulo 2π
// (ik_duplicate_tolerance), and whole turns keep them so. The limits are applied to the
// fixed-size vectors; only a kept solution is copied to the heap (its one allocation).
void closed_form_solutions(const SerialArm& arm, const RevoluteChain& chain, IkFamily family, const JointLimits& limits,
                           const Posed& pose, const InverseOptions& options, Representatives& kept) {
  const int n = arm.dof();
  IkSolutionSet set;
  analytic_inverse(chain, family, pose, set);
  kept.q.reserve(static_cast<std::size_t>(set.count));
  kept.inside.reserve(static_cast<std::size_t>(set.count));
  // Limits that hold all of (−π, π] (with the slack) leave the solver's joints as they are
  // (IkSolutionSet holds them in (−π, π]).
  bool whole_turns = true;
  for (int i = 0; i < n && whole_turns; ++i)
    whole_turns = !(limits.lower(i) - limit_slack > -pi) && !(limits.upper(i) + limit_slack < pi);
  bool polished = false;
  for (int k = 0; k < set.count; ++k) {
    const Eigen::Matrix<double, 6, 1>& solved = set[k];
    Eigen::Matrix<double, 6, 1> fixed = solved;
    bool inside = true, as_solved = true;
    if (!whole_turns) {
      inside = into_limits(fixed, limits);
      as_solved = fixed == solved;
    }
    if (!inside && !options.keep_outside_limits) continue;
    if (as_solved && set.error[static_cast<std::size_t>(k)] <= checked_by_solver) {
      if (polished && is_duplicate(kept.q, fixed)) continue;
      kept.q.emplace_back(fixed);
      kept.inside.push_back(inside);
      continue;
    }
    Eigen::VectorXd q = fixed;
    if (!reproduces(arm, q, pose)) {
      if (!polish(arm, pose, q)) continue;
      polished = true;
    }
    if (polished && is_duplicate(kept.q, q)) continue;
    kept.q.push_back(std::move(q));
    kept.inside.push_back(inside);
  }
}

// Numeric fallback: restarts drawn uniformly inside the limits within one turn, until the
// attempts or the time budget run out; each root polished by Newton on the full pose.
std::vector<Eigen::VectorXd> numeric_solutions(const SerialArm& arm, const KDL::Chain& arm_chain,
                                               const JointLimits& limits, const Posed& pose,
                                               const InverseOptions& options) {
  const int n = arm.dof();
  std::vector<Eigen::VectorXd> raw;
  // A copy of the KDL chain: its joints keep their last pose in mutable members, so the arm's
  // own chain must not be used by two threads at once.
  const KDL::Chain chain = arm_chain;
  KDL::ChainIkSolverPos_LMA solver(chain, 1e-12, lma_run_length, 1e-15);
  std::mt19937_64 generator(options.seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const KDL::Frame goal = to_frame(pose);
  // A budget beyond a million seconds is no budget; capped so that it converts to the clock's
  // integer ticks without overflow.
  const auto budget = std::chrono::duration<double>(std::min(options.time_budget, 1e6));
  const auto deadline =
      std::chrono::steady_clock::now() + std::chrono::duration_cast<std::chrono::steady_clock::duration>(budget);
  KDL::JntArray q_init(static_cast<unsigned>(n));
  KDL::JntArray q_out(static_cast<unsigned>(n));
  for (int attempt = 0; attempt < options.max_attempts; ++attempt) {
    if (std::chrono::steady_clock::now() > deadline) break;
    for (int i = 0; i < n; ++i) {
      // One turn is enough to start from: inside the limits and [−π, π] where they meet,
      // else the limits' first turn (±1e16 rad limits would otherwise start at 1e15 rad).
      double lo = std::isfinite(limits.lower(i)) ? std::max(limits.lower(i), -pi) : -pi;
      double hi = std::isfinite(limits.upper(i)) ? std::min(limits.upper(i), pi) : pi;
      if (!(lo < hi)) {
        lo = limits.lower(i);
        hi = std::min(limits.upper(i), lo + two_pi);
      }
      q_init(static_cast<unsigned>(i)) = lo + (hi - lo) * unit(generator);
    }
    // The return code says little; forward kinematics below decides.
    if (!solve_before(solver, goal, q_init, q_out, deadline)) break;
    Eigen::VectorXd q = q_out.data;
    if (!q.allFinite()) continue;
    if (!polish(arm, pose, q)) continue;
    raw.push_back(q);
  }
  return raw;
}

// The solutions of the other families (`raw`) brought into the limits, checked and kept unless
// one kept already is the same up to 2π per joint.
void keep_solutions(const SerialArm& arm, const std::vector<Eigen::VectorXd>& raw, const JointLimits& limits,
                    const Posed& pose, const InverseOptions& options, Representatives& kept) {
  const int n = arm.dof();
  for (Eigen::VectorXd q : raw) {
    if (q.size() != n || !q.allFinite()) continue;
    const bool inside = into_limits(q, limits);
    if (!inside && !options.keep_outside_limits) continue;
    // Every solution is checked by forward kinematics (reproduces); one that misses by a little
    // (an analytic root rounded, a 2π shift) gets Newton steps, one that misses by more is not a solution.
    if (!reproduces(arm, q, pose) && !polish(arm, pose, q)) continue;
    // Duplicates (equal up to 2π per joint) are looked for among these representatives only:
    // the copies of different representatives are then different too.
    if (is_duplicate(kept.q, q)) continue;
    kept.q.push_back(q);
    kept.inside.push_back(inside);
  }
}

// The 2π copies inside the limits of every representative into `result`: counted first, refused
// beyond the cap, then made.
void add_copies(const SerialArm& arm, const Representatives& kept, const JointLimits& limits, const Posed& pose,
                InverseResult& result) {
  const double count = copy_count(kept.q, kept.inside, limits);
  if (count > static_cast<double>(input_budget::max_ik_solutions)) {
    std::ostringstream why;
    why << "asks for the 2π copies of the " << kept.q.size() << " solutions inside the joint limits, " << count
        << " in all, more than " << input_budget::max_ik_solutions
        << " (doc/input-budget.md); leave it false for the distinct solutions, or narrow the limits";
    throw std::invalid_argument(describe("offer_equivalents", std::string("true"), why.str()));
  }
  for (std::size_t r = 0; r < kept.q.size(); ++r) {
    if (!kept.inside[r]) {  // kept outside the limits: no copies of it are inside
      result.solutions.push_back(kept.q[r]);
      result.within_limits.push_back(false);
      continue;
    }
    std::vector<Eigen::VectorXd> variants = copies_within(kept.q[r], limits);
    for (Eigen::VectorXd& candidate : variants) {
      if (&candidate != &variants.front() && !reproduces(arm, candidate, pose) && !polish(arm, pose, candidate))
        continue;
      result.solutions.push_back(candidate);
      result.within_limits.push_back(true);
    }
  }
}

}  // namespace

InverseResult SerialArm::inverse_solutions(const Posed& pose, const InverseOptions& options) const {
  {
    const Eigen::Quaterniond& r = pose.quaternion();
    require_finite(Eigen::Vector4d(r.w(), r.x(), r.y(), r.z()), "pose quaternion (w, x, y, z)");
    require_finite(pose.translation(), "pose translation");
  }
  require(options.max_attempts > 0, "max_attempts", options.max_attempts, "must be greater than zero");
  require_positive(options.time_budget, "time_budget");

  const Redundancy& redundancy = model_->redundancy;
  if (options.redundancy) {
    require(redundancy.has_parameter(), "redundancy", *options.redundancy,
            "the arm has no redundancy parameter (its family is " + to_string(model_->family) + ")");
    require(!options.q_ref, "redundancy", *options.redundancy, "give either redundancy or q_ref, not both");
    require_finite(*options.redundancy, "redundancy");
  }
  if (options.q_ref) require_joint_vector(*options.q_ref, "q_ref");

  const JointLimits& limits = model_->limits;
  InverseResult result;
  result.family = model_->family;

  Representatives kept;
  std::vector<Eigen::VectorXd> raw;
  if (model_->family == IkFamily::spherical_wrist || model_->family == IkFamily::three_parallel) {
    closed_form_solutions(*this, model_->revolute, model_->family, limits, pose, options, kept);
    result.complete = true;
  } else if (model_->family == IkFamily::locked_joint) {
    // Every solution at each parameter value (doc/inverse-kinematics.md (eq. 40)): one asked for,
    // q_ref's, or the default set spread over the range.
    std::vector<double> values;
    if (options.redundancy) {
      values.push_back(*options.redundancy);
    } else if (options.q_ref) {
      values.push_back(redundancy.value(*options.q_ref));
    } else {
      values = redundancy.default_values();
    }
    for (const double value : values) locked_joint_inverse(model_->revolute, model_->lock, value, pose, raw);
    result.complete = values.size() == 1;
  } else if (model_->family != IkFamily::general) {
    raw = analytic_inverse(model_->revolute, model_->family, pose);
    result.complete = true;
  } else {
    // A start known (q_ref): Newton's method from it first (doc/inverse-kinematics.md (eq. 46)),
    // the search from random starts only when asked, or when Newton lands on no solution inside
    // the limits.
    if (options.q_ref) {
      Eigen::VectorXd q = *options.q_ref;
      if (polish_from(*this, pose, q))
        keep_solutions(*this, std::vector<Eigen::VectorXd>{q}, limits, pose, options, kept);
    }
    if (kept.q.empty() || options.wide_search) raw = numeric_solutions(*this, model_->chain, limits, pose, options);
    result.complete = false;
  }
  keep_solutions(*this, raw, limits, pose, options, kept);

  if (!options.offer_equivalents) {
    result.solutions = std::move(kept.q);
    result.within_limits = std::move(kept.inside);
  } else {
    add_copies(*this, kept, limits, pose, result);
  }
  if (options.q_ref) nearest_first(result, *options.q_ref);
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
      throw std::invalid_argument(describe("q_ref", q_ref,
                                           "expected " + std::to_string(solutions[k].size()) +
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
