// Joint angles modulo a turn: π as a double (Eigen's EIGEN_PI, rounded once) and the reduction
// into (−π, π] that every joint value the plugin returns goes through.
#pragma once

#include <cmath>

#include <Eigen/Core>

namespace dispkin {
namespace serial {
namespace detail {

constexpr double pi = static_cast<double>(EIGEN_PI);
constexpr double two_pi = 2.0 * pi;

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
