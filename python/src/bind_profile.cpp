// Python binding of dispkin/profile.hpp: Profile (time-optimal trapezoid and S-curve).
#include <cmath>
#include <cstddef>
#include <string>

#include <pybind11/numpy.h>
#include <pybind11/eigen.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "bindings.hpp"
#include "conversions.hpp"
#include "interpreter_lock.hpp"
#include "path_state.hpp"
#include "value_protocol.hpp"
#include "dispkin/error.hpp"
#include "dispkin/profile.hpp"
#include "dispkin/planning/velocity_limit.hpp"

namespace dispkin {
namespace python {

namespace {

// (N,) times in, (N, 4) rows (s, v, a, j) out. Times must be finite; outside [0, T] the end
// states are returned (Profile::state_at clamps).
py::array_t<double> sample(const Profile& profile, const py::object& times) {
  const std::string expected = "an array of shape (N,)";
  const Array t = as_array(times, "times", expected);
  if (t.ndim() != 1) wrong_shape("times", expected, t);
  const auto n = static_cast<std::size_t>(t.shape(0));
  for (std::size_t i = 0; i < n; ++i) {
    require(std::isfinite(t.data()[i]), "times[" + std::to_string(i) + "]", t.data()[i], "must be finite");
  }
  py::array_t<double> out({static_cast<py::ssize_t>(n), py::ssize_t{4}});
  double* row = out.mutable_data();
  const double* at = t.data();
  {
    const UnlockedIf unlocked(worth_releasing(n, profile_state_ns));
    for (std::size_t i = 0; i < n; ++i, row += 4) {
      const ProfileState x = profile.state_at(at[i]);
      row[0] = x.s;
      row[1] = x.v;
      row[2] = x.a;
      row[3] = x.j;
    }
  }
  return out;
}

py::list phases(const Profile& profile) {
  py::list out;
  for (int i = 0; i < profile.phase_count(); ++i) {
    const ProfilePhase& p = profile.phase(i);
    out.append(py::make_tuple(p.duration, p.jerk, p.start.s, p.start.v, p.start.a));
  }
  return out;
}

const char* kind_name(const Profile& p) { return profile_name(p.kind()); }

std::string profile_repr(const Profile& p) {
  return std::string("Profile(kind=\"") + kind_name(p) + "\", distance=" + float_repr(p.distance()) +
         ", duration=" + float_repr(p.duration()) + ", peak_velocity=" + float_repr(p.peak_velocity()) +
         ", phases=" + std::to_string(p.phase_count()) + ")";
}

}  // namespace

void bind_profile(py::module_& m) {
  py::class_<Profile> profile(m, "Profile", R"doc(
A one-dimensional time-optimal time law s(t) over a distance S (metres, or any unit of path
length): piecewise-constant jerk, at most seven phases, from velocity v_start to v_end with
zero acceleration at both ends. Build it with Profile.trapezoid or Profile.scurve; immutable.)doc");
  profile
      .def_static("trapezoid", &Profile::trapezoid, py::arg("distance"), py::arg("v_max"), py::arg("a_max"),
                  py::arg("v_start") = 0.0, py::arg("v_end") = 0.0,
                  "The time-optimal law under |v| <= v_max, |a| <= a_max (no jerk limit): accelerate at "
                  "+a_max to the peak velocity, cruise, decelerate at -a_max. v_start, v_end in [0, v_max]. "
                  "ValueError on bad input or if `distance` is too short to go from v_start to v_end.")
      .def_static("scurve", &Profile::scurve, py::arg("distance"), py::arg("v_max"), py::arg("a_max"), py::arg("j_max"),
                  py::arg("v_start") = 0.0, py::arg("v_end") = 0.0,
                  "The time-optimal seven-phase law under |v| <= v_max, |a| <= a_max, |jerk| <= j_max, "
                  "accelerations zero at both ends. v_start, v_end in [0, v_max]. ValueError on bad input, "
                  "or if `distance` is too short for the accelerate-cruise-decelerate law between v_start "
                  "and v_end (a law dipping below both boundary velocities is not supported).")
      .def_static("from_state", &Profile::from_state, py::arg("distance"), py::arg("v_max"), py::arg("a_max"),
                  py::arg("jerk"), py::arg("v_start") = 0.0, py::arg("a_start") = 0.0, py::arg("v_end") = 0.0,
                  "The time-optimal jerk-limited law from a moving, accelerating state (v_start, a_start) "
                  "to (distance, v_end, acceleration 0) under 0 <= v <= v_max, |a| <= a_max, |jerk| <= jerk; "
                  "it never runs backwards. A start beyond the limits (v_start > v_max, |a_start| > a_max, or "
                  "an a_start that carries v above v_max) first eases onto them at full jerk. Where the "
                  "distance is too short for a law between its end velocities, the law dips (slows down and "
                  "speeds up again). v_end in [0, v_max]. ValueError on bad input, or if no law fits in "
                  "`distance` (the message names the distance needed and the shortfall).")
      .def_static("trapezoid_from_state", &Profile::trapezoid_from_state, py::arg("distance"), py::arg("v_max"),
                  py::arg("a_max"), py::arg("v_start") = 0.0, py::arg("v_end") = 0.0,
                  "The time-optimal law without a jerk limit from velocity v_start >= 0, which may exceed "
                  "v_max: above it, brake at -a_max to v_max, cruise, decelerate to v_end; otherwise as "
                  "Profile.trapezoid. ValueError on bad input or if `distance` is too short.")
      .def_property_readonly("kind", &kind_name, "\"trapezoid\" or \"scurve\".")
      .def_property_readonly("duration", &Profile::duration, "The duration T in seconds.")
      .def_property_readonly("distance", &Profile::distance, "The distance S covered.")
      .def_property_readonly("peak_velocity", &Profile::peak_velocity,
                             "The velocity reached between acceleration and deceleration.")
      .def_property_readonly("phases", &phases,
                             "The phases of non-zero duration, each a tuple (duration, jerk, s, v, a) with "
                             "the state (s, v, a) at the phase start. Trapezoid phases have jerk 0 and a "
                             "constant acceleration a.")
      .def("sample", &sample, py::arg("times"),
           "States at `times` ((N,) seconds, finite) as an (N, 4) array of rows (s, v, a, jerk). Times "
           "outside [0, duration] give the start or end state.")
      .def("__repr__", &profile_repr);
  def_pickle(profile, "Profile", &profile_state, [](const py::object& state) { return profile_from_state(state); });

  // (N, 2) rows (length, limit) as the staircase's segments.
  const auto staircase = [](const Eigen::MatrixXd& segments) {
    if (segments.cols() != 2) {
      throw std::invalid_argument("segments: expected an array of shape (N, 2) of (length, limit), got shape (" +
                                  std::to_string(segments.rows()) + ", " + std::to_string(segments.cols()) + ")");
    }
    std::vector<LimitedSegment> list;
    for (Eigen::Index i = 0; i < segments.rows(); ++i) list.push_back({segments(i, 0), segments(i, 1)});
    return list;
  };
  m.def(
      "velocity_limited_law",
      [staircase](const Eigen::MatrixXd& segments, double a_max, std::optional<double> j_max, double v_start,
                  double v_end) { return velocity_limited_law(staircase(segments), a_max, j_max, v_start, v_end); },
      py::arg("segments"), py::arg("a_max"), py::arg("j_max") = py::none(), py::arg("v_start") = 0.0,
      py::arg("v_end") = 0.0,
      "The time law under a piecewise-constant velocity limit: `segments` is an (N, 2) array of rows "
      "(length, limit). A list of Profiles in order, each within one segment (a segment may hold "
      "several), velocities joining continuously, every velocity within its segment's limit. Without "
      "j_max the time-optimal trapezoid chain (velocity_limited_chain); with it, for a law ending at rest, "
      "the faster of that chain and the law that carries acceleration across the boundaries "
      "(doc/profiles.md §8) — never slower than the chain.");
  m.def(
      "velocity_limited_chain",
      [staircase](const Eigen::MatrixXd& segments, double a_max, std::optional<double> j_max, double v_start,
                  double v_end) { return velocity_limited_chain(staircase(segments), a_max, j_max, v_start, v_end); },
      py::arg("segments"), py::arg("a_max"), py::arg("j_max") = py::none(), py::arg("v_start") = 0.0,
      py::arg("v_end") = 0.0,
      "The chain of laws under a piecewise-constant velocity limit (doc/profiles.md §5): one Profile "
      "per row (length, limit) of `segments` (a trapezoid without j_max, an S-curve with it), the "
      "boundary velocities from a forward and a backward pass, every S-curve at zero acceleration at "
      "its segment's boundaries.");
  m.def(
      "jerk_limited_duration_bound",
      [staircase](const Eigen::MatrixXd& segments, double a_max, double j_max, double v_start, double v_end) {
        return jerk_limited_duration_bound(staircase(segments), a_max, j_max, v_start, v_end);
      },
      py::arg("segments"), py::arg("a_max"), py::arg("j_max"), py::arg("v_start") = 0.0, py::arg("v_end") = 0.0,
      "A duration (s) no jerk-limited law under the staircase `segments` ((N, 2) rows (length, limit)) can beat "
      "(doc/profiles.md §8.5): the best sum over cuts of the staircase into windows of the least time each window "
      "needs when only its end limits, its highest limit, a_max and j_max are kept. velocity_limited_law's "
      "duration lies between it and the law's own.");
}

}  // namespace python
}  // namespace dispkin
