// Serial-arm plugin: forward kinematics, Jacobian and RNE torques through KDL, and
// SerialArm::inverse_solutions (analytic family plus limits, 2π copies and the check by forward
// kinematics of every solution) on the DH UR5e and the KR6-like arm of tests/data/urdf.
#include <string>
#include <vector>

#include <benchmark/benchmark.h>

#include <dispkin/serial/serial_arm.hpp>

namespace {

using dispkin::Posed;
using dispkin::serial::InverseOptions;
using dispkin::serial::SerialArm;

const std::string urdf_dir = std::string(DISPKIN_SOURCE_DIR) + "/tests/data/urdf/";

const SerialArm& ur5e() {
  static const SerialArm arm = SerialArm::from_urdf_file(urdf_dir + "arm_ur5e_dh.urdf", "base_link", "tool0");
  return arm;
}
const SerialArm& kr6() {
  static const SerialArm arm = SerialArm::from_urdf_file(urdf_dir + "arm_kr6_like_dh.urdf", "base_link", "flange");
  return arm;
}

Eigen::VectorXd bench_q() {
  Eigen::VectorXd q(6);
  q << 0.3, -1.2, 1.5, -0.4, 1.1, 0.2;
  return q;
}

void BM_SerialForward(benchmark::State& state) {
  const Eigen::VectorXd q = bench_q();
  for (auto _ : state) benchmark::DoNotOptimize(ur5e().forward(q));
}
BENCHMARK(BM_SerialForward);

void BM_SerialJacobian(benchmark::State& state) {
  const Eigen::VectorXd q = bench_q();
  for (auto _ : state) benchmark::DoNotOptimize(ur5e().jacobian(q));
}
BENCHMARK(BM_SerialJacobian);

void BM_SerialTorques(benchmark::State& state) {
  const Eigen::VectorXd q = bench_q();
  const Eigen::VectorXd qd = Eigen::VectorXd::Constant(6, 0.5);
  const Eigen::VectorXd qdd = Eigen::VectorXd::Constant(6, -1.0);
  for (auto _ : state) benchmark::DoNotOptimize(ur5e().torques(q, qd, qdd));
}
BENCHMARK(BM_SerialTorques);

void BM_SerialStaticTorques(benchmark::State& state) {
  const Eigen::VectorXd q = bench_q();
  for (auto _ : state) benchmark::DoNotOptimize(ur5e().static_torques(q));
}
BENCHMARK(BM_SerialStaticTorques);

// range(0): 0 = UR5e, 1 = KR6-like; range(1): 1 = with the 2π copies inside the limits.
void BM_SerialInverse(benchmark::State& state) {
  const SerialArm& arm = state.range(0) == 0 ? ur5e() : kr6();
  Eigen::VectorXd q = bench_q();
  q(1) = -0.6;  // inside the KR6-like limits too
  const Posed pose = arm.forward(q);
  InverseOptions options;
  options.offer_equivalents = state.range(1) == 1;
  std::size_t count = 0;
  for (auto _ : state) {
    const auto result = arm.inverse_solutions(pose, options);
    count = result.solutions.size();
    benchmark::DoNotOptimize(result);
  }
  state.counters["solutions"] = static_cast<double>(count);
}
BENCHMARK(BM_SerialInverse)->Args({0, 0})->Args({0, 1})->Args({1, 0})->Args({1, 1});

}  // namespace
