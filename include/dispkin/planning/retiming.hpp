//! Joint-limit prediction and re-timing of a planned Cartesian trajectory, for any machine whose
//! joints follow the path (doc/retiming.md).
//!
//! A machine enters through the JointModel interface: its joint positions along the path (the
//! branch continuous from a start configuration) and their derivative per unit of path, its
//! joint limits, and, where it has a dynamics model, the torque coefficients. The serial-arm
//! and hexapod plugins implement it (serial/serial_retiming.hpp, hexapod/hexapod_retiming.hpp,
//! which also hold their check_joint_limits and the KUKA re-timing patent's scaling loop).
//!
//! check_joint_limits samples the trajectory at the profile's characteristic points (every
//! phase boundary and phase middle of every time law) and at `samples_between` equidistant
//! times between consecutive ones, and reports the factors of the KUKA re-timing patent ("The
//! robot drives through a preset working track", Burkhart et al., filed 2018-11-12):
//!   FVEL = maxᵢ |q̇ᵢ| / q̇maxᵢ,   FACC = maxᵢ |τdyn,ᵢ| / (τmaxᵢ − |τsta,ᵢ|).
//!
//! retime_optimal is the fastest path parameterisation that keeps the DISP limits and the
//! joint velocity, acceleration and torque limits at once, slowing down only where a limit
//! binds (reachability analysis over a grid of s, as in TOPP-RA). With a jerk limit
//! (limits.jerk) it is followed by jerk limiting: each rest-to-rest run's law is replaced by its
//! moving average over a window T ≤ 2a/j (a/j, the S-curve's, wherever the acceleration does not
//! reverse within T), whose jerk is bounded by j; the speed caps are tightened beforehand to their
//! minimum over the distance the window spans, so the DISP limits still hold rigorously, and the
//! joint limits through the same dense check and refinement.
#pragma once

#include <cmath>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "dispkin/path/path.hpp"
#include "dispkin/planning/planner.hpp"

namespace dispkin {

//! Options of the dense joint-limit check (check_joint_limits).
struct JointCheckOptions {
  int samples_between = 10;  //!< equidistant samples between characteristic points, ≥ 0
  //! Time step of the central differences for q̈ (s), > 0.
  double difference_step = 1e-4;
};

//! The machine's joint state at one checked instant.
struct JointSample {
  //! The instant (s) and the path position there (m).
  //!@{
  double time = 0.0, s = 0.0;
  //!@}
  //! The joint positions, velocities and accelerations q, q̇, q̈.
  //!@{
  Eigen::VectorXd q, qd, qdd;
  //!@}
  //! The static torque g(q) and the dynamic torque τ(q, q̇, q̈) − g(q).
  //!@{
  Eigen::VectorXd static_torque, dynamic_torque;
  //!@}
};

//! What check_joint_limits found.
struct JointLimitReport {
  std::vector<JointSample> samples;  //!< the joint state at every checked instant, in time order
  double velocity_factor = 0.0;      //!< FVEL (0 if no joint states a velocity limit)
  double acceleration_factor = 0.0;  //!< FACC (0 if no joint states an effort limit)
  int velocity_joint = -1;           //!< the joint where FVEL is reached (−1: none)
  std::size_t velocity_sample = 0;   //!< the index in `samples` where FVEL is reached
  int torque_joint = -1;             //!< the joint where FACC is reached (−1: none)
  std::size_t torque_sample = 0;     //!< the index in `samples` where FACC is reached
  double position_excess = 0.0;      //!< largest excursion of q outside [lower, upper] (rad), 0 if none
  int position_joint = -1;           //!< the joint of the largest excursion (−1: none)
  std::size_t position_sample = 0;   //!< the index in `samples` of the largest excursion

