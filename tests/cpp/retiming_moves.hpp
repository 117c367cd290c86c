// The UR5e move shared by the re-timing tests (test_retiming.cpp, test_optimal_retiming.cpp):
// the DH UR5e of tests/data/urdf, a 50 mm tool ball 100 mm out, and a LIN of ~290 mm with a
// 0.5 rad turn from a fixed configuration.
#pragma once

#include <string>

#include <dispkin/path/path.hpp>
#include <dispkin/serial/serial_arm.hpp>
#include <dispkin/shapes.hpp>

#include "serial_test_arms.hpp"  // ur5e

namespace dispkin::testing {

inline MetricSetd tool() {
  MetricSetd set;
  set.add_relative(shapes::icosahedron(0.05, Eigen::Vector3d(0, 0, 0.1)));
  return set;
}

struct Move {
  Eigen::VectorXd q_start;
  Path path;
};

inline Move lin_move(const serial::SerialArm& arm) {
  using Vec = Eigen::Vector3d;
  Eigen::VectorXd q(6);
  q << 0.3, -1.2, 1.5, -1.9, -1.57, 0.2;
  const Posed a = arm.forward(q);
  const Posed b = Posed(Eigen::Quaterniond(Eigen::AngleAxisd(0.5, Vec::UnitZ())), Vec(0.25, -0.1, -0.1)) * a;
  return {q, Path::lin(a, Posed(b.quaternion(), a.translation() + Vec(0.25, -0.1, -0.1)))};
}

}  // namespace dispkin::testing
