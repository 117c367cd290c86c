// 02 — a hexapod scan: tilt a fibre end ±5° about itself, legs kept in range and below their
// speed. The fibre end is the tool frame (on the platform) and the work frame (in the world):
// tilts are commanded as XYZUVW of the tool frame in the work frame, so they turn about the
// fibre end. The metric set is a 10 mm spherical shell around the fibre end (2 mm/s); the leg speed
// is held by rule (a) of the DISP patent JP7742490B2, the six upper leg joints as a group, or by
// rule (b), the joint-space metric. (The Python twin is 02_hexapod_scan.py.)
#include <cmath>
#include <cstdio>

#include <dispkin/dispkin.hpp>

int main() {
  const double deg = 3.14159265358979323846 / 180.0;
  const dispkin::hexapod::Hexapod hexapod =
      dispkin::hexapod::Hexapod::symmetric(0.12, 20 * deg, 0.08, 20 * deg, 0.15, 0.13, 0.20, 0.01);
  const Eigen::Vector3d fibre_end(0.0, 0.0, 0.05);  // platform coordinates
  const dispkin::WorkToolFrames frames(dispkin::Posed(Eigen::Quaterniond::Identity(), Eigen::Vector3d(0, 0, 0.20)),
                                       dispkin::Posed(Eigen::Quaterniond::Identity(), fibre_end));

  dispkin::MetricSetd shell;
  shell.add_relative(dispkin::shapes::spherical_shell(0.01, 40, frames.pivot()));
  shell.set_group_speed(0, 0.002);
  dispkin::MetricSetd with_legs = shell;
  hexapod.add_leg_speed_group(with_legs, 1);

  auto tilt = [&](double u, double v) {
    return frames.platform_pose_xyzuvw((Eigen::Matrix<double, 6, 1>() << 0, 0, 0, u * deg, v * deg, 0).finished());
  };
  const dispkin::Posed poses[] = {tilt(0, 0), tilt(5, 0), tilt(-5, 0), tilt(0, 5)};
  dispkin::Path path = dispkin::Path::lin(poses[0], poses[1], dispkin::Interpolation::decoupled, frames.pivot());
  for (int k = 1; k + 1 < 4; ++k)
    path.then(dispkin::Path::lin(poses[k], poses[k + 1], dispkin::Interpolation::decoupled, frames.pivot()));

  const dispkin::Limits limits{0.01, 0.05, 0.5};
  const dispkin::Trajectory rule_a = dispkin::plan(path, with_legs, limits);
  const dispkin::Trajectory rule_b =
      dispkin::plan(path, shell, limits, dispkin::ProfileKind::scurve, hexapod.joint_metric(path, limits));
  bool ok = true;
  for (const auto* traj : {&rule_a, &rule_b}) {
    const dispkin::hexapod::TrajectoryCheck check = hexapod.check_trajectory(*traj, 1e-3);
    std::printf("scan (leg rule %s): %.2f s, legs %.2f .. %.2f mm, fastest leg %.3f mm/s (limit 10 mm/s): %s\n",
                traj == &rule_a ? "(a)" : "(b)", traj->duration(), check.min_length.minCoeff() * 1e3,
                check.max_length.maxCoeff() * 1e3, check.max_speed.maxCoeff() * 1e3,
                check.ok() ? "within limits" : "OUT OF LIMITS");
    ok = ok && check.ok();
  }
  return ok ? 0 : 1;
}
