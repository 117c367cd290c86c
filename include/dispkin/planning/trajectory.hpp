//! A trajectory is a path and a time law: a SampledPath (the sections by DISP arc length s) run
//! through by a TimeLaw s(t) (doc/planning.md (eq. 1)). plan() builds both, together with the
//! velocity-limit curve and the rests that any re-timing of the same path must keep to;
//! with_time_law() gives the same path under another time law. Sampling is noexcept,
//! allocation-free and lock-free.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "dispkin/path/sampled_path.hpp"
#include "dispkin/planning/time_law.hpp"
#include "dispkin/pose.hpp"

namespace dispkin {

//! What a trajectory is at one instant.
struct TrajectorySample {
  Posed pose;           //!< the pose
  Twistd body_twist;    //!< its body twist (v, ω), m/s and rad/s
  double s = 0.0;       //!< DISP arc length travelled, m
  double s_dot = 0.0;   //!< ṡ: the speed bound of every point of the set, m/s
  double s_ddot = 0.0;  //!< s̈, m/s²
};

//! One span of a velocity-limit curve: ṡ ≤ `limit` (m/s) for s in [start_s, start_s + length).
struct SpeedLimit {
  //! Where the span starts (m of DISP arc length), how long it is (m) and the limit of ṡ there (m/s).
  //!@{
  double start_s, length, limit;
  //!@}
  //! The span's own limit of s̈ (m/s², a move's own acceleration or the angular acceleration's
  //! share of it); 0: only the trajectory's (TimeLawLimits::acceleration).
  double acceleration = 0.0;
  //! What ṡ may reach there under a speed override above 1 (m/s): the limit before a move's own
  //! velocity lowered it (the system velocity and the curvature rule, doc/planning.md §4); 0: the
  //! limit itself.
  double ceiling = 0.0;

  //! The ceiling, or the limit where none was given.
  double top() const noexcept { return ceiling > limit ? ceiling : limit; }
};

//! What a trajectory's time law keeps to besides its velocity-limit curve, and so what a new law
//! from one of its states (a stop, a speed override) keeps to as well: |s̈| ≤ acceleration (m/s²)
//! and, for the S-curve, |s⃛| ≤ jerk (m/s³; none: the trapezoid).
struct TimeLawLimits {
  double acceleration = 0.0;   //!< m/s²
  std::optional<double> jerk;  //!< m/s³, S-curve only
};

//! A place inside the path where the trajectory comes to rest, and why.
struct Stop {
  double s;            //!< path position (m of DISP arc length)
  std::string reason;  //!< e.g. "the motion reverses ..."
};

//! A planned trajectory. A control loop samples consecutive cycles fastest with a Cursor
//! (sample(t, cursor)).
class Trajectory {
 public:
  //! The range of a speed override factor: 0.1 % to 10× (above 1 each span is capped at its
  //! ceiling anyway; below 0.1 % a law would outlast dispkin's numeric range).
  //!@{
  static constexpr double min_override = 1e-3, max_override = 10.0;
  //!@}

  Trajectory() = default;
  //! `path` run through by `law`, planned under the velocity-limit curve `speed_limits` with rests
  //! at `rest_positions` (0, every corner, path.length()).
  //! `stops`: why it rests at each inner rest position.
  //! `sources`: where each section comes from (empty: where it lies in the path's whole
  //! sections, SampledPath::parts()).
  //! `limits`: what the time law keeps to (what stopped_at(), resumed_at() and with_override()
  //! need; none for a law made under other limits, e.g. a re-timing under joint limits), and
  //! `override_factor`: the speed override the law runs at from its last event on (1: as planned).
  Trajectory(SampledPath path, TimeLaw law, std::vector<SpeedLimit> speed_limits, std::vector<double> rest_positions,
             std::vector<Stop> stops = {}, std::vector<SectionSource> sources = {},
             std::optional<TimeLawLimits> limits = std::nullopt, double override_factor = 1.0)
      : path_(std::move(path)),
        law_(std::move(law)),
        speed_limits_(std::move(speed_limits)),
        rest_s_(std::move(rest_positions)),
        stops_(std::move(stops)),
        sources_(std::move(sources)),
        limits_(limits),
        override_(override_factor),
        end_s_(law_end()) {
    require_consistent();
  }

