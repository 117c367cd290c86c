// Joint-limit prediction and re-timing for a serial arm (serial_retiming.hpp): its check, the KUKA
// re-timing patent's scaling loop, and the arm as a JointModel for retime_optimal.
#include "dispkin/serial/serial_retiming.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include <Eigen/LU>

#include "dispkin/error.hpp"
#include "dispkin/planning/trajectory_acceleration.hpp"
#include "dispkin/serial/followed_trajectory.hpp"
#include "joint_following.hpp"
#include "redundancy_rule.hpp"
#include "redundancy_schedule.hpp"

namespace dispkin::serial {
using detail::branch_solution;
using detail::joint_velocity;
using dispkin::detail::where;

namespace {

// Adds a sample (q, q̇, q̈ and the torques) to the report: its position excess and its share of
// FVEL and FACC (doc/retiming.md (eq. 4) and (eq. 5)). Throws std::runtime_error where the static
// torque alone reaches an effort limit (doc/retiming.md eq. 6).
void add_sample(JointLimitReport& report, JointSample sample, const SerialArm& arm, const JointLimits& limits,
                double s) {
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
                << " N·m at " << where(sample.time, s) << " reaches its effort limit " << limits.effort(i)
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
  report.samples.push_back(std::move(sample));
}

// The phase of `law` running at t: its piece and the phase within it.
std::pair<std::size_t, int> phase_at(const TimeLaw& law, double t) noexcept {
  const std::size_t piece = law.piece_at(t, law.size());
  const TimeLaw::Piece& p = law.pieces()[piece];
  int phase = 0;
  while (phase + 1 < p.profile.phase_count() && p.profile.phase_start_time(phase + 1) <= t - p.start_time) ++phase;
  return {piece, phase};
}

// Whether the tool's acceleration is continuous on [t0, t1]: one phase of one law (the
// acceleration of a trapezoid steps between phases) and one section of the path (the pose's
// second derivative steps at a junction). Only there is q̈ taken in closed form (doc/retiming.md
// (doc/retiming.md eq. 27)); across a step the central difference of (eq. 2) stays, as the check has always
// measured it.
bool acceleration_continuous(const Trajectory& trajectory, double t0, double t1) noexcept {
  const TimeLaw& law = trajectory.time_law();
  if (phase_at(law, t0) != phase_at(law, t1)) return false;
  std::size_t piece = law.size();
  const double s0 = law.state_at(t0, piece).s, s1 = law.state_at(t1, piece).s;
  const SampledPath& path = trajectory.path();
  return path.section_at(s0, path.section_count()) == path.section_at(s1, path.section_count());
}

// What the joints at a trajectory sample are solved with: q_ref with the parameter's value θ(s),
// and θ̇ = θ′ ṡ, θ̈ = θ″ ṡ² + θ′ s̈ (doc/inverse-kinematics.md eq. 48); q_ref itself (not a copy)
// and zero rates where the parameter is held.
struct ParameterAt {
  const Eigen::VectorXd& reference;
  detail::ParameterRates rates;
};

// At path position s moving at rate r and acceleration a (per second, or per unit σ of the
// re-timing grid): θ at s, r θ′ and r² θ″ + a θ′. `moved` holds the reference where the parameter moves.
ParameterAt parameter_at(const detail::RedundancySchedule& schedule, double s, double r, double a,
                         const Eigen::VectorXd& q_ref, Eigen::VectorXd& moved) {
  if (!schedule.moves()) return {q_ref, {}};
  const detail::RedundancySchedule::State theta = schedule.at(s);
  moved = schedule.reference(q_ref, theta.value);
  return {moved, {theta.rate * r, theta.curvature * r * r + theta.rate * a}};
}

ParameterAt parameter_at(const detail::RedundancySchedule& schedule, const TrajectorySample& here,
                         const Eigen::VectorXd& q_ref, Eigen::VectorXd& moved) {
  return parameter_at(schedule, here.s, here.s_dot, here.s_ddot, q_ref, moved);
}

}  // namespace

JointLimitReport check_joint_limits(const Trajectory& trajectory, const SerialArm& arm, const Eigen::VectorXd& q_start,
                                    const JointCheckOptions& options, const RedundancyRule& redundancy_rule) {
  const std::vector<double> times = checked_times(trajectory, options);
  require(q_start.size() == arm.dof(), "q_start size", static_cast<long>(q_start.size()),
          "must equal the arm's dof " + std::to_string(arm.dof()));
  require_finite(q_start, "q_start");
  detail::require_valid(redundancy_rule);
  // θ(s) on FollowedTrajectory's default grid: the check sees the joints from_start gives.
  const detail::RedundancySchedule schedule(trajectory.path(), arm, q_start, false, FollowedTrajectory::default_spacing,
                                            redundancy_rule);
  const JointLimits limits = arm.joint_limits();
  JointLimitReport report;
  report.samples.reserve(times.size());
  const double duration = trajectory.duration();
  const double h = options.difference_step;
  Eigen::VectorXd q_prev = q_start, guess, moved, moved_before, moved_after;
  for (std::size_t k = 0; k < times.size(); ++k) {
    const double t = times[k];
    const TrajectorySample here = trajectory.sample(t);
    JointSample sample;
    sample.time = t;
    sample.s = here.s;
    // Newton from the previous instant's q moved on by its q̇ and q̈ (second order): one step
    // from there reaches the tolerance.
    const JointSample* previous = k ? &report.samples.back() : nullptr;
    if (previous) {
      const double dt = t - previous->time;
      guess = q_prev + dt * previous->qd + (0.5 * dt * dt) * previous->qdd;
    }
    const ParameterAt parameter = parameter_at(schedule, here, q_prev, moved);
    sample.q = branch_solution(arm, here.pose, parameter.reference, t, here.s, previous ? &guess : nullptr);
    const double t_before = std::max(0.0, t - h), t_after = std::min(duration, t + h);
    if (t - h >= 0.0 && t + h <= duration && acceleration_continuous(trajectory, t_before, t_after)) {
      // q̇ and q̈ from one factorisation of J_b (doc/retiming.md eq. 27), τ and g(q) on the pass that gave J_b;
      // τ − g(q) formed in place.
      detail::joint_rates_and_torques(arm, sample.q, here.body_twist, body_acceleration(trajectory, t), t, here.s,
                                      sample.qd, sample.qdd, sample.dynamic_torque, sample.static_torque,
                                      parameter.rates);
      sample.dynamic_torque -= sample.static_torque;
    } else {
      sample.qd = joint_velocity(arm, sample.q, here.body_twist, t, here.s, parameter.rates.rate);
      // q̈ by central differences of the Jacobian velocities (one-sided at the ends).
      if (t_after > t_before) {
        const TrajectorySample before = trajectory.sample(t_before), after = trajectory.sample(t_after);
        const ParameterAt at_before = parameter_at(schedule, before, sample.q, moved_before);
        const ParameterAt at_after = parameter_at(schedule, after, sample.q, moved_after);
        // Predicted to first order, so that Newton needs a single step.
        const Eigen::VectorXd guess_before = sample.q - (t - t_before) * sample.qd;
        const Eigen::VectorXd guess_after = sample.q + (t_after - t) * sample.qd;
        const Eigen::VectorXd q_before =
            branch_solution(arm, before.pose, at_before.reference, t_before, before.s, &guess_before);
        const Eigen::VectorXd q_after =
            branch_solution(arm, after.pose, at_after.reference, t_after, after.s, &guess_after);
        sample.qdd = (joint_velocity(arm, q_after, after.body_twist, t_after, after.s, at_after.rates.rate) -
                      joint_velocity(arm, q_before, before.body_twist, t_before, before.s, at_before.rates.rate)) /
                     (t_after - t_before);
      } else {
        sample.qdd = Eigen::VectorXd::Zero(sample.q.size());
      }
      // τ and g(q) in one pass (doc/retiming.md eq. 3).
      arm.torques(sample.q, sample.qd, sample.qdd, sample.dynamic_torque, sample.static_torque);
      sample.dynamic_torque -= sample.static_torque;
    }

    add_sample(report, std::move(sample), arm, limits, here.s);
    q_prev = report.samples.back().q;
  }
  require_consistent(report);  // what a stored report is checked for, a made one holds too
  return report;
}

JointLimitReport check_joint_limits(const JointTrajectory& trajectory, const SerialArm& arm,
                                    const std::vector<double>& times) {
  require(trajectory.dof() == arm.dof(), "trajectory dof", static_cast<long>(trajectory.dof()),
          "must equal the arm's dof " + std::to_string(arm.dof()));
  const JointLimits limits = arm.joint_limits();
  JointLimitReport report;
  for (const double t : times) {
    require(std::isfinite(t), "times", t, "must be finite");
    const JointTrajectorySample here = trajectory.sample(t);
    JointSample sample;
    sample.time = t;
    sample.s = here.s;
    sample.q = here.q;
    sample.qd = here.qd;
    sample.qdd = here.qdd;
    Eigen::VectorXd torque;
    arm.torques(sample.q, sample.qd, sample.qdd, torque, sample.static_torque);
    sample.dynamic_torque = torque - sample.static_torque;
    add_sample(report, std::move(sample), arm, limits, here.s);
  }
  require_consistent(report);  // what a stored report is checked for, a made one holds too
  return report;
}

FollowedJoints follow_joints(const Trajectory& trajectory, const SerialArm& arm, const Eigen::VectorXd& q_start,
                             const std::vector<double>& times, double difference_step) {
  require_positive(difference_step, "difference_step");
  const auto count = static_cast<Eigen::Index>(times.size());
  const Eigen::Index n = arm.dof();
  for (const double t : times) require(std::isfinite(t), "times", t, "must be finite");
  std::vector<Posed> poses;
  poses.reserve(times.size());
  for (const double t : times) poses.push_back(trajectory.sample(t).pose);
  // A redundant arm's parameter stays at q_start's value: the Jacobian velocities below keep it
  // still (doc/inverse-kinematics.md (eq. 42)).
  RedundancyRule kept;
  kept.move = false;
  const std::vector<Eigen::VectorXd> q = follow(arm, poses, q_start, {}, kept);
  FollowedJoints out{Eigen::MatrixXd(count, n), Eigen::MatrixXd(count, n), Eigen::MatrixXd(count, n)};
  const double duration = trajectory.duration();
  for (Eigen::Index k = 0; k < count; ++k) {
    const double t = times[static_cast<std::size_t>(k)];
    const Eigen::VectorXd& q_k = q[static_cast<std::size_t>(k)];
    out.q.row(k) = q_k.transpose();
    out.qd.row(k) = joint_velocity(arm, q_k, trajectory.sample(t).body_twist).transpose();
    // q̈ by central differences of the Jacobian velocities (one-sided at the ends), each neighbour
    // on the branch of q_k (doc/retiming.md (eq. 2)).
    const double t_before = std::max(t - difference_step, 0.0), t_after = std::min(t + difference_step, duration);
    if (!(t_after > t_before)) {
      out.qdd.row(k).setZero();
      continue;
    }
    Eigen::VectorXd rate[2];
    const double at[2] = {t_before, t_after};
    for (int side = 0; side < 2; ++side) {
      const TrajectorySample neighbour = trajectory.sample(at[side]);
      const Eigen::VectorXd q_side = follow(arm, {neighbour.pose}, q_k, {}, kept).front();
      rate[side] = joint_velocity(arm, q_side, neighbour.body_twist);
    }
    out.qdd.row(k) = ((rate[1] - rate[0]) / (t_after - t_before)).transpose();
  }
  return out;
}

RetimeResult retime_by_scaling(const Path& given_path, const MetricSetd& set, const Limits& limits, ProfileKind profile,
                               const SerialArm& arm, const Eigen::VectorXd& q_start, const JointCheckOptions& options,
                               int max_iterations, double corner_tolerance, const RedundancyRule& redundancy_rule) {
  require(max_iterations >= 1, "max_iterations", static_cast<long>(max_iterations), "must be ≥ 1");
  PlanOptions continuous;
  continuous.corner_tolerance = corner_tolerance;
  const std::optional<Path> blended = continuous_path(given_path, continuous);
  const Path& path = blended ? *blended : given_path;
  Limits scaled = limits;
  for (int iteration = 1; iteration <= max_iterations; ++iteration) {
    Trajectory trajectory = plan(path, set, scaled, profile);
    JointLimitReport report = check_joint_limits(trajectory, arm, q_start, options, redundancy_rule);
    if (report.position_excess > 0.0) {
      const JointSample& at = report.samples[report.position_sample];
      throw std::runtime_error("joint " + arm.joint_names()[static_cast<std::size_t>(report.position_joint)] +
                               " leaves its position range by " + std::to_string(report.position_excess) + " rad at " +
                               where(at.time, at.s) + ": slowing down cannot help");
    }
    if (report.velocity_factor <= 1.0 && report.acceleration_factor <= 1.0) {
      return RetimeResult{std::move(trajectory), scaled, iteration, std::move(report)};
    }
    // The KUKA re-timing patent's rule: velocity over FVEL, acceleration over FACC (each only when above 1).
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

namespace {

// The arm as a JointModel. With a moving redundancy rule and its schedule θ(s) on a planned path
// (along()), the joints are solved at θ(s) with θ′ and θ″ per unit σ (doc/inverse-kinematics.md
// eq. 51): the joints check_joint_limits with the same rule sees on that path.
class SerialModel final : public JointModel {
 public:
  SerialModel(const SerialArm& arm, const RedundancyRule& rule) : arm_(arm), rule_(rule) {}
  SerialModel(const SerialArm& arm, const RedundancyRule& rule, detail::RedundancySchedule schedule)
      : arm_(arm), rule_(rule), schedule_(std::move(schedule)) {}
  int dof() const override { return arm_.dof(); }
  std::string joint_name(int k) const override { return arm_.joint_names()[static_cast<std::size_t>(k)]; }
  const char* position_unit() const override { return "rad"; }
  void joints(const Posed& pose, const Twistd& per_sigma, const Eigen::VectorXd& q_ref, const Eigen::VectorXd* guess,
              const PathPlace& place, Eigen::VectorXd& q, Eigen::VectorXd& q1) const override {
    constexpr double no_time = std::numeric_limits<double>::quiet_NaN();
    Eigen::VectorXd moved;
    const ParameterAt parameter = parameter_at(place, q_ref, moved);
    q = detail::branch_solution(arm_, pose, parameter.reference, no_time, place.s, guess);
    q1 = detail::joint_velocity(arm_, q, per_sigma, no_time, place.s, parameter.rates.rate);
  }
  bool joints_with_rate(const Posed& pose, const Twistd& per_sigma, const Twistd& per_sigma_rate,
                        const Eigen::VectorXd& q_ref, const Eigen::VectorXd* guess, const PathPlace& place,
                        Eigen::VectorXd& q, Eigen::VectorXd& q1, Eigen::VectorXd& q2) const override {
    constexpr double no_time = std::numeric_limits<double>::quiet_NaN();
    Eigen::VectorXd moved;
    const ParameterAt parameter = parameter_at(place, q_ref, moved);
    q = detail::branch_solution(arm_, pose, parameter.reference, no_time, place.s, guess);
    // q′ and q″ from one factorisation of J_b (doc/retiming.md (eq. 28)), with θ′ and θ″ per unit σ.
    detail::joint_rates(arm_, q, per_sigma, per_sigma_rate, no_time, place.s, q1, q2, parameter.rates);
    return true;
  }
  void rate_steps(const Eigen::VectorXd& q, const Eigen::VectorXd& q2, const PathPlace& place, double s_before,
                  double s_after, std::vector<Eigen::VectorXd>& q2_other) const override {
    q2_other.clear();
    if (!schedule_.moves()) return;
    // θ″ steps at the schedule's nodes (doc/inverse-kinematics.md eq. 50), and q″ is affine in it:
    // q″ + Δθ″ n with the self-motion n of doc/inverse-kinematics.md eq. 43 (eq. 48), per unit σ
    // (eq. 51). The lowest and the highest θ″ nearby bound every value between.
    double low, high;
    schedule_.curvature_range(s_before, s_after, low, high);
    const double here = schedule_.at(place.s).curvature;
    if (low == here && high == here) return;
    constexpr double no_time = std::numeric_limits<double>::quiet_NaN();
    const Twistd still(Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero());
    const Eigen::VectorXd n = detail::joint_velocity(arm_, q, still, no_time, place.s, 1.0);
    const double r2 = place.s_per_sigma * place.s_per_sigma;
    for (const double curvature : {low, high}) {
      if (curvature != here) q2_other.push_back(q2 + ((curvature - here) * r2) * n);
    }
  }
  bool rates_step() const override { return schedule_.moves(); }
  std::unique_ptr<JointModel> along(const Trajectory& planned, const Eigen::VectorXd& q_start) const override {
    // θ(s) on the nodes check_joint_limits takes (FollowedTrajectory's default spacing): the
    // grid's joints are the check's.
    detail::RedundancySchedule schedule(planned.path(), arm_, q_start, false, FollowedTrajectory::default_spacing,
                                        rule_);
    if (!schedule.moves()) return nullptr;
    return std::make_unique<SerialModel>(arm_, rule_, std::move(schedule));
  }
  void torque_coefficients(const Eigen::VectorXd& q, const Eigen::VectorXd& q1, const Eigen::VectorXd& q2,
                           Eigen::VectorXd& gravity, Eigen::VectorXd& torque_u,
                           Eigen::VectorXd& torque_x) const override {
    // g = τ(q, 0, 0), M q′ = τ(q, 0, q′) − g, M q″ + C(q, q′) q′ = τ(q, q′, q″) − g (doc/retiming.md
    // (doc/retiming.md eq. 12)); g comes with the last of them, from the same pass.
    const Eigen::VectorXd zero = Eigen::VectorXd::Zero(q.size());
    arm_.torques(q, q1, q2, torque_x, gravity);
    torque_u = arm_.torques(q, zero, q1) - gravity;
    torque_x -= gravity;
  }
  JointLimitReport check(const Trajectory& trajectory, const Eigen::VectorXd& q_start,
                         int samples_between) const override {
    JointCheckOptions options;
    options.samples_between = samples_between;
    return check_joint_limits(trajectory, arm_, q_start, options, rule_);
  }
  std::optional<Trajectory> scaled_scurve(const Path& path, const MetricSetd& set, const Limits& limits,
                                          const Eigen::VectorXd& q_start, double headroom) const override {
    // Run with the joint speed and effort limits 0.1 % lower, as the grid laws are solved: the
    // loop converges onto its limits at its check points, and a candidate needs that clearance.
    JointLimits held_back = arm_.joint_limits();
    held_back.velocity *= 1.0 - headroom;
    held_back.effort *= 1.0 - headroom;
    try {
      return retime_by_scaling(path, set, limits, ProfileKind::scurve, arm_.with_joint_limits(held_back), q_start, {},
                               20, 0.0, rule_)
          .trajectory;
    } catch (const std::runtime_error&) {
      return std::nullopt;  // the loop did not converge (or slowing down cannot help): no candidate
    }
  }
  JointBounds bounds(const OptimalRetimeOptions& options) const override {
    const JointLimits joint = arm_.joint_limits();
    const int n = dof();
    JointBounds b{joint.velocity,
                  options.joint_acceleration.size() ? options.joint_acceleration : JointBounds::unlimited(n),
                  JointBounds::unlimited(n)};
    if (options.torque_limits && joint.effort.size() == n) b.effort = joint.effort;
    return b;
  }

 private:
  // What the joints at `place` are solved with: q_ref with the parameter at θ(s), and per unit σ
  // θ′ ds/dσ and θ″ (ds/dσ)² (doc/inverse-kinematics.md eq. 51); q_ref itself and zero rates
  // where the parameter is held. `moved` holds the reference where it moves.
  ParameterAt parameter_at(const PathPlace& place, const Eigen::VectorXd& q_ref, Eigen::VectorXd& moved) const {
    // ds/dσ is constant within a section: no θ′ d²s/dσ² term.
    return serial::parameter_at(schedule_, place.s, place.s_per_sigma, 0.0, q_ref, moved);
  }

  const SerialArm& arm_;
  RedundancyRule rule_;
  detail::RedundancySchedule schedule_;  // none (held) unless made by along()
};

}  // namespace

std::unique_ptr<JointModel> joint_model(const SerialArm& arm, const RedundancyRule& redundancy_rule) {
  detail::require_valid(redundancy_rule);
  return std::make_unique<SerialModel>(arm, redundancy_rule);
}

OptimalRetimeResult retime_optimal(const Path& path, const MetricSetd& set, const Limits& limits, const SerialArm& arm,
                                   const Eigen::VectorXd& q_start, const OptimalRetimeOptions& options,
                                   const RedundancyRule& redundancy_rule) {
  require(q_start.size() == arm.dof(), "q_start size", static_cast<long>(q_start.size()),
          "must equal the arm's dof " + std::to_string(arm.dof()));
  require_finite(q_start, "q_start");
  detail::require_valid(redundancy_rule);
  return retime_optimal(path, set, limits, SerialModel(arm, redundancy_rule), q_start, options);
}

}  // namespace dispkin::serial
