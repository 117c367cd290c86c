// Work and tool frames: commands converted to platform poses and back, XYZUVW about the tool
// origin, and the metric sets generated around the frames' origins against brute force.
#include <cmath>

#include <gtest/gtest.h>

#include <dispkin/disp.hpp>
#include <dispkin/frames.hpp>
#include <dispkin/hexapod/hexapod.hpp>

#include "random_cases.hpp"

namespace dispkin {
namespace {

using hexapod::Hexapod;
using testing::message_of;
using testing::Random;
using V = Eigen::Vector3d;
using Vector6 = Eigen::Matrix<double, 6, 1>;

WorkToolFrames random_frames(Random& rnd) { return WorkToolFrames(rnd.pose(0.5), rnd.pose(0.1)); }

TEST(Frames, CommandToPlatformAndBackIsTheIdentity) {
  Random rnd(601);
  for (int n = 0; n < testing::case_count(10000); ++n) {
    const WorkToolFrames frames = random_frames(rnd);
    const Posed command = rnd.pose(0.3);
    EXPECT_TRUE(frames.tool_in_work(frames.platform_pose(command)).is_approx(command, 1e-12)) << n;
    const Posed platform = rnd.pose(0.3);
    EXPECT_TRUE(frames.platform_pose(frames.tool_in_work(platform)).is_approx(platform, 1e-12)) << n;
  }
}

TEST(Frames, PlatformPosePutsTheToolFrameAtTheCommandInTheWorkFrame) {
  Random rnd(602);
  for (int n = 0; n < 1000; ++n) {
    const WorkToolFrames frames = random_frames(rnd);
    const Posed command = rnd.pose(0.3);
    const Posed platform = frames.platform_pose(command);
    // A point x given in tool coordinates: via the platform (T F x) and via the work frame (W X x).
    const V x = rnd.vector(0.2);
    EXPECT_LT(((platform * (frames.tool() * x)) - (frames.work() * (command * x))).norm(), 1e-12);
  }
}

TEST(Frames, XyzuvwRotatesAboutTheToolOrigin) {
  Random rnd(603);
  for (int n = 0; n < 1000; ++n) {
    const WorkToolFrames frames = random_frames(rnd);
    Vector6 a;
    a << rnd.vector(0.05), rnd.vector(0.4);
    Vector6 b = a;
    b.tail<3>() += rnd.vector(0.3);  // only U, V, W change
    // The tool origin stays where it is in the world.
    const V origin_a = frames.platform_pose_xyzuvw(a) * frames.pivot();
    const V origin_b = frames.platform_pose_xyzuvw(b) * frames.pivot();
    EXPECT_LT((origin_a - origin_b).norm(), 1e-12);
    EXPECT_LT((frames.xyzuvw(frames.platform_pose_xyzuvw(a)) - a).cwiseAbs().maxCoeff(), 1e-12);
  }
}

TEST(Frames, IdentityFramesCommandThePlatformItself) {
  Random rnd(604);
  const Posed pose = rnd.pose();
  EXPECT_TRUE(WorkToolFrames().platform_pose(pose).is_approx(pose, 0.0));
}

// Brute force: the fastest of the given points, relative ones at r (‖v + ω × r‖), absolute ones
// at their current body position T⁻¹ a.
double brute_force(const std::vector<V>& relative, const std::vector<V>& absolute, const Posed& pose,
                   const Twistd& xi) {
  double best = 0.0;
  for (const V& r : relative) best = std::max(best, (xi.linear + xi.angular.cross(r)).norm());
  for (const V& a : absolute) {
    const V b = pose.inverse() * a;
    best = std::max(best, (xi.linear + xi.angular.cross(b)).norm());
  }
  return best;
}

TEST(Frames, GeneratedIcosahedraMatchBruteForceOverTheirPoints) {
  Random rnd(605);
  for (int n = 0; n < testing::case_count(2000); ++n) {
    const WorkToolFrames frames = random_frames(rnd);
    const double tool_radius = rnd.uniform(0.005, 0.05), work_radius = rnd.uniform(0.05, 0.3);
    MetricSetd set;
    frames.add_tool_envelope(set, tool_radius);
    frames.add_work_envelope(set, work_radius, Envelope::icosahedron, 1);
    std::vector<V> relative, absolute;
    // The points, generated independently: icosahedron vertices (±1, ±φ, 0) cyclically, scaled
    // to circumscribe the sphere, placed with the frames.
    const double phi = (1 + std::sqrt(5.0)) / 2;
    const double vertex_radius = std::sqrt(10 + 2 * std::sqrt(5.0)) / 4 / (std::sqrt(3.0) * (3 + std::sqrt(5.0)) / 12);
    for (int k = 0; k < 12; ++k) {
      const double s1 = k & 1 ? -1 : 1, s2 = k & 2 ? -1 : 1;
      V u;
      if (k < 4)
        u = V(0, s1, s2 * phi);
      else if (k < 8)
        u = V(s1, s2 * phi, 0);
      else
        u = V(s2 * phi, 0, s1);
      u.normalize();
      relative.push_back(frames.tool() * (tool_radius * vertex_radius * u));
      absolute.push_back(frames.work() * (work_radius * vertex_radius * u));
    }
    ASSERT_EQ(set.point_count(), 24u);
    const Posed pose = rnd.pose(0.5);
    const Twistd xi(rnd.vector(1.0), rnd.vector(2.0));
    const double expected = brute_force(relative, absolute, pose, xi);
    ASSERT_NEAR(max_point_speed(set, pose, xi), expected, 1e-12 * (1 + expected)) << n;
    // Each group on its own: the tool group is the relative icosahedron, the work group the absolute one.
    ASSERT_EQ(set.find_group(0)->relative_points.size(), 12u);
    ASSERT_EQ(set.find_group(1)->absolute_points.size(), 12u);
  }
}

TEST(Frames, GeneratedSpheresMatchBruteForceOverSurfaceSamples) {
  Random rnd(606);
  for (int n = 0; n < 20; ++n) {
    const WorkToolFrames frames = random_frames(rnd);
    const double tool_radius = rnd.uniform(0.005, 0.05), work_radius = rnd.uniform(0.05, 0.3);
    MetricSetd tool, work;
    frames.add_tool_envelope(tool, tool_radius, Envelope::sphere);
    frames.add_work_envelope(work, work_radius, Envelope::sphere);
    const Posed pose = rnd.pose(0.5);
    const Twistd xi(rnd.vector(1.0), rnd.vector(2.0));
    std::vector<V> relative, absolute;
    for (int k = 0; k < 100000; ++k) {
      const V u = rnd.unit_vector();
      relative.push_back(frames.tool() * (tool_radius * u));
      absolute.push_back(frames.work() * (work_radius * u));
    }
    const double sampled_tool = brute_force(relative, {}, pose, xi), sampled_work = brute_force({}, absolute, pose, xi);
    const double exact_tool = max_point_speed(tool, pose, xi), exact_work = max_point_speed(work, pose, xi);
    EXPECT_GE(exact_tool, sampled_tool * (1 - 1e-12));
    EXPECT_LE(exact_tool, sampled_tool * (1 + 1e-4));
    EXPECT_GE(exact_work, sampled_work * (1 - 1e-12));
    EXPECT_LE(exact_work, sampled_work * (1 + 1e-4));
  }
}

// A pivot scan in the tool frame: the hexapod plans about the tool origin, which stays put.
TEST(Frames, HexapodRotationAboutTheToolOriginKeepsItInPlace) {
  const Hexapod h = Hexapod::symmetric(0.15, 0.35, 0.10, 0.35, 0.20, 0.15, 0.32, 0.01);
  const WorkToolFrames frames(Posed(Eigen::Quaterniond::Identity(), V(0, 0, 0.25)),
                              Posed(Eigen::Quaterniond::Identity(), V(0.01, 0.0, 0.05)));
  Vector6 a = Vector6::Zero(), b = Vector6::Zero();
  b(3) = 0.1;
  const Posed pa = frames.platform_pose_xyzuvw(a), pb = frames.platform_pose_xyzuvw(b);
  ASSERT_TRUE(h.check(pa).reachable());
  ASSERT_TRUE(h.check(pb).reachable());
  EXPECT_LT(((pa * frames.pivot()) - frames.work().translation()).norm(), 1e-15);
  EXPECT_LT(((pb * frames.pivot()) - frames.work().translation()).norm(), 1e-15);
}

TEST(FramesBadInput, RadiusAndGroup) {
  MetricSetd set;
  const WorkToolFrames frames;
  EXPECT_NE(message_of([&] { frames.add_tool_envelope(set, 0.0); }).find("radius = 0"), std::string::npos);
  EXPECT_NE(message_of([&] { frames.add_work_envelope(set, std::nan(""), Envelope::sphere); }).find("radius = nan"),
            std::string::npos);
  EXPECT_NE(message_of([&] { frames.add_tool_envelope(set, -1.0, Envelope::sphere); }).find("radius = -1"),
            std::string::npos);
  EXPECT_NE(message_of([&] { frames.add_tool_envelope(set, 0.1, Envelope::icosahedron, -1); }).find("group = -1"),
            std::string::npos);
  Vector6 bad = Vector6::Zero();
  bad(3) = std::nan("");
  EXPECT_NE(message_of([&] { frames.platform_pose_xyzuvw(bad); }).find("xyzuvw"), std::string::npos);
  EXPECT_TRUE(set.empty());
}

}  // namespace
}  // namespace dispkin
