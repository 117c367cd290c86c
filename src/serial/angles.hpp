// Joint angles modulo a turn: the reduction into (−π, π] that every joint value the plugin
// returns goes through (π and 2π from dispkin/numbers.hpp).
#pragma once

#include <cmath>

#include "dispkin/numbers.hpp"

namespace dispkin {
namespace serial {
namespace detail {

using dispkin::pi;
using dispkin::two_pi;

//! The angle a mod 2π in (−π, π].
inline double wrap_angle(double a) noexcept {
  if (a > pi || a <= -pi) {  // (std::remainder is several times slower than this on glibc)
    a -= two_pi * std::floor((a + pi) / two_pi);
    if (a <= -pi) a += two_pi;
    if (a > pi) a -= two_pi;
  }
  return a;
}

}  // namespace detail
}  // namespace serial
}  // namespace dispkin
