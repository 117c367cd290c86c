// Python binding of SerialArm's inverse kinematics (dispkin/serial/serial_arm.hpp): InverseResult,
// Redundancy, and the methods inverse, inverse_many, inverse_solutions and nearest.
#include <optional>
#include <string>
#include <vector>

#include <pybind11/eigen.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "interpreter_lock.hpp"
#include "serial_arm_binding.hpp"
#include "value_protocol.hpp"

namespace dispkin {
namespace python {

namespace {

using serial::InverseOptions;
using serial::InverseResult;
using serial::SerialArm;

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

constexpr const char* family_names =
    "must be 'spherical_wrist', 'three_parallel', 'offset_wrist', 'general' or 'locked_joint'";

serial::IkFamily family_named(const std::string& name) {
  using serial::IkFamily;
  for (IkFamily f : {IkFamily::spherical_wrist, IkFamily::three_parallel, IkFamily::offset_wrist, IkFamily::general,
                     IkFamily::locked_joint})
    if (serial::to_string(f) == name) return f;
  throw std::invalid_argument(describe("family", name, family_names));
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

}  // namespace

void bind_inverse_result(py::module_& m) {
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
}

void def_inverse_kinematics(py::class_<SerialArm>& arm) {
  arm.def(
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
      .def_static(
          "nearest",
          [](const py::object& solutions, const py::object& q_ref) {
            return to_vector_array(
                serial::nearest(joint_vectors(solutions, "solutions"), joint_vector(q_ref, "q_ref")));
          },
          py::arg("solutions"), py::arg("q_ref"), "The solution closest to q_ref (Euclidean, no wrapping).");
}

}  // namespace python
}  // namespace dispkin
