// Analytic inverse kinematics, all solutions, per family (targets: closed forms ≤ 3 µs, the
// offset-wrist search ≤ 100 µs with ≥ 99.99 % recovery). Each benchmark cycles through 64 poses of
// random joint vectors.
#include <random>
#include <string>
#include <vector>

#include <benchmark/benchmark.h>

#include <dispkin/serial/analytic_ik.hpp>
#include <dispkin/serial/redundancy.hpp>
#include <dispkin/serial/serial_arm.hpp>

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

// Seven joints (redundancy.hpp): every solution at one value of the locked joint, the value of
// the joint vector each of 64 poses was made from.
std::vector<Eigen::VectorXd> seven_joint_vectors() {
  std::mt19937_64 engine(7);
  std::uniform_real_distribution<double> angle(-2.8, 2.8);
  std::vector<Eigen::VectorXd> qs;
  for (int n = 0; n < 64; ++n) {
    Eigen::VectorXd q(7);
    for (int i = 0; i < 7; ++i) q(i) = angle(engine);
    qs.push_back(q);
  }
  return qs;
}

void locked_joint(benchmark::State& state, const serial::RevoluteChain& chain) {
  const serial::LockedJoint lock = serial::find_locked_joint(chain);
  const std::vector<Eigen::VectorXd> qs = seven_joint_vectors();
  std::vector<Posed> poses;
  for (const Eigen::VectorXd& q : qs) poses.push_back(serial::forward(chain, q));
  std::vector<Eigen::VectorXd> out;
  out.reserve(8);
  std::size_t i = 0;
  long solutions = 0;
  for (auto _ : state) {
    const std::size_t k = i++ % poses.size();
    out.clear();
    serial::locked_joint_inverse(chain, lock, qs[k](lock.joint), poses[k], out);
    solutions += static_cast<long>(out.size());
    benchmark::DoNotOptimize(out.data());
  }
  state.counters["solutions"] = static_cast<double>(solutions) / static_cast<double>(state.iterations());
}

// SerialArm::inverse_solutions at q_ref's value (the user's call: limits, checks, nearest first)
// on the iiwa14 test URDF.
void arm_at_q_ref(benchmark::State& state) {
  const serial::SerialArm arm = serial::SerialArm::from_urdf_file(
      std::string(DISPKIN_SOURCE_DIR) + "/tests/data/urdf/arm_iiwa14_dh.urdf", "link_0", "tool0");
  std::vector<Eigen::VectorXd> qs = seven_joint_vectors();
  for (Eigen::VectorXd& q : qs) q *= 0.7;  // inside the iiwa's limits
  std::vector<Posed> poses;
  for (const Eigen::VectorXd& q : qs) poses.push_back(arm.forward(q));
  serial::InverseOptions options;
  std::size_t i = 0;
  long solutions = 0;
  for (auto _ : state) {
    const std::size_t k = i++ % poses.size();
    options.q_ref = qs[k];
    const serial::InverseResult r = arm.inverse_solutions(poses[k], options);
    solutions += static_cast<long>(r.solutions.size());
    benchmark::DoNotOptimize(r.solutions.data());
  }
  state.counters["solutions"] = static_cast<double>(solutions) / static_cast<double>(state.iterations());
}

BENCHMARK_CAPTURE(locked_joint, panda_q7, dispkin::testing::franka_panda());
BENCHMARK_CAPTURE(locked_joint, iiwa14_q7, dispkin::testing::kuka_iiwa14());
BENCHMARK(arm_at_q_ref);
BENCHMARK_CAPTURE(closed_form, spherical_wrist_kuka_kr6, dispkin::testing::kuka_kr6_r900());
BENCHMARK_CAPTURE(closed_form, spherical_wrist_abb_irb6640, dispkin::testing::abb_irb6640());
BENCHMARK_CAPTURE(closed_form, three_parallel_ur5, dispkin::testing::ur5());
BENCHMARK_CAPTURE(listed, spherical_wrist_kuka_kr6, dispkin::testing::kuka_kr6_r900());
BENCHMARK_CAPTURE(listed, three_parallel_ur10e, dispkin::testing::ur10e());
BENCHMARK_CAPTURE(listed, offset_wrist_jaco2, dispkin::testing::kinova_jaco2_j2n6s300())->Unit(benchmark::kMicrosecond);

}  // namespace
