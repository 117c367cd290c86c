// Joint angles modulo a turn: the reduction into (−π, π] that every joint value the plugin
// returns goes through, and the half turn of a flipped joint (π and 2π from dispkin/numbers.hpp).
#pragma once

#include <cmath>

#include "dispkin/numbers.hpp"

namespace dispkin {
namespace serial {
namespace detail {

using dispkin::pi;
using dispkin::two_pi;

//! The angle a mod 2π in (−π, π], exact for any a: a − 2πk to the last bit (2π as two_pi).
inline double wrap_angle(double a) noexcept {
  if (a > -pi && a <= pi) return a;
  if (!(std::abs(a) <= 3.0 * pi)) {
    // Far from (−π, π] (a joint of ±1e16 rad keeps every digit): std::remainder is exact.
    double r = std::remainder(a, two_pi);  // in [−π, π]
    if (r <= -pi) r += two_pi;
    return r;
  }
  // A turn or so away, as sums and differences of wrapped angles are: a − 2πk is exact there
  // (Sterbenz's lemma), and several times cheaper than std::remainder on glibc.
  a -= two_pi * std::floor((a + pi) / two_pi);
  if (a <= -pi) a += two_pi;
  if (a > pi) a -= two_pi;
  return a;
}

//! θ + π in (−π, π] for θ in (−π, π]: the other solution of a joint whose neighbours turn by a
//! half turn with it (the wrist flip, doc/inverse-kinematics.md (eq. 27); the shoulder's second
//! q₁ on axis 1, doc/inverse-kinematics.md eq. 30).
inline double half_turn(double angle) noexcept { return angle > 0.0 ? angle - pi : angle + pi; }

}  // namespace detail
}  // namespace serial
}  // namespace dispkin
