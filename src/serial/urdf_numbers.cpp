// Every number of a URDF's links and joints, read once from the XML before urdfdom builds its
// model: text that is not a number, NaN, infinities, magnitudes beyond dispkin's numeric range
// and impossible inertias are refused by name and line. urdfdom would drop an <inertial> whose
// mass reads "nan" (the link then has no mass, with only a warning) and carry 1e300 m into
// forward kinematics (2e300 m) and torques (NaN).
#include "urdf_numbers.hpp"

#include <cctype>
#include <charconv>
#include <cmath>
#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

#include <Eigen/Eigenvalues>
#include <tinyxml.h>

#include "dispkin/error.hpp"

namespace dispkin {
namespace serial {
namespace {

enum class Kind {
  coordinate,    // finite, |x| ≤ 1e12 (lengths in m, angles in rad, coefficients)
  non_negative,  // the same and ≥ 0 (masses, speed and effort limits)
  joint_limit,   // finite: position limits may be wider (example-robot-data's iris: ±1e16 rad)
};

struct NumberAttribute {
  const char* element;
  const char* attribute;
  int count;
  Kind kind;
};

// The numeric attributes of URDF 1.0 (wiki.ros.org/urdf/XML/link, /joint) that urdfdom reads.
constexpr NumberAttribute numbers[] = {
    {"origin", "xyz", 3, Kind::coordinate},
    {"origin", "rpy", 3, Kind::coordinate},
    {"axis", "xyz", 3, Kind::coordinate},
    {"mass", "value", 1, Kind::non_negative},
    {"inertia", "ixx", 1, Kind::coordinate},
    {"inertia", "ixy", 1, Kind::coordinate},
    {"inertia", "ixz", 1, Kind::coordinate},
    {"inertia", "iyy", 1, Kind::coordinate},
    {"inertia", "iyz", 1, Kind::coordinate},
    {"inertia", "izz", 1, Kind::coordinate},
    {"limit", "lower", 1, Kind::joint_limit},
    {"limit", "upper", 1, Kind::joint_limit},
    {"limit", "effort", 1, Kind::non_negative},
    {"limit", "velocity", 1, Kind::non_negative},
    {"dynamics", "damping", 1, Kind::coordinate},
    {"dynamics", "friction", 1, Kind::coordinate},
    {"safety_controller", "soft_lower_limit", 1, Kind::joint_limit},
    {"safety_controller", "soft_upper_limit", 1, Kind::joint_limit},
    {"safety_controller", "k_position", 1, Kind::coordinate},
    {"safety_controller", "k_velocity", 1, Kind::coordinate},
    {"calibration", "rising", 1, Kind::coordinate},
    {"calibration", "falling", 1, Kind::coordinate},
    {"mimic", "multiplier", 1, Kind::coordinate},
    {"mimic", "offset", 1, Kind::coordinate},
    {"box", "size", 3, Kind::coordinate},
    {"cylinder", "radius", 1, Kind::coordinate},
    {"cylinder", "length", 1, Kind::coordinate},
    {"sphere", "radius", 1, Kind::coordinate},
    {"capsule", "radius", 1, Kind::coordinate},
    {"capsule", "length", 1, Kind::coordinate},
    {"mesh", "scale", 3, Kind::coordinate},
};

// "link "l1" inertial mass", "joint "j1" origin xyz": the owner, the elements below it and the
// attribute (a lone "value" is left out).
std::string name_of(const std::string& owner, const std::string& elements, const char* attribute) {
  std::string name = owner + elements;
  if (std::strcmp(attribute, "value") != 0) name += std::string(" ") + attribute;
  return name;
}

std::string on_line(const TiXmlElement& e) { return " (line " + std::to_string(e.Row()) + ")"; }

// The whitespace-separated numbers of the text, as urdfdom reads them (a leading '+' allowed);
// false when a part is not a number.
bool parse_numbers(const char* text, std::vector<double>& out) {
  out.clear();
  const char* p = text;
  const char* end = text + std::strlen(text);
  while (true) {
    while (p < end && std::isspace(static_cast<unsigned char>(*p))) ++p;
    if (p == end) return true;
    if (*p == '+') ++p;
    double value = 0.0;
    const auto [next, error] = std::from_chars(p, end, value);
    if (error != std::errc() || (next < end && !std::isspace(static_cast<unsigned char>(*next)))) return false;
    out.push_back(value);
    p = next;
  }
}

void check_attribute(const TiXmlElement& e, const NumberAttribute& spec, const std::string& name) {
  const char* text = e.Attribute(spec.attribute);
  if (text == nullptr) return;  // optional, or urdfdom's to report as missing
  std::vector<double> values;
  const std::string count_text = spec.count == 1 ? "a number" : std::to_string(spec.count) + " numbers";
  if (!parse_numbers(text, values) || static_cast<int>(values.size()) != spec.count)
    throw std::invalid_argument(describe(name, std::string(text), "must be " + count_text + on_line(e)));
  const Eigen::Map<const Eigen::VectorXd> v(values.data(), static_cast<Eigen::Index>(values.size()));
  const auto refuse = [&](const std::string& reason) {
    if (spec.count == 1) throw std::invalid_argument(describe(name, values[0], reason + on_line(e)));
    throw std::invalid_argument(describe(name, v, reason + on_line(e)));
  };
  if (!v.allFinite()) refuse("must be finite");
  if (spec.kind != Kind::joint_limit && v.cwiseAbs().maxCoeff() > numeric_range::max_translation)
    refuse("must be within ±1e12 (dispkin's numeric range)");
  if (spec.kind == Kind::non_negative && v.minCoeff() < 0.0) refuse("must be finite and not negative");
}

void check_element(const TiXmlElement& e, const std::string& owner, const std::string& elements) {
  const std::string tag = e.Value();
  const std::string here = elements + " " + tag;
  for (const NumberAttribute& spec : numbers)
    if (tag == spec.element) check_attribute(e, spec, name_of(owner, here, spec.attribute));
  for (const TiXmlElement* child = e.FirstChildElement(); child != nullptr; child = child->NextSiblingElement())
    check_element(*child, owner, here);
}

}  // namespace

std::string impossible_inertia(const Eigen::Matrix3d& inertia) {
  // Principal moments this far (relative to the largest) below zero or below the triangle
  // inequality are rounding of the printed digits; URDF exporters print six or more.
  constexpr double rounding = 1e-6;
  const Eigen::Vector3d moments =
      Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(inertia, Eigen::EigenvaluesOnly).eigenvalues();
  const double slack = rounding * moments.cwiseAbs().maxCoeff();
  if (moments(0) < -slack)
    return "is not positive semidefinite (a principal moment is " + std::to_string(moments(0)) + " kg m²)";
  if (moments(0) + moments(1) < moments(2) - slack)
    return "is not the inertia of a body: its principal moments break the triangle inequality (the two smaller must "
           "add up "
           "to at least the largest)";
  return "";
}

void require_valid_numbers(const TiXmlElement& robot) {
  for (const TiXmlElement* e = robot.FirstChildElement(); e != nullptr; e = e->NextSiblingElement()) {
    const std::string tag = e->Value();
    if (tag != "link" && tag != "joint") continue;
    const char* name = e->Attribute("name");
    const std::string owner = tag + " \"" + echoed(name != nullptr ? name : "") + "\"";
    for (const TiXmlElement* child = e->FirstChildElement(); child != nullptr; child = child->NextSiblingElement())
      check_element(*child, owner, "");
  }
}

}  // namespace serial
}  // namespace dispkin
