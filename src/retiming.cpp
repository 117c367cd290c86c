// Joint-limit prediction and the seed's re-timing loop (retiming.hpp).
#include "dispkin/retiming.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <string>

#include <Eigen/LU>

#include "dispkin/error.hpp"
#include "joint_following.hpp"

namespace dispkin {
namespace detail {

std::string where(double t, double s) {
  std::ostringstream out;
  if (std::isnan(t)) {
    out << "path position s = " << s << " m";
  } else {
    out << "t = " << t << " s (path position s = " << s << " m)";
  }
  return out.str();
}

Eigen::VectorXd continuous_solution(const serial::SerialArm& arm, const Posed& pose, const Eigen::VectorXd& q_ref,
                                    double t, double s) {
  constexpr double two_pi = 6.28318530717958647692;
  serial::InverseOptions options;
  options.offer_equivalents = false;
  options.keep_outside_limits = true;  // reported as a position excursion, not hidden
  const std::vector<Eigen::VectorXd> solutions = arm.inverse_solutions(pose, options).solutions;
  if (solutions.empty()) throw std::runtime_error("the pose at " + where(t, s) + " has no inverse-kinematics solution");
  Eigen::VectorXd best;
  double best_distance = std::numeric_limits<double>::infinity();
  for (Eigen::VectorXd q : solutions) {
    for (Eigen::Index i = 0; i < q.size(); ++i) q(i) += two_pi * std::round((q_ref(i) - q(i)) / two_pi);
    const double distance = (q - q_ref).norm();
    if (distance < best_distance) {
      best_distance = distance;
      best = q;
    }
  }
  return best;
}

Eigen::VectorXd tracked_solution(const serial::SerialArm& arm, const Posed& pose, const Eigen::VectorXd& q_ref, double t,
                                 double s, const Eigen::VectorXd* guess) {
  // Newton's method on the body-frame pose error from q_ref. Along a trajectory consecutive
  // poses are close, so it converges quadratically in two or three steps to the solution on
  // q_ref's branch — a third of the cost of enumerating every analytic solution. Anything
  // unusual (no convergence, a near-singular Jacobian, a step of more than 0.3 rad, where a
  // different branch may have been reached) falls back to the analytic nearest solution.
  constexpr double tolerance = 1e-13, largest_step = 0.3;
  Eigen::VectorXd q = guess ? *guess : q_ref;
  for (int iteration = 0; iteration < 6; ++iteration) {
    const Eigen::Matrix<double, 6, 1> error = (arm.forward(q).inverse() * pose).log().vector();
    if (error.lpNorm<Eigen::Infinity>() <= tolerance) {
      if ((q - q_ref).lpNorm<Eigen::Infinity>() <= largest_step) return q;
      break;
    }
    const Eigen::MatrixXd j = arm.body_jacobian(q);
    if (j.cols() != 6) break;
    const Eigen::Matrix<double, 6, 6> j6 = j;
    const Eigen::PartialPivLU<Eigen::Matrix<double, 6, 6>> lu(j6);
    if (!(std::abs(lu.determinant()) > 1e-9)) break;
    q += lu.solve(error);
    if (!q.allFinite()) break;
  }
  return continuous_solution(arm, pose, q_ref, t, s);
}

Eigen::VectorXd joint_velocity(const serial::SerialArm& arm, const Eigen::VectorXd& q, const Twistd& body,
                               double t, double s) {
  const Eigen::MatrixXd j = arm.body_jacobian(q);
  if (j.cols() != 6) throw std::invalid_argument(describe("arm dof", static_cast<long>(j.cols()), "must be 6 to invert the Jacobian"));
  const Eigen::FullPivLU<Eigen::MatrixXd> lu(j);
  if (lu.rcond() < 1e-10) {
    throw std::runtime_error("the arm is singular at " + where(t, s) + " (rcond of the Jacobian " + std::to_string(lu.rcond()) + ")");
  }
  return lu.solve(body.vector());
}

}  // namespace detail

using detail::tracked_solution;
using detail::joint_velocity;
using detail::where;

namespace {

// The checked instants of `trajectory` (options validated here): its characteristic points
// and samples_between equidistant ones between consecutive ones.
std::vector<double> checked_times(const Trajectory& trajectory, const JointCheckOptions& options) {
  require(options.samples_between >= 0, "samples_between", static_cast<long>(options.samples_between), "must be ≥ 0");
  require_positive(options.difference_step, "difference_step");
  const std::vector<double> marks = trajectory.characteristic_times();
  std::vector<double> times;
  for (std::size_t k = 0; k + 1 < marks.size(); ++k) {
    for (int i = 0; i <= options.samples_between; ++i)
      times.push_back(marks[k] + (marks[k + 1] - marks[k]) * i / (options.samples_between + 1));
  }
  times.push_back(marks.back());
  return times;
}

}  // namespace

JointLimitReport check_joint_limits(const Trajectory& trajectory, const serial::SerialArm& arm,
                                    const Eigen::VectorXd& q_start, const JointCheckOptions& options) {
  const std::vector<double> times = checked_times(trajectory, options);
  require(q_start.size() == arm.dof(), "q_start size", static_cast<long>(q_start.size()),
          "must equal the arm's dof " + std::to_string(arm.dof()));
  require_finite(q_start, "q_start");
  const JointLimits limits = arm.joint_limits();


  JointLimitReport report;
  const double duration = trajectory.duration();
  const double h = options.difference_step;
  Eigen::VectorXd q_prev = q_start;
  for (const double t : times) {
    const TrajectorySample here = trajectory.sample(t);
    JointSample sample;
    sample.time = t;
    sample.s = here.s;
    sample.q = tracked_solution(arm, here.pose, q_prev, t, here.s);
    sample.qd = joint_velocity(arm, sample.q, here.body_twist, t, here.s);
    // q̈ by central differences of the Jacobian velocities (one-sided at the ends).
    const double t_before = std::max(0.0, t - h), t_after = std::min(duration, t + h);
    if (t_after > t_before) {
      const TrajectorySample before = trajectory.sample(t_before), after = trajectory.sample(t_after);
      // Predicted to first order, so that Newton needs a single step.
      const Eigen::VectorXd guess_before = sample.q - (t - t_before) * sample.qd;
      const Eigen::VectorXd guess_after = sample.q + (t_after - t) * sample.qd;
      const Eigen::VectorXd q_before = tracked_solution(arm, before.pose, sample.q, t_before, before.s, &guess_before);
      const Eigen::VectorXd q_after = tracked_solution(arm, after.pose, sample.q, t_after, after.s, &guess_after);
      sample.qdd = (joint_velocity(arm, q_after, after.body_twist, t_after, after.s) -
                    joint_velocity(arm, q_before, before.body_twist, t_before, before.s)) /
                   (t_after - t_before);
    } else {
      sample.qdd = Eigen::VectorXd::Zero(sample.q.size());
    }
    sample.static_torque = arm.static_torques(sample.q);
    sample.dynamic_torque = arm.torques(sample.q, sample.qd, sample.qdd) - sample.static_torque;

    const std::size_t index = report.samples.size();
    for (Eigen::Index i = 0; i < sample.q.size(); ++i) {
      const double excess = std::max(limits.lower(i) - sample.q(i), sample.q(i) - limits.upper(i));
      if (excess > report.position_excess) {
        report.position_excess = excess;
        report.position_joint = static_cast<int>(i);
        report.position_sample = index;
      }
      if (std::isfinite(limits.velocity(i))) {
        const double f = std::abs(sample.qd(i)) / limits.velocity(i);
        if (f > report.velocity_factor) {
          report.velocity_factor = f;
          report.velocity_joint = static_cast<int>(i);
          report.velocity_sample = index;
        }
      }
      if (limits.effort.size() == sample.q.size() && std::isfinite(limits.effort(i))) {
        const double holding = std::abs(sample.static_torque(i));
        if (holding >= limits.effort(i)) {
          std::ostringstream message;
          message << "joint " << arm.joint_names()[static_cast<std::size_t>(i)] << ": the static torque " << holding
                  << " N·m at " << where(t, here.s) << " reaches its effort limit " << limits.effort(i)
                  << " N·m: no speed makes this path feasible";
          throw std::runtime_error(message.str());
        }
        const double f = std::abs(sample.dynamic_torque(i)) / (limits.effort(i) - holding);
        if (f > report.acceleration_factor) {
          report.acceleration_factor = f;
          report.torque_joint = static_cast<int>(i);
          report.torque_sample = index;
        }
      }
    }
    q_prev = sample.q;
    report.samples.push_back(std::move(sample));
  }
  return report;
}

JointLimitReport check_joint_limits(const Trajectory& trajectory, const Hexapod& hexapod,
                                    const JointCheckOptions& options) {
  const std::vector<double> times = checked_times(trajectory, options);
  const double duration = trajectory.duration(), h = options.difference_step;
  auto leg_speeds = [&](const TrajectorySample& at) -> Eigen::VectorXd {
    return hexapod.leg_jacobian(at.pose) * at.body_twist.vector();
  };
  JointLimitReport report;
  for (const double t : times) {
    const TrajectorySample here = trajectory.sample(t);
    JointSample sample;
    sample.time = t;
    sample.s = here.s;
    sample.q = hexapod.leg_lengths(here.pose);
    sample.qd = leg_speeds(here);
    const double t_before = std::max(0.0, t - h), t_after = std::min(duration, t + h);
    sample.qdd = t_after > t_before
                     ? Eigen::VectorXd((leg_speeds(trajectory.sample(t_after)) - leg_speeds(trajectory.sample(t_before))) /
                                       (t_after - t_before))
                     : Eigen::VectorXd::Zero(6);
    const std::size_t index = report.samples.size();
    for (int k = 0; k < 6; ++k) {
      const double excess = std::max(hexapod.leg_min()(k) - sample.q(k), sample.q(k) - hexapod.leg_max()(k));
      if (excess > report.position_excess) {
        report.position_excess = excess;
        report.position_joint = k;
        report.position_sample = index;
      }
      const double f = std::abs(sample.qd(k)) / hexapod.leg_speed()(k);
      if (f > report.velocity_factor) {
        report.velocity_factor = f;
        report.velocity_joint = k;
        report.velocity_sample = index;
      }
    }
    report.samples.push_back(std::move(sample));
  }
  return report;
}

RetimeResult retime_by_scaling(const Path& path, const MetricSetd& set, const Limits& limits, ProfileKind profile,
                               const serial::SerialArm& arm, const Eigen::VectorXd& q_start,
                               const JointCheckOptions& options, int max_iterations) {
  require(max_iterations >= 1, "max_iterations", static_cast<long>(max_iterations), "must be ≥ 1");
  Limits scaled = limits;
  for (int iteration = 1; iteration <= max_iterations; ++iteration) {
    Trajectory trajectory = plan(path, set, scaled, profile);
    JointLimitReport report = check_joint_limits(trajectory, arm, q_start, options);
    if (report.position_excess > 0.0) {
      const JointSample& at = report.samples[report.position_sample];
      throw std::runtime_error("joint " + arm.joint_names()[static_cast<std::size_t>(report.position_joint)] +
                               " leaves its position range by " + std::to_string(report.position_excess) + " rad at " +
                               where(at.time, at.s) + ": slowing down cannot help");
    }
    if (report.velocity_factor <= 1.0 && report.acceleration_factor <= 1.0) {
      return RetimeResult{std::move(trajectory), scaled, iteration, std::move(report)};
    }
    // The seed's rule: velocity over FVEL, acceleration over FACC (each only when above 1).
    // The dynamic torque also grows with q̇² (centripetal and Coriolis terms), so a step may
    // fall short: hence the loop.
    if (report.velocity_factor > 1.0) scaled.velocity /= report.velocity_factor;
    if (report.acceleration_factor > 1.0) {
      scaled.acceleration /= report.acceleration_factor;
      // Keep the jerk-limited ramps in proportion (the time to reach a stays the same).
      if (scaled.jerk) *scaled.jerk /= report.acceleration_factor;
    }
  }
  throw std::runtime_error("re-timing did not converge in " + std::to_string(max_iterations) +
                           " plans (velocity limit now " + std::to_string(scaled.velocity) + " m/s, acceleration " +
                           std::to_string(scaled.acceleration) + " m/s²)");
}

}  // namespace dispkin
