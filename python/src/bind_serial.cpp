// Python binding of dispkin/serial/serial_arm.hpp: SerialArm, JointLimits, InverseResult; and the
// arm's joints along a trajectory (serial_retiming.hpp) as SerialArm methods.
// Joint vectors are (n,) arrays; a Jacobian is (6, n); poses are Pose or (4, 4) arrays.
#include <optional>
#include <string>
#include <vector>

#include <pybind11/eigen.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "bindings.hpp"
#include "conversions.hpp"
#include "interpreter_lock.hpp"
#include "value_protocol.hpp"
#include "dispkin/serial/ptp.hpp"
#include "dispkin/serial/serial_arm.hpp"
#include "dispkin/serial/serial_retiming.hpp"

namespace dispkin {
namespace python {

namespace {

using serial::FollowedJoints;
using serial::InverseOptions;
using serial::InverseResult;
using serial::JointTrajectory;
using serial::SerialArm;

// A Pose or a (4, 4) matrix. A Pose is read as it is, and so is a contiguous float64 array, C
// or Fortran order (Pose.matrix() gives the latter), without a converted copy; anything else
// goes through numpy's conversion.
Posed pose_of(const py::handle& obj, const std::string& name) {
  if (py::isinstance<Posed>(obj)) return obj.cast<const Posed&>();
  if (py::array_t<double>::check_(obj)) {
    const auto a = py::reinterpret_borrow<py::array>(obj);
    if (a.ndim() == 2 && a.shape(0) == 4 && a.shape(1) == 4) {
      const auto* data = static_cast<const double*>(a.data());
      if (a.flags() & py::array::c_style)
        return Posed::from_matrix(Eigen::Map<const Eigen::Matrix<double, 4, 4, Eigen::RowMajor>>(data));
      if (a.flags() & py::array::f_style) return Posed::from_matrix(Eigen::Map<const Eigen::Matrix4d>(data));
    }
  }
  return Posed::from_matrix(matrix4(obj, name));
}

// The poses of inverse_many: an (N, 4, 4) array, or a sequence of Poses and (4, 4) arrays. Read
// while the interpreter lock is held; `poses[i]` names a bad one.
std::vector<Posed> poses_of(const py::handle& obj) {
  const std::string expected = "an array of shape (N, 4, 4) or a sequence of Poses";
  std::vector<Posed> out;
  const auto named = [](std::size_t i) { return "poses[" + std::to_string(i) + "]"; };
  // The pose checks (finite, rigid) say what is wrong with "matrix" or "rotation": prefixed
  // with the index.
  const auto checked = [&](std::size_t i, const auto& make) {
    try {
      out.push_back(make());
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument(named(i) + " " + e.what());
    }
  };
  if (py::isinstance<py::array>(obj) || !py::isinstance<py::sequence>(obj) || py::isinstance<py::str>(obj)) {
    const Array a = as_array(obj, "poses", expected);
    if (a.ndim() != 3 || a.shape(1) != 4 || a.shape(2) != 4) wrong_shape("poses", expected, a);
    out.reserve(static_cast<std::size_t>(a.shape(0)));
    for (py::ssize_t i = 0; i < a.shape(0); ++i)
      checked(static_cast<std::size_t>(i), [&] {
        return Posed::from_matrix(Eigen::Map<const Eigen::Matrix<double, 4, 4, Eigen::RowMajor>>(a.data() + 16 * i));
      });
    return out;
  }
  const auto seq = py::reinterpret_borrow<py::sequence>(obj);
  out.reserve(seq.size());
  for (std::size_t i = 0; i < seq.size(); ++i) {
    const py::object item = seq[i];
    if (py::isinstance<Posed>(item)) {
      out.push_back(item.cast<const Posed&>());
      continue;
    }
    const Eigen::Matrix4d m = matrix4(item, named(i));
    checked(i, [&] { return Posed::from_matrix(m); });
  }
  return out;
}

// Solutions as the rows of a (k, n) array ((0, n) when there are none).
py::array_t<double> solution_rows(const std::vector<Eigen::VectorXd>& solutions, int n) {
  py::array_t<double> out({static_cast<py::ssize_t>(solutions.size()), static_cast<py::ssize_t>(n)});
  double* data = out.mutable_data();
  for (const Eigen::VectorXd& q : solutions) {
    Eigen::Map<Eigen::VectorXd>(data, n) = q;
    data += n;
  }
  return out;
}

// Whether an IK call is long enough to hand the interpreter lock to other threads meanwhile
// (interpreter_lock.hpp): the closed forms without 2π copies take a few µs; the offset-wrist
// search, the numeric fallback and the copies take tens of µs to seconds.
bool long_inverse(const SerialArm& arm, const InverseOptions& options) {
  const serial::IkFamily f = arm.family();
  const bool one_closed_form = (f == serial::IkFamily::spherical_wrist || f == serial::IkFamily::three_parallel) ||
                               (f == serial::IkFamily::locked_joint && (options.redundancy || options.q_ref));
  return options.offer_equivalents || !one_closed_form;
}

InverseResult solve(const SerialArm& arm, const Posed& pose, const InverseOptions& options) {
  if (!long_inverse(arm, options)) return arm.inverse_solutions(pose, options);
  py::gil_scoped_release unlocked;
  return arm.inverse_solutions(pose, options);
}

// A joint vector: shape (n,); its length is checked by the C++ call, which knows n.
Eigen::VectorXd joint_vector(const py::handle& obj, const std::string& name) {
  const std::string expected = "an array of shape (n,)";
  const Array a = as_array(obj, name, expected);
  if (a.ndim() != 1) wrong_shape(name, expected, a);
  return Eigen::Map<const Eigen::VectorXd>(a.data(), a.shape(0));
}

py::array_t<double> to_vector_array(const Eigen::VectorXd& v) {
  py::array_t<double> out(py::ssize_t{v.size()});
  Eigen::Map<Eigen::VectorXd>(out.mutable_data(), v.size()) = v;
  return out;
}

py::list to_list(const std::vector<Eigen::VectorXd>& solutions) {
  py::list out;
  for (const Eigen::VectorXd& q : solutions) out.append(to_vector_array(q));
  return out;
}

std::vector<Eigen::VectorXd> joint_vectors(const py::handle& obj, const std::string& name) {
  std::vector<Eigen::VectorXd> out;
  if (py::isinstance<py::array>(obj)) {
    const Array a = as_array(obj, name, "an array of shape (N, n)");
    if (a.ndim() != 2) wrong_shape(name, "an array of shape (N, n) or a list of (n,) arrays", a);
    for (py::ssize_t i = 0; i < a.shape(0); ++i)
      out.push_back(Eigen::Map<const Eigen::VectorXd>(a.data() + i * a.shape(1), a.shape(1)));
    return out;
  }
  if (!py::isinstance<py::sequence>(obj)) throw py::value_error(name + ": expected a list of (n,) arrays");
  std::size_t k = 0;
  for (const py::handle item : obj.cast<py::sequence>())
    out.push_back(joint_vector(item, name + "[" + std::to_string(k++) + "]"));
  return out;
}

// The redundancy parameter value and q_ref of inverse() (None: not given).
void choose_redundancy(InverseOptions& o, const py::object& redundancy, const py::object& q_ref) {
  if (!redundancy.is_none()) {
    if (!py::isinstance<py::float_>(redundancy) && !py::isinstance<py::int_>(redundancy) &&
        !py::hasattr(redundancy, "__float__"))
      throw py::type_error("redundancy: expected a number (rad), got " +
                           std::string(py::str(py::type::of(redundancy))));
    o.redundancy = py::float_(redundancy).cast<double>();
  }
  if (!q_ref.is_none()) o.q_ref = joint_vector(q_ref, "q_ref");
}

InverseOptions options_of(bool keep_outside_limits, bool offer_equivalents, int max_attempts, double time_budget,
                          unsigned seed) {
  InverseOptions o;
  o.keep_outside_limits = keep_outside_limits;
  o.offer_equivalents = offer_equivalents;
  o.max_attempts = max_attempts;
  o.time_budget = time_budget;
  o.seed = seed;
  return o;
}

// A (N, columns) array as its rows.
Array rows_of(const py::handle& obj, const std::string& name, py::ssize_t columns) {
  const std::string expected = "an array of shape (N, " + std::to_string(columns) + ")";
  Array a = as_array(obj, name, expected);
  if (a.ndim() != 2 || a.shape(1) != columns) wrong_shape(name, expected, a);
  return a;
}

std::vector<double> times_of(const py::handle& obj, const std::string& name) {
  const Array a = as_array(obj, name, "an array of shape (N,)");
  if (a.ndim() != 1) wrong_shape(name, "an array of shape (N,)", a);
  return std::vector<double>(a.data(), a.data() + a.shape(0));
}

py::array_t<double> to_rows(const Eigen::MatrixXd& m) {
  py::array_t<double> out({static_cast<py::ssize_t>(m.rows()), static_cast<py::ssize_t>(m.cols())});
  Eigen::Map<Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>(out.mutable_data(), m.rows(),
                                                                                     m.cols()) = m;
  return out;
}

// from_urdf: text that starts with '<' (after blanks) is the XML itself, anything else a path.
SerialArm from_urdf(const std::string& path_or_string, const std::string& base_link, const std::string& tip_link) {
  const auto first = path_or_string.find_first_not_of(" \t\r\n");
  if (first != std::string::npos && path_or_string[first] == '<')
    return SerialArm::from_urdf_string(path_or_string, base_link, tip_link);
  return SerialArm::from_urdf_file(path_or_string, base_link, tip_link);
}

constexpr const char* family_names =
    "must be 'spherical_wrist', 'three_parallel', 'offset_wrist', 'general' or 'locked_joint'";

serial::IkFamily family_named(const std::string& name) {
  using serial::IkFamily;
  for (IkFamily f : {IkFamily::spherical_wrist, IkFamily::three_parallel, IkFamily::offset_wrist, IkFamily::general,
                     IkFamily::locked_joint})
    if (serial::to_string(f) == name) return f;
  throw std::invalid_argument(describe("family", name, family_names));
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

InverseResult inverse_result_from_state(const py::object& state) {
  const py::tuple s = state_tuple(state, 4, "InverseResult");
  const auto field = [](std::size_t k, const char* name) { return StateField("InverseResult", k, name); };
  InverseResult r;
  r.solutions = [&] {
    std::vector<Eigen::VectorXd> out;
    const py::sequence items = state_sequence(s[0], field(0, "solutions"));
    for (std::size_t k = 0; k < items.size(); ++k)
      out.push_back(state_vector<Eigen::Dynamic>(items[k], field(0, "solutions").at(k)));
    return out;
  }();
  r.within_limits = state_cast<std::vector<bool>>(s[1], field(1, "within_limits"));
  r.complete = state_cast<bool>(s[2], field(2, "complete"));
  const StateField family_at = field(3, "family");
  const std::string family = state_cast<std::string>(s[3], family_at);
  try {
    r.family = family_named(family);
  } catch (const std::invalid_argument&) {
    throw py::value_error(family_at.message(s[3], family_names));
  }
  // One flag per solution, every solution of one size and finite (a joint vector).
  require(r.within_limits.size() == r.solutions.size(), "within_limits size",
          static_cast<unsigned long>(r.within_limits.size()),
          "must be the number of solutions, " + std::to_string(r.solutions.size()));
  for (std::size_t k = 0; k < r.solutions.size(); ++k) {
    const std::string name = "solutions[" + std::to_string(k) + "]";
    require(r.solutions[k].size() == r.solutions.front().size(), name + " size",
            static_cast<long>(r.solutions[k].size()),
            "must be the size of solutions[0], " + std::to_string(r.solutions.front().size()));
    require_finite(r.solutions[k], name);
  }
  return r;
}

std::string inverse_result_repr(const InverseResult& r) {
  std::size_t inside = 0;
  for (bool b : r.within_limits) inside += b ? 1 : 0;
  return "InverseResult(solutions=" + std::to_string(r.solutions.size()) + ", within_limits=" + std::to_string(inside) +
         ", complete=" + (r.complete ? "True" : "False") + ", family='" + serial::to_string(r.family) + "')";
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

}  // namespace

void bind_serial(py::module_& m) {
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

  py::class_<InverseResult> inverse_result(m, "InverseResult", "What SerialArm.inverse_solutions found.");
  inverse_result
      .def_property_readonly(
          "solutions", [](const InverseResult& r) { return to_list(r.solutions); },
          "list of (n,) joint vectors, each reproducing the pose to 1e-10")
      .def_readonly("within_limits", &InverseResult::within_limits,
                    "per solution: inside the position limits (all True unless keep_outside_limits)")
      .def_readonly(
          "complete", &InverseResult::complete,
          "True: every solution (analytic family; a seven-joint arm: every one at the redundancy value asked for); "
          "False: what the numeric search found, or a seven-joint arm's solutions at the default values")
      .def_property_readonly(
          "family", [](const InverseResult& r) { return serial::to_string(r.family); },
          "the method used: 'spherical_wrist', 'three_parallel', 'offset_wrist', 'general' or "
          "'locked_joint'")
      .def("__repr__", &inverse_result_repr);
  def_pickle(
      inverse_result, "InverseResult",
      [](const InverseResult& r) {
        return py::make_tuple(to_list(r.solutions), py::cast(r.within_limits), r.complete, serial::to_string(r.family));
      },
      &inverse_result_from_state);

  py::class_<serial::Redundancy>(m, "Redundancy",
                                 "The redundancy parameter of a seven-joint arm (SerialArm.redundancy): a locked joint "
                                 "whose every value leaves a 6R closed form (doc/inverse-kinematics.md section 11).")
      .def_readonly("kind", &serial::Redundancy::kind, "'locked_joint', or 'none' (no parameter)")
      .def_readonly("joint", &serial::Redundancy::joint, "index in q of the locked joint (-1: none)")
      .def_readonly("joint_name", &serial::Redundancy::joint_name, "its URDF name ('' if none)")
      .def_readonly("lower", &serial::Redundancy::lower, "lower end of the parameter's range (rad)")
      .def_readonly("upper", &serial::Redundancy::upper, "upper end of the parameter's range (rad)")
      .def_property_readonly("default_values", &serial::Redundancy::default_values,
                             "the values SerialArm.inverse solves at when given neither redundancy nor q_ref: the "
                             "centres of 16 equal parts of [lower, upper]")
      .def(
          "value", [](const serial::Redundancy& r, const py::object& q) { return r.value(joint_vector(q, "q")); },
          py::arg("q"), "the parameter value of the joint vector q (q[joint]); ValueError when there is none")
      .def("__repr__", [](const serial::Redundancy& r) {
        if (!r.has_parameter()) return std::string("Redundancy(kind='none')");
        return "Redundancy(kind='" + r.kind + "', joint=" + std::to_string(r.joint) + ", joint_name='" + r.joint_name +
               "', lower=" + py::repr(py::float_(r.lower)).cast<std::string>() +
               ", upper=" + py::repr(py::float_(r.upper)).cast<std::string>() + ")";
      });

  py::class_<SerialArm> serial_arm(m, "SerialArm", R"doc(
A serial arm of revolute joints between two links of a URDF (urdfdom into an Orocos KDL chain).
Fixed joints are folded in, continuous joints have infinite position limits, prismatic, planar
and floating joints on the path are refused. Units: metres, radians, seconds, kilograms, N m.)doc");
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
      .def(
          "inverse",
          [](const SerialArm& a, const py::handle& pose, bool equivalents, const py::object& redundancy,
             const py::object& q_ref, bool wide_search) {
            InverseOptions options;
            options.offer_equivalents = equivalents;
            options.wide_search = wide_search;
            choose_redundancy(options, redundancy, q_ref);
            return solution_rows(solve(a, pose_of(pose, "pose"), options).solutions, a.dof());
          },
          py::arg("pose"), py::arg("offer_equivalents") = false, py::kw_only(), py::arg("redundancy") = py::none(),
          py::arg("q_ref") = py::none(), py::arg("wide_search") = false,
          "The distinct joint vectors inside the limits whose forward() is `pose` (a Pose or (4, 4)) to 1e-10, "
          "as the rows of a (k, n) array, one per solution, each angle the 2pi-equivalent nearest to 0 inside "
          "the limits; with offer_equivalents=True also their 2pi copies inside the limits (at most 10000, else "
          "ValueError); (0, n) when unreachable. A redundant arm with a parameter (arm.redundancy): every "
          "solution at redundancy=value, or at q_ref's value with q_ref=q (nearest to q_ref first; on any arm "
          "q_ref orders the solutions so), or with neither at each of arm.redundancy.default_values. An arm of "
          "family 'general' given q_ref: Newton's method from q_ref first, its solution alone when it converges "
          "inside the limits; wide_search=True adds the search from random starts.")
      .def(
          "inverse_many",
          [](const SerialArm& a, const py::handle& poses, bool equivalents) {
            std::vector<Posed> targets = poses_of(poses);
            InverseOptions options;
            options.offer_equivalents = equivalents;
            std::vector<std::vector<Eigen::VectorXd>> found(targets.size());
            {
              py::gil_scoped_release unlocked;
              for (std::size_t i = 0; i < targets.size(); ++i)
                found[i] = a.inverse_solutions(targets[i], options).solutions;
            }
            py::list out(found.size());
            for (std::size_t i = 0; i < found.size(); ++i) out[i] = solution_rows(found[i], a.dof());
            return out;
          },
          py::arg("poses"), py::arg("offer_equivalents") = false,
          "inverse() of every pose of an (N, 4, 4) array or a sequence of Poses: a list of N arrays, the i-th the "
          "(k_i, n) array inverse(poses[i]) gives. The interpreter lock is released for the whole batch. "
          "ValueError naming poses[i] for a pose that is not finite or not rigid.")
      .def(
          "inverse_solutions",
          [](const SerialArm& a, const py::handle& pose, bool keep, bool equivalents, int attempts, double budget,
             unsigned seed, const py::object& redundancy, const py::object& q_ref, bool wide_search) {
            InverseOptions options = options_of(keep, equivalents, attempts, budget, seed);
            options.wide_search = wide_search;
            choose_redundancy(options, redundancy, q_ref);
            return solve(a, pose_of(pose, "pose"), options);
          },
          py::arg("pose"), py::arg("keep_outside_limits") = false, py::arg("offer_equivalents") = false,
          py::arg("max_attempts") = 64, py::arg("time_budget") = 0.05, py::arg("seed") = 1u, py::kw_only(),
          py::arg("redundancy") = py::none(), py::arg("q_ref") = py::none(), py::arg("wide_search") = false,
          "inverse() with options and a report (InverseResult): solutions outside the limits kept and flagged, "
          "2pi copies on request (at most 10000, else ValueError); for the numeric fallback the restarts, time budget "
          "(s, "
          "bounding the search's time) and seed.")
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
          "(w - p1).(w2 x w1), w3.((p3 - p2) x (w - p3)), w5.(w4 x w6); see serial_arm.hpp).")
      .def_static(
          "nearest",
          [](const py::object& solutions, const py::object& q_ref) {
            return to_vector_array(
                serial::nearest(joint_vectors(solutions, "solutions"), joint_vector(q_ref, "q_ref")));
          },
          py::arg("solutions"), py::arg("q_ref"), "The solution closest to q_ref (Euclidean, no wrapping).")
      .def(
          "follow",
          [](const SerialArm& a, const std::vector<Posed>& poses, const py::object& q_start, bool move_redundancy,
             double gain, double max_rate, double singularity_weight) {
            const Eigen::VectorXd start = joint_vector(q_start, "q_start");
            serial::RedundancyRule rule;
            rule.move = move_redundancy;
            rule.gain = gain;
            rule.max_rate = max_rate;
            rule.singularity_weight = singularity_weight;
            std::vector<Eigen::VectorXd> path;
            {
              py::gil_scoped_release unlocked;
              path = serial::follow(a, poses, start, {}, rule);
            }
            py::array_t<double> out({static_cast<py::ssize_t>(path.size()), static_cast<py::ssize_t>(a.dof())});
            for (std::size_t k = 0; k < path.size(); ++k)
              Eigen::Map<Eigen::VectorXd>(out.mutable_data() + k * static_cast<std::size_t>(a.dof()), a.dof()) =
                  path[k];
            return out;
          },
          py::arg("poses"), py::arg("q_start"), py::kw_only(),
          py::arg("move_redundancy") = serial::RedundancyRule{}.move, py::arg("gain") = serial::RedundancyRule{}.gain,
          py::arg("max_rate") = serial::RedundancyRule{}.max_rate,
          py::arg("singularity_weight") = serial::RedundancyRule{}.singularity_weight,
          "(N, n) joint path: for each pose the solution nearest to the previous one, from q_start. "
          "RuntimeError naming the first pose without a solution. A seven-joint arm with a redundancy parameter "
          "starts at q_start's value and, with move_redundancy, moves it away from joint limits and singular poses "
          "by at most max_rate rad per radian the other joints travel (doc/inverse-kinematics.md eq. 45); no joint "
          "steps more than 0.3 rad from one pose to the next (RuntimeError naming the pose instead).")
      .def(
          "joint_velocities",
          [](const SerialArm& a, const py::object& q, const py::object& body_twists) {
            const Array qs = rows_of(q, "q", a.dof());
            const Array twists = rows_of(body_twists, "body_twists", 6);
            if (twists.shape(0) != qs.shape(0))
              throw py::value_error("body_twists: expected " + std::to_string(qs.shape(0)) + " rows like q, got " +
                                    std::to_string(twists.shape(0)));
            using Rows = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
            const Rows q_rows = Eigen::Map<const Rows>(qs.data(), qs.shape(0), a.dof());
            const Rows twist_rows = Eigen::Map<const Rows>(twists.data(), twists.shape(0), 6);
            Eigen::MatrixXd out(qs.shape(0), a.dof());
            {
              py::gil_scoped_release unlocked;
              for (Eigen::Index k = 0; k < q_rows.rows(); ++k) {
                const Twistd xi(Eigen::Matrix<double, 6, 1>(twist_rows.row(k).transpose()));
                out.row(k) = serial::joint_velocity(a, q_rows.row(k).transpose(), xi).transpose();
              }
            }
            return to_rows(out);
          },
          py::arg("q"), py::arg("body_twists"),
          "(N, n) joint velocities: row k solves body_jacobian(q[k]) qd = body_twists[k] ((N, n) and (N, 6) "
          "arrays) in the least-squares sense, minimum norm (exact for a 6-joint arm away from singularities).")
      .def(
          "follow_trajectory",
          [](const SerialArm& a, const Trajectory& trajectory, const py::object& times, const py::object& q_start,
             double difference_step) {
            const Eigen::VectorXd start = joint_vector(q_start, "q_start");
            const std::vector<double> at = times_of(times, "times");
            FollowedJoints j;
            {
              py::gil_scoped_release unlocked;
              j = follow_joints(trajectory, a, start, at, difference_step);
            }
            return py::make_tuple(to_rows(j.q), to_rows(j.qd), to_rows(j.qdd));
          },
          py::arg("trajectory"), py::arg("times"), py::arg("q_start"), py::arg("difference_step") = 1e-4,
          "(q, qd, qdd), each (N, n), of the arm following a Cartesian trajectory at `times` (s): q by follow() "
          "from q_start, qd by joint_velocities() of the trajectory's body twist, qdd by central differences of "
          "qd over +-difference_step (one-sided at the ends), each neighbour followed from the sample's q.")
      .def(
          "check_joint_limits",
          [](const SerialArm& a, const py::object& trajectory, const py::object& times) {
            const JointTrajectory& move = trajectory.cast<const JointTrajectory&>();
            const std::vector<double> at = times_of(times, "times");
            const SerialArm arm = a;  // its gravity as now, whatever another thread sets meanwhile
            JointLimitReport report;
            {
              py::gil_scoped_release unlocked;
              report = check_joint_limits(move, arm, at);
            }
            return py::cast(std::move(report));  // py::object: JointLimitReport is bound after SerialArm
          },
          py::arg("trajectory"), py::arg("times"),
          "JointLimitReport of a PTP move (JointTrajectory) at `times` (s): the factors FVEL and FACC of its "
          "joint line's own q, qd, qdd. RuntimeError where the static torque alone reaches an effort limit.")
      .def_property_readonly("urdf", &SerialArm::urdf, "the URDF text the arm was read from")
      .def("__repr__", [](const SerialArm& a) {
        return "SerialArm(robot='" + a.robot_name() + "', base_link='" + a.base_link() + "', tip_link='" +
               a.tip_link() + "', dof=" + std::to_string(a.dof()) + ", family='" + serial::to_string(a.family()) + "')";
      });
  def_pickle(serial_arm, "SerialArm", &arm_state, &arm_from_state);
}

}  // namespace python
}  // namespace dispkin
