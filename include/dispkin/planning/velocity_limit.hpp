//! Time-optimal laws under a velocity-limit curve v_lim(s) (doc/profiles.md §5): the curve is
//! piecewise constant — one value per segment of the path — and the law is a chain of Profiles, one
//! per segment, whose boundary velocities come from the classic two passes: forward (how fast can
//! it be when it gets here), backward (how fast may it be to still slow down in time), each
//! boundary at most the smaller limit of its two segments.
//!
//! The change of velocity from u to w costs at least the distance
//!   trapezoid:  |w² − u²| / (2a)
//!   S-curve:    (u + w)/2 · T,  T = Δ/a + a/j if Δ ≥ a²/j, else 2√(Δ/j),  Δ = |w − u|
//! (a jerk-limited change from rest acceleration to rest acceleration is symmetric in time, so
//! its distance is the mean velocity times its duration). For the trapezoid the result is the
//! time-optimal law under v_lim. For the S-curve every segment of the chain starts and ends with
//! zero acceleration — time-optimal per segment, slow across many short segments — so the S-curve
//! law ending at rest is also built carrying acceleration across boundaries (§8), and the faster
//! of the two is taken.
#pragma once

#include <optional>
#include <vector>

#include "dispkin/profile.hpp"

namespace dispkin {

//! One piece of a piecewise-constant velocity limit: `length` of path at speed ≤ `limit`, and
//! acceleration ≤ `acceleration` when positive (a move's own limit; 0: the law's a_max).
struct LimitedSegment {
  double length;              //!< > 0
  double limit;               //!< > 0
  double acceleration = 0.0;  //!< ≥ 0; min(acceleration, a_max) when positive
};

//! The least distance a law needs to go from velocity u to w (both ≥ 0) under a (and j, if
//! given), starting and ending with zero acceleration.
double velocity_change_distance(double u, double w, double a, std::optional<double> j) noexcept;

//! The chain of laws over `segments` of doc/profiles.md §5: one Profile per segment, its
//! boundary velocities from the two passes, every boundary crossed at zero acceleration; from
//! v_start to v_end (each at most the limit of its segment); segment i accelerates at most at its
//! own acceleration (when given) and a_max. For the trapezoid it is the time-optimal law under the
//! staircase. Throws std::invalid_argument for bad input (naming it) or if v_end cannot be reached
//! (too little distance to slow down or speed up).
std::vector<Profile> velocity_limited_chain(const std::vector<LimitedSegment>& segments, double a_max,
                                            std::optional<double> j_max, double v_start = 0.0, double v_end = 0.0);

//! The law under the staircase (doc/profiles.md §5, §8): the chain above, or, for the S-curve
//! ending at rest, the law that carries acceleration across the boundaries where it is faster —
//! never slower than the chain. The laws come in order, each within one segment (a segment may
//! hold several); their s, ṡ (and s̈ for the S-curve) join continuously, ṡ ≤ the limit of the
//! segment at every instant. Throws as velocity_limited_chain.
std::vector<Profile> velocity_limited_law(const std::vector<LimitedSegment>& segments, double a_max,
                                          std::optional<double> j_max, double v_start = 0.0, double v_end = 0.0);

//! A duration no law under the staircase with |s̈| ≤ each segment's acceleration (and a_max),
//! |s⃛| ≤ j_max, from v_start to v_end, can beat (doc/profiles.md §8.5, eqs. 34–37): the largest
//! sum, over cuts of the staircase into windows, of the least time each window needs when only its
//! end limits, its highest limit and the acceleration and jerk limits are kept. How far a law
//! could still gain: velocity_limited_law's duration lies between it and the law's own. Throws as
//! velocity_limited_chain for bad input.
double jerk_limited_duration_bound(const std::vector<LimitedSegment>& segments, double a_max, double j_max,
                                   double v_start = 0.0, double v_end = 0.0);

}  // namespace dispkin
