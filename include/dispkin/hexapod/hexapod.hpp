//! The hexapod (Stewart platform) plugin: six legs of variable length between base joints
//! b_i (base coordinates) and platform joints p_i (platform coordinates).
//!
//! Convention: a platform pose T = (R, t) maps platform coordinates to base coordinates, as
//! Pose does, and leg i has length ℓ_i(T) = ‖T p_i − b_i‖ = ‖R p_i + t − b_i‖.
//!
//! Pivot point: a pose given as XYZUVW rotates about the pivot (platform coordinates),
//! Pose::from_xyzuvw(v, pivot). PI-style controllers only accept a new pivot while
//! U = V = W = 0, because the same XYZUVW about another pivot is another pose. dispkin allows
//! changing the pivot at any orientation: xyzuvw_for_new_pivot() gives the XYZUVW about the new
//! pivot that keeps the platform where it is (UVW unchanged, XYZ moved by (R − I)(p_new − p_old)).
//!
//! Planning side: constructors, forward() and the checks throw; leg_lengths() is noexcept and
//! does not allocate (the inverse kinematics on a controller's cycle).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "dispkin/kinematics.hpp"
#include "dispkin/metric_set.hpp"
#include "dispkin/path/path.hpp"
#include "dispkin/planning/planner.hpp"
#include "dispkin/pose.hpp"

