// Workloads and timing helpers of the control-loop request benchmarks (control_events.cpp and,
// with Ruckig, control_events_vs_ruckig.cpp): the trajectories a stop or a speed override is
// requested on, the seeded request instants, and per-call and per-pass timing by the thread's
// CPU time. Results: benchmarks/history/2026-12-04-control-loop-requests-stop-speed-override-append.md.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <ctime>
#include <functional>
#include <optional>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "dispkin/planning/motion_stream.hpp"
#include "dispkin/planning/planner.hpp"
#include "dispkin/shapes.hpp"

namespace control_events {

using dispkin::Path;
using dispkin::Posed;
using dispkin::ProfileKind;
using dispkin::Trajectory;
using V = Eigen::Vector3d;

//! Keeps `value` alive for the optimiser (as Google Benchmark's DoNotOptimize).
template <class T>
inline void keep(T const& value) {
  asm volatile("" : : "g"(&value) : "memory");
}

//! CPU time of the calling thread (ns): time spent descheduled on a shared machine is not counted.
inline double thread_cpu_ns() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return 1e9 * static_cast<double>(ts.tv_sec) + static_cast<double>(ts.tv_nsec);
}

//! The value below which a fraction q of `v` lies (nearest rank of the sorted values).
inline double quantile(std::vector<double> v, double q) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  const auto rank = static_cast<std::size_t>(std::ceil(q * static_cast<double>(v.size())));
  return v[std::min(v.size() - 1, rank == 0 ? 0 : rank - 1)];
}
inline double median(const std::vector<double>& v) { return quantile(v, 0.5); }
inline double largest(const std::vector<double>& v) { return v.empty() ? 0.0 : *std::max_element(v.begin(), v.end()); }

//! What reading the thread CPU clock twice costs (median ns over many pairs): subtracted from
//! every per-call time.
inline double thread_clock_overhead() {
  std::vector<double> d(20001);
  for (double& x : d) {
    const double a = thread_cpu_ns();
    x = thread_cpu_ns() - a;
  }
  return median(d);
}

//! Thread CPU ns of one call of f(), less the clock's own cost.
template <class F>
inline double time_call(F&& f, double overhead) {
  const double a = thread_cpu_ns();
  f();
  return thread_cpu_ns() - a - overhead;
}

//! Per-call figures over many calls.
struct Spread {
  double median, p99, max;
};
inline Spread spread(const std::vector<double>& ns) { return {median(ns), quantile(ns, 0.99), largest(ns)}; }

//! Two contenders over the same calls in alternating rounds (A then B, then B then A, ...), each
//! pass timed as a whole by the thread CPU time: the median ns per call of each and the median
//! and range of the per-round ratios B / A (a ratio of two passes taken back to back is what a
//! shared machine leaves intact).
struct Rounds {
  double a_median, b_median, ratio_median, ratio_min, ratio_max;
};
inline Rounds alternate(const std::function<void()>& pass_a, const std::function<void()>& pass_b, std::size_t calls,
                        int rounds) {
  pass_a();  // warm-up
  pass_b();
  std::vector<double> a, b, r;
  const auto per_call = [&](const std::function<void()>& pass) {
    const double t0 = thread_cpu_ns();
    pass();
    return (thread_cpu_ns() - t0) / static_cast<double>(calls);
  };
  for (int k = 0; k < rounds; ++k) {
    double ta, tb;
    if (k % 2 == 0) {
      ta = per_call(pass_a);
      tb = per_call(pass_b);
    } else {
      tb = per_call(pass_b);
      ta = per_call(pass_a);
    }
    a.push_back(ta);
    b.push_back(tb);
    r.push_back(tb / ta);
  }
  return {median(a), median(b), median(r), *std::min_element(r.begin(), r.end()),
          *std::max_element(r.begin(), r.end())};
}

//! The metric set of the planner benchmarks and the stream tests: an icosahedron of 0.1 m
//! around the TCP, moving with the tool.
inline dispkin::MetricSetd tool_set() {
  dispkin::MetricSetd set;
  set.add_relative(dispkin::shapes::icosahedron(0.1));
  return set;
}

//! v 0.2 m/s, a 1 m/s², j 10 m/s³ (the S-curve only).
inline dispkin::Limits limits_for(ProfileKind kind) {
  dispkin::Limits limits{0.2, 1.0, std::nullopt};
  if (kind == ProfileKind::scurve) limits.jerk = 10.0;
  return limits;
}

//! A zig-zag of `count` LINs of 5–15 cm, turning the tool by up to ±0.2 rad about z each move,
//! from `start`.
inline std::vector<Path> zigzag(std::mt19937_64& rng, int count, Posed start = Posed()) {
  const auto uniform = [&](double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); };
  std::vector<Path> out;
  Posed p = start;
  for (int k = 0; k < count; ++k) {
    const Posed q(Eigen::Quaterniond(Eigen::AngleAxisd(uniform(-0.2, 0.2), V::UnitZ())) * p.quaternion(),
                  p.translation() + V(uniform(0.05, 0.15), uniform(-0.05, 0.05), uniform(-0.01, 0.01)));
    out.push_back(Path::lin(p, q));
    p = q;
  }
  return out;
}

//! The first `count` moves joined into one path.
inline Path joined_path(const std::vector<Path>& moves, std::size_t count) {
  Path path = moves[0];
  for (std::size_t k = 1; k < count; ++k) path.then(moves[k]);
  return path;
}

//! A trajectory a request is made on, with what a 1-DoF planner needs of it.
struct Workload {
  std::string name;
  ProfileKind kind;
  dispkin::Limits limits;
  Trajectory trajectory;
};

//! The corner tolerance of the blended chains (m).
constexpr double kCornerTolerance = 1e-3;

//! A single LIN (0.32 m turning the tool by 0.8 rad, as the planner benchmarks) and a chain of 50
//! zig-zag LINs blended within 1 mm, each under the S-curve and the trapezoid.
inline std::vector<Workload> workloads() {
  const dispkin::MetricSetd set = tool_set();
  const Posed lin_end(Eigen::Quaterniond(Eigen::AngleAxisd(0.8, V(0.3, 0.2, 1.0).normalized())), V(0.3, 0.1, 0.05));
  const Path lin = Path::lin(Posed(), lin_end);
  std::mt19937_64 rng(20261206);
  const Path chain = joined_path(zigzag(rng, 50), 50);
  dispkin::PlanOptions options;
  options.corner_tolerance = kCornerTolerance;
  std::vector<Workload> out;
  for (const ProfileKind kind : {ProfileKind::scurve, ProfileKind::trapezoid}) {
    const std::string law = kind == ProfileKind::scurve ? "S-curve" : "trapezoid";
    const dispkin::Limits limits = limits_for(kind);
    out.push_back({"LIN, " + law, kind, limits, dispkin::plan(lin, set, limits, kind)});
    out.push_back({"50-move chain, " + law, kind, limits, dispkin::plan(chain, set, limits, kind, options)});
  }
  return out;
}

//! A request: its instant (uniform over the motion) and an override factor (uniform in [0.1, 1]).
struct Request {
  double t, factor;
};

inline std::vector<Request> requests(const Trajectory& trajectory, std::size_t count, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> instant(0.0, trajectory.duration()), factor(0.1, 1.0);
  std::vector<Request> out(count);
  for (Request& r : out) {
    r.t = instant(rng);
    r.factor = factor(rng);
  }
  return out;
}

}  // namespace control_events
