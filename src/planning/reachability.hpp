// Reachability analysis of a path parameterisation (internal; used by retime_optimal).
//
// Along a path cut by a grid s₀ < s₁ < … < s_N, the state is x = ṡ² and the control u = s̈,
// constant on each interval, so that x_{i+1} = x_i + 2Δ_i u_i. Every limit that is linear in
// (s̈, ṡ²) at a fixed s — joint velocities (x q′² ≤ q̇max²), joint accelerations
// (q′u + q″x), joint torques (M q′ u + (M q″ + C q′) x + g), the DISP speed and acceleration —
// is a half-plane a·u + b·x ≤ c; each interval's admissible (u_i, x_i) is a convex polygon.
//
// The fastest parameterisation (as in TOPP-RA, Pham & Pham 2018) comes from two passes:
//   backward: K_N = {x_end};  K_i = { x : ∃u, (u, x) ∈ P_i, x + 2Δ_i u ∈ K_{i+1} }
//             — the controllable sets, intervals of x computed exactly by clipping polygons;
//   forward:  x₀ = x_start;  u_i = the largest u with (u, x_i) ∈ P_i and x_i + 2Δ_i u ∈ K_{i+1}.
// Greedy maximal acceleration inside the controllable sets is time-optimal for this
// discretisation, and it never gets stuck: K_{i+1} is reachable from every x_i ∈ K_i.
#pragma once

#include <cstddef>
#include <vector>

#include <Eigen/Core>

namespace dispkin::detail {

//! a·u + b·x ≤ c, with u = s̈ and x = ṡ².
struct HalfPlane {
  double a, b, c;
};

//! A convex polygon in the (u, x) plane, as its vertices in order (possibly degenerate: a
//! segment or a point, which is how equalities such as x = 0 appear).
class ConvexPolygon {
 public:
  //! The box |u| ≤ u_bound, 0 ≤ x ≤ x_bound.
  ConvexPolygon(double u_bound, double x_bound);
  //! A copy with room to be clipped further without allocating.
  ConvexPolygon(const ConvexPolygon& other);
  ConvexPolygon(ConvexPolygon&&) noexcept = default;
  //! The vertices and tolerance only, into the storage this polygon has (no allocation once it
  //! has held as many vertices).
  ConvexPolygon& operator=(const ConvexPolygon& other);
  ConvexPolygon& operator=(ConvexPolygon&&) noexcept = default;
  //! Keeps the part with a·u + b·x ≤ c (up to a rounding tolerance relative to the box).
  void clip(const HalfPlane& h);
  bool empty() const noexcept { return vertices_.empty(); }
  //! The smallest and largest x of the polygon (it must not be empty).
  void x_range(double& lo, double& hi) const noexcept;
  //! The largest u with (u, x) in the polygon; false if the line at x misses it.
  bool largest_u_at(double x, double& u) const noexcept;

 private:
  // Room for the vertices a polygon usually reaches (4 of the box and one per binding limit),
  // so that clipping does not allocate.
  static constexpr std::size_t reserved_vertices = 16;
  std::vector<Eigen::Vector2d> vertices_;  // (u, x)
  std::vector<Eigen::Vector2d> scratch_;   // clip()'s output, swapped in
  double tolerance_;
  bool deduplicated_ = false;  // clipped at least once: no repeated vertices
};

//! One interval of the grid: its length Δ_i > 0 and its admissible polygon P_i in (u_i, x_i).
struct GridInterval {
  double delta;
  ConvexPolygon admissible;
};

//! The result of the two passes: x at every grid point (N + 1 values) and u per interval, or
//! the interval where the controllable set became empty (the limits cannot all be kept there
//! at any speed that still reaches the end) — then x and u are empty.
struct Parameterisation {
  std::vector<double> x, u;
  std::ptrdiff_t infeasible_interval = -1;
};

//! The fastest parameterisation from x_start to x_end over `intervals` (see the file comment).
Parameterisation fastest_parameterisation(std::vector<GridInterval> intervals, double x_start, double x_end);

//! The same on the caller's intervals, whose polygons it clips to the controllable sets (no copy).
Parameterisation fastest_parameterisation_clipping(std::vector<GridInterval>& intervals, double x_start, double x_end);

}  // namespace dispkin::detail
