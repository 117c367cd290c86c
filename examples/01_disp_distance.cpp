// 01 — the first DISP distance: how fast does a tool really move?
//
// A 300 mm tool turns while its centre point (TCP) moves 50 mm. A controller that limits the
// TCP speed and, separately, the angular speed lets the tool tip run faster than commanded.
// dispkin measures the move with the metric set {tool tip, sphere around the TCP} instead.
#include <cstdio>

#include <dispkin/dispkin.hpp>

int main() {
  using dispkin::Posed;
  using Vector6 = Eigen::Matrix<double, 6, 1>;
  const double deg = 3.14159265358979323846 / 180.0;

  dispkin::MetricSetd tool;
  tool.add_relative(Eigen::Vector3d(0.0, 0.0, 0.3));  // the tool tip, 300 mm along z
  tool.add_sphere(Eigen::Vector3d::Zero(), 0.1);      // 100 mm sphere around the TCP

  const Posed start = Posed::from_xyzuvw(Vector6::Zero());
  const Posed end = Posed::from_xyzuvw((Vector6() << 0.05, 0.02, 0.0, 10 * deg, 0.0, 30 * deg).finished());

  const double chord = dispkin::disp_distance(tool, start, end);
  const double lin = dispkin::section_length(tool, start, end, dispkin::Interpolation::decoupled);
  const double screw = dispkin::section_length(tool, start, end, dispkin::Interpolation::screw);

  // The usual controller: TCP at v, rotation at v / eqradius (eqradius = the sphere radius).
  const double v = 0.1;  // m/s
  const double eqradius = 0.1;
  const double tcp_path = (end.translation() - start.translation()).norm();
  const double angle = 2.0 * std::atan2((start.quaternion().conjugate() * end.quaternion()).vec().norm(),
                                        std::abs((start.quaternion().conjugate() * end.quaternion()).w()));
  const double tcp_only_duration = std::max(tcp_path / v, angle * eqradius / v);

  std::printf("chord distance            %.6f m\n", chord);
  std::printf("LIN section length        %.6f m  -> %.3f s at %.2f m/s\n", lin, lin / v, v);
  std::printf("screw section length      %.6f m  -> %.3f s\n", screw, screw / v);
  std::printf("TCP + angular limit       %.3f s: fastest point at %.3f m/s = %.2f x the limit\n", tcp_only_duration,
              lin / tcp_only_duration, lin / tcp_only_duration / v);
  return chord <= lin * (1 + 1e-12) ? 0 : 1;
}
