// Shape builders, and how far each sphere approximation is from the exact sphere
// (doc/disp-metric.md eqs. 25–26).
#include <gtest/gtest.h>

#include <dispkin/disp.hpp>
#include <dispkin/shapes.hpp>

#include "random_cases.hpp"

namespace dispkin {
namespace {

using V = Eigen::Vector3d;
using testing::Random;

double max_speed(const std::vector<V>& points, const Twistd& xi) {
  double best = 0.0;
  for (const auto& p : points) best = std::max(best, point_speed(xi, p));
  return best;
}

TEST(Shapes, BoxCorners) {
  const auto corners = shapes::box(V(1, 2, 4), V(10, 0, 0));
  ASSERT_EQ(corners.size(), 8u);
  for (const auto& c : corners) {
    EXPECT_DOUBLE_EQ(std::abs(c.x() - 10), 0.5);
    EXPECT_DOUBLE_EQ(std::abs(c.y()), 1.0);
    EXPECT_DOUBLE_EQ(std::abs(c.z()), 2.0);
  }
}

TEST(Shapes, IcosahedronOnAndAroundTheSphere) {
  const V center(0.1, -0.2, 0.3);
  const auto on = shapes::icosahedron(2.0, center, false);
  ASSERT_EQ(on.size(), 12u);
  for (const auto& p : on) EXPECT_NEAR((p - center).norm(), 2.0, 1e-14);
  const auto around = shapes::icosahedron(2.0, center, true);
  for (const auto& p : around) EXPECT_NEAR((p - center).norm(), 2.0 * 1.2584085723648189, 1e-12);
  // The circumscribed one touches the sphere with its faces: inradius = radius.
  shapes::Polyhedron<double> poly = shapes::detail::unit_icosahedron<double>();
  for (auto& v : poly.vertices) v = center + 2.0 * shapes::icosahedron_circumradius_ratio<double>() * v;
  EXPECT_NEAR(poly.inradius(center), 2.0, 1e-12);
  // Every edge has the same length (regular).
  const auto unit = shapes::detail::unit_icosahedron<double>();
  for (const auto& f : unit.faces)
    for (int e = 0; e < 3; ++e)
      EXPECT_NEAR((unit.vertices[f[e]] - unit.vertices[f[(e + 1) % 3]]).norm(), 1.0514622242382672, 1e-12);
}

TEST(Shapes, IcosphereCircumscribesAndCounts) {
  const int expected[] = {12, 42, 162, 642, 2562};
  for (int s = 0; s <= 4; ++s) {
    const auto points = shapes::icosphere(0.5, s);
    EXPECT_EQ(points.size(), static_cast<std::size_t>(expected[s]));
    double min_norm = 1e9;
    for (const auto& p : points) min_norm = std::min(min_norm, p.norm());
    EXPECT_GT(min_norm, 0.5) << "all vertices outside the sphere";
  }
}

TEST(Shapes, SphericalShellPointsLieOnTheShell) {
  const V pivot(1, 2, 3);
  const auto shell = shapes::spherical_shell(0.25, 50, pivot);
  ASSERT_EQ(shell.size(), 50u);
  for (const auto& p : shell) EXPECT_NEAR((p - pivot).norm(), 0.25, 1e-15);
  MetricSetd set;
  set.add_relative(shell);
  EXPECT_TRUE(set.is_well_formed());
}

// For any motion: inscribed icosahedron ≤ exact sphere ≤ circumscribed icosahedron ≤ 1.2584 ×
// exact, and circumscribed icospheres approach the exact value from above as they refine.
TEST(Shapes, SphereApproximationsBracketTheExactSpeed) {
  Random rnd(21);
  const int n = testing::case_count(10000) / 10;
  const double ratio = shapes::icosahedron_circumradius_ratio<double>();
  const auto inscribed = shapes::icosahedron(1.0, V::Zero(), false);
  const auto circumscribed = shapes::icosahedron(1.0, V::Zero(), true);
  std::vector<std::vector<V>> spheres;
  for (int s = 1; s <= 3; ++s) spheres.push_back(shapes::icosphere(1.0, s));
  double worst_over = 0.0;
  for (int i = 0; i < n; ++i) {
    const Twistd xi(rnd.vector(1.0), rnd.vector(2.0));
    const double exact = sphere_speed(xi, V::Zero(), 1.0);
    ASSERT_LE(max_speed(inscribed, xi), exact * (1 + 1e-12));
    const double outer = max_speed(circumscribed, xi);
    ASSERT_GE(outer, exact * (1 - 1e-12));
    ASSERT_LE(outer, ratio * exact * (1 + 1e-12));
    worst_over = std::max(worst_over, outer / exact - 1);
    double previous = outer;
    for (const auto& sphere : spheres) {
      const double approx = max_speed(sphere, xi);
      ASSERT_GE(approx, exact * (1 - 1e-12));
      previous = approx;
    }
    // The 642-vertex icosphere is within 1 % of the sphere for every motion.
    ASSERT_LE(previous, exact * 1.01);
  }
  EXPECT_LT(worst_over, ratio - 1) << "over-estimate bounded by 25.8 %";
}

TEST(ShapesBadInput, Arguments) {
  EXPECT_THROW(shapes::icosahedron(0.0), std::invalid_argument);
  EXPECT_THROW(shapes::icosahedron(-1.0), std::invalid_argument);
  EXPECT_THROW(shapes::icosphere(1.0, 8), std::invalid_argument);
  EXPECT_THROW(shapes::spherical_shell(1.0, 3), std::invalid_argument);
  EXPECT_THROW(shapes::box(V(1, 0, 1)), std::invalid_argument);
  try {
    shapes::icosahedron(std::nan(""));
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("radius = nan"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace dispkin
