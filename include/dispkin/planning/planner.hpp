//! The DISP trajectory planner: a path, a metric set and limits → a trajectory whose points
//! never move faster than the system velocity (MATH.md §5–7).
//!
//! The path length is the sum of the section lengths L_k under the set (each group weighted
//! by v_sys / v_g). A time law s(t) with 0 ≤ ṡ ≤ v_sys, |s̈| ≤ a, |s⃛| ≤ j runs over it and
//! section k is traversed at τ = (s − s_k)/L_k: every point of every group then moves at most
//! at ṡ · (its weight)⁻¹ ≤ its limit, at every instant (not only at samples).
//!
//! Rule at corners (this version): where the path's direction changes between two sections
//! (their twists per unit of s differ), the trajectory comes to rest — the patent's "lower
//! speed at direction reversals" in its simplest safe form. Tangent-continuous junctions (the
//! sections of one CIRC, collinear LINs) are passed at speed within one time law.
#pragma once

#include <optional>
#include <vector>

#include "dispkin/metric_set.hpp"
#include "dispkin/path/path.hpp"
#include "dispkin/pose.hpp"
#include "dispkin/profile.hpp"
#include "dispkin/path/section_motion.hpp"

namespace dispkin {

namespace detail {
struct TrajectoryAccess;
}  // namespace detail

//! System limits in the DISP metric: velocity (m/s), acceleration (m/s²), jerk (m/s³, for the
//! S-curve). Each must be finite and positive.
struct Limits {
  double velocity = 0.0;       //!< v_sys (m/s): no point of the set faster (groups: their own limit)
  double acceleration = 0.0;   //!< |s̈| ≤ this (m/s²); the curvature rule lowers the speed where the path bends
  std::optional<double> jerk;  //!< |s⃛| ≤ this (m/s³), S-curve only

  //! Throws std::invalid_argument naming the limit; the jerk is required for the S-curve
  //! and refused for the trapezoid (it would be silently ignored).
  void validate(ProfileKind kind) const;
};

//! Extra constraints for plan() beyond the metric set.
struct PlanOptions {
  //! Empty: none. Otherwise one length per section of the path (m, each finite and ≥ 0): section
  //! k is planned with length max(L_k, min_section_lengths[k]). Joint-space metrics (a
  //! hexapod's leg speeds, Hexapod::joint_metric) enter the plan this way. Lengthening a
  //! section only slows it down, so the DISP guarantee of the set still holds.
  std::vector<double> min_section_lengths;
};

//! What a trajectory is at one instant.
struct TrajectorySample {
  Posed pose;          //!< the pose
  Twistd body_twist;   //!< its body twist (v, ω), m/s and rad/s
  double s = 0.0;      //!< DISP arc length travelled, m
  double s_dot = 0.0;  //!< ṡ: the speed bound of every point of the set, m/s
  double s_ddot = 0.0; //!< s̈, m/s²
};

//! A planned trajectory. Sampling is noexcept and allocation-free; a control loop samples
//! consecutive cycles fastest with a Cursor (sample(t, cursor)).
class Trajectory {
 public:
  double duration() const noexcept { return pieces_.empty() ? 0.0 : pieces_.back().end_time; }
  double length() const noexcept { return starts_.empty() ? 0.0 : starts_.back().s + lengths_.back(); }
  std::size_t section_count() const noexcept { return motions_.size(); }
  const std::vector<double>& section_lengths() const noexcept { return lengths_; }
  //! Number of rest-to-rest pieces (1 + corners where the trajectory stops).
  std::size_t piece_count() const noexcept { return rest_pieces_; }
  //! Number of time laws: each rest-to-rest piece has one per segment of its velocity-limit
  //! curve (plan() slows down where the path curves tightly).
  std::size_t law_count() const noexcept { return pieces_.size(); }

  //! Every phase boundary and phase middle of every time law, sorted, from 0 to duration():
  //! the instants where velocity or acceleration peak or change their course (the seed's
  //! P0, P1, P12, P2, P3 for each law). Planning side; allocates.
  std::vector<double> characteristic_times() const;

