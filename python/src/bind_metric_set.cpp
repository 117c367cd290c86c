// Python binding of dispkin/metric_set.hpp (and its hull reduction from convex_hull.hpp): MetricSet.
#include <string>

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "bindings.hpp"
#include "conversions.hpp"
#include "interpreter_lock.hpp"
#include "value_protocol.hpp"
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

// Two groups' points, coordinate by coordinate with `same`.
template <typename Same>
bool same_points(const PointColumns<double>& a, const PointColumns<double>& b, Same same) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (!same(a[i], b[i])) return false;
  return true;
}

template <typename Same>
bool same_spheres(const std::vector<Sphere<double>>& a, const std::vector<Sphere<double>>& b, Same same) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    const Eigen::Matrix<double, 4, 1> x(a[i].center.x(), a[i].center.y(), a[i].center.z(), a[i].radius);
    const Eigen::Matrix<double, 4, 1> y(b[i].center.x(), b[i].center.y(), b[i].center.z(), b[i].radius);
    if (!same(x, y)) return false;
  }
  return true;
}

// The same groups with the same objects in the same order and the same speed limits; `same`
// compares two coordinate vectors, `same_speed` two speed limits.
template <typename Same, typename SameSpeed>
bool same_sets(const MetricSetd& a, const MetricSetd& b, Same same, SameSpeed same_speed) {
  if (a.groups().size() != b.groups().size()) return false;
  for (std::size_t k = 0; k < a.groups().size(); ++k) {
    const MetricGroup<double>& g = a.groups()[k];
    const MetricGroup<double>& h = b.groups()[k];
    if (g.id != h.id || g.speed_limit.has_value() != h.speed_limit.has_value()) return false;
    if (g.speed_limit && !same_speed(*g.speed_limit, *h.speed_limit)) return false;
    if (!same_points(g.relative_points, h.relative_points, same) ||
        !same_points(g.absolute_points, h.absolute_points, same) ||
        !same_spheres(g.relative_spheres, h.relative_spheres, same) ||
        !same_spheres(g.absolute_spheres, h.absolute_spheres, same))
      return false;
  }
  return true;
}

// The state of a pickled MetricSet: per group (id, speed limit or None, relative points,
// absolute points, relative spheres, absolute spheres), spheres as (N, 4) rows (centre, radius).
py::list metric_set_state(const MetricSetd& set) {
  const auto spheres = [](const std::vector<Sphere<double>>& list) {
    py::array_t<double> out({static_cast<py::ssize_t>(list.size()), py::ssize_t{4}});
    double* data = out.mutable_data();
    for (std::size_t i = 0; i < list.size(); ++i) {
      Eigen::Map<Eigen::Vector3d>(data + 4 * i) = list[i].center;
      data[4 * i + 3] = list[i].radius;
    }
    return out;
  };
  py::list groups;
  for (const auto& g : set.groups()) {
    groups.append(py::make_tuple(g.id, g.speed_limit, to_array(g.relative_points), to_array(g.absolute_points),
                                 spheres(g.relative_spheres), spheres(g.absolute_spheres)));
  }
  return groups;
}

