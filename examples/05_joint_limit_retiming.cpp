// 05 — a UR5e move that is too fast for its joints, re-timed two ways: the scaling loop of the KUKA
// re-timing patent ("The robot drives through a preset working track"; slow the whole move until
// FVEL, FACC ≤ 1) and the optimal re-timing (slow down only where a joint velocity or torque limit
// binds), the latter also with a jerk limit. The move: a LIN of 350 mm with a 30° turn of the tool,
// requested at 3 m/s and 400 m/s² for a 50 mm ball 100 mm out on the tool. (The Python twin,
// 05_joint_limit_retiming.py, also plots joint speeds and torques against their limits.)
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include <dispkin/dispkin.hpp>

int main() {
  using dispkin::Posed;
  using V = Eigen::Vector3d;
  const auto arm = dispkin::serial::SerialArm::from_urdf_file(
      std::string(DISPKIN_SOURCE_DIR) + "/python/dispkin/data/ur5e.urdf", "base_link", "tool0");
  Eigen::VectorXd q_start(6);
  q_start << 0.3, -1.2, 1.5, -1.9, -1.57, 0.2;
  const Posed start = arm.forward(q_start);
  const double deg = 3.14159265358979323846 / 180.0;
  const Eigen::Quaterniond turned = Eigen::Quaterniond(Eigen::AngleAxisd(30 * deg, V::UnitZ())) * start.quaternion();
  const dispkin::Path path = dispkin::Path::lin(start, Posed(turned, start.translation() + V(0.25, -0.2, -0.15)));
  dispkin::MetricSetd tool;
  tool.add_relative(dispkin::shapes::icosahedron(0.05, V(0, 0, 0.1)));
  const dispkin::Limits fast{3.0, 400.0, std::nullopt};

  const dispkin::Trajectory requested = dispkin::plan(path, tool, fast, dispkin::ProfileKind::trapezoid);
  const dispkin::JointLimitReport before = dispkin::serial::check_joint_limits(requested, arm, q_start);
  std::printf("requested: %.3f s, FVEL %.2f, FACC %.2f\n", requested.duration(), before.velocity_factor,
              before.acceleration_factor);

  const dispkin::RetimeResult scaled =
      dispkin::serial::retime_by_scaling(path, tool, fast, dispkin::ProfileKind::trapezoid, arm, q_start);
  std::printf("scaling:   %.3f s after %d plans (velocity %.3f m/s, acceleration %.1f m/s²)\n",
              scaled.trajectory.duration(), scaled.iterations, scaled.limits.velocity, scaled.limits.acceleration);
  const dispkin::OptimalRetimeResult optimal = dispkin::serial::retime_optimal(path, tool, fast, arm, q_start);
  std::printf("optimal:   %.3f s; largest joint speed / limit %.3f, torque / limit %.3f (checked at %zu samples)\n",
              optimal.trajectory.duration(), optimal.velocity_ratio, optimal.torque_ratio,
              optimal.report.samples.size());
  // The same with a jerk limit on the tool points (2000 m/s³): each rest-to-rest run is averaged
  // over a window T so that |s⃛| ≤ j; it costs about T.
  dispkin::Limits smooth = fast;
  smooth.jerk = 2000.0;
  const dispkin::OptimalRetimeResult jerked = dispkin::serial::retime_optimal(path, tool, smooth, arm, q_start);
  std::printf("optimal, jerk ≤ %.0f m/s³: %.3f s (window %.1f ms); joint speed / limit %.3f, torque / limit %.3f\n",
              *smooth.jerk, jerked.trajectory.duration(), jerked.jerk_window * 1e3, jerked.velocity_ratio,
              jerked.torque_ratio);
  const bool ok = requested.duration() < optimal.trajectory.duration() &&
                  optimal.trajectory.duration() <= scaled.trajectory.duration() && optimal.velocity_ratio <= 1.0 &&
                  optimal.torque_ratio <= 1.0 && jerked.trajectory.duration() >= optimal.trajectory.duration() &&
                  jerked.velocity_ratio <= 1.0 && jerked.torque_ratio <= 1.0;
  return ok ? 0 : 1;
}