namespace dispkin::hexapod {

//! One leg out of its length range in a workspace check.
struct LegViolation {
  int leg;        //!< 0-based leg index
  double length;  //!< its length at the checked pose
  double lower;   //!< the leg's shortest length (m)
  double upper;   //!< the leg's longest length (m)
  double excess;  //!< how far outside: lower − length or length − upper, > 0
};

//! The result of Hexapod::check(pose): the leg lengths and the legs out of range.
struct WorkspaceCheck {
  Eigen::Matrix<double, 6, 1> lengths;   //!< the six leg lengths at the pose (m)
  std::vector<LegViolation> violations;  //!< empty when every leg is within its range
  //! Whether every leg is within its range.
  bool reachable() const noexcept { return violations.empty(); }
};

//! One stretch of a trajectory where a leg leaves its length range or exceeds its speed.
struct LegExcursion {
  //! What a leg can leave: its length range or its speed limit.
  enum class Kind { length, speed } kind;  //!< what this leg leaves
  int leg;                                 //!< 0-based leg index
  double start_time;                       //!< first sample out of range (s)
  double end_time;                         //!< last sample out of range (s)
  double worst_time;                       //!< the sample with the largest excess
  double worst_value;                      //!< the leg's length (m) or speed (m/s) there
  double excess;                           //!< how far beyond the range or speed limit, > 0
};

//! The result of Hexapod::check_trajectory: extremes per leg and every excursion.
struct TrajectoryCheck {
  //! Per leg: its shortest and longest length (m) and its largest speed |ℓ̇| (m/s).
  //!@{
  Eigen::Matrix<double, 6, 1> min_length, max_length, max_speed;
  //!@}
  std::vector<LegExcursion> excursions;  //!< in order of leg, then time
  //! Whether no leg leaves its range or exceeds its speed.
  bool ok() const noexcept { return excursions.empty(); }
};

//! What the check results satisfy (Hexapod::check and check_trajectory make them so; a stored
//! one is checked): legs 0…5, every number finite, a leg's range lower < upper, an excess > 0
//! that is how far the length lies outside that range (to rounding), an excursion's worst time
//! inside its stretch, extremes in order (min_length ≤ max_length, speeds ≥ 0), violations one
//! per leg and in order with the lengths they report. std::invalid_argument naming the field.
inline void require_consistent(const LegViolation& v, const std::string& name = "") {
  require(v.leg >= 0 && v.leg < 6, name + "leg", static_cast<long>(v.leg), "must be a leg index 0 to 5");
  require_finite(Eigen::Vector4d(v.length, v.lower, v.upper, v.excess), name + "(length, lower, upper, excess)");
  require(v.lower < v.upper, name + "(lower, upper)", Eigen::Vector2d(v.lower, v.upper), "must have lower < upper");
  // The excess is lower − length or length − upper, computed once: equal to a few ε of the sizes.
  const double outside = std::max(v.lower - v.length, v.length - v.upper);
  const double rounding = 8.0 * std::numeric_limits<double>::epsilon() *
                          std::max({std::abs(v.length), std::abs(v.lower), std::abs(v.upper)});
  require(v.excess > 0.0 && std::abs(v.excess - outside) <= rounding, name + "excess", v.excess,
          "must be > 0 and how far the length lies outside [lower, upper] (" + std::to_string(outside) + ")");
}

//! A WorkspaceCheck: finite lengths, each violation consistent and reporting its leg's length.
inline void require_consistent(const WorkspaceCheck& c) {
  require_finite(c.lengths, "lengths");
  for (std::size_t k = 0; k < c.violations.size(); ++k) {
    const LegViolation& v = c.violations[k];
    const std::string name = "violations[" + std::to_string(k) + "].";
    require_consistent(v, name);
    require(k == 0 || v.leg > c.violations[k - 1].leg, name + "leg", static_cast<long>(v.leg),
            "must follow the leg before it (one per leg, in order)");
    require(v.length == c.lengths(v.leg), name + "length", v.length,
            "must be the length of leg " + std::to_string(v.leg) + " in lengths, " + std::to_string(c.lengths(v.leg)));
  }
}

//! A LegExcursion: a known kind, a leg 0…5, start ≤ worst ≤ end time, finite values, excess > 0.
inline void require_consistent(const LegExcursion& e, const std::string& name = "") {
  require(e.kind == LegExcursion::Kind::length || e.kind == LegExcursion::Kind::speed, name + "kind",
          static_cast<long>(e.kind), "must be 'length' or 'speed'");
  require(e.leg >= 0 && e.leg < 6, name + "leg", static_cast<long>(e.leg), "must be a leg index 0 to 5");
  require_finite(Eigen::Vector3d(e.start_time, e.end_time, e.worst_time), name + "(start_time, end_time, worst_time)");
  require(e.start_time <= e.worst_time && e.worst_time <= e.end_time, name + "(start_time, end_time, worst_time)",
          Eigen::Vector3d(e.start_time, e.end_time, e.worst_time), "must have start_time <= worst_time <= end_time");
  require_finite(e.worst_value, name + "worst_value");
  require(std::isfinite(e.excess) && e.excess > 0.0, name + "excess", e.excess, "must be finite and > 0");
}

//! A TrajectoryCheck: finite extremes in order, speeds ≥ 0, each excursion consistent.
inline void require_consistent(const TrajectoryCheck& c) {
  require_finite(c.min_length, "min_length");
  require_finite(c.max_length, "max_length");
  require_finite(c.max_speed, "max_speed");
  require((c.min_length.array() <= c.max_length.array()).all(), "min_length", c.min_length,
          "must not exceed max_length");
  require((c.max_speed.array() >= 0.0).all(), "max_speed", c.max_speed, "must not be negative");
  for (std::size_t k = 0; k < c.excursions.size(); ++k)
    require_consistent(c.excursions[k], "excursions[" + std::to_string(k) + "].");
}

//! Forward kinematics tuning: Newton's method on SE(3).
struct ForwardOptions {
  double tolerance = 1e-12;  //!< converged when every |ℓ_i(T) − ℓ_i| ≤ this (m)
  int max_iterations = 50;   //!< failure after this many Newton steps
  double min_rcond = 1e-10;  //!< singular when the scaled leg Jacobian's reciprocal condition number is below this
};

//! A Stewart platform: geometry, leg limits, inverse and forward kinematics.
//!
//! Invariants (checked by the constructor): all data finite; the base joints are not
//! collinear, neither are the platform joints; 0 ≤ leg_min < leg_max; leg_speed > 0.
class Hexapod : public Kinematics {
 public:
  using Joints = Eigen::Matrix<double, 3, 6>;    //!< one joint per column
  using Legs = Eigen::Matrix<double, 6, 1>;      //!< one value per leg (lengths, speeds)
  using Jacobian = Eigen::Matrix<double, 6, 6>;  //!< ∂ℓ/∂ξ, see leg_jacobian()

  //! From any layout. `home` is the pose forward() starts from when no guess is given.
  Hexapod(const Joints& base_joints, const Joints& platform_joints, const Legs& leg_min, const Legs& leg_max,
          const Legs& leg_speed, const Posed& home = Posed());

