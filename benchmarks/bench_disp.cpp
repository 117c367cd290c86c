// Google Benchmark programs for the DISP core: chord distance, section length, sphere speed,
// pose arithmetic and the convex-hull reduction. Results and the command that produced them:
// benchmarks/RESULTS.md.
//
// Every benchmark cycles through kMoves precomputed, seeded random moves (a start pose, an end
// pose, a body twist) so that neither the branch predictor nor the compiler sees one case.
#include <cstddef>
#include <cstdint>
#include <map>
#include <random>
#include <utility>
#include <vector>

#include <benchmark/benchmark.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "dispkin/convex_hull.hpp"
#include "dispkin/disp.hpp"
#include "dispkin/metric_set.hpp"
#include "dispkin/pose.hpp"
#include "dispkin/shapes.hpp"

namespace {

using dispkin::Frame;
using dispkin::Interpolation;
using dispkin::MetricSetd;
using dispkin::Posed;
using dispkin::Twistd;
using Eigen::Vector3d;
using Vector6d = Eigen::Matrix<double, 6, 1>;

constexpr std::size_t kMoves = 1024;  // a power of two: the index wraps with a mask
constexpr int64_t kBytesPerPoint = sizeof(Vector3d);
static_assert(kBytesPerPoint == 24, "points are stored as three packed doubles");

// Tool frame: the TCP sits 0.1 m along the flange's z axis; it is the decoupled sections' pivot.
const Vector3d kPivot(0.0, 0.0, 0.1);

// A realistic section of a robot program, in metres and radians: the start pose anywhere in a
// 1 m workspace with any orientation; the end pose reached by a body twist of up to 0.2 m per
// axis and a rotation of up to 90° about a random axis.
struct Moves {
  std::vector<Posed> start;
  std::vector<Posed> end;
  std::vector<Twistd> twist;     // the body twist log(start⁻¹ end) of each move
  std::vector<Vector6d> xyzuvw;  // start.to_xyzuvw()
};

// Draws x, then y, then z (argument evaluation order is unspecified, so never f(d(), d(), d())).
template <typename Distribution>
Vector3d random_vector(Distribution& x, Distribution& y, Distribution& z, std::mt19937_64& rng) {
  Vector3d v;
  v.x() = x(rng);
  v.y() = y(rng);
  v.z() = z(rng);
  return v;
}

// Uniform on SO(3): a normalised 4-D Gaussian.
Eigen::Quaterniond random_rotation(std::mt19937_64& rng) {
  std::normal_distribution<double> gauss(0.0, 1.0);
  Eigen::Quaterniond q;
  q.w() = gauss(rng);
  q.vec() = random_vector(gauss, gauss, gauss, rng);
  q.normalize();
  return q;
}

Vector3d random_unit(std::mt19937_64& rng) {
  std::normal_distribution<double> gauss(0.0, 1.0);
  return random_vector(gauss, gauss, gauss, rng).normalized();
}

const Moves& moves() {
  static const Moves m = [] {
    std::mt19937_64 rng(20240601);
    std::uniform_real_distribution<double> workspace(-0.5, 0.5);
    std::uniform_real_distribution<double> step(-0.2, 0.2);
    std::uniform_real_distribution<double> angle(0.0, 1.5707963267948966);
    Moves out;
    for (std::size_t i = 0; i < kMoves; ++i) {
      const Eigen::Quaterniond orientation = random_rotation(rng);
      const Vector3d position = random_vector(workspace, workspace, workspace, rng);
      const Posed a = Posed::unchecked(orientation, position);
      const Vector3d linear = random_vector(step, step, step, rng);
      const double turn = angle(rng);
      const Twistd xi(linear, turn * random_unit(rng));
      out.start.push_back(a);
      out.end.push_back(a * Posed::exp(xi));
      out.twist.push_back(xi);
      out.xyzuvw.push_back(a.to_xyzuvw());
    }
    return out;
  }();
  return m;
}

// The 12-vertex icosahedron circumscribing a 0.1 m ball around the TCP, as tool points.
const MetricSetd& icosahedron_relative() {
  static const MetricSetd set = [] {
    MetricSetd s;
    s.add_relative(dispkin::shapes::icosahedron(0.1, kPivot));
    return s;
  }();
  return set;
}

// The same icosahedron as a protected zone fixed in the world.
const MetricSetd& icosahedron_absolute() {
  static const MetricSetd set = [] {
    MetricSetd s;
    s.add_absolute(dispkin::shapes::icosahedron(0.1, Vector3d(0.4, 0.0, 0.3)));
    return s;
  }();
  return set;
}

// One relative sphere of radius 0.1 m around the TCP (handled exactly, doc/disp-metric.md eq. 25).
const MetricSetd& one_sphere() {
  static const MetricSetd set = [] {
    MetricSetd s;
    s.add_sphere(kPivot, 0.1, Frame::relative);
    return s;
  }();
  return set;
}

// `count` tool points uniformly random in a 0.2 × 0.2 × 0.3 m box, and the set holding them.
// 10^5 points (2.4 MB) stay in this machine's L3 cache; 10^7 points (240 MB) come from DRAM.
const std::vector<Vector3d>& cloud_points(std::size_t count) {
  static std::map<std::size_t, std::vector<Vector3d>> clouds;
  auto it = clouds.find(count);
  if (it == clouds.end()) {
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> xy(-0.1, 0.1);
    std::uniform_real_distribution<double> z(0.0, 0.3);
    std::vector<Vector3d> points;
    points.reserve(count);
    for (std::size_t i = 0; i < count; ++i) points.push_back(random_vector(xy, xy, z, rng));
    it = clouds.emplace(count, std::move(points)).first;
  }
  return it->second;
}

const MetricSetd& cloud_relative(std::size_t count) {
  static std::map<std::size_t, MetricSetd> sets;
  auto it = sets.find(count);
  if (it == sets.end()) {
    MetricSetd set;
    set.add_relative(cloud_points(count));
    it = sets.emplace(count, std::move(set)).first;
  }
  return it->second;
}

std::size_t cloud_size(const benchmark::State& state) { return static_cast<std::size_t>(state.range(0)); }

void set_point_counters(benchmark::State& state, std::size_t points) {
  const auto n = static_cast<int64_t>(points);
  state.SetItemsProcessed(state.iterations() * n);
  state.SetBytesProcessed(state.iterations() * n * kBytesPerPoint);
}

// ---------------------------------------------------------------------------------------------
// Chord distance (doc/disp-metric.md eq. 19)

template <typename Norm>
void disp_distance_icosahedron(benchmark::State& state) {
  const MetricSetd& set = icosahedron_relative();
  const Moves& m = moves();
  std::size_t i = 0;
  for (auto _ : state) {
    double d = dispkin::disp_distance<Norm>(set, m.start[i], m.end[i]);
    benchmark::DoNotOptimize(d);
    i = (i + 1) & (kMoves - 1);
  }
  state.SetItemsProcessed(state.iterations() * 12);
}
BENCHMARK_TEMPLATE(disp_distance_icosahedron, dispkin::EuclideanNorm);
BENCHMARK_TEMPLATE(disp_distance_icosahedron, dispkin::MaxNorm);
BENCHMARK_TEMPLATE(disp_distance_icosahedron, dispkin::L1Norm);

// ---------------------------------------------------------------------------------------------
// Section length (doc/section-length.md eq. 1)

void section_length_on(benchmark::State& state, const MetricSetd& set, Interpolation kind) {
  const Moves& m = moves();
  std::size_t i = 0;
  for (auto _ : state) {
    double length = dispkin::section_length(set, m.start[i], m.end[i], kind, kPivot);
    benchmark::DoNotOptimize(length);
    i = (i + 1) & (kMoves - 1);
  }
}

void section_length_icosahedron(benchmark::State& state, Frame frame, Interpolation kind) {
  section_length_on(state, frame == Frame::relative ? icosahedron_relative() : icosahedron_absolute(), kind);
  state.SetItemsProcessed(state.iterations() * 12);
}
BENCHMARK_CAPTURE(section_length_icosahedron, relative_screw, Frame::relative, Interpolation::screw);
BENCHMARK_CAPTURE(section_length_icosahedron, relative_decoupled, Frame::relative, Interpolation::decoupled);
BENCHMARK_CAPTURE(section_length_icosahedron, absolute_screw, Frame::absolute, Interpolation::screw);
BENCHMARK_CAPTURE(section_length_icosahedron, absolute_decoupled, Frame::absolute, Interpolation::decoupled);

// ---------------------------------------------------------------------------------------------
// Large clouds of relative points: items/s and bytes/s (24 bytes per point), next to a streaming
// read of the same points. The argument is the number of points: 10^5 (the target; 2.4 MB, in
// L3 cache here) and 10^7 (240 MB, from DRAM).

void section_length_cloud(benchmark::State& state, Interpolation kind) {
  section_length_on(state, cloud_relative(cloud_size(state)), kind);
  set_point_counters(state, cloud_size(state));
}
BENCHMARK_CAPTURE(section_length_cloud, screw, Interpolation::screw)
    ->Arg(100000)
    ->Arg(10000000)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(section_length_cloud, decoupled, Interpolation::decoupled)
    ->Arg(100000)
    ->Arg(10000000)
    ->Unit(benchmark::kMicrosecond);

void disp_distance_cloud(benchmark::State& state) {
  const MetricSetd& set = cloud_relative(cloud_size(state));
  const Moves& m = moves();
  std::size_t i = 0;
  for (auto _ : state) {
    double d = dispkin::disp_distance(set, m.start[i], m.end[i]);
    benchmark::DoNotOptimize(d);
    i = (i + 1) & (kMoves - 1);
  }
  set_point_counters(state, cloud_size(state));
}
BENCHMARK(disp_distance_cloud)->Arg(100000)->Arg(10000000)->Unit(benchmark::kMicrosecond);

// Reference: a pure streaming read of the same points (the three coordinate columns the set
// holds, 24 bytes per point), summing into eight independent accumulators so that no add waits
// for another — the read, not the arithmetic, limits it.
void stream_read_cloud(benchmark::State& state) {
  const auto& points = cloud_relative(cloud_size(state)).groups().front().relative_points;
  const double* columns[3] = {points.x().data(), points.y().data(), points.z().data()};
  const std::size_t count = points.size();
  for (auto _ : state) {
    double acc[8] = {0, 0, 0, 0, 0, 0, 0, 0};
    for (const double* data : columns) {
      std::size_t k = 0;
      for (; k + 8 <= count; k += 8)
        for (std::size_t j = 0; j < 8; ++j) acc[j] += data[k + j];
      for (; k < count; ++k) acc[0] += data[k];
    }
    double sum = ((acc[0] + acc[1]) + (acc[2] + acc[3])) + ((acc[4] + acc[5]) + (acc[6] + acc[7]));
    benchmark::DoNotOptimize(sum);
  }
  set_point_counters(state, points.size());
}
BENCHMARK(stream_read_cloud)->Arg(100000)->Arg(10000000)->Unit(benchmark::kMicrosecond);

// Second reference: the same read as a per-point Vector3d loop (`s += p`), one dependency chain
// per coordinate — the shape of a naive per-point kernel, for comparison only.
void stream_read_cloud_vector3_loop(benchmark::State& state) {
  const std::vector<Vector3d> points = cloud_relative(cloud_size(state)).groups().front().relative_points.to_vectors();
  for (auto _ : state) {
    Vector3d sum = Vector3d::Zero();
    for (const Vector3d& p : points) sum += p;
    benchmark::DoNotOptimize(sum);
  }
  set_point_counters(state, points.size());
}
BENCHMARK(stream_read_cloud_vector3_loop)->Arg(100000)->Unit(benchmark::kMicrosecond);

// ---------------------------------------------------------------------------------------------
// One sphere, exactly (doc/disp-metric.md eq. 25)

void sphere_speed(benchmark::State& state) {
  const Moves& m = moves();
  std::size_t i = 0;
  for (auto _ : state) {
    double speed = dispkin::sphere_speed(m.twist[i], kPivot, 0.1);
    benchmark::DoNotOptimize(speed);
    i = (i + 1) & (kMoves - 1);
  }
}
BENCHMARK(sphere_speed);

void section_length_sphere(benchmark::State& state, Interpolation kind) {
  section_length_on(state, one_sphere(), kind);
}
BENCHMARK_CAPTURE(section_length_sphere, screw, Interpolation::screw);
BENCHMARK_CAPTURE(section_length_sphere, decoupled, Interpolation::decoupled);

// ---------------------------------------------------------------------------------------------
// Pose arithmetic a controller runs every cycle (doc/disp-metric.md eqs. 2, 11–12)

void pose_compose(benchmark::State& state) {
  const Moves& m = moves();
  std::size_t i = 0;
  for (auto _ : state) {
    Posed p = m.start[i] * m.end[i];
    benchmark::DoNotOptimize(p);
    i = (i + 1) & (kMoves - 1);
  }
}
BENCHMARK(pose_compose);

void pose_inverse(benchmark::State& state) {
  const Moves& m = moves();
  std::size_t i = 0;
  for (auto _ : state) {
    Posed p = m.start[i].inverse();
    benchmark::DoNotOptimize(p);
    i = (i + 1) & (kMoves - 1);
  }
}
BENCHMARK(pose_inverse);

void pose_exp(benchmark::State& state) {
  const Moves& m = moves();
  std::size_t i = 0;
  for (auto _ : state) {
    Posed p = Posed::exp(m.twist[i]);
    benchmark::DoNotOptimize(p);
    i = (i + 1) & (kMoves - 1);
  }
}
BENCHMARK(pose_exp);

void pose_log(benchmark::State& state) {
  const Moves& m = moves();
  std::size_t i = 0;
  for (auto _ : state) {
    Twistd xi = m.end[i].log();
    benchmark::DoNotOptimize(xi);
    i = (i + 1) & (kMoves - 1);
  }
}
BENCHMARK(pose_log);

void pose_from_xyzuvw(benchmark::State& state) {
  const Moves& m = moves();
  std::size_t i = 0;
  for (auto _ : state) {
    Posed p = Posed::from_xyzuvw(m.xyzuvw[i]);
    benchmark::DoNotOptimize(p);
    i = (i + 1) & (kMoves - 1);
  }
}
BENCHMARK(pose_from_xyzuvw);

void pose_to_xyzuvw(benchmark::State& state) {
  const Moves& m = moves();
  std::size_t i = 0;
  for (auto _ : state) {
    Vector6d x = m.start[i].to_xyzuvw();
    benchmark::DoNotOptimize(x);
    i = (i + 1) & (kMoves - 1);
  }
}
BENCHMARK(pose_to_xyzuvw);

// ---------------------------------------------------------------------------------------------
// One-off costs: building the set and reducing a 10^5-point cloud to its hull vertices (Qhull)

// Building the set: add_relative of 10^5 points (finiteness checks, moments for is_well_formed).
void metric_set_add_cloud(benchmark::State& state) {
  const std::vector<Vector3d>& points = cloud_points(cloud_size(state));
  for (auto _ : state) {
    MetricSetd set;
    set.add_relative(points);
    benchmark::DoNotOptimize(set);
  }
  state.SetItemsProcessed(state.iterations() * static_cast<int64_t>(points.size()));
}
BENCHMARK(metric_set_add_cloud)->Arg(100000)->Unit(benchmark::kMillisecond);

void convex_hull_vertices_on(benchmark::State& state, const std::vector<Vector3d>& points) {
  std::size_t hull_size = 0;
  for (auto _ : state) {
    std::vector<Vector3d> hull = dispkin::convex_hull_vertices(points);
    hull_size = hull.size();
    benchmark::DoNotOptimize(hull);
  }
  state.counters["hull_vertices"] = static_cast<double>(hull_size);
  state.SetItemsProcessed(state.iterations() * static_cast<int64_t>(points.size()));
}

// Uniform in a box: about 200 of the 10^5 points end up on the hull.
void convex_hull_cloud(benchmark::State& state) { convex_hull_vertices_on(state, cloud_points(cloud_size(state))); }
BENCHMARK(convex_hull_cloud)->Arg(100000)->Unit(benchmark::kMillisecond);

// The worst case: 10^5 points on a sphere, every one a hull vertex.
void convex_hull_shell(benchmark::State& state) {
  const std::vector<Vector3d> shell = dispkin::shapes::spherical_shell(0.1, static_cast<int>(state.range(0)), kPivot);
  convex_hull_vertices_on(state, shell);
}
BENCHMARK(convex_hull_shell)->Arg(100000)->Unit(benchmark::kMillisecond);

}  // namespace
