// Analytic inverse kinematics, all solutions, per family (targets: closed forms ≤ 3 µs, the
// offset-wrist search ≤ 100 µs with ≥ 99.99 % recovery). Each benchmark cycles through 64 poses of
// random joint vectors.
#include <random>
#include <vector>

#include <benchmark/benchmark.h>

#include <dispkin/serial/analytic_ik.hpp>

#include "../tests/cpp/serial_test_chains.hpp"

namespace {

using dispkin::Posed;
namespace serial = dispkin::serial;

std::vector<Posed> bench_poses(const serial::RevoluteChain& chain) {
  std::mt19937_64 engine(7);
  std::uniform_real_distribution<double> angle(-3.14159, 3.14159);
  std::vector<Posed> poses;
  for (int n = 0; n < 64; ++n) {
    Eigen::VectorXd q(6);
    for (int i = 0; i < 6; ++i) q(i) = angle(engine);
    poses.push_back(serial::forward(chain, q));
  }
  return poses;
}

// The allocation-free closed form (IkSolutionSet).
void closed_form(benchmark::State& state, const serial::RevoluteChain& chain) {
  const serial::IkFamily family = serial::recognise(chain);
  const std::vector<Posed> poses = bench_poses(chain);
  serial::IkSolutionSet set;
  std::size_t i = 0;
  long solutions = 0;
  for (auto _ : state) {
    serial::analytic_inverse(chain, family, poses[i++ % poses.size()], set);
    solutions += set.count;
    benchmark::DoNotOptimize(set);
  }
  state.counters["solutions"] = static_cast<double>(solutions) / static_cast<double>(state.iterations());
}

// The std::vector interface (any family).
void listed(benchmark::State& state, const serial::RevoluteChain& chain) {
  const serial::IkFamily family = serial::recognise(chain);
  const std::vector<Posed> poses = bench_poses(chain);
  std::size_t i = 0;
  long solutions = 0;
  for (auto _ : state) {
    const auto q = serial::analytic_inverse(chain, family, poses[i++ % poses.size()]);
    solutions += static_cast<long>(q.size());
    benchmark::DoNotOptimize(q.data());
  }
  state.counters["solutions"] = static_cast<double>(solutions) / static_cast<double>(state.iterations());
}

BENCHMARK_CAPTURE(closed_form, spherical_wrist_kuka_kr6, dispkin::testing::kuka_kr6_r900());
BENCHMARK_CAPTURE(closed_form, spherical_wrist_abb_irb6640, dispkin::testing::abb_irb6640());
BENCHMARK_CAPTURE(closed_form, three_parallel_ur5, dispkin::testing::ur5());
BENCHMARK_CAPTURE(listed, spherical_wrist_kuka_kr6, dispkin::testing::kuka_kr6_r900());
BENCHMARK_CAPTURE(listed, three_parallel_ur10e, dispkin::testing::ur10e());
BENCHMARK_CAPTURE(listed, offset_wrist_jaco2, dispkin::testing::kinova_jaco2_j2n6s300())->Unit(benchmark::kMicrosecond);

}  // namespace