  //! What every trajectory satisfies, whoever made it (plan, a re-timing, a pickle); the
  //! constructor checks it and throws std::invalid_argument naming the part otherwise:
  //! - the sections join (require_join) and each has one length L_k, finite and > 0, whose
  //!   inverse is finite (sampling divides by it);
  //! - the time law runs its pieces one after another (each starts where the one before ends, to
  //!   1e-9 of the path length), in at least one and at most one run per piece, from s = 0 to
  //!   the path's length (to 1e-9 of it) — or, for a stopped trajectory, to a position before
  //!   it where the last law ends at rest;
  //! - no piece is faster than the velocity-limit curve over its span allows (its peak at most the
  //!   largest ceiling of the spans it crosses, to 1e-8), every limit in dispkin's numeric range
  //!   and the spans in order along the path;
  //! - the limits, when given, and the override factor are in dispkin's numeric range;
  //! - the rests lie on the path in order; the section sources each name a part τ ⊂ [0, 1].
  //! The metric set is not part of a trajectory: the lengths themselves are taken as given.
  void require_consistent() const;

  //! The same path, velocity-limit curve and rests under another time law (re-timing), made
  //! under other limits: the result holds no TimeLawLimits.
  Trajectory with_time_law(TimeLaw law) const {
    return Trajectory(path_, std::move(law), speed_limits_, rest_s_, stops_, sources_);
  }

  //! @name Events in the control loop (doc/events.md)
  //! Each gives a new trajectory: the same motion up to t (bit for bit), then a new time law from
  //! the state there (s, ṡ, s̈) along the same path. They need the trajectory's limits() and throw
  //! std::invalid_argument naming t or the factor when out of range.
  //!@{
  //! Stops on the path: from the state at t the fastest stop to rest under the acceleration and
  //! jerk limits (doc/events.md eq. 2), the velocity-limit curve kept. At and after the end, or
  //! at rest, the motion is already stopped there. The path stays whole: resumed_at() goes on.
  Trajectory stopped_at(double t) const;
  //! Goes on from the state at t (a stopped trajectory at rest, or still braking) to the end of
  //! the path, at the override factor in force. Throws std::invalid_argument unless stopped().
  Trajectory resumed_at(double t) const;
  //! From the state at t the path continues under factor × the velocity-limit curve (each span at
  //! most its ceiling), the change time-optimal for the first span (doc/events.md §3); factor in
  //! [min_override, max_override]. Composes: the factor is relative to the curve as planned, not to the last override.
  //! A stopped trajectory keeps its stop and resumes at the new factor.
  Trajectory with_override(double t, double factor) const;
  //! Goes on at t over `longer`, a plan of this path extended (doc/events.md §5): the same motion
  //! up to t, then from the state there to the end of `longer`: this path up to the first start
  //! of a section as planned ahead of the state that `longer` holds at the same pose, longer's
  //! path and velocity-limit curve from there, at the override in force. Throws
  //! std::invalid_argument naming `longer` where it holds no such start ahead of the state (the
  //! state is past where the paths part), or this trajectory holds no limits.
  Trajectory continued_on(double t, const Trajectory& longer) const;
  //! The same path and velocity-limit curve run from the moving state ṡ = velocity (m/s, ≥ 0),
  //! s̈ = acceleration (m/s²) at its start instead of from rest, at the override in force
  //! (doc/events.md §3): over the first run the time-optimal law from that state — easing down
  //! first where it lies above the limit at the start, as after an override — then the laws of
  //! the other runs as planned. plan() starts so from PlanOptions::start_velocity, and
  //! MotionStream joins a move to a running motion so. Throws std::invalid_argument naming the
  //! velocity or the acceleration when not finite, above the highest limit at the start (its
  //! ceiling) or the acceleration limit (the trapezoid has no acceleration state: 0 only), or
  //! when the motion cannot come to rest within the first run; and when the trajectory was
  //! stopped or holds no limits.
  Trajectory starting_from(double velocity, double acceleration) const;
  //!@}

