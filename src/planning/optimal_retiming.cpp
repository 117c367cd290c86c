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
//
// Jerk limiting (limits.jerk = j). Each run's law σ(t) is replaced by its moving average over a
// window T (jerk_filter.hpp): σ⃛ is then (σ̈(t) − σ̈(t−T))/T, and T is the smallest window that
// keeps that ≤ j ρ, with ρ = dσ/ds the run's lowest (so s⃛ = σ⃛/ρ_k ≤ j in every section). The
// other limits are made to survive the average before the grid is solved:
//   - |σ̈| ≤ a ρ everywhere in the run: the average of accelerations within it stays within it;
//   - the averaged σ̇ at t is the mean of σ̇ over [t − T, t], where σ lies within T·max σ̇ of the
//     averaged position: every speed cap (the DISP velocity-limit curve in σ and the joint
//     speeds q̇ᵢ = q′ᵢ σ̇) is lowered to its minimum over that reach around each interval, so
//     the mean of the speeds is below the cap at the averaged position too;
//   - joint accelerations and torques mix σ̈ and σ̇² with coefficients that vary along the
//     path: they are left to the dense check and its tightening loop.
// T and max σ̇ are not known before the solve: the reach is estimated from a solve without it
// and widened and re-solved until the solve's own window and top speed stay within it (T never
// exceeds 2A/j, and tightening only lowers the speeds, so this settles).
// The run takes the solve's duration plus T, and T grows with the steps of σ̈: the solve is
// given an acceleration cap A ≤ aρ and a uniform speed cap V, both chosen by a scan and golden-
// section search to minimise that sum (a low jerk limit wants a lower A, as the S-curve's peak
// acceleration stays below a_max on short moves; a V below the joints' speed limits gives a
// flat cruise where the speed would otherwise follow a joint limit up and down). This is not
// the jerk-limited optimum (that problem is not convex in (σ̈, σ̇²)): measured against the seed's
// scaling with S-curves it is up to 3.5 % slower where the jerk binds more than the joints, and
// up to 12 % faster where the joints bind (benchmarks/RESULTS.md). The planner's own S-curve law
// and the seed's scaling (with the standing headroom) are taken instead where they pass the
// dense joint check with that headroom and are faster.
#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <sstream>
#include <string>

#include "dispkin/error.hpp"
#include "dispkin/planning/retiming.hpp"
#include "jerk_filter.hpp"
#include "reachability.hpp"

