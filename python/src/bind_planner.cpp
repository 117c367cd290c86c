// Python binding of dispkin/planning/planner.hpp: Limits, plan, Trajectory (with TrajectoryCursor for
// control loops), OverlappedTrajectory, MotionStream.
#include <array>
#include <optional>
#include <string>
#include <type_traits>
#include <vector>

#include <pybind11/eigen.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "bindings.hpp"
#include "conversions.hpp"
#include "interpreter_lock.hpp"
#include "path_state.hpp"
#include "value_protocol.hpp"
#include "dispkin/error.hpp"
#include "dispkin/hexapod/hexapod.hpp"
#include "dispkin/planning/motion_stream.hpp"
#include "dispkin/planning/overlap.hpp"
#include "dispkin/planning/planner.hpp"
#include "dispkin/planning/trajectory_acceleration.hpp"

namespace dispkin {
namespace python {

namespace {

using hexapod::Hexapod;


Limits make_limits(double velocity, double acceleration, std::optional<double> jerk,
                   std::optional<double> angular_velocity, std::optional<double> angular_acceleration) {
  Limits limits{velocity, acceleration, jerk, angular_velocity, angular_acceleration};
  require_limit(velocity, "velocity");
  require_limit(acceleration, "acceleration");
  if (jerk) require_limit(*jerk, "jerk");
  if (angular_velocity) require_limit(*angular_velocity, "angular_velocity");
  if (angular_acceleration) require_limit(*angular_acceleration, "angular_acceleration");
  return limits;
}

// Both None, or both given and close.
bool optional_close(const std::optional<double>& a, const std::optional<double>& b, double rel_tol, double abs_tol) {
  if (a.has_value() != b.has_value()) return false;
  return !a || isclose(*a, *b, rel_tol, abs_tol);
}

bool limits_close(const Limits& a, const Limits& b, double rel_tol, double abs_tol) {
  require_tolerances(rel_tol, abs_tol);
  return isclose(a.velocity, b.velocity, rel_tol, abs_tol) &&
         isclose(a.acceleration, b.acceleration, rel_tol, abs_tol) &&
         optional_close(a.jerk, b.jerk, rel_tol, abs_tol) &&
         optional_close(a.angular_velocity, b.angular_velocity, rel_tol, abs_tol) &&
         optional_close(a.angular_acceleration, b.angular_acceleration, rel_tol, abs_tol);
}

py::tuple limits_state(const Limits& l) {
  return py::make_tuple(l.velocity, l.acceleration, l.jerk, l.angular_velocity, l.angular_acceleration);
}

// The times to sample at: a number (one time, `scalar`) or (N,), each finite.
struct Times {
  std::vector<double> t;
  bool scalar;
};

Times times_of(const py::object& times) {
  if (PyFloat_Check(times.ptr())) {  // one time, the usual call of a loop: no array to make
    Times one{{PyFloat_AS_DOUBLE(times.ptr())}, true};
    require_finite(one.t[0], "times");
    return one;
  }
  const Array a = as_array(times, "times", "a number or an array of shape (N,)");
  if (a.ndim() > 1) wrong_shape("times", "a number or an array of shape (N,)", a);
  Times out{std::vector<double>(a.data(), a.data() + a.size()), a.ndim() == 0};
  for (double x : out.t) require_finite(x, "times");
  return out;
}

// An (N, *shape_tail) array for N times, or for a number one sample shaped shape_tail (a float
// when that is empty), as numpy does for a scalar; `fill` writes the numbers (C++ only: for many
// times it runs with the interpreter lock released). With `out` (not None) they are written into
// that preallocated array, of the same shape, and it is returned; for a number where the sample
// is a float, `out` has shape (1,) or ().
template <typename Fill>
py::object shaped(const Times& times, const std::vector<py::ssize_t>& shape_tail, const py::object& out, Fill fill) {
  std::vector<py::ssize_t> shape;
  if (!times.scalar) shape.push_back(static_cast<py::ssize_t>(times.t.size()));
  shape.insert(shape.end(), shape_tail.begin(), shape_tail.end());
  const auto target_array = [&]() -> py::array {
    if (out.is_none()) return py::array_t<double>(shape);
    if (shape.empty()) return output_array(out, "out", shape, std::array<py::ssize_t, 1>{1});
    return output_array(out, "out", shape);
  };
  py::array target = target_array();
  double* data = static_cast<double*>(target.mutable_data());
  {
    const UnlockedIf unlocked(worth_releasing(times.t.size(), trajectory_sample_ns));
    fill(data);
  }
  if (out.is_none() && shape.empty()) return py::float_(*data);
  return std::move(target);
}

// Samples the trajectory at `times` and writes `columns` numbers per sample with `write`.
template <typename Sampled, typename Write>
py::object sampled(const Sampled& traj, const py::object& times, const py::object& out,
                   std::vector<py::ssize_t> shape_tail, py::ssize_t columns, Write write) {
  const Times at = times_of(times);
  return shaped(at, shape_tail, out, [&](double* data) {
    const std::vector<double>& t = at.t;
    if constexpr (std::is_same_v<Sampled, Trajectory> || std::is_same_v<Sampled, MotionStream>) {
      // A cursor: consecutive times (the usual array) find their section without search.
      typename Sampled::Cursor cursor;
      for (std::size_t i = 0; i < t.size(); ++i)
        write(traj.sample(t[i], cursor), data + static_cast<py::ssize_t>(i) * columns);
    } else {
      for (std::size_t i = 0; i < t.size(); ++i) write(traj.sample(t[i]), data + static_cast<py::ssize_t>(i) * columns);
    }
  });
}

// What each sampling method writes of a sample; TrajectoryCursor writes its state with the same
// functions, so that its numbers are those of the methods bit for bit.
void write_matrix(const TrajectorySample& s, double* out) {
  Eigen::Map<Eigen::Matrix<double, 4, 4, Eigen::RowMajor>>{out} = s.pose.matrix();
}
void write_xyzuvw(const TrajectorySample& s, double* out) {
  Eigen::Map<Eigen::Matrix<double, 6, 1>>{out} = s.pose.to_xyzuvw();
}
void write_body_twist(const TrajectorySample& s, double* out) {
  Eigen::Map<Eigen::Matrix<double, 6, 1>>{out} = s.body_twist.vector();
}

// A Trajectory::Cursor with the trajectory it runs along, for Python control loops. It holds
// the Python Trajectory, so the trajectory lives as long as the cursor; a Trajectory cannot be
// changed once built, so `trajectory` stays valid. The C++ cursor is only a hint (any value
// samples the same numbers), so the pair has no other invariant.
struct TrajectoryCursor {
  py::object owner;              // the Python Trajectory
  const Trajectory* trajectory;  // its C++ value
  Trajectory::Cursor cursor;     // the law and section of the last sample
  std::optional<double> t;       // the time of the last sample, as given
};

// One state in TrajectoryCursor's flat layout: the XYZUVW pose [0, 6), the body twist [6, 12),
// then s, s-dot and s-double-dot.
constexpr py::ssize_t cursor_state_size = 15;
constexpr py::ssize_t cursor_s = 12;

void write_cursor_state(const TrajectorySample& s, double* out) {
  write_xyzuvw(s, out);
  write_body_twist(s, out + 6);
  out[cursor_s] = s.s;
  out[cursor_s + 1] = s.s_dot;
  out[cursor_s + 2] = s.s_ddot;
}

// A sampling method's docstring: `doc`, then how it takes `out`.
std::string with_out(const char* doc) {
  return std::string(doc) +
         " `out` (keyword): a preallocated writeable C-contiguous float64 array of exactly the shape returned, written "
         "in "
         "place and returned instead of a new array (ValueError naming `out` and what it is otherwise).";
}

// The sampling methods shared by Trajectory, OverlappedTrajectory and MotionStream.
template <typename T>
void add_sampling(py::class_<T>& cls) {
  cls.def(
         "sample",
         [](const T& traj, const py::object& times, const py::object& out) {
           return sampled(traj, times, out, {4, 4}, 16, write_matrix);
         },
         py::arg("times"), py::kw_only(), py::arg("out") = py::none(),
         with_out("Poses at `times` as (N, 4, 4) homogeneous matrices; one (4, 4) for a number.").c_str())
      .def(
          "sample_xyzuvw",
          [](const T& traj, const py::object& times, const py::object& out) {
            return sampled(traj, times, out, {6}, 6, write_xyzuvw);
          },
          py::arg("times"), py::kw_only(), py::arg("out") = py::none(),
          with_out("Poses at `times` as (N, 6) XYZUVW (metres, radians); (6,) for a number.").c_str())
      .def(
          "body_twist",
          [](const T& traj, const py::object& times, const py::object& out) {
            return sampled(traj, times, out, {6}, 6, write_body_twist);
          },
          py::arg("times"), py::kw_only(), py::arg("out") = py::none(),
          with_out("Body twists (v, omega) at `times`, (N, 6), m/s and rad/s; (6,) for a number.").c_str())
      .def(
          "path_position",
          [](const T& traj, const py::object& times, const py::object& out) {
            return sampled(traj, times, out, {}, 1, [](const TrajectorySample& s, double* o) { *o = s.s; });
          },
          py::arg("times"), py::kw_only(), py::arg("out") = py::none(),
          with_out("s at `times`, (N,), metres of DISP arc length; a float for a number (with `out`: an array of shape "
                   "(1,) or (), returned).")
              .c_str())
      .def(
          "path_velocity",
          [](const T& traj, const py::object& times, const py::object& out) {
            return sampled(traj, times, out, {}, 1, [](const TrajectorySample& s, double* o) { *o = s.s_dot; });
          },
          py::arg("times"), py::kw_only(), py::arg("out") = py::none(),
          with_out("s-dot at `times`, (N,), m/s: the speed bound of every point of the set; a float for a number "
                   "(with `out`: an array of shape (1,) or (), returned).")
              .c_str())
      .def(
          "path_acceleration",
          [](const T& traj, const py::object& times, const py::object& out) {
            return sampled(traj, times, out, {}, 1, [](const TrajectorySample& s, double* o) { *o = s.s_ddot; });
          },
          py::arg("times"), py::kw_only(), py::arg("out") = py::none(),
          with_out("s-double-dot at `times`, (N,), m/s^2; a float for a number (with `out`: an array of shape (1,) or "
                   "(), returned).")
              .c_str());
}

// PlanOptions::joint_metric of plan()'s `joint_metric` argument: a Hexapod's own (C++, run with
// the interpreter lock released), or an object's leg_section_lengths(path, system_velocity),
// called with the lock taken back and its result converted to lengths.
JointMetric joint_metric_of(const py::object& joint_metric) {
  if (joint_metric.is_none()) return {};
  if (py::isinstance<Hexapod>(joint_metric)) return joint_metric.cast<const Hexapod&>().joint_metric();
  if (!py::hasattr(joint_metric, "leg_section_lengths")) {
    throw std::invalid_argument(describe("joint_metric", std::string(py::repr(joint_metric)),
                                         "must have a method leg_section_lengths(path, system_velocity) (a Hexapod)"));
  }
  return [joint_metric](const Path& path, const Limits& limits) {
    const py::gil_scoped_acquire locked;
    const py::object lengths = joint_metric.attr("leg_section_lengths")(path, limits.velocity);
    const std::string expected = "an array of shape (" + std::to_string(path.size()) + ",)";
    const Array a = as_array(lengths, "joint_metric.leg_section_lengths(path, velocity)", expected);
    if (a.ndim() != 1) wrong_shape("joint_metric.leg_section_lengths(path, velocity)", expected, a);
    return std::vector<double>(a.data(), a.data() + a.size());
  };
}

void bind_limits(py::module_& m) {
  py::class_<Limits> limits(
      m, "Limits",
      "System limits in the DISP metric: velocity (m/s), acceleration (m/s^2), jerk (m/s^3, S-curve only), "
      "and optionally the tool's angular velocity (rad/s) and angular acceleration (rad/s^2).");
  limits
      .def(py::init(&make_limits), py::arg("velocity"), py::arg("acceleration"), py::arg("jerk") = py::none(),
           py::arg("angular_velocity") = py::none(), py::arg("angular_acceleration") = py::none(),
           "Limits from the path velocity (m/s), acceleration (m/s^2) and jerk (m/s^3), each in "
           "[1e-12, 1e12] (dispkin's numeric range); the jerk is required by the S-curve profile and refused by the "
           "trapezoid (plan checks). "
           "angular_velocity (rad/s) and angular_acceleration (rad/s^2), when given, limit the tool's rotation "
           "separately "
           "(|omega| never above angular_velocity, exactly).")
      .def_readonly("velocity", &Limits::velocity,
                    "The path velocity limit, m/s: no point of the metric set moves faster.")
      .def_readonly("acceleration", &Limits::acceleration, "The path acceleration limit, m/s^2.")
      .def_readonly("jerk", &Limits::jerk, "The path jerk limit, m/s^3, or None (trapezoid profile).")
      .def_readonly("angular_velocity", &Limits::angular_velocity, "The tool's angular velocity limit, rad/s, or None.")
      .def_readonly("angular_acceleration", &Limits::angular_acceleration,
                    "The tool's angular acceleration limit, rad/s^2, or None.")
      .def(
          "__eq__", [](const Limits& a, const Limits& b) { return limits_state(a).equal(limits_state(b)); },
          py::is_operator(), "The same velocity, acceleration, jerk and angular limits (each both None or equal).")
      .def("__hash__", [](const Limits& l) { return py::hash(limits_state(l)); })
      .def("isclose", &limits_close, py::arg("other"), py::kw_only(), py::arg("rel_tol") = 1e-9,
           py::arg("abs_tol") = 0.0, "math.isclose for every limit (a limit of None only matches None).")
      .def("__repr__", [](const Limits& l) {
        std::string out = "Limits(velocity=" + float_repr(l.velocity) + ", acceleration=" + float_repr(l.acceleration) +
                          ", jerk=" + (l.jerk ? float_repr(*l.jerk) : std::string("None"));
        if (l.angular_velocity) out += ", angular_velocity=" + float_repr(*l.angular_velocity);
        if (l.angular_acceleration) out += ", angular_acceleration=" + float_repr(*l.angular_acceleration);
        return out + ")";
      });
  def_pickle(limits, "Limits", &limits_state, [](const py::object& state) {
    const py::tuple s = state_tuple(state, 5, "Limits");
    const auto item = [&s](std::size_t k, const char* field) {
      return state_item<std::optional<double>>(s, k, "Limits", field);
    };
    return make_limits(state_item<double>(s, 0, "Limits", "velocity"),
                       state_item<double>(s, 1, "Limits", "acceleration"), item(2, "jerk"), item(3, "angular_velocity"),
                       item(4, "angular_acceleration"));
  });
}

// What a trajectory was planned on and under: its length, sections, stops, velocity-limit curve,
// and the body acceleration along it.
void def_trajectory_plan(py::class_<Trajectory>& trajectory) {
  trajectory.def_property_readonly("duration", &Trajectory::duration, "Seconds.")
      .def_property_readonly("length", &Trajectory::length, "The DISP arc length, metres.")
      .def_property_readonly("piece_count", &Trajectory::piece_count, "Rest-to-rest pieces (1 + corners).")
      .def_property_readonly("law_count", &Trajectory::law_count,
                             "Time laws: one per segment of each piece's velocity-limit curve (the path "
                             "slows down where it curves tightly: speed^2 x curvature <= acceleration).")
      .def(
          "section_lengths",
          [](const Trajectory& t) {
            return py::array_t<double>(static_cast<py::ssize_t>(t.section_lengths().size()),
                                       t.section_lengths().data());
          },
          "L of every section, metres.")
      .def(
          "rest_positions",
          [](const Trajectory& t) {
            return py::array_t<double>(static_cast<py::ssize_t>(t.rest_positions().size()), t.rest_positions().data());
          },
          "Path positions s (m) where the trajectory is at rest: 0, every corner, the length.")
      .def(
          "section_sources",
          [](const Trajectory& t) {
            Eigen::MatrixXd out(static_cast<Eigen::Index>(t.section_sources().size()), 3);
            for (std::size_t k = 0; k < t.section_sources().size(); ++k) {
              const SectionSource& source = t.section_sources()[k];
              out.row(static_cast<Eigen::Index>(k)) << static_cast<double>(source.section), source.tau_start,
                  source.tau_end;
            }
            return out;
          },
          "Where each section comes from, as (K, 3) rows (section of the path as planned, tau start, tau end): the "
          "planner cuts sections whose fastest point's speed varies, and plans the blended path in continuous-path "
          "mode.")
      .def_property_readonly(
          "stops",
          [](const Trajectory& t) {
            py::list out;
            for (const Stop& stop : t.stops()) out.append(py::make_tuple(stop.s, stop.reason));
            return out;
          },
          "The corners where the trajectory comes to rest inside the path, as (path position s in m, reason) tuples; "
          "empty when the motion is one continuous run.")
      .def(
          "speed_limits",
          [](const Trajectory& t) {
            Eigen::MatrixXd out(static_cast<Eigen::Index>(t.speed_limits().size()), 3);
            for (std::size_t k = 0; k < t.speed_limits().size(); ++k) {
              const SpeedLimit& span = t.speed_limits()[k];
              out.row(static_cast<Eigen::Index>(k)) << span.start_s, span.length, span.limit;
            }
            return out;
          },
          "The velocity-limit curve it was planned under, as (K, 3) rows (start s, length, limit): m, m, m/s. "
          "The system velocity, lowered where the path curves tightly; any re-timing keeps to it.")
      .def(
          "body_acceleration",
          [](const Trajectory& traj, const py::object& times, const py::object& out) {
            const Times at = times_of(times);
            return shaped(at, {6}, out, [&](double* data) {
              for (std::size_t i = 0; i < at.t.size(); ++i)
                Eigen::Map<Eigen::Matrix<double, 6, 1>>(data + 6 * i) = body_acceleration(traj, at.t[i]).vector();
            });
          },
          py::arg("times"), py::kw_only(), py::arg("out") = py::none(),
          with_out(
              "The time derivative of the body twist at `times`: (v-dot, omega-dot) in body coordinates, (N, 6), "
              "m/s^2 and rad/s^2; (6,) for a number. From the path's second derivative (doc/planning.md section 12).")
              .c_str());
}

// The events of a trajectory (doc/events.md): a stop, a resumption, a speed override, a moving start.
void def_trajectory_events(py::class_<Trajectory>& trajectory) {
  trajectory
      .def("stopped_at", &Trajectory::stopped_at, py::arg("t"),
           "A feed hold that keeps to the path: the same motion up to t (bit for bit), then the fastest stop from the "
           "state there (path velocity and acceleration) to rest on the same path, under the acceleration and jerk "
           "limits it was planned with and its velocity-limit curve (doc/events.md). At or after the end, the same "
           "trajectory. `resumed_at` goes on to the end.")
      .def("resumed_at", &Trajectory::resumed_at, py::arg("t"),
           "A stopped trajectory continued at t (at rest where it stopped, or while it still brakes) to the end of "
           "its path, at the speed override in force. ValueError unless `stopped`.")
      .def("with_override", &Trajectory::with_override, py::arg("t"), py::arg("factor"),
           "A speed override from t on: the same motion up to t, then the path continues under factor x the "
           "velocity-limit curve (each span at most its ceiling: factors above 1 only speed up what a move's own "
           "velocity slowed down), the change eased in at full jerk from the state at t. factor in [0.001, 10], "
           "relative to the curve as planned (a second override replaces the first).")
      .def("starting_from", &Trajectory::starting_from, py::arg("velocity"), py::arg("acceleration") = 0.0,
           "The same path and velocity-limit curve run from the moving state (path velocity m/s, path acceleration "
           "m/s^2; S-curve only) at its start instead of from rest: the first run's law is the time-optimal one from "
           "that state (doc/events.md section 3). ValueError when the state is above the limits at the start, below "
           "the jerk limit's release curve, or cannot keep to the velocity-limit curve of the first run.")
      .def_property_readonly("override_factor", &Trajectory::override_factor,
                             "The speed override in force from the last event on (1.0 as planned).")
      .def_property_readonly("stopped", &Trajectory::stopped,
                             "Whether the motion ends at rest before the end of its path (stopped_at).")
      .def_property_readonly("end_position", &Trajectory::end_position,
                             "Where the motion ends, m of DISP arc length: the length, or where it stopped.")
      .def_property_readonly(
          "time_law_limits",
          [](const Trajectory& t) -> py::object {
            if (!t.limits()) return py::none();
            return py::make_tuple(t.limits()->acceleration, py::cast(t.limits()->jerk));
          },
          "(acceleration m/s^2, jerk m/s^3 or None) that the time law keeps to, and so every stop or override of it; "
          "None for a re-timed trajectory (its law keeps to joint limits), which refuses events.")
      .def("__repr__", [](const Trajectory& t) {
        return "Trajectory(duration=" + float_repr(t.duration()) + ", sections=" + std::to_string(t.section_count()) +
               ")";
      });
}

py::class_<Trajectory> bind_trajectory(py::module_& m) {
  py::class_<Trajectory> trajectory(m, "Trajectory", R"doc(
A planned trajectory: no point or sphere of the metric set moves faster than its limit at any
time. Sample it at any times (seconds, clamped to [0, duration]).)doc");
  def_trajectory_plan(trajectory);
  def_trajectory_events(trajectory);

  def_pickle(trajectory, "Trajectory", &trajectory_state,
             [](const py::object& state) { return trajectory_from_state(state); });
  add_sampling(trajectory);
  return trajectory;
}

// TrajectoryCursor, and Trajectory.cursor() that makes one.
void bind_trajectory_cursor(py::module_& m, py::class_<Trajectory>& trajectory) {
  py::class_<TrajectoryCursor> cursor(m, "TrajectoryCursor", R"doc(
Where a control loop has got to along a Trajectory (Trajectory.cursor()): sample(t, out) finds
the time law and section of t from those of the sample before (in constant time for the same or
the next ones, the usual controller cycle; by binary search after a jump) and writes the whole
state at t into the preallocated array `out`, allocating nothing. It keeps its trajectory alive.

A state is SIZE = 15 float64 numbers, in this order (the class attributes hold the indices):

- [0:6] the XYZUVW pose, metres and radians (XYZUVW; Trajectory.sample_xyzuvw);
- [6:12] the body twist (v, omega), m/s and rad/s (BODY_TWIST; Trajectory.body_twist);
- [12] s, metres of DISP arc length (PATH_POSITION; Trajectory.path_position);
- [13] s-dot, m/s (PATH_VELOCITY; Trajectory.path_velocity);
- [14] s-double-dot, m/s^2 (PATH_ACCELERATION; Trajectory.path_acceleration).

Each number is that method's at the same time, bit for bit, in whatever order the times come.
Views made once, e.g. twist = out[TrajectoryCursor.BODY_TWIST], read the state of every cycle.)doc");
  cursor.attr("SIZE") = cursor_state_size;
  cursor.attr("XYZUVW") = py::slice(0, 6, std::nullopt);
  cursor.attr("BODY_TWIST") = py::slice(6, cursor_s, std::nullopt);
  cursor.attr("PATH_POSITION") = cursor_s;
  cursor.attr("PATH_VELOCITY") = cursor_s + 1;
  cursor.attr("PATH_ACCELERATION") = cursor_s + 2;
  cursor
      .def(
          "sample",
          [](TrajectoryCursor& c, double t, const py::object& out) -> py::object {
            require_finite(t, "t");
            py::array target = out.is_none() ? py::array(py::array_t<double>(cursor_state_size))
                                             : output_array(out, "out", std::array<py::ssize_t, 1>{cursor_state_size});
            write_cursor_state(c.trajectory->sample(t, c.cursor), static_cast<double*>(target.mutable_data()));
            c.t = t;
            return std::move(target);
          },
          py::arg("t"), py::arg("out") = py::none(),
          "Writes the state at time t (seconds, finite; clamped to [0, duration]) into `out`, a writeable C-contiguous "
          "float64 array of shape (15,) in the layout of the class, and returns `out` (a new array when None). With "
          "`out` given nothing is allocated: a control loop passes the same array at every cycle.")
      .def_property_readonly(
          "t", [](const TrajectoryCursor& c) { return c.t; },
          "The time of the last sample, seconds, as given; None before the first.")
      .def_property_readonly(
          "section", [](const TrajectoryCursor& c) { return c.cursor.section; },
          "The index of the section of the last sample (0 before the first), into Trajectory.section_lengths().")
      .def_property_readonly(
          "trajectory", [](const TrajectoryCursor& c) { return c.owner; }, "The Trajectory the cursor runs along.")
      .def("__repr__", [](const TrajectoryCursor& c) {
        return "TrajectoryCursor(t=" + (c.t ? float_repr(*c.t) : std::string("None")) +
               ", section=" + std::to_string(c.cursor.section) + ")";
      });
  trajectory.def(
      "cursor",
      [](const py::object& self) {
        return TrajectoryCursor{self, &self.cast<const Trajectory&>(), Trajectory::Cursor{}, std::nullopt};
      },
      "A TrajectoryCursor at the start of the trajectory, for sampling it in a control loop: one state per call, "
      "written into a preallocated array without allocating, each found from the one before.");
}

void bind_overlapped_trajectory(py::module_& m) {
  py::class_<OverlappedTrajectory> overlapped(m, "OverlappedTrajectory", R"doc(
The Mamezou trajectory article's overlapped velocity method: `after` starts `overlap` seconds before `before` ends and
the two motions add up meanwhile — P(t) = P_b(t) + P_f(t') - P_2 for the point `pivot` (body
coordinates; the origin by default) and R(t) = R_f(t') R_2^-1 R_b(t). Overlapping the
deceleration of one move with the acceleration of the next runs through the via point without
stopping. No speed guarantee of its own: a point's velocity is the sum of two, so check the
peak (e.g. with dispkin.max_point_speed) before using large overlaps.)doc");
  overlapped
      .def(py::init([](const Trajectory& before, const Trajectory& after, double overlap, const py::object& pivot) {
             return OverlappedTrajectory(before, after, overlap, vector3(pivot, "pivot"));
           }),
           py::arg("before"), py::arg("after"), py::arg("overlap"),
           py::arg_v("pivot", py::make_tuple(0.0, 0.0, 0.0), "(0, 0, 0)"),
           "`after` started `overlap` seconds (0 <= overlap <= the shorter duration) before `before` ends; "
           "`after` must start where `before` ends. `pivot`: the body point (metres) whose velocities add.")
      .def_property_readonly("duration", &OverlappedTrajectory::duration, "Seconds.")
      .def_property_readonly("overlap", &OverlappedTrajectory::overlap, "Seconds during which both moves run.")
      .def_property_readonly("overlap_start", &OverlappedTrajectory::overlap_start,
                             "When the second move starts, seconds.")
      .def("__repr__", [](const OverlappedTrajectory& o) {
        return "OverlappedTrajectory(duration=" + float_repr(o.duration()) + ", overlap=" + float_repr(o.overlap()) +
               ")";
      });
  add_sampling(overlapped);
}

void bind_motion_stream(py::module_& m) {
  py::class_<MotionStream> stream(m, "MotionStream", R"doc(
Moves appended while the motion runs (doc/events.md section 5): what is planned always ends at rest
at the last appended pose; a move appended while the motion runs is joined to it from its state (the
path ahead planned again with the move, corners blended within `corner_tolerance` as `plan` does; the
cost is that of the look-ahead), one appended after the motion ended starts from rest.
`stop`, `resume` and `set_override` act at any time. Every request at time t leaves the motion
before t as it was, bit for bit; requests come in time order. Sample it at any times (seconds).)doc");
  stream
      .def(py::init(
               [](const MetricSetd& set, const Limits& limits, const std::string& profile, double corner_tolerance) {
                 return MotionStream(set, limits, profile_kind(profile), corner_tolerance);
               }),
           py::arg("metric_set"), py::arg("limits"), py::arg("profile") = "scurve", py::arg("corner_tolerance") = 0.0,
           "An empty stream under the metric set and limits, with the \"scurve\" or \"trapezoid\" law; corners blended "
           "within corner_tolerance (m; 0 stops at every corner).")
      .def("append", &MotionStream::append, py::arg("path"), py::arg("t"),
           "Appends `path` (it starts where the last appended move ends) at time t (s, not before the last request).")
      .def("stop", &MotionStream::stop, py::arg("t"),
           "Stops on the path from the state at t as fast as the limits allow; moves appended while stopped wait for "
           "resume.")
      .def("resume", &MotionStream::resume, py::arg("t"),
           "Goes on at t through every move appended. ValueError unless stopped.")
      .def("set_override", &MotionStream::set_override, py::arg("t"), py::arg("factor"),
           "The speed override from t on (factor in [0.001, 10], relative to the limits as planned).")
      .def_property_readonly("duration", &MotionStream::duration, "When what is planned now ends, at rest (s).")
      .def("done", &MotionStream::done, py::arg("t"), "Whether the motion has run everything planned by t.")
      .def_property_readonly("stopped", &MotionStream::stopped, "Whether a stop holds the motion until resume.")
      .def_property_readonly("override_factor", &MotionStream::override_factor, "The override in force.")
      .def_property_readonly("waiting_moves", &MotionStream::waiting_moves, "Moves appended while stopped.")
      .def("forget_before", &MotionStream::forget_before, py::arg("t"),
           "Lets go of the stretches of motion that ended before t (to keep a long stream's memory to its look-ahead); "
           "samples before t then give the state where the first stretch kept starts.")
      .def_property_readonly("changed_from", &MotionStream::changed_from,
                             "From when the last request changed the motion (s): samples before it are as they were; "
                             "inf where nothing changed (a move waiting for resume).")
      .def_property_readonly("leg_count", &MotionStream::leg_count,
                             "Stretches of motion from rest (a move appended too late to be joined starts a new one).")
      .def("__repr__", [](const MotionStream& s) {
        return "MotionStream(duration=" + float_repr(s.duration()) + ", legs=" + std::to_string(s.leg_count()) + ")";
      });
  add_sampling(stream);
}

void bind_plan(py::module_& m) {
  m.def(
      "plan",
      [](const Path& path, const MetricSetd& set, const Limits& limits, const std::string& profile,
         const py::object& joint_metric, double corner_tolerance, double start_velocity, double start_acceleration) {
        const ProfileKind kind = profile_kind(profile);
        PlanOptions options;
        options.corner_tolerance = corner_tolerance;
        options.start_velocity = start_velocity;
        options.start_acceleration = start_acceleration;
        options.joint_metric = joint_metric_of(joint_metric);
        const UnlockedIf unlocked(true, path, set);
        return plan(path, set, limits, kind, options);
      },
      py::arg("path"), py::arg("metric_set"), py::arg("limits"), py::arg("profile") = "scurve", py::kw_only(),
      py::arg("joint_metric") = py::none(), py::arg("corner_tolerance") = 0.0, py::arg("start_velocity") = 0.0,
      py::arg("start_acceleration") = 0.0,
      "Plan `path` under the metric set and limits with a time-optimal \"scurve\" (needs limits.jerk) "
      "or \"trapezoid\" law. The trajectory stops at corners of the path unless `corner_tolerance` (m, keyword) is "
      "positive: then every corner is blended with the largest blend whose pivot stays within that distance of the "
      "corner and that takes at most half of each neighbouring move, and the motion runs through at speed "
      "(corners that cannot be blended stop: see Trajectory.stops). Each move runs under its own velocity and "
      "acceleration (Path.lin(..., velocity=, acceleration=)), capped by `limits`. `joint_metric` (keyword): an "
      "object with leg_section_lengths(path, system_velocity); each section of the path as planned (blended when "
      "corner_tolerance is positive) is then at least that long. For a "
      "Hexapod its C++ joint_metric is used: the leg-speed lengths (rule (b)), raised to one common speed along "
      "sections that continue one another (a CIRC), so the trajectory does not stop at their junctions. "
      "`start_velocity` (m/s) and `start_acceleration` (m/s², S-curve only; keywords): the state the motion starts in "
      "instead of rest, within the limits at the start (doc/events.md section 3); its first run is the time-optimal "
      "law "
      "from that state.");
}

}  // namespace

void bind_planner(py::module_& m) {
  bind_limits(m);
  py::class_<Trajectory> trajectory = bind_trajectory(m);
  bind_trajectory_cursor(m, trajectory);
  bind_overlapped_trajectory(m);
  bind_motion_stream(m);
  bind_plan(m);
}

}  // namespace python
}  // namespace dispkin
