// Time-optimal re-timing under DISP and joint limits (retiming.hpp, retime_optimal;
// doc/retiming.md §4–6). The stages, each in its own file:
//   - smooth_parameter: the planned path by a parameter σ in which the pose derivative is
//     continuous through tangent junctions, with the DISP limits in σ (doc/retiming.md eq. 9–10);
//   - joint_grid: the joint path q(σ), q′, q″ and the torque coefficients on a grid of each
//     rest-to-rest run, and each run's limits as half-planes in (σ̈, σ̇²) (doc/retiming.md eq. 11–15);
//   - reachability: the fastest parameterisation of a run on its grid (doc/retiming.md eq. 16, as in TOPP-RA);
//   - jerk_limited_run / jerk_filter: with a jerk limit, the moving average of the run's law over
//     the smallest window that keeps the jerk, with the speed caps tightened over the window's
//     reach (doc/retiming.md eq. 19–22), and the laws back in s.
// This file drives them: the grid, the dense check of the result against the joint limits, the
// tightening of the limits where it overshoots between grid points (doc/retiming.md eq. 18), and, with a jerk
// limit, the planner's own S-curve plan and the machine's scaling loop as faster candidates.
#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <optional>
#include <sstream>
#include <string>

#include "dispkin/error.hpp"
#include "dispkin/planning/retiming.hpp"
#include "jerk_filter.hpp"
#include "jerk_limited_run.hpp"
#include "joint_grid.hpp"
#include "reachability.hpp"
#include "smooth_parameter.hpp"

