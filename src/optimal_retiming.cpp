// Time-optimal re-timing under DISP and joint limits (retiming.hpp, retime_optimal).
//
// Along the path, with q(s) the joint path (IK, continuous branch) and ′ = d/ds:
//   q̇ = q′ ṡ,   q̈ = q′ s̈ + q″ ṡ²,   τ = M q′ s̈ + (M q″ + C(q, q′) q′) ṡ² + g(q),
// all linear in (u, x) = (s̈, ṡ²). The torque coefficients come from three recursive
// Newton–Euler evaluations: g = τ(q, 0, 0), M q′ = τ(q, 0, q′) − g and
// M q″ + C(q, q′) q′ = τ(q, q′, q″) − g (C(q, q̇) q̇ is quadratic in q̇). The limits are imposed
// at both ends of every grid interval (x_{i+1} = x_i + 2Δu_i keeps that linear in (u_i, x_i)),
// and reachability.hpp finds the fastest parameterisation. Between grid points the
// coefficients vary smoothly, so a limit can be exceeded there by O(Δ²): the result is checked
// densely, and if it overshoots the joint limits are tightened on the grid by the overshoot
// and the grid re-solved.
#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <string>

#include "dispkin/error.hpp"
#include "dispkin/retiming.hpp"
#include "joint_following.hpp"
#include "reachability.hpp"

