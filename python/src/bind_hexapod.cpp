// Python binding of dispkin/hexapod/hexapod.hpp: Hexapod, WorkspaceCheck, LegViolation,
// xyzuvw_for_new_pivot. Joints are (6, 3) arrays (one joint per row), legs (6,) arrays.
#include <string>
#include <vector>

#include <pybind11/eigen.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "bindings.hpp"
#include "conversions.hpp"
#include "interpreter_lock.hpp"
#include "value_protocol.hpp"
#include "dispkin/hexapod/hexapod.hpp"
#include "dispkin/planning/planner.hpp"

namespace dispkin {
namespace python {

namespace {

using hexapod::Hexapod;
using hexapod::LegExcursion;
using hexapod::LegViolation;
using hexapod::TrajectoryCheck;
using hexapod::WorkspaceCheck;
using hexapod::xyzuvw_for_new_pivot;
using Legs = Hexapod::Legs;
using Vector6d = Eigen::Matrix<double, 6, 1>;

Hexapod::Joints joints(const py::handle& obj, const std::string& name) {
  const std::string expected = "an array of shape (6, 3)";
  const Array a = as_array(obj, name, expected);
  if (a.ndim() != 2 || a.shape(0) != 6 || a.shape(1) != 3) wrong_shape(name, expected, a);
  return Eigen::Map<const Eigen::Matrix<double, 3, 6>>(a.data());  // row-major (6, 3) = column-major (3, 6)
}

py::array_t<double> joints_array(const Hexapod::Joints& j) {
  py::array_t<double> out({py::ssize_t{6}, py::ssize_t{3}});
  Eigen::Map<Eigen::Matrix<double, 3, 6>>(out.mutable_data()) = j;
  return out;
}

// A number for all six legs, or one per leg.
Legs legs(const py::handle& obj, const std::string& name) {
  const std::string expected = "a number or an array of shape (6,)";
  const Array a = as_array(obj, name, expected);
  if (a.ndim() == 0) return Legs::Constant(*a.data());
  if (a.ndim() != 1 || a.shape(0) != 6) wrong_shape(name, expected, a);
  return Eigen::Map<const Legs>(a.data());
}

py::array_t<double> legs_array(const Legs& l) {
  py::array_t<double> out(py::ssize_t{6});
  Eigen::Map<Legs>(out.mutable_data()) = l;
  return out;
}

// A Pose or a (4, 4) matrix.
Posed pose_of(const py::handle& obj, const std::string& name) {
  if (py::isinstance<Posed>(obj)) return obj.cast<Posed>();
  return Posed::from_matrix(matrix4(obj, name));
}

// inverse(): a Pose or (4, 4) → (6,); a sequence of poses or (N, 4, 4) → (N, 6).
py::array_t<double> inverse(const Hexapod& h, const py::object& poses) {
  if (py::isinstance<Posed>(poses)) return legs_array(h.leg_lengths(poses.cast<Posed>()));
  std::vector<Posed> list;
  if (py::isinstance<py::array>(poses) || !py::isinstance<py::sequence>(poses)) {
    const std::string expected = "a Pose, a sequence of Poses, or an array of shape (4, 4) or (N, 4, 4)";
    const Array a = as_array(poses, "pose", expected);
    if (a.ndim() == 2) return legs_array(h.leg_lengths(pose_of(a, "pose")));
    if (a.ndim() != 3 || a.shape(1) != 4 || a.shape(2) != 4) wrong_shape("pose", expected, a);
    for (py::ssize_t i = 0; i < a.shape(0); ++i) {
      const Eigen::Matrix4d m = Eigen::Map<const Eigen::Matrix<double, 4, 4, Eigen::RowMajor>>(a.data() + 16 * i);
      list.push_back(Posed::from_matrix(m));
    }
  } else {
    const py::sequence seq = poses.cast<py::sequence>();
    for (std::size_t i = 0; i < seq.size(); ++i) list.push_back(pose_of(seq[i], "pose[" + std::to_string(i) + "]"));
  }
  py::array_t<double> out({static_cast<py::ssize_t>(list.size()), py::ssize_t{6}});
  double* data = out.mutable_data();
  {
    const UnlockedIf unlocked(worth_releasing(list.size(), leg_lengths_ns));
    for (std::size_t i = 0; i < list.size(); ++i) Eigen::Map<Legs>(data + 6 * i) = h.leg_lengths(list[i]);
  }
  return out;
}

// inverse_xyzuvw(): (6,) → (6,), (N, 6) → (N, 6).
py::array_t<double> inverse_xyzuvw(const Hexapod& h, const py::object& xyzuvw, const py::object& pivot) {
  const Eigen::Vector3d p = vector3(pivot, "pivot");
  const std::string expected = "an array of shape (6,) or (N, 6)";
  const Array a = as_array(xyzuvw, "xyzuvw", expected);
  if (a.ndim() == 1 && a.shape(0) == 6)
    return legs_array(h.leg_lengths(Vector6d(Eigen::Map<const Vector6d>(a.data())), p));
  if (a.ndim() != 2 || a.shape(1) != 6) wrong_shape("xyzuvw", expected, a);
  py::array_t<double> out({a.shape(0), py::ssize_t{6}});
  double* data = out.mutable_data();
  const double* given = a.data();
  {
    const UnlockedIf unlocked(worth_releasing(static_cast<std::size_t>(a.shape(0)), leg_lengths_ns));
    for (py::ssize_t i = 0; i < a.shape(0); ++i)
      Eigen::Map<Legs>(data + 6 * i) = h.leg_lengths(Vector6d(Eigen::Map<const Vector6d>(given + 6 * i)), p);
  }
  return out;
}

// Pickled states of the check results: their fields, in declaration order.
py::tuple violation_state(const LegViolation& v) { return py::make_tuple(v.leg, v.length, v.lower, v.upper, v.excess); }

// The checks' results are checked like what Hexapod::check makes (require_consistent): a stored
// one is read field by field, then checked whole.
template <typename Field>
LegViolation violation_of(const py::tuple& s, Field field) {
  return LegViolation{state_cast<int>(s[0], field(0, "leg")), state_cast<double>(s[1], field(1, "length")),
                      state_cast<double>(s[2], field(2, "lower")), state_cast<double>(s[3], field(3, "upper")),
                      state_cast<double>(s[4], field(4, "excess"))};
}

LegViolation violation_from_state(const py::object& state) {
  const LegViolation v = violation_of(state_tuple(state, 5, "LegViolation"), [](std::size_t k, const char* name) {
    return StateField("LegViolation", k, name);
  });
  require_consistent(v);
  return v;
}

const char* kind_name(const LegExcursion& e) { return e.kind == LegExcursion::Kind::length ? "length" : "speed"; }

py::tuple excursion_state(const LegExcursion& e) {
  return py::make_tuple(kind_name(e), e.leg, e.start_time, e.end_time, e.worst_time, e.worst_value, e.excess);
}

template <typename Field>
LegExcursion excursion_of(const py::tuple& s, Field field) {
  const StateField kind_at = field(0, "kind");
  const std::string kind = state_cast<std::string>(s[0], kind_at);
  if (kind != "length" && kind != "speed") throw py::value_error(kind_at.message(s[0], "must be 'length' or 'speed'"));
  return LegExcursion{kind == "length" ? LegExcursion::Kind::length : LegExcursion::Kind::speed,
                      state_cast<int>(s[1], field(1, "leg")),
                      state_cast<double>(s[2], field(2, "start_time")),
                      state_cast<double>(s[3], field(3, "end_time")),
                      state_cast<double>(s[4], field(4, "worst_time")),
                      state_cast<double>(s[5], field(5, "worst_value")),
                      state_cast<double>(s[6], field(6, "excess"))};
}

LegExcursion excursion_from_state(const py::object& state) {
  const LegExcursion e = excursion_of(state_tuple(state, 7, "LegExcursion"), [](std::size_t k, const char* name) {
    return StateField("LegExcursion", k, name);
  });
  require_consistent(e);
  return e;
}

// The items of a list field, each the state of a T (`of` reads its fields).
template <typename T, typename Of>
std::vector<T> nested_items(const py::handle& obj, const StateField& where, std::size_t size, Of of) {
  std::vector<T> out;
  const py::sequence items = state_sequence(obj, where);
  for (std::size_t k = 0; k < items.size(); ++k) {
    const StateField at = where.at(k);
    // A LegViolation / LegExcursion object as stored by pickle, or its state tuple.
    if (py::isinstance<T>(items[k])) {
      out.push_back(state_cast<T>(items[k], at));
      continue;
    }
    const py::tuple s = state_fields(items[k], size, at);
    out.push_back(of(s, [&](std::size_t, const char* name) { return at / ("." + std::string(name)); }));
  }
  return out;
}

WorkspaceCheck workspace_check_from_state(const py::object& state) {
  const py::tuple s = state_tuple(state, 2, "WorkspaceCheck");
  const WorkspaceCheck c{
      state_vector<6>(s[0], StateField("WorkspaceCheck", 0, "lengths")),
      nested_items<LegViolation>(s[1], StateField("WorkspaceCheck", 1, "violations"), 5,
                                 [](const py::tuple& v, auto field) { return violation_of(v, field); })};
  require_consistent(c);
  return c;
}

TrajectoryCheck trajectory_check_from_state(const py::object& state) {
  const py::tuple s = state_tuple(state, 4, "TrajectoryCheck");
  const auto field = [](std::size_t k, const char* name) { return StateField("TrajectoryCheck", k, name); };
  const TrajectoryCheck c{state_vector<6>(s[0], field(0, "min_length")), state_vector<6>(s[1], field(1, "max_length")),
                          state_vector<6>(s[2], field(2, "max_speed")),
                          nested_items<LegExcursion>(s[3], field(3, "excursions"), 7,
                                                     [](const py::tuple& e, auto f) { return excursion_of(e, f); })};
  require_consistent(c);
  return c;
}

std::string workspace_check_repr(const WorkspaceCheck& c) {
  std::string legs;
  for (const LegViolation& v : c.violations) legs += (legs.empty() ? "" : ", ") + std::to_string(v.leg);
  return "WorkspaceCheck(reachable=" + std::string(c.reachable() ? "True" : "False") +
         ", lengths=" + tuple_repr(c.lengths) + ", legs_out_of_range=[" + legs + "])";
}

std::string trajectory_check_repr(const TrajectoryCheck& c) {
  return "TrajectoryCheck(ok=" + std::string(c.ok() ? "True" : "False") + ", min_length=" + tuple_repr(c.min_length) +
         ", max_length=" + tuple_repr(c.max_length) + ", max_speed=" + tuple_repr(c.max_speed) +
         ", excursions=" + std::to_string(c.excursions.size()) + ")";
}

void bind_leg_violation(py::module_& m) {
  py::class_<LegViolation> violation(m, "LegViolation", "A leg out of its length range (Hexapod.check).");
  violation.def_readonly("leg", &LegViolation::leg, "0-based leg index")
      .def_readonly("length", &LegViolation::length, "the leg's length at the pose (m)")
      .def_readonly("lower", &LegViolation::lower, "the leg's shortest length (m)")
      .def_readonly("upper", &LegViolation::upper, "the leg's longest length (m)")
      .def_readonly("excess", &LegViolation::excess, "how far outside the range (m), > 0")
      .def("__repr__", [](const LegViolation& v) {
        return "LegViolation(leg=" + std::to_string(v.leg) + ", length=" + float_repr(v.length) +
               ", lower=" + float_repr(v.lower) + ", upper=" + float_repr(v.upper) +
               ", excess=" + float_repr(v.excess) + ")";
      });
  def_pickle(violation, "LegViolation", &violation_state, &violation_from_state);
}

void bind_workspace_check(py::module_& m) {
  py::class_<WorkspaceCheck> workspace_check(m, "WorkspaceCheck",
                                             "Leg lengths at a pose and the legs out of range (Hexapod.check).");
  workspace_check
      .def_property_readonly(
          "lengths", [](const WorkspaceCheck& c) { return legs_array(c.lengths); }, "(6,) leg lengths (m)")
      .def_readonly("violations", &WorkspaceCheck::violations, "list of LegViolation, empty when reachable")
      .def_property_readonly("reachable", &WorkspaceCheck::reachable, "True when every leg is within its range")
      .def("__bool__", &WorkspaceCheck::reachable)
      .def("__repr__", &workspace_check_repr);
  def_pickle(
      workspace_check, "WorkspaceCheck",
      [](const WorkspaceCheck& c) { return py::make_tuple(legs_array(c.lengths), c.violations); },
      &workspace_check_from_state);
}

void bind_leg_excursion(py::module_& m) {
  py::class_<LegExcursion> excursion(m, "LegExcursion",
                                     "A stretch of a trajectory where a leg leaves its range or exceeds its speed.");
  excursion
      .def_property_readonly(
          "kind", [](const LegExcursion& e) { return e.kind == LegExcursion::Kind::length ? "length" : "speed"; },
          "'length' or 'speed'")
      .def_readonly("leg", &LegExcursion::leg, "0-based leg index")
      .def_readonly("start_time", &LegExcursion::start_time, "first sample out of range (s)")
      .def_readonly("end_time", &LegExcursion::end_time, "last sample out of range (s)")
      .def_readonly("worst_time", &LegExcursion::worst_time, "the sample with the largest excess (s)")
      .def_readonly("worst_value", &LegExcursion::worst_value, "the leg's length (m) or speed (m/s) there")
      .def_readonly("excess", &LegExcursion::excess, "how far beyond the range or limit, > 0")
      .def("__repr__", [](const LegExcursion& e) {
        return std::string("LegExcursion(kind='") + kind_name(e) + "', leg=" + std::to_string(e.leg) +
               ", start_time=" + float_repr(e.start_time) + ", end_time=" + float_repr(e.end_time) +
               ", excess=" + float_repr(e.excess) + ")";
      });
  def_pickle(excursion, "LegExcursion", &excursion_state, &excursion_from_state);
}

void bind_trajectory_check(py::module_& m) {
  py::class_<TrajectoryCheck> trajectory_check(
      m, "TrajectoryCheck", "Leg extremes along a trajectory and every excursion (Hexapod.check_trajectory).");
  trajectory_check
      .def_property_readonly(
          "min_length", [](const TrajectoryCheck& c) { return legs_array(c.min_length); }, "(6,) m")
      .def_property_readonly(
          "max_length", [](const TrajectoryCheck& c) { return legs_array(c.max_length); }, "(6,) m")
      .def_property_readonly(
          "max_speed", [](const TrajectoryCheck& c) { return legs_array(c.max_speed); }, "(6,) m/s")
      .def_readonly("excursions", &TrajectoryCheck::excursions, "list of LegExcursion, empty when ok")
      .def_property_readonly("ok", &TrajectoryCheck::ok, "True when no leg leaves its range or exceeds its speed")
      .def("__bool__", &TrajectoryCheck::ok)
      .def("__repr__", &trajectory_check_repr);
  def_pickle(
      trajectory_check, "TrajectoryCheck",
      [](const TrajectoryCheck& c) {
        return py::make_tuple(legs_array(c.min_length), legs_array(c.max_length), legs_array(c.max_speed),
                              c.excursions);
      },
      &trajectory_check_from_state);
}

// A hexapod as described: its joints, leg ranges and speeds, home pose; the JSON description.
void def_hexapod_description(py::class_<Hexapod>& hexapod) {
  hexapod
      .def(py::init([](const py::object& base, const py::object& platform, const py::object& lo, const py::object& hi,
                       const py::object& speed, const py::object& home) {
             return Hexapod(joints(base, "base_joints"), joints(platform, "platform_joints"), legs(lo, "leg_min"),
                            legs(hi, "leg_max"), legs(speed, "leg_speed"),
                            home.is_none() ? Posed() : pose_of(home, "home"));
           }),
           py::arg("base_joints"), py::arg("platform_joints"), py::arg("leg_min"), py::arg("leg_max"),
           py::arg("leg_speed"), py::arg("home") = py::none(),
           "From any layout: (6, 3) base and platform joints, leg limits (a number or (6,) each), and the "
           "home pose forward() starts from (default identity).")
      .def_static("symmetric", &Hexapod::symmetric, py::arg("base_radius"), py::arg("base_gap"),
                  py::arg("platform_radius"), py::arg("platform_gap"), py::arg("height"), py::arg("leg_min"),
                  py::arg("leg_max"), py::arg("leg_speed"),
                  "The symmetric 6-6 layout (joints in pairs `gap` rad apart, base pairs at 0, 120, 240 deg, "
                  "platform pairs at 60, 180, 300 deg); platform_gap = 0 gives 6-3. Home: `height` above the base.")
      .def_static("load", &Hexapod::load, py::arg("path"), "Reads a JSON description written by save().")
      .def("save", &Hexapod::save, py::arg("path"), "Writes the JSON description.")
      .def_static("from_json", &Hexapod::from_json, py::arg("text"), "From the JSON description as text.")
      .def("to_json", &Hexapod::to_json, "The JSON description as text.")
      .def_property_readonly(
          "base_joints", [](const Hexapod& h) { return joints_array(h.base_joints()); },
          "(6, 3) base joints, base coordinates (m)")
      .def_property_readonly(
          "platform_joints", [](const Hexapod& h) { return joints_array(h.platform_joints()); },
          "(6, 3) platform joints, platform coordinates (m)")
      .def_property_readonly(
          "leg_min", [](const Hexapod& h) { return legs_array(h.leg_min()); }, "(6,) shortest leg lengths (m)")
      .def_property_readonly(
          "leg_max", [](const Hexapod& h) { return legs_array(h.leg_max()); }, "(6,) longest leg lengths (m)")
      .def_property_readonly(
          "leg_speed", [](const Hexapod& h) { return legs_array(h.leg_speed()); }, "(6,) leg speed limits (m/s)")
      .def_property_readonly("home", &Hexapod::home, "the pose forward() starts from by default")
      .def_property_readonly("dof", &Hexapod::dof, "6")
      .def_property_readonly("joint_names", &Hexapod::joint_names, "['leg1', ..., 'leg6']");
}

// Leg lengths of poses and back, the leg Jacobian, the workspace check of a pose.
void def_hexapod_kinematics(py::class_<Hexapod>& hexapod) {
  hexapod
      .def("inverse", &inverse, py::arg("pose"),
           "Leg lengths: a Pose or (4, 4) matrix -> (6,); a sequence of poses or (N, 4, 4) -> (N, 6).")
      .def("inverse_xyzuvw", &inverse_xyzuvw, py::arg("xyzuvw"),
           py::arg_v("pivot", py::make_tuple(0.0, 0.0, 0.0), "(0, 0, 0)"),
           "Leg lengths of XYZUVW about `pivot` (platform coordinates): (6,) -> (6,), (N, 6) -> (N, 6).")
      .def(
          "leg_jacobian",
          [](const Hexapod& h, const py::object& pose) {
            return Eigen::Matrix<double, 6, 6, Eigen::RowMajor>(h.leg_jacobian(pose_of(pose, "pose")));
          },
          py::arg("pose"), "(6, 6) d(legs)/d(body twist (v, w)) of T exp(twist).")
      .def(
          "forward",
          [](const Hexapod& h, const py::object& l, const py::object& guess) {
            const Legs target = vector<6>(l, "legs");
            const Posed start = guess.is_none() ? h.home() : pose_of(guess, "guess");
            py::gil_scoped_release unlocked;  // Newton's method from the guess
            return h.forward(target, start);
          },
          py::arg("legs"), py::arg("guess") = py::none(),
          "The pose with these leg lengths (Newton's method from `guess`, default home), to 1e-12 m. "
          "RuntimeError, with the iteration count and residual, when it does not converge or is singular.")
      .def(
          "check",
          [](const Hexapod& h, const Trajectory& trajectory, double dt) { return h.check_trajectory(trajectory, dt); },
          py::call_guard<py::gil_scoped_release>(), py::arg("trajectory"), py::arg("dt") = 1e-3,
          "For a planned Trajectory: leg lengths and leg speeds every `dt` seconds against the limits "
          "(a TrajectoryCheck with the margins and every excursion). Same as check_trajectory.")
      .def(
          "check", [](const Hexapod& h, const py::object& pose) { return h.check(pose_of(pose, "pose")); },
          py::arg("pose"), "Which legs are out of range at `pose`, and by how much.")
      .def(
          "require_reachable",
          [](const Hexapod& h, const py::object& pose) { h.require_reachable(pose_of(pose, "pose")); }, py::arg("pose"),
          "ValueError naming the first leg out of range.");
}

// Legs along planned trajectories: the check, the leg-speed rule (b) section lengths and bounds, the leg speed group
// (rule (a)).
void def_hexapod_leg_speed(py::class_<Hexapod>& hexapod) {
  hexapod
      .def("check_trajectory", &Hexapod::check_trajectory<Trajectory>, py::call_guard<py::gil_scoped_release>(),
           py::arg("trajectory"), py::arg("dt"),
           "Dense check every `dt` seconds: leg lengths and leg speeds (J times the body twist) against the limits.")
      .def(
          "leg_section_lengths",
          [](const Hexapod& h, const Path& path, double system_velocity, double tolerance) {
            std::vector<double> lengths;
            {
              const UnlockedIf unlocked(true, path);
              lengths = h.leg_section_lengths(path, system_velocity, tolerance);
            }
            return py::array_t<double>(static_cast<py::ssize_t>(lengths.size()), lengths.data());
          },
          py::arg("path"), py::arg("system_velocity"), py::arg("tolerance") = 1e-3,
          "Leg-speed rule (b), the joint-space metric: the minimum length of every section of `path` (m, (N,)) "
          "so that no leg exceeds its speed at path speed `system_velocity`: v_sys * max_i r_i / leg_speed_i.")
      .def(
          "leg_rate_bounds",
          [](const Hexapod& h, const Path& path, double tolerance) {
            py::array_t<double> out({static_cast<py::ssize_t>(path.size()), py::ssize_t{6}});
            double* data = out.mutable_data();
            {
              const UnlockedIf unlocked(true, path);
              for (std::size_t k = 0; k < path.size(); ++k)
                Eigen::Map<Legs>(data + 6 * k) = h.leg_rate_bounds(path.sections()[k], tolerance);
            }
            return out;
          },
          py::arg("path"), py::arg("tolerance") = 1e-3,
          "(N, 6) upper bounds r_i of max over tau of |d(leg i)/d(tau)| per section (m per unit of the section "
          "parameter), rigorous, within `tolerance` of the section's largest leg-speed demand.")
      .def(
          "add_leg_speed_group",
          [](const Hexapod& h, MetricSetd& set, int group) {
            require_not_read(&set, "Hexapod.add_leg_speed_group");
            h.add_leg_speed_group(set, group);
          },
          py::arg("metric_set"), py::arg("group"),
          "Adds the platform joints as relative points of `group`, speed limit = the smallest leg speed.");
}

void bind_hexapod_class(py::module_& m) {
  py::class_<Hexapod> hexapod(m, "Hexapod", R"doc(
A hexapod (Stewart platform): six legs between base joints b_i (base coordinates) and platform
joints p_i (platform coordinates). A platform pose T maps platform to base coordinates and
leg i has length |T p_i - b_i|. Lengths in metres, leg speeds in m/s.)doc");
  def_hexapod_description(hexapod);
  def_hexapod_kinematics(hexapod);
  def_hexapod_leg_speed(hexapod);
  hexapod.def("__repr__", [](const Hexapod& h) {
    return "Hexapod(leg_min=" + tuple_repr(h.leg_min()) + ", leg_max=" + tuple_repr(h.leg_max()) +
           ", leg_speed=" + tuple_repr(h.leg_speed()) + ")";
  });
  def_pickle(
      hexapod, "Hexapod", [](const Hexapod& h) { return py::make_tuple(h.to_json()); },
      [](const py::object& state) {
        return Hexapod::from_json(state_item<std::string>(state_tuple(state, 1, "Hexapod"), 0, "Hexapod", "json"));
      });
}

void bind_xyzuvw_for_new_pivot(py::module_& m) {
  m.def(
      "xyzuvw_for_new_pivot",
      [](const py::object& xyzuvw, const py::object& old_pivot, const py::object& new_pivot) {
        return Vector6d(xyzuvw_for_new_pivot(vector<6>(xyzuvw, "xyzuvw"), vector3(old_pivot, "old_pivot"),
                                             vector3(new_pivot, "new_pivot")));
      },
      py::arg("xyzuvw"), py::arg("old_pivot"), py::arg("new_pivot"),
      "The XYZUVW about `new_pivot` of the pose that is `xyzuvw` about `old_pivot` (same pose, same UVW).");
}

}  // namespace

void bind_hexapod(py::module_& m) {
  bind_leg_violation(m);
  bind_workspace_check(m);
  bind_leg_excursion(m);
  bind_trajectory_check(m);
  bind_hexapod_class(m);
  bind_xyzuvw_for_new_pivot(m);
}

}  // namespace python
}  // namespace dispkin
