// Planning and sampling trajectories (targets: a 1000-section path planned in ≤ 100 µs,
// sampling ≤ 50 ns per sample).
#include <cmath>
#include <string>
#include <vector>

#include <benchmark/benchmark.h>

#include "dispkin/planning/planner.hpp"
#include "dispkin/shapes.hpp"

namespace {

using dispkin::Posed;
using V = Eigen::Vector3d;

dispkin::MetricSetd icosahedron_tool() {
  dispkin::MetricSetd set;
  set.add_relative(dispkin::shapes::icosahedron(0.1));
  return set;
}

const Posed kStart;
const Posed kEnd(Eigen::Quaterniond(Eigen::AngleAxisd(0.8, V(0.3, 0.2, 1.0).normalized())), V(0.3, 0.1, 0.05));
const Posed kVia(Eigen::Quaterniond::Identity(), V(0.15, 0.2, 0.0));

void plan_lin_icosahedron(benchmark::State& state) {
  const auto set = icosahedron_tool();
  const auto path = dispkin::Path::lin(kStart, kEnd);
  for (auto _ : state) benchmark::DoNotOptimize(dispkin::plan(path, set, dispkin::Limits{0.1, 0.5, 5.0}));
  state.counters["pieces"] =
      static_cast<double>(dispkin::plan(path, set, dispkin::Limits{0.1, 0.5, 5.0}).path().section_count());
}
BENCHMARK(plan_lin_icosahedron);

// A CIRC cut into about 1000 sections (tolerance chosen for it), icosahedron set.
void plan_circ_1000_sections(benchmark::State& state) {
  const auto set = icosahedron_tool();
  const auto path = dispkin::Path::circ(kStart, kVia, kEnd, V::Zero(), 2.2e-3);
  for (auto _ : state) benchmark::DoNotOptimize(dispkin::plan(path, set, dispkin::Limits{0.1, 0.5, 5.0}));
  state.counters["sections"] = static_cast<double>(path.size());
}
BENCHMARK(plan_circ_1000_sections)->Unit(benchmark::kMicrosecond);

// A CAM-style polyline of 10³ points on three quarters of a circle (R = 0.2 m), planned in
// continuous-path mode with a corner tolerance of 1e-4 R: blending every corner and planning
// the one run.
void plan_polyline_1000_blended(benchmark::State& state) {
  const auto set = icosahedron_tool();
  std::vector<Posed> points;
  for (int k = 0; k <= 1000; ++k) {
    const double angle = 1.5 * dispkin::pi * k / 1000;
    points.push_back(Posed(Eigen::Quaterniond::Identity(), V(0.2 * std::cos(angle), 0.2 * std::sin(angle), 0.0)));
  }
  auto path = dispkin::Path::lin(points[0], points[1]);
  for (std::size_t k = 2; k < points.size(); ++k) path.then(dispkin::Path::lin(points[k - 1], points[k]));
  dispkin::PlanOptions options;
  options.corner_tolerance = 2e-5;
  for (auto _ : state) {
    benchmark::DoNotOptimize(
        dispkin::plan(path, set, dispkin::Limits{0.1, 0.5, 5.0}, dispkin::ProfileKind::scurve, options));
  }
}
BENCHMARK(plan_polyline_1000_blended)->Unit(benchmark::kMillisecond);

// A SPLINE through five key poses, cut into about 1000 curved sections (tolerance chosen for
// it), icosahedron set.
std::vector<Posed> spline_keys() {
  const auto turn = [](double a) { return Eigen::Quaterniond(Eigen::AngleAxisd(a, V(0.3, 0.2, 1.0).normalized())); };
  return {kStart, Posed(turn(0.2), V(0.1, 0.1, 0.0)), Posed(turn(0.4), V(0.2, 0.0, 0.05)),
          Posed(turn(0.6), V(0.3, 0.1, 0.05)), Posed(turn(0.8), V(0.4, 0.0, 0.0))};
}

void plan_spline_1000_sections(benchmark::State& state) {
  const auto set = icosahedron_tool();
  const auto path = dispkin::Path::spline(spline_keys(), V::Zero(), 8e-3);
  for (auto _ : state) benchmark::DoNotOptimize(dispkin::plan(path, set, dispkin::Limits{0.1, 0.5, 5.0}));
  state.counters["sections"] = static_cast<double>(path.size());
}
BENCHMARK(plan_spline_1000_sections)->Unit(benchmark::kMicrosecond);

void build_spline_1000_sections(benchmark::State& state) {
  const auto keys = spline_keys();
  for (auto _ : state) benchmark::DoNotOptimize(dispkin::Path::spline(keys, V::Zero(), 8e-3));
}
BENCHMARK(build_spline_1000_sections)->Unit(benchmark::kMicrosecond);

// Sampling: path 0 = LIN, 1 = CIRC (~1000 sections), 2 = SPLINE (~1000 sections); times
// 0 = random (sample(t)), 1 = consecutive (sample(t)), 2 = consecutive with a cursor (a
// control loop: sample(t, cursor)). 4096 times over the whole trajectory.
void sample_trajectory(benchmark::State& state) {
  const auto set = icosahedron_tool();
  const int kind = static_cast<int>(state.range(0));
  const int mode = static_cast<int>(state.range(1));
  const auto path = kind == 0   ? dispkin::Path::lin(kStart, kEnd)
                    : kind == 1 ? dispkin::Path::circ(kStart, kVia, kEnd, V::Zero(), 2.2e-3)
                                : dispkin::Path::spline(spline_keys(), V::Zero(), 8e-3);
  const auto traj = dispkin::plan(path, set, dispkin::Limits{0.1, 0.5, 5.0});
  std::vector<double> times(4096);
  for (std::size_t i = 0; i < times.size(); ++i) {
    const std::size_t slot = mode == 0 ? (i * 2654435761u) % 4096 : i;
    times[i] = traj.duration() * static_cast<double>(slot) / 4096.0;
  }
  std::size_t i = 0;
  if (mode == 2) {
    dispkin::Trajectory::Cursor cursor;
    for (auto _ : state) {
      benchmark::DoNotOptimize(traj.sample(times[i], cursor));
      i = (i + 1) & 4095;
    }
  } else {
    for (auto _ : state) {
      benchmark::DoNotOptimize(traj.sample(times[i]));
      i = (i + 1) & 4095;
    }
  }
  const char* paths[] = {"LIN", "CIRC, ~1000 sections", "SPLINE, ~1000 sections"};
  const char* modes[] = {"random times", "consecutive times", "consecutive times, cursor"};
  state.SetLabel(std::string(paths[kind]) + ", " + modes[mode]);
}
BENCHMARK(sample_trajectory)->ArgsProduct({{0, 1, 2}, {0, 1, 2}});

}  // namespace
