// libFuzzer target: the URDF loader, SerialArm::from_urdf_string.
//
// Input: URDF text. If it starts with a line "@<base> <tip>", those are the chain's end links
// and the rest is the URDF; otherwise the chain runs from "base_link" to "tool0". A loaded arm
// is also asked for its forward kinematics, Jacobian and static torques at q = 0 (finite
// output required).
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>

#include <dispkin/serial/serial_arm.hpp>

#include "fuzz_input.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using dispkin::fuzz::check_finite;
  std::string xml(reinterpret_cast<const char*>(data), size);
  // A '%' outside comments (urdfdom uses attribute text as a printf format: a crash in vfprintf)
  // must be refused by the loader before urdfdom parses it: no skip here.
  std::string base = "base_link", tip = "tool0";
  if (!xml.empty() && xml[0] == '@') {
    const std::size_t end = xml.find('\n');
    std::istringstream header(xml.substr(1, end == std::string::npos ? std::string::npos : end - 1));
    header >> base >> tip;
    xml = end == std::string::npos ? std::string() : xml.substr(end + 1);
  }
  dispkin::fuzz::expect_clean([&] {
    const auto arm = dispkin::serial::SerialArm::from_urdf_string(xml, base, tip);
    const Eigen::VectorXd q = Eigen::VectorXd::Zero(arm.dof());
    check_finite(arm.forward(q), "forward(0) of a loaded URDF");
    check_finite(arm.jacobian(q), "jacobian(0) of a loaded URDF");
    check_finite(arm.static_torques(q), "static_torques(0) of a loaded URDF");
  });
  return 0;
}