namespace dispkin {
namespace {

// The fraction of every joint limit kept free at the checked samples, for what happens between
// them: the grid laws are solved at (1 − this) of the limits, and a candidate law from elsewhere
// (the S-curve plan, the KUKA re-timing patent's scaling loop) must check out this far below them.
constexpr double standing_headroom = 1e-3;
// A candidate law has none of the grid laws' structure between its characteristic points (a joint
// speed may peak anywhere in a cruise): it is checked at least this densely (measured: 3 samples
// between missed a joint-speed peak by 0.1 % on a scaled UR5e move).
constexpr int candidate_samples_between = 10;

// Throws std::invalid_argument naming the first bad option.
void require_valid(const OptimalRetimeOptions& options, int dof) {
  require(options.grid_intervals >= 2, "grid_intervals", static_cast<long>(options.grid_intervals), "must be ≥ 2");
  require_positive(options.difference_step, "difference_step");
  require(options.check_samples_between >= 0, "check_samples_between", static_cast<long>(options.check_samples_between),
          "must be ≥ 0");
  require(options.max_refinements >= 0, "max_refinements", static_cast<long>(options.max_refinements), "must be ≥ 0");
  const Eigen::VectorXd& acceleration = options.joint_acceleration;
  require(acceleration.size() == 0 || acceleration.size() == dof, "joint_acceleration size",
          static_cast<long>(acceleration.size()), "must be 0 or the machine's dof " + std::to_string(dof));
  for (Eigen::Index k = 0; k < acceleration.size(); ++k) {
    require(acceleration(k) > 0.0, "joint_acceleration[" + std::to_string(k) + "]", acceleration(k), "must be > 0");
  }
}

// The grid of every rest-to-rest run (each gets its share of options.grid_intervals, at least
// 2), the joints followed from q_start; the runs' index ranges in `runs`.
std::vector<detail::GridPoint> joint_grid(const detail::SmoothParameter& smooth, const JointModel& model,
                                          const OptimalRetimeOptions& options, const Eigen::VectorXd& q_start,
                                          const JointBounds& bounds, std::vector<detail::Run>& runs) {
  const std::vector<double>& rests = smooth.rests();
  // The torque coefficients (two inverse-dynamics passes a point) only where an effort limit is kept.
  const bool torques = bounds.effort.array().isFinite().any();
  std::vector<detail::GridPoint> grid;
  Eigen::VectorXd q_ref = q_start, guess;
  for (std::size_t r = 0; r + 1 < rests.size(); ++r) {
    const double lo = rests[r], hi = rests[r + 1];
    if (!(hi > lo)) continue;
    const auto count =
        static_cast<std::size_t>(std::max(2.0, std::round(options.grid_intervals * (hi - lo) / smooth.length())));
    const double h = options.difference_step * (hi - lo) / static_cast<double>(count);
    runs.push_back({grid.size(), count});
    for (std::size_t i = 0; i <= count; ++i) {
      const double sigma = i == count ? hi : lo + (hi - lo) * static_cast<double>(i) / static_cast<double>(count);
      // Inside a run, Newton starts from the previous point moved on by its q′ and q″ (second order).
      const detail::GridPoint* previous = i ? &grid.back() : nullptr;
      if (previous) {
        const double step = sigma - previous->sigma;
        guess = previous->q + step * previous->q1 + (0.5 * step * step) * previous->q2;
      }
      grid.push_back(detail::grid_point(smooth, model, sigma, h, (hi - lo) / static_cast<double>(count), lo, hi, q_ref,
                                        previous ? &guess : nullptr, torques));
      q_ref = grid.back().q;
    }
  }
  return grid;
}

// Holding still must be possible everywhere (the KUKA re-timing patent's "cannot be reached by
// slowing down"): throws std::runtime_error naming the joint and the place where it is not.
void require_holding_possible(const std::vector<detail::GridPoint>& grid, const JointBounds& bounds,
                              const JointModel& model, const detail::SmoothParameter& smooth) {
  for (const detail::GridPoint& p : grid) {
    for (Eigen::Index k = 0; k < p.gravity.size(); ++k) {
      if (std::abs(p.gravity(k)) >= bounds.effort(k)) {
        std::ostringstream message;
        message << "joint " << model.joint_name(static_cast<int>(k)) << ": the static torque " << std::abs(p.gravity(k))
                << " N·m at " << detail::where(std::nan(""), smooth.s_of(p.sigma)) << " reaches its effort limit "
                << bounds.effort(k) << " N·m: no speed makes this path feasible";
        throw std::runtime_error(message.str());
      }
    }
  }
}

// The dense check of r.trajectory (model.check at samples_between) and its largest ratios to the
// joint limits, the whole torque against the effort limit. Throws std::runtime_error where a
// joint leaves its position range (slowing down cannot help).
void measure_check(OptimalRetimeResult& r, const JointModel& model, const JointBounds& bounds,
                   const Eigen::VectorXd& q_start, int samples_between) {
  const int dof = model.dof();
  r.report = model.check(r.trajectory, q_start, samples_between);
  if (r.report.position_excess > 0.0) {
    const JointSample& at = r.report.samples[r.report.position_sample];
    throw std::runtime_error("joint " + model.joint_name(r.report.position_joint) + " leaves its position range by " +
                             std::to_string(r.report.position_excess) + " " + model.position_unit() + " at " +
                             detail::where(at.time, at.s) + ": slowing down cannot help");
  }
  r.velocity_ratio = r.acceleration_ratio = r.torque_ratio = 0.0;
  for (const JointSample& sample : r.report.samples) {
    for (int k = 0; k < dof; ++k) {
      r.velocity_ratio = std::max(r.velocity_ratio, std::abs(sample.qd(k)) / bounds.velocity(k));
      r.acceleration_ratio = std::max(r.acceleration_ratio, std::abs(sample.qdd(k)) / bounds.acceleration(k));
      if (sample.static_torque.size() == dof) {
        const double torque = sample.static_torque(k) + sample.dynamic_torque(k);
        r.torque_ratio = std::max(r.torque_ratio, std::abs(torque) / bounds.effort(k));
      }
    }
  }
}

// The laws of every run at `scale` of the joint limits on the grid: the time-optimal ones under
// the acceleration limit, or under a jerk limit the moving average of the acceleration steps;
// the grid's path positions and speeds, and the widest averaging window, recorded in `result`.
std::vector<Profile> grid_laws(const detail::SmoothParameter& smooth, const std::vector<detail::GridPoint>& grid,
                               const JointBounds& bounds, double scale, const std::vector<detail::Run>& runs,
                               const Limits& limits, OptimalRetimeResult& result) {
  std::vector<Profile> laws;
  result.grid_s.clear();
  result.grid_speed.clear();
  result.jerk_window = 0.0;
  for (const detail::Run& run : runs) {
    const detail::RunProblem problem(smooth, grid, bounds, scale, run);
    auto record_grid = [&](const detail::Parameterisation& fastest) {
      for (std::size_t i = 0; i <= run.count; ++i) {
        const double sigma = grid[run.first + i].sigma;
        result.grid_s.push_back(smooth.s_of(sigma));
        result.grid_speed.push_back(std::sqrt(fastest.x[i]) * smooth.s_per_sigma(smooth.section_at(sigma)));
      }
    };

    if (limits.jerk) {
      const detail::JerkLimitedSolution chosen =
          detail::jerk_limited_solution(problem, limits.acceleration, *limits.jerk);
      const detail::Parameterisation& fastest = chosen.fastest;
      const detail::AccelerationSteps& steps = chosen.steps;
      const double window = chosen.window;
      result.jerk_window = std::max(result.jerk_window, window);
      record_grid(fastest);
      double end_time = 0.0;
      const std::vector<detail::JerkPhase> phases = detail::moving_average(steps, window, end_time);
      detail::append_jerk_laws(smooth, phases, problem.end(), laws);
      continue;
    }

    const detail::Parameterisation fastest = problem.solve(0.0, 0.0);
    record_grid(fastest);
    detail::append_acceleration_laws(problem, fastest, limits.acceleration, laws);
  }
  return laws;
}

// Under a jerk limit, the planner's own S-curve law and the KUKA re-timing patent's scaling loop
// with the S-curve as candidates under the same dense check: the fastest that keeps every joint
// limit with the grid laws' headroom, if it is faster than `result`.
std::optional<OptimalRetimeResult> faster_scurve(const Path& path, const MetricSetd& set, const Limits& limits,
                                                 const JointModel& model, const JointBounds& bounds,
                                                 const Eigen::VectorXd& q_start, const OptimalRetimeOptions& options,
                                                 const OptimalRetimeResult& result) {
  std::vector<Trajectory> candidates;
  candidates.push_back(plan(path, set, limits, ProfileKind::scurve));
  if (std::optional<Trajectory> scaled = model.scaled_scurve(path, set, limits, q_start, standing_headroom)) {
    candidates.push_back(std::move(*scaled));
  }
  std::sort(candidates.begin(), candidates.end(),
            [](const Trajectory& a, const Trajectory& b) { return a.duration() < b.duration(); });
  for (Trajectory& candidate : candidates) {
    if (candidate.duration() >= result.trajectory.duration()) break;
    OptimalRetimeResult direct = result;
    direct.trajectory = std::move(candidate);
    measure_check(direct, model, bounds, q_start, std::max(options.check_samples_between, candidate_samples_between));
    // The same headroom as the grid laws' own: a law at its limits at the checked samples
    // may exceed them between (measured: 3·10⁻⁵ on a scaled UR5e move).
    if (std::max({direct.velocity_ratio, direct.acceleration_ratio, direct.torque_ratio}) <= 1.0 - standing_headroom) {
      direct.jerk_window = 0.0;
      return direct;
    }
  }
  return std::nullopt;
}

// The fastest timing of `path` for `model` (see the file comment); options already checked.
OptimalRetimeResult fastest_timing(const Path& path, const MetricSetd& set, const Limits& limits,
                                   const JointModel& model, const Eigen::VectorXd& q_start,
                                   const OptimalRetimeOptions& options) {
  require_valid(options, model.dof());
  // The plan gives the DISP velocity-limit curve and the rests (the same for both profiles).
  if (limits.jerk) limits.validate(ProfileKind::scurve);
  Limits unjerked = limits;
  unjerked.jerk.reset();
  const Trajectory planned = plan(path, set, unjerked, ProfileKind::trapezoid);
  const detail::SmoothParameter smooth(planned, limits.acceleration);
  const JointBounds bounds = model.bounds(options);
  // The joints along this plan's path: where they depend on the path position (a moving
  // redundancy parameter), the grid solves them as the dense check of the result does.
  const std::unique_ptr<JointModel> on_path = model.along(planned, q_start);

  std::vector<detail::Run> runs;
  const std::vector<detail::GridPoint> grid =
      joint_grid(smooth, on_path ? *on_path : model, options, q_start, bounds, runs);
  require_holding_possible(grid, bounds, model, smooth);

  OptimalRetimeResult result;
  // The grid solution sits exactly on its limits, and between grid points the coefficients
  // move by O(Δ²): 0.1 % headroom from the start spares the re-solve and re-check in most cases
  // (measured: first-pass overshoots of 2–3·10⁻⁴ on 100-interval grids of UR5e moves).
  double scale = 1.0 - standing_headroom;
  for (int refinement = 0;; ++refinement) {
    const std::vector<Profile> laws = grid_laws(smooth, grid, bounds, scale, runs, limits, result);
    result.trajectory = planned.with_time_law(TimeLaw::consecutive(laws, runs.size()));

    measure_check(result, model, bounds, q_start, options.check_samples_between);
    const double worst = std::max({result.velocity_ratio, result.acceleration_ratio, result.torque_ratio});
    result.margin = 1.0 - scale;
    result.refinements = refinement;
    if (worst <= 1.0) {
      // With a jerk limit the averaged law is not the jerk-limited optimum: a faster S-curve
      // candidate that passes the same check is the result instead.
      if (limits.jerk) {
        if (std::optional<OptimalRetimeResult> direct =
                faster_scurve(path, set, limits, model, bounds, q_start, options, result))
          return std::move(*direct);
      }
      return result;
    }
    if (refinement == options.max_refinements) {
      throw std::runtime_error("optimal re-timing: the dense check still finds a joint limit exceeded by a factor " +
                               std::to_string(worst) + " after " + std::to_string(refinement) +
                               " refinements; use more grid_intervals");
    }
    // Tighten by the overshoot found, with a little to spare.
    scale *= (1.0 - standing_headroom) / worst;
  }
}

}  // namespace

bool JointModel::joints_with_rate(const Posed& pose, const Twistd& per_sigma, const Twistd&,
                                  const Eigen::VectorXd& q_ref, const Eigen::VectorXd* guess, const PathPlace& place,
                                  Eigen::VectorXd& q, Eigen::VectorXd& q1, Eigen::VectorXd&) const {
  joints(pose, per_sigma, q_ref, guess, place, q, q1);
  return false;
}

void JointModel::rate_steps(const Eigen::VectorXd&, const Eigen::VectorXd&, const PathPlace&, double, double,
                            std::vector<Eigen::VectorXd>& q2_other) const {
  q2_other.clear();
}

std::unique_ptr<JointModel> JointModel::along(const Trajectory&, const Eigen::VectorXd&) const { return nullptr; }

std::optional<Trajectory> JointModel::scaled_scurve(const Path&, const MetricSetd&, const Limits&,
                                                    const Eigen::VectorXd&, double) const {
  return std::nullopt;
}

OptimalRetimeResult retime_optimal(const Path& path, const MetricSetd& set, const Limits& limits,
                                   const JointModel& model, const Eigen::VectorXd& q_start,
                                   const OptimalRetimeOptions& options) {
  require(q_start.size() == model.dof(), "q_start size", static_cast<long>(q_start.size()),
          "must equal the machine's dof " + std::to_string(model.dof()));
  require_finite(q_start, "q_start");
  PlanOptions continuous;
  continuous.corner_tolerance = options.corner_tolerance;
  const std::optional<Path> blended = continuous_path(path, continuous);
  return fastest_timing(blended ? *blended : path, set, limits, model, q_start, options);
}

}  // namespace dispkin
