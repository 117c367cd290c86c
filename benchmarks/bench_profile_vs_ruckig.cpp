// Google Benchmark: Profile::from_state against Ruckig's calculate (1 DoF, position interface),
// on the same seeded states. Built only when DISPKIN_RUCKIG_DIR names a Ruckig source tree
// (benchmarks/CMakeLists.txt); Ruckig is measured, nothing of it is part of dispkin.
// Results: benchmarks/history/2026-12-04-profiles-laws-from-a-state-against-ruckig.md.
//
// Cases: 1024 states inside the limits (v_start, a_start, v_end random within them, 1 in 6 at
// a_start = ±a_max, v_end = v_max or v_end = 0; distance raised tenfold until a law exists), and
// 1024 states beyond them (v_start up to 3 v_max, or |a_start| up to 3 a_max). Limits log-uniform
// as the tests: v_max 1e-2…10, a_max 1e-2…100, j_max 1e-1…1e4. Ruckig gets min_velocity = 0, the
// same problem. Before timing, each benchmark's counter "max_rel_diff" reports the largest
// relative difference of the two durations over the cases where both plan (inside the limits).
//
// Run with interleaved repetitions, so that both contenders see the same machine load:
//   build/cmake/benchmarks/dispkin_bench_vs_ruckig --benchmark_repetitions=11 \
//     --benchmark_enable_random_interleaving=true --benchmark_report_aggregates_only=true
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <random>
#include <stdexcept>
#include <vector>

#include <benchmark/benchmark.h>
#include <ruckig/ruckig.hpp>

#include "dispkin/profile.hpp"

namespace {

using dispkin::Profile;

constexpr std::size_t kCases = 1024;  // a power of two: the index wraps with a mask

struct Case {
  double distance, v_max, a_max, j_max, v_start, a_start, v_end;
};

std::vector<Case> make_cases(bool beyond, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  auto uniform = [&](double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); };
  auto log_uniform = [&](double lo, double hi) { return std::pow(10.0, uniform(std::log10(lo), std::log10(hi))); };
  std::vector<Case> cases;
  while (cases.size() < kCases) {
    Case c{log_uniform(1e-6, 10.0), log_uniform(1e-2, 10.0), log_uniform(1e-2, 100.0), log_uniform(1e-1, 1e4), 0, 0, 0};
    c.v_start = c.v_max * uniform(0, 1);
    c.a_start = c.a_max * uniform(-1, 1);
    c.v_end = c.v_max * uniform(0, 1);
    switch (rng() % 6) {
      case 0:
        c.a_start = rng() % 2 ? c.a_max : -c.a_max;
        break;
      case 1:
        c.v_end = c.v_max;
        break;
      case 2:
        c.v_end = 0.0;
        break;
      default:
        break;
    }
    if (beyond) {
      if (rng() % 2)
        c.v_start = c.v_max * uniform(1, 3);
      else
        c.a_start = c.a_max * uniform(1, 3) * (rng() % 2 ? 1.0 : -1.0);
    }
    const double natural = c.v_start + c.a_start * std::abs(c.a_start) / (2.0 * c.j_max);
    if (c.a_start < 0.0 && natural < 0.0) continue;
    if (!beyond && (natural > c.v_max || std::abs(c.a_start) > c.a_max)) continue;
    for (int tries = 0; tries < 12; ++tries, c.distance *= 10.0) {
      try {
        Profile::from_state(c.distance, c.v_max, c.a_max, c.j_max, c.v_start, c.a_start, c.v_end);
        cases.push_back(c);
        break;
      } catch (const std::invalid_argument&) {
      }
    }
  }
  return cases;
}

const std::vector<Case>& inside_cases() {
  static const std::vector<Case> cases = make_cases(false, 20261204);
  return cases;
}
const std::vector<Case>& beyond_cases() {
  static const std::vector<Case> cases = make_cases(true, 20261205);
  return cases;
}

struct RuckigOne {
  ruckig::Ruckig<1> otg;
  ruckig::InputParameter<1> input;
  ruckig::Trajectory<1> trajectory;
  RuckigOne() {
    input.current_position = {0.0};
    input.target_acceleration = {0.0};
    input.min_velocity = {0.0};
  }
  // The duration, NaN where Ruckig reports no law.
  double plan(const Case& c) {
    input.current_velocity = {c.v_start};
    input.current_acceleration = {c.a_start};
    input.target_position = {c.distance};
    input.target_velocity = {c.v_end};
    input.max_velocity = {c.v_max};
    input.max_acceleration = {c.a_max};
    input.max_jerk = {c.j_max};
    const ruckig::Result r = otg.calculate(input, trajectory);
    return r == ruckig::Result::Working ? trajectory.get_duration() : std::numeric_limits<double>::quiet_NaN();
  }
};

double max_relative_difference(const std::vector<Case>& cases) {
  RuckigOne r;
  double worst = 0.0;
  for (const Case& c : cases) {
    const double theirs = r.plan(c);
    if (!std::isfinite(theirs)) continue;
    const double ours =
        Profile::from_state(c.distance, c.v_max, c.a_max, c.j_max, c.v_start, c.a_start, c.v_end).duration();
    worst = std::max(worst, std::abs(ours - theirs) / theirs);
  }
  return worst;
}

void from_state_inside(benchmark::State& state) {
  const auto& cases = inside_cases();
  std::size_t i = 0;
  for (auto _ : state) {
    const Case& c = cases[i++ & (kCases - 1)];
    Profile p = Profile::from_state(c.distance, c.v_max, c.a_max, c.j_max, c.v_start, c.a_start, c.v_end);
    benchmark::DoNotOptimize(p);
  }
  state.counters["max_rel_diff"] = max_relative_difference(cases);
}
BENCHMARK(from_state_inside);

void ruckig_calculate_inside(benchmark::State& state) {
  const auto& cases = inside_cases();
  RuckigOne r;
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(r.plan(cases[i++ & (kCases - 1)]));
  }
}
BENCHMARK(ruckig_calculate_inside);

void from_state_beyond(benchmark::State& state) {
  const auto& cases = beyond_cases();
  std::size_t i = 0;
  for (auto _ : state) {
    const Case& c = cases[i++ & (kCases - 1)];
    Profile p = Profile::from_state(c.distance, c.v_max, c.a_max, c.j_max, c.v_start, c.a_start, c.v_end);
    benchmark::DoNotOptimize(p);
  }
}
BENCHMARK(from_state_beyond);

void ruckig_calculate_beyond(benchmark::State& state) {
  const auto& cases = beyond_cases();
  RuckigOne r;
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(r.plan(cases[i++ & (kCases - 1)]));
  }
}
BENCHMARK(ruckig_calculate_beyond);

}  // namespace
