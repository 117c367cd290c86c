// Uses the header-only core and a compiled part (Qhull-backed hull reduction) of the
// installed dispkin; prints the section length of a turn of a 1 m icosahedron.
#include <cmath>
#include <iostream>

#include <dispkin/dispkin.hpp>

int main() {
  dispkin::MetricSetd set;
  set.add_relative(dispkin::convex_hull_vertices(dispkin::shapes::icosphere(1.0, 2)));
  const dispkin::Posed a;
  const dispkin::Posed b = dispkin::Posed::from_xyzuvw((Eigen::Matrix<double, 6, 1>() << 0, 0, 0, 0, 0, 0.5).finished());
  const double length = dispkin::section_length(set, a, b, dispkin::Interpolation::screw);
  std::cout << "dispkin " << dispkin::version << " section length " << length << "\n";
  return std::isfinite(length) && length > 0.5 ? 0 : 1;
}
