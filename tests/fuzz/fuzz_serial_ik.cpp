// libFuzzer target: inverse kinematics of a fixed UR5e (tests/data/urdf/arm_ur5e_dh.urdf) at
// fuzzed poses — straight from the bytes, or forward(q) of fuzzed joints (reachable, often
// near singular) moved by a fuzzed perturbation. Every returned solution must be finite and
// reproduce the pose to inverse_tolerance, as inverse_solutions promises.
#include <cstddef>
#include <cstdint>

#include <dispkin/serial/serial_arm.hpp>

#include "fuzz_input.hpp"

namespace {

const dispkin::serial::SerialArm& ur5e() {
  static const dispkin::serial::SerialArm arm = dispkin::serial::SerialArm::from_urdf_file(
      DISPKIN_SOURCE_DIR "/tests/data/urdf/arm_ur5e_dh.urdf", "base_link", "tool0");
  return arm;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using dispkin::fuzz::check_finite;
  const auto& arm = ur5e();
  dispkin::fuzz::Input in(data, size);
  dispkin::fuzz::expect_clean([&] {
    dispkin::Posed target;
    if (in.flag()) {
      target = in.pose();
    } else {
      Eigen::VectorXd q(6);
      for (int i = 0; i < 6; ++i) q(i) = in.flag() ? in.number() : 0.5 * M_PI * in.below(5);
      target = arm.forward(q);
      check_finite(target, "forward(q)");
      if (in.flag()) {
        const Eigen::Vector3d v = in.vector3() * 1e-6, w = in.vector3() * 1e-6;
        target = target * dispkin::Posed::exp(dispkin::Twistd(v, w));
      }
    }
    dispkin::serial::InverseOptions options;
    options.keep_outside_limits = in.flag();
    options.offer_equivalents = in.flag();
    const dispkin::serial::InverseResult result = arm.inverse_solutions(target, options);
    if (result.within_limits.size() != result.solutions.size()) dispkin::fuzz::finding("within_limits size");
    for (const Eigen::VectorXd& q : result.solutions) {
      check_finite(q, "IK solution");
      if (!arm.forward(q).is_approx(target, dispkin::serial::inverse_tolerance))
        dispkin::fuzz::finding("IK solution does not reproduce the pose");
      (void)arm.configuration(q);
    }
  });
  return 0;
}
