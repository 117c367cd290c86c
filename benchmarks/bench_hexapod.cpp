// Hexapod inverse kinematics (target < 1 µs), the leg Jacobian and forward kinematics.
#include <benchmark/benchmark.h>

#include <dispkin/hexapod/hexapod.hpp>

namespace {

using dispkin::Posed;
using dispkin::Twistd;
using dispkin::hexapod::Hexapod;

const double pi = 3.14159265358979323846;

Hexapod bench_hexapod() { return Hexapod::symmetric(0.15, 20 * pi / 180, 0.10, 20 * pi / 180, 0.20, 0.15, 0.32, 0.01); }

Posed bench_pose(const Hexapod& h) {
  return h.home() * Posed::exp(Twistd(Eigen::Vector3d(0.01, -0.02, 0.015), Eigen::Vector3d(0.05, -0.1, 0.08)));
}

void BM_HexapodInverse(benchmark::State& state) {
  const Hexapod h = bench_hexapod();
  Posed pose = bench_pose(h);
  for (auto _ : state) {
    benchmark::DoNotOptimize(pose);
    Hexapod::Legs legs = h.leg_lengths(pose);
    benchmark::DoNotOptimize(legs);
  }
}
BENCHMARK(BM_HexapodInverse);

void BM_HexapodInverseXyzuvw(benchmark::State& state) {
  const Hexapod h = bench_hexapod();
  Eigen::Matrix<double, 6, 1> v;
  v << 0.01, -0.02, 0.215, 0.05, -0.1, 0.08;
  const Eigen::Vector3d pivot(0.0, 0.0, 0.05);
  for (auto _ : state) {
    benchmark::DoNotOptimize(v);
    Hexapod::Legs legs = h.leg_lengths(v, pivot);
    benchmark::DoNotOptimize(legs);
  }
}
BENCHMARK(BM_HexapodInverseXyzuvw);

void BM_HexapodLegJacobian(benchmark::State& state) {
  const Hexapod h = bench_hexapod();
  Posed pose = bench_pose(h);
  for (auto _ : state) {
    benchmark::DoNotOptimize(pose);
    Hexapod::Jacobian j = h.leg_jacobian(pose);
    benchmark::DoNotOptimize(j);
  }
}
BENCHMARK(BM_HexapodLegJacobian);

// From home to a pose 25 mm and 8° away: a typical first call without a better guess.
void BM_HexapodForwardFromHome(benchmark::State& state) {
  const Hexapod h = bench_hexapod();
  Hexapod::Legs legs = h.leg_lengths(bench_pose(h));
  for (auto _ : state) {
    benchmark::DoNotOptimize(legs);
    Posed pose = h.forward(legs);
    benchmark::DoNotOptimize(pose);
  }
}
BENCHMARK(BM_HexapodForwardFromHome);

// From the previous cycle's pose, 10 µm and 0.1 mrad away: forward kinematics on a controller.
void BM_HexapodForwardTracking(benchmark::State& state) {
  const Hexapod h = bench_hexapod();
  const Posed target = bench_pose(h);
  const Posed previous = target * Posed::exp(Twistd(Eigen::Vector3d(1e-5, 0, 0), Eigen::Vector3d(0, 1e-4, 0)));
  Hexapod::Legs legs = h.leg_lengths(target);
  for (auto _ : state) {
    benchmark::DoNotOptimize(legs);
    Posed pose = h.forward(legs, previous);
    benchmark::DoNotOptimize(pose);
  }
}
BENCHMARK(BM_HexapodForwardTracking);

}  // namespace
