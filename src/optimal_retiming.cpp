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
//
// The parameter. The planner maps DISP arc length s linearly onto each section (τ = (s − s_k)/L_k),
// so through a tangent junction the pose derivative per unit s steps by up to 1 % (the junction
// rule): harmless for point speeds, but a step in q̇ at speed is an impulse in q̈ and in the
// torques. The re-timing therefore works in a parameter σ in which the pose derivative is
// continuous: each section gets a σ-length ℓ_k with ℓ_{k+1}/ℓ_k = |ξ_{k+1}(0)| / |ξ_k(1)| (the
// twists per unit τ on both sides of the junction, parallel by the junction rule). Point
// speeds are then σ̇ L_k/ℓ_k, so the DISP limits become σ̇ ≤ v_lim ℓ_k/L_k and |σ̈| ≤ a ℓ_k/L_k
// per section, and the result goes back to s section by section (ṡ = σ̇ L_k/ℓ_k: the time law
// in s steps at junctions exactly where the section lengths do, and the motion is smooth).
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
  // s at the start of section k, and the section holding s.
  static double section_start(const Trajectory& t, std::size_t k) { return t.starts_[k].s; }
  static std::size_t section_at(const Trajectory& t, double s) { return t.section_at(s, t.starts_.size()); }
  // Pose and body twist per unit τ of section k at τ.
  static void section_state(const Trajectory& t, std::size_t k, double tau, Posed& pose, Twistd& per_tau) {
    t.motions_.at(k, tau, pose, per_tau);
  }
};

}  // namespace detail
namespace {

using detail::HalfPlane;
using detail::TrajectoryAccess;

// The planned path by the smooth parameter σ (see the file comment), with each section's DISP
// limits expressed in σ.
class SmoothParameter {
 public:
  SmoothParameter(const Trajectory& planned, double acceleration) : planned_(planned) {
    const std::vector<double>& lengths = planned.section_lengths();
    const std::vector<double>& rests = planned.rest_positions();
    const std::size_t n = lengths.size();
    ell_.resize(n);
    sigma_start_.resize(n + 1);
    speed_.resize(n);
    acceleration_.resize(n);
    sigma_start_[0] = 0.0;
    Posed pose;
    Twistd out, in;
    for (std::size_t k = 0; k < n; ++k) {
      const bool run_start = std::binary_search(rests.begin(), rests.end(), TrajectoryAccess::section_start(planned, k));
      ell_[k] = lengths[k];
      if (k > 0 && !run_start && lengths[k] > 0.0) {
        TrajectoryAccess::section_state(planned, k - 1, 1.0, pose, out);
        TrajectoryAccess::section_state(planned, k, 0.0, pose, in);
        const double n_out = out.vector().norm(), n_in = in.vector().norm();
        if (n_out > 0.0 && n_in > 0.0 && ell_[k - 1] > 0.0) ell_[k] = ell_[k - 1] * n_in / n_out;
      }
      sigma_start_[k + 1] = sigma_start_[k] + ell_[k];
      // The DISP velocity limit of the section: the span of the plan's curve that holds it.
      double cap = std::numeric_limits<double>::infinity();
      const double middle = TrajectoryAccess::section_start(planned, k) + 0.5 * lengths[k];
      for (const Trajectory::SpeedLimit& span : planned.speed_limits()) {
        if (span.start_s <= middle && middle <= span.start_s + span.length) cap = std::min(cap, span.limit);
      }
      const double ratio = lengths[k] > 0.0 ? ell_[k] / lengths[k] : 1.0;  // σ per unit s
      speed_[k] = cap * ratio;
      acceleration_[k] = acceleration * ratio;
    }
    for (const double rest : rests) rest_sigma_.push_back(sigma_at(rest));
  }

  double length() const noexcept { return sigma_start_.back(); }
  const std::vector<double>& rests() const noexcept { return rest_sigma_; }
  std::size_t sections() const noexcept { return ell_.size(); }
  double start(std::size_t k) const noexcept { return sigma_start_[k]; }
  double ell(std::size_t k) const noexcept { return ell_[k]; }
  // ds/dσ on section k.
  double s_per_sigma(std::size_t k) const noexcept {
    return ell_[k] > 0.0 ? planned_.section_lengths()[k] / ell_[k] : 1.0;
  }

