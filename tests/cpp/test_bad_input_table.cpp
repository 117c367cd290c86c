// The bad-input table, C++ side: every public entry point × every kind of bad input (NaN, ±inf,
// empty, wrong size, zero or negative limits, degenerate sets, unreachable poses, out-of-range
// legs, malformed files, unknown names), one row each. A row asserts the exception type
// (std::invalid_argument / std::runtime_error) AND a fragment of the message
// "<argument> = <value>: <reason>" that names the argument and shows the value.
//
// Rows with `observed` set are the known gaps ("strict xfail"): the entry point does NOT
// reject the input. Such a row passes while the input is still accepted and fails once the
// library starts rejecting it, so that the row is promoted. The Python table and the list in
// tests/BAD_INPUT.md are in tests/python/test_bad_input_table.py.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <limits>
#include <ostream>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include <dispkin/convex_hull.hpp>
#include <dispkin/disp.hpp>
#include <dispkin/frames.hpp>
#include <dispkin/hexapod/hexapod.hpp>
#include <dispkin/metric_set.hpp>
#include <dispkin/planning/overlap.hpp>
#include <dispkin/path/path.hpp>
#include <dispkin/planning/planner.hpp>
#include <dispkin/pose.hpp>
#include <dispkin/profile.hpp>
#include <dispkin/shapes.hpp>
#if defined(DISPKIN_HAS_SERIAL)
#include <dispkin/serial/ptp.hpp>
#include <dispkin/hexapod/hexapod_retiming.hpp>
#include <dispkin/serial/serial_retiming.hpp>
#include <dispkin/serial/serial_arm.hpp>
#endif