namespace dispkin {
namespace {

// The fraction of every joint limit kept free at the checked samples, for what happens between
// them: the grid laws are solved at (1 − this) of the limits, and a candidate law from elsewhere
// (the S-curve plan, the seed's scaling) must check out this far below them.
constexpr double standing_headroom = 1e-3;
// A candidate law has none of the grid laws' structure between its characteristic points (a joint
// speed may peak anywhere in a cruise): it is checked at least this densely (measured: 3 samples
// between missed a joint-speed peak by 0.1 % on a scaled UR5e move).
constexpr int candidate_samples_between = 10;

using detail::HalfPlane;

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
      const bool run_start = std::binary_search(rests.begin(), rests.end(), planned.path().section_start(k));
      ell_[k] = lengths[k];
      if (k > 0 && !run_start && lengths[k] > 0.0) {
        planned.path().section_state_at(k - 1, 1.0, pose, out);
        planned.path().section_state_at(k, 0.0, pose, in);
        const double n_out = out.vector().norm(), n_in = in.vector().norm();
        if (n_out > 0.0 && n_in > 0.0 && ell_[k - 1] > 0.0) ell_[k] = ell_[k - 1] * n_in / n_out;
      }
      sigma_start_[k + 1] = sigma_start_[k] + ell_[k];
      // The DISP velocity limit of the section: the span of the plan's curve that holds it.
      double cap = std::numeric_limits<double>::infinity();
      const double middle = planned.path().section_start(k) + 0.5 * lengths[k];
      for (const SpeedLimit& span : planned.speed_limits()) {
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
    planned_.path().section_state_at(k, tau, pose, per_sigma);
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
    const std::size_t k = planned_.path().section_at(s, planned_.section_count());
    const double length = planned_.section_lengths()[k];
    return sigma_start_[k] + (length > 0.0 ? (s - planned_.path().section_start(k)) / length * ell_[k] : 0.0);
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
  model.torque_coefficients(p.q, p.q1, p.q2, p.gravity, p.torque_u, p.torque_x);
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

// The cap on σ̇² from the joint velocity limits at one grid point (+∞ where none binds).
double joint_speed_cap(const GridPoint& p, const JointBounds& bounds, double scale) {
  double cap = std::numeric_limits<double>::infinity();
  for (Eigen::Index k = 0; k < p.q.size(); ++k) {
    if (std::isfinite(bounds.velocity(k)) && p.q1(k) != 0.0) {
      const double v = scale * bounds.velocity(k) / std::abs(p.q1(k));
      cap = std::min(cap, v * v);
    }
  }
  return cap;
}

// The grid solution of one run as a law in time: σ at the grid points, σ̇ = √x, σ̈ = u, and the
// time of each interval from its mean speed (exact for constant σ̈).
detail::AccelerationSteps acceleration_steps(const std::vector<GridPoint>& grid, std::size_t first, std::size_t count,
                                             const detail::Parameterisation& fastest) {
  detail::AccelerationSteps steps;
  steps.time.resize(count + 1);
  steps.position.resize(count + 1);
  steps.speed.resize(count + 1);
  steps.acceleration.resize(count);
  double time = 0.0;
  for (std::size_t i = 0; i <= count; ++i) {
    steps.time[i] = time;
    steps.position[i] = grid[first + i].sigma;
    steps.speed[i] = std::sqrt(fastest.x[i]);
    if (i == count) break;
    const double delta = grid[first + i + 1].sigma - grid[first + i].sigma;
    steps.acceleration[i] = fastest.u[i];
    time += 2.0 * delta / (std::sqrt(fastest.x[i]) + std::sqrt(fastest.x[i + 1]));
  }
  steps.speed.front() = steps.speed.back() = 0.0;
  return steps;
}

// σ at time τ into a phase (its Taylor polynomial), and the state there.
detail::JerkPhase advance(const detail::JerkPhase& p, double tau) {
  detail::JerkPhase out = p;
  out.duration = p.duration - tau;
  out.position = p.position + tau * (p.speed + tau * (0.5 * p.acceleration + p.jerk * tau / 6.0));
  out.speed = std::max(0.0, p.speed + tau * (p.acceleration + 0.5 * p.jerk * tau));
  out.acceleration = p.acceleration + p.jerk * tau;
  return out;
}

// A run's jerk-limited law in σ (constant-jerk phases ending at rest at `run_end`) as laws in
// s: cut where sections begin (ds/dσ changes there: ṡ, s̈, s⃛ are σ̇, σ̈, σ⃛ times the section's
// ds/dσ), at most Profile::max_phases phases per law.
void append_jerk_laws(const SmoothParameter& smooth, std::vector<detail::JerkPhase> phases, double run_end,
                      std::vector<Profile>& laws) {
  const double run_start = phases.front().position;
  // Cut at every section start inside the run; σ is non-decreasing, so by bisection on the
  // phase's cubic.
  std::vector<detail::JerkPhase> cut;
  cut.reserve(phases.size() + smooth.sections());
  std::size_t k = smooth.section_at(run_start) + 1;
  for (std::size_t m = 0; m < phases.size(); ++m) {
    detail::JerkPhase p = phases[m];
    const double next = m + 1 < phases.size() ? phases[m + 1].position : run_end;
    while (k < smooth.sections() && smooth.start(k) < run_end && smooth.start(k) <= p.position) ++k;
    while (k < smooth.sections() && smooth.start(k) < next && smooth.start(k) < run_end) {
      const double target = smooth.start(k);
      double lo = 0.0, hi = p.duration;
      for (int iteration = 0; iteration < 200 && hi - lo > 1e-15 * p.duration; ++iteration) {
        const double mid = 0.5 * (lo + hi);
        (advance(p, mid).position < target ? lo : hi) = mid;
      }
      if (hi > 1e-12 * p.duration && hi < p.duration * (1.0 - 1e-12)) {
        detail::JerkPhase head = p;
        head.duration = hi;
        cut.push_back(head);
        p = advance(p, hi);
        p.position = target;  // exactly on the section start
      }
      ++k;
    }
    cut.push_back(p);
  }
  // Group by section, at most max_phases per law.
  std::size_t first = 0;
  while (first < cut.size()) {
    auto section_of = [&](const detail::JerkPhase& p) { return smooth.section_at(advance(p, 0.5 * p.duration).position); };
    const std::size_t section = section_of(cut[first]);
    std::size_t last = first + 1;
    while (last < cut.size() && last - first < static_cast<std::size_t>(Profile::max_phases) && section_of(cut[last]) == section) ++last;
    const double r = smooth.s_per_sigma(section);
    double durations[Profile::max_phases], jerks[Profile::max_phases];
    for (std::size_t m = first; m < last; ++m) {
      durations[m - first] = cut[m].duration;
      jerks[m - first] = r * cut[m].jerk;
    }
    const detail::JerkPhase& a = cut[first];
    const double end_position = last < cut.size() ? cut[last].position : run_end;
    const double end_speed = last < cut.size() ? cut[last].speed : 0.0;
    const double end_acceleration = last < cut.size() ? cut[last].acceleration : 0.0;
    laws.push_back(Profile::from_phases(durations, jerks, static_cast<int>(last - first), r * a.speed, r * a.acceleration,
                                        r * std::max(0.0, end_position - a.position), r * end_speed, r * end_acceleration));
    first = last;
  }
}

std::string interval_text(double s0, double s1) {
  std::ostringstream out;
  out << "[" << s0 << ", " << s1 << "] m";
  return out.str();
}

// Golden-section search for the shortest `duration` of `evaluate(x)` over [lo, hi] in `iterations`
// steps, starting from `best` (a scan's winner); returns the best candidate seen.
template <typename Candidate, typename Evaluate>
Candidate golden_section(double lo, double hi, int iterations, Candidate best, Evaluate&& evaluate) {
  constexpr double golden = 0.6180339887498949;
  double x1 = hi - golden * (hi - lo), x2 = lo + golden * (hi - lo);  // x1 ≤ x2
  Candidate c1 = evaluate(x1), c2 = evaluate(x2);
  for (int iteration = 0;; ++iteration) {
    if (c1.duration < best.duration) best = c1;
    if (c2.duration < best.duration) best = c2;
    if (iteration == iterations) return best;
    if (c1.duration <= c2.duration) {  // the minimum lies in [lo, x2]
      hi = x2;
      x2 = x1;
      c2 = std::move(c1);
      x1 = hi - golden * (hi - lo);
      c1 = evaluate(x1);
    } else {  // in [x1, hi]
      lo = x1;
      x1 = x2;
      c1 = std::move(c2);
      x2 = lo + golden * (hi - lo);
      c2 = evaluate(x2);
    }
  }
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

  // The plan gives the DISP velocity-limit curve and the rests (the same for both profiles).
  if (limits.jerk) limits.validate(ProfileKind::scurve);
  Limits unjerked = limits;
  unjerked.jerk.reset();
  const Trajectory planned = plan(path, set, unjerked, ProfileKind::trapezoid);
  const SmoothParameter smooth(planned, limits.acceleration);
  const JointBounds bounds = model.bounds(options);
  // Path position s of a σ, for messages and the result.
  auto s_of = [&](double sigma) {
    const std::size_t k = smooth.section_at(sigma);
    return planned.path().section_start(k) + (sigma - smooth.start(k)) * smooth.s_per_sigma(k);
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

  // The dense check of r.trajectory, with the whole torque against the effort limit.
  auto measure = [&](OptimalRetimeResult& r, int samples_between) {
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
  };

  OptimalRetimeResult result;
  // The grid solution sits exactly on its limits, and between grid points the coefficients
  // move by O(Δ²): 0.1 % headroom from the start spares the re-solve and re-check in most cases
  // (measured: first-pass overshoots of 2–3·10⁻⁴ on 100-interval grids of UR5e moves).
  double scale = 1.0 - standing_headroom;
  std::vector<HalfPlane> at_start, at_end;
  for (int refinement = 0;; ++refinement) {
    std::vector<Profile> laws;
    result.grid_s.clear();
    result.grid_speed.clear();
    result.jerk_window = 0.0;
    for (const Run& run : runs) {
      const double run_start = grid[run.first].sigma, run_end = grid[run.first + run.count].sigma;
      // The grid problem of the run. With a jerk limit, `reach` > 0 widens every speed cap (the
      // DISP velocity-limit curve and the joint speeds) to its minimum over ±reach around the
      // interval, and the acceleration cap is the run's lowest: the moving average then keeps
      // them (see jerk_filter.hpp and the file comment).
      auto solve = [&](double reach, double run_acceleration, double run_speed = std::numeric_limits<double>::infinity()) {
        std::vector<detail::GridInterval> intervals;
        intervals.reserve(run.count);
        for (std::size_t i = run.first; i < run.first + run.count; ++i) {
          const GridPoint &p = grid[i], &p_next = grid[i + 1];
          const double delta = p_next.sigma - p.sigma;
          double speed, accel;
          smooth.limits_over(p.sigma, p_next.sigma, speed, accel);
          if (reach > 0.0) {
            double unused;
            smooth.limits_over(std::max(run_start, p.sigma - reach), std::min(run_end, p_next.sigma + reach), speed, unused);
          }
          if (run_acceleration > 0.0) accel = run_acceleration;
          speed = std::min(speed, run_speed);
          detail::GridInterval interval{delta, detail::ConvexPolygon(accel, speed * speed)};
          interval.admissible.clip({2.0 * delta, 1.0, speed * speed});  // at the interval's end as well
          at_start.clear();
          at_end.clear();
          append_limits(p, bounds, scale, at_start);
          append_limits(p_next, bounds, scale, at_end);
          for (const HalfPlane& h : at_start) interval.admissible.clip(h);
          for (const HalfPlane& h : at_end) interval.admissible.clip({h.a + 2.0 * delta * h.b, h.b, h.c});
          if (reach > 0.0) {
            double joint_speed = std::numeric_limits<double>::infinity();  // σ̇² cap of the joint speeds nearby
            for (std::size_t g = run.first; g <= run.first + run.count; ++g) {
              if (grid[g].sigma >= p.sigma - reach && grid[g].sigma <= p_next.sigma + reach) {
                joint_speed = std::min(joint_speed, joint_speed_cap(grid[g], bounds, scale));
              }
            }
            if (std::isfinite(joint_speed)) {
              interval.admissible.clip({0.0, 1.0, joint_speed});
              interval.admissible.clip({2.0 * delta, 1.0, joint_speed});
            }
          }
          intervals.push_back(std::move(interval));
        }
        detail::Parameterisation fastest = detail::fastest_parameterisation(std::move(intervals), 0.0, 0.0);
        if (fastest.infeasible_interval >= 0) {
          const std::size_t i = run.first + static_cast<std::size_t>(fastest.infeasible_interval);
          throw std::runtime_error("no speed keeps every joint limit on the path interval " +
                                   interval_text(s_of(grid[i].sigma), s_of(grid[i + 1].sigma)) +
                                   " while still reaching the next rest");
        }
        for (std::size_t i = 0; i < run.count; ++i) {
          if (!(fastest.x[i] + fastest.x[i + 1] > 0.0)) {
            throw std::runtime_error("the joint limits allow no motion on the path interval " +
                                     interval_text(s_of(grid[run.first + i].sigma), s_of(grid[run.first + i + 1].sigma)));
          }
        }
        return fastest;
      };
      auto record_grid = [&](const detail::Parameterisation& fastest) {
        for (std::size_t i = 0; i <= run.count; ++i) {
          const double sigma = grid[run.first + i].sigma;
          result.grid_s.push_back(s_of(sigma));
          result.grid_speed.push_back(std::sqrt(fastest.x[i]) * smooth.s_per_sigma(smooth.section_at(sigma)));
        }
      };

      if (limits.jerk) {
        // The run's lowest σ per s: its acceleration and jerk caps in σ are a ρ and j ρ.
        double rho = std::numeric_limits<double>::infinity();
        for (std::size_t k = smooth.section_at(run_start); k < smooth.sections() && smooth.start(k) < run_end; ++k) {
          if (smooth.ell(k) > 0.0) rho = std::min(rho, 1.0 / smooth.s_per_sigma(k));
        }
        const double top_acceleration = limits.acceleration * rho, run_jerk = *limits.jerk * rho;
        auto top_speed = [](const detail::Parameterisation& p) {
          return std::sqrt(*std::max_element(p.x.begin(), p.x.end()));
        };
        // The jerk-limited law under the acceleration cap A ≤ a ρ and the speed cap V: its window
        // and its duration.
        struct Candidate {
          double cap, speed, window, duration;
          detail::Parameterisation fastest;
          detail::AccelerationSteps steps;
        };
        auto jerk_limited = [&](double cap, double speed) {
          Candidate c{cap, speed, 0.0, std::numeric_limits<double>::infinity(), {}, {}};
          const double longest = 2.0 * cap / run_jerk;  // 2A/j: a window that always suffices
          // First without the reach: its window and its top speed (tightening only lowers the
          // speeds) estimate the reach; widened and re-solved until the solve keeps to it.
          c.fastest = solve(0.0, cap, speed);
          c.steps = acceleration_steps(grid, run.first, run.count, c.fastest);
          double assumed = detail::smallest_window(c.steps, run_jerk, longest);
          double speed_bound = top_speed(c.fastest);
          for (int attempt = 0;; ++attempt) {
            const double reach = assumed * speed_bound;
            c.fastest = solve(reach, cap, speed);
            c.steps = acceleration_steps(grid, run.first, run.count, c.fastest);
            c.window = detail::smallest_window(c.steps, run_jerk, longest);
            const double top = top_speed(c.fastest);
            if (c.window <= assumed && c.window * top <= reach) break;
            if (attempt == 20) {
              throw std::runtime_error("jerk limiting: the moving-average window did not settle on the path interval " +
                                       interval_text(s_of(run_start), s_of(run_end)));
            }
            assumed = std::min(longest, std::max(c.window, 1.25 * assumed));
            speed_bound = std::max(speed_bound, top);
          }
          c.duration = c.steps.time.back() + c.window;
          return c;
        };
        // The window grows with the steps of σ̈: where the jerk limit is low against the
        // accelerations the joints allow, a lower acceleration cap A gives a shorter law (as the
        // S-curve's peak acceleration stays below a_max when a/j is long against the move), and a
        // speed cap V below what the joints allow gives a flat cruise instead of a speed that
        // follows a joint limit up and down (each change a step of σ̈). (A, V) are chosen to
        // minimise the duration: for each V of a scan, a scan of A over three decades and a
        // golden-section search between the best A's neighbours.
        auto best_for_speed = [&](double speed) {
          constexpr int scan = 8;
          constexpr double decades = 3.0;
          auto cap_at = [&](double e) { return top_acceleration * std::pow(10.0, -decades * e); };  // e ∈ [0, 1]
          std::vector<Candidate> scanned;
          scanned.reserve(scan + 1);
          std::size_t best = 0;
          for (int i = 0; i <= scan; ++i) {
            scanned.push_back(jerk_limited(cap_at(static_cast<double>(i) / scan), speed));
            if (scanned.back().duration < scanned[best].duration) best = scanned.size() - 1;
          }
          // Between the best A's neighbours.
          return golden_section(std::max(0.0, (static_cast<double>(best) - 1.0) / scan),
                                std::min(1.0, (static_cast<double>(best) + 1.0) / scan), 8, scanned[best],
                                [&](double e) { return jerk_limited(cap_at(e), speed); });
        };
        // V as a fraction f of the top speed without a jerk limit (f = 1: no cap): a scan, then
        // golden-section search between the best fraction's neighbours.
        const double free_speed = top_speed(solve(0.0, top_acceleration));
        const std::vector<double> fractions{1.0, 0.95, 0.9, 0.8, 0.7, 0.6, 0.5, 0.4, 0.3};
        auto at_fraction = [&](double f) {
          return best_for_speed(f >= 1.0 ? std::numeric_limits<double>::infinity() : f * free_speed);
        };
        std::size_t best = 0;
        Candidate chosen = at_fraction(fractions[0]);
        for (std::size_t i = 1; i < fractions.size(); ++i) {
          Candidate c = at_fraction(fractions[i]);
          if (c.duration < chosen.duration) {
            chosen = std::move(c);
            best = i;
          }
        }
        // Between the best fraction's neighbours (fractions fall: the one after is the lower end).
        chosen = golden_section(fractions[std::min(best + 1, fractions.size() - 1)], fractions[best > 0 ? best - 1 : 0], 6,
                                std::move(chosen), at_fraction);
        const detail::Parameterisation& fastest = chosen.fastest;
        const detail::AccelerationSteps& steps = chosen.steps;
        const double window = chosen.window;
        result.jerk_window = std::max(result.jerk_window, window);
        record_grid(fastest);
        double end_time = 0.0;
        const std::vector<detail::JerkPhase> phases = detail::moving_average(steps, window, end_time);
        append_jerk_laws(smooth, phases, run_end, laws);
        continue;
      }

      const detail::Parameterisation fastest = solve(0.0, 0.0);
      record_grid(fastest);
      // Back to s: constant σ̈ over each grid interval, cut where sections begin (ṡ = σ̇ ds/dσ).
      for (std::size_t i = 0; i < run.count; ++i) {
        const double sigma0 = grid[run.first + i].sigma, sigma1 = grid[run.first + i + 1].sigma;
        const double x0 = fastest.x[i], u = fastest.u[i];
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
          // above, so that rounding cannot make the law infeasible). |v1 − v0| (v1 + v0), the form
          // of the trapezoid's own check: v1² − v0² cancels when the speeds nearly agree.
          const double acc = std::max(std::abs(v1 - v0) * (v1 + v0) / (2.0 * distance) * (1.0 + 1e-9), 1e-12 * limits.acceleration);
          laws.push_back(Profile::trapezoid(distance, std::max(v0, v1), acc, v0, v1));
          a = b;
        }
      }
    }
    result.trajectory = planned.with_time_law(TimeLaw::consecutive(laws, runs.size()));

    measure(result, options.check_samples_between);
    const double worst = std::max({result.velocity_ratio, result.acceleration_ratio, result.torque_ratio});
    result.margin = 1.0 - scale;
    result.refinements = refinement;
    if (worst <= 1.0) {
      // With a jerk limit, two more candidates under the same dense check: the planner's own
      // S-curve law, which may already keep every joint limit (where the jerk alone binds, the
      // S-curve is the optimum the average only approaches), and the seed's scaling with the
      // S-curve (the averaged law is not the jerk-limited optimum and can lose to it by a few
      // per cent where the jerk binds more than the joints). The fastest that passes is the result.
      if (limits.jerk) {
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
          measure(direct, std::max(options.check_samples_between, candidate_samples_between));
          // The same headroom as the grid laws' own: a law at its limits at the checked samples
          // may exceed them between (measured: 3·10⁻⁵ on a scaled UR5e move).
          if (std::max({direct.velocity_ratio, direct.acceleration_ratio, direct.torque_ratio}) <= 1.0 - standing_headroom) {
            direct.jerk_window = 0.0;
            return direct;
          }
        }
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

std::optional<Trajectory> JointModel::scaled_scurve(const Path&, const MetricSetd&, const Limits&, const Eigen::VectorXd&,
                                                 double) const {
  return std::nullopt;
}

OptimalRetimeResult retime_optimal(const Path& path, const MetricSetd& set, const Limits& limits, const JointModel& model,
                                   const Eigen::VectorXd& q_start, const OptimalRetimeOptions& options) {
  require(q_start.size() == model.dof(), "q_start size", static_cast<long>(q_start.size()),
          "must equal the machine's dof " + std::to_string(model.dof()));
  require_finite(q_start, "q_start");
  return fastest_timing(path, set, limits, model, q_start, options);
}

}  // namespace dispkin