  // The section holding σ (the later one at a junction).
  std::size_t section_at(double sigma) const noexcept {
    const auto next = std::upper_bound(sigma_start_.begin(), sigma_start_.end() - 1, sigma);
    const std::size_t k = next == sigma_start_.begin() ? 0 : static_cast<std::size_t>(next - sigma_start_.begin()) - 1;
    return std::min(k, ell_.size() - 1);
  }

  // Pose and body twist per unit σ.
  void state(double sigma, Posed& pose, Twistd& per_sigma) const {
    const std::size_t k = section_at(sigma);
    const double tau = ell_[k] > 0.0 ? std::clamp((sigma - sigma_start_[k]) / ell_[k], 0.0, 1.0) : 0.0;
    TrajectoryAccess::section_state(planned_, k, tau, pose, per_sigma);
    per_sigma = per_sigma * (ell_[k] > 0.0 ? 1.0 / ell_[k] : 0.0);
  }

  // The DISP limits in σ over [σ0, σ1]: the lowest of the sections it touches.
  void limits_over(double sigma0, double sigma1, double& speed, double& acceleration) const noexcept {
    speed = acceleration = std::numeric_limits<double>::infinity();
    for (std::size_t k = section_at(sigma0); k < ell_.size() && sigma_start_[k] < sigma1; ++k) {
      speed = std::min(speed, speed_[k]);
      acceleration = std::min(acceleration, acceleration_[k]);
    }
  }

 private:
  double sigma_at(double s) const noexcept {
    const std::size_t k = TrajectoryAccess::section_at(planned_, s);
    const double length = planned_.section_lengths()[k];
    return sigma_start_[k] + (length > 0.0 ? (s - TrajectoryAccess::section_start(planned_, k)) / length * ell_[k] : 0.0);
  }

  const Trajectory& planned_;
  std::vector<double> ell_, sigma_start_, speed_, acceleration_, rest_sigma_;
};

// What the limits need of the joint path at one grid position σ.
struct GridPoint {
  double sigma;
  Eigen::VectorXd q, q1, q2;                    // q, dq/dσ, d²q/dσ²
  Eigen::VectorXd torque_u, torque_x, gravity;  // τ = torque_u·σ̈ + torque_x·σ̇² + gravity (empty: no dynamics)
};

// The joint limits (+∞ where none).
struct JointBounds {
  Eigen::VectorXd velocity, acceleration, effort;
};

// What the re-timing needs of a machine: its joints along the path, their limits, the torque
// coefficients where it has a dynamics model, and the dense check of a timed result.
class JointModel {
 public:
  virtual ~JointModel() = default;
  virtual int dof() const = 0;
  virtual std::string joint_name(int k) const = 0;
  virtual const char* position_unit() const = 0;
  // q on the branch of q_ref (Newton from `guess` where that applies) and q′ = dq/dσ.
  virtual void joints(const Posed& pose, const Twistd& per_sigma, const Eigen::VectorXd& q_ref,
                      const Eigen::VectorXd* guess, double s, Eigen::VectorXd& q, Eigen::VectorXd& q1) const = 0;
  // Fills p.gravity, p.torque_u, p.torque_x (left empty without a dynamics model).
  virtual void torque_coefficients(GridPoint& p) const = 0;
  virtual JointLimitReport check(const Trajectory& trajectory, const Eigen::VectorXd& q_start, int samples_between) const = 0;
  virtual JointBounds bounds(const OptimalRetimeOptions& options) const = 0;
};

class SerialModel final : public JointModel {
 public:
  explicit SerialModel(const serial::SerialArm& arm) : arm_(arm) {}
  int dof() const override { return arm_.dof(); }
  std::string joint_name(int k) const override { return arm_.joint_names()[static_cast<std::size_t>(k)]; }
  const char* position_unit() const override { return "rad"; }
  void joints(const Posed& pose, const Twistd& per_sigma, const Eigen::VectorXd& q_ref, const Eigen::VectorXd* guess,
              double s, Eigen::VectorXd& q, Eigen::VectorXd& q1) const override {
    constexpr double no_time = std::numeric_limits<double>::quiet_NaN();
    q = detail::tracked_solution(arm_, pose, q_ref, no_time, s, guess);
    q1 = detail::joint_velocity(arm_, q, per_sigma, no_time, s);
  }
  void torque_coefficients(GridPoint& p) const override {
    const Eigen::VectorXd zero = Eigen::VectorXd::Zero(p.q.size());
    p.gravity = arm_.static_torques(p.q);
    p.torque_u = arm_.torques(p.q, zero, p.q1) - p.gravity;
    p.torque_x = arm_.torques(p.q, p.q1, p.q2) - p.gravity;
  }
  JointLimitReport check(const Trajectory& trajectory, const Eigen::VectorXd& q_start, int samples_between) const override {
    JointCheckOptions options;
    options.samples_between = samples_between;
    return check_joint_limits(trajectory, arm_, q_start, options);
  }
  JointBounds bounds(const OptimalRetimeOptions& options) const override {
    const JointLimits joint = arm_.joint_limits();
    const int n = dof();
    JointBounds b{joint.velocity, options.joint_acceleration.size() ? options.joint_acceleration : none(n), none(n)};
    if (options.torque_limits && joint.effort.size() == n) b.effort = joint.effort;
    return b;
  }
  static Eigen::VectorXd none(int n) { return Eigen::VectorXd::Constant(n, std::numeric_limits<double>::infinity()); }