  //! The common symmetric layouts: base joints on a circle of `base_radius` in the plane
  //! z = 0, in pairs centred at 0°, 120°, 240° and `base_gap` (rad) apart; platform joints
  //! on a circle of `platform_radius` in the platform's z = 0 plane, in pairs centred at 60°,
  //! 180°, 300° and `platform_gap` apart. Leg 2k starts at 120°k − base_gap/2 and ends at
  //! 120°k − 60° + platform_gap/2, leg 2k+1 starts at 120°k + base_gap/2 and ends at
  //! 120°k + 60° − platform_gap/2. platform_gap = 0 gives the 6-3 layout (platform joints
  //! coincide in pairs). Home: the platform `height` above the base, not rotated.
  static Hexapod symmetric(double base_radius, double base_gap, double platform_radius, double platform_gap,
                           double height, double leg_min, double leg_max, double leg_speed);

  //! A description saved by save(). Throws std::invalid_argument naming the key when the file
  //! is unreadable, not JSON, or a key is missing or of the wrong kind.
  static Hexapod load(const std::string& path);
  //! Writes the JSON description (base, platform, limits per leg, home pose).
  void save(const std::string& path) const;
  //! The JSON description as text.
  std::string to_json() const;
  //! The hexapod of a JSON description (the text of save()); errors as load().
  static Hexapod from_json(const std::string& text);

  const Joints& base_joints() const noexcept { return base_; }          //!< b_i, base coordinates (m)
  const Joints& platform_joints() const noexcept { return platform_; }  //!< p_i, platform coordinates (m)
  const Legs& leg_min() const noexcept { return leg_min_; }             //!< shortest leg lengths (m)
  const Legs& leg_max() const noexcept { return leg_max_; }             //!< longest leg lengths (m)
  const Legs& leg_speed() const noexcept { return leg_speed_; }         //!< leg speed limits (m/s)
  const Posed& home() const noexcept { return home_; }                  //!< the pose forward() starts from

  //! Inverse kinematics: ℓ_i = ‖T p_i − b_i‖. No checks, no allocation.
  Legs leg_lengths(const Posed& pose) const noexcept;
  //! Inverse kinematics of XYZUVW about `pivot` (platform coordinates).
  Legs leg_lengths(const Eigen::Matrix<double, 6, 1>& xyzuvw, const Eigen::Vector3d& pivot) const;

  //! ∂ℓ/∂ξ for the body twist ξ = (v, ω) of T·exp(ξ): row i = (ũ_iᵀ, (p_i × ũ_i)ᵀ) with
  //! ũ_i = Rᵀ u_i the unit leg vector u_i = (T p_i − b_i)/ℓ_i in platform coordinates.
  //! So ℓ̇ = J ξ for the body velocity ξ of the platform.
  Jacobian leg_jacobian(const Posed& pose) const noexcept;

  //! Forward kinematics: the pose with these leg lengths, by Newton's method on SE(3) from
  //! `guess` (T ← T·exp(δ), J δ = −(ℓ(T) − legs) solved by partial-pivot LU) until every leg
  //! is within options.tolerance, then one polishing step (kept if it does not increase the
  //! residual), which brings the pose to rounding (≈ 1e-15 for a desktop hexapod). Throws
  //! std::invalid_argument for non-finite or non-positive legs and std::runtime_error, with
  //! the iteration count and residual, when the Jacobian is singular or Newton does not
  //! converge (unreachable lengths, a start too far away).
  Posed forward(const Legs& legs, const Posed& guess, const ForwardOptions& options = {}) const;
  //! Forward kinematics from home().
  Posed forward(const Legs& legs) const { return forward(legs, home_); }

  //! Which legs are out of their length range at `pose`, and by how much.
  WorkspaceCheck check(const Posed& pose) const noexcept;
  //! Throws std::invalid_argument naming the first leg out of range, its length and range.
  void require_reachable(const Posed& pose) const;

  //! Dense check of a whole trajectory: samples at t = 0, dt, 2dt, …, duration (and the end),
  //! leg lengths by the inverse kinematics and leg speeds ℓ̇ = J ξ from each sample's body
  //! twist (exact at the sample, no finite differences). `trajectory` is anything with
  //! duration() and sample(t) returning .pose and .body_twist (dispkin::Trajectory).
  template <typename TrajectoryLike>
  TrajectoryCheck check_trajectory(const TrajectoryLike& trajectory, double dt) const;

