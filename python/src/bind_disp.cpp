// Python binding of dispkin/disp.hpp (and convex_hull_vertices): distances, speeds, section
// lengths, interpolation.
#include <cmath>
#include <optional>
#include <string>

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "bindings.hpp"
#include "conversions.hpp"
#include "interpreter_lock.hpp"
#include "dispkin/convex_hull.hpp"
#include "dispkin/disp.hpp"
#include "dispkin/error.hpp"

namespace dispkin {
namespace python {

namespace {

using OptionalSpeed = std::optional<double>;

Twistd checked_twist(const py::object& twist) {
  const Eigen::Matrix<double, 6, 1> xi = vector<6>(twist, "twist");
  require_finite(xi, "twist");
  return Twistd(xi);
}

double distance(const MetricSetd& set, const Posed& a, const Posed& b, const std::string& norm,
                OptionalSpeed system_velocity) {
  const UnlockedIf unlocked(worth_releasing(set), set);
  if (norm == "euclidean") return disp_distance<EuclideanNorm, double>(set, a, b, system_velocity);
  if (norm == "max") return disp_distance<MaxNorm, double>(set, a, b, system_velocity);
  if (norm == "l1") return disp_distance<L1Norm, double>(set, a, b, system_velocity);
  throw std::invalid_argument(describe("norm", norm, "must be \"euclidean\", \"max\" or \"l1\""));
}

py::object speeds_of_points(const py::object& twist, const py::object& point) {
  const Twistd xi = checked_twist(twist);
  const Array a = as_array(point, "point", "an array of shape (3,) or (N, 3)");
  const std::vector<Eigen::Vector3d> pts = points(a, "point", true);
  for (std::size_t i = 0; i < pts.size(); ++i) require_finite(pts[i], "point");  // point_speed does not check
  if (a.ndim() == 1) return py::float_(point_speed<double>(xi, pts.front()));
  py::array_t<double> out(static_cast<py::ssize_t>(pts.size()));
  double* data = out.mutable_data();
  {
    const UnlockedIf unlocked(worth_releasing(pts.size(), point_speed_ns));
    for (std::size_t i = 0; i < pts.size(); ++i) data[i] = point_speed<double>(xi, pts[i]);
  }
  return std::move(out);
}

// The DISP distance between two poses and the length of a section.
void bind_lengths(py::module_& m) {
  const py::tuple origin = py::make_tuple(0.0, 0.0, 0.0);

  m.def("disp_distance", &distance, py::arg("metric_set"), py::arg("pose_a"), py::arg("pose_b"),
        py::arg("norm") = "euclidean", py::arg("system_velocity") = py::none(),
        "The DISP distance between two poses (metres): the longest chord any point or sphere of the "
        "set travels, relative objects in world, absolute ones seen from the tool; `norm` is "
        "\"euclidean\", \"max\" or \"l1\". Groups with their own speed limit are weighted by "
        "system_velocity / speed (system_velocity in m/s, then required). The set must be "
        "well-formed.");
  m.def(
      "section_length",
      [](const MetricSetd& set, const Posed& a, const Posed& b, const std::string& interpolation,
         const py::object& pivot, OptionalSpeed system_velocity) {
        const Interpolation kind = interpolation_from_string(interpolation);
        const Eigen::Vector3d p = vector3(pivot, "pivot");
        const UnlockedIf unlocked(worth_releasing(set), set);
        return section_length<double>(set, a, b, kind, p, system_velocity);
      },
      py::arg("metric_set"), py::arg("pose_a"), py::arg("pose_b"), py::arg("interpolation") = "decoupled",
      py::arg_v("pivot", origin, "(0, 0, 0)"), py::arg("system_velocity") = py::none(),
      "The exact length L of the section from pose_a to pose_b (metres): the largest speed of any "
      "point or sphere of the set per unit of the section parameter tau in [0, 1]. Moving along tau "
      "at dtau/dt = v / L keeps every object at or below speed v. `interpolation` is \"decoupled\" "
      "(LIN: `pivot`, body coordinates, travels a straight line while the orientation turns about "
      "one axis) or \"screw\" (constant body twist). Groups weighted as in disp_distance.");
}

// The speeds of points and spheres under a twist, and the fastest point of a set.
void bind_speeds(py::module_& m) {
  m.def("point_speed", &speeds_of_points, py::arg("twist"), py::arg("point"),
        "Speed ||v + ω × p|| (m/s) of a body point p under the body twist (v, ω): a float for a (3,) "
        "point, an (N,) array for the rows of an (N, 3) array. For an absolute point, p is its "
        "current body position.");
  m.def(
      "sphere_speed",
      [](const py::object& twist, const py::object& center, double radius) {
        const Twistd xi = checked_twist(twist);
        const Eigen::Vector3d c = vector3(center, "center");
        require_translation(c, "center");
        require(std::isfinite(radius) && radius >= 0.0, "radius", radius, "must be finite and not negative");
        return sphere_speed<double>(xi, c, radius);
      },
      py::arg("twist"), py::arg("center"), py::arg("radius"),
      "Exact largest speed (m/s) of any point of the ball (centre in body coordinates, radius in "
      "metres) under the body twist (v, ω).");
  m.def(
      "max_point_speed",
      [](const MetricSetd& set, const Posed& pose, const py::object& twist, OptionalSpeed system_velocity) {
        const Twistd xi = checked_twist(twist);
        const UnlockedIf unlocked(worth_releasing(set), set);
        return max_point_speed<double>(set, pose, xi, system_velocity);
      },
      py::arg("metric_set"), py::arg("pose"), py::arg("twist"), py::arg("system_velocity") = py::none(),
      "The largest speed (m/s) of any point or sphere of the set when the tool is at `pose` and moves "
      "with body twist (v, ω); absolute objects count with their apparent speed seen from the tool. "
      "Groups weighted as in disp_distance.");
}

// The pose at tau along the section between two poses (decoupled or screw, about a pivot).
void bind_interpolation(py::module_& m) {
  const py::tuple origin = py::make_tuple(0.0, 0.0, 0.0);

  m.def(
      "interpolate",
      [](const Posed& a, const Posed& b, double tau, const std::string& interpolation, const py::object& pivot) {
        require_finite(tau, "tau");
        const Interpolation kind = interpolation_from_string(interpolation);
        const Eigen::Vector3d p = vector3(pivot, "pivot");
        require_translation(p, "pivot");
        return interpolate<double>(a, b, tau, kind, p);
      },
      py::arg("pose_a"), py::arg("pose_b"), py::arg("tau"), py::arg("interpolation") = "decoupled",
      py::arg_v("pivot", origin, "(0, 0, 0)"),
      "The pose at tau in [0, 1] of the section from pose_a to pose_b (\"decoupled\" or \"screw\", "
      "as in section_length): the motion whose speed section_length bounds.");
}

// The vertices of the convex hull of points (Qhull).
void bind_convex_hull(py::module_& m) {
  m.def(
      "convex_hull_vertices",
      [](const py::object& pts) {
        const std::vector<Eigen::Vector3d> given = points(pts, "points", false);
        std::vector<Eigen::Vector3d> vertices;
        {
          const UnlockedIf unlocked(worth_releasing(given.size(), hull_point_ns));
          vertices = convex_hull_vertices(given);
        }
        return to_array(vertices);
      },
      py::arg("points"),
      "The vertices of the convex hull of the rows of an (N, 3) array (Qhull), as an (M, 3) array of "
      "exact copies in input order. Only they can be the fastest or the farthest-moving points.");
}

}  // namespace

void bind_disp(py::module_& m) {
  bind_lengths(m);
  bind_speeds(m);
  bind_interpolation(m);
  bind_convex_hull(m);
}

}  // namespace python
}  // namespace dispkin