// add_points, add_sphere and set_group_speed check every value, as for a set built by hand.
MetricSetd metric_set_from_state(const py::object& state) {
  if (!py::isinstance<py::list>(state) && !py::isinstance<py::tuple>(state))
    throw py::type_error("MetricSet.__setstate__: state: expected a list of groups, got " +
                         echoed(std::string(py::repr(state))));
  MetricSetd set;
  std::size_t k = 0;
  for (const py::handle item : py::reinterpret_borrow<py::sequence>(state)) {
    const StateField group_at("MetricSet", k++, "group");
    const py::tuple g = state_fields(item, 6, group_at);
    const int id = state_cast<int>(g[0], group_at / ".id");
    const std::optional<double> speed = state_cast<std::optional<double>>(g[1], group_at / ".speed_limit");
    if (speed) set.set_group_speed(id, *speed);
    const auto rows = [&](std::size_t i, const char* name, py::ssize_t columns) {
      const StateField at = group_at / ("." + std::string(name));
      const bool sequence =
          py::isinstance<py::tuple>(g[i]) || py::isinstance<py::list>(g[i]) || py::isinstance<py::array>(g[i]);
      const Array a = sequence ? Array::ensure(g[i]) : Array(py::ssize_t{0});
      if (!sequence || !a)
        throw py::type_error(at.message(g[i], "must be an array of shape (N, " + std::to_string(columns) + ")"));
      if (a.size() > 0 && (a.ndim() != 2 || a.shape(1) != columns))
        throw py::value_error(
            at.message(g[i], "must be an array of shape (N, " + std::to_string(columns) + "), not " + shape_string(a)));
      return a;
    };
    for (std::size_t i = 2; i < 4; ++i) {
      const Array a = rows(i, i == 2 ? "relative_points" : "absolute_points", 3);
      std::vector<Eigen::Vector3d> points;
      for (py::ssize_t r = 0; a.size() > 0 && r < a.shape(0); ++r)
        points.emplace_back(Eigen::Map<const Eigen::Vector3d>(a.data() + 3 * r));
      set.add_points(points, i == 2 ? Frame::relative : Frame::absolute, id);
    }
    for (std::size_t i = 4; i < 6; ++i) {
      const Array a = rows(i, i == 4 ? "relative_spheres" : "absolute_spheres", 4);
      for (py::ssize_t r = 0; a.size() > 0 && r < a.shape(0); ++r) {
        const double* x = a.data() + 4 * r;
        set.add_sphere(Eigen::Vector3d(x[0], x[1], x[2]), x[3], i == 4 ? Frame::relative : Frame::absolute, id);
      }
    }
  }
  return set;
}

std::string metric_set_repr(const MetricSetd& set) {
  std::string groups;
  std::string speeds;
  for (const auto& g : set.groups()) {
    groups += (groups.empty() ? "" : ", ") + std::to_string(g.id);
    if (g.speed_limit)
      speeds += (speeds.empty() ? "" : ", ") + std::to_string(g.id) + ": " + float_repr(*g.speed_limit);
  }
  return "MetricSet(groups=[" + groups + "], points=" + std::to_string(set.point_count()) +
         ", spheres=" + std::to_string(set.sphere_count()) + (speeds.empty() ? "" : ", group_speeds={" + speeds + "}") +
         ", well_formed=" + (set.is_well_formed() ? "True" : "False") + ")";
}

}  // namespace

// An empty set and what is added to it: relative and absolute points, spheres, group speeds.
void def_metric_set_building(py::class_<MetricSetd>& metric_set) {
  metric_set.def(py::init<>(), "An empty set.")
      .def(
          "add_relative",
          [](MetricSetd& self, const py::object& pts, int group) {
            require_not_read(&self, "MetricSet.add_relative");
            self.add_points(points(pts, "points", true), Frame::relative, group);
          },
          py::arg("points"), py::arg("group") = 0,
          "Add points that move with the tool: a (3,) array or the rows of an (N, 3) array, body "
          "coordinates, metres.")
      .def(
          "add_absolute",
          [](MetricSetd& self, const py::object& pts, int group) {
            require_not_read(&self, "MetricSet.add_absolute");
            self.add_points(points(pts, "points", true), Frame::absolute, group);
          },
          py::arg("points"), py::arg("group") = 0,
          "Add fixed points of the world (a protected zone): a (3,) array or the rows of an (N, 3) "
          "array, world coordinates, metres.")
      .def(
          "add_sphere",
          [](MetricSetd& self, const py::object& center, double radius, bool absolute, int group) {
            require_not_read(&self, "MetricSet.add_sphere");
            self.add_sphere(vector3(center, "center"), radius, absolute ? Frame::absolute : Frame::relative, group);
          },
          py::arg("center"), py::arg("radius"), py::arg("absolute") = false, py::arg("group") = 0,
          "Add a ball (handled exactly): centre (3,) in body coordinates, or world coordinates if "
          "`absolute`; radius >= 0 in metres.")
      .def(
          "set_group_speed",
          [](MetricSetd& self, int group, double speed) {
            require_not_read(&self, "MetricSet.set_group_speed");
            self.set_group_speed(group, speed);
          },
          py::arg("group"), py::arg("speed"),
          "Give group `group` its own speed limit in m/s (> 0); the group is created if needed. Its "
          "lengths are then weighted by system_velocity / speed.");
}

