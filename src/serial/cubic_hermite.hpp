// The cubic Hermite polynomial of doc/ptp.md eq. 18 on one interval (internal to the serial plugin):
// the joints of a FollowedTrajectory between its nodes, and a moving redundancy parameter between
// the nodes of its schedule (doc/inverse-kinematics.md eq. 50).
#pragma once

namespace dispkin::serial::detail {

// The cubic Hermite polynomial on one interval of span h between (q0, m0) and (q1, m1), the slopes
// per unit of the variable h is measured in (τ for the followed joints, s for the parameter), at
// x ∈ [0, 1] of it: value, first and second derivative per that unit (doc/ptp.md eq. 18).
struct Hermite {
  double x, h;
  template <typename A, typename B, typename C, typename D>
  auto value(const A& q0, const B& m0, const C& q1, const D& m1) const {
    const double x2 = x * x, x3 = x2 * x;
    return (2 * x3 - 3 * x2 + 1) * q0 + ((x3 - 2 * x2 + x) * h) * m0 + (3 * x2 - 2 * x3) * q1 + ((x3 - x2) * h) * m1;
  }
  template <typename A, typename B, typename C, typename D>
  auto rate(const A& q0, const B& m0, const C& q1, const D& m1) const {
    const double x2 = x * x;
    return ((6 * x2 - 6 * x) / h) * (q0 - q1) + (3 * x2 - 4 * x + 1) * m0 + (3 * x2 - 2 * x) * m1;
  }
  template <typename A, typename B, typename C, typename D>
  auto curvature(const A& q0, const B& m0, const C& q1, const D& m1) const {
    return ((12 * x - 6) / (h * h)) * (q0 - q1) + ((6 * x - 4) / h) * m0 + ((6 * x - 2) / h) * m1;
  }
};

}  // namespace dispkin::serial::detail
