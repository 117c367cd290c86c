// Python binding of dispkin/serial/serial_arm.hpp: JointLimits and SerialArm, whose inverse
// kinematics (bind_serial_inverse.cpp) and following of poses and trajectories
// (bind_serial_following.cpp) are bound beside it (serial_arm_binding.hpp).
// Joint vectors are (n,) arrays; a Jacobian is (6, n); poses are Pose or (4, 4) arrays.
#include <optional>
#include <string>

#include <pybind11/eigen.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "bindings.hpp"
#include "serial_arm_binding.hpp"
#include "value_protocol.hpp"

namespace dispkin {
namespace python {

namespace {

using serial::SerialArm;

// from_urdf: text that starts with '<' (after blanks) is the XML itself, anything else a path.
SerialArm from_urdf(const std::string& path_or_string, const std::string& base_link, const std::string& tip_link) {
  const auto first = path_or_string.find_first_not_of(" \t\r\n");
  if (first != std::string::npos && path_or_string[first] == '<')
    return SerialArm::from_urdf_string(path_or_string, base_link, tip_link);
  return SerialArm::from_urdf_file(path_or_string, base_link, tip_link);
}

py::tuple joint_limits_state(const JointLimits& l) {
  return py::make_tuple(to_vector_array(l.lower), to_vector_array(l.upper), to_vector_array(l.velocity),
                        to_vector_array(l.effort));
}

// Joint limits from the 4 items of their state; `field(k, name)` says where item k sits. Checked
// as SerialArm::with_joint_limits checks them (require_joint_limits), for as many joints as
// `lower` has.
template <typename Field>
JointLimits joint_limits_of(const py::tuple& s, Field field) {
  JointLimits l{
      state_vector<Eigen::Dynamic>(s[0], field(0, "lower")), state_vector<Eigen::Dynamic>(s[1], field(1, "upper")),
      state_vector<Eigen::Dynamic>(s[2], field(2, "velocity")), state_vector<Eigen::Dynamic>(s[3], field(3, "effort"))};
  require(l.lower.size() >= 1, "lower size", 0L, "must be at least 1 (one entry per joint)");
  require_joint_limits(l, l.lower.size(), [](Eigen::Index i) { return "joint " + std::to_string(i); });
  return l;
}

JointLimits joint_limits_from_state(const py::object& state) {
  return joint_limits_of(state_tuple(state, 4, "JointLimits"),
                         [](std::size_t k, const char* name) { return StateField("JointLimits", k, name); });
}

// The state of a pickled SerialArm: the URDF text and links it was read from, its joint limits
// (with_joint_limits may have replaced the URDF's) and its gravity.
py::tuple arm_state(const SerialArm& a) {
  return py::make_tuple(a.urdf(), a.base_link(), a.tip_link(), joint_limits_state(a.joint_limits()),
                        to_array(a.gravity()));
}

// The URDF goes through the loader's checks, the limits through with_joint_limits'.
SerialArm arm_from_state(const py::object& state) {
  const py::tuple s = state_tuple(state, 5, "SerialArm");
  const auto field = [](std::size_t k, const char* name) { return StateField("SerialArm", k, name); };
  const std::string urdf = state_cast<std::string>(s[0], field(0, "urdf"));
  const std::string base = state_cast<std::string>(s[1], field(1, "base_link")),
                    tip = state_cast<std::string>(s[2], field(2, "tip_link"));
  const py::tuple limits = state_fields(s[3], 4, field(3, "joint_limits"));
  const JointLimits joint_limits = joint_limits_of(
      limits, [&](std::size_t, const char* name) { return field(3, "joint_limits") / ("." + std::string(name)); });
  const Eigen::Vector3d gravity = state_vector<3>(s[4], field(4, "gravity"));
  SerialArm arm = SerialArm::from_urdf_string(urdf, base, tip).with_joint_limits(joint_limits);
  arm.set_gravity(gravity);
  return arm;
}


void bind_joint_limits(py::module_& m) {
  py::class_<JointLimits> joint_limits(m, "JointLimits", "Joint-space limits, one entry per joint ((n,) arrays).");
  joint_limits
      .def_property_readonly(
          "lower", [](const JointLimits& l) { return to_vector_array(l.lower); },
          "smallest joint positions (rad); -inf for a continuous joint")
      .def_property_readonly(
          "upper", [](const JointLimits& l) { return to_vector_array(l.upper); },
          "largest joint positions (rad); +inf for a continuous joint")
      .def_property_readonly(
          "velocity", [](const JointLimits& l) { return to_vector_array(l.velocity); },
          "largest joint speeds (rad/s); +inf where the URDF states none")
      .def_property_readonly(
          "effort", [](const JointLimits& l) { return to_vector_array(l.effort); },
          "largest joint torques (N m); +inf where the URDF states none (empty for a hexapod)")
      .def("__repr__", [](const JointLimits& l) {
        return "JointLimits(lower=" + tuple_repr(l.lower) + ", upper=" + tuple_repr(l.upper) +
               ", velocity=" + tuple_repr(l.velocity) + ", effort=" + tuple_repr(l.effort) + ")";
      });
  def_pickle(joint_limits, "JointLimits", &joint_limits_state, &joint_limits_from_state);
}

// The arm model: links, joints and limits, gravity, forward kinematics.
void def_arm_model(py::class_<SerialArm>& serial_arm) {
  serial_arm
      .def_static("from_urdf", &from_urdf, py::arg("path_or_string"), py::arg("base_link"), py::arg("tip_link"),
                  "From a URDF file, or URDF text when the string starts with '<'. ValueError naming the file, "
                  "link or joint for malformed URDF, unknown links, base not an ancestor of tip, unsupported joints.")
      .def_property_readonly("robot_name", &SerialArm::robot_name, "the URDF's <robot name>")
      .def_property_readonly("base_link", &SerialArm::base_link, "the link the chain starts from")
      .def_property_readonly("tip_link", &SerialArm::tip_link, "the link whose pose forward() gives")
      .def_property_readonly("dof", &SerialArm::dof, "number of joints n")
      .def_property_readonly("joint_names", &SerialArm::joint_names, "the joints in the order of q (base to tip)")
      .def_property_readonly("joint_limits", &SerialArm::joint_limits,
                             "position, velocity and effort limits (JointLimits)")
      .def(
          "with_joint_limits",
          [](const SerialArm& a, const std::optional<Eigen::VectorXd>& lower,
             const std::optional<Eigen::VectorXd>& upper, const std::optional<Eigen::VectorXd>& velocity,
             const std::optional<Eigen::VectorXd>& effort) {
            JointLimits l = a.joint_limits();
            if (lower) l.lower = *lower;
            if (upper) l.upper = *upper;
            if (velocity) l.velocity = *velocity;
            if (effort) l.effort = *effort;
            return a.with_joint_limits(l);
          },
          py::arg("lower") = py::none(), py::arg("upper") = py::none(), py::arg("velocity") = py::none(),
          py::arg("effort") = py::none(),
          "The same arm with some joint limits replaced ((dof,) arrays; None keeps the URDF's): lower < upper "
          "(+-inf for continuous joints), velocity > 0 and effort > 0 (inf: none). MoveIt's joint_limits.yaml "
          "overrides a URDF this way (dispkin.limits_files.apply_moveit_joint_limits).")
      .def_property_readonly(
          "redundancy", &SerialArm::redundancy, py::return_value_policy::reference_internal,
          "the redundancy parameter (Redundancy): for a seven-joint arm of family 'locked_joint' the "
          "locked joint and its range; kind 'none' for any other arm")
      .def_property_readonly(
          "family", [](const SerialArm& a) { return serial::to_string(a.family()); },
          "the analytic IK family recognised from the joint axes: 'spherical_wrist', "
          "'three_parallel', 'offset_wrist' or 'general' (numeric fallback)")
      .def_property(
          "gravity", [](const SerialArm& a) { return to_array(a.gravity()); },
          [](SerialArm& a, const py::object& g) { a.set_gravity(vector3(g, "gravity")); },
          "(3,) gravitational acceleration in base coordinates (m/s^2), default (0, 0, -9.81)")
      .def(
          "forward", [](const SerialArm& a, const py::object& q) { return a.forward(joint_vector(q, "q")); },
          py::arg("q"), "The tip pose in base coordinates for joint positions q (n,).")
      .def_property_readonly("urdf", &SerialArm::urdf, "the URDF text the arm was read from")
      .def("__repr__", [](const SerialArm& a) {
        return "SerialArm(robot='" + a.robot_name() + "', base_link='" + a.base_link() + "', tip_link='" +
               a.tip_link() + "', dof=" + std::to_string(a.dof()) + ", family='" + serial::to_string(a.family()) + "')";
      });
}

// Velocities and forces at a joint vector: Jacobians, torques, the configuration flags.
void def_arm_differentials(py::class_<SerialArm>& serial_arm) {
  serial_arm
      .def(
          "jacobian",
          [](const SerialArm& a, const py::object& q) {
            return Eigen::Matrix<double, 6, Eigen::Dynamic, Eigen::RowMajor>(a.jacobian(joint_vector(q, "q")));
          },
          py::arg("q"),
          "(6, n) geometric Jacobian: rows (v, w), the velocity of the tip frame's origin and the angular "
          "velocity, both in base coordinates.")
      .def(
          "body_jacobian",
          [](const SerialArm& a, const py::object& q) {
            return Eigen::Matrix<double, 6, Eigen::Dynamic, Eigen::RowMajor>(a.body_jacobian(joint_vector(q, "q")));
          },
          py::arg("q"), "(6, n) body Jacobian: the same twist (v, w) in tip coordinates (Pose.log convention).")
      .def(
          "torques",
          [](const SerialArm& a, const py::object& q, const py::object& qd, const py::object& qdd) {
            return to_vector_array(a.torques(joint_vector(q, "q"), joint_vector(qd, "qd"), joint_vector(qdd, "qdd")));
          },
          py::arg("q"), py::arg("qd"), py::arg("qdd"),
          "(n,) joint torques M(q) qdd + C(q, qd) qd + g(q) (N m), recursive Newton-Euler.")
      .def(
          "static_torques",
          [](const SerialArm& a, const py::object& q) {
            return to_vector_array(a.static_torques(joint_vector(q, "q")));
          },
          py::arg("q"), "(n,) gravity torques g(q) = torques(q, 0, 0) (N m).")
      .def(
          "configuration",
          [](const SerialArm& a, const py::object& q) {
            const serial::Configuration c = a.configuration(joint_vector(q, "q"));
            return py::make_tuple(c.shoulder, c.elbow, c.wrist);
          },
          py::arg("q"),
          "(shoulder, elbow, wrist) flags of a 6R arm, each +1, -1 or 0 on the boundary (signs of "
          "(w - p1).(w2 x w1), w3.((p3 - p2) x (w - p3)), w5.(w4 x w6); see serial_arm.hpp).");
}

}  // namespace

void bind_serial(py::module_& m) {
  bind_joint_limits(m);
  bind_inverse_result(m);
  py::class_<SerialArm> serial_arm(m, "SerialArm", R"doc(
A serial arm of revolute joints between two links of a URDF (urdfdom into an Orocos KDL chain).
Fixed joints are folded in, continuous joints have infinite position limits, prismatic, planar
and floating joints on the path are refused. Units: metres, radians, seconds, kilograms, N m.)doc");
  def_arm_model(serial_arm);
  def_arm_differentials(serial_arm);
  def_pickle(serial_arm, "SerialArm", &arm_state, &arm_from_state);
  def_inverse_kinematics(serial_arm);
  def_following(serial_arm);
}

}  // namespace python
}  // namespace dispkin
