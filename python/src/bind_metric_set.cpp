// Python binding of dispkin/metric_set.hpp (and its hull reduction from convex_hull.hpp): MetricSet.
#include <string>

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "bindings.hpp"
#include "conversions.hpp"
#include "dispkin/convex_hull.hpp"
#include "dispkin/error.hpp"
#include "dispkin/metric_set.hpp"

namespace dispkin {
namespace python {

namespace {

const MetricGroup<double>& existing_group(const MetricSetd& set, int group) {
  const MetricGroup<double>* g = set.find_group(group);
  if (g == nullptr) throw std::invalid_argument(describe("group", group, "no such group in the set"));
  return *g;
}

py::list group_spheres(const MetricSetd& set, int group) {
  const MetricGroup<double>& g = existing_group(set, group);
  py::list out;
  for (const auto& s : g.relative_spheres) out.append(py::make_tuple(to_array(s.center), s.radius, false));
  for (const auto& s : g.absolute_spheres) out.append(py::make_tuple(to_array(s.center), s.radius, true));
  return out;
}

std::string metric_set_repr(const MetricSetd& set) {
  std::string groups;
  std::string speeds;
  for (const auto& g : set.groups()) {
    groups += (groups.empty() ? "" : ", ") + std::to_string(g.id);
    if (g.speed_limit) speeds += (speeds.empty() ? "" : ", ") + std::to_string(g.id) + ": " + float_repr(*g.speed_limit);
  }
  return "MetricSet(groups=[" + groups + "], points=" + std::to_string(set.point_count()) +
         ", spheres=" + std::to_string(set.sphere_count()) + (speeds.empty() ? "" : ", group_speeds={" + speeds + "}") +
         ", well_formed=" + (set.is_well_formed() ? "True" : "False") + ")";
}

}  // namespace

void bind_metric_set(py::module_& m) {
  py::class_<MetricSetd>(m, "MetricSet", R"doc(
The metric establishment set: the points and spheres the speed limit applies to.
Relative points and spheres are in body (tool) coordinates and move with the tool; absolute ones
are in world coordinates and stay put (their apparent speed seen from the tool is limited).
Objects belong to groups (non-negative integers, default 0); a group may have its own speed limit.
Lengths in metres.)doc")
      .def(py::init<>(), "An empty set.")
      .def(
          "add_relative",
          [](MetricSetd& self, const py::object& pts, int group) {
            self.add_points(points(pts, "points", true), Frame::relative, group);
          },
          py::arg("points"), py::arg("group") = 0,
          "Add points that move with the tool: a (3,) array or the rows of an (N, 3) array, body "
          "coordinates, metres.")
      .def(
          "add_absolute",
          [](MetricSetd& self, const py::object& pts, int group) {
            self.add_points(points(pts, "points", true), Frame::absolute, group);
          },
          py::arg("points"), py::arg("group") = 0,
          "Add fixed points of the world (a protected zone): a (3,) array or the rows of an (N, 3) "
          "array, world coordinates, metres.")
      .def(
          "add_sphere",
          [](MetricSetd& self, const py::object& center, double radius, bool absolute, int group) {
            self.add_sphere(vector3(center, "center"), radius, absolute ? Frame::absolute : Frame::relative, group);
          },
          py::arg("center"), py::arg("radius"), py::arg("absolute") = false, py::arg("group") = 0,
          "Add a ball (handled exactly): centre (3,) in body coordinates, or world coordinates if "
          "`absolute`; radius >= 0 in metres.")
      .def("set_group_speed", &MetricSetd::set_group_speed, py::arg("group"), py::arg("speed"),
           "Give group `group` its own speed limit in m/s (> 0); the group is created if needed. Its "
           "lengths are then weighted by system_velocity / speed.")
      .def_property_readonly(
          "groups",
          [](const MetricSetd& self) {
            py::list ids;
            for (const auto& g : self.groups()) ids.append(g.id);
            return ids;
          },
          "The group ids, ascending.")
      .def(
          "relative_points",
          [](const MetricSetd& self, int group) { return to_array(existing_group(self, group).relative_points); },
          py::arg("group") = 0, "The group's relative points as an (N, 3) array (body coordinates, metres).")
      .def(
          "absolute_points",
          [](const MetricSetd& self, int group) { return to_array(existing_group(self, group).absolute_points); },
          py::arg("group") = 0, "The group's absolute points as an (N, 3) array (world coordinates, metres).")
      .def("spheres", &group_spheres, py::arg("group") = 0,
           "The group's spheres as a list of (center (3,), radius, absolute) tuples: relative spheres "
           "first, then absolute ones, each in the order added.")
      .def(
          "group_speed",
          [](const MetricSetd& self, int group) { return existing_group(self, group).speed_limit; },
          py::arg("group"), "The group's own speed limit in m/s, or None if it follows the system velocity.")
      .def("is_well_formed", &MetricSetd::is_well_formed,
           "Whether the DISP distance over this set is a metric (the relative or the absolute part "
           "spans at least a plane, or holds a sphere of positive radius).")
      .def("require_well_formed", &MetricSetd::require_well_formed,
           "Raise ValueError explaining why the set is not well-formed; do nothing if it is.")
      .def_property_readonly("point_count", &MetricSetd::point_count, "Number of points, all groups and frames.")
      .def_property_readonly("sphere_count", &MetricSetd::sphere_count, "Number of spheres, all groups and frames.")
      .def("reduce_to_hull", &reduced_to_hull_vertices,
           "A new set with every group's relative and absolute points replaced by the vertices of "
           "their convex hull (Qhull); spheres and group speeds unchanged. Every distance and section "
           "length is the same.")
      .def("__repr__", &metric_set_repr);
}

}  // namespace python
}  // namespace dispkin
