// The hexapod shared by the hexapod tests (test_hexapod.cpp, test_hexapod_leg_speed.cpp,
// test_hexapod_description.cpp) and the random poses it reaches.
#pragma once

#include <dispkin/hexapod/hexapod.hpp>

#include "random_cases.hpp"

namespace dispkin::testing {

//! A desktop hexapod: base radius 150 mm, platform radius 100 mm, joints in pairs 20° apart.
inline hexapod::Hexapod test_hexapod() {
  constexpr double degree = 3.14159265358979323846 / 180;
  return hexapod::Hexapod::symmetric(0.15, 20 * degree, 0.10, 20 * degree, 0.20, 0.15, 0.32, 0.01);
}

//! A random pose around home whose legs are all in range.
inline Posed reachable_pose(const hexapod::Hexapod& h, Random& rnd) {
  for (;;) {
    const Posed pose = h.home() * Posed::exp(Twistd(rnd.vector(0.04), rnd.unit_vector() * rnd.uniform(0.0, 0.25)));
    if (h.check(pose).reachable()) return pose;
  }
}

}  // namespace dispkin::testing
