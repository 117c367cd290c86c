// The input check every law of dispkin/profile.hpp makes of its distance (profile.cpp,
// profile_phases.cpp).
#pragma once

#include <cmath>

#include "dispkin/error.hpp"

namespace dispkin::detail {

inline void require_distance(double distance) {
  require(std::isfinite(distance) && distance >= 0.0, "distance", distance, "must be finite and not negative");
}

}  // namespace dispkin::detail
