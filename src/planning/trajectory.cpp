// Sampling a trajectory: the time law gives s, ṡ, s̈ at t, the sampled path the pose and the
// body twist per unit τ at s (trajectory.hpp).
#include "dispkin/planning/trajectory.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "dispkin/error.hpp"
#include "../message_number.hpp"
#include "law_under_curve.hpp"

namespace dispkin {

using detail::number;  // message_number.hpp

namespace {

std::string indexed(const char* name, std::size_t k) { return std::string(name) + "[" + std::to_string(k) + "]"; }

// The sections join, and each has a length that sampling can divide by. Parts of one section
// that follow one another join by being one motion; elsewhere the sampled poses are compared.
void require_sections(const SampledPath& path) {
  const std::vector<Section>& sections = path.whole_sections();
  const std::vector<double>& lengths = path.section_lengths();
  require(!sections.empty() && !lengths.empty(), "sections", 0L, "must hold at least one section");
  for (std::size_t i = 0; i < sections.size(); ++i) require_valid(sections[i], [i] { return indexed("sections", i); });
  Posed end, start;
  Twistd twist;
  const bool parts = !path.parts().empty();
  for (std::size_t k = 0; k < lengths.size(); ++k) {
    const double L = lengths[k];
    require_lazily(
        std::isfinite(L) && L > 0.0 && std::isfinite(1.0 / L), [k] { return indexed("section_lengths", k); }, L,
        [] { return "must be finite and > 0, with a finite inverse"; });
    if (k == 0) continue;
    const SectionSource before = path.part(k - 1), after = path.part(k);
    if (before.section == after.section && before.tau_end == after.tau_start) continue;
    path.section_state_at(k - 1, 1.0, end, twist);
    path.section_state_at(k, 0.0, start, twist);
    // Named by the section it starts, or by the part when it starts inside one.
    require_join(end, start, [&] {
      return (!parts                   ? indexed("sections", k)
              : after.tau_start == 0.0 ? indexed("sections", after.section)
                                       : indexed("section_parts", k)) +
             ".start";
    });
  }
  require(std::isfinite(path.length()), "length", path.length(), "must be finite (the sum of the section lengths)");
}

// The velocity-limit curve: spans in order along the path, limits in the numeric range.
void require_speed_limits(const std::vector<SpeedLimit>& limits, double length, double tol_s) {
  double last_end = 0.0;
  for (std::size_t k = 0; k < limits.size(); ++k) {
    const SpeedLimit& l = limits[k];
    const auto name = [k](const char* field) { return [k, field] { return indexed("speed_limits", k) + field; }; };
    require_lazily(std::isfinite(l.start_s) && l.start_s >= last_end - tol_s && l.start_s <= length + tol_s,
                   name(".start_s"), l.start_s, [] { return "must lie on the path, after the span before it"; });
    require_lazily(std::isfinite(l.length) && l.length >= 0.0 && l.start_s + l.length <= length + tol_s,
                   name(".length"), l.length, [] { return "must be finite, not negative, and end on the path"; });
    // Curvature lowers a limit below the system velocity (never to 0); above 1e12 m/s durations overflow.
    require_lazily(std::isfinite(l.limit) && l.limit > 0.0 && l.limit <= numeric_range::max_limit, name(".limit"),
                   l.limit, [] { return "must be in (0, 1e12] m/s"; });
    require_lazily(l.acceleration == 0.0 ||
                       (l.acceleration >= numeric_range::min_limit && l.acceleration <= numeric_range::max_limit),
                   name(".acceleration"), l.acceleration,
                   [] { return "must be 0 (none of its own) or in [1e-12, 1e12] m/s²"; });
    require_lazily(l.ceiling == 0.0 || (l.ceiling >= l.limit && l.ceiling <= numeric_range::max_limit),
                   name(".ceiling"), l.ceiling,
                   [&] { return "must be 0 (the limit) or in [limit, 1e12] m/s, the limit being " + number(l.limit); });
    last_end = l.start_s + l.length;
  }
}

// The largest limit of the spans that [s0, s1] crosses (+inf without a curve): a law over
// [s0, s1] may reach it somewhere, never more. The laws come in order along the path, and so do
// the spans: `first` is where the search for the next law starts (one walk over both, not a
// search over every span per law: a long job has 10⁵ of each).
double largest_limit(const std::vector<SpeedLimit>& limits, double s0, double s1, double tol_s, std::size_t& first) {
  if (limits.empty()) return std::numeric_limits<double>::infinity();
  while (first + 1 < limits.size() && limits[first].start_s + limits[first].length < s0 - tol_s) ++first;
  double out = 0.0;
  for (std::size_t k = first; k < limits.size() && limits[k].start_s <= s1 + tol_s; ++k)
    if (limits[k].start_s + limits[k].length >= s0 - tol_s) out = std::max(out, limits[k].top());
  return out;
}

// The highest ṡ of `law` over [0, t] (a law cut at t): at phase starts, at t, and where ṡ peaks
// inside a phase (s̈ = 0).
double peak_until(const Profile& law, double t) {
  double peak = std::max(law.state_at(0.0).v, law.state_at(t).v);
  for (int i = 0; i < law.phase_count() && law.phase_start_time(i) < t; ++i) {
    const ProfilePhase& p = law.phase(i);
    peak = std::max(peak, p.start.v);
    if (p.jerk != 0.0) {
      const double at = -p.start.a / p.jerk;  // time into the phase where s̈ = 0
      if (at > 0.0 && at < p.duration && law.phase_start_time(i) + at < t)
        peak = std::max(peak, p.start.v + 0.5 * p.start.a * at);
    }
  }
  return peak;
}

// The name of a checked field for require_lazily. (Messages are made on failure only: events
// check every trajectory they make.)
auto named(const char* name) {
  return [name] { return std::string(name); };
}

// Every law of the time law starts where the one before ends and keeps under the velocity-limit
// curve of the spans it crosses, and within the acceleration limit it was planned under.
void require_time_law(const Trajectory& t, double tol_s) {
  const TimeLaw& law = t.time_law();
  const std::vector<SpeedLimit>& speed_limits = t.speed_limits();
  const std::optional<TimeLawLimits>& limits = t.limits();
  const std::vector<TimeLaw::Piece>& pieces = law.pieces();
  require(!pieces.empty(), "time_law pieces", 0L, "must hold at least one law");
  require_lazily(
      law.run_count() >= 1 && law.run_count() <= pieces.size(), [] { return std::string("time_law runs"); },
      static_cast<unsigned long>(law.run_count()),
      [&] { return "must be at least 1 and at most the number of laws " + std::to_string(pieces.size()); });
  std::size_t span = 0;  // the first span the next law may cross
  for (std::size_t k = 0; k < pieces.size(); ++k) {
    const TimeLaw::Piece& p = pieces[k];
    const auto name = [k](const char* field) { return [k, field] { return indexed("time_law pieces", k) + field; }; };
    const double s_before = k == 0 ? 0.0 : pieces[k - 1].start_s + pieces[k - 1].distance();
    require_lazily(std::isfinite(p.start_s) && std::abs(p.start_s - s_before) <= tol_s, name(".start_s"), p.start_s,
                   [&] { return "must be where the law before ends, s = " + number(s_before); });
    // Speeds where laws meet are not compared: the optimal re-timing's laws meet with speeds
    // apart by up to a few 0.1 % (one law per grid interval), and end at rest to its solver's
    // precision (1.6e-8 m/s), not to rounding.
    require_lazily(std::isfinite(p.end_time), name(" end time"), p.end_time, [] { return "must be finite"; });
    // A law cut where another takes over runs for a part of its own duration.
    require_lazily(!p.cut || (p.end_time > p.start_time && p.end_time - p.start_time < p.profile.duration()),
                   name(" cut time"), p.end_time,
                   [&] { return "must lie inside the law's own run, after " + number(p.start_time) + " s"; });
    const double allowed = largest_limit(speed_limits, p.start_s, p.start_s + p.distance(), tol_s, span);
    // A cut law runs up to its cut only: what it would have done after it is not checked.
    const double peak = p.cut ? peak_until(p.profile, p.end_time - p.start_time) : p.profile.peak_velocity();
    require_lazily(peak <= allowed * (1.0 + 1e-8), name(" peak velocity"), peak,
                   [&] { return "must be at most the velocity limit over its span, " + number(allowed) + " m/s"; });
    // A law planned under TimeLawLimits keeps to them in every phase (a pickle cannot bring a
    // law that accelerates beyond them, which the profile's own checks scale their tolerance by).
    if (limits) {
      for (int i = 0; i < p.profile.phase_count(); ++i) {
        const ProfilePhase& phase = p.profile.phase(i);
        const double a = std::max(std::abs(phase.start.a), std::abs(phase.end.a));
        require_lazily(a <= limits->acceleration * (1.0 + 1e-6), name(" acceleration"), a, [&] {
          return "must be within the trajectory's acceleration limit " + number(limits->acceleration) +
                 " m/s² in every phase";
        });
      }
    }
    require_lazily(speed_limits.empty() ||
                       detail::keeps_under_tops(p.profile, p.cut ? p.end_time - p.start_time : p.profile.duration(),
                                                p.start_s, peak, speed_limits, span, tol_s),
                   name(" velocity"), peak,
                   [&] { return std::string("must keep under the velocity limit of every span it crosses"); });
  }
}

// The time law runs to the path's end, or stops before it at rest where a stop is recorded.
void require_law_end(const Trajectory& t, double length, double tol_s) {
  const TimeLaw& law = t.time_law();
  const std::vector<SpeedLimit>& speed_limits = t.speed_limits();
  const std::optional<TimeLawLimits>& limits = t.limits();
  const double end_s = t.end_position();
  const std::vector<Stop>& stops = t.stops();
  const std::vector<double>& rest_s = t.rest_positions();
  const std::vector<TimeLaw::Piece>& pieces = law.pieces();
  const TimeLaw::Piece& last = pieces.back();
  const double law_end = last.start_s + last.distance();
  // The law runs to the path's end, or stops before it at rest (stopped_at).
  require_lazily(std::isfinite(law_end) && law_end <= length + tol_s && law_end >= -tol_s, named("time_law distance"),
                 law_end, [&] {
                   return "must be the path length, the sum of the section lengths, " + number(length) +
                          " m (or less, stopped at rest)";
                 });
  if (end_s < length) {
    // A stop before the end is a rest of the trajectory, with its reason (stopped_at).
    const auto near = [&](double s) { return std::abs(s - law_end) <= tol_s; };
    require_lazily(std::any_of(stops.begin(), stops.end(), [&](const Stop& x) { return near(x.s); }) &&
                       std::any_of(rest_s.begin(), rest_s.end(), near),
                   named("time_law distance"), law_end, [&] {
                     return "must be the path length, the sum of the section lengths, " + number(length) +
                            " m, unless the motion stopped there: a rest position and a stop at that position";
                   });
    const ProfileState end =
        last.profile.state_at(last.cut ? last.end_time - last.start_time : last.profile.duration());
    // At rest to 1e-8 of the trajectory's scales: its highest limit and its acceleration.
    double scale_v = last.profile.peak_velocity();
    for (const SpeedLimit& l : speed_limits) scale_v = std::max(scale_v, l.top());
    const double scale_a = limits ? limits->acceleration : std::abs(end.a);
    require_lazily(std::abs(end.v) <= 1e-8 * scale_v && std::abs(end.a) <= 1e-8 * scale_a,
                   named("time_law end velocity"), end.v, [&] {
                     return "must be 0 (at rest) where the motion stops before the end of the path, at s = " +
                            number(law_end) + " m";
                   });
  }
}

// The limits and override of the events, the rest positions and stops on the path, the section
// sources within their sections.
void require_event_records(const Trajectory& t, double length, double tol_s) {
  const std::optional<TimeLawLimits>& limits = t.limits();
  const std::vector<Stop>& stops = t.stops();
  const std::vector<double>& rest_s = t.rest_positions();
  const double factor = t.override_factor();
  const std::vector<SectionSource>& sources = t.section_sources();
  const SampledPath& path = t.path();
  if (limits) {
    require(limits->acceleration >= numeric_range::min_limit && limits->acceleration <= numeric_range::max_limit,
            "limits.acceleration", limits->acceleration, "must be in [1e-12, 1e12] m/s²");
    if (limits->jerk)
      require(*limits->jerk >= numeric_range::min_limit && *limits->jerk <= numeric_range::max_limit, "limits.jerk",
              *limits->jerk, "must be in [1e-12, 1e12] m/s³");
  }
  require_lazily(
      factor >= Trajectory::min_override && factor <= Trajectory::max_override, named("override_factor"), factor,
      [] { return "must be in [" + number(Trajectory::min_override) + ", " + number(Trajectory::max_override) + "]"; });
  for (std::size_t k = 0; k < rest_s.size(); ++k) {
    const double s = rest_s[k];
    require_lazily(
        std::isfinite(s) && s >= -tol_s && s <= length + tol_s && (k == 0 || s >= rest_s[k - 1]),
        [k] { return indexed("rest_positions", k); }, s, [] { return "must lie on the path, in order"; });
  }
  for (std::size_t k = 0; k < stops.size(); ++k)
    require_lazily(
        std::isfinite(stops[k].s) && stops[k].s >= -tol_s && stops[k].s <= length + tol_s,
        [k] { return indexed("stops", k) + ".s"; }, stops[k].s, [] { return "must lie on the path"; });
  require_lazily(
      sources.empty() || sources.size() == path.section_count(), [] { return std::string("section_sources size"); },
      static_cast<unsigned long>(sources.size()),
      [&] { return "must be 0 or the section count " + std::to_string(path.section_count()); });
  for (std::size_t k = 0; k < sources.size(); ++k) {
    const SectionSource& source = sources[k];
    require_lazily(
        source.tau_start >= 0.0 && source.tau_start <= source.tau_end && source.tau_end <= 1.0,
        [k] { return indexed("section_sources", k); }, Eigen::Vector2d(source.tau_start, source.tau_end),
        [] { return "must be a part [tau_start, tau_end] of [0, 1]"; });
  }
}

}  // namespace

void Trajectory::require_consistent() const { check(true); }

Trajectory Trajectory::with_events(TimeLaw law, std::vector<double> rests, std::vector<Stop> stops,
                                   double factor) const {
  Trajectory out(*this);  // the copy is not checked again
  out.law_ = std::move(law);
  out.rest_s_ = std::move(rests);
  out.stops_ = std::move(stops);
  out.override_ = factor;
  out.end_s_ = out.law_end();
  out.check(false);
  return out;
}

void Trajectory::check(bool sections) const {
  if (sections) require_sections(path_);
  const double length = path_.length();
  // Positions along the path are sums of lengths: they agree to rounding, 1e-9 of the length.
  const double tol_s = 1e-9 * length;
  require_speed_limits(speed_limits_, length, tol_s);
  require_time_law(*this, tol_s);
  require_law_end(*this, length, tol_s);
  require_event_records(*this, length, tol_s);
}

double Trajectory::law_end() const noexcept {
  if (law_.size() == 0) return 0.0;
  const TimeLaw::Piece& last = law_.pieces().back();
  const double end = last.start_s + last.distance(), length = path_.length();
  return std::abs(end - length) <= 1e-9 * length ? length : end;
}

TrajectorySample Trajectory::sample(double t) const noexcept {
  Cursor search{law_.size(), path_.section_count()};  // no hint: binary search
  return sample(t, search);
}

TrajectorySample Trajectory::sample(double t, Cursor& cursor) const noexcept {
  TrajectorySample out;
  if (law_.size() == 0) return out;
  if (!(t > 0.0)) t = 0.0;
  const ProfileState law = law_.state_at(t, cursor.piece);
  // At and past the end the path's end exactly (the laws' distances add up to its length only
  // to rounding).
  out.s = t >= law_.duration() ? end_s_ : law.s;
  out.s_dot = law.v;
  out.s_ddot = law.a;
  const std::size_t k = cursor.section = path_.section_state(out.s, cursor.section, out.pose, out.body_twist);
  out.body_twist = out.body_twist * (out.s_dot * path_.inverse_length(k));  // per τ → per second
  return out;
}

void Trajectory::sample(const double* times, TrajectorySample* out, std::size_t count) const noexcept {
  Cursor cursor;
  for (std::size_t i = 0; i < count; ++i) out[i] = sample(times[i], cursor);
}

}  // namespace dispkin