  //! FVEL ≤ 1, FACC ≤ 1 and no joint outside its position range.
  bool within_limits() const noexcept {
    return velocity_factor <= 1.0 && acceleration_factor <= 1.0 && position_excess == 0.0;
  }
};

//! What every report satisfies (check_joint_limits makes it so; a stored one is checked):
//! every sample has q, q̇, q̈ of one size n ≥ 1 and torques of one size (n, or 0 for a machine
//! without a dynamics model), every number finite; the factors and the
//! position excess finite and ≥ 0; each joint index −1 (none) or below n and each sample index
//! naming a sample. Throws std::invalid_argument naming the field otherwise.
inline void require_consistent(const JointLimitReport& r) {
  const auto sample_name = [](std::size_t k, const char* field) {
    return "samples[" + std::to_string(k) + "]." + field;
  };
  const Eigen::Index n = r.samples.empty() ? 0 : r.samples.front().q.size();
  const Eigen::Index torques = r.samples.empty() ? 0 : r.samples.front().static_torque.size();
  require(r.samples.empty() || n >= 1, "samples[0].q size", static_cast<long>(n), "must be at least 1 (one per joint)");
  require(torques == 0 || torques == n, "samples[0].static_torque size", static_cast<long>(torques),
          "must be the joint count " + std::to_string(n) + " or 0 (no dynamics model)");
  const auto sound = [n, torques](const JointSample& x) {
    return std::isfinite(x.time) && std::isfinite(x.s) && x.q.size() == n && x.qd.size() == n && x.qdd.size() == n &&
           x.static_torque.size() == torques && x.dynamic_torque.size() == torques && x.q.allFinite() &&
           x.qd.allFinite() && x.qdd.allFinite() && x.static_torque.allFinite() && x.dynamic_torque.allFinite();
  };
  for (std::size_t k = 0; k < r.samples.size(); ++k) {
    const JointSample& x = r.samples[k];
    if (sound(x)) continue;  // the messages below name the field; built only for a sample that fails
    require_finite(x.time, sample_name(k, "time"));  // in the order checked: a PTP check takes times as given
    require_finite(x.s, sample_name(k, "s"));
    const auto sized = [&](const Eigen::VectorXd& v, const char* field, Eigen::Index size) {
      require(v.size() == size, sample_name(k, field) + " size", static_cast<long>(v.size()),
              "must be " + std::to_string(size) + ", as in samples[0]");
      require_finite(v, sample_name(k, field));
    };
    sized(x.q, "q", n);
    sized(x.qd, "qd", n);
    sized(x.qdd, "qdd", n);
    sized(x.static_torque, "static_torque", torques);
    sized(x.dynamic_torque, "dynamic_torque", torques);
  }
  const auto factor = [](double f, const char* name) {
    require(std::isfinite(f) && f >= 0.0, name, f, "must be finite and not negative");
  };
  factor(r.velocity_factor, "velocity_factor");
  factor(r.acceleration_factor, "acceleration_factor");
  factor(r.position_excess, "position_excess");
  const auto joint = [n](int j, const char* name) {
    require(j >= -1 && j < n, name, static_cast<long>(j),
            "must be -1 (none) or a joint index below " + std::to_string(n));
  };
  joint(r.velocity_joint, "velocity_joint");
  joint(r.torque_joint, "torque_joint");
  joint(r.position_joint, "position_joint");
  const auto sample = [&r](std::size_t i, const char* name) {
    require(i == 0 || i < r.samples.size(), name, static_cast<unsigned long>(i),
            "must index a sample (there are " + std::to_string(r.samples.size()) + ")");
  };
  sample(r.velocity_sample, "velocity_sample");
  sample(r.torque_sample, "torque_sample");
  sample(r.position_sample, "position_sample");
}

//! The result of the KUKA re-timing patent's scaling loop (retime_by_scaling).
struct RetimeResult {
  Trajectory trajectory;    //!< the plan under the scaled limits
  Limits limits;            //!< the scaled limits it was planned with
  int iterations = 0;       //!< plans made (1: the original already fits)
  JointLimitReport report;  //!< of the final trajectory: within_limits() is true
};

//! Options of retime_optimal.
struct OptimalRetimeOptions {
  //! Grid intervals over the whole path (≥ 2; each rest-to-rest run gets a share proportional
  //! to its length, at least 2). Limits are imposed at both ends of every interval.
  int grid_intervals = 100;
  //! Joint acceleration limits q̈maxᵢ (rad/s² or m/s², each > 0, +∞ for none); empty: none
  //! (URDF states none; MoveIt's joint_limits.yaml does).
  Eigen::VectorXd joint_acceleration;
  //! Keep |τᵢ| ≤ the effort limit where the machine states one.
  bool torque_limits = true;
  //! Step of the central differences for q″(s), as a fraction of the run's grid interval, > 0.
  double difference_step = 1e-3;
  //! The dense check of the result: samples between its characteristic points (≥ 0).
  int check_samples_between = 3;
  //! Re-solves with tightened limits when the dense check finds an overshoot between grid
  //! points (≥ 0); if the last one still overshoots, retime_optimal throws.
  int max_refinements = 6;
  //! Continuous-path mode as plan()'s (PlanOptions::corner_tolerance, m, ≥ 0): the path re-timed
  //! is continuous_path(path) with its corners blended, and its rests are kept; 0 re-times the
  //! path as given.
  double corner_tolerance = 0.0;
};

//! What retime_optimal produced.
struct OptimalRetimeResult {
  //! The re-timed trajectory: the same path, one constant-acceleration law per grid interval
  //! (with a jerk limit: constant-jerk laws of at most seven phases each).
  Trajectory trajectory;
  //! The dense check of `trajectory` (check_joint_limits at check_samples_between).
  JointLimitReport report;
  //! Largest |q̇ᵢ|/q̇maxᵢ, |q̈ᵢ|/q̈maxᵢ and |τᵢ|/τmaxᵢ at the checked samples (each ≤ 1; 0 where no
  //! limit applies). τ is the whole torque, static plus dynamic.
  //!@{
  double velocity_ratio = 0.0, acceleration_ratio = 0.0, torque_ratio = 0.0;
  //!@}
  //! The fraction by which the joint limits were tightened on the grid so that they hold between
  //! grid points too (0: not needed), and the re-solves that took.
  //!@{
  double margin = 0.0;
  int refinements = 0;
  //!@}
  //! The grid positions s (m) and ṡ there (m/s) (with a jerk limit: of the law before its
  //! moving average).
  //!@{
  std::vector<double> grid_s, grid_speed;
  //!@}
  //! With a jerk limit: the longest moving-average window T (s) of the rest-to-rest runs, the
  //! time each run grew by; 0 without, and 0 when the trajectory is the plain S-curve plan or
  //! the KUKA re-timing patent's scaling loop with the S-curve (either keeps every joint limit
  //! and is faster than the average).
  double jerk_window = 0.0;
};

//! What every result satisfies, beyond its trajectory's and report's own checks: the grid's
//! positions and speeds pair up, finite, the positions in order on the path and the speeds not
//! negative; ratios, margin and jerk window finite and ≥ 0 (the margin below 1: it is a
//! fraction the limits were tightened by); refinements ≥ 0. std::invalid_argument otherwise.
inline void require_consistent(const OptimalRetimeResult& r) {
  require_consistent(r.report);
  require(r.grid_speed.size() == r.grid_s.size(), "grid_speed size", static_cast<unsigned long>(r.grid_speed.size()),
          "must be the size of grid_s, " + std::to_string(r.grid_s.size()));
  const double length = r.trajectory.length();
  for (std::size_t k = 0; k < r.grid_s.size(); ++k) {
    const std::string at = "[" + std::to_string(k) + "]";
    require(std::isfinite(r.grid_s[k]) && r.grid_s[k] >= 0.0 && r.grid_s[k] <= length * (1.0 + 1e-9) &&
                (k == 0 || r.grid_s[k] >= r.grid_s[k - 1]),
            "grid_s" + at, r.grid_s[k], "must lie on the path (s in [0, length]), in order");
    require(std::isfinite(r.grid_speed[k]) && r.grid_speed[k] >= 0.0, "grid_speed" + at, r.grid_speed[k],
            "must be finite and not negative");
  }
  for (const auto& [value, name] :
       {std::pair{r.velocity_ratio, "velocity_ratio"}, std::pair{r.acceleration_ratio, "acceleration_ratio"},
        std::pair{r.torque_ratio, "torque_ratio"}, std::pair{r.jerk_window, "jerk_window"}})
    require(std::isfinite(value) && value >= 0.0, name, value, "must be finite and not negative");
  require(std::isfinite(r.margin) && r.margin >= 0.0 && r.margin < 1.0, "margin", r.margin, "must be in [0, 1)");
  require(r.refinements >= 0, "refinements", static_cast<long>(r.refinements), "must not be negative");
}

//! The joint limits re-timing keeps (+∞ where none).
struct JointBounds {
  //! Per joint: the velocity (rad/s or m/s), acceleration (rad/s² or m/s²) and effort (N·m or N) limits.
  //!@{
  Eigen::VectorXd velocity, acceleration, effort;
  //!@}
  //! n entries of +∞.
  static Eigen::VectorXd unlimited(int n) {
    return Eigen::VectorXd::Constant(n, std::numeric_limits<double>::infinity());
  }
};

//! Where on the path the re-timing asks for the joints: the path position s (m) and its rate
//! ds/dσ per unit of the parameter the twists are given in (doc/retiming.md eq. 9).
struct PathPlace {
  double s = 0.0;            //!< the path position (m)
  double s_per_sigma = 1.0;  //!< ds/dσ: the path's rate per unit of the re-timing's parameter σ
};

//! What re-timing needs of a machine whose joints follow a Cartesian path: the joints along the
//! path, their limits, the torque coefficients where it has a dynamics model, and the dense check
//! of a timed result. Implemented by the serial-arm and hexapod plugins; a machine of another
//! kind implements it to use retime_optimal.
class JointModel {
 public:
  virtual ~JointModel() = default;
  //! The number of joints.
  virtual int dof() const = 0;
  //! The name of joint k in messages ("shoulder_pan_joint", "leg 1").
  virtual std::string joint_name(int k) const = 0;
  //! The unit of a joint position in messages ("rad", "m").
  virtual const char* position_unit() const = 0;
  //! q at `pose` on the branch of q_ref (Newton from `guess` where that applies, q_ref if null)
  //! and q′ = J⁻¹ ξ′, the joint velocity per unit of path for the body twist `per_sigma` per
  //! unit of path, at `place` (named in messages). Throws std::runtime_error where the pose has
  //! no solution or the machine is singular.
  virtual void joints(const Posed& pose, const Twistd& per_sigma, const Eigen::VectorXd& q_ref,
                      const Eigen::VectorXd* guess, const PathPlace& place, Eigen::VectorXd& q,
                      Eigen::VectorXd& q1) const = 0;
  //! joints() and q″ = d²q/dσ² for the derivative `per_sigma_rate` of the body twist per unit of
  //! path, in closed form (doc/retiming.md (eq. 28)): true. The default calls joints() and returns
  //! false, leaving q″ alone: the re-timing then takes it by central differences of q′.
  virtual bool joints_with_rate(const Posed& pose, const Twistd& per_sigma, const Twistd& per_sigma_rate,
                                const Eigen::VectorXd& q_ref, const Eigen::VectorXd* guess, const PathPlace& place,
                                Eigen::VectorXd& q, Eigen::VectorXd& q1, Eigen::VectorXd& q2) const;
  //! Where q″ steps between places of the path (not at section junctions, which the re-timing
  //! knows): the other values q″ takes on the path positions [s_before, s_after] around `place`,
  //! given q, q′ and q″ there, each as if taken at `place` — the values the limits between the
  //! grid points must allow for. None by default. (A seven-joint arm's moving parameter: θ″ steps
  //! at the nodes of doc/inverse-kinematics.md eq. 50.)
  virtual void rate_steps(const Eigen::VectorXd& q, const Eigen::VectorXd& q2, const PathPlace& place, double s_before,
                          double s_after, std::vector<Eigen::VectorXd>& q2_other) const;
  //! Whether q″ may step between places (rate_steps), and q′ · ds/dσ with it at a section junction:
  //! then the re-timing keeps the limits there for q″ as each section gives it, not only for the
  //! central difference across the junction. False by default.
  virtual bool rates_step() const { return false; }
  //! The model of the joints along `planned` followed from q_start, where they depend on more than
  //! the pose and the branch: a seven-joint arm whose redundancy parameter moves along the path, as a
  //! function of the planned path's position s (doc/inverse-kinematics.md §14). Null (the default):
  //! this model itself.
  virtual std::unique_ptr<JointModel> along(const Trajectory& planned, const Eigen::VectorXd& q_start) const;
  //! The torque along the path is τ = torque_u σ̈ + torque_x σ̇² + gravity, from q, q′ and q″
  //! (doc/retiming.md); all three are left empty without a dynamics model.
  virtual void torque_coefficients(const Eigen::VectorXd& q, const Eigen::VectorXd& q1, const Eigen::VectorXd& q2,
                                   Eigen::VectorXd& gravity, Eigen::VectorXd& torque_u,
                                   Eigen::VectorXd& torque_x) const = 0;
  //! check_joint_limits of the machine for `trajectory` from q_start.
  virtual JointLimitReport check(const Trajectory& trajectory, const Eigen::VectorXd& q_start,
                                 int samples_between) const = 0;
  //! The limits to keep: the machine's velocity and effort limits (effort only with
  //! options.torque_limits) and options.joint_acceleration.
  virtual JointBounds bounds(const OptimalRetimeOptions& options) const = 0;
  //! The KUKA re-timing patent's scaling loop with the S-curve, where the machine has it and it
  //! converges with every joint limit held back by `headroom` (a fraction): one more candidate
  //! for the jerk-limited result. None by default.
  virtual std::optional<Trajectory> scaled_scurve(const Path& path, const MetricSetd& set, const Limits& limits,
                                                  const Eigen::VectorXd& q_start, double headroom) const;
};

//! The instants check_joint_limits looks at: the characteristic times of `trajectory` and
//! options.samples_between equidistant ones between consecutive ones. Throws
//! std::invalid_argument for bad options.
std::vector<double> checked_times(const Trajectory& trajectory, const JointCheckOptions& options);

//! The fastest parameterisation of `path` (planned with plan(path, set, limits, trapezoid): the
//! DISP velocity-limit curve and its rests are kept, and |s̈| ≤ limits.acceleration) under the
//! joint limits of `model` (model.bounds(options)), followed from q_start (size model.dof()).
//! Without limits.jerk the time laws are piecewise-constant s̈ (one per grid interval and
//! section). With limits.jerk they are piecewise-constant s⃛ with |s⃛| ≤ j inside every section
//! (at a tangent junction ṡ steps with the section's ds/dσ, ≤ 1 %, as without a jerk limit; the
//! motion itself is smooth there): each run is the jerk-free result, re-solved with speed caps
//! tightened over the window's reach and its lowest acceleration cap, then averaged over a window
//! T (jerk_window), so it takes T longer per run than that re-solve. If plan(path, set, limits,
//! scurve) or model.scaled_scurve keeps every joint limit 0.1 % clear at a dense check (at least
//! 10 samples between characteristic points) and is faster, the fastest of them is returned
//! instead (jerk_window 0). Throws std::invalid_argument for bad options/limits or a q_start of
//! the wrong size, std::runtime_error where the path has no joint solution or is singular, where
//! the static torque reaches a limit, where a joint leaves its position range, or if the dense
//! check still fails after max_refinements.
OptimalRetimeResult retime_optimal(const Path& path, const MetricSetd& set, const Limits& limits,
                                   const JointModel& model, const Eigen::VectorXd& q_start,
                                   const OptimalRetimeOptions& options = {});

}  // namespace dispkin
