// Hull-vertex reduction (Qhull): the reduced set measures every motion exactly as the cloud.
#include <algorithm>

#include <gtest/gtest.h>

#include <dispkin/convex_hull.hpp>
#include <dispkin/disp.hpp>
#include <dispkin/shapes.hpp>

#include "random_cases.hpp"

namespace dispkin {
namespace {

using V = Eigen::Vector3d;
using testing::Random;

bool contains(const std::vector<V>& set, const V& p) { return std::find(set.begin(), set.end(), p) != set.end(); }

double max_speed(const std::vector<V>& points, const Twistd& xi) {
  double best = 0;
  for (const auto& p : points) best = std::max(best, point_speed(xi, p));
  return best;
}

TEST(ConvexHull, CubeCloudReducesToTheCorners) {
  Random rnd(91);
  std::vector<V> cloud = shapes::box(V(1, 2, 3));
  for (int i = 0; i < 5000; ++i) cloud.push_back(V(rnd.uniform(-0.5, 0.5), rnd.uniform(-1, 1), rnd.uniform(-1.5, 1.5)));
  std::shuffle(cloud.begin(), cloud.end(), rnd.engine());
  const auto hull = convex_hull_vertices(cloud);
  ASSERT_EQ(hull.size(), 8u);
  for (const auto& corner : shapes::box(V(1, 2, 3))) EXPECT_TRUE(contains(hull, corner));
}

TEST(ConvexHull, IcosphereVerticesAreAllKept) {
  const auto sphere = shapes::icosphere(1.0, 3);
  std::vector<V> cloud = sphere;
  Random rnd(92);
  for (int i = 0; i < 2000; ++i) cloud.push_back(rnd.unit_vector() * rnd.uniform(0.0, 0.9));
  const auto hull = convex_hull_vertices(cloud);
  EXPECT_EQ(hull.size(), sphere.size());
  for (const auto& v : sphere) EXPECT_TRUE(contains(hull, v));
}

TEST(ConvexHull, FlatCollinearAndCoincidentClouds) {
  Random rnd(93);
  // A flat square with interior points, tilted and far from the origin.
  const Posed place = rnd.pose(100.0);
  std::vector<V> flat;
  for (const auto& c : std::vector<V>{V(-1, -1, 0), V(1, -1, 0), V(1, 1, 0), V(-1, 1, 0)}) flat.push_back(place * c);
  for (int i = 0; i < 500; ++i) flat.push_back(place * V(rnd.uniform(-0.9, 0.9), rnd.uniform(-0.9, 0.9), 0));
  const auto flat_hull = convex_hull_vertices(flat);
  EXPECT_EQ(flat_hull.size(), 4u);
  for (int i = 0; i < 4; ++i) EXPECT_TRUE(contains(flat_hull, flat[static_cast<std::size_t>(i)]));

  std::vector<V> line;
  for (int i = 0; i < 100; ++i) line.push_back(V(1, 2, 3) + rnd.uniform(-1, 1) * V(0.3, -0.2, 0.1));
  line.push_back(V(1, 2, 3) + 2.0 * V(0.3, -0.2, 0.1));
  line.push_back(V(1, 2, 3) - 2.0 * V(0.3, -0.2, 0.1));
  const auto ends = convex_hull_vertices(line);
  ASSERT_EQ(ends.size(), 2u);
  EXPECT_TRUE(contains(ends, line[100]));
  EXPECT_TRUE(contains(ends, line[101]));

  EXPECT_EQ(convex_hull_vertices(std::vector<V>(10, V(1, 1, 1))).size(), 1u);
}

TEST(ConvexHull, ReducedSetMeasuresExactlyAsTheCloud) {
  Random rnd(94);
  const int n = std::max(20, testing::case_count(10000) / 100);
  for (int i = 0; i < n; ++i) {
    MetricSetd cloud;
    std::vector<V> rel, abs;
    for (int k = 0; k < 300; ++k) rel.push_back(rnd.vector(0.5));
    for (int k = 0; k < 300; ++k) abs.push_back(rnd.vector(2.0));
    cloud.add_relative(rel);
    cloud.add_absolute(abs, 2);
    cloud.add_sphere(V(0, 0, 1), 0.1, Frame::relative, 2);
    cloud.set_group_speed(2, 0.7);
    const MetricSetd reduced = reduced_to_hull_vertices(cloud);
    ASSERT_LT(reduced.point_count(), cloud.point_count());
    ASSERT_EQ(reduced.sphere_count(), 1u);
    for (int k = 0; k < 20; ++k) {
      const Posed a = rnd.pose(), b = rnd.nearby(a, 0.5, 2.0);
      const V pivot = rnd.vector(0.2);
      ASSERT_DOUBLE_EQ(disp_distance(reduced, a, b, 1.0), disp_distance(cloud, a, b, 1.0));
      for (const auto kind : {Interpolation::screw, Interpolation::decoupled})
        ASSERT_DOUBLE_EQ(section_length(reduced, a, b, kind, pivot, 1.0),
                         section_length(cloud, a, b, kind, pivot, 1.0));
    }
  }
}

TEST(ConvexHull, LargeCloudKeepsTheFastestPoint) {
  Random rnd(95);
  std::vector<V> cloud;
  for (int i = 0; i < 100000; ++i) cloud.push_back(rnd.vector(1.0));
  const auto hull = convex_hull_vertices(cloud);
  EXPECT_LT(hull.size(), 1000u);
  for (int k = 0; k < 100; ++k) {
    const Twistd xi(rnd.vector(1.0), rnd.vector(1.0));
    ASSERT_DOUBLE_EQ(max_speed(hull, xi), max_speed(cloud, xi));
  }
}

TEST(ConvexHullBadInput, NonFinitePoint) {
  std::vector<V> cloud = shapes::box(V(1, 1, 1));
  cloud.push_back(V(0, std::nan(""), 0));
  try {
    convex_hull_vertices(cloud);
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("points[8]"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace dispkin
