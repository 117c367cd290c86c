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
    // The 2π copies (up to 64 per solution on the UR5e's ±2π joints, each checked twice) cost
    // most of an execution: asked for in one input out of eight.
    options.offer_equivalents = in.below(8) == 0;
    const dispkin::serial::InverseResult result = arm.inverse_solutions(target, options);
    if (result.within_limits.size() != result.solutions.size()) dispkin::fuzz::finding("within_limits size");
    for (std::size_t k = 0; k < result.solutions.size(); ++k) {
      const Eigen::VectorXd& q = result.solutions[k];
      check_finite(q, "IK solution");
      if (!arm.forward(q).is_approx(target, dispkin::serial::inverse_tolerance))
        dispkin::fuzz::finding("IK solution does not reproduce the pose");
      if (k < 8) (void)arm.configuration(q);  // exercised on the first few (the copies share flags)
    }
  });
  return 0;
}
