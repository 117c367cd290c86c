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
  // As cut_curve: the velocity (|ċ| + ρ|ω|) sampled along the blend, its rate of change bounded
  // by |c̈| + ρ(|ω̇| + |ω|²) from the motion bounds over the whole blend (eqs. 31–33), ρ = 0.1 m.
  // A section of span h strays by at most rate·h/2 from its middle velocity, so
  // h = 2 · tolerance · speed / rate.
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
  const detail::MotionBounds bounds = whole.motion_bounds();
  const double rate = bounds.pivot_acceleration + metres_per_radian * (bounds.omega_dot + bounds.omega * bounds.omega);
  // A blend that (nearly) stops somewhere (a reversal) still gets finite sections: its bounds
  // stay rigorous, only looser there.
  const double speed = std::max(min_speed, 1e-3 * max_speed);
  const double wanted = speed > 0.0 ? std::ceil(rate / (2.0 * tolerance * speed)) : 1.0;
  const int count = static_cast<int>(std::clamp(std::isfinite(wanted) ? wanted : 1.0, 1.0, 100000.0));
  for (int k = 0; k < count; ++k) {
    SlerpBlendSection section = whole;
    section.v0 = double(k) / count;
    section.v1 = k + 1 == count ? 1.0 : double(k + 1) / count;
    append(section);
  }
}

}  // namespace dispkin
