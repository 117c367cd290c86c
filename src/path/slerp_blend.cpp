// The cutting of nested-SLERP blends (the Mamezou trajectory article's "Fitting Posture",
// doc/planning.md §6.1) into sections; the blend's planning is in blend.cpp.
#include <algorithm>
#include <cmath>
#include <limits>

#include "dispkin/path/path.hpp"
#include "path_geometry.hpp"

namespace dispkin {

void Path::cut_slerp_blend(const SlerpBlendSection& blend, double tolerance) {
  using detail::metres_per_radian;
  // As cut_curve: the speed |ċ| + ρ|ω| per unit v, ρ = 0.1 m, sampled along the blend; the blend
  // is cut where that speed varies (doc/section-length.md eq. 29), each section bounded to its
  // exact peak (SlerpBlendSection::bounds, doc/section-length.md eqs. 25–27).
  SlerpBlendSection whole = blend;
  whole.v0 = 0.0;
  whole.v1 = 1.0;
  constexpr int samples = 64;
  double min_speed = std::numeric_limits<double>::infinity(), max_speed = 0.0;
  for (int i = 0; i <= samples; ++i) {
    const double v = double(i) / samples;
    Posed pose;
    Twistd twist;
    whole.at(v, pose, twist);
    const double speed = whole.position.first(v).norm() + metres_per_radian * twist.angular.norm();
    min_speed = std::min(min_speed, speed);
    max_speed = std::max(max_speed, speed);
  }
  const int count = detail::sections_for_speed_range(min_speed, max_speed, tolerance);
  for (int k = 0; k < count; ++k) {
    SlerpBlendSection section = whole;
    section.v0 = double(k) / count;
    section.v1 = k + 1 == count ? 1.0 : double(k + 1) / count;
    append(section);
  }
}

}  // namespace dispkin
