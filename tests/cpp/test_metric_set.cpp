// MetricSet: well-formedness (doc/disp-metric.md §4), groups and their limits, bad input.
#include <gtest/gtest.h>

#include <dispkin/disp.hpp>
#include <dispkin/metric_set.hpp>

#include "random_cases.hpp"

namespace dispkin {
namespace {

using testing::message_of;

using V = Eigen::Vector3d;

TEST(MetricSet, WellFormedNeedsAPlaneOrABall) {
  MetricSetd set;
  EXPECT_FALSE(set.is_well_formed());
  set.add_relative(V(0, 0, 0));
  EXPECT_FALSE(set.is_well_formed()) << "a single point cannot see a rotation about itself";
  set.add_relative(V(1, 0, 0));
  set.add_relative(V(2, 0, 0));
  EXPECT_FALSE(set.is_well_formed()) << "collinear points cannot see a rotation about their line";
  set.add_relative(V(1, 1e-3, 0));
  EXPECT_TRUE(set.is_well_formed());

  MetricSetd ball;
  ball.add_sphere(V(1, 2, 3), 0.1);
  EXPECT_TRUE(ball.is_well_formed()) << "a sphere of positive radius is well-formed on its own";
  MetricSetd dot;
  dot.add_sphere(V(1, 2, 3), 0.0);
  EXPECT_FALSE(dot.is_well_formed()) << "a sphere of radius 0 is a point";
}

TEST(MetricSet, CollinearWithinRoundingIsDegenerate) {
  MetricSetd set;
  for (int i = 0; i < 10; ++i) set.add_relative(V(1000.0 + i, 2000.0 + 2.0 * i, -i) + V(1e-13 * (i % 3), 0, 0));
  EXPECT_FALSE(set.is_well_formed()) << "far from the origin, rounding-level offsets are not a plane";
  set.add_relative(V(1000.0, 2001.0, 0.0));
  EXPECT_TRUE(set.is_well_formed());
}

TEST(MetricSet, MixedSetsNeedOnePartWellFormedOnItsOwn) {
  // One relative point and one absolute point: some pose puts the point on the line through
  // the fixed point, and a rotation about it is not seen — rejected.
  MetricSetd mixed;
  mixed.add_relative(V(0, 0, 0.2));
  mixed.add_absolute(V(1, 0, 0));
  mixed.add_absolute(V(2, 0, 0));
  EXPECT_FALSE(mixed.is_well_formed());
  const Posed a = Posed::from_xyzuvw((Eigen::Matrix<double, 6, 1>() << 1.5, 0, -0.2, 0, 0, 0).finished());
  // The demonstration of why: a turn about the x axis through all three points has length 0.
  const Posed b = a * Posed(Eigen::Quaterniond(Eigen::AngleAxisd(0.5, V::UnitX())),
                            V(0, 0.2 * std::sin(0.5), 0.2 * (1 - std::cos(0.5))));
  MetricSetd unchecked_rel;  // same geometry, evaluated piecewise
  EXPECT_NEAR(((b * V(0, 0, 0.2)) - (a * V(0, 0, 0.2))).norm(), 0.0, 1e-12);
  EXPECT_NEAR((b.inverse() * V(1, 0, 0) - a.inverse() * V(1, 0, 0)).norm(), 0.0, 1e-12);
  EXPECT_FALSE(a.is_approx(b, 1e-3));

  mixed.add_absolute(V(0, 1, 0));  // the absolute part now spans a plane
  EXPECT_TRUE(mixed.is_well_formed());
}

TEST(MetricSet, GroupsKeepTheirLimitsAndOrder) {
  MetricSetd set;
  set.add_relative(V(0, 0, 1), 3);
  set.add_relative(V(1, 0, 0), 0);
  set.set_group_speed(3, 0.5);
  ASSERT_EQ(set.groups().size(), 2u);
  EXPECT_EQ(set.groups()[0].id, 0);
  EXPECT_EQ(set.groups()[1].id, 3);
  EXPECT_FALSE(set.groups()[0].speed_limit.has_value());
  EXPECT_DOUBLE_EQ(*set.find_group(3)->speed_limit, 0.5);
  EXPECT_DOUBLE_EQ(set.find_group(3)->weight(2.0), 4.0);
  EXPECT_DOUBLE_EQ(set.find_group(0)->weight(2.0), 1.0);
  EXPECT_DOUBLE_EQ(set.find_group(0)->weight(std::nullopt), 1.0);
  EXPECT_EQ(set.point_count(), 2u);
}

TEST(MetricSetBadInput, NonFinitePoints) {
  MetricSetd set;
  const std::string m = message_of([&] { set.add_relative(std::vector<V>{V(0, 0, 0), V(0, std::nan(""), 1)}); });
  EXPECT_NE(m.find("points[1] = (0, nan, 1)"), std::string::npos) << m;
  EXPECT_EQ(set.point_count(), 0u) << "a rejected batch adds nothing";
  EXPECT_NE(message_of([&] { set.add_absolute(V(std::numeric_limits<double>::infinity(), 0, 0)); }).find("inf"),
            std::string::npos);
}

TEST(MetricSetBadInput, NegativeOrNonFiniteRadius) {
  MetricSetd set;
  EXPECT_NE(message_of([&] { set.add_sphere(V::Zero(), -0.1); }).find("radius = -0.1"), std::string::npos);
  EXPECT_NE(message_of([&] { set.add_sphere(V::Zero(), std::nan("")); }).find("radius = nan"), std::string::npos);
  EXPECT_NE(message_of([&] { set.add_sphere(V(std::nan(""), 0, 0), 1.0); }).find("center"), std::string::npos);
}

TEST(MetricSetBadInput, GroupIdsAndSpeeds) {
  MetricSetd set;
  EXPECT_NE(message_of([&] { set.add_relative(V::Zero(), -1); }).find("group = -1"), std::string::npos);
  EXPECT_NE(message_of([&] { set.set_group_speed(1, 0.0); }).find("speed = 0"), std::string::npos);
  EXPECT_NE(message_of([&] { set.set_group_speed(1, -2.0); }).find("speed = -2"), std::string::npos);
  EXPECT_NE(message_of([&] { set.set_group_speed(1, std::numeric_limits<double>::infinity()); }).find("speed = inf"),
            std::string::npos);
}

TEST(MetricSetBadInput, DegenerateSetIsRefusedByTheDispFunctions) {
  MetricSetd set;
  set.add_relative(V(0, 0, 0));
  set.add_relative(V(0, 0, 1));
  const std::string m = message_of([&] { disp_distance(set, Posed(), Posed()); });
  EXPECT_NE(m.find("metric_set"), std::string::npos) << m;
  EXPECT_NE(m.find("not well-formed"), std::string::npos) << m;
  EXPECT_NE(message_of([&] { section_length(set, Posed(), Posed(), Interpolation::screw); }).find("not well-formed"),
            std::string::npos);
  EXPECT_NE(message_of([&] { disp_distance(MetricSetd(), Posed(), Posed()); }).find("empty"), std::string::npos);
}

TEST(MetricSetBadInput, GroupLimitNeedsTheSystemVelocity) {
  MetricSetd set;
  set.add_sphere(V::Zero(), 0.1);
  set.add_relative(V(0, 0, 1), 1);
  set.set_group_speed(1, 0.05);
  const std::string m = message_of([&] { disp_distance(set, Posed(), Posed()); });
  EXPECT_NE(m.find("system_velocity"), std::string::npos) << m;
  EXPECT_NE(m.find("group 1"), std::string::npos) << m;
  EXPECT_NE(message_of([&] { disp_distance(set, Posed(), Posed(), -1.0); }).find("system_velocity = -1"),
            std::string::npos);
  // A given system velocity is checked even where no group needs it.
  MetricSetd plain;
  plain.add_sphere(V::Zero(), 0.1);
  EXPECT_NE(message_of([&] {
              section_length(plain, Posed(), Posed(), Interpolation::screw, V::Zero(), 0.0);
            }).find("system_velocity = 0"),
            std::string::npos);
  EXPECT_NE(message_of([&] { max_point_speed(plain, Posed(), Twistd(), std::nan("")); }).find("system_velocity = nan"),
            std::string::npos);
}

}  // namespace
}  // namespace dispkin
