// A motion planned while it runs (motion_stream.hpp; doc/events.md §5).
#include "dispkin/planning/motion_stream.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

#include "dispkin/error.hpp"

namespace dispkin {

namespace {

// ds_new / ds_old where the motion is: at s on `old` and at the start of `next`, one pose with
// twists per unit of s in one direction (1 where the path stands still).
double speed_ratio(const Trajectory& old, double s, const Trajectory& next) {
  Posed pose;
  Twistd per_s_old, per_s_next;
  old.path_state(s, pose, per_s_old);
  next.path_state(0.0, pose, per_s_next);
  const double a = per_s_old.vector().norm(), b = per_s_next.vector().norm();
  return a > 0.0 && b > 0.0 ? a / b : 1.0;
}

// The path of `trajectory` ahead of s: its sections from s on (the one holding s cut there, by
// τ as sampling computes it, so the cut starts where the motion is to rounding), with their move
// limits, in the moves they come from; none where nothing is left, or only a sliver.
std::optional<Path> path_ahead(const Trajectory& trajectory, const std::vector<MoveLimits>& move_limits,
                               const std::vector<std::size_t>& moves, double s) {
  const SampledPath& path = trajectory.path();
  const std::size_t n = path.section_count();
  const std::size_t first = path.section_at(s, n);
  const double length = path.section_lengths()[first];
  const double tau = std::clamp((s - path.section_start(first)) / length, 0.0, 1.0);
  std::vector<Section> sections;
  std::vector<MoveLimits> limits;
  std::vector<std::size_t> move_starts;
  for (std::size_t k = first; k < n; ++k) {
    if (k == first && tau > 0.0) {
      // Within 10⁻⁶ of the section's end the part left is a sliver whose twist direction is lost
      // to rounding (as blends snap there, path/blend.cpp): no path ahead starts there.
      if (tau > 1.0 - 1e-6) return std::nullopt;
      sections.push_back(section_part(path.section(k), tau, 1.0));
    } else {
      sections.push_back(path.section(k));
    }
    if (sections.size() == 1 || moves[k] != moves[k - 1]) move_starts.push_back(sections.size() - 1);
    limits.push_back(move_limits[k]);
  }
  if (sections.empty()) return std::nullopt;
  // Path::blended measures each move's size itself; the sizes given here are not used.
  return Path::from_sections(sections, 1.0, 1.0, limits, move_starts);
}

}  // namespace

MotionStream::MotionStream(MetricSetd set, Limits limits, ProfileKind profile, double corner_tolerance)
    : set_(std::move(set)), limits_(limits), profile_(profile) {
  limits_.validate(profile_);
  if (profile_ == ProfileKind::trapezoid) limits_.jerk.reset();
  require(std::isfinite(corner_tolerance) && corner_tolerance >= 0.0, "corner_tolerance", corner_tolerance,
          "must be finite and not negative");
  options_.corner_tolerance = corner_tolerance;
}

Path MotionStream::blended_path(const Path& path) const {
  return options_.corner_tolerance > 0.0 ? path.blended(options_.corner_tolerance, nullptr, options_.blend_tolerance)
                                         : path;
}

Trajectory MotionStream::planned(const Path& path) const {
  const Trajectory trajectory = plan(path, set_, limits_, profile_);
  return override_ == 1.0 ? trajectory : trajectory.with_override(0.0, override_);
}

void MotionStream::require_time(double t) {
  require(std::isfinite(t) && t >= last_request_, "t", t,
          "must be finite and not before the last request, at " + std::to_string(last_request_) + " s");
  last_request_ = t;
}

std::size_t MotionStream::stretch_at(double t, std::size_t hint) const noexcept {
  // The last stretch that starts at or before t (the first for t before every start).
  const std::size_t last = stretches_.size() - 1;
  const auto is_it = [&](std::size_t k) {
    return (k == 0 || stretches_[k].start <= t) && (k == last || t < stretches_[k + 1].start);
  };
  if (hint <= last && is_it(hint)) return hint;
  if (hint < last && is_it(hint + 1)) return hint + 1;
  const auto next =
      std::upper_bound(stretches_.begin(), stretches_.end(), t, [](double x, const Stretch& k) { return x < k.start; });
  return next == stretches_.begin() ? 0 : static_cast<std::size_t>(next - stretches_.begin()) - 1;
}

MotionStream::Stretch MotionStream::stretch(Trajectory trajectory, const Path& path, double start, double s,
                                            bool from_rest) {
  Stretch out;
  out.start = start;
  out.s = s;
  out.from_rest = from_rest;
  // Each section of the trajectory is a part of a section of the planned path.
  const std::vector<SectionSource>& sources = trajectory.section_sources();
  const std::vector<std::size_t>& move_starts = path.move_starts();
  for (std::size_t k = 0; k < trajectory.section_count(); ++k) {
    const std::size_t section = sources.empty() ? k : sources[k].section;
    out.limits.push_back(path.section_limits()[section]);
    out.moves.push_back(static_cast<std::size_t>(std::upper_bound(move_starts.begin(), move_starts.end(), section) -
                                                 move_starts.begin()));
  }
  out.trajectory = std::make_shared<const Trajectory>(std::move(trajectory));
  return out;
}

void MotionStream::push(Stretch next) {
  // A stretch that starts where the last one does replaces it: nothing samples that one.
  if (!stretches_.empty() && stretches_.back().start == next.start) {
    rest_starts_ -= stretches_.back().from_rest ? 1 : 0;
    stretches_.pop_back();
  }
  rest_starts_ += next.from_rest ? 1 : 0;
  changed_from_ = next.start;
  stretches_.push_back(std::move(next));
}

std::optional<MotionStream::Stretch> MotionStream::joined(const Path& extra, double at) const {
  const Stretch& last = stretches_.back();
  const Trajectory& running = *last.trajectory;
  std::size_t piece = running.time_law().size();
  const ProfileState x = running.time_law().state_at(at - last.start, piece);
  std::optional<Path> ahead = path_ahead(running, last.limits, last.moves, x.s);
  if (!ahead) return std::nullopt;
  ahead->then(extra);
  const Path path = blended_path(*ahead);
  try {
    const Trajectory from_rest = planned(path);
    // The same motion in the new plan's s: its sections are bounded afresh, so one unit of s is
    // another stretch of the path there. Within a section s ↦ τ is affine, so ṡ and s̈ both
    // scale by the ratio of the twists per unit of s (doc/events.md eq. 7).
    const double r = speed_ratio(running, x.s, from_rest);
    const double a = profile_ == ProfileKind::scurve ? r * x.a : 0.0;  // the trapezoid has no acceleration state
    Stretch out = stretch(from_rest.starting_from(std::max(r * x.v, 0.0), a), path, at, last.s + x.s,
                          x.s == 0.0 && last.from_rest);
    out.unstarted = last.start == at ? last.unstarted : std::vector<Path>{};
    out.unstarted.push_back(extra);
    return out;
  } catch (const std::invalid_argument&) {
    // The state lies above the new plan's limits there (the path ahead is slower per unit of s
    // than what runs), or cannot keep to them.
    return std::nullopt;
  }
}

void MotionStream::continue_with(const Path& extra, double t) {
  const Stretch& last = stretches_.back();
  const double end = last.start + last.trajectory->duration();
  if (t < end) {
    // The motion runs (or waits to start): the path ahead of it and `extra`, from the state at t
    // (§5). Where that state lies above the new plan's limits — a slower move joins the blended
    // chain, whose lengths are balanced along it (doc/planning.md eq. 34) — the motion runs on as
    // planned a little longer, braking for its end, and joins later.
    const double from = std::max(t, last.start);
    for (const double share : {0.0, 0.25, 0.5, 0.75, 0.9}) {
      std::optional<Stretch> next = joined(extra, from + share * (end - from));
      if (next) {
        push(std::move(*next));
        return;
      }
    }
  }
  const Path path = blended_path(extra);
  Stretch next = stretch(planned(path), path, std::max(t, end), last.s + last.trajectory->end_position(), true);
  next.unstarted.push_back(extra);
  push(std::move(next));
}

void MotionStream::append(const Path& path, double t) {
  require_time(t);
  changed_from_ = std::numeric_limits<double>::infinity();
  if (last_end_) require_join(*last_end_, path.start(), [] { return std::string("path.start"); });
  last_end_ = path.end();
  if (stopped_) {
    waiting_.push_back(path);
  } else if (stretches_.empty()) {
    const Path blended = blended_path(path);
    Stretch first = stretch(planned(blended), blended, t, 0.0, true);
    first.unstarted.push_back(path);
    push(std::move(first));
  } else {
    continue_with(path, t);
  }
}

void MotionStream::stop(double t) {
  require_time(t);
  require(!stretches_.empty(), "t", t, "stops a motion: nothing was appended yet");
  require(!stopped_, "t", t, "stops a running motion: it is stopped already");
  // A stretch that would start after t (a move that came late, or a join that takes over later)
  // does not: its moves wait for resume().
  if (stretches_.size() > 1 && stretches_.back().start > t) {
    waiting_.insert(waiting_.begin(), stretches_.back().unstarted.begin(), stretches_.back().unstarted.end());
    rest_starts_ -= stretches_.back().from_rest ? 1 : 0;
    stretches_.pop_back();
  }
  Stretch& last = stretches_.back();
  last.trajectory = std::make_shared<const Trajectory>(last.trajectory->stopped_at(t - last.start));
  stopped_ = true;
  changed_from_ = t;
}

void MotionStream::resume(double t) {
  require_time(t);
  require(stopped_, "t", t, "resumes a stopped motion only");
  stopped_ = false;
  Stretch& last = stretches_.back();
  if (last.trajectory->stopped())
    last.trajectory = std::make_shared<const Trajectory>(last.trajectory->resumed_at(t - last.start));
  std::vector<Path> waiting = std::move(waiting_);
  waiting_.clear();
  for (const Path& path : waiting) continue_with(path, t);
  changed_from_ = t;
}

void MotionStream::set_override(double t, double factor) {
  require_time(t);
  require(factor >= Trajectory::min_override && factor <= Trajectory::max_override, "factor", factor,
          "must be in [0.001, 10]");
  override_ = factor;
  if (stretches_.empty()) return;
  changed_from_ = t;
  for (std::size_t k = stretch_at(t, stretches_.size()); k < stretches_.size(); ++k) {
    Stretch& stretch = stretches_[k];
    stretch.trajectory =
        std::make_shared<const Trajectory>(stretch.trajectory->with_override(std::max(t - stretch.start, 0.0), factor));
  }
}

void MotionStream::forget_before(double t) noexcept {
  if (stretches_.empty() || !(t > stretches_.front().start)) return;
  const std::size_t active = stretch_at(t, stretches_.size());
  stretches_.erase(stretches_.begin(), stretches_.begin() + static_cast<std::ptrdiff_t>(active));
}

TrajectorySample MotionStream::sample(double t) const noexcept {
  Cursor cursor{stretches_.size(), {}};
  return sample(t, cursor);
}

TrajectorySample MotionStream::sample(double t, Cursor& cursor) const noexcept {
  if (stretches_.empty()) return TrajectorySample{};
  const std::size_t k = stretch_at(t, cursor.leg);
  if (k != cursor.leg) cursor.trajectory = Trajectory::Cursor{};
  cursor.leg = k;
  const Stretch& stretch = stretches_[k];
  TrajectorySample x = stretch.trajectory->sample(t - stretch.start, cursor.trajectory);
  x.s += stretch.s;
  return x;
}

double MotionStream::duration() const noexcept {
  return stretches_.empty() ? 0.0 : stretches_.back().start + stretches_.back().trajectory->duration();
}

}  // namespace dispkin
