//! The DISP trajectory planner: a path, a metric set and limits → a trajectory whose points
//! never move faster than the system velocity (doc/planning.md eq. 5).
//!
//! The path length is the sum of the section lengths L_k under the set (each group weighted
//! by v_sys / v_g). A time law s(t) with 0 ≤ ṡ ≤ v_sys, |s̈| ≤ a, |s⃛| ≤ j runs over it and
//! section k is traversed at τ = (s − s_k)/L_k: every point of every group then moves at most
//! at ṡ · (its weight)⁻¹ ≤ its limit, at every instant (not only at samples).
//!
//! Rule at corners: where the path's direction changes between two sections (their twists per
//! unit of s differ), the trajectory comes to rest — the "lower speed at direction reversals"
//! of the DISP patent JP7742490B2 in its simplest safe form (doc/planning.md §3) — unless
//! PlanOptions::corner_tolerance blends the corner. Tangent-continuous junctions (the sections
//! of one CIRC, collinear LINs, blends) are passed at speed within one time law. Sections whose
//! fastest point's speed varies are cut so that a cruise runs within 0.5 % of the limit
//! (doc/planning.md §9); each move runs under its own MoveLimits.
#pragma once

#include <functional>
#include <optional>
#include <vector>

#include "dispkin/metric_set.hpp"
#include "dispkin/path/path.hpp"
#include "dispkin/pose.hpp"
#include "dispkin/planning/trajectory.hpp"
#include "dispkin/profile.hpp"

namespace dispkin {

//! System limits in the DISP metric: velocity (m/s), acceleration (m/s²), jerk (m/s³, for the
//! S-curve), and optionally the tool's angular velocity (rad/s) and angular acceleration
//! (rad/s²) — the separate rotational limit of robot controllers ($VEL.ORI1, Pilz's
//! max_rot_vel). Each given value must be finite and positive.
struct Limits {
  double velocity = 0.0;       //!< v_sys (m/s): no point of the set faster (groups: their own limit)
  double acceleration = 0.0;   //!< |s̈| ≤ this (m/s²); the curvature rule lowers the speed where the path bends
  std::optional<double> jerk;  //!< |s⃛| ≤ this (m/s³), S-curve only
  //! |ω| ≤ this (rad/s), exactly: one more term θ·v_sys/ω_max of each section's length
  //! (doc/planning.md eq. 36). With it the metric set need not see every rotation: one
  //! tool-centre point is enough (the TCP speed and rotation limits of robot controllers).
  std::optional<double> angular_velocity{};
  //! |ω̇| ≤ this (rad/s²) from the path acceleration, and again from the curvature rule on
  //! curved sections (doc/planning.md eq. 37).
  std::optional<double> angular_acceleration{};

  //! Throws std::invalid_argument naming the limit; the jerk is required for the S-curve
  //! and refused for the trapezoid (it would be silently ignored).
  void validate(ProfileKind kind) const;
};

//! A joint-space metric for plan(): the minimum length (m) of each section of `path` for
//! `limits` (PlanOptions::joint_metric).
using JointMetric = std::function<std::vector<double>(const Path& path, const Limits& limits)>;

//! Extra constraints for plan() beyond the metric set.
struct PlanOptions {
  //! Empty: none. Otherwise one length per section of the path (m, each finite and ≥ 0): section
  //! k is planned with length max(L_k, min_section_lengths[k]). Joint-space metrics (a
  //! hexapod's leg speeds, Hexapod::joint_metric) enter the plan this way. Lengthening a
  //! section only slows it down, so the DISP guarantee of the set still holds.
  std::vector<double> min_section_lengths;

  //! A joint-space metric (the DISP patent JP7742490B2's rule (b)): given the path as planned
  //! (Path::blended(corner_tolerance) in continuous-path mode, else the path as given) and the
  //! limits, the minimum length of each of its sections (m), used as min_section_lengths are.
  //! Empty: none. hexapod::Hexapod::joint_metric() gives a hexapod's leg speeds; any machine
  //! whose joint speeds bound per section can give one. Not combined with min_section_lengths.
  JointMetric joint_metric;

  //! Continuous-path mode (doc/planning.md §10): 0 (the default) stops at every corner; a
  //! positive distance (m) plans Path::blended(corner_tolerance) instead, so that every corner
  //! the blends can round is passed at speed. Corners left (reversals, turns too sharp for
  //! the tolerance) stop and are listed by Trajectory::stops(). Not combined with
  //! min_section_lengths (those are per section of the path as given); joint_metric is
  //! evaluated on the blended path.
  double corner_tolerance = 0.0;
  //! How finely the corner blends are cut into sections (Path::blended's `tolerance`, in
  //! (0, 0.1]): coarser plans faster, at a slightly lower speed through the blends.
  double blend_tolerance = 1e-3;
  //! The state the motion starts in (doc/events.md §3): path velocity ṡ (m/s, ≥ 0, at most the
  //! velocity limit at the start) and, under the S-curve, path acceleration s̈ (m/s², within the
  //! acceleration limit; the trapezoid has no acceleration state: 0). Both 0 (the default): from
  //! rest. A moving start has no rest at s = 0, and the first run's law is the time-optimal one
  //! from that state (Trajectory::starting_from).
  //!@{
  double start_velocity = 0.0;
  double start_acceleration = 0.0;
  //!@}
};

//! The path that plan() runs along under `options` in continuous-path mode (doc/planning.md §10):
//! Path::blended(options.corner_tolerance, stops, options.blend_tolerance) when the corner
//! tolerance is positive, empty when the path is planned as given. Re-timing plans the same path
//! (OptimalRetimeOptions::corner_tolerance). Throws std::invalid_argument for a corner tolerance
//! that is negative or not finite.
std::optional<Path> continuous_path(const Path& path, const PlanOptions& options,
                                    std::vector<CornerStop>* stops = nullptr);

//! Plans `path` under `set` and `limits` with a time-optimal `profile` law per rest-to-rest
//! piece. Throws std::invalid_argument for bad limits or a set that is not well-formed (with an
//! angular velocity limit: an empty set).
Trajectory plan(const Path& path, const MetricSetd& set, const Limits& limits,
                ProfileKind profile = ProfileKind::scurve);

//! The same with `options`; also throws std::invalid_argument when min_section_lengths has the
//! wrong size or an entry that is negative or not finite.
Trajectory plan(const Path& path, const MetricSetd& set, const Limits& limits, ProfileKind profile,
                const PlanOptions& options);

}  // namespace dispkin
