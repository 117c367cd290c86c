// PTP moves (ptp.hpp): planning one joint-line move of the DH UR5e under a tool set (an
// icosahedron of 12 points, an absolute sphere) — the section cutting, the velocity-limit curve
// and the time laws — and sampling it (q, q̇, q̈, pose, twist at one instant).
#include <string>

#include <benchmark/benchmark.h>

#include <dispkin/serial/ptp.hpp>
#include <dispkin/shapes.hpp>

namespace {

using dispkin::serial::SerialArm;

const SerialArm& ur5e() {
  static const SerialArm arm = SerialArm::from_urdf_file(
      std::string(DISPKIN_SOURCE_DIR) + "/tests/data/urdf/arm_ur5e_dh.urdf", "base_link", "tool0");
  return arm;
}

dispkin::MetricSetd tool_set() {
  dispkin::MetricSetd set;
  set.add_relative(dispkin::shapes::icosahedron(0.1));
  set.add_sphere(Eigen::Vector3d(0.4, 0.0, 0.3), 0.05, dispkin::Frame::absolute);
  return set;
}

dispkin::JointPath bench_move() {
  Eigen::VectorXd q_a(6), q_b(6);
  q_a << 0.1, -1.2, 1.3, -1.0, -1.2, 0.2;
  q_b << 1.4, -0.6, 0.7, -1.6, -0.9, 1.1;
  return dispkin::JointPath(q_a, q_b);
}

void BM_PtpPlanUr5e(benchmark::State& state) {
  const dispkin::MetricSetd set = tool_set();
  const dispkin::JointPath move = bench_move();
  const dispkin::Limits limits{0.5, 2.0, 20.0};
  std::size_t sections = 0;
  for (auto _ : state) {
    const dispkin::serial::JointTrajectory traj =
        dispkin::serial::plan(move, set, limits, dispkin::ProfileKind::scurve, ur5e());
    sections = traj.sections().size();
    benchmark::DoNotOptimize(traj.duration());
  }
  state.counters["sections"] = static_cast<double>(sections);
}
BENCHMARK(BM_PtpPlanUr5e)->Unit(benchmark::kMicrosecond);

void BM_PtpSampleUr5e(benchmark::State& state) {
  const dispkin::serial::JointTrajectory traj = dispkin::serial::plan(
      bench_move(), tool_set(), dispkin::Limits{0.5, 2.0, 20.0}, dispkin::ProfileKind::scurve, ur5e());
  double t = 0.0;
  const double dt = traj.duration() / 997.0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(traj.sample(t));
    t += dt;
    if (t > traj.duration()) t = 0.0;
  }
}
BENCHMARK(BM_PtpSampleUr5e);

}  // namespace