  //! Leg-speed rule (a) of the DISP patent JP7742490B2 (doc/planning.md §2): adds the six platform
  //! joints as relative points of `group` to `set` and sets that group's speed to the smallest leg
  //! speed limit. Since a leg's speed ℓ̇_i = u_i·ṗ_i never exceeds the speed of its platform joint,
  //! a trajectory that keeps the group within its speed keeps every leg within its limit.
  void add_leg_speed_group(MetricSetd& set, int group) const;

  // Leg speeds along a path (rule (b)): leg_rate_bounds, leg_section_lengths and joint_metric
  // sample path sections, so they are part of the umbrella library dispkin::dispkin
  // (src/hexapod/hexapod_along_path.cpp); dispkin::hexapod alone has the rest of this class.

  //! The DISP patent's leg-speed rule (b), the joint-space metric: upper bounds r_i ≥ max over
  //! τ ∈ [0, 1] of |dℓ_i/dτ| along one section (m per unit τ), dℓ_i/dτ = (leg_jacobian row i) ·
  //! (section_twist per unit τ), exact at every τ.
  //!
  //! Rule (a rigorous Lipschitz bound on a uniform grid τ_k = k h, h = 1/N): with V ≥ the speed
  //! per unit τ of every platform joint (section_length over the six joints, the section's own
  //! guarantee) and A ≥ their acceleration per unit τ² (closed form per section kind, below),
  //! |d²ℓ_i/dτ²| = |u_i·p̈_i + (‖ṗ_i‖² − (u_i·ṗ_i)²)/ℓ_i| ≤ M_i = A + V²/ℓ_low,i, where
  //! ℓ_low,i = min_k ℓ_i(τ_k) − V h/2 bounds the leg from below (|dℓ_i/dτ| ≤ V). Between two
  //! grid points |dℓ_i/dτ| then stays under (|g_k| + |g_k+1| + M_i h)/2, so
  //!   r_i = min(V, max_k (|g_k| + |g_k+1| + M_i h)/2),   g_k = dℓ_i/dτ(τ_k).
  //! N is chosen so that M_i h/2 ≤ `tolerance` · (the section's largest sampled demand
  //! max_j |g_j|/leg_speed_j) · leg_speed_i: the bound then exceeds the true maximum by at most
  //! that much. N stays within [64, 65536]; at the upper end the bound is still rigorous, only
  //! looser than the tolerance.
  //!
  //! A (acceleration of the platform joints per unit τ²): decoupled LIN θ² max_j ‖p_j − pivot‖
  //! (the pivot moves at constant velocity, the rotation is about a fixed axis); screw LIN
  //! max_j ‖ω × (v + ω × p_j)‖ (constant body twist); arc φ² ‖c₀ − centre‖ + θ² max_j ‖p_j −
  //! pivot‖. A section kind without a closed form here (a future spline or blend) gets r_i = V,
  //! still an upper bound (it is rule (a) for that section), only not tight.
  //! Throws std::invalid_argument for a tolerance outside (0, 1].
  Legs leg_rate_bounds(const Section& section, double tolerance = 1e-3) const;

  //! Minimum length per section of `path` for rule (b): a section traversed at the system
  //! velocity v_sys in time L / v_sys moves leg i at |dℓ_i/dτ| v_sys / L, so it needs
  //! L ≥ v_sys · max_i r_i / leg_speed_i. Throws std::invalid_argument for a non-positive or
  //! non-finite system velocity or a bad tolerance.
  std::vector<double> leg_section_lengths(const Path& path, double system_velocity, double tolerance = 1e-3) const;

  //! Rule (b) for plan(): PlanOptions whose min_section_lengths are at least
  //! leg_section_lengths(path, limits.velocity). plan(path, set, limits, profile,
  //! hexapod.joint_metric(path, limits)) keeps every leg within its speed at all times and the
  //! metric set under its own limits; each section gets the longer of its two lengths. Along a
  //! run of sections that continue one another (the sections of a CIRC, collinear LINs) the
  //! lengths are raised to one common speed (λ c_k, c_k ∝ the twist per unit τ at the
  //! junctions), so the planner passes the junctions without stopping instead of coming to
  //! rest wherever the leg demand changes.
  PlanOptions joint_metric(const Path& path, const Limits& limits) const;