// What a set holds, group by group, whether it is well formed, and its reduction to the hull.
void def_metric_set_contents(py::class_<MetricSetd>& metric_set) {
  metric_set
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
          "group_speed", [](const MetricSetd& self, int group) { return existing_group(self, group).speed_limit; },
          py::arg("group"), "The group's own speed limit in m/s, or None if it follows the system velocity.")
      .def("is_well_formed", &MetricSetd::is_well_formed,
           "Whether the DISP distance over this set is a metric (the relative or the absolute part "
           "spans at least a plane, or holds a sphere of positive radius).")
      .def("require_well_formed", &MetricSetd::require_well_formed,
           "Raise ValueError explaining why the set is not well-formed; do nothing if it is.")
      .def_property_readonly("point_count", &MetricSetd::point_count, "Number of points, all groups and frames.")
      .def_property_readonly("sphere_count", &MetricSetd::sphere_count, "Number of spheres, all groups and frames.")
      .def(
          "reduce_to_hull",
          [](const MetricSetd& self) {
            const UnlockedIf unlocked(true, self);
            return reduced_to_hull_vertices(self);
          },
          "A new set with every group's relative and absolute points replaced by the vertices of "
          "their convex hull (Qhull); spheres and group speeds unchanged. Every distance and section "
          "length is the same.");
}

// Comparison: exactly (==), or within tolerances (isclose).
void def_metric_set_comparison(py::class_<MetricSetd>& metric_set) {
  metric_set
      .def(
          "__eq__",
          [](const MetricSetd& a, const MetricSetd& b) {
            return same_sets(
                a, b, [](const auto& x, const auto& y) { return x == y; }, [](double x, double y) { return x == y; });
          },
          py::is_operator(),
          "The same groups holding the same points and spheres in the same order, with the same speed limits.")
      .def(
          "isclose",
          [](const MetricSetd& a, const MetricSetd& b, double rel_tol, double abs_tol) {
            require_tolerances(rel_tol, abs_tol);
            return same_sets(
                a, b, [&](const auto& x, const auto& y) { return all_close(x, y, rel_tol, abs_tol); },
                [&](double x, double y) { return isclose(x, y, rel_tol, abs_tol); });
          },
          py::arg("other"), py::kw_only(), py::arg("rel_tol") = 1e-9, py::arg("abs_tol") = 0.0,
          "Like ==, with math.isclose for every coordinate, radius and speed limit.");
}

void bind_metric_set(py::module_& m) {
  py::class_<MetricSetd> metric_set(m, "MetricSet", R"doc(
The metric establishment set: the points and spheres the speed limit applies to.
Relative points and spheres are in body (tool) coordinates and move with the tool; absolute ones
are in world coordinates and stay put (their apparent speed seen from the tool is limited).
Objects belong to groups (non-negative integers, default 0); a group may have its own speed limit.
Lengths in metres.)doc");
  def_metric_set_building(metric_set);
  def_metric_set_contents(metric_set);
  def_metric_set_comparison(metric_set);
  metric_set.def("__repr__", &metric_set_repr);
  def_pickle(metric_set, "MetricSet", &metric_set_state, &metric_set_from_state);
}

}  // namespace python
}  // namespace dispkin