 private:
  const serial::SerialArm& arm_;
};

// A hexapod: the legs are the joints (ℓ = IK, ℓ′ = J_leg ξ′), no dynamics model.
class HexapodModel final : public JointModel {
 public:
  explicit HexapodModel(const Hexapod& hexapod) : hexapod_(hexapod) {}
  int dof() const override { return 6; }
  std::string joint_name(int k) const override { return "leg " + std::to_string(k + 1); }
  const char* position_unit() const override { return "m"; }
  void joints(const Posed& pose, const Twistd& per_sigma, const Eigen::VectorXd&, const Eigen::VectorXd*, double,
              Eigen::VectorXd& q, Eigen::VectorXd& q1) const override {
    q = hexapod_.leg_lengths(pose);
    q1 = hexapod_.leg_jacobian(pose) * per_sigma.vector();
  }
  void torque_coefficients(GridPoint&) const override {}
  JointLimitReport check(const Trajectory& trajectory, const Eigen::VectorXd&, int samples_between) const override {
    JointCheckOptions options;
    options.samples_between = samples_between;
    return check_joint_limits(trajectory, hexapod_, options);
  }
  JointBounds bounds(const OptimalRetimeOptions& options) const override {
    return {hexapod_.leg_speed(), options.joint_acceleration.size() ? options.joint_acceleration : SerialModel::none(6),
            SerialModel::none(6)};
  }

 private:
  const Hexapod& hexapod_;
};

// The joint path at σ, with d²q/dσ² by central differences inside [lo, hi] (one-sided at its
// ends: a run's ends are rests, where the path may turn a corner).
GridPoint grid_point(const SmoothParameter& path, const JointModel& model, double sigma, double h, double lo,
                     double hi, const Eigen::VectorXd& q_ref) {
  auto joint_path = [&](double at, const Eigen::VectorXd& reference, const Eigen::VectorXd* guess, Eigen::VectorXd& q,
                        Eigen::VectorXd& q1) {
    Posed pose;
    Twistd per_sigma;
    path.state(at, pose, per_sigma);
    model.joints(pose, per_sigma, reference, guess, at, q, q1);
  };
  GridPoint p;
  p.sigma = sigma;
  joint_path(sigma, q_ref, nullptr, p.q, p.q1);
  const double before = std::max(lo, sigma - h), after = std::min(hi, sigma + h);
  // Predicted to first order, so that Newton needs a single step.
  const Eigen::VectorXd guess_before = p.q - (sigma - before) * p.q1, guess_after = p.q + (after - sigma) * p.q1;
  Eigen::VectorXd q_before, q1_before, q_after, q1_after;
  joint_path(before, p.q, &guess_before, q_before, q1_before);
  joint_path(after, p.q, &guess_after, q_after, q1_after);
  p.q2 = (q1_after - q1_before) / (after - before);
  model.torque_coefficients(p);
  return p;
}

// The joint limits at one grid point as half-planes in (u, x), each limit multiplied by `scale`.
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
    if (std::isfinite(bounds.effort(k)) && p.gravity.size()) {
      const double t = scale * bounds.effort(k);
      out.push_back({p.torque_u(k), p.torque_x(k), t - p.gravity(k)});
      out.push_back({-p.torque_u(k), -p.torque_x(k), t + p.gravity(k)});
    }
  }
}

std::string interval_text(double s0, double s1) {
  std::ostringstream out;
  out << "[" << s0 << ", " << s1 << "] m";
  return out.str();
}

