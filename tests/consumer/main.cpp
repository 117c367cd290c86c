// Uses the header-only core, a compiled part (Qhull-backed hull reduction) and, when built,
// the serial-arm plugin of the installed dispkin; prints the section length of a turn of a 1 m icosahedron.
#include <cmath>
#include <iostream>

#include <dispkin/dispkin.hpp>

int main() {
  dispkin::MetricSetd set;
  set.add_relative(dispkin::convex_hull_vertices(dispkin::shapes::icosphere(1.0, 2)));
  const dispkin::Posed a;
  const dispkin::Posed b = dispkin::Posed::from_xyzuvw((Eigen::Matrix<double, 6, 1>() << 0, 0, 0, 0, 0, 0.5).finished());
  const double length = dispkin::section_length(set, a, b, dispkin::Interpolation::screw);
#if defined(DISPKIN_HAS_SERIAL)
  // The serial-arm plugin (urdfdom and KDL linked privately into dispkin::serial): a one-joint
  // arm from URDF text, so that the installed package's link dependencies are exercised.
  const auto arm = dispkin::serial::SerialArm::from_urdf_string(
      "<robot name='r'><link name='a'/><link name='b'/><joint name='j' type='continuous'><parent link='a'/>"
      "<child link='b'/><origin xyz='0 0 0.1'/><axis xyz='0 0 1'/></joint></robot>",
      "a", "b");
  if (arm.dof() != 1 || std::abs(arm.forward(Eigen::VectorXd::Zero(1)).translation().z() - 0.1) > 1e-15) return 1;
#endif
  std::cout << "dispkin " << dispkin::version << " section length " << length << "\n";
  return std::isfinite(length) && length > 0.5 ? 0 : 1;
}
