// The angles of many (cos, sin) pairs at once: the closed forms compose every joint from the
// cosine and sine its subproblem gives and take the arctangents of a pose's solutions together,
// with SLEEF's vectorised atan2 (two pairs a call) instead of one libm call per joint.
#pragma once

#include <cstddef>

#include "ik_subproblems.hpp"

namespace dispkin {
namespace serial {
namespace detail {

//! angles[i] = atan2(pairs[i].s, pairs[i].c) in [−π, π] for i < n. SLEEF's atan2 of bound
//! 3.5 ULP (≤ 1.6e-15 rad), where libm's is 1 ULP: the closed forms keep their solutions exact to
//! rounding (doc/inverse-kinematics.md eq. 26) within the round trips' bound. Elsewhere than on
//! x86-64 each pair goes through CosSin::angle.
void angles_of(const CosSin* pairs, std::size_t n, double* angles) noexcept;

}  // namespace detail
}  // namespace serial
}  // namespace dispkin
