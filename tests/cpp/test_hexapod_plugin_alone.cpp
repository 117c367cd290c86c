// The hexapod plugin on its own: this program links dispkin::hexapod and nothing of the umbrella,
// so building it is half the test. src/hexapod/hexapod.cpp used to hold the leg speeds along a path
// too, which call the umbrella's section sampling: at commit 3e28d68, where CurveSection::length
// and motion_bounds were not inline, its object needed the umbrella and a static link of the plugin
// alone failed. Those now live in the umbrella (src/hexapod/hexapod_along_path.cpp).
#include <gtest/gtest.h>

#include "dispkin/hexapod/hexapod.hpp"

namespace dispkin {
namespace {

using hexapod::Hexapod;

TEST(HexapodPluginAlone, KinematicsAndJsonWithoutTheUmbrella) {
  const Hexapod hexapod = Hexapod::symmetric(0.15, 0.35, 0.10, 0.35, 0.20, 0.15, 0.32, 0.01);
  Eigen::Matrix<double, 6, 1> xyzuvw;
  xyzuvw << 0.01, -0.02, 0.21, 0.03, -0.02, 0.05;
  const Posed pose = Posed::from_xyzuvw(xyzuvw);
  const Hexapod::Legs legs = hexapod.leg_lengths(pose);
  const Posed back = hexapod.forward(legs);
  EXPECT_LT((back.translation() - pose.translation()).norm(), 1e-12);
  const Hexapod copy = Hexapod::from_json(hexapod.to_json());
  EXPECT_EQ(copy.leg_lengths(pose), legs);
}

}  // namespace
}  // namespace dispkin
