// libFuzzer target: building poses from fuzzed numbers — quaternion + translation, rotation
// matrix, 4×4 matrix, XYZUVW about a pivot — and the exp/log/compose/inverse/to_xyzuvw maps
// on what was accepted.
#include <cstddef>
#include <cstdint>

#include <dispkin/pose.hpp>

#include "fuzz_input.hpp"

namespace {

using dispkin::Posed;
using dispkin::fuzz::check_finite;

// A rotation matrix: straight from the bytes, or a rotation from a quaternion moved by a
// fuzzed perturbation (so the orthonormality check is hit from both sides).
Eigen::Matrix3d rotation(dispkin::fuzz::Input& in) {
  Eigen::Matrix3d r;
  if (in.flag()) {
    for (int i = 0; i < 9; ++i) r(i / 3, i % 3) = in.number();
    return r;
  }
  const double w = in.number(), x = in.number(), y = in.number(), z = in.number();
  Eigen::Quaterniond q(w, x, y, z);
  q.normalize();
  r = q.toRotationMatrix();
  r(in.below(3), in.below(3)) += in.number() * 1e-7;
  return r;
}

void exercise(const Posed& p, dispkin::fuzz::Input& in) {
  check_finite(p, "accepted pose");
  const Posed other = in.pose();
  check_finite(p * other, "composition");
  check_finite(p.inverse(), "inverse");
  const dispkin::Twistd xi = p.log();
  check_finite(xi.vector(), "log");
  check_finite(Posed::exp(xi), "exp(log)");
  const Eigen::Vector3d pivot = in.vector3();
  check_finite(p.to_xyzuvw(pivot), "to_xyzuvw");
  check_finite(p.rotated_about_pivot(other, pivot), "rotated_about_pivot");
  check_finite(p * pivot, "transform of a point");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  dispkin::fuzz::Input in(data, size);
  dispkin::fuzz::expect_clean([&] {
    switch (in.below(4)) {
      case 0:
        exercise(in.pose(), in);
        break;
      case 1: {
        const Eigen::Matrix3d r = rotation(in);
        exercise(Posed(r, in.vector3()), in);
        break;
      }
      case 2: {
        Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
        m.topLeftCorner<3, 3>() = rotation(in);
        m.topRightCorner<3, 1>() = in.vector3();
        if (in.flag())
          for (int i = 0; i < 4; ++i) m(3, i) = in.number();
        exercise(Posed::from_matrix(m), in);
        break;
      }
      default: {
        const Eigen::Matrix<double, 6, 1> xyzuvw = in.vector6();
        exercise(Posed::from_xyzuvw(xyzuvw, in.vector3()), in);
        break;
      }
    }
  });
  return 0;
}