  //! One span of the velocity-limit curve the trajectory was planned under: ṡ ≤ `limit` (m/s)
  //! for s in [start_s, start_s + length).
  struct SpeedLimit {
    double start_s, length, limit;
  };
  //! The velocity-limit curve (system velocity, lowered where the path curves tightly), in
  //! order of s; together with rest_positions() what any re-timing must keep to.
  const std::vector<SpeedLimit>& speed_limits() const noexcept { return speed_limits_; }
  //! The path positions s where the trajectory is at rest: 0, every corner, length().
  const std::vector<double>& rest_positions() const noexcept { return rest_s_; }

  //! The pose at path position s (clamped to [0, length()]) and its body twist per unit of s
  //! (the body twist at ṡ = 1 m/s).
  void path_state(double s, Posed& pose, Twistd& twist_per_s) const noexcept;

  //! Where a sequence of samples has got to: the time law and the section of the last sample.
  //! A control loop keeps one per trajectory and passes it to sample(t, cursor), which then
  //! finds the law and the section of a nearby time without searching. Any value is valid
  //! (a default one, one left by another trajectory): it is only a hint.
  struct Cursor {
    std::size_t piece = 0;    //!< index of the time law of the last sample
    std::size_t section = 0;  //!< index of the section of the last sample
  };

  //! The state at time t (clamped to [0, duration]).
  TrajectorySample sample(double t) const noexcept;
  //! The same state as sample(t), bit for bit, found from `cursor` (then moved to t): in
  //! constant time when t lies in the law and section of the previous sample or the next
  //! one, by binary search otherwise. Consecutive controller cycles are the fast case.
  TrajectorySample sample(double t, Cursor& cursor) const noexcept;
  //! out[i] = sample(times[i]), found with one cursor (fastest for increasing times).
  void sample(const double* times, TrajectorySample* out, std::size_t count) const noexcept;

 private:
  friend Trajectory plan(const Path&, const MetricSetd&, const Limits&, ProfileKind, const PlanOptions&);
  friend struct detail::TrajectoryAccess;  // re-timing: the same path under new time laws

  // One time law: over a segment of constant velocity limit, within a rest-to-rest run.
  struct Piece {
    Profile profile;
    double start_time, end_time;  // in trajectory time
    double start_s;               // DISP arc length at its start
  };

  // The law running at t: the first that ends after t (the last one for t ≥ duration), found
  // from the hint `piece` when that or the next one is it.
  std::size_t piece_at(double t, std::size_t piece) const noexcept;
  // The section holding s: the last whose start is ≤ s (the first for s below it), found from
  // the hint `section` when that or the next one is it.
  std::size_t section_at(double s, std::size_t section) const noexcept;
  // The pose and body twist per unit τ at s, in the section section_at(s, hint), which it
  // returns (callers scale the twist once: by 1/L_k, or by ṡ/L_k when sampling).
  std::size_t section_state(double s, std::size_t hint, Posed& pose, Twistd& twist_per_tau) const noexcept;

  detail::SectionMotions motions_;  // section k, ready to sample
  // What sampling needs of section k: s at its start, and 1 / L_k (sampling multiplies).
  struct SectionStart {
    double s, inverse_length;
  };

  std::vector<double> lengths_;        // L_k
  std::vector<SectionStart> starts_;   // of section k
  std::vector<Piece> pieces_;
  std::size_t rest_pieces_ = 0;
  std::vector<SpeedLimit> speed_limits_;
  std::vector<double> rest_s_;
};

//! Plans `path` under `set` and `limits` with a time-optimal `profile` law per rest-to-rest
//! piece. Throws std::invalid_argument for bad limits or a set that is not well-formed.
Trajectory plan(const Path& path, const MetricSetd& set, const Limits& limits, ProfileKind profile = ProfileKind::scurve);

//! The same with `options`; also throws std::invalid_argument when min_section_lengths has the
//! wrong size or an entry that is negative or not finite.
Trajectory plan(const Path& path, const MetricSetd& set, const Limits& limits, ProfileKind profile,
                const PlanOptions& options);

}  // namespace dispkin
