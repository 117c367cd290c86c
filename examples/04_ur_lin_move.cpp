// 04 — a LIN move of a UR5e in Cartesian space and the joint path that drives it: 200 mm along
// x, 100 mm along y, 100 mm down while the tool turns 30° about its axis, no point of the tool
// (tip 150 mm out, 40 mm ball at the flange) above 0.25 m/s; every sample solved by the
// analytic IK and the solution nearest to the previous one kept. (The Python twin is
// 04_ur_lin_move.py.)
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <dispkin/dispkin.hpp>

int main() {
  using dispkin::Posed;
  const auto arm = dispkin::serial::SerialArm::from_urdf_file(
      std::string(DISPKIN_SOURCE_DIR) + "/python/dispkin/data/ur5e.urdf", "base_link", "tool0");
  Eigen::VectorXd q_start(6);
  q_start << 0.0, -1.9, 1.9, -1.57, -1.57, 0.0;
  const Posed start = arm.forward(q_start);
  const double deg = 3.14159265358979323846 / 180.0;
  const Posed goal = Posed(Eigen::Quaterniond::Identity(), Eigen::Vector3d(0.2, 0.1, -0.1)) * start *
                     Posed::from_xyzuvw((Eigen::Matrix<double, 6, 1>() << 0, 0, 0, 0, 0, 30 * deg).finished());

  dispkin::MetricSetd tool;
  tool.add_relative(Eigen::Vector3d(0.0, 0.0, 0.15));
  tool.add_sphere(Eigen::Vector3d::Zero(), 0.04);
  const dispkin::Trajectory traj =
      dispkin::plan(dispkin::Path::lin(start, goal), tool, dispkin::Limits{0.25, 1.0, 10.0});

  std::vector<Posed> poses;
  std::vector<double> times;
  for (int k = 0; k <= 10; ++k) {
    times.push_back(traj.duration() * k / 10.0);
    poses.push_back(traj.sample(times.back()).pose);
  }
  const std::vector<Eigen::VectorXd> joints = dispkin::serial::follow(arm, poses, q_start);
  std::printf("%s: family %s, LIN move of %.3f s\n   t/s  ", arm.robot_name().c_str(),
              dispkin::serial::to_string(arm.family()).c_str(), traj.duration());
  for (const std::string& name : arm.joint_names()) std::printf("  %11.11s", name.c_str());
  std::printf("\n");
  double worst = 0.0;
  double step = 0.0;
  for (std::size_t k = 0; k < joints.size(); ++k) {
    std::printf("%7.3f  ", times[k]);
    for (int i = 0; i < 6; ++i) std::printf("  %11.5f", joints[k](i));
    std::printf("\n");
    worst = std::max(worst, (arm.forward(joints[k]).matrix() - poses[k].matrix()).cwiseAbs().maxCoeff());
    if (k > 0) step = std::max(step, (joints[k] - joints[k - 1]).cwiseAbs().maxCoeff());
  }
  std::printf("largest pose error %.1e, largest joint step between samples %.3f rad\n", worst, step);
  return worst <= 1e-10 && step < 0.5 ? 0 : 1;
}