namespace {

using namespace dispkin;
using Eigen::Matrix4d;
using Eigen::Quaterniond;
using Eigen::Vector3d;
using hexapod::ForwardOptions;
using hexapod::Hexapod;
using Vector6d = Eigen::Matrix<double, 6, 1>;

const double nan_ = std::numeric_limits<double>::quiet_NaN();
const double inf_ = std::numeric_limits<double>::infinity();
const double pi = 3.14159265358979323846;

enum class Expect { invalid_argument, runtime_error };

struct Row {
  std::string entry;
  std::string bad;
  std::function<void()> call;
  Expect expect;
  std::string fragment;
  std::string observed;  // non-empty: the input is NOT rejected (strict xfail), what happens instead
};

Vector6d v6(double a, double b, double c, double d, double e, double f) {
  Vector6d v;
  v << a, b, c, d, e, f;
  return v;
}

MetricSetd good_set() {
  MetricSetd s;
  s.add_relative(std::vector<Vector3d>{Vector3d::UnitX(), Vector3d::UnitY(), Vector3d::UnitZ()});
  return s;
}

MetricSetd collinear_set() {
  MetricSetd s;
  s.add_relative(std::vector<Vector3d>{Vector3d(0, 0, 0), Vector3d(1, 0, 0), Vector3d(2, 0, 0)});
  return s;
}

Hexapod hexapod() { return Hexapod::symmetric(0.15, 20 * pi / 180, 0.10, 20 * pi / 180, 0.20, 0.15, 0.32, 0.01); }

const Posed A;
const Posed B = Posed::from_xyzuvw(v6(0.1, 0, 0, 0, 0, 0.5));
const Posed C = Posed::from_xyzuvw(v6(0.1, 0.1, 0, 0, 0, 0));
const Twistd XI(Vector3d(0.1, 0, 0), Vector3d(0, 0, 1));

Limits limits(double v, double a, std::optional<double> j) {
  Limits l;
  l.velocity = v;
  l.acceleration = a;
  l.jerk = j;
  return l;
}

std::string replace_once(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

std::string temp_file(const std::string& name, const std::string& content) {
  const std::string path = ::testing::TempDir() + name;
  std::ofstream(path) << content;
  return path;
}

std::vector<Row> rows() {
  const auto IA = Expect::invalid_argument;
  const auto RT = Expect::runtime_error;
  std::vector<Row> r;
  auto row = [&](std::string entry, std::string bad, std::function<void()> call, Expect e, std::string fragment,
                 std::string observed = "") {
    r.push_back({std::move(entry), std::move(bad), std::move(call), e, std::move(fragment), std::move(observed)});
  };
  (void)RT;

  // --- Pose ---
  row(
      "Pose(quaternion, translation)", "NaN quaternion", [] { Posed(Quaterniond(nan_, 0, 0, 0), Vector3d::Zero()); },
      IA, "quaternion (w, x, y, z) = (nan, 0, 0, 0)");
  row(
      "Pose(quaternion, translation)", "+inf translation", [] { Posed(Quaterniond::Identity(), Vector3d(inf_, 0, 0)); },
      IA, "translation = (inf, 0, 0)");
  row(
      "Pose(quaternion, translation)", "-inf translation",
      [] { Posed(Quaterniond::Identity(), Vector3d(0, -inf_, 0)); }, IA, "translation = (0, -inf, 0)");
  row(
      "Pose(quaternion, translation)", "translation beyond the numeric range (1e13 m)",
      [] { Posed(Quaterniond::Identity(), Vector3d(0, 0, 1e13)); }, IA,
      "translation = (0, 0, 1e+13): must have coordinates within ±1e12 m");
  row(
      "Pose::from_xyzuvw", "X beyond the numeric range (1e300 m)",
      [] { Posed::from_xyzuvw((Eigen::Matrix<double, 6, 1>() << 1e300, 0, 0, 0, 0, 0).finished()); }, IA,
      "xyzuvw (X, Y, Z) = (1e+300, 0, 0): must have coordinates within ±1e12 m");
  row(
      "Pose(quaternion, translation)", "zero quaternion", [] { Posed(Quaterniond(0, 0, 0, 0), Vector3d::Zero()); }, IA,
      "quaternion (w, x, y, z) = (0, 0, 0, 0): must be a unit quaternion");
  row(
      "Pose(quaternion, translation)", "non-unit quaternion", [] { Posed(Quaterniond(2, 0, 0, 0), Vector3d::Zero()); },
      IA, "quaternion (w, x, y, z) = (2, 0, 0, 0): must be a unit quaternion");
  row(
      "Pose(rotation, translation)", "scaled rotation",
      [] { Posed(Eigen::Matrix3d(2 * Eigen::Matrix3d::Identity()), Vector3d::Zero()); }, IA,
      "rotation = (2, 0, 0, 0, 2, 0, 0, 0, 2): must be orthonormal with determinant +1");
  row(
      "Pose(rotation, translation)", "reflection (det -1)",
      [] { Posed(Eigen::Matrix3d(Vector3d(1, 1, -1).asDiagonal()), Vector3d::Zero()); }, IA,
      "rotation = (1, 0, 0, 0, 1, 0, 0, 0, -1): must be orthonormal with determinant +1");
  row(
      "Pose(rotation, translation)", "NaN rotation", [] { Posed(Eigen::Matrix3d::Constant(nan_), Vector3d::Zero()); },
      IA, "rotation = (nan, nan, nan");
  row(
      "Pose::from_matrix", "NaN entry",
      [] {
        Matrix4d m = Matrix4d::Identity();
        m(0, 3) = nan_;
        Posed::from_matrix(m);
      },
      IA, "matrix = (1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, nan, 0, 0, 1)");
  row(
      "Pose::from_matrix", "+inf entry",
      [] {
        Matrix4d m = Matrix4d::Identity();
        m(1, 1) = inf_;
        Posed::from_matrix(m);
      },
      IA, "matrix = (1, 0, 0, 0, 0, inf");
  row(
      "Pose::from_matrix", "bad last row",
      [] {
        Matrix4d m = Matrix4d::Identity();
        m(3, 3) = 2;
        Posed::from_matrix(m);
      },
      IA, "matrix last row = (0, 0, 0, 2)");
  row(
      "Pose::from_matrix", "scaled rotation",
      [] {
        Matrix4d m = 2 * Matrix4d::Identity();
        m(3, 3) = 1;
        Posed::from_matrix(m);
      },
      IA, "rotation = (2, 0, 0, 0, 2, 0, 0, 0, 2): must be orthonormal");
  row(
      "Pose::from_xyzuvw", "NaN", [] { Posed::from_xyzuvw(v6(0, 0, 0, nan_, 0, 0)); }, IA,
      "xyzuvw = (0, 0, 0, nan, 0, 0)");
  row(
      "Pose::from_xyzuvw", "+inf", [] { Posed::from_xyzuvw(v6(inf_, 0, 0, 0, 0, 0)); }, IA,
      "xyzuvw = (inf, 0, 0, 0, 0, 0)");
  row(
      "Pose::from_xyzuvw", "NaN pivot", [] { Posed::from_xyzuvw(Vector6d::Zero(), Vector3d(nan_, 0, 0)); }, IA,
      "pivot = (nan, 0, 0)");
  row(
      "Pose::to_xyzuvw", "NaN pivot", [] { B.to_xyzuvw(Vector3d(nan_, 0, 0)); }, IA, "pivot = (nan, 0, 0)");
  row(
      "Pose::to_xyzuvw", "-inf pivot", [] { B.to_xyzuvw(Vector3d(0, 0, -inf_)); }, IA, "pivot = (0, 0, -inf)");
  row(
      "Pose::rotated_about_pivot", "NaN pivot", [] { A.rotated_about_pivot(B, Vector3d(nan_, 0, 0)); }, IA,
      "pivot = (nan, 0, 0)");
  row(
      "Pose::rotated_about_pivot", "+inf pivot", [] { A.rotated_about_pivot(B, Vector3d(0, inf_, 0)); }, IA,
      "pivot = (0, inf, 0)");

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

  // --- DISP functions ---
  row(
      "disp_distance", "empty set", [] { disp_distance(MetricSetd(), A, B); }, IA,
      "metric_set = \"MetricSet\": is not well-formed: the set is empty");
  row(
      "disp_distance", "collinear set", [] { disp_distance(collinear_set(), A, B); }, IA,
      "metric_set = \"MetricSet\": is not well-formed");
  row(
      "disp_distance", "zero system_velocity", [] { disp_distance(good_set(), A, B, 0.0); }, IA, "system_velocity = 0");
  row(
      "disp_distance", "negative system_velocity", [] { disp_distance(good_set(), A, B, -1.0); }, IA,
      "system_velocity = -1");
  row(
      "disp_distance", "NaN system_velocity", [] { disp_distance(good_set(), A, B, nan_); }, IA,
      "system_velocity = nan");
  row(
      "interpolation_from_string", "unknown interpolation", [] { interpolation_from_string("slerp"); }, IA,
      "interpolation = \"slerp\"");
  row(
      "interpolation_from_string", "empty name", [] { interpolation_from_string(""); }, IA, "interpolation = \"\"");
  row(
      "interpolate", "NaN tau", [] { (void)interpolate(A, B, nan_, Interpolation::decoupled); }, IA, "tau = nan",
      "returns a pose whose quaternion and translation are all NaN (noexcept, unchecked; the Python binding rejects "
      "it)");
  row(
      "interpolate", "tau above 1", [] { (void)interpolate(A, B, 2.0, Interpolation::decoupled); }, IA, "tau = 2",
      "extrapolates: the pose at tau = 2 (x = 0.2); tau in [0, 1] is not checked");
  row(
      "section_length", "empty set", [] { section_length(MetricSetd(), A, B, Interpolation::decoupled); }, IA,
      "metric_set = \"MetricSet\": is not well-formed");
  row(
      "section_length", "collinear set", [] { section_length(collinear_set(), A, B, Interpolation::screw); }, IA,
      "metric_set = \"MetricSet\": is not well-formed");
  row(
      "section_length", "NaN pivot",
      [] { section_length(good_set(), A, B, Interpolation::decoupled, Vector3d(nan_, 0, 0)); }, IA,
      "pivot = (nan, 0, 0)");
  row(
      "section_length", "pivot beyond the numeric range (1e13 m)",
      [] { section_length(good_set(), A, B, Interpolation::screw, Vector3d(0, 1e13, 0)); }, IA,
      "pivot = (0, 1e+13, 0): must have coordinates within ±1e12 m");
  row(
      "section_length", "zero system_velocity",
      [] { section_length(good_set(), A, B, Interpolation::decoupled, Vector3d::Zero(), 0.0); }, IA,
      "system_velocity = 0");
  row(
      "section_length", "+inf system_velocity",
      [] { section_length(good_set(), A, B, Interpolation::decoupled, Vector3d::Zero(), inf_); }, IA,
      "system_velocity = inf");
  row(
      "max_point_speed", "negative system_velocity", [] { max_point_speed(good_set(), A, XI, -2.0); }, IA,
      "system_velocity = -2");
  row(
      "max_point_speed", "empty set", [] { (void)max_point_speed(MetricSetd(), A, XI); }, IA,
      "metric_set = \"MetricSet\": is empty");
  row(
      "max_point_speed", "NaN twist",
      [] { (void)max_point_speed(good_set(), A, Twistd(Vector3d(nan_, 0, 0), Vector3d::Zero())); }, IA, "twist");

  // --- Path / JointPath ---
  row(
      "Path::lin", "NaN pivot", [] { Path::lin(A, B, Interpolation::decoupled, Vector3d(nan_, 0, 0)); }, IA,
      "pivot = (nan, 0, 0)");
  // A LIN pivot of 6.3e257 m, beyond the numeric range, was once accepted and Path::sample
  // returned infinities.
  row(
      "Path::lin", "pivot beyond the numeric range (6.3e257 m)",
      [] { Path::lin(A, B, Interpolation::decoupled, Vector3d(117, 6.3e257, 117)); }, IA,
      "pivot = (117, 6.3e+257, 117): must have coordinates within ±1e12 m");
  row(
      "Path::lin", "coinciding poses", [] { Path::lin(A, A); }, IA, "b = (0, 0, 0): start and end poses coincide");
  row(
      "Path::circ", "collinear via",
      [] { Path::circ(A, Posed::from_xyzuvw(v6(0.05, 0, 0, 0, 0, 0)), Posed::from_xyzuvw(v6(0.1, 0, 0, 0, 0, 0))); },
      IA, "via = (0.05, 0, 0): is collinear with the start and end points");
  row(
      "Path::circ", "via 1e-9 m off the line, beyond the end",
      [] { Path::circ(A, Posed::from_xyzuvw(v6(0.2, 1e-9, 0, 0, 0, 0)), Posed::from_xyzuvw(v6(0.1, 0, 0, 0, 0, 0))); },
      IA,
      "via = (0.2, 1e-09, 0): is almost collinear with the start and end points and outside the segment between them");
  row(
      "Path::circ", "via equals start", [] { Path::circ(A, A, C); }, IA,
      "via = (0, 0, 0): coincides with the start point");
  row(
      "Path::circ", "zero tolerance", [] { Path::circ(A, B, C, Vector3d::Zero(), 0.0); }, IA, "tolerance = 0");
  row(
      "Path::circ", "negative tolerance", [] { Path::circ(A, B, C, Vector3d::Zero(), -1e-3); }, IA,
      "tolerance = -0.001");
  row(
      "Path::circ", "NaN tolerance", [] { Path::circ(A, B, C, Vector3d::Zero(), nan_); }, IA, "tolerance = nan");
  row(
      "Path::circ", "NaN pivot", [] { Path::circ(A, B, C, Vector3d(nan_, 0, 0)); }, IA, "pivot = (nan, 0, 0)");
  row(
      "Path::circ", "pivot beyond the numeric range (1e13 m)", [] { Path::circ(A, B, C, Vector3d(1e13, 0, 0)); }, IA,
      "pivot = (1e+13, 0, 0): must have coordinates within ±1e12 m");
  row(
      "Path::spline", "two poses",
      [] {
        Path::spline({A, B});
      },
      IA, "poses = 2: key poses given: a SPLINE needs at least three");
  row(
      "Path::spline", "repeated key pose",
      [] {
        Path::spline({A, B, B, C});
      },
      IA, "poses[2] = (0.1, 0, 0): coincides with the key pose before it");
  row(
      "Path::spline", "zero tolerance",
      [] {
        Path::spline({A, B, C}, Vector3d::Zero(), 0.0);
      },
      IA, "tolerance = 0");
  row(
      "Path::spline", "NaN pivot",
      [] {
        Path::spline({A, B, C}, Vector3d(nan_, 0, 0));
      },
      IA, "pivot = (nan, 0, 0)");
  row(
      "Path::spline", "pivot beyond the numeric range (1e13 m)",
      [] {
        Path::spline({A, B, C}, Vector3d(0, 0, -1e13));
      },
      IA, "pivot = (0, 0, -1e+13): must have coordinates within ±1e12 m");
  row(
      "Path::then (blend)", "negative blend", [] { Path::lin(A, B).then(Path::lin(B, C), -0.01); }, IA,
      "before = -0.01: must be a positive distance");
  row(
      "Path::then (blend)", "NaN after", [] { Path::lin(A, B).then(Path::lin(B, C), 0.01, nan_); }, IA,
      "after = nan: must be a positive distance");
  row(
      "Path::then (blend)", "blend over half the next move", [] { Path::lin(A, B).then(Path::lin(B, C), 0.01, 0.08); },
      IA, "after = 0.08: exceeds half of the move after the via point");
  row(
      "Path::then (blend)", "not joining", [] { Path::lin(A, B).then(Path::lin(C, B), 0.01); }, IA,
      "next = (0.1, 0.1, 0): must start where the path ends");
  row(
      "Path::then", "discontinuous join",
      [] {
        Path p = Path::lin(A, B);
        p.then(Path::lin(C, A));
      },
      IA, "next = (0.1, 0.1, 0): must start where the path ends");
  row(
      "Path::section_lengths", "empty set", [] { Path::lin(A, B).section_lengths(MetricSetd()); }, IA,
      "metric_set = \"MetricSet\": is not well-formed");
  row(
      "Path::sample", "NaN u", [] { (void)Path::lin(A, B).sample(nan_); }, IA, "u = nan",
      "returns the start pose (noexcept; NaN treated as u <= 0)");
  row(
      "Path::sample", "u above 1", [] { (void)Path::lin(A, B).sample(1.5); }, IA, "u = 1.5",
      "clamped to the end pose (documented: \"Clamped outside\")");
  row(
      "Path::sample", "-inf u", [] { (void)Path::lin(A, B).sample(-inf_); }, IA, "u = -inf",
      "clamped to the start pose (documented: \"Clamped outside\")");
  row(
      "JointPath", "NaN joint", [] { JointPath(Eigen::Vector2d(0, nan_), Eigen::Vector2d(0, 1)); }, IA,
      "q_start = (0, nan): must be finite");
  row(
      "JointPath", "size mismatch", [] { JointPath(Eigen::VectorXd::Zero(2), Eigen::VectorXd::Zero(3)); }, IA,
      "q_end size = 3");
  row(
      "JointPath", "empty", [] { JointPath(Eigen::VectorXd(), Eigen::VectorXd()); }, IA,
      "q_start = 0: must have at least one joint");
  row(
      "JointPath::sample", "NaN u", [] { JointPath(Eigen::Vector2d(0, 0), Eigen::Vector2d(1, 1)).sample(nan_); }, IA,
      "u = nan", "returns (nan, nan) (the Python binding rejects it: u = nan: must be finite)");
  row(
      "max_point_speed", "+inf twist",
      [] { (void)max_point_speed(good_set(), A, Twistd(Vector3d(inf_, 0, 0), Vector3d::Zero())); }, IA, "twist");
  row(
      "JointPath::sample", "u above 1", [] { JointPath(Eigen::Vector2d(0, 0), Eigen::Vector2d(1, 1)).sample(2.0); }, IA,
      "u = 2", "clamped, returns (1, 1) (documented: \"u clamped to [0, 1]\")");

  // --- Profile ---
  row(
      "Profile::trapezoid", "v_max whose duration overflows (10 m at 1e-308 m/s)",
      [] { Profile::trapezoid(10, 1e-308, 1); }, IA,
      "v_max = 1e-308: with a_max = 1 over distance = 10: the law's duration overflows");
  row(
      "Profile::scurve", "v_max whose duration overflows (10 m at 1e-308 m/s)",
      [] { Profile::scurve(10, 1e-308, 1, 1); }, IA,
      "v_max = 1e-308: with a_max = 1, j_max = 1 over distance = 10: the law's duration overflows");
  row(
      "Profile::trapezoid", "NaN distance", [] { Profile::trapezoid(nan_, 1, 1); }, IA, "distance = nan");
  row(
      "Profile::trapezoid", "negative distance", [] { Profile::trapezoid(-1, 1, 1); }, IA, "distance = -1");
  row(
      "Profile::trapezoid", "+inf distance", [] { Profile::trapezoid(inf_, 1, 1); }, IA, "distance = inf");
  row(
      "Profile::trapezoid", "zero v_max", [] { Profile::trapezoid(1, 0, 1); }, IA, "v_max = 0");
  row(
      "Profile::trapezoid", "negative a_max", [] { Profile::trapezoid(1, 1, -1); }, IA, "a_max = -1");
  row(
      "Profile::trapezoid", "+inf v_max", [] { Profile::trapezoid(1, inf_, 1); }, IA, "v_max = inf");
  row(
      "Profile::trapezoid", "negative v_start", [] { Profile::trapezoid(1, 1, 1, -0.5); }, IA, "v_start = -0.5");
  row(
      "Profile::trapezoid", "v_end above v_max", [] { Profile::trapezoid(1, 1, 1, 0, 2.0); }, IA, "v_end = 2");
  row(
      "Profile::scurve", "zero j_max", [] { Profile::scurve(1, 1, 1, 0); }, IA, "j_max = 0");
  row(
      "Profile::scurve", "NaN j_max", [] { Profile::scurve(1, 1, 1, nan_); }, IA, "j_max = nan");
  row(
      "Profile::scurve", "negative v_max", [] { Profile::scurve(1, -1, 1, 1); }, IA, "v_max = -1");
  row(
      "Profile::scurve", "NaN distance", [] { Profile::scurve(nan_, 1, 1, 1); }, IA, "distance = nan");
  row(
      "Profile::from_phases", "zero phases",
      [] {
        const double d[] = {1.0};
        Profile::from_phases(d, d, 0, 0, 0, 1, 1, 0);
      },
      IA, "count = 0");
  row(
      "Profile::from_phases", "NaN duration",
      [] {
        const double d[] = {nan_}, j[] = {0.0};
        Profile::from_phases(d, j, 1, 1, 0, 1, 1, 0);
      },
      IA, "durations[0] = nan");
  row(
      "Profile::from_phases", "inf jerk",
      [] {
        const double d[] = {1.0}, j[] = {inf_};
        Profile::from_phases(d, j, 1, 1, 0, 1, 1, 0);
      },
      IA, "jerks[0] = inf");
  row(
      "Profile::from_phases", "negative v_start",
      [] {
        const double d[] = {1.0}, j[] = {0.0};
        Profile::from_phases(d, j, 1, -1, 0, 1, 1, 0);
      },
      IA, "v_start = -1");
  row(
      "Profile::from_phases", "end state not reached",
      [] {
        const double d[] = {1.0}, j[] = {0.0};
        Profile::from_phases(d, j, 1, 1, 0, 2, 1, 0);
      },
      IA, "distance = 2");

  // --- Limits / plan ---
  row(
      "Limits::validate", "zero velocity", [] { limits(0, 1, 10).validate(ProfileKind::scurve); }, IA, "velocity = 0");
  row(
      "Limits::validate", "negative acceleration", [] { limits(1, -1, 10).validate(ProfileKind::scurve); }, IA,
      "acceleration = -1");
  row(
      "Limits::validate", "NaN velocity", [] { limits(nan_, 1, 10).validate(ProfileKind::scurve); }, IA,
      "velocity = nan");
  row(
      "Limits::validate", "+inf acceleration", [] { limits(1, inf_, 10).validate(ProfileKind::scurve); }, IA,
      "acceleration = inf");
  row(
      "Limits::validate", "velocity below the numeric range (1e-13)",
      [] { limits(1e-13, 1, 10).validate(ProfileKind::scurve); }, IA, "velocity = 1e-13: must be in [1e-12, 1e12]");
  row(
      "Limits::validate", "jerk above the numeric range (1e13)",
      [] { limits(1, 1, 1e13).validate(ProfileKind::scurve); }, IA, "jerk = 1e+13: must be in [1e-12, 1e12]");
  row(
      "Limits::validate", "zero jerk", [] { limits(1, 1, 0.0).validate(ProfileKind::scurve); }, IA, "jerk = 0");
  row(
      "Limits::validate", "negative jerk", [] { limits(1, 1, -5.0).validate(ProfileKind::scurve); }, IA, "jerk = -5");
  row(
      "Limits::validate", "scurve without jerk", [] { limits(1, 1, std::nullopt).validate(ProfileKind::scurve); }, IA,
      "jerk is missing: the S-curve profile needs a jerk limit");
  row(
      "Limits::validate", "jerk with trapezoid", [] { limits(1, 1, 10).validate(ProfileKind::trapezoid); }, IA,
      "jerk = 10");
  row(
      "plan", "empty set", [] { plan(Path::lin(A, B), MetricSetd(), limits(0.1, 1, 10)); }, IA,
      "metric_set = \"MetricSet\": is not well-formed");
  row(
      "plan", "collinear set", [] { plan(Path::lin(A, B), collinear_set(), limits(0.1, 1, 10)); }, IA,
      "metric_set = \"MetricSet\": is not well-formed");
  row(
      "plan", "zero velocity", [] { plan(Path::lin(A, B), good_set(), limits(0, 1, 10)); }, IA, "velocity = 0");
  row(
      "plan", "NaN jerk", [] { plan(Path::lin(A, B), good_set(), limits(0.1, 1, nan_)); }, IA, "jerk = nan");
  row(
      "plan(options)", "too many min lengths",
      [] {
        PlanOptions o;
        o.min_section_lengths = {0.1, 0.2};
        plan(Path::lin(A, B), good_set(), limits(0.1, 1, 10), ProfileKind::scurve, o);
      },
      IA, "min_section_lengths size = 2: must be 0 or the path's section count 1");
  row(
      "plan(options)", "negative min length",
      [] {
        PlanOptions o;
        o.min_section_lengths = {-0.5};
        plan(Path::lin(A, B), good_set(), limits(0.1, 1, 10), ProfileKind::scurve, o);
      },
      IA, "min_section_lengths[0] = -0.5");
  row(
      "plan(options)", "NaN min length",
      [] {
        PlanOptions o;
        o.min_section_lengths = {nan_};
        plan(Path::lin(A, B), good_set(), limits(0.1, 1, 10), ProfileKind::scurve, o);
      },
      IA, "min_section_lengths[0] = nan");
  row(
      "plan(options)", "+inf min length",
      [] {
        PlanOptions o;
        o.min_section_lengths = {inf_};
        plan(Path::lin(A, B), good_set(), limits(0.1, 1, 10), ProfileKind::scurve, o);
      },
      IA, "min_section_lengths[0] = inf");

  row(
      "OverlappedTrajectory", "negative overlap",
      [] {
        const Trajectory t = plan(Path::lin(A, B), good_set(), limits(0.1, 1, 10));
        OverlappedTrajectory(t, plan(Path::lin(B, C), good_set(), limits(0.1, 1, 10)), -0.5);
      },
      IA, "overlap = -0.5");
  row(
      "OverlappedTrajectory", "NaN overlap",
      [] {
        const Trajectory t = plan(Path::lin(A, B), good_set(), limits(0.1, 1, 10));
        OverlappedTrajectory(t, plan(Path::lin(B, C), good_set(), limits(0.1, 1, 10)), nan_);
      },
      IA, "overlap = nan");
  row(
      "OverlappedTrajectory", "overlap longer than a move",
      [] {
        const Trajectory t = plan(Path::lin(A, B), good_set(), limits(0.1, 1, 10));
        OverlappedTrajectory(t, plan(Path::lin(B, C), good_set(), limits(0.1, 1, 10)), 100.0);
      },
      IA, "overlap = 100: must be between 0 and the shorter move's duration");
  row(
      "OverlappedTrajectory", "moves not joining",
      [] {
        const Trajectory t = plan(Path::lin(A, B), good_set(), limits(0.1, 1, 10));
        OverlappedTrajectory(t, plan(Path::lin(C, B), good_set(), limits(0.1, 1, 10)), 0.1);
      },
      IA, "after = (0.1, 0.1, 0): must start where `before` ends");
  row(
      "Trajectory::stopped_at", "NaN time",
      [] { plan(Path::lin(A, B), good_set(), limits(0.1, 1, 10)).stopped_at(nan_); }, IA, "t = nan: must be finite");
  row(
      "Trajectory::with_override", "factor 0",
      [] { plan(Path::lin(A, B), good_set(), limits(0.1, 1, 10)).with_override(0.1, 0.0); }, IA,
      "factor = 0: must be in [0.001, 10]");
  row(
      "Trajectory::with_override", "NaN factor",
      [] { plan(Path::lin(A, B), good_set(), limits(0.1, 1, 10)).with_override(0.1, nan_); }, IA, "factor = nan");
  row(
      "Trajectory::resumed_at", "not stopped",
      [] { plan(Path::lin(A, B), good_set(), limits(0.1, 1, 10)).resumed_at(0.1); }, IA,
      "t = 0.1: resumes a stopped trajectory only");
  row(
      "Trajectory::stopped_at", "a re-timed law (limits unknown)",
      [] {
        const Trajectory t = plan(Path::lin(A, B), good_set(), limits(0.1, 1, 10));
        t.with_time_law(t.time_law()).stopped_at(0.1);
      },
      IA, "stopped_at: the trajectory holds no time-law limits");
  // --- Hexapod ---
  row(
      "Hexapod(...)", "NaN base joint",
      [] {
        Hexapod h = hexapod();
        Hexapod::Joints b = h.base_joints();
        b(0, 0) = nan_;
        Hexapod(b, h.platform_joints(), h.leg_min(), h.leg_max(), h.leg_speed());
      },
      IA, "base_joints = (nan, -0.02604722665, 0");
  row(
      "Hexapod(...)", "+inf platform joint",
      [] {
        Hexapod h = hexapod();
        Hexapod::Joints p = h.platform_joints();
        p(2, 5) = inf_;
        Hexapod(h.base_joints(), p, h.leg_min(), h.leg_max(), h.leg_speed());
      },
      IA, "platform_joints = (0.0642787609687, -0.0766044443119, 0");
  row(
      "Hexapod(...)", "base joint beyond the numeric range (1e13 m)",
      [] {
        Hexapod h = hexapod();
        Hexapod::Joints b = h.base_joints();
        b(1, 2) = 1e13;
        Hexapod(b, h.platform_joints(), h.leg_min(), h.leg_max(), h.leg_speed());
      },
      IA, "must have coordinates within ±1e12 m");
  row(
      "Hexapod(...)", "collinear base joints",
      [] {
        Hexapod h = hexapod();
        Hexapod::Joints b = Hexapod::Joints::Zero();
        b.row(0).setLinSpaced(0.0, 1.0);
        Hexapod(b, h.platform_joints(), h.leg_min(), h.leg_max(), h.leg_speed());
      },
      IA, "base_joints = (0, 0, 0, 0.2, 0, 0, 0.4, 0, 0, 0.6, 0, 0, 0.8, 0, 0, 1, 0, 0): must not be collinear");
  row(
      "Hexapod(...)", "leg_max below leg_min",
      [] {
        Hexapod h = hexapod();
        Hexapod::Legs mx = h.leg_max();
        mx(3) = 0.1;
        Hexapod(h.base_joints(), h.platform_joints(), h.leg_min(), mx, h.leg_speed());
      },
      IA, "leg_max[3] = 0.1");
  row(
      "Hexapod(...)", "negative leg_min",
      [] {
        Hexapod h = hexapod();
        Hexapod::Legs mn = h.leg_min();
        mn(0) = -0.1;
        Hexapod(h.base_joints(), h.platform_joints(), mn, h.leg_max(), h.leg_speed());
      },
      IA, "leg_min[0] = -0.1");
  row(
      "Hexapod(...)", "zero leg_speed",
      [] {
        Hexapod h = hexapod();
        Hexapod::Legs s = h.leg_speed();
        s(5) = 0.0;
        Hexapod(h.base_joints(), h.platform_joints(), h.leg_min(), h.leg_max(), s);
      },
      IA, "leg_speed[5] = 0");
  row(
      "Hexapod(...)", "NaN leg_max",
      [] {
        Hexapod h = hexapod();
        Hexapod::Legs mx = h.leg_max();
        mx(1) = nan_;
        Hexapod(h.base_joints(), h.platform_joints(), h.leg_min(), mx, h.leg_speed());
      },
      IA, "leg_max[1] = nan");
  row(
      "Hexapod(...)", "unreachable home",
      [] {
        Hexapod h = hexapod();
        Hexapod(h.base_joints(), h.platform_joints(), h.leg_min(), h.leg_max(), h.leg_speed(),
                Posed(Quaterniond::Identity(), Vector3d(0, 0, 5)));
      },
      IA, "home", "accepted: home at z = 5 m (legs ~5 m, range [0.15, 0.32]) is not checked against the leg ranges");
  row(
      "Hexapod::symmetric", "zero base_radius", [] { Hexapod::symmetric(0.0, 0.3, 0.1, 0.3, 0.2, 0.1, 0.3, 0.01); }, IA,
      "base_radius = 0");
  row(
      "Hexapod::symmetric", "NaN height", [] { Hexapod::symmetric(0.15, 0.3, 0.1, 0.3, nan_, 0.1, 0.3, 0.01); }, IA,
      "height = nan");
  row(
      "Hexapod::symmetric", "negative leg_speed", [] { Hexapod::symmetric(0.15, 0.3, 0.1, 0.3, 0.2, 0.1, 0.3, -0.01); },
      IA, "leg_speed[0] = -0.01");
  row(
      "Hexapod::symmetric", "+inf platform_radius",
      [] { Hexapod::symmetric(0.15, 0.3, inf_, 0.3, 0.2, 0.1, 0.3, 0.01); }, IA, "platform_radius = inf");
  row(
      "Hexapod::symmetric", "negative base_gap", [] { Hexapod::symmetric(0.15, -0.3, 0.1, 0.3, 0.2, 0.1, 0.3, 0.01); },
      IA, "base_gap = -0.3");
  row(
      "Hexapod::symmetric", "both gaps zero", [] { Hexapod::symmetric(0.15, 0.0, 0.1, 0.0, 0.2, 0.1, 0.3, 0.01); }, IA,
      "base_gap = 0");
  row(
      "Hexapod::from_json", "truncated JSON", [] { Hexapod::from_json("{"); }, IA,
      "description = \"<text>\": is not JSON");
  row(
      "Hexapod::from_json", "empty text", [] { Hexapod::from_json(""); }, IA, "description = \"<text>\": is not JSON");
  row(
      "Hexapod::from_json", "not an object", [] { Hexapod::from_json("[1, 2]"); }, IA,
      "description = \"[1,2]\": must be a JSON object");
  row(
      "Hexapod::from_json", "negative speed",
      [] { Hexapod::from_json(replace_once(hexapod().to_json(), "\"speed\": 0.01", "\"speed\": -1.0")); }, IA,
      "leg_speed[0] = -1: must be in [1e-12, 1e12]");
  row(
      "Hexapod::from_json", "string speed",
      [] { Hexapod::from_json(replace_once(hexapod().to_json(), "\"speed\": 0.01", "\"speed\": \"fast\"")); }, IA,
      "legs[0].speed = \"fast\": must be a number");
  row(
      "Hexapod::from_json", "NaN literal",
      [] { Hexapod::from_json(replace_once(hexapod().to_json(), "\"speed\": 0.01", "\"speed\": NaN")); }, IA,
      "description = \"<text>\": is not JSON");
  row(
      "Hexapod::from_json", "wrong format tag",
      [] { Hexapod::from_json(replace_once(hexapod().to_json(), "\"dispkin.hexapod\"", "\"urdf\"")); }, IA,
      "format = \"urdf\": must be");
  row(
      "Hexapod::load", "missing file", [] { Hexapod::load("/nonexistent/hexapod.json"); }, IA,
      "path = \"/nonexistent/hexapod.json\": cannot be opened");
  row(
      "Hexapod::load", "malformed file",
      [] {
        const std::string path =
            temp_file("dispkin_bad_input_malformed.json", "{\"format\": \"dispkin.hexapod\", \"legs\": [");
        try {
          Hexapod::load(path);
        } catch (...) {
          std::remove(path.c_str());
          throw;
        }
        std::remove(path.c_str());
      },
      IA, "dispkin_bad_input_malformed.json: description = \"<text>\": is not JSON");
  // Hostile hexapod descriptions: depth, size, unknown keys, numbers beyond the range, bytes.
  row(
      "Hexapod::from_json", "arrays nested 10⁵ deep",
      [] { Hexapod::from_json(std::string(100000, '[') + std::string(100000, ']')); }, IA,
      "description nesting depth = 101: arrays and objects nest at most 100 deep");
  row(
      "Hexapod::from_json", "objects nested 10⁵ deep",
      [] {
        std::string text;
        for (int i = 0; i < 100000; ++i) text += "{\"a\":";
        Hexapod::from_json(text + "1" + std::string(100000, '}'));
      },
      IA, "description nesting depth = 101");
  row(
      "Hexapod::from_json", "text over 1 MiB", [] { Hexapod::from_json(std::string((1 << 20) + 1, ' ')); }, IA,
      "description size = 1048577: more than 1048576 bytes, the limit of a hexapod description");
  row(
      "Hexapod::from_json", "10⁴ legs (message not echoing them)",
      [] {
        std::string legs = "[";
        for (int i = 0; i < 10000; ++i) legs += std::string(i ? "," : "") + "{\"min\": 0.1}";
        Hexapod::from_json("{\"format\": \"dispkin.hexapod\", \"version\": 1, \"legs\": " + legs + "]}");
      },
      IA, ", … 10000 items]\": must be an array of 6 leg objects");
  row(
      "Hexapod::from_json", "misspelt per-leg key",
      [] { Hexapod::from_json(replace_once(hexapod().to_json(), "\"speed\"", "\"sped\"")); }, IA,
      "legs[0].sped = 0.01: unknown key (allowed here: base, platform, min, max, speed)");
  row(
      "Hexapod::from_json", "unknown top-level key",
      [] { Hexapod::from_json(replace_once(hexapod().to_json(), "\"units\"", "\"leg_speed\": -1, \"units\"")); }, IA,
      "leg_speed = -1: unknown key (allowed here: format, version, units, legs, home)");
  row(
      "Hexapod::from_json", "leg speed 5e-324",
      [] { Hexapod::from_json(replace_once(hexapod().to_json(), "\"speed\": 0.01", "\"speed\": 5e-324")); }, IA,
      "leg_speed[0] = 4.94065645841e-324: must be in [1e-12, 1e12]");
  row(
      "Hexapod::from_json", "leg speed 1e300",
      [] { Hexapod::from_json(replace_once(hexapod().to_json(), "\"speed\": 0.01", "\"speed\": 1e300")); }, IA,
      "leg_speed[0] = 1e+300: must be in [1e-12, 1e12]");
  row(
      "Hexapod::from_json", "leg max 1e300",
      [] { Hexapod::from_json(replace_once(hexapod().to_json(), "\"max\": 0.32", "\"max\": 1e300")); }, IA,
      "leg_max[0] = 1e+300: must be at most 1e12 m");
  row(
      "Hexapod::from_json", "invalid UTF-8 in a string",
      [] { Hexapod::from_json(replace_once(hexapod().to_json(), "\"m, m/s\"", "\"m\xff\xfe\"")); }, IA,
      "invalid string: ill-formed UTF-8 byte; last read: '\"m\\xff");
  row(
      "Hexapod::forward", "NaN legs",
      [] {
        Hexapod::Legs l = Hexapod::Legs::Constant(0.2);
        l(0) = nan_;
        hexapod().forward(l);
      },
      IA, "legs[0] = nan");
  row(
      "Hexapod::forward", "negative legs", [] { hexapod().forward(Hexapod::Legs(Hexapod::Legs::Constant(-0.2))); }, IA,
      "legs[0] = -0.2");
  row(
      "Hexapod::forward", "zero tolerance",
      [] {
        ForwardOptions o;
        o.tolerance = 0;
        Hexapod h = hexapod();
        h.forward(Hexapod::Legs(Hexapod::Legs::Constant(0.2)), h.home(), o);
      },
      IA, "tolerance = 0");
  row(
      "Hexapod::forward", "wrong size q (5)",
      [] {
        const Hexapod h = hexapod();
        h.forward(Eigen::VectorXd(Eigen::VectorXd::Constant(5, 0.2)));
      },
      IA, "q size = 5: a hexapod has 6 legs");
  row(
      "Hexapod::forward", "out-of-range legs", [] { hexapod().forward(Hexapod::Legs(Hexapod::Legs::Constant(5.0))); },
      IA, "legs");
  row(
      "Hexapod::require_reachable", "unreachable pose",
      [] { hexapod().require_reachable(Posed(Quaterniond::Identity(), Vector3d(0, 0, 5))); }, IA,
      "leg 0 length = 5.00095177608: outside the leg's range [0.15, 0.32]");
  row(
      "Hexapod::check_trajectory", "zero dt",
      [] {
        Hexapod h = hexapod();
        h.check_trajectory(plan(Path::lin(h.home(), h.home() * B), good_set(), limits(0.1, 1, 10)), 0.0);
      },
      IA, "dt = 0");
  row(
      "Hexapod::check_trajectory", "negative dt",
      [] {
        Hexapod h = hexapod();
        h.check_trajectory(plan(Path::lin(h.home(), h.home() * B), good_set(), limits(0.1, 1, 10)), -0.01);
      },
      IA, "dt = -0.01");
  row(
      "Hexapod::check_trajectory", "NaN dt",
      [] {
        Hexapod h = hexapod();
        h.check_trajectory(plan(Path::lin(h.home(), h.home() * B), good_set(), limits(0.1, 1, 10)), nan_);
      },
      IA, "dt = nan");
  row(
      "Hexapod::check_trajectory", "+inf dt",
      [] {
        Hexapod h = hexapod();
        h.check_trajectory(plan(Path::lin(h.home(), h.home() * B), good_set(), limits(0.1, 1, 10)), inf_);
      },
      IA, "dt = inf");
  row(
      "Hexapod::add_leg_speed_group", "negative group",
      [] {
        MetricSetd s = good_set();
        hexapod().add_leg_speed_group(s, -1);
      },
      IA, "group = -1");
  row(
      "Hexapod::leg_rate_bounds", "zero tolerance",
      [] {
        Hexapod h = hexapod();
        h.leg_rate_bounds(Path::lin(h.home(), h.home() * B).sections().front(), 0.0);
      },
      IA, "tolerance = 0: must be in (0, 1]");
  row(
      "Hexapod::leg_rate_bounds", "NaN tolerance",
      [] {
        Hexapod h = hexapod();
        h.leg_rate_bounds(Path::lin(h.home(), h.home() * B).sections().front(), nan_);
      },
      IA, "tolerance = nan");
  row(
      "Hexapod::leg_rate_bounds", "tolerance above 1",
      [] {
        Hexapod h = hexapod();
        h.leg_rate_bounds(Path::lin(h.home(), h.home() * B).sections().front(), 1.5);
      },
      IA, "tolerance = 1.5");
  row(
      "Hexapod::leg_section_lengths", "zero system_velocity",
      [] {
        Hexapod h = hexapod();
        h.leg_section_lengths(Path::lin(h.home(), h.home() * B), 0.0);
      },
      IA, "system_velocity = 0");
  row(
      "Hexapod::leg_section_lengths", "NaN system_velocity",
      [] {
        Hexapod h = hexapod();
        h.leg_section_lengths(Path::lin(h.home(), h.home() * B), nan_);
      },
      IA, "system_velocity = nan");
  row(
      "Hexapod::leg_section_lengths", "+inf system_velocity",
      [] {
        Hexapod h = hexapod();
        h.leg_section_lengths(Path::lin(h.home(), h.home() * B), inf_);
      },
      IA, "system_velocity = inf");
  row(
      "Hexapod::joint_metric", "negative velocity",
      [] {
        Hexapod h = hexapod();
        h.joint_metric(Path::lin(h.home(), h.home() * B), limits(-1, 1, 10));
      },
      IA, "system_velocity = -1");

  // --- WorkToolFrames ---
  row(
      "WorkToolFrames::add_tool_envelope", "zero radius",
      [] {
        MetricSetd s;
        WorkToolFrames().add_tool_envelope(s, 0.0);
      },
      IA, "radius = 0");
  row(
      "WorkToolFrames::add_tool_envelope", "NaN radius",
      [] {
        MetricSetd s;
        WorkToolFrames().add_tool_envelope(s, nan_, Envelope::sphere);
      },
      IA, "radius = nan");
  row(
      "WorkToolFrames::add_tool_envelope", "negative group",
      [] {
        MetricSetd s;
        WorkToolFrames().add_tool_envelope(s, 0.1, Envelope::icosahedron, -2);
      },
      IA, "group = -2");
  row(
      "WorkToolFrames::add_work_envelope", "negative radius",
      [] {
        MetricSetd s;
        WorkToolFrames().add_work_envelope(s, -0.1);
      },
      IA, "radius = -0.1");
  row(
      "WorkToolFrames::add_work_envelope", "+inf radius",
      [] {
        MetricSetd s;
        WorkToolFrames().add_work_envelope(s, inf_, Envelope::sphere);
      },
      IA, "radius = inf");
  row(
      "WorkToolFrames::platform_pose_xyzuvw", "NaN U",
      [] { WorkToolFrames().platform_pose_xyzuvw(v6(0, 0, 0, nan_, 0, 0)); }, IA, "xyzuvw = (0, 0, 0, nan, 0, 0)");
#if defined(DISPKIN_HAS_SERIAL)
  // --- SerialArm (tests/data/urdf/arm_*.urdf) ---
  using serial::PtpOptions;
  using serial::SerialArm;
  static const std::string urdf = std::string(DISPKIN_SOURCE_DIR) + "/tests/data/urdf/";
  const auto arm = [] { return SerialArm::from_urdf_file(urdf + "arm_planar_two_link.urdf", "base", "link2"); };
  const Eigen::Vector2d q0 = Eigen::Vector2d::Zero();
  row(
      "SerialArm::from_urdf_file", "missing file", [] { SerialArm::from_urdf_file("/nonexistent/arm.urdf", "a", "b"); },
      IA, "path = \"/nonexistent/arm.urdf\": cannot be opened");
  row(
      "SerialArm::from_urdf_file", "not XML",
      [] { SerialArm::from_urdf_file(urdf + "arm_bad_not_xml.urdf", "base", "l1"); }, IA,
      "URDF: not a valid robot description");
  row(
      "SerialArm::from_urdf_file", "unknown base link",
      [] { SerialArm::from_urdf_file(urdf + "arm_planar_two_link.urdf", "nowhere", "link2"); }, IA,
      "base_link = \"nowhere\": is not a link of robot \"planar_two_link\"");
  row(
      "SerialArm::from_urdf_file", "unknown tip link",
      [] { SerialArm::from_urdf_file(urdf + "arm_planar_two_link.urdf", "base", "nowhere"); }, IA,
      "tip_link = \"nowhere\": is not a link");
  row(
      "SerialArm::from_urdf_file", "base not an ancestor",
      [] { SerialArm::from_urdf_file(urdf + "arm_planar_two_link.urdf", "link2", "link1"); }, IA,
      "base_link = \"link2\": is not an ancestor of tip_link \"link1\"");
  row(
      "SerialArm::from_urdf_file", "prismatic joint on the path",
      [] { SerialArm::from_urdf_file(urdf + "arm_bad_prismatic.urdf", "base", "l2"); }, IA,
      "joint \"slide\" between \"l1\" and \"l2\": only revolute, continuous and fixed joints");
  row(
      "SerialArm::from_urdf_file", "lower above upper",
      [] { SerialArm::from_urdf_file(urdf + "arm_bad_limits.urdf", "base", "l1"); }, IA,
      "joint \"j1\" limit (lower, upper) = (1, -1): needs lower < upper");
  row(
      "SerialArm::from_urdf_file", "zero axis",
      [] { SerialArm::from_urdf_file(urdf + "arm_bad_zero_axis.urdf", "base", "l1"); }, IA,
      "joint \"j1\" axis = (0, 0, 0): must not be zero");
  row(
      "SerialArm::from_urdf_file", "negative mass",
      [] { SerialArm::from_urdf_file(urdf + "arm_bad_negative_mass.urdf", "base", "l1"); }, IA,
      "link \"l1\" inertial mass = -1");
  row(
      "SerialArm::from_urdf_string", "empty text", [] { SerialArm::from_urdf_string("", "base", "link2"); }, IA,
      "URDF: not a valid robot description");
  row(
      "SerialArm::from_urdf_string", "'%' in an attribute (urdfdom printf format)",
      [] { SerialArm::from_urdf_string("<robot name=\"r\"><link name=\"a%n\"/></robot>", "a", "b"); }, IA,
      "URDF line 1, column 23, <link> attribute \"name\" = \"a%n\": contains '%'");
  // The same '%' as TinyXML decodes character references: zero-padded, wrapping at 2³² (its
  // multiplier is 32 bits), and the low byte of the code point in a document declared Latin-1.
  for (const char* spelling : {"&#37;", "&#x25;", "&#000000000000000000000000037;", "&#x0000000000000000000025;",
                               "&#x100000025;", "&#x1000000000000025;"}) {
    row(
        "SerialArm::from_urdf_string", std::string("'%' as the character reference ") + spelling,
        [spelling] {
          SerialArm::from_urdf_string(std::string("<robot name=\"r\"><link name=\"a") + spelling + "n\"/></robot>", "a",
                                      "b");
        },
        IA, "<link> attribute \"name\" = \"a%n\": contains '%'");
  }
  row(
      "SerialArm::from_urdf_string", "'%' as the low byte of &#293; in a Latin-1 document",
      [] {
        SerialArm::from_urdf_string(
            "<?xml version=\"1.0\" encoding=\"ISO-8859-1\"?><robot name=\"r\"><link name=\"a&#293;n\"/></robot>", "a",
            "b");
      },
      IA, "<link> attribute \"name\" = \"a%n\": contains '%'");
  row(
      "SerialArm::from_urdf_string", "'%' in element text (CDATA)",
      [] {
        SerialArm::from_urdf_string("<robot name=\"r\"><link name=\"a\"><![CDATA[%n%n]]></link></robot>", "a", "b");
      },
      IA, "text = \"%n%n\": contains '%'");
  row(
      "SerialArm::from_urdf_string", "empty base link", [] { SerialArm::from_urdf_string("<robot/>", "", "link2"); },
      IA, "base_link = \"\": must name a link");
  // Hostile URDFs: depth, attribute count, numbers, inertias, the joint graph.
  const auto planar_text = [] {
    std::ifstream in(urdf + "arm_planar_two_link.urdf");
    return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  };
  row(
      "SerialArm::from_urdf_string", "elements nested 4·10⁴ deep",
      [planar_text] {
        std::string deep;
        for (int i = 0; i < 40000; ++i) deep += "<a>";
        for (int i = 0; i < 40000; ++i) deep += "</a>";
        SerialArm::from_urdf_string(
            replace_once(planar_text(), "<link name=\"base\"/>", "<link name=\"base\"/>" + deep), "base", "link2");
      },
      IA, "nests deeper than 100 elements");
  row(
      "SerialArm::from_urdf_string", "4·10⁴ attributes on <robot>",
      [planar_text] {
        std::string attributes;
        for (int i = 0; i < 40000; ++i) attributes += " a" + std::to_string(i) + "=\"1\"";
        SerialArm::from_urdf_string(replace_once(planar_text(), "<robot name=\"planar_two_link\"",
                                                 "<robot name=\"planar_two_link\"" + attributes),
                                    "base", "link2");
      },
      IA, "has more than 100 attributes");
  row(
      "SerialArm::from_urdf_string", "NaN mass",
      [planar_text] {
        SerialArm::from_urdf_string(replace_once(planar_text(), "<mass value=\"2.0\"/>", "<mass value=\"nan\"/>"),
                                    "base", "link2");
      },
      IA, "link \"link1\" inertial mass = nan: must be finite");
  row(
      "SerialArm::from_urdf_string", "infinite ixx",
      [planar_text] {
        SerialArm::from_urdf_string(replace_once(planar_text(), "ixx=\"0.11\"", "ixx=\"inf\""), "base", "link2");
      },
      IA, "link \"link1\" inertial inertia ixx = inf: must be finite");
  row(
      "SerialArm::torques", "a link breaking the triangle inequality",
      [planar_text] {
        SerialArm::from_urdf_string(replace_once(planar_text(), "ixx=\"0.11\"", "ixx=\"0.5\""), "base", "link2")
            .static_torques(Eigen::Vector2d::Zero());
      },
      IA, "is not the inertia of a body: its principal moments break the triangle inequality");
  row(
      "SerialArm::from_urdf_string", "joint origin 1e300 m",
      [planar_text] {
        SerialArm::from_urdf_string(replace_once(planar_text(), "<origin xyz=\"0 0 0.3\"", "<origin xyz=\"0 0 1e300\""),
                                    "base", "link2");
      },
      IA, "joint \"mount_joint\" origin xyz = (0, 0, 1e+300): must be within ±1e12");
  row(
      "SerialArm::from_urdf_string", "a link with two parent joints",
      [planar_text] {
        SerialArm::from_urdf_string(
            replace_once(
                planar_text(), "</robot>",
                "<joint name=\"again\" type=\"fixed\"><parent link=\"base\"/><child link=\"link2\"/></joint></robot>"),
            "base", "link2");
      },
      IA, "is the child of two joints");
  row(
      "SerialArm::inverse_solutions", "2π copies of ±100 rad limits",
      [] {
        const SerialArm ur = SerialArm::from_urdf_file(urdf + "arm_ur5e_dh.urdf", "base_link", "tool0");
        JointLimits l = ur.joint_limits();
        l.lower.setConstant(-100.0);
        l.upper.setConstant(100.0);
        const SerialArm wide = ur.with_joint_limits(l);
        serial::InverseOptions o;
        o.offer_equivalents = true;
        wide.inverse_solutions(wide.forward((Eigen::VectorXd(6) << 0.3, -1.2, 1.5, -1.9, -1.57, 0.2).finished()), o);
      },
      IA, "offer_equivalents = \"true\": asks for the 2π copies of the 8 solutions inside the joint limits");
  row(
      "SerialArm::from_urdf_string", "tip equal to base", [] { SerialArm::from_urdf_string("<robot/>", "a", "a"); }, IA,
      "tip_link = \"a\": must differ from base_link");
  row(
      "SerialArm::forward", "wrong size q (3)", [arm] { arm().forward(Eigen::Vector3d::Zero()); }, IA,
      "q = (0, 0, 0): expected 2 joint values, got 3");
  row(
      "SerialArm::forward", "NaN q", [arm] { arm().forward(Eigen::Vector2d(0, nan_)); }, IA,
      "q = (0, nan): must be finite");
  row(
      "SerialArm::jacobian", "+inf q", [arm] { arm().jacobian(Eigen::Vector2d(inf_, 0)); }, IA,
      "q = (inf, 0): must be finite");
  row(
      "SerialArm::torques", "wrong size qd (1)", [arm, q0] { arm().torques(q0, Eigen::VectorXd::Zero(1), q0); }, IA,
      "qd = (0): expected 2 joint values, got 1");
  row(
      "SerialArm::torques", "NaN qdd", [arm, q0] { arm().torques(q0, q0, Eigen::Vector2d(nan_, 0)); }, IA,
      "qdd = (nan, 0): must be finite");
  row(
      "SerialArm::static_torques", "empty q", [arm] { arm().static_torques(Eigen::VectorXd()); }, IA,
      "q = (): expected 2 joint values, got 0");
  row(
      "SerialArm::set_gravity", "NaN gravity",
      [arm] {
        SerialArm a = arm();
        a.set_gravity(Vector3d(0, 0, nan_));
      },
      IA, "gravity = (0, 0, nan): must be finite");
  row(
      "SerialArm::inverse_solutions", "zero max_attempts",
      [arm] {
        serial::InverseOptions o;
        o.max_attempts = 0;
        arm().inverse_solutions(Posed(), o);
      },
      IA, "max_attempts = 0: must be greater than zero");
  row(
      "SerialArm::inverse_solutions", "negative time_budget",
      [arm] {
        serial::InverseOptions o;
        o.time_budget = -1;
        arm().inverse_solutions(Posed(), o);
      },
      IA, "time_budget = -1: must be finite and greater than zero");
  row(
      "SerialArm::configuration", "not a 6R arm", [arm, q0] { arm().configuration(q0); }, IA,
      "dof = 2: configuration flags are defined for 6R arms");
  row(
      "serial::nearest", "no solutions", [] { serial::nearest({}, Eigen::VectorXd::Zero(6)); }, IA,
      "solutions = 0: must not be empty");
  row(
      "serial::nearest", "wrong size q_ref",
      [] { serial::nearest({Eigen::VectorXd::Zero(6)}, Eigen::VectorXd::Zero(2)); }, IA,
      "q_ref = (0, 0): expected 6 joint values like the solutions, got 2");
  row(
      "serial::follow", "unreachable pose",
      [arm, q0] { serial::follow(arm(), {Posed(Quaterniond::Identity(), Vector3d(5, 0, 0))}, q0); }, RT,
      "poses[0] translation = (5, 0, 0): has no inverse-kinematics solution");
  // --- check_joint_limits / retime_by_scaling ---
  const auto ur5e = [] { return SerialArm::from_urdf_file(urdf + "arm_ur5e_dh.urdf", "base_link", "tool0"); };
  const auto q_ur = [] { return (Eigen::VectorXd(6) << 0.3, -1.2, 1.5, -1.9, -1.57, 0.2).finished(); };
  const auto ur_path = [ur5e, q_ur] {
    const Posed a = ur5e().forward(q_ur());
    return Path::lin(a, Posed(a.quaternion(), a.translation() + Vector3d(0.05, 0, 0)));
  };
  row(
      "check_joint_limits", "negative samples_between",
      [=] {
        JointCheckOptions o;
        o.samples_between = -1;
        check_joint_limits(plan(ur_path(), good_set(), limits(0.1, 1, 10)), ur5e(), q_ur(), o);
      },
      IA, "samples_between = -1");
  row(
      "check_joint_limits", "zero difference_step",
      [=] {
        JointCheckOptions o;
        o.difference_step = 0.0;
        check_joint_limits(plan(ur_path(), good_set(), limits(0.1, 1, 10)), ur5e(), q_ur(), o);
      },
      IA, "difference_step = 0");
  row(
      "check_joint_limits", "q_start of the wrong size",
      [=] { check_joint_limits(plan(ur_path(), good_set(), limits(0.1, 1, 10)), ur5e(), Eigen::VectorXd::Zero(5)); },
      IA, "q_start size = 5");
  row(
      "check_joint_limits", "NaN q_start",
      [=] {
        check_joint_limits(plan(ur_path(), good_set(), limits(0.1, 1, 10)), ur5e(), Eigen::VectorXd::Constant(6, nan_));
      },
      IA, "q_start = (nan");
  row(
      "retime_by_scaling", "zero max_iterations",
      [=] { retime_by_scaling(ur_path(), good_set(), limits(0.1, 1, 10), ProfileKind::scurve, ur5e(), q_ur(), {}, 0); },
      IA, "max_iterations = 0");
  // --- retime_optimal ---
  const auto optimal = [=](const OptimalRetimeOptions& o) {
    retime_optimal(ur_path(), good_set(), limits(0.1, 1, std::nullopt), ur5e(), q_ur(), o);
  };
  row(
      "retime_optimal", "NaN jerk",
      [=] { retime_optimal(ur_path(), good_set(), limits(0.1, 1, nan_), ur5e(), q_ur()); }, IA, "jerk = nan");
  row(
      "retime_optimal", "zero jerk",
      [=] { retime_optimal(ur_path(), good_set(), limits(0.1, 1, 0.0), ur5e(), q_ur()); }, IA, "jerk = 0");
  row(
      "retime_optimal", "one grid interval",
      [=] {
        OptimalRetimeOptions o;
        o.grid_intervals = 1;
        optimal(o);
      },
      IA, "grid_intervals = 1");
  row(
      "retime_optimal", "NaN difference_step",
      [=] {
        OptimalRetimeOptions o;
        o.difference_step = nan_;
        optimal(o);
      },
      IA, "difference_step = nan");
  row(
      "retime_optimal", "negative check_samples_between",
      [=] {
        OptimalRetimeOptions o;
        o.check_samples_between = -1;
        optimal(o);
      },
      IA, "check_samples_between = -1");
  row(
      "retime_optimal", "negative max_refinements",
      [=] {
        OptimalRetimeOptions o;
        o.max_refinements = -1;
        optimal(o);
      },
      IA, "max_refinements = -1");
  row(
      "retime_optimal", "joint_acceleration of the wrong size",
      [=] {
        OptimalRetimeOptions o;
        o.joint_acceleration = Eigen::VectorXd::Ones(2);
        optimal(o);
      },
      IA, "joint_acceleration size = 2");
  row(
      "retime_optimal", "zero joint acceleration",
      [=] {
        OptimalRetimeOptions o;
        o.joint_acceleration = Eigen::VectorXd::Ones(6);
        o.joint_acceleration(4) = 0;
        optimal(o);
      },
      IA, "joint_acceleration[4] = 0");
  row(
      "retime_optimal", "hexapod, leg accelerations of the wrong size",
      [=] {
        OptimalRetimeOptions o;
        o.joint_acceleration = Eigen::VectorXd::Ones(3);
        const Hexapod h = hexapod();
        retime_optimal(Path::lin(h.home(), h.home() * Posed(Quaterniond::Identity(), Vector3d(0.01, 0, 0))), good_set(),
                       limits(0.1, 1, std::nullopt), h, o);
      },
      IA, "joint_acceleration size = 3");
  row(
      "check_joint_limits", "hexapod, zero difference_step",
      [=] {
        JointCheckOptions o;
        o.difference_step = 0.0;
        const Hexapod h = hexapod();
        check_joint_limits(plan(Path::lin(h.home(), h.home() * Posed(Quaterniond::Identity(), Vector3d(0.01, 0, 0))),
                                good_set(), limits(0.1, 1, 10)),
                           h, o);
      },
      IA, "difference_step = 0");
  row(
      "SerialArm::with_joint_limits", "effort of the wrong size",
      [=] {
        JointLimits l = ur5e().joint_limits();
        l.effort = Eigen::VectorXd::Ones(2);
        ur5e().with_joint_limits(l);
      },
      IA, "effort size = 2");
  row(
      "SerialArm::with_joint_limits", "negative velocity",
      [=] {
        JointLimits l = ur5e().joint_limits();
        l.velocity(1) = -1;
        ur5e().with_joint_limits(l);
      },
      IA, "joint \"shoulder_lift_joint\" velocity = -1");
  // --- plan(JointPath, ..., SerialArm): PTP moves (ptp.hpp) ---
  const auto q6 = [](double x) { return Eigen::VectorXd::Constant(6, x); };
  const auto ptp = [=](const JointPath& move, const MetricSetd& set, const Limits& l, const PtpOptions& o) {
    plan(move, set, l, l.jerk ? ProfileKind::scurve : ProfileKind::trapezoid, ur5e(), o);
  };
  row(
      "JointPath", "q_end of another size", [=] { JointPath(q6(0), Eigen::VectorXd::Zero(5)); }, IA,
      "q_end size = 5: must equal q_start size 6");
  row(
      "JointPath", "NaN q_end",
      [=] {
        Eigen::VectorXd q = q6(0);
        q(2) = nan_;
        JointPath(q6(0), q);
      },
      IA, "q_end = (0, 0, nan, 0, 0, 0): must be finite");
  row(
      "plan (PTP)", "q_a of the wrong size for the arm",
      [=] { ptp(JointPath(Eigen::VectorXd::Zero(5), Eigen::VectorXd::Ones(5)), good_set(), limits(0.1, 1, 10), {}); },
      IA, "q_a size = 5: must be the arm's dof 6");
  row(
      "plan (PTP)", "q_b outside the joint range",
      [=] {
        Eigen::VectorXd q = q6(0.1);
        q(1) = 7.0;
        ptp(JointPath(q6(0), q), good_set(), limits(0.1, 1, 10), {});
      },
      IA, "q_b[1] = 7: is outside the position limits [lower, upper] of joint \"shoulder_lift_joint\"");
  row(
      "plan (PTP)", "q_b equal to q_a", [=] { ptp(JointPath(q6(0.1), q6(0.1)), good_set(), limits(0.1, 1, 10), {}); },
      IA, "equals q_a: a PTP move must move");
  row(
      "plan (PTP)", "zero velocity", [=] { ptp(JointPath(q6(0), q6(0.1)), good_set(), limits(0.0, 1, 10), {}); }, IA,
      "velocity = 0");
  row(
      "plan (PTP)", "collinear set", [=] { ptp(JointPath(q6(0), q6(0.1)), collinear_set(), limits(0.1, 1, 10), {}); },
      IA, "metric_set = \"MetricSet\": is not well-formed");
  row(
      "plan (PTP)", "zero tolerance",
      [=] {
        PtpOptions o;
        o.tolerance = 0.0;
        ptp(JointPath(q6(0), q6(0.1)), good_set(), limits(0.1, 1, 10), o);
      },
      IA, "tolerance = 0: must be in (0, 0.5]");
  row(
      "plan (PTP)", "joint_acceleration of the wrong size",
      [=] {
        PtpOptions o;
        o.joint_acceleration = Eigen::VectorXd::Ones(3);
        ptp(JointPath(q6(0), q6(0.1)), good_set(), limits(0.1, 1, 10), o);
      },
      IA, "joint_acceleration size = 3");
  row(
      "plan (PTP)", "NaN joint acceleration",
      [=] {
        PtpOptions o;
        o.joint_acceleration = q6(1.0);
        o.joint_acceleration(4) = nan_;
        ptp(JointPath(q6(0), q6(0.1)), good_set(), limits(0.1, 1, 10), o);
      },
      IA, "joint_acceleration[4] = nan: must be > 0");
  row(
      "retime_optimal", "q_start of the wrong size",
      [=] { retime_optimal(ur_path(), good_set(), limits(0.1, 1, std::nullopt), ur5e(), Eigen::VectorXd::Zero(5)); },
      IA, "q_start size = 5");
#endif
  return r;
}

std::string row_name(const Row& row) {
  std::string name = row.entry + "_" + row.bad;
  std::string out;
  for (std::size_t i = 0; i < name.size(); ++i) {
    const char c = name[i];
    if (c == '+' && name.compare(i, 4, "+inf") == 0)
      out += "Pos";
    else if (c == '-' && name.compare(i, 4, "-inf") == 0)
      out += "Neg";
    else if (std::isalnum(static_cast<unsigned char>(c)))
      out += c;
    else if (!out.empty() && out.back() != '_')
      out += '_';
  }
  while (!out.empty() && out.back() == '_') out.pop_back();
  return out;
}

// Readable test parameters in gtest's output (instead of a byte dump).
void PrintTo(const Row& row, std::ostream* out) { *out << row.entry << " / " << row.bad; }

class BadInputRows : public ::testing::TestWithParam<Row> {};

TEST_P(BadInputRows, RejectsWithNamedArgumentAndValue) {
  const Row& row = GetParam();
  std::string what;
  bool invalid_argument = false, runtime_error = false, other = false, threw = false;
  try {
    row.call();
  } catch (const std::invalid_argument& e) {
    threw = invalid_argument = true;
    what = e.what();
  } catch (const std::runtime_error& e) {
    threw = runtime_error = true;
    what = e.what();
  } catch (const std::exception& e) {
    threw = other = true;
    what = e.what();
  }
  if (threw) RecordProperty("message", what);
  const bool right_type = row.expect == Expect::invalid_argument ? invalid_argument : runtime_error;
  const bool matches = threw && right_type && what.find(row.fragment) != std::string::npos;
  if (!row.observed.empty()) {
    // Strict xfail: the gap must still be there, else promote the row.
    EXPECT_FALSE(matches) << row.entry << " now rejects " << row.bad << " (" << what
                          << "): remove `observed` from this row";
    RecordProperty("xfail", row.observed);
    return;
  }
  ASSERT_TRUE(threw) << row.entry << " accepted " << row.bad;
  EXPECT_FALSE(other) << "unexpected exception type: " << what;
  EXPECT_TRUE(right_type) << "wrong exception type: " << what;
  EXPECT_NE(what.find(row.fragment), std::string::npos)
      << "message \"" << what << "\" lacks \"" << row.fragment << "\"";
}

INSTANTIATE_TEST_SUITE_P(BadInputTable, BadInputRows, ::testing::ValuesIn(rows()),
                         [](const ::testing::TestParamInfo<Row>& param) { return row_name(param.param); });

TEST(BadInputTableMeta, NamesAreUniqueAndGapsAreCounted) {
  const std::vector<Row> all = rows();
  std::vector<std::string> names;
  int gaps = 0;
  for (const Row& r : all) {
    names.push_back(row_name(r));
    if (!r.observed.empty()) ++gaps;
  }
  std::sort(names.begin(), names.end());
  EXPECT_EQ(std::adjacent_find(names.begin(), names.end()), names.end());
  RecordProperty("rows", static_cast<int>(all.size()));
  RecordProperty("not_rejected", gaps);
}

}  // namespace