// The fastest timing of `path` for `model` (see the file comment); options already checked.
OptimalRetimeResult fastest_timing(const Path& path, const MetricSetd& set, const Limits& limits, const JointModel& model,
                                   const Eigen::VectorXd& q_start, const OptimalRetimeOptions& options) {
  require(options.grid_intervals >= 2, "grid_intervals", static_cast<long>(options.grid_intervals), "must be ≥ 2");
  require_positive(options.difference_step, "difference_step");
  require(options.check_samples_between >= 0, "check_samples_between",
          static_cast<long>(options.check_samples_between), "must be ≥ 0");
  require(options.max_refinements >= 0, "max_refinements", static_cast<long>(options.max_refinements), "must be ≥ 0");
  const int dof = model.dof();
  const Eigen::VectorXd& acceleration = options.joint_acceleration;
  require(acceleration.size() == 0 || acceleration.size() == dof, "joint_acceleration size",
          static_cast<long>(acceleration.size()), "must be 0 or the machine's dof " + std::to_string(dof));
  for (Eigen::Index k = 0; k < acceleration.size(); ++k) {
    require(acceleration(k) > 0.0, "joint_acceleration[" + std::to_string(k) + "]", acceleration(k), "must be > 0");
  }

  const Trajectory planned = plan(path, set, limits, ProfileKind::trapezoid);
  const SmoothParameter smooth(planned, limits.acceleration);
  const JointBounds bounds = model.bounds(options);
  // Path position s of a σ, for messages and the result.
  auto s_of = [&](double sigma) {
    const std::size_t k = smooth.section_at(sigma);
    return TrajectoryAccess::section_start(planned, k) + (sigma - smooth.start(k)) * smooth.s_per_sigma(k);
  };

  // The grid: each rest-to-rest run gets its share of the intervals.
  const std::vector<double>& rests = smooth.rests();
  struct Run {
    std::size_t first, count;  // grid points [first, first + count]
  };
  std::vector<Run> runs;
  std::vector<GridPoint> grid;
  Eigen::VectorXd q_ref = q_start;
  for (std::size_t r = 0; r + 1 < rests.size(); ++r) {
    const double lo = rests[r], hi = rests[r + 1];
    if (!(hi > lo)) continue;
    const auto count = static_cast<std::size_t>(std::max(2.0, std::round(options.grid_intervals * (hi - lo) / smooth.length())));
    const double h = options.difference_step * (hi - lo) / static_cast<double>(count);
    runs.push_back({grid.size(), count});
    for (std::size_t i = 0; i <= count; ++i) {
      const double sigma = i == count ? hi : lo + (hi - lo) * static_cast<double>(i) / static_cast<double>(count);
      grid.push_back(grid_point(smooth, model, sigma, h, lo, hi, q_ref));
      q_ref = grid.back().q;
    }
  }
  // Holding still must be possible everywhere (the seed's "cannot be reached by slowing down").
  for (const GridPoint& p : grid) {
    for (Eigen::Index k = 0; k < p.gravity.size(); ++k) {
      if (std::abs(p.gravity(k)) >= bounds.effort(k)) {
        std::ostringstream message;
        message << "joint " << model.joint_name(static_cast<int>(k)) << ": the static torque "
                << std::abs(p.gravity(k)) << " N·m at " << detail::where(std::nan(""), s_of(p.sigma))
                << " reaches its effort limit " << bounds.effort(k) << " N·m: no speed makes this path feasible";
        throw std::runtime_error(message.str());
      }
    }
  }

  OptimalRetimeResult result;
  // The grid solution sits exactly on its limits, and between grid points the coefficients
  // move by O(Δ²): 0.1 % headroom from the start spares the re-solve and re-check in most cases
  // (measured: first-pass overshoots of 2–3·10⁻⁴ on 100-interval grids of UR5e moves).
  double scale = 1.0 - 1e-3;
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
        const double delta = p_next.sigma - p.sigma;
        double speed, accel;
        smooth.limits_over(p.sigma, p_next.sigma, speed, accel);
        detail::GridInterval interval{delta, detail::ConvexPolygon(accel, speed * speed)};
        interval.admissible.clip({2.0 * delta, 1.0, speed * speed});  // at the interval's end as well
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
                                 interval_text(s_of(grid[i].sigma), s_of(grid[i + 1].sigma)) +
                                 " while still reaching the next rest");
      }
      // Back to s: constant σ̈ over each grid interval, cut where sections begin (ṡ = σ̇ ds/dσ).
      for (std::size_t i = 0; i < run.count; ++i) {
        const double sigma0 = grid[run.first + i].sigma, sigma1 = grid[run.first + i + 1].sigma;
        const double x0 = fastest.x[i], u = fastest.u[i];
        if (!(fastest.x[i] + fastest.x[i + 1] > 0.0)) {
          throw std::runtime_error("the joint limits allow no motion on the path interval " +
                                   interval_text(s_of(sigma0), s_of(sigma1)));
        }
        result.grid_s.push_back(s_of(sigma0));
        result.grid_speed.push_back(std::sqrt(x0) * smooth.s_per_sigma(smooth.section_at(sigma0)));
        for (double a = sigma0; a < sigma1;) {
          const std::size_t k = smooth.section_at(a);
          double b = k + 1 < smooth.sections() ? std::min(sigma1, smooth.start(k + 1)) : sigma1;
          if (!(b > a)) break;
          // A section boundary within rounding of the interval's end: one piece to the end (a
          // piece of 1e-15 m would only test the rounding of the trapezoid's feasibility check).
          if (sigma1 - b <= 1e-9 * (sigma1 - sigma0)) b = sigma1;
          if (b - a <= 1e-9 * (sigma1 - sigma0)) {  // the same at the interval's start
            a = b;
            continue;
          }
          const double r = smooth.s_per_sigma(k);
          const double v0 = r * std::sqrt(std::max(0.0, x0 + 2.0 * u * (a - sigma0)));
          const double v1 = r * std::sqrt(std::max(0.0, x0 + 2.0 * u * (b - sigma0)));
          const double distance = r * (b - a);
          // The trapezoid between v0 and v1 whose acceleration just covers the distance (a hair
          // above, so that rounding cannot make the law infeasible).
          const double acc = std::max(std::abs(v1 * v1 - v0 * v0) / (2.0 * distance) * (1.0 + 1e-9), 1e-12 * limits.acceleration);
          laws.push_back(Profile::trapezoid(distance, std::max(v0, v1), acc, v0, v1));
          a = b;
        }
      }
      const double end = grid[run.first + run.count].sigma;
      result.grid_s.push_back(s_of(end));
      result.grid_speed.push_back(std::sqrt(fastest.x.back()) * smooth.s_per_sigma(smooth.section_at(end)));
    }
    result.trajectory = TrajectoryAccess::with_laws(planned, laws, runs.size());

    // The dense check, with the whole torque against the effort limit.
    result.report = model.check(result.trajectory, q_start, options.check_samples_between);
    if (result.report.position_excess > 0.0) {
      const JointSample& at = result.report.samples[result.report.position_sample];
      throw std::runtime_error("joint " + model.joint_name(result.report.position_joint) +
                               " leaves its position range by " + std::to_string(result.report.position_excess) +
                               " " + model.position_unit() + " at " + detail::where(at.time, at.s) +
                               ": slowing down cannot help");
    }
    result.velocity_ratio = result.acceleration_ratio = result.torque_ratio = 0.0;
    for (const JointSample& sample : result.report.samples) {
      for (int k = 0; k < dof; ++k) {
        result.velocity_ratio = std::max(result.velocity_ratio, std::abs(sample.qd(k)) / bounds.velocity(k));
        result.acceleration_ratio = std::max(result.acceleration_ratio, std::abs(sample.qdd(k)) / bounds.acceleration(k));
        if (sample.static_torque.size() == dof) {
          const double torque = sample.static_torque(k) + sample.dynamic_torque(k);
          result.torque_ratio = std::max(result.torque_ratio, std::abs(torque) / bounds.effort(k));
        }
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

}  // namespace

OptimalRetimeResult retime_optimal(const Path& path, const MetricSetd& set, const Limits& limits,
                                   const serial::SerialArm& arm, const Eigen::VectorXd& q_start,
                                   const OptimalRetimeOptions& options) {
  require(q_start.size() == arm.dof(), "q_start size", static_cast<long>(q_start.size()),
          "must equal the arm's dof " + std::to_string(arm.dof()));
  require_finite(q_start, "q_start");
  return fastest_timing(path, set, limits, SerialModel(arm), q_start, options);
}

OptimalRetimeResult retime_optimal(const Path& path, const MetricSetd& set, const Limits& limits, const Hexapod& hexapod,
                                   const OptimalRetimeOptions& options) {
  return fastest_timing(path, set, limits, HexapodModel(hexapod), hexapod.leg_lengths(hexapod.home()), options);
}

}  // namespace dispkin
