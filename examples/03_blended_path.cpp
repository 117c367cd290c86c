// 03 — a blended LIN–CIRC–LIN path: through both via points without stopping.
//
// A tool 0.2 m long (icosahedra of points around its flange and its tip) moves along a LIN, a
// CIRC and a LIN. Unblended, the planner stops at both via points (the direction of motion
// jumps there); with 30 mm blends the corners become smooth pose curves, the path is one
// rest-to-rest move and takes less time. (The Python twin, 03_blended_path.py, also plots it.)
#include <cstdio>

#include <dispkin/dispkin.hpp>

namespace {

dispkin::Posed pose(double x, double y, double yaw_degrees) {
  const double deg = 3.14159265358979323846 / 180.0;
  return dispkin::Posed::from_xyzuvw(
      (Eigen::Matrix<double, 6, 1>() << x, y, 0.0, 0.0, 0.0, yaw_degrees * deg).finished());
}

}  // namespace

int main() {
  using dispkin::Path;
  const dispkin::Posed start = pose(0, 0, 0), p1 = pose(0.3, 0, 10), via = pose(0.45, 0.1, 20), p2 = pose(0.3, 0.2, 30),
                       end = pose(0, 0.2, 40);
  dispkin::MetricSetd tool;
  tool.add_relative(dispkin::shapes::icosahedron(0.02, Eigen::Vector3d(0, 0, 0)));
  tool.add_relative(dispkin::shapes::icosahedron(0.02, Eigen::Vector3d(0, 0, 0.2)));
  const dispkin::Limits limits{0.25, 1.0, 10.0};

  Path sharp = Path::lin(start, p1);
  sharp.then(Path::circ(p1, via, p2)).then(Path::lin(p2, end));
  Path smooth = Path::lin(start, p1);
  smooth.then(Path::circ(p1, via, p2), 0.03).then(Path::lin(p2, end), 0.03);

  const dispkin::Trajectory stop_and_go = dispkin::plan(sharp, tool, limits);
  const dispkin::Trajectory blended = dispkin::plan(smooth, tool, limits);
  std::printf("sharp corners: %zu sections, %zu rest-to-rest pieces, %.3f s\n", sharp.size(), stop_and_go.piece_count(),
              stop_and_go.duration());
  std::printf("blended 30 mm: %zu sections, %zu rest-to-rest piece,  %.3f s\n", smooth.size(), blended.piece_count(),
              blended.duration());
  return blended.piece_count() == 1 && blended.duration() < stop_and_go.duration() ? 0 : 1;
}
