// Cycle times in continuous-path mode (not a timing: a program that prints durations and their
// ratios, doc/planning.md §9–§11): a list of 21 poses as LINs stopping at every corner, blended
// within 10 % of its shortest move, and as a SPLINE; a 10³-point polyline of a circle blended
// within 10⁻⁴ R against the CIRC; a 0.3 m + 90° LIN as one move before the cut and now; a
// combined move under the rotational limit against the v/ω sphere.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include "dispkin/planning/planner.hpp"
#include "dispkin/shapes.hpp"

namespace {

using dispkin::Path;
using dispkin::Posed;
using V = Eigen::Vector3d;

Path lins_through(const std::vector<Posed>& poses) {
  Path path = Path::lin(poses[0], poses[1]);
  for (std::size_t i = 2; i < poses.size(); ++i) path.then(Path::lin(poses[i - 1], poses[i]));
  return path;
}

dispkin::MetricSetd tool(double radius) {
  dispkin::MetricSetd set;
  set.add_relative(dispkin::shapes::icosahedron(radius));
  return set;
}

}  // namespace

int main() {
  const dispkin::Limits limits{0.1, 1.0, 10.0};
  const auto kind = dispkin::ProfileKind::scurve;

  // 21 poses, steps of up to 0.3 m and 0.8 rad, seeded.
  std::mt19937_64 engine(1802);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<Posed> poses{Posed()};
  double shortest = 1e300;
  for (int k = 1; k < 21; ++k) {
    const V step = 0.3 * V(u(engine), u(engine), u(engine)) / std::sqrt(3.0);
    const V axis = V(u(engine), u(engine), u(engine)).normalized();
    poses.push_back(poses.back() * Posed::exp(dispkin::Twistd(step, 0.8 * std::abs(u(engine)) * axis)));
    shortest = std::min(shortest, (poses[k].translation() - poses[k - 1].translation()).norm());
  }
  const auto set = tool(0.1);
  dispkin::PlanOptions blend;
  blend.corner_tolerance = 0.1 * shortest;
  const double stops = dispkin::plan(lins_through(poses), set, limits, kind).duration();
  const double blended = dispkin::plan(lins_through(poses), set, limits, kind, blend).duration();
  const double spline = dispkin::plan(Path::spline(poses), set, limits, kind).duration();
  std::printf(
      "21-pose list: stopping %.4f s, blended (d = %.4f m) %.4f s, spline %.4f s; blended / spline %.4f, "
      "stopping / blended %.3f\n",
      stops, blend.corner_tolerance, blended, spline, blended / spline, stops / blended);

  // A polyline of 10³ points on three quarters of a circle, R = 0.2 m.
  const double radius = 0.2;
  std::vector<Posed> polyline;
  for (int k = 0; k <= 1000; ++k) {
    const double angle = 1.5 * dispkin::pi * k / 1000;
    polyline.push_back(
        Posed(Eigen::Quaterniond::Identity(), V(radius * std::cos(angle), radius * std::sin(angle), 0.0)));
  }
  dispkin::PlanOptions fine;
  fine.corner_tolerance = 1e-4 * radius;
  const auto small_tool = tool(0.05);
  const double through = dispkin::plan(lins_through(polyline), small_tool, limits, kind, fine).duration();
  const double circ =
      dispkin::plan(Path::circ(polyline.front(), polyline[500], polyline.back()), small_tool, limits, kind).duration();
  const double polyline_stops = dispkin::plan(lins_through(polyline), small_tool, limits, kind).duration();
  std::printf(
      "10^3-point polyline of a circle: blended (d = 1e-4 R) %.4f s, CIRC %.4f s, ratio %.4f; stopping %.2f s\n",
      through, circ, through / circ, polyline_stops);

  // A 0.3 m + 90° decoupled LIN of a 0.3 m icosahedron: one section (the fastest instant bounds
  // the whole move) against the planned, cut move.
  const Posed a, b(Eigen::Quaterniond(Eigen::AngleAxisd(0.5 * dispkin::pi, V::UnitZ())), V(0.3, 0.0, 0.0));
  const auto wide = tool(0.3);
  const Path lin = Path::lin(a, b);
  const double one_section = dispkin::Profile::scurve(lin.section_lengths(wide, limits.velocity)[0], limits.velocity,
                                                      limits.acceleration, *limits.jerk)
                                 .duration();
  const double cut = dispkin::plan(lin, wide, limits, kind).duration();
  std::printf("0.3 m + 90 deg LIN (0.3 m icosahedron): as one section %.4f s, planned %.4f s, ratio %.4f\n",
              one_section, cut, one_section / cut);

  // A combined move (0.3 m and 120°) of the tool centre under v = 0.2 m/s and ω = 0.5 rad/s: the
  // rotational limit against the sphere of radius v/ω around the tool centre.
  dispkin::Limits rotational{0.2, 1.0, 10.0};
  rotational.angular_velocity = 0.5;
  const Posed c(Eigen::Quaterniond(Eigen::AngleAxisd(2.0 * dispkin::pi / 3.0, V::UnitZ())), V(0.3, 0.0, 0.0));
  dispkin::MetricSetd centre;
  centre.add_relative(V::Zero());
  const double with_limit = dispkin::plan(Path::lin(a, c), centre, rotational, kind).duration();
  dispkin::MetricSetd sphere = centre;
  sphere.add_sphere(V::Zero(), 0.2 / 0.5);
  const double with_sphere = dispkin::plan(Path::lin(a, c), sphere, dispkin::Limits{0.2, 1.0, 10.0}, kind).duration();
  std::printf("0.3 m + 120 deg, v 0.2 m/s, w 0.5 rad/s: rotational limit %.4f s, v/w sphere %.4f s, ratio %.4f\n",
              with_limit, with_sphere, with_sphere / with_limit);
  return 0;
}
