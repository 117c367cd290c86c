//! A motion planned while it runs: moves appended one after another, a stop on the path, a
//! resumption and a speed override at any instant (doc/events.md §5). Sampling is noexcept,
//! allocation-free and lock-free; requests (append, stop, resume, set_override) plan, allocate
//! and may throw. A MotionStream is a value: a worker thread copies it, applies a request to
//! the copy and hands it to the control thread, which swaps it in at a cycle boundary
//! (examples/06_control_loop.cpp).
#pragma once

#include <cstddef>
#include <limits>
#include <memory>
#include <optional>
#include <vector>

#include "dispkin/metric_set.hpp"
#include "dispkin/path/path.hpp"
#include "dispkin/planning/planner.hpp"
#include "dispkin/planning/trajectory.hpp"

namespace dispkin {

//! Moves appended while the motion runs, under one metric set and limits. What is planned always
//! ends at rest at the last appended pose, so the motion is safe whenever the next move comes
//! late; a move that comes in time is joined to the motion without a stop (corners blended
//! within `corner_tolerance`, as plan() does). Every request at time t leaves the motion before
//! t as it was, bit for bit.
class MotionStream {
 public:
  //! Where a sequence of samples has got to (sample(t, cursor)); any value is valid.
  struct Cursor {
    std::size_t leg = 0;            //!< the stretch of motion of the last sample
    Trajectory::Cursor trajectory;  //!< where in that stretch's trajectory
  };

  //! An empty stream under `set` and `limits` (validated as plan() does), with the `profile`
  //! law and corners blended within `corner_tolerance` (m; 0: every corner a stop).
  MotionStream(MetricSetd set, Limits limits, ProfileKind profile = ProfileKind::scurve, double corner_tolerance = 0.0);

  //! Appends `path` at time t: it starts where the last appended move ends (the first: anywhere).
  //! While the motion runs, what lies ahead of it from t on — the rest of what is planned, then
  //! `path`, its corner blended from where the motion is — is planned again from the state at t
  //! (PlanOptions::start_velocity): the cost is that of the look-ahead, not of the moves run.
  //! When the motion has ended, `path` runs from rest. While stopped, the move waits for
  //! resume(). Throws std::invalid_argument naming `path` or t (finite, not before the last
  //! request).
  void append(const Path& path, double t);
  //! Stops on the path from the state at t, as fast as the limits allow (Trajectory::stopped_at);
  //! moves appended while stopped wait for resume().
  void stop(double t);
  //! Goes on at t from where the stop left the motion (at rest, or still braking) through every
  //! move appended. Throws std::invalid_argument unless stopped.
  void resume(double t);
  //! The speed override from t on (Trajectory::with_override; factor in [0.001, 10]); moves
  //! appended later run at it too.
  void set_override(double t, double factor);

  //! Lets go of the stretches of motion that ended before t (a stream keeps all it ran, so that
  //! any past time can be sampled; a controller streaming for hours calls this now and then to
  //! keep its memory to the look-ahead). Samples before t are not kept: there the stream gives
  //! the state where the first stretch kept starts. Nothing at or after t changes; sampling with
  //! a cursor made before goes on (the cursor finds its stretch again).
  void forget_before(double t) noexcept;

  //! The state at t: before the first move, a default sample; after the end, at rest at the end.
  TrajectorySample sample(double t) const noexcept;
  //! The same, found from `cursor` (constant time for consecutive cycles).
  TrajectorySample sample(double t, Cursor& cursor) const noexcept;

  //! When what is planned now ends, at rest (s); 0 before the first move.
  double duration() const noexcept;
  //! Whether the motion has run everything planned by t (at rest at the last pose, or stopped).
  bool done(double t) const noexcept { return t >= duration(); }
  //! Whether a stop holds the motion (until resume()).
  bool stopped() const noexcept { return stopped_; }
  //! The override in force.
  double override_factor() const noexcept { return override_; }
  //! Moves appended while stopped, waiting for resume().
  std::size_t waiting_moves() const noexcept { return waiting_.size(); }
  //! From when the last request changed the motion (s): samples before it are as they were, bit
  //! for bit (a controller that samples ahead keeps what it sampled before this time). A stop,
  //! a resumption and an override change it from their t; an append from where the joined plan
  //! takes over (t, or later while the motion brakes for its end) or where its leg from rest
  //! starts; +∞ where nothing changed (a move that waits for resume()).
  double changed_from() const noexcept { return changed_from_; }
  //! Legs: stretches of motion that start from rest (a move that came late starts a new one).
  std::size_t leg_count() const noexcept { return rest_starts_; }

 private:
  // A stretch of the motion: its trajectory runs in stream time t − start, from `start` until
  // the next stretch starts. A join starts a new stretch from the state where it takes over; the
  // trajectories are immutable and shared, so copying a stream copies pointers.
  struct Stretch {
    std::shared_ptr<const Trajectory> trajectory;
    double start = 0.0;
    double s = 0.0;          // the stream's arc length where it starts (its trajectory's s = 0)
    bool from_rest = false;  // a leg (leg_count)
    // The move limits and the move of each section of the trajectory (what planning the path
    // ahead again needs).
    std::vector<MoveLimits> limits;
    std::vector<std::size_t> moves;
    // The moves appended while it had not started yet: a stop before its start puts them back
    // in the queue.
    std::vector<Path> unstarted;
  };

  Path blended_path(const Path& path) const;  // its corners blended as plan() does
  // A blended path from rest, at the override in force.
  Trajectory planned(const Path& path) const;
  void require_time(double t);
  std::size_t stretch_at(double t, std::size_t hint) const noexcept;
  // Runs `extra` after what is planned: joined to the motion ahead of t where it can be, else
  // from rest at the end.
  void continue_with(const Path& extra, double t);
  // The last stretch with `extra` joined from its state at time `at` (≥ its start), or none
  // where the state does not keep to the path ahead planned afresh.
  std::optional<Stretch> joined(const Path& extra, double at) const;
  // A stretch of `trajectory` planned over `path`.
  static Stretch stretch(Trajectory trajectory, const Path& path, double start, double s, bool from_rest);
  void push(Stretch next);

  MetricSetd set_;
  Limits limits_;
  ProfileKind profile_;
  PlanOptions options_;
  double override_ = 1.0;
  bool stopped_ = false;
  double last_request_ = 0.0;
  double changed_from_ = std::numeric_limits<double>::infinity();
  std::size_t rest_starts_ = 0;
  std::vector<Stretch> stretches_;
  std::vector<Path> waiting_;
  std::optional<Posed> last_end_;  // where the last appended move ends
};

}  // namespace dispkin