  //! What the time law keeps to, if known (plan() gives them; with_time_law() does not).
  const std::optional<TimeLawLimits>& limits() const noexcept { return limits_; }
  //! The speed override in force from the last event on (1 as planned).
  double override_factor() const noexcept { return override_; }
  //! Whether the motion ends at rest before the end of its path (stopped_at()).
  bool stopped() const noexcept { return end_s_ < path_.length(); }
  //! Where the motion ends (m of DISP arc length): length(), or where it stopped.
  double end_position() const noexcept { return end_s_; }

  const SampledPath& path() const noexcept { return path_; }  //!< the path, with its section lengths
  const TimeLaw& time_law() const noexcept { return law_; }   //!< s(t)

  double duration() const noexcept { return law_.duration(); }  //!< how long the motion takes (s)
  double length() const noexcept { return path_.length(); }     //!< the path's DISP length (m)
  //! The number of sections of the path.
  std::size_t section_count() const noexcept { return path_.section_count(); }
  //! The DISP length L_k of each section (m).
  const std::vector<double>& section_lengths() const noexcept { return path_.section_lengths(); }
  //! Number of rest-to-rest pieces (1 + corners where the trajectory stops).
  std::size_t piece_count() const noexcept { return law_.run_count(); }
  //! Number of time laws: each rest-to-rest piece has one per segment of its velocity-limit
  //! curve (plan() slows down where the path curves tightly).
  std::size_t law_count() const noexcept { return law_.size(); }

  //! Every phase boundary and phase middle of every time law, sorted, from 0 to duration(): the
  //! instants where velocity or acceleration peak or change their course (the KUKA re-timing
  //! patent's P0, P1, P12, P2, P3 for each law; doc/planning.md §5). Planning side; allocates.
  std::vector<double> characteristic_times() const { return law_.characteristic_times(); }

  //! The velocity-limit curve (system velocity, lowered where the path curves tightly), in
  //! order of s; together with rest_positions() what any re-timing must keep to.
  const std::vector<SpeedLimit>& speed_limits() const noexcept { return speed_limits_; }
  //! The path positions s where the trajectory is at rest: 0, every corner, length().
  const std::vector<double>& rest_positions() const noexcept { return rest_s_; }
  //! The inner rests (rest_positions() without 0 and length()) with the reason of each.
  const std::vector<Stop>& stops() const noexcept { return stops_; }
  //! Where each section comes from in the path as planned: for a plan, where it lies in the
  //! path's whole sections (the path as planned; empty when one to one).
  const std::vector<SectionSource>& section_sources() const noexcept {
    return sources_.empty() ? path_.parts() : sources_;
  }

  //! The pose at path position s (clamped to [0, length()]) and its body twist per unit of s
  //! (the body twist at ṡ = 1 m/s).
  void path_state(double s, Posed& pose, Twistd& twist_per_s) const noexcept { path_.state(s, pose, twist_per_s); }

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
  double law_end() const noexcept;  // where the last law ends (the path's length to 1e-9: that length)
  // This trajectory's path, velocity-limit curve and sources under another law, rests, stops and
  // override (the events): everything checked as the constructor does but the sections, which
  // are this trajectory's, checked when it was made.
  Trajectory with_events(TimeLaw law, std::vector<double> rests, std::vector<Stop> stops, double factor) const;
  void check(bool sections) const;
  // The motion up to `at` (TimeLaw::before), at rest where it ended for the time after its end,
  // and the state x there, from which a new law goes on.
  TimeLaw motion_until(double at, ProfileState& x) const;

  SampledPath path_;
  TimeLaw law_;
  std::vector<SpeedLimit> speed_limits_;
  std::vector<double> rest_s_;
  std::vector<Stop> stops_;
  std::vector<SectionSource> sources_;  // given apart from the path's parts (empty: those)
  std::optional<TimeLawLimits> limits_;
  double override_ = 1.0;
  double end_s_ = 0.0;  // where the last law ends: the path's length, or a stop before it
};

}  // namespace dispkin
