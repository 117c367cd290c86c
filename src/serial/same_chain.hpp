// Whether two moves were planned on the same arm: their chains' axes, axis points and tip pose at
// q = 0 equal (internal to the serial plugin; the overlaps refuse moves of different arms).
#pragma once

#include "dispkin/serial/revolute_chain.hpp"

namespace dispkin::serial::detail {

inline bool same_chain(const RevoluteChain& a, const RevoluteChain& b) {
  return a.axes == b.axes && a.points == b.points && a.tip_at_zero.translation() == b.tip_at_zero.translation() &&
         a.tip_at_zero.quaternion().coeffs() == b.tip_at_zero.quaternion().coeffs();
}

}  // namespace dispkin::serial::detail
