// Google Benchmark programs for the time-optimal profiles (dispkin/profile.hpp): planning a
// trapezoid or an S-curve, rest to rest and with boundary velocities, and evaluating state_at.
// Results: benchmarks/history/2026-11-22-profiles.md.
//
// Every benchmark cycles through kCases seeded random cases (distances 1e-6 … 10, limits over
// decades, as the tests), so that neither the branch predictor nor the compiler sees one case.
#include <cmath>
#include <cstddef>
#include <random>
#include <vector>

#include <benchmark/benchmark.h>

#include "dispkin/profile.hpp"

namespace {

using dispkin::Profile;

constexpr std::size_t kCases = 1024;  // a power of two: the index wraps with a mask

struct Case {
  double distance, v_max, a_max, j_max, v_start, v_end;
};

double log_uniform(std::mt19937_64& rng, double lo, double hi) {
  return std::pow(10.0, std::uniform_real_distribution<double>(std::log10(lo), std::log10(hi))(rng));
}

// Rest-to-rest cases, or cases with boundary velocities in [0, v_max] that the S-curve accepts
// (S is raised by the distance of the direct change between them).
std::vector<Case> make_cases(bool boundary_velocities) {
  std::mt19937_64 rng(20261122);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<Case> cases;
  while (cases.size() < kCases) {
    Case c{};
    c.distance = log_uniform(rng, 1e-6, 10.0);
    c.v_max = log_uniform(rng, 1e-2, 10.0);
    c.a_max = log_uniform(rng, 1e-2, 100.0);
    c.j_max = log_uniform(rng, 1e-1, 1e4);
    if (boundary_velocities) {
      c.v_start = c.v_max * unit(rng);
      c.v_end = c.v_max * unit(rng);
      const double dv = std::abs(c.v_end - c.v_start);
      const double change =
          dv >= c.a_max * c.a_max / c.j_max ? dv / c.a_max + c.a_max / c.j_max : 2 * std::sqrt(dv / c.j_max);
      c.distance += 0.5 * (c.v_start + c.v_end) * change;
    }
    cases.push_back(c);
  }
  return cases;
}

const std::vector<Case>& rest_cases() {
  static const std::vector<Case> cases = make_cases(false);
  return cases;
}

const std::vector<Case>& boundary_cases() {
  static const std::vector<Case> cases = make_cases(true);
  return cases;
}

void trapezoid_rest_to_rest(benchmark::State& state) {
  const auto& cases = rest_cases();
  std::size_t i = 0;
  for (auto _ : state) {
    const Case& c = cases[i++ & (kCases - 1)];
    Profile p = Profile::trapezoid(c.distance, c.v_max, c.a_max);
    benchmark::DoNotOptimize(p);
  }
}
BENCHMARK(trapezoid_rest_to_rest);

void scurve_rest_to_rest(benchmark::State& state) {
  const auto& cases = rest_cases();
  std::size_t i = 0;
  for (auto _ : state) {
    const Case& c = cases[i++ & (kCases - 1)];
    Profile p = Profile::scurve(c.distance, c.v_max, c.a_max, c.j_max);
    benchmark::DoNotOptimize(p);
  }
}
BENCHMARK(scurve_rest_to_rest);

void trapezoid_boundary_velocities(benchmark::State& state) {
  const auto& cases = boundary_cases();
  std::size_t i = 0;
  for (auto _ : state) {
    const Case& c = cases[i++ & (kCases - 1)];
    Profile p = Profile::trapezoid(c.distance, c.v_max, c.a_max, c.v_start, c.v_end);
    benchmark::DoNotOptimize(p);
  }
}
BENCHMARK(trapezoid_boundary_velocities);

// The peak is a Newton root here (no closed form).
void scurve_boundary_velocities(benchmark::State& state) {
  const auto& cases = boundary_cases();
  std::size_t i = 0;
  for (auto _ : state) {
    const Case& c = cases[i++ & (kCases - 1)];
    Profile p = Profile::scurve(c.distance, c.v_max, c.a_max, c.j_max, c.v_start, c.v_end);
    benchmark::DoNotOptimize(p);
  }
}
BENCHMARK(scurve_boundary_velocities);

// state_at at scattered times over 1024 S-curves: one sample per iteration.
void scurve_state_at(benchmark::State& state) {
  const auto& cases = rest_cases();
  std::vector<Profile> profiles;
  std::vector<double> times;
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (const Case& c : cases) {
    profiles.push_back(Profile::scurve(c.distance, c.v_max, c.a_max, c.j_max));
    times.push_back(profiles.back().duration() * unit(rng));
  }
  std::size_t i = 0;
  for (auto _ : state) {
    const std::size_t k = i++ & (kCases - 1);
    benchmark::DoNotOptimize(profiles[k].state_at(times[k]));
  }
}
BENCHMARK(scurve_state_at);

// sample() over a controller's stream of times: 1000 consecutive samples of one profile.
void scurve_sample_stream(benchmark::State& state) {
  const Profile p = Profile::scurve(1.0, 1.0, 2.0, 10.0);
  std::vector<double> times(1000);
  for (std::size_t k = 0; k < times.size(); ++k) times[k] = p.duration() * static_cast<double>(k) / 999.0;
  std::vector<dispkin::ProfileState> out(times.size());
  for (auto _ : state) {
    p.sample(times.data(), out.data(), times.size());
    benchmark::DoNotOptimize(out.data());
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(state.iterations() * static_cast<int64_t>(times.size()));
}
BENCHMARK(scurve_sample_stream);

}  // namespace
