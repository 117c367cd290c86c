// A motion planned while it runs (motion_stream.hpp; doc/events.md §5).
#include "dispkin/planning/motion_stream.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

#include "dispkin/error.hpp"

namespace dispkin {

MotionStream::MotionStream(MetricSetd set, Limits limits, ProfileKind profile, double corner_tolerance)
    : set_(std::move(set)), limits_(limits), profile_(profile) {
  limits_.validate(profile_);
  if (profile_ == ProfileKind::trapezoid) limits_.jerk.reset();
  require(std::isfinite(corner_tolerance) && corner_tolerance >= 0.0, "corner_tolerance", corner_tolerance,
          "must be finite and not negative");
  options_.corner_tolerance = corner_tolerance;
}

Trajectory MotionStream::planned(const Path& path) const {
  const Trajectory trajectory = plan(path, set_, limits_, profile_, options_);
  return override_ == 1.0 ? trajectory : trajectory.with_override(0.0, override_);
}

void MotionStream::require_time(double t) {
  require(std::isfinite(t) && t >= last_request_, "t", t,
          "must be finite and not before the last request, at " + std::to_string(last_request_) + " s");
  last_request_ = t;
}

std::size_t MotionStream::leg_at(double t, std::size_t hint) const noexcept {
  // The last leg that starts at or before t (the first for t before every start).
  const std::size_t last = legs_.size() - 1;
  const auto is_it = [&](std::size_t k) { return (k == 0 || legs_[k].start <= t) && (k == last || t < legs_[k + 1].start); };
  if (hint <= last && is_it(hint)) return hint;
  if (hint < last && is_it(hint + 1)) return hint + 1;
  const auto next = std::upper_bound(legs_.begin(), legs_.end(), t, [](double x, const Leg& leg) { return x < leg.start; });
  return next == legs_.begin() ? 0 : static_cast<std::size_t>(next - legs_.begin()) - 1;
}

void MotionStream::continue_with(const Path& extra, double t) {
  Leg& leg = legs_.back();
  const double end = leg.start + leg.trajectory.duration();
  if (t < end) {
    // The motion runs: plan the leg's path with `extra` joined to it and go on over that plan from
    // the state at t, if the longer path is this one up to where the motion is (the join, and
    // the blend of its corner, lie ahead).
    Path longer = leg.path;
    longer.then(extra);
    try {
      Trajectory next = leg.trajectory.continued_on(t - leg.start, plan(longer, set_, limits_, profile_, options_));
      leg.trajectory = std::move(next);
      leg.path = std::move(longer);
      return;
    } catch (const std::invalid_argument&) {
      // Too late to join: the motion comes to rest at the end of the leg first.
    }
  }
  legs_.push_back(Leg{planned(extra), extra, std::max(t, end)});
}

void MotionStream::append(const Path& path, double t) {
  require_time(t);
  const Path* last = !waiting_.empty() ? &waiting_.back() : !legs_.empty() ? &legs_.back().path : nullptr;
  if (last) require_join(last->end(), path.start(), [] { return std::string("path.start"); });
  if (stopped_) {
    waiting_.push_back(path);
  } else if (legs_.empty()) {
    legs_.push_back(Leg{planned(path), path, t});
  } else {
    continue_with(path, t);
  }
}

void MotionStream::stop(double t) {
  require_time(t);
  require(!legs_.empty(), "t", t, "stops a motion: nothing was appended yet");
  require(!stopped_, "t", t, "stops a running motion: it is stopped already");
  // A leg that would start after t (a move that came late) waits for resume() instead.
  while (legs_.size() > 1 && legs_.back().start > t) {
    waiting_.insert(waiting_.begin(), legs_.back().path);
    legs_.pop_back();
  }
  Leg& leg = legs_.back();
  leg.trajectory = leg.trajectory.stopped_at(t - leg.start);
  stopped_ = true;
}

void MotionStream::resume(double t) {
  require_time(t);
  require(stopped_, "t", t, "resumes a stopped motion only");
  stopped_ = false;
  Leg& leg = legs_.back();
  if (leg.trajectory.stopped()) leg.trajectory = leg.trajectory.resumed_at(t - leg.start);
  std::vector<Path> waiting = std::move(waiting_);
  waiting_.clear();
  for (const Path& path : waiting) continue_with(path, t);
}

void MotionStream::set_override(double t, double factor) {
  require_time(t);
  require(factor >= Trajectory::min_override && factor <= Trajectory::max_override, "factor", factor, "must be in [0.001, 10]");
  override_ = factor;
  if (legs_.empty()) return;
  const std::size_t active = leg_at(t, legs_.size());
  for (std::size_t k = active; k < legs_.size(); ++k) {
    Leg& leg = legs_[k];
    leg.trajectory = leg.trajectory.with_override(std::max(t - leg.start, 0.0), factor);
  }
}

TrajectorySample MotionStream::sample(double t) const noexcept {
  Cursor cursor{legs_.size(), {}};
  return sample(t, cursor);
}

TrajectorySample MotionStream::sample(double t, Cursor& cursor) const noexcept {
  if (legs_.empty()) return TrajectorySample{};
  const std::size_t k = leg_at(t, cursor.leg);
  if (k != cursor.leg) cursor.trajectory = Trajectory::Cursor{};
  cursor.leg = k;
  const Leg& leg = legs_[k];
  return leg.trajectory.sample(t - leg.start, cursor.trajectory);
}

double MotionStream::duration() const noexcept {
  return legs_.empty() ? 0.0 : legs_.back().start + legs_.back().trajectory.duration();
}

}  // namespace dispkin
