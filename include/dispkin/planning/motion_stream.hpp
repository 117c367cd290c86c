//! A motion planned while it runs: moves appended one after another, a stop on the path, a
//! resumption and a speed override at any instant (doc/events.md §5). Sampling is noexcept,
//! allocation-free and lock-free; requests (append, stop, resume, set_override) plan, allocate
//! and may throw. A MotionStream is a value: a worker thread copies it, applies a request to
//! the copy and hands it to the control thread, which swaps it in at a cycle boundary
//! (examples/06_control_loop.cpp).
#pragma once

#include <cstddef>
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
    std::size_t leg = 0;             //!< the leg of the last sample
    Trajectory::Cursor trajectory;  //!< where in that leg's trajectory
  };

  //! An empty stream under `set` and `limits` (validated as plan() does), with the `profile`
  //! law and corners blended within `corner_tolerance` (m; 0: every corner a stop).
  MotionStream(MetricSetd set, Limits limits, ProfileKind profile = ProfileKind::scurve, double corner_tolerance = 0.0);

  //! Appends `path` at time t: it starts where the last appended move ends (the first: anywhere).
  //! While the motion runs and the join lies ahead of it, the motion from t on is planned again
  //! over the longer path (the look-ahead); otherwise `path` runs from rest after what is planned.
  //! While stopped, the move waits for resume(). Throws std::invalid_argument naming `path` or
  //! t (finite, not before the last request).
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
  //! Legs: stretches of motion that start from rest (a move that came late starts a new one).
  std::size_t leg_count() const noexcept { return legs_.size(); }

 private:
  struct Leg {
    Trajectory trajectory;  // over `path`, in leg time t − start
    Path path;              // the moves of the leg
    double start = 0.0;     // stream time of the leg's t = 0
  };

  Trajectory planned(const Path& path) const;  // a leg's plan at the override in force
  void require_time(double t);
  std::size_t leg_at(double t, std::size_t hint) const noexcept;
  // Runs `extra` after the current leg: joined to it at t when the join lies ahead, else as a new
  // leg from rest at its end.
  void continue_with(const Path& extra, double t);

  MetricSetd set_;
  Limits limits_;
  ProfileKind profile_;
  PlanOptions options_;
  double override_ = 1.0;
  bool stopped_ = false;
  double last_request_ = 0.0;
  std::vector<Leg> legs_;
  std::vector<Path> waiting_;
};

}  // namespace dispkin
