//! Mathematical constants, each defined once: π as a double (Eigen's EIGEN_PI rounded once, the
//! same value as the literal 3.141592653589793) and 2π.
#pragma once

#include <Eigen/Core>

namespace dispkin {

constexpr double pi = static_cast<double>(EIGEN_PI);  //!< π
constexpr double two_pi = 2.0 * pi;                   //!< 2π, one full turn (rad)

}  // namespace dispkin
