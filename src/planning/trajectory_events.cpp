// Events on a planned trajectory: a stop on the path, a resumption, a speed override
// (trajectory.hpp; doc/events.md). Each keeps the motion up to the event as it is and appends a
// new time law from the state there, along the same path.
#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "dispkin/error.hpp"
#include "dispkin/planning/trajectory.hpp"
#include "dispkin/planning/velocity_limit.hpp"
#include "law_from_state.hpp"
#include "law_under_curve.hpp"
#include "../message_number.hpp"

namespace dispkin {

using detail::number;  // message_number.hpp

namespace {

// The staircase over [s0, s1] (doc/events.md eq. 5): the parts of the spans there, each limit
// scaled by the override and capped at the span's ceiling.
std::vector<LimitedSegment> staircase(const std::vector<SpeedLimit>& spans, double s0, double s1, double factor) {
  std::vector<LimitedSegment> out;
  const double tiny = 1e-12 * std::max(1.0, std::abs(s1));
  for (const SpeedLimit& span : spans) {
    const double a = std::max(s0, span.start_s), b = std::min(s1, span.start_s + span.length);
    if (b - a <= tiny) continue;
    out.push_back({b - a, std::min(factor * span.limit, span.top()), span.acceleration});
  }
  // Rounding of the span ends: the segments cover [s0, s1] exactly.
  if (!out.empty()) {
    double covered = 0.0;
    for (const LimitedSegment& g : out) covered += g.length;
    out.back().length = std::max(out.back().length + (s1 - s0 - covered), 0.5 * out.back().length);
  }
  return out;
}

// The smallest acceleration limit of the spans over [s0, s1] and of the law itself.
double smallest_acceleration(const std::vector<SpeedLimit>& spans, double s0, double s1, double a_max) {
  double a = a_max;
  for (const SpeedLimit& span : spans)
    if (span.start_s < s1 && span.start_s + span.length > s0 && span.acceleration > 0.0)
      a = std::min(a, span.acceleration);
  return a;
}

// The state at t (clamped to the motion) of `law`.
// The state at t (clamped to the motion) of `law`; ṡ at least 0 (a law ending at rest may give
// −1e-34 by rounding, and no law runs backwards).
ProfileState state_at(const TimeLaw& law, double t) {
  std::size_t piece = law.size();
  ProfileState x = law.state_at(std::clamp(t, 0.0, law.duration()), piece);
  x.v = std::max(x.v, 0.0);
  return x;
}

const TimeLawLimits& limits_of(const std::optional<TimeLawLimits>& limits, const char* what) {
  if (!limits)
    throw std::invalid_argument(
        std::string(what) +
        ": the trajectory holds no time-law limits (a re-timed or older trajectory): plan it again");
  return *limits;
}

void require_time(double t) { require(std::isfinite(t), "t", t, "must be finite"); }

// The reason of the rest a stop adds (stopped_at), by which resumed_at finds it.
constexpr const char* stopped_reason = "stopped at t = ";

bool is_stop_of_event(const Stop& stop) { return stop.reason.rfind(stopped_reason, 0) == 0; }

}  // namespace

Trajectory Trajectory::stopped_at(double t) const {
  require_time(t);
  const TimeLawLimits& limits = limits_of(limits_, "stopped_at");
  if (t >= duration()) return *this;  // at rest at its end already
  const double at = std::max(t, 0.0);
  const ProfileState x = state_at(law_, at);
  TimeLaw law = law_.before(at);
  // The fastest stop under the smallest acceleration limit of the spans it crosses (doc/events.md eq. 4): the
  // spans it crosses under one limit can only be fewer under a smaller one.
  double a = limits.acceleration;
  std::optional<Profile> stop = detail::fastest_stop(x.v, x.a, a, limits.jerk);
  for (int i = 0; i < 8 && stop; ++i) {
    const double a_spans = smallest_acceleration(speed_limits_, x.s, x.s + stop->distance(), limits.acceleration);
    if (a_spans >= a) break;
    a = a_spans;
    stop = detail::fastest_stop(x.v, x.a, a, limits.jerk);
  }
  // The run ends with the stop; at rest between runs (or where the motion ended) it has ended
  // already.
  const bool running = stop || law.size() == 0 || law.pieces().back().cut;
  if (stop) law.append(*stop, x.s);
  if (law.size() == 0) law.append(Profile::trapezoid(0.0, 1.0, 1.0), 0.0);  // stopped before it started
  if (running || law.run_count() == 0) law.end_run();
  // Where it rests is a rest of the trajectory, with its reason (unless it is one already: a
  // corner, or the start).
  const TimeLaw::Piece& last = law.pieces().back();
  const double s_end = last.start_s + last.distance(), tol = 1e-9 * length();
  std::vector<double> rests = rest_s_;
  std::vector<Stop> stops = stops_;
  if (s_end < length() - tol) {
    const auto near = [&](double s) { return std::abs(s - s_end) <= tol; };
    if (std::none_of(rests.begin(), rests.end(), near))
      rests.insert(std::upper_bound(rests.begin(), rests.end(), s_end), s_end);
    if (std::none_of(stops.begin(), stops.end(), [&](const Stop& other) { return near(other.s); })) {
      const auto after =
          std::upper_bound(stops.begin(), stops.end(), s_end, [](double s, const Stop& other) { return s < other.s; });
      stops.insert(after, Stop{s_end, stopped_reason + number(at) + " s"});
    }
  }
  return with_events(std::move(law), std::move(rests), std::move(stops), override_);
}

namespace {

// Whether `laws`, run one after another from s, keep under the curve as planned (the tops of
// `spans`) at every position.
bool keep_under_curve(const std::vector<Profile>& laws, double s, const std::vector<SpeedLimit>& spans, double tol) {
  std::size_t first = 0;
  for (const Profile& piece : laws) {
    while (first + 1 < spans.size() && spans[first].start_s + spans[first].length < s - tol) ++first;
    if (!detail::keeps_under_tops(piece, piece.duration(), s, piece.peak_velocity(), spans, first, tol)) return false;
    s += piece.distance();
  }
  return true;
}

// What a law from a moving state does where it cannot keep under the curve ahead (the state
// carries acceleration into a lower limit that a law ending at s̈ = 0 cannot meet in time).
enum class AboveCurve { stop_first, refuse };

// The laws from the state x at `at` to the end of the path at `factor` (doc/events.md §3): the
// first run from the state to the next rest, the others from rest to rest as planned. Where
// the law of §3 from the state would cross the curve, the fastest stop and a restart
// (AboveCurve::stop_first), or std::invalid_argument (AboveCurve::refuse).
void append_continuation(TimeLaw& law, const ProfileState& x, const std::vector<SpeedLimit>& spans,
                         const std::vector<double>& rests, double length, const TimeLawLimits& limits, double factor,
                         AboveCurve above = AboveCurve::stop_first) {
  std::vector<double> ends;
  const double tol = 1e-9 * length;
  for (double r : rests)
    if (r > x.s + tol) ends.push_back(r);
  if (ends.empty() || ends.back() < length - tol) ends.push_back(length);
  double s0 = x.s;
  bool first = true;
  for (double s1 : ends) {
    const std::vector<LimitedSegment> segments = staircase(spans, s0, s1, factor);
    if (segments.empty()) continue;
    const bool moving = first && (x.v != 0.0 || (limits.jerk && x.a != 0.0));
    std::vector<Profile> laws =
        moving ? detail::staircase_law_from_state(segments, limits.acceleration, limits.jerk, x.v, x.a, tol)
               : velocity_limited_law(segments, limits.acceleration, limits.jerk);
    if (moving && !keep_under_curve(laws, s0, spans, tol)) {
      if (above == AboveCurve::refuse)
        throw std::invalid_argument(
            describe("state", Eigen::Vector2d(x.v, x.a),
                     "lies above the velocity-limit curve ahead: no law from it keeps to the curve"));
      laws = detail::stop_then_staircase(segments, limits.acceleration, limits.jerk, x.v, x.a, tol);
    }
    double s = s0;
    for (const Profile& piece : laws) {
      law.append(piece, s);
      s += piece.distance();
    }
    law.end_run();
    s0 = s1;
    first = false;
  }
}

}  // namespace

TimeLaw Trajectory::motion_until(double at, ProfileState& x) const {
  TimeLaw law = law_.before(at);
  x = state_at(law_, at);
  if (at > duration()) {
    // At rest where the motion ended until `at`.
    const double wait = at - duration(), no_jerk = 0.0;
    law.append(Profile::from_phases(&wait, &no_jerk, 1, 0.0, 0.0, 0.0, 0.0, 0.0), end_s_);
    x = ProfileState{end_s_, 0.0, 0.0, 0.0};
  }
  return law;
}

Trajectory Trajectory::resumed_at(double t) const {
  require_time(t);
  const TimeLawLimits& limits = limits_of(limits_, "resumed_at");
  require(stopped(), "t", t, "resumes a stopped trajectory only: this one runs to the end of its path");
  // The rest the stop added goes; a planned one (a corner, the start) stays.
  const double tol = 1e-9 * length();
  std::vector<Stop> stops = stops_;
  std::vector<double> rests = rest_s_;
  const auto ours = std::find_if(stops.begin(), stops.end(),
                                 [&](const Stop& x) { return is_stop_of_event(x) && std::abs(x.s - end_s_) <= tol; });
  if (ours != stops.end()) {
    stops.erase(ours);
    const auto rest = std::find_if(rests.begin(), rests.end(), [&](double r) { return std::abs(r - end_s_) <= tol; });
    if (rest != rests.end() && *rest > 0.0) rests.erase(rest);
  }
  const double at = std::max(t, 0.0);
  ProfileState x;
  TimeLaw law = motion_until(at, x);
  append_continuation(law, x, speed_limits_, rests, length(), limits, override_);
  return with_events(std::move(law), std::move(rests), std::move(stops), override_);
}

Trajectory Trajectory::with_override(double t, double factor) const {
  require_time(t);
  require(factor >= min_override && factor <= max_override, "factor", factor,
          "must be in [" + number(min_override) + ", " + number(max_override) + "]");
  const TimeLawLimits& limits = limits_of(limits_, "with_override");
  // A stop keeps braking as fast as it can; the new factor holds from the resumption on. At the
  // end nothing is left to run at it.
  if (stopped() || t >= duration()) return with_events(law_, rest_s_, stops_, factor);
  const double at = std::max(t, 0.0);
  const ProfileState x = state_at(law_, at);
  // Within rounding of the end nothing is left to run at it.
  if (x.s >= length() * (1.0 - 1e-9)) return with_events(law_, rest_s_, stops_, factor);
  TimeLaw law = law_.before(at);
  append_continuation(law, x, speed_limits_, rest_s_, length(), limits, factor);
  return with_events(std::move(law), rest_s_, stops_, factor);
}

Trajectory Trajectory::starting_from(double velocity, double acceleration) const {
  const TimeLawLimits& limits = limits_of(limits_, "starting_from");
  require(std::isfinite(velocity) && velocity >= 0.0, "velocity", velocity, "must be finite and ≥ 0 (m/s)");
  require(std::isfinite(acceleration), "acceleration", acceleration, "must be finite (m/s²)");
  require(!stopped(), "velocity", velocity,
          "starts a trajectory that runs to the end of its path: this one was stopped");
  if (!limits.jerk)
    require(acceleration == 0.0, "acceleration", acceleration,
            "is not a state of the trapezoid law (s̈ jumps there): it must be 0");
  require(std::abs(acceleration) <= limits.acceleration * (1.0 + 1e-12), "acceleration", acceleration,
          "must be within the acceleration limit, ±" + number(limits.acceleration) + " m/s²");
  // Above the limit at the start (scaled by the override, doc/events.md eq. 5) the law eases down onto it as
  // after an override (§3); never above what the path allows there at all, its ceiling.
  const double top = speed_limits_.empty() ? 0.0 : speed_limits_.front().top();
  require(velocity <= top * (1.0 + 1e-12), "velocity", velocity,
          "must be at most the highest velocity limit at the start of the path, " + number(top) + " m/s");
  // Braking so hard that ṡ would reach 0 before the jerk limit brings s̈ back to 0 (v_r < 0 in
  // doc/events.md eq. 1): no law from that state keeps to the limits without running backwards.
  if (limits.jerk && acceleration < 0.0) {
    const double release = acceleration * acceleration / (2.0 * *limits.jerk);
    require(release <= velocity * (1.0 + 1e-9), "acceleration", acceleration,
            "brakes harder than the jerk limit " + number(*limits.jerk) + " m/s³ can end before the velocity " +
                number(velocity) + " m/s reaches 0 (it needs at least " + number(release) + " m/s)");
  }
  if (velocity == 0.0 && acceleration == 0.0) return *this;
  // Moving at s = 0: no rest there; the other rests stay.
  std::vector<double> rests;
  for (double r : rest_s_)
    if (r > 1e-9 * length()) rests.push_back(r);
  TimeLaw law;
  try {
    append_continuation(law, ProfileState{0.0, velocity, acceleration, 0.0}, speed_limits_, rests, length(), limits,
                        override_, AboveCurve::refuse);
  } catch (const std::invalid_argument&) {
    const double run = rests.empty() ? length() : rests.front();
    throw std::invalid_argument(describe("velocity", velocity,
                                         "with acceleration " + number(acceleration) +
                                             " m/s² cannot keep to the velocity-limit curve of the first run of "
                                             "the path, " +
                                             number(run) + " m, and come to rest within it"));
  }
  return with_events(std::move(law), std::move(rests), stops_, override_);
}

namespace {

// Where `longer` takes over from `path` (doc/events.md §5): the first start of a section as
// planned (τ = 0 of planned section i, or the end of `path`) at or after s that both hold at the
// same pose, bit for bit; `here` and `there` index the trajectory sections starting there.
struct Splice {
  std::size_t here, there;
};

// Sections of sampled paths gathered into one: each whole section once per run of its parts.
struct SampledPathParts {
  std::vector<Section> sections;
  std::vector<SectionSource> parts;
  std::vector<double> lengths;

