// Laws from explicit phases, and the consistency every law is checked against
// (dispkin/profile.hpp; doc/profiles.md §4).
#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>

#include "dispkin/error.hpp"
#include "dispkin/profile.hpp"
#include "message_number.hpp"
#include "profile_checks.hpp"

namespace dispkin {

using detail::number;            // message_number.hpp
using detail::require_distance;  // profile_checks.hpp

// --- explicit phases -------------------------------------------------------------------------

Profile Profile::from_parts(const Parts& parts) {
  require(parts.count >= 0 && parts.count <= max_phases, "count", static_cast<long>(parts.count),
          "must be within [0, 7]");
  const auto finite_state = [](const ProfileState& x, const std::string& name) {
    require(std::isfinite(x.s) && std::isfinite(x.v) && std::isfinite(x.a) && std::isfinite(x.j), name,
            Eigen::Vector4d(x.s, x.v, x.a, x.j), "every value of the state (s, v, a, j) must be finite");
  };
  const std::size_t n = static_cast<std::size_t>(parts.count);
  require(parts.times[0] == 0.0, "times[0]", parts.times[0], "must be 0");
  for (std::size_t i = 0; i < n; ++i) {
    const std::string name = "phases[" + std::to_string(i) + "]";
    require(std::isfinite(parts.times[i + 1]) && parts.times[i + 1] >= parts.times[i],
            "times[" + std::to_string(i + 1) + "]", parts.times[i + 1],
            "must be finite and not below the time before it");
    require(std::isfinite(parts.phases[i].duration) && parts.phases[i].duration >= 0.0, name + ".duration",
            parts.phases[i].duration, "must be finite and not negative");
    require_finite(parts.phases[i].jerk, name + ".jerk");
    finite_state(parts.phases[i].start, name + ".start");
    finite_state(parts.phases[i].end, name + ".end");
  }
  require(std::isfinite(parts.distance) && parts.distance >= 0.0, "distance", parts.distance,
          "must be finite and not negative");
  require(std::isfinite(parts.peak_velocity) && parts.peak_velocity >= 0.0, "peak_velocity", parts.peak_velocity,
          "must be finite and not negative");
  finite_state(parts.start, "start");
  finite_state(parts.end, "end");
  Profile law;
  law.kind_ = parts.kind;
  law.count_ = parts.count;
  law.phases_ = parts.phases;
  law.time_ = parts.times;
  law.distance_ = parts.distance;
  law.peak_velocity_ = parts.peak_velocity;
  law.start_ = parts.start;
  law.end_ = parts.end;
  law.require_consistent();
  return law;
}

namespace {

// The scales of a law, against which its consistency is measured: the largest speed,
// acceleration and jerk any phase end reaches (the speed widened by what the acceleration adds
// over the law), and its duration.
struct LawScales {
  double v = 0.0, a = 0.0, j = 0.0, duration = 0.0, distance = 0.0;
};

// How far two states of a law may differ and still be the same state: 1e-8 of the law's scales,
// the tolerance within which from_phases lets its forward and backward halves meet (the
// factories meet to rounding, a few ε), and 64 times the smallest double, the resolution of
// laws far outside the numeric range (S = 1e-315 m has 32 significant bits left).
struct StateTolerance {
  static constexpr double relative = 1e-8;
  double s, v, a;
  explicit StateTolerance(const LawScales& x) {
    const double resolution = 64.0 * std::numeric_limits<double>::denorm_min();
    s = relative * (x.distance + x.v * x.duration) + resolution;
    v = relative * x.v + resolution;
    a = relative * (x.a + x.j * x.duration) + 1e-12 * x.v / std::max(x.duration, std::numeric_limits<double>::min()) +
        resolution;
  }
};

std::string state_text(const ProfileState& x) {
  std::ostringstream out;
  out.precision(17);
  out << "(s = " << x.s << ", v = " << x.v << ", a = " << x.a << ")";
  return out.str();
}

}  // namespace

void Profile::require_consistent() const {
  const std::size_t n = static_cast<std::size_t>(count_);
  LawScales scale;
  scale.duration = duration();
  scale.distance = distance_;
  const auto widen = [&](const ProfileState& x) {
    scale.v = std::max(scale.v, std::abs(x.v));
    scale.a = std::max(scale.a, std::abs(x.a));
  };
  widen(start_);
  widen(end_);
  for (std::size_t i = 0; i < n; ++i) {
    widen(phases_[i].start);
    widen(phases_[i].end);
    scale.j = std::max(scale.j, std::abs(phases_[i].jerk));
  }
  scale.v += scale.a * scale.duration;
  const StateTolerance tol(scale);
  // Each pair is one state seen from two sides (the end of a phase and the start of the next, a
  // phase's end and its start carried over its duration by the Taylor polynomials state_at
  // uses): different numbers there would make s(t) jump. The trapezoid's acceleration jumps
  // between phases by design; within a phase it is constant.
  // Names are made on failure only: every law planned passes here.
  const auto same = [&](const ProfileState& x, const ProfileState& y, bool acceleration, auto name) {
    const bool close =
        std::abs(x.s - y.s) <= tol.s && std::abs(x.v - y.v) <= tol.v && (!acceleration || std::abs(x.a - y.a) <= tol.a);
    if (!close)
      throw std::invalid_argument(describe(name() + " (s, v, a)", Eigen::Vector3d(y.s, y.v, y.a),
                                           "must be " + state_text(x) + " (to 1e-8 of the law's scale)"));
  };
  const auto phase = [](std::size_t i, const char* field) {
    return [i, field] { return "phases[" + std::to_string(i) + "]" + field; };
  };
  const auto named = [](const char* name) { return [name] { return std::string(name); }; };
  // Accelerations are compared within phases only: the trapezoid's jump between phases by design,
  // and an S-curve's jerk phase shorter than its start time's resolution is left out, its
  // acceleration then jumping (a = 1e-300 m/s² at j = 1e300 m/s³).
  const bool continuous_acceleration = false;
  require(start_.s == 0.0, "start.s", start_.s, "must be 0 (a law starts at s = 0)");
  require_lazily(std::abs(end_.s - distance_) <= tol.s, named("end.s"), end_.s,
                 [&] { return "must be the distance " + number(distance_); });
  if (n == 0) same(start_, end_, false, named("end"));
  for (std::size_t i = 0; i < n; ++i) {
    const ProfilePhase& p = phases_[i];
    const double d = p.duration;
    require_lazily(
        std::abs((time_[i + 1] - time_[i]) - d) <= 4.0 * std::numeric_limits<double>::epsilon() * time_[i + 1],
        phase(i, ".duration"), d,
        [&] { return "must be the time between its start and end times (" + number(time_[i + 1] - time_[i]) + ")"; });
    const ProfileState& x = p.start;
    const ProfileState carried{x.s + d * (x.v + d * (0.5 * x.a + p.jerk * d / 6.0)), x.v + d * (x.a + 0.5 * p.jerk * d),
                               x.a + p.jerk * d, p.jerk};
    same(carried, p.end, true, phase(i, ".end"));
    same(i == 0 ? start_ : phases_[i - 1].end, x, continuous_acceleration, phase(i, ".start"));
    if (i + 1 == n) same(p.end, end_, continuous_acceleration, named("end"));
  }
  // 0 ≤ ṡ ≤ peak_velocity: at every phase end, and inside a phase at the vertex of its parabola.
  const auto within = [&](double v, auto name) {
    require_lazily(v >= -tol.v && v <= peak_velocity_ + tol.v, name, v, [&] {
      return "must be within [0, peak_velocity = " + number(peak_velocity_) + "] (to 1e-8 of the law's scale)";
    });
  };
  for (std::size_t i = 0; i < n; ++i) {
    const ProfilePhase& p = phases_[i];
    within(p.start.v, phase(i, ".start.v"));
    within(p.end.v, phase(i, ".end.v"));
    if (p.jerk != 0.0) {
      const double at = -p.start.a / p.jerk;
      if (at > 0.0 && at < p.duration) within(p.start.v + at * (p.start.a + 0.5 * p.jerk * at), phase(i, " vertex.v"));
    }
  }
  within(start_.v, named("start.v"));
  within(end_.v, named("end.v"));
}

namespace {

void require_phases(const double* durations, const double* jerks, int count, double v_start, double a_start,
                    double distance, double v_end, double a_end) {
  require(count >= 1 && count <= Profile::max_phases, "count", static_cast<long>(count), "must be within [1, 7]");
  for (int i = 0; i < count; ++i) {
    require(std::isfinite(durations[i]) && durations[i] > 0.0, "durations[" + std::to_string(i) + "]", durations[i],
            "must be finite and > 0");
    require_finite(jerks[i], "jerks[" + std::to_string(i) + "]");
  }
  require_distance(distance);
  require(std::isfinite(v_start) && v_start >= 0.0, "v_start", v_start, "must be finite and not negative");
  require(std::isfinite(v_end) && v_end >= 0.0, "v_end", v_end, "must be finite and not negative");
  require_finite(a_start, "a_start");
  require_finite(a_end, "a_end");
}

// The velocity's extremes over the phases (inside a phase ṡ is a parabola; its vertex, where
// a = 0, may be its lowest or highest point), and the largest |s̈| and |s⃛|.
struct PhaseExtremes {
  double lowest, peak = 0.0, a = 0.0, j = 0.0, v = 0.0;
};

PhaseExtremes phase_extremes(const ProfilePhase* phases, int count, double v_start, double v_end) {
  PhaseExtremes e{std::min(v_start, v_end)};
  for (int i = 0; i < count; ++i) {
    const ProfilePhase& phase = phases[i];
    e.a = std::max({e.a, std::abs(phase.start.a), std::abs(phase.end.a)});
    e.j = std::max(e.j, std::abs(phase.jerk));
    e.v = std::max({e.v, phase.start.v, phase.end.v});
    e.peak = std::max({e.peak, phase.start.v, phase.end.v});
    e.lowest = std::min({e.lowest, phase.start.v, phase.end.v});
    if (phase.jerk != 0.0) {
      const double at = -phase.start.a / phase.jerk;
      if (at > 0.0 && at < phase.duration) {
        const double v = phase.start.v + at * (phase.start.a + 0.5 * phase.jerk * at);
        e.lowest = std::min(e.lowest, v);
        e.peak = std::max(e.peak, v);
      }
    }
  }
  return e;
}

}  // namespace

Profile Profile::from_phases(const double* durations, const double* jerks, int count, double v_start, double a_start,
                             double distance, double v_end, double a_end) {
  require_phases(durations, jerks, count, v_start, a_start, distance, v_end, a_end);
  Profile p;
  p.kind_ = ProfileKind::scurve;
  p.distance_ = distance;
  p.start_ = {0.0, v_start, a_start, 0.0};
  p.end_ = {distance, v_end, a_end, 0.0};
  for (int i = 0; i < count; ++i) {
    ProfilePhase& phase = p.phases_[static_cast<std::size_t>(i)];
    phase.duration = durations[i];
    phase.jerk = jerks[i];
    phase.start.j = phase.end.j = jerks[i];
    p.time_[static_cast<std::size_t>(i + 1)] = p.time_[static_cast<std::size_t>(i)] + durations[i];
  }
  p.count_ = count;
  const auto [x, y] = p.integrate_from_both_ends(v_start, a_start, v_end, a_end);
  // The law's scales: the largest speed and acceleration any phase reaches, and its duration.
  const double total = p.duration();
  const PhaseExtremes e = phase_extremes(p.phases_.data(), count, v_start, v_end);
  const double scale_a = std::max({std::abs(a_start), std::abs(a_end), e.a});
  const double scale_v = std::max({v_start, v_end, e.v}) + scale_a * total;
  const double tolerance = 1e-8;
  const bool meet = std::abs(x.s - y.s) <= tolerance * (distance + scale_v * total) &&
                    std::abs(x.v - y.v) <= tolerance * scale_v &&
                    std::abs(x.a - y.a) <= tolerance * (scale_a + e.j * total) +
                                               1e-12 * scale_v / std::max(total, std::numeric_limits<double>::min());
  if (!meet) {
    throw std::invalid_argument(
        describe("distance", distance,
                 "the phases do not lead from the start state (v = " + number(v_start) + ", a = " + number(a_start) +
                     ") to the end state (v = " + number(v_end) + ", a = " + number(a_end) +
                     "): integrated forward they reach s = " + number(x.s) + ", v = " + number(x.v) +
                     ", a = " + number(x.a) + " where integrated backward they give s = " + number(y.s) +
                     ", v = " + number(y.v) + ", a = " + number(y.a)));
  }
  if (e.lowest < -tolerance * scale_v) {
    throw std::invalid_argument(
        describe("v_start", v_start,
                 "the phases make the velocity negative (down to " + number(e.lowest) + "): s would move backwards"));
  }
  p.peak_velocity_ = e.peak;
  p.require_consistent();
  return p;
}

// Forward over the first half, backward over the second: they meet at phase `middle` (the
// states each half reaches there). A law of one phase is carried forward, so that it starts
// exactly at s = 0 (where it meets its end state, state_at's end is exactly the distance).
std::pair<ProfileState, ProfileState> Profile::integrate_from_both_ends(double v_start, double a_start, double v_end,
                                                                        double a_end) noexcept {
  const int middle = std::max(1, count_ / 2);
  ProfileState x{0.0, v_start, a_start, 0.0};
  for (int i = 0; i < middle; ++i) {
    ProfilePhase& phase = phases_[static_cast<std::size_t>(i)];
    const double d = phase.duration, j = phase.jerk;
    phase.start = {x.s, x.v, x.a, j};
    x.s += d * (x.v + d * (0.5 * x.a + j * d / 6.0));
    x.v += d * (x.a + 0.5 * j * d);
    x.a += j * d;
    phase.end = {x.s, x.v, x.a, j};
  }
  ProfileState y{distance_, v_end, a_end, 0.0};
  for (int i = count_ - 1; i >= middle; --i) {
    ProfilePhase& phase = phases_[static_cast<std::size_t>(i)];
    const double d = phase.duration, j = phase.jerk;
    phase.end = {y.s, y.v, y.a, j};
    y.s -= d * (y.v - d * (0.5 * y.a - j * d / 6.0));
    y.v -= d * (y.a - 0.5 * j * d);
    y.a -= j * d;
    phase.start = {y.s, y.v, y.a, j};
  }
  return {x, y};
}

}  // namespace dispkin
