// Uses the header-only core, compiled parts of the core (Qhull-backed hull reduction) and of the
// hexapod plugin (inverse kinematics, JSON) and, when built and linked, the serial-arm plugin of
// the installed dispkin; prints the section length of a turn of a 1 m icosahedron.
#include <cmath>
#include <iostream>

#include <dispkin/dispkin.hpp>

int main() {
  dispkin::MetricSetd set;
  set.add_relative(dispkin::convex_hull_vertices(dispkin::shapes::icosphere(1.0, 2)));
  const dispkin::Posed a;
  const dispkin::Posed b =
      dispkin::Posed::from_xyzuvw((Eigen::Matrix<double, 6, 1>() << 0, 0, 0, 0, 0, 0.5).finished());
  const double length = dispkin::section_length(set, a, b, dispkin::Interpolation::screw);
  // The hexapod plugin: legs of the home pose, and its JSON description read back.
  const auto hexapod = dispkin::hexapod::Hexapod::symmetric(0.2, 0.1, 0.1, 0.1, 0.2, 0.15, 0.35, 0.01);
  const auto again = dispkin::hexapod::Hexapod::from_json(hexapod.to_json());
  const auto legs =
      again.inverse(dispkin::Posed::from_xyzuvw((Eigen::Matrix<double, 6, 1>() << 0, 0, 0.2, 0, 0, 0).finished()));
  if (legs.size() != 1 || legs[0].size() != 6 || !(legs[0].minCoeff() > 0.15 && legs[0].maxCoeff() < 0.35)) return 2;
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
