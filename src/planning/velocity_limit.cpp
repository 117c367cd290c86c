// Time-optimal laws under a piecewise-constant velocity limit (velocity_limit.hpp).
#include "dispkin/planning/velocity_limit.hpp"

#include <algorithm>
#include <array>
#include <utility>
#include <cmath>
#include <string>

#include "carried_acceleration.hpp"
#include "staircase_input.hpp"
#include "reachable_velocity.hpp"
#include "dispkin/error.hpp"

namespace dispkin {

double velocity_change_distance(double u, double w, double a, std::optional<double> j) noexcept {
  const double delta = std::abs(w - u);
  if (!j) return std::abs(w * w - u * u) / (2.0 * a);
  const double time = delta >= a * a / *j ? delta / a + a / *j : 2.0 * std::sqrt(delta / *j);
  return 0.5 * (u + w) * time;
}

namespace detail {

void require_staircase(const std::vector<LimitedSegment>& segments, double a_max, std::optional<double> j_max,
                       double v_start, double v_end) {
  require(!segments.empty(), "segments", 0L, "is empty: nothing to move along");
  require_positive(a_max, "a_max");
  if (j_max) require_positive(*j_max, "j_max");
  for (std::size_t i = 0; i < segments.size(); ++i) {
    // The message is only formatted when a value is refused.
    if (!(segments[i].length > 0.0 && std::isfinite(segments[i].length)))
      require_positive(segments[i].length, "segments[" + std::to_string(i) + "].length");
    if (!(segments[i].limit > 0.0 && std::isfinite(segments[i].limit)))
      require_positive(segments[i].limit, "segments[" + std::to_string(i) + "].limit");
    if (!(segments[i].acceleration >= 0.0 && std::isfinite(segments[i].acceleration)))
      require(false, "segments[" + std::to_string(i) + "].acceleration", segments[i].acceleration,
              "must be finite and not negative");
  }
  require(std::isfinite(v_start) && v_start >= 0.0 && v_start <= segments.front().limit, "v_start", v_start,
          "must be in [0, limit of the first segment]");
  require(std::isfinite(v_end) && v_end >= 0.0 && v_end <= segments.back().limit, "v_end", v_end,
          "must be in [0, limit of the last segment]");
}

}  // namespace detail

std::vector<Profile> velocity_limited_chain(const std::vector<LimitedSegment>& segments, double a_max,
                                            std::optional<double> j_max, double v_start, double v_end) {
  detail::require_staircase(segments, a_max, j_max, v_start, v_end);
  auto accel = [&](std::size_t i) { return detail::segment_acceleration(segments[i], a_max); };

  // Boundary velocities: u[0] = v_start, u[n] = v_end, inner ones capped by both limits.
  const std::size_t n = segments.size();
  std::vector<double> u(n + 1);
  u[0] = v_start;
  u[n] = v_end;
  for (std::size_t i = 1; i < n; ++i) u[i] = std::min(segments[i - 1].limit, segments[i].limit);
  for (std::size_t i = n; i-- > 0;)
    u[i] = std::min(u[i], detail::reachable_velocity(u[i + 1], u[i], segments[i].length, accel(i), j_max));
  for (std::size_t i = 0; i < n; ++i)
    u[i + 1] = std::min(u[i + 1], detail::reachable_velocity(u[i], u[i + 1], segments[i].length, accel(i), j_max));
  if (std::abs(u[0] - v_start) > 1e-12 * std::max(1.0, v_start) ||
      std::abs(u[n] - v_end) > 1e-12 * std::max(1.0, v_end)) {
    throw std::invalid_argument(
        describe("v_end", v_end,
                 "cannot be reached from v_start = " + std::to_string(v_start) + " within the segments' length"));
  }

  std::vector<Profile> laws;
  laws.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    const LimitedSegment& g = segments[i];
    laws.push_back(j_max ? Profile::scurve(g.length, g.limit, accel(i), *j_max, u[i], u[i + 1])
                         : Profile::trapezoid(g.length, g.limit, accel(i), u[i], u[i + 1]));
  }
  return laws;
}