namespace dispkin {
namespace detail {

// Builds a trajectory on the same path with other time laws.
struct TrajectoryAccess {
  // `planned` with its laws replaced by `laws`, consecutive from s = 0 over its whole length,
  // in `runs` rest-to-rest runs.
  static Trajectory with_laws(const Trajectory& planned, const std::vector<Profile>& laws, std::size_t runs) {
    Trajectory out = planned;
    out.pieces_.clear();
    out.pieces_.reserve(laws.size());
    double time = 0.0, s = 0.0;
    for (const Profile& law : laws) {
      out.pieces_.push_back(Trajectory::Piece{law, time, time + law.duration(), s});
      time += law.duration();
      s += law.distance();
    }
    out.rest_pieces_ = runs;
    return out;
  }
};

}  // namespace detail
namespace {

using detail::HalfPlane;

// What the limits need of the joint path at one grid position.
struct GridPoint {
  double s;
  Eigen::VectorXd q, q1, q2;  // q, q′, q″
  Eigen::VectorXd torque_u, torque_x, gravity;  // τ = torque_u·s̈ + torque_x·ṡ² + gravity
};

// The joint path at s, with q″ by central differences of q′ inside [s_lo, s_hi] (one-sided at
// its ends: a run's ends are rests, where the path may turn a corner).
GridPoint grid_point(const Trajectory& planned, const serial::SerialArm& arm, double s, double h, double s_lo,
                     double s_hi, const Eigen::VectorXd& q_ref) {
  constexpr double no_time = std::numeric_limits<double>::quiet_NaN();
  auto joint_path = [&](double at, const Eigen::VectorXd& reference, Eigen::VectorXd& q, Eigen::VectorXd& q1) {
    Posed pose;
    Twistd per_s;
    planned.path_state(at, pose, per_s);
    q = detail::continuous_solution(arm, pose, reference, no_time, at);
    q1 = detail::joint_velocity(arm, q, per_s, no_time, at);
  };
  GridPoint p;
  p.s = s;
  joint_path(s, q_ref, p.q, p.q1);
  const double before = std::max(s_lo, s - h), after = std::min(s_hi, s + h);
  Eigen::VectorXd q_before, q1_before, q_after, q1_after;
  joint_path(before, p.q, q_before, q1_before);
  joint_path(after, p.q, q_after, q1_after);
  p.q2 = (q1_after - q1_before) / (after - before);
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(p.q.size());
  p.gravity = arm.static_torques(p.q);
  p.torque_u = arm.torques(p.q, zero, p.q1) - p.gravity;
  p.torque_x = arm.torques(p.q, p.q1, p.q2) - p.gravity;
  return p;
}

// The joint limits at one grid point as half-planes in (u, x), each limit multiplied by `scale`.
struct JointBounds {
  Eigen::VectorXd velocity, acceleration, effort;  // +∞ where none
};

void append_limits(const GridPoint& p, const JointBounds& bounds, double scale, std::vector<HalfPlane>& out) {
  for (Eigen::Index k = 0; k < p.q.size(); ++k) {
    if (std::isfinite(bounds.velocity(k))) {
      const double v = scale * bounds.velocity(k);
      out.push_back({0.0, p.q1(k) * p.q1(k), v * v});
    }
    if (std::isfinite(bounds.acceleration(k))) {
      const double a = scale * bounds.acceleration(k);
      out.push_back({p.q1(k), p.q2(k), a});
      out.push_back({-p.q1(k), -p.q2(k), a});
    }
    if (std::isfinite(bounds.effort(k))) {
      const double t = scale * bounds.effort(k);
      out.push_back({p.torque_u(k), p.torque_x(k), t - p.gravity(k)});
      out.push_back({-p.torque_u(k), -p.torque_x(k), t + p.gravity(k)});
    }
  }
}

// The lowest DISP speed limit over [s0, s1].
double speed_cap(const Trajectory& planned, double s0, double s1) {
  double cap = std::numeric_limits<double>::infinity();
  for (const Trajectory::SpeedLimit& span : planned.speed_limits()) {
    if (span.start_s < s1 && span.start_s + span.length > s0) cap = std::min(cap, span.limit);
  }
  return cap;
}

std::string interval_text(double s0, double s1) {
  std::ostringstream out;
  out << "[" << s0 << ", " << s1 << "] m";
  return out.str();
}

}  // namespace

OptimalRetimeResult retime_optimal(const Path& path, const MetricSetd& set, const Limits& limits,
                                   const serial::SerialArm& arm, const Eigen::VectorXd& q_start,
                                   const OptimalRetimeOptions& options) {
  require(options.grid_intervals >= 2, "grid_intervals", static_cast<long>(options.grid_intervals), "must be ≥ 2");
  require_positive(options.difference_step, "difference_step");
  require(options.check_samples_between >= 0, "check_samples_between",
          static_cast<long>(options.check_samples_between), "must be ≥ 0");
  require(options.max_refinements >= 0, "max_refinements", static_cast<long>(options.max_refinements), "must be ≥ 0");
  const int dof = arm.dof();
  require(q_start.size() == dof, "q_start size", static_cast<long>(q_start.size()),
          "must equal the arm's dof " + std::to_string(dof));
  require_finite(q_start, "q_start");
  const Eigen::VectorXd& acceleration = options.joint_acceleration;
  require(acceleration.size() == 0 || acceleration.size() == dof, "joint_acceleration size",
          static_cast<long>(acceleration.size()), "must be 0 or the arm's dof " + std::to_string(dof));
  for (Eigen::Index k = 0; k < acceleration.size(); ++k) {
    require(acceleration(k) > 0.0, "joint_acceleration[" + std::to_string(k) + "]", acceleration(k), "must be > 0");
  }

  const Trajectory planned = plan(path, set, limits, ProfileKind::trapezoid);
  const JointLimits joint = arm.joint_limits();
  constexpr double none = std::numeric_limits<double>::infinity();
  JointBounds bounds{joint.velocity, acceleration.size() ? acceleration : Eigen::VectorXd::Constant(dof, none),
                     Eigen::VectorXd::Constant(dof, none)};
  if (options.torque_limits && joint.effort.size() == dof) bounds.effort = joint.effort;

  // The grid: each rest-to-rest run of the plan gets its share of the intervals.
  const std::vector<double>& rests = planned.rest_positions();
  const double total = planned.length();
  struct Run {
    std::size_t first, count;  // grid points [first, first + count]
  };
  std::vector<Run> runs;
  std::vector<GridPoint> grid;
  Eigen::VectorXd q_ref = q_start;
  for (std::size_t r = 0; r + 1 < rests.size(); ++r) {
    const double s0 = rests[r], s1 = rests[r + 1];
    if (!(s1 > s0)) continue;
    const auto count = static_cast<std::size_t>(std::max(2.0, std::round(options.grid_intervals * (s1 - s0) / total)));
    const double h = options.difference_step * (s1 - s0) / static_cast<double>(count);
    runs.push_back({grid.size(), count});
    for (std::size_t i = 0; i <= count; ++i) {
      const double s = i == count ? s1 : s0 + (s1 - s0) * static_cast<double>(i) / static_cast<double>(count);
      grid.push_back(grid_point(planned, arm, s, h, s0, s1, q_ref));
      q_ref = grid.back().q;
    }
  }
  // Holding still must be possible everywhere (the seed's "cannot be reached by slowing down").
  for (const GridPoint& p : grid) {
    for (int k = 0; k < dof; ++k) {
      if (std::abs(p.gravity(k)) >= bounds.effort(k)) {
        std::ostringstream message;
        message << "joint " << arm.joint_names()[static_cast<std::size_t>(k)] << ": the static torque "
                << std::abs(p.gravity(k)) << " N·m at " << detail::where(std::nan(""), p.s)
                << " reaches its effort limit " << bounds.effort(k) << " N·m: no speed makes this path feasible";
        throw std::runtime_error(message.str());
      }
    }
  }

  OptimalRetimeResult result;
  double scale = 1.0 - 1e-9;  // rounding headroom: the grid solution sits exactly on its limits
  std::vector<HalfPlane> at_start, at_end;
  for (int refinement = 0;; ++refinement) {
    std::vector<Profile> laws;
    result.grid_s.clear();
    result.grid_speed.clear();
    for (const Run& run : runs) {
      std::vector<detail::GridInterval> intervals;
      intervals.reserve(run.count);
      for (std::size_t i = run.first; i < run.first + run.count; ++i) {
        const GridPoint &p = grid[i], &p_next = grid[i + 1];
        const double delta = p_next.s - p.s;
        const double cap = speed_cap(planned, p.s, p_next.s);
        detail::GridInterval interval{delta, detail::ConvexPolygon(limits.acceleration, cap * cap)};
        interval.admissible.clip({2.0 * delta, 1.0, cap * cap});  // x_{i+1} ≤ cap² as well
        at_start.clear();
        at_end.clear();
        append_limits(p, bounds, scale, at_start);
        append_limits(p_next, bounds, scale, at_end);
        for (const HalfPlane& h : at_start) interval.admissible.clip(h);
        for (const HalfPlane& h : at_end) interval.admissible.clip({h.a + 2.0 * delta * h.b, h.b, h.c});
        intervals.push_back(std::move(interval));
      }
      const detail::Parameterisation fastest = detail::fastest_parameterisation(std::move(intervals), 0.0, 0.0);
      if (fastest.infeasible_interval >= 0) {
        const std::size_t i = run.first + static_cast<std::size_t>(fastest.infeasible_interval);
        throw std::runtime_error("no speed keeps every joint limit on the path interval " +
                                 interval_text(grid[i].s, grid[i + 1].s) + " while still reaching the next rest");
      }
      for (std::size_t i = 0; i < run.count; ++i) {
        const double s0 = grid[run.first + i].s, delta = grid[run.first + i + 1].s - s0;
        const double v0 = std::sqrt(fastest.x[i]), v1 = std::sqrt(fastest.x[i + 1]);
        if (!(v0 + v1 > 0.0)) {
          throw std::runtime_error("the joint limits allow no motion on the path interval " +
                                   interval_text(s0, s0 + delta));
        }
        // Constant s̈ over the interval: the trapezoid between v0 and v1 whose acceleration just
        // covers Δ (a hair above, so that rounding cannot make the law infeasible).
        const double a = std::max(std::abs(v1 * v1 - v0 * v0) / (2.0 * delta) * (1.0 + 1e-9), 1e-12 * limits.acceleration);
        laws.push_back(Profile::trapezoid(delta, std::max(v0, v1), a, v0, v1));
        result.grid_s.push_back(s0);
        result.grid_speed.push_back(v0);
      }
      result.grid_s.push_back(grid[run.first + run.count].s);
      result.grid_speed.push_back(std::sqrt(fastest.x.back()));
    }
    result.trajectory = detail::TrajectoryAccess::with_laws(planned, laws, runs.size());

    // The dense check, with the whole torque against the effort limit.
    JointCheckOptions check;
    check.samples_between = options.check_samples_between;
    result.report = check_joint_limits(result.trajectory, arm, q_start, check);
    if (result.report.position_excess > 0.0) {
      const JointSample& at = result.report.samples[result.report.position_sample];
      throw std::runtime_error("joint " + arm.joint_names()[static_cast<std::size_t>(result.report.position_joint)] +
                               " leaves its position range by " + std::to_string(result.report.position_excess) +
                               " rad at " + detail::where(at.time, at.s) + ": slowing down cannot help");
    }
    result.velocity_ratio = result.acceleration_ratio = result.torque_ratio = 0.0;
    for (const JointSample& sample : result.report.samples) {
      const Eigen::VectorXd torque = sample.static_torque + sample.dynamic_torque;
      for (int k = 0; k < dof; ++k) {
        result.velocity_ratio = std::max(result.velocity_ratio, std::abs(sample.qd(k)) / bounds.velocity(k));
        result.acceleration_ratio = std::max(result.acceleration_ratio, std::abs(sample.qdd(k)) / bounds.acceleration(k));
        result.torque_ratio = std::max(result.torque_ratio, std::abs(torque(k)) / bounds.effort(k));
      }
    }
    const double worst = std::max({result.velocity_ratio, result.acceleration_ratio, result.torque_ratio});
    result.margin = 1.0 - scale;
    result.refinements = refinement;
    if (worst <= 1.0) return result;
    if (refinement == options.max_refinements) {
      throw std::runtime_error("optimal re-timing: the dense check still finds a joint limit exceeded by a factor " +
                               std::to_string(worst) + " after " + std::to_string(refinement) +
                               " refinements; use more grid_intervals");
    }
    // Tighten by the overshoot found, with a little to spare.
    scale *= (1.0 - 1e-3) / worst;
  }
}

}  // namespace dispkin
