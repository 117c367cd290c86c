// 02 — a hexapod scan: tilt a fibre end ±5° about itself, legs kept in range and below their
// speed. The metric set is a 10 mm spherical shell around the fibre end (2 mm/s) plus the six
// upper leg joints held to the leg speed. (The Python twin is 02_hexapod_scan.py.)
#include <cmath>
#include <cstdio>

#include <dispkin/dispkin.hpp>

int main() {
  const double deg = 3.14159265358979323846 / 180.0;
  const dispkin::Hexapod hexapod = dispkin::Hexapod::symmetric(0.12, 20 * deg, 0.08, 20 * deg, 0.15, 0.13, 0.20, 0.01);
  const Eigen::Vector3d pivot(0.0, 0.0, 0.05);  // the fibre end, platform coordinates

  dispkin::MetricSetd scan;
  scan.add_relative(dispkin::shapes::spherical_shell(0.01, 40, pivot));
  scan.set_group_speed(0, 0.002);
  hexapod.add_leg_speed_group(scan, 1);

  auto tilt = [&](double u, double v) {
    return dispkin::Posed::from_xyzuvw((Eigen::Matrix<double, 6, 1>() << 0, 0, 0.15, u * deg, v * deg, 0).finished(), pivot);
  };
  const dispkin::Posed poses[] = {tilt(0, 0), tilt(5, 0), tilt(-5, 0), tilt(0, 5)};
  dispkin::Path path = dispkin::Path::lin(poses[0], poses[1], dispkin::Interpolation::decoupled, pivot);
  for (int k = 1; k + 1 < 4; ++k) path.then(dispkin::Path::lin(poses[k], poses[k + 1], dispkin::Interpolation::decoupled, pivot));

  const dispkin::Trajectory traj = dispkin::plan(path, scan, dispkin::Limits{0.01, 0.05, 0.5});
  const dispkin::TrajectoryCheck check = hexapod.check_trajectory(traj, 1e-3);
  std::printf("scan: %.2f s, legs %.2f .. %.2f mm, fastest leg %.3f mm/s (limit 10 mm/s): %s\n", traj.duration(),
              check.min_length.minCoeff() * 1e3, check.max_length.maxCoeff() * 1e3, check.max_speed.maxCoeff() * 1e3,
              check.ok() ? "within limits" : "OUT OF LIMITS");
  return check.ok() ? 0 : 1;
}
