// Joint-limit check and both re-timing methods on a 6-axis arm move: example 05's UR5e LIN (350 mm,
// 30° turn) requested at 3 m/s and 400 m/s² for a tool ball, which the joints cannot follow. The
// optimal re-timing is timed whole (plan, joint path and torque coefficients on the grid,
// reachability passes, dense check) and with its check reduced to the characteristic points;
// benchmarks/retime_vs_toppra.py compares with toppra. The large joint motion is a LIN of
// example-robot-data's UR5 whose joints move 0.1–1.2 rad, under slack DISP limits, joint velocity
// and acceleration only.
#include <cstdlib>
#include <filesystem>
#include <string>

#include <benchmark/benchmark.h>

#include <dispkin/hexapod/hexapod_retiming.hpp>
#include <dispkin/serial/serial_retiming.hpp>
#include <dispkin/shapes.hpp>

namespace {

using V = Eigen::Vector3d;

struct Move {
  dispkin::serial::SerialArm arm;
  Eigen::VectorXd q_start;
  dispkin::Path path;
  dispkin::MetricSetd tool;
};

const Move& move() {
  static const Move m = [] {
    auto arm = dispkin::serial::SerialArm::from_urdf_file(
        std::string(DISPKIN_SOURCE_DIR) + "/tests/data/urdf/arm_ur5e_dh.urdf", "base_link", "tool0");
    Eigen::VectorXd q(6);
    q << 0.3, -1.2, 1.5, -1.9, -1.57, 0.2;
    const dispkin::Posed a = arm.forward(q);
    const Eigen::Quaterniond turned =
        Eigen::Quaterniond(Eigen::AngleAxisd(0.5235987755982988, V::UnitZ())) * a.quaternion();
    dispkin::MetricSetd tool;
    tool.add_relative(dispkin::shapes::icosahedron(0.05, V(0, 0, 0.1)));
    return Move{arm, q, dispkin::Path::lin(a, dispkin::Posed(turned, a.translation() + V(0.25, -0.2, -0.15))), tool};
  }();
  return m;
}

const dispkin::Limits fast{3.0, 400.0, std::nullopt};

void BM_RetimeCheckJointLimits(benchmark::State& state) {
  const Move& m = move();
  const dispkin::Trajectory t = dispkin::plan(m.path, m.tool, fast, dispkin::ProfileKind::trapezoid);
  for (auto _ : state) benchmark::DoNotOptimize(dispkin::serial::check_joint_limits(t, m.arm, m.q_start));
}
BENCHMARK(BM_RetimeCheckJointLimits)->Unit(benchmark::kMillisecond);

void BM_RetimeScaling(benchmark::State& state) {
  const Move& m = move();
  for (auto _ : state) {
    benchmark::DoNotOptimize(
        dispkin::serial::retime_by_scaling(m.path, m.tool, fast, dispkin::ProfileKind::trapezoid, m.arm, m.q_start));
  }
}
BENCHMARK(BM_RetimeScaling)->Unit(benchmark::kMillisecond);

// Argument: check_samples_between (the dense check's density).
void BM_RetimeOptimal(benchmark::State& state) {
  const Move& m = move();
  dispkin::OptimalRetimeOptions options;
  options.grid_intervals = 100;
  options.check_samples_between = static_cast<int>(state.range(0));
  for (auto _ : state)
    benchmark::DoNotOptimize(dispkin::serial::retime_optimal(m.path, m.tool, fast, m.arm, m.q_start, options));
}
BENCHMARK(BM_RetimeOptimal)->Arg(0)->Arg(3)->Unit(benchmark::kMillisecond);

// The same with a jerk limit of 2000 m/s³ (the S-curve's): the jerk-free solve, the re-solves
// with the speed caps tightened over the window's reach, the moving average, and the dense check.
void BM_RetimeOptimalJerkLimited(benchmark::State& state) {
  const Move& m = move();
  dispkin::Limits limits = fast;
  limits.jerk = 2000.0;
  dispkin::OptimalRetimeOptions options;
  options.grid_intervals = 100;
  options.check_samples_between = static_cast<int>(state.range(0));
  for (auto _ : state)
    benchmark::DoNotOptimize(dispkin::serial::retime_optimal(m.path, m.tool, limits, m.arm, m.q_start, options));
}
BENCHMARK(BM_RetimeOptimalJerkLimited)->Arg(0)->Arg(3)->Unit(benchmark::kMillisecond);

// example-robot-data's ur5_robot.urdf in the project's .venv (scripts/install-deps.sh installs it
// from requirements-dev.txt), or in $DISPKIN_EXAMPLE_ROBOTS (its robots/ folder); empty if absent.
std::string example_robot_ur5() {
  namespace fs = std::filesystem;
  const fs::path below = "ur_description/urdf/ur5_robot.urdf";
  if (const char* robots = std::getenv("DISPKIN_EXAMPLE_ROBOTS")) return (fs::path(robots) / below).string();
  const fs::path lib = fs::path(DISPKIN_SOURCE_DIR) / ".venv/lib";
  std::error_code error;
  for (const auto& python : fs::directory_iterator(lib, error)) {
    const fs::path urdf = python.path() / "site-packages/cmeel.prefix/share/example-robot-data/robots" / below;
    if (fs::exists(urdf)) return urdf.string();
  }
  return {};
}

// Argument: check_samples_between. The move of retime_vs_toppra.py's large_move(): configurations
// 1.2, 0.5, 0.6, 0.3, 0.4, 0.1 rad apart, DISP limits 10 m/s and 1000 m/s², joint accelerations
// 8 rad/s² (first three) and 12 rad/s², no torque limits.
void BM_RetimeOptimalLargeMotion(benchmark::State& state) {
  const std::string urdf = example_robot_ur5();
  if (urdf.empty()) {
    state.SkipWithError("example-robot-data's ur5_robot.urdf not found (scripts/install-deps.sh installs it)");
    return;
  }
  const auto arm = dispkin::serial::SerialArm::from_urdf_file(urdf, "base_link", "tool0");
  Eigen::VectorXd q(6), moved(6);
  q << 0.0, -1.6, 1.7, -1.7, -1.57, 0.0;
  moved << 1.2, 0.5, -0.6, 0.3, 0.4, 0.1;
  const dispkin::Path path = dispkin::Path::lin(arm.forward(q), arm.forward(q + moved));
  dispkin::MetricSetd tool;
  tool.add_relative(dispkin::shapes::icosahedron(0.05, V(0, 0, 0.1)));
  const dispkin::Limits slack{10.0, 1000.0, std::nullopt};
  dispkin::OptimalRetimeOptions options;
  options.grid_intervals = 100;
  options.joint_acceleration.resize(6);
  options.joint_acceleration << 8.0, 8.0, 8.0, 12.0, 12.0, 12.0;
  options.torque_limits = false;
  options.check_samples_between = static_cast<int>(state.range(0));
  for (auto _ : state) benchmark::DoNotOptimize(dispkin::serial::retime_optimal(path, tool, slack, arm, q, options));
}
BENCHMARK(BM_RetimeOptimalLargeMotion)->Arg(0)->Arg(3)->Unit(benchmark::kMillisecond);

}  // namespace