namespace {

double total_duration(const std::vector<Profile>& laws) {
  double sum = 0.0;
  for (const Profile& p : laws) sum += p.duration();
  return sum;
}

// The cruise of a chain law at its segment's limit, if it has one (phase index), where the
// staircase is cut into runs (doc/profiles.md §8.3, eq. 33).
std::optional<int> cruise_at_limit(const Profile& law, double limit) {
  for (int i = 0; i < law.phase_count(); ++i) {
    const ProfilePhase& p = law.phase(i);
    if (p.jerk == 0.0 && p.start.a == 0.0 && p.duration > 0.0 && p.start.v >= limit * (1.0 - 1e-12)) return i;
  }
  return std::nullopt;
}

// A chain law cut in the middle of its cruise (phase `cruise`): the part before and the part after.
std::pair<Profile, Profile> cut_in_cruise(const Profile& law, int cruise) {
  std::array<double, Profile::max_phases> durations{}, jerks{};
  const ProfilePhase& c = law.phase(cruise);
  const double half = 0.5 * c.duration, s_cut = c.start.s + c.start.v * half;
  for (int i = 0; i <= cruise; ++i) {
    durations[static_cast<std::size_t>(i)] = i == cruise ? half : law.phase(i).duration;
    jerks[static_cast<std::size_t>(i)] = law.phase(i).jerk;
  }
  const ProfileState start = law.state_at(0.0), end = law.state_at(law.duration());
  Profile before =
      Profile::from_phases(durations.data(), jerks.data(), cruise + 1, start.v, 0.0, s_cut, c.start.v, 0.0);
  const int rest = law.phase_count() - cruise;
  for (int i = 0; i < rest; ++i) {
    durations[static_cast<std::size_t>(i)] = i == 0 ? c.duration - half : law.phase(cruise + i).duration;
    jerks[static_cast<std::size_t>(i)] = law.phase(cruise + i).jerk;
  }
  Profile after =
      Profile::from_phases(durations.data(), jerks.data(), rest, c.start.v, 0.0, law.distance() - s_cut, end.v, 0.0);
  return {std::move(before), std::move(after)};
}

// One run of the staircase: its segments (the first and last possibly parts of a segment), the
// velocities at its ends, and the chain's laws over it.
struct Run {
  std::vector<LimitedSegment> segments;
  std::vector<double> accelerations;
  double v_start = 0.0, v_end = 0.0;
  double a_max = 0.0;
  std::vector<Profile> chain;
};

// The fastest of the chain and the laws that carry acceleration over the run, forwards and
// backwards, with and without settling in the troughs (doc/profiles.md §8.3, eq. 33).
bool append_fastest(Run& run, double j_max, std::vector<Profile>& out) {
  std::vector<Profile>* best = &run.chain;
  double duration = total_duration(run.chain);
  std::vector<Profile> candidates[4];
  // A run of one segment is crossed by its chain law, time-optimal for one segment.
  const bool open_end = run.v_end > 0.0, open_start = run.v_start > 0.0;
  const bool ends_fit = (!open_end || run.v_end == run.segments.back().limit) &&
                        (!open_start || run.v_start == run.segments.front().limit);
  // No jerk-limited law is faster than the trapezoid law over the run (§5): where the chain is
  // within 0.1 % of it, at most that much is left to gain: not worth the search.
  const bool worth = run.segments.size() > 1 && ends_fit &&
                     duration > 1.001 * total_duration(velocity_limited_chain(run.segments, run.a_max, std::nullopt,
                                                                              run.v_start, run.v_end));
  if (worth) {
    const std::vector<LimitedSegment> reversed(run.segments.rbegin(), run.segments.rend());
    const std::vector<double> reversed_accelerations(run.accelerations.rbegin(), run.accelerations.rend());
    int i = 0;
    for (const bool settle : {false, true}) {
      if (auto forward =
              detail::carried_acceleration_law(run.segments, run.accelerations, j_max, run.v_start, run.v_end, settle))
        candidates[i] = std::move(*forward);
      ++i;
      // Built from the end and run backwards, it enters the limits ahead as the forward law
      // leaves them behind.
      if (auto backward =
              detail::carried_acceleration_law(reversed, reversed_accelerations, j_max, run.v_end, run.v_start, settle))
        candidates[i] = detail::reversed_in_time(*backward);
      ++i;
    }
    for (std::vector<Profile>& candidate : candidates) {
      if (candidate.empty()) continue;
      const double d = total_duration(candidate);
      if (d < duration) {
        duration = d;
        best = &candidate;
      }
    }
  }
  for (Profile& law : *best) out.push_back(std::move(law));
  return best != &run.chain;
}

}  // namespace

std::vector<Profile> velocity_limited_law(const std::vector<LimitedSegment>& segments, double a_max,
                                          std::optional<double> j_max, double v_start, double v_end) {
  std::vector<Profile> chain = velocity_limited_chain(segments, a_max, j_max, v_start, v_end);
  if (!j_max) return chain;
  // The jerk-limited chain returns to zero acceleration at every boundary. Where a chain law
  // cruises at its segment's limit no law is faster, so the staircase is cut there into runs
  // (doc/profiles.md §8.3), and each run takes the fastest of its chain and the laws that carry
  // acceleration across its boundaries (§8).
  std::vector<Profile> laws;
  laws.reserve(chain.size());
  Run run;
  run.v_start = v_start;
  run.a_max = a_max;
  bool faster = false;
  for (std::size_t k = 0; k < segments.size(); ++k) {
    const double a_k = detail::segment_acceleration(segments[k], a_max);
    const std::optional<int> cruise =
        k + 1 < segments.size() ? cruise_at_limit(chain[k], segments[k].limit) : std::nullopt;
    if (!cruise) {
      run.segments.push_back(segments[k]);
      run.accelerations.push_back(a_k);
      run.chain.push_back(chain[k]);
      continue;
    }
    auto [before, after] = cut_in_cruise(chain[k], *cruise);
    run.segments.push_back({before.distance(), segments[k].limit, segments[k].acceleration});
    run.accelerations.push_back(a_k);
    run.chain.push_back(std::move(before));
    run.v_end = segments[k].limit;
    faster = append_fastest(run, *j_max, laws) || faster;
    run = Run{};
    run.v_start = segments[k].limit;
    run.a_max = a_max;
    run.segments.push_back({after.distance(), segments[k].limit, segments[k].acceleration});
    run.accelerations.push_back(a_k);
    run.chain.push_back(std::move(after));
  }
  run.v_end = v_end;
  faster = append_fastest(run, *j_max, laws) || faster;
  // Where no run gains, the chain as it was (its laws uncut).
  return faster ? laws : chain;
}

}  // namespace dispkin