  // Sections [from, to) of `path`.
  void append(const SampledPath& path, std::size_t from, std::size_t to) {
    std::size_t last = path.whole_sections().size();  // none yet
    for (std::size_t k = from; k < to; ++k) {
      const SectionSource part = path.part(k);
      if (part.section != last) {
        sections.push_back(path.whole_sections()[part.section]);
        last = part.section;
      }
      parts.push_back({sections.size() - 1, part.tau_start, part.tau_end});
      lengths.push_back(path.section_lengths()[k]);
    }
  }
};

SectionSource source_of(const Trajectory& traj, std::size_t k) {
  return traj.section_sources().empty() ? SectionSource{k, 0.0, 1.0} : traj.section_sources()[k];
}

std::optional<Splice> splice_point(const Trajectory& path, const Trajectory& longer, double s) {
  const std::size_t n = path.section_count(), m = longer.section_count();
  std::size_t there = 0;
  for (std::size_t here = path.path().section_at(s, n); here <= n; ++here) {
    const bool end = here == n;
    if (!end && (path.path().section_start(here) < s || source_of(path, here).tau_start != 0.0)) continue;
    if (end && source_of(path, n - 1).tau_end != 1.0) break;
    const std::size_t planned = end ? source_of(path, n - 1).section + 1 : source_of(path, here).section;
    while (there < m && source_of(longer, there).section < planned) ++there;
    if (there == m) break;
    const SectionSource other = source_of(longer, there);
    if (other.section != planned || other.tau_start != 0.0) continue;
    Posed a, b;
    Twistd ta, tb;
    if (end)
      path.path().section_state_at(n - 1, 1.0, a, ta);
    else
      path.path().section_state_at(here, 0.0, a, ta);
    longer.path().section_state_at(there, 0.0, b, tb);
    if (a.matrix() == b.matrix()) return Splice{here, there};
  }
  return std::nullopt;
}

}  // namespace

Trajectory Trajectory::continued_on(double t, const Trajectory& longer) const {
  require_time(t);
  const TimeLawLimits& limits = limits_of(limits_, "continued_on");
  const double at = std::max(t, 0.0);
  ProfileState x;
  TimeLaw law = motion_until(at, x);
  const std::optional<Splice> splice = splice_point(*this, longer, x.s);
  if (!splice)
    throw std::invalid_argument(describe("longer", "Trajectory",
                                         "must go on from a section start of this path ahead of s = " + number(x.s) +
                                             " m (the position at t = " + number(at) +
                                             " s), at the same pose: it is no plan of this path extended"));
  // This path up to the splice, longer's from there on, its positions moved by Δ.
  const std::size_t here = splice->here, there = splice->there;
  const double s_here = here == section_count() ? length() : path_.section_start(here);
  const double shift = s_here - longer.path_.section_start(there), tol = 1e-9 * std::max(length(), longer.length());
  SampledPathParts joined;
  joined.append(path_, 0, here);
  joined.append(longer.path_, there, longer.section_count());
  // Where the sections come from in the two paths as planned.
  std::vector<SectionSource> sources;
  const std::vector<SectionSource>&mine = section_sources(), &theirs = longer.section_sources();
  if (!mine.empty() && !theirs.empty()) {
    sources.assign(mine.begin(), mine.begin() + static_cast<std::ptrdiff_t>(here));
    sources.insert(sources.end(), theirs.begin() + static_cast<std::ptrdiff_t>(there), theirs.end());
  }
  std::vector<SpeedLimit> spans;
  for (const SpeedLimit& span : speed_limits_) {
    if (span.start_s >= s_here - tol) break;
    spans.push_back(span);
    spans.back().length = std::min(span.length, s_here - span.start_s);
  }
  for (const SpeedLimit& span : longer.speed_limits_) {
    const double from = std::max(span.start_s, s_here - shift);
    if (span.start_s + span.length <= from + tol) continue;
    spans.push_back(span);
    spans.back().start_s = from + shift;
    spans.back().length = span.start_s + span.length - from;
  }
  // The rests and stops of this path before the splice (not a stop of an event: the motion goes
  // on from it), longer's from it on.
  const auto event_stop_at = [&](double s) {
    return std::any_of(stops_.begin(), stops_.end(),
                       [&](const Stop& stop) { return is_stop_of_event(stop) && std::abs(stop.s - s) <= tol; });
  };
  std::vector<double> rests;
  std::vector<Stop> stops;
  for (double r : rest_s_)
    if (r < s_here - tol && !(r > 0.0 && event_stop_at(r))) rests.push_back(r);
  for (double r : longer.rest_s_)
    if (r >= s_here - shift - tol) rests.push_back(r + shift);
  for (const Stop& stop : stops_)
    if (stop.s < s_here - tol && !is_stop_of_event(stop)) stops.push_back(stop);
  for (const Stop& stop : longer.stops_)
    if (stop.s >= s_here - shift - tol) stops.push_back(Stop{stop.s + shift, stop.reason});
  SampledPath spliced(std::move(joined.sections), std::move(joined.parts), std::move(joined.lengths));
  append_continuation(law, x, spans, rests, spliced.length(), limits, override_);
  return Trajectory(std::move(spliced), std::move(law), std::move(spans), std::move(rests), std::move(stops),
                    std::move(sources), limits_, override_);
}

}  // namespace dispkin
