// The rows of the C++ bad-input table (tests/cpp/test_bad_input_table.cpp) of one area: MetricSet, the point shapes and
// the convex hull.
#include "rows.hpp"

namespace bad_input {

void metric_set_rows(std::vector<Row>& table) {
  const RowAdder row{table};
  // --- MetricSet ---
  row(
      "MetricSet::add_relative", "NaN point",
      [] {
        MetricSetd s;
        s.add_relative(std::vector<Vector3d>{Vector3d::Zero(), Vector3d(nan_, 0, 0)});
      },
      IA, "points[1] = (nan, 0, 0)");
  row(
      "MetricSet::add_relative", "+inf point",
      [] {
        MetricSetd s;
        s.add_relative(Vector3d(0, inf_, 0));
      },
      IA, "points[0] = (0, inf, 0)");
  row(
      "MetricSet::set_group_speed", "speed above the numeric range (1e13)",
      [] {
        MetricSetd s;
        s.set_group_speed(1, 1e13);
      },
      IA, "speed = 1e+13: must be in [1e-12, 1e12]");
  row(
      "MetricSet::add_relative", "negative group",
      [] {
        MetricSetd s;
        s.add_relative(Vector3d::Zero(), -1);
      },
      IA, "group = -1");
  row(
      "MetricSet::add_absolute", "-inf point",
      [] {
        MetricSetd s;
        s.add_absolute(Vector3d(0, 0, -inf_));
      },
      IA, "points[0] = (0, 0, -inf)");
  row(
      "MetricSet::add_absolute", "point beyond the numeric range (1e13 m)",
      [] {
        MetricSetd s;
        s.add_absolute(Vector3d(0, 1e13, 0));
      },
      IA, "points[0] = (0, 1e+13, 0): must have coordinates within ±1e12 m");
  row(
      "MetricSet::add_absolute", "negative group",
      [] {
        MetricSetd s;
        s.add_absolute(Vector3d::Zero(), -3);
      },
      IA, "group = -3");
  row(
      "MetricSet::add_points", "NaN point",
      [] {
        MetricSetd s;
        s.add_points({Vector3d(nan_, 0, 0)}, Frame::absolute);
      },
      IA, "points[0] = (nan, 0, 0)");
  row(
      "MetricSet::add_sphere", "NaN center",
      [] {
        MetricSetd s;
        s.add_sphere(Vector3d(nan_, 0, 0), 0.1);
      },
      IA, "center = (nan, 0, 0)");
  row(
      "MetricSet::add_sphere", "negative radius",
      [] {
        MetricSetd s;
        s.add_sphere(Vector3d::Zero(), -0.1);
      },
      IA, "radius = -0.1");
  row(
      "MetricSet::add_sphere", "NaN radius",
      [] {
        MetricSetd s;
        s.add_sphere(Vector3d::Zero(), nan_);
      },
      IA, "radius = nan");
  row(
      "MetricSet::add_sphere", "+inf radius",
      [] {
        MetricSetd s;
        s.add_sphere(Vector3d::Zero(), inf_);
      },
      IA, "radius = inf");
  row(
      "MetricSet::add_sphere", "center beyond the numeric range (1e13 m)",
      [] {
        MetricSetd s;
        s.add_sphere(Vector3d(-1e13, 0, 0), 0.1);
      },
      IA, "center = (-1e+13, 0, 0): must have coordinates within ±1e12 m");
  row(
      "MetricSet::add_sphere", "radius beyond the numeric range (1e13 m)",
      [] {
        MetricSetd s;
        s.add_sphere(Vector3d::Zero(), 1e13);
      },
      IA, "radius = 1e+13: must be finite and not negative, at most 1e12 m");
  row(
      "MetricSet::add_sphere", "negative group",
      [] {
        MetricSetd s;
        s.add_sphere(Vector3d::Zero(), 0.1, Frame::relative, -1);
      },
      IA, "group = -1");
  row(
      "MetricSet::set_group_speed", "zero speed",
      [] {
        MetricSetd s;
        s.set_group_speed(1, 0.0);
      },
      IA, "speed = 0");
  row(
      "MetricSet::set_group_speed", "negative speed",
      [] {
        MetricSetd s;
        s.set_group_speed(1, -1.0);
      },
      IA, "speed = -1");
  row(
      "MetricSet::set_group_speed", "NaN speed",
      [] {
        MetricSetd s;
        s.set_group_speed(1, nan_);
      },
      IA, "speed = nan");
  row(
      "MetricSet::set_group_speed", "+inf speed",
      [] {
        MetricSetd s;
        s.set_group_speed(1, inf_);
      },
      IA, "speed = inf");
  row(
      "MetricSet::set_group_speed", "negative group",
      [] {
        MetricSetd s;
        s.set_group_speed(-1, 1.0);
      },
      IA, "group = -1");
  row(
      "MetricSet::require_well_formed", "empty set", [] { MetricSetd().require_well_formed(); }, IA,
      "metric_set = \"MetricSet\": is not well-formed: the set is empty");
  row(
      "MetricSet::require_well_formed", "collinear set", [] { collinear_set().require_well_formed(); }, IA,
      "metric_set = \"MetricSet\": is not well-formed: its relative part (3 objects)");

  // --- shapes ---
  row(
      "shapes::box", "zero edge", [] { shapes::box<double>(Vector3d(0, 1, 1)); }, IA, "size = (0, 1, 1)");
  row(
      "shapes::box", "negative edge", [] { shapes::box<double>(Vector3d(1, -1, 1)); }, IA, "size = (1, -1, 1)");
  row(
      "shapes::box", "NaN edge", [] { shapes::box<double>(Vector3d(1, 1, nan_)); }, IA, "size = (1, 1, nan)");
  row(
      "shapes::box", "+inf center", [] { shapes::box<double>(Vector3d(1, 1, 1), Vector3d(inf_, 0, 0)); }, IA,
      "center = (inf, 0, 0)");
  row(
      "shapes::box", "center beyond the numeric range (1e13 m)",
      [] { shapes::box<double>(Vector3d(1, 1, 1), Vector3d(0, 0, 1e13)); }, IA,
      "center = (0, 0, 1e+13): must have coordinates within ±1e12 m");
  row(
      "shapes::icosahedron", "zero radius", [] { shapes::icosahedron(0.0); }, IA, "radius = 0");
  row(
      "shapes::icosahedron", "negative radius", [] { shapes::icosahedron(-1.0); }, IA, "radius = -1");
  row(
      "shapes::icosahedron", "NaN radius", [] { shapes::icosahedron(nan_); }, IA, "radius = nan");
  row(
      "shapes::icosahedron", "+inf radius", [] { shapes::icosahedron(inf_); }, IA, "radius = inf");
  row(
      "shapes::icosahedron", "NaN center", [] { shapes::icosahedron(1.0, Vector3d(nan_, 0, 0)); }, IA,
      "center = (nan, 0, 0)");
  row(
      "shapes::icosphere", "zero radius", [] { shapes::icosphere(0.0, 1); }, IA, "radius = 0");
  row(
      "shapes::icosphere", "negative subdivisions", [] { shapes::icosphere(1.0, -1); }, IA, "subdivisions = -1");
  row(
      "shapes::icosphere", "too many subdivisions", [] { shapes::icosphere(1.0, 8); }, IA, "subdivisions = 8");
  row(
      "shapes::icosphere", "-inf center", [] { shapes::icosphere(1.0, 1, Vector3d(0, -inf_, 0)); }, IA,
      "center = (0, -inf, 0)");
  row(
      "shapes::spherical_shell", "negative radius", [] { shapes::spherical_shell(-1.0, 10); }, IA, "radius = -1");
  row(
      "shapes::spherical_shell", "count too small", [] { shapes::spherical_shell(1.0, 3); }, IA, "count = 3");
  row(
      "shapes::spherical_shell", "zero count", [] { shapes::spherical_shell(1.0, 0); }, IA, "count = 0");
  row(
      "shapes::spherical_shell", "NaN center", [] { shapes::spherical_shell(1.0, 10, Vector3d(nan_, 0, 0)); }, IA,
      "center = (nan, 0, 0)");

  // --- convex hull ---
  row(
      "convex_hull_vertices", "NaN point",
      [] {
        convex_hull_vertices({Vector3d::Zero(), Vector3d::UnitX(), Vector3d::UnitY(), Vector3d(0, 0, nan_)});
      },
      IA, "points[3] = (0, 0, nan): must be finite");
  row(
      "convex_hull_vertices", "+inf point",
      [] {
        convex_hull_vertices({Vector3d::Zero(), Vector3d::UnitX(), Vector3d::UnitY(), Vector3d(inf_, 0, 1)});
      },
      IA, "points[3] = (inf, 0, 1): must be finite");
  row(
      "convex_hull_vertices", "point beyond the numeric range (1e13 m)",
      [] {
        convex_hull_vertices({Vector3d::Zero(), Vector3d::UnitX(), Vector3d::UnitY(), Vector3d(0, 0, 1e13)});
      },
      IA, "points[3] = (0, 0, 1e+13): must have coordinates within ±1e12 m");
}

}  // namespace bad_input