  //! Rule (b) as PlanOptions::joint_metric: joint_metric(path, limits).min_section_lengths for the
  //! path as planned, so that plan() evaluates it after blending corners. Holds a copy of this
  //! hexapod.
  JointMetric joint_metric() const;

  // Kinematics
  int dof() const override { return 6; }
  Posed forward(const Eigen::VectorXd& q) const override;
  std::vector<Eigen::VectorXd> inverse(const Posed& pose) const override;
  JointLimits joint_limits() const override;
  std::vector<std::string> joint_names() const override;

 private:
  Joints base_;
  Joints platform_;
  Legs leg_min_;
  Legs leg_max_;
  Legs leg_speed_;
  Posed home_;
  double platform_scale_;  // length that scales the rotation columns of the Jacobian
};

template <typename TrajectoryLike>
TrajectoryCheck Hexapod::check_trajectory(const TrajectoryLike& trajectory, double dt) const {
  require_positive(dt, "dt");
  const double duration = trajectory.duration();
  require(std::isfinite(duration) && duration >= 0.0, "duration", duration, "must be finite and not negative");
  const double steps = std::ceil(duration / dt);
  require(steps <= 1e8, "dt", dt, "gives more than 1e8 samples for this trajectory");
  const long n = static_cast<long>(steps);
  TrajectoryCheck result;
  result.min_length.setConstant(std::numeric_limits<double>::infinity());
  result.max_length.setConstant(-std::numeric_limits<double>::infinity());
  result.max_speed.setZero();
  // Open excursion per leg and kind (index leg + 6·kind), −1 when none.
  std::array<long, 12> open;
  open.fill(-1);
  std::vector<LegExcursion> found;
  for (long k = 0; k <= n; ++k) {
    const double t = k == n ? duration : static_cast<double>(k) * dt;
    const auto sample = trajectory.sample(t);
    const Legs lengths = leg_lengths(sample.pose);
    const Legs speeds = leg_jacobian(sample.pose) * sample.body_twist.vector();
    for (int i = 0; i < 6; ++i) {
      result.min_length(i) = std::min(result.min_length(i), lengths(i));
      result.max_length(i) = std::max(result.max_length(i), lengths(i));
      result.max_speed(i) = std::max(result.max_speed(i), std::abs(speeds(i)));
      const double length_excess = std::max(leg_min_(i) - lengths(i), lengths(i) - leg_max_(i));
      const double speed_excess = std::abs(speeds(i)) - leg_speed_(i);
      const double excess[2] = {length_excess, speed_excess};
      const double value[2] = {lengths(i), std::abs(speeds(i))};
      for (int kind = 0; kind < 2; ++kind) {
        long& slot = open[static_cast<std::size_t>(i + 6 * kind)];
        if (excess[kind] > 0.0) {
          if (slot < 0) {
            slot = static_cast<long>(found.size());
            found.push_back({kind == 0 ? LegExcursion::Kind::length : LegExcursion::Kind::speed, i, t, t, t,
                             value[kind], excess[kind]});
          }
          LegExcursion& e = found[static_cast<std::size_t>(slot)];
          e.end_time = t;
          if (excess[kind] > e.excess) {
            e.excess = excess[kind];
            e.worst_time = t;
            e.worst_value = value[kind];
          }
        } else {
          slot = -1;
        }
      }
    }
  }
  std::stable_sort(found.begin(), found.end(),
                   [](const LegExcursion& a, const LegExcursion& b) { return a.leg < b.leg; });
  result.excursions = std::move(found);
  return result;
}

//! The XYZUVW about `new_pivot` of the pose that is `xyzuvw` about `old_pivot` (both in
//! platform coordinates): same platform pose, U, V, W unchanged up to the angle convention.
Eigen::Matrix<double, 6, 1> xyzuvw_for_new_pivot(const Eigen::Matrix<double, 6, 1>& xyzuvw,
                                                 const Eigen::Vector3d& old_pivot, const Eigen::Vector3d& new_pivot);

}  // namespace dispkin::hexapod
