// Time laws that start from a moving state of a planned trajectory: the fastest stop (feed hold)
// and the law over a run's velocity-limit staircase from that state (internal to the trajectory
// events, trajectory_events.cpp; doc/events.md).
#pragma once

#include <optional>
#include <vector>

#include "dispkin/planning/velocity_limit.hpp"
#include "dispkin/profile.hpp"

namespace dispkin::detail {

//! The fastest stop from ṡ = v0 ≥ 0, s̈ = a0 to rest (ṡ = s̈ = 0) under |s̈| ≤ a_max and
//! |s⃛| ≤ j_max (doc/events.md eqs. 1–4), never running backwards: at full jerk to the peak
//! deceleration, held at a_max if it is reached, and back to 0 at full jerk. A state beyond the
//! limits (|a0| > a_max) eases back onto them at full jerk. Without a jerk limit (the trapezoid)
//! a0 is not a state: the stop decelerates at a_max. At rest (v0 = 0 and a0 = 0) there is no law.
//! A state below the release curve (a0 < 0 with a0² / 2j > v0: ṡ would reach 0 before s̈ can,
//! which a trajectory's laws reach by rounding only) stops from ṡ = a0² / 2j.
std::optional<Profile> fastest_stop(double v0, double a0, double a_max, std::optional<double> j_max);

//! The fastest stop from (v0, a0) under the smallest acceleration limit of `segments` (a run's
//! staircase, which ends at rest), then from rest the staircase law over what is left: the
//! law from a state that every other law keeps above (doc/events.md §1), so it keeps under the
//! curve wherever any law does. Throws std::invalid_argument if the stop overruns the run
//! (beyond `tolerance`, m).
std::vector<Profile> stop_then_staircase(const std::vector<LimitedSegment>& segments, double a_max,
                                         std::optional<double> j_max, double v0, double a0, double tolerance);

//! The law over a run's staircase `segments` (which ends at rest) from the moving state
//! (v0, a0) at its start (doc/events.md §3): on the first segments the time-optimal law from the
//! state (Profile::from_state), which first eases onto the limits where the state lies above
//! them, to the highest velocity from which the rest of the staircase is reached, then the
//! staircase law of velocity_limited_law. Segments are merged into the first law while they are
//! too short for it. Where no such law fits the whole run (the state releases its braking onto
//! rest), the fastest stop and from rest the staircase law over what is left; a stop that ends
//! within `tolerance` (m: the rounding of path positions) of the run's end is the law. Throws
//! std::invalid_argument if the state cannot come to rest within the run.
std::vector<Profile> staircase_law_from_state(const std::vector<LimitedSegment>& segments, double a_max,
                                              std::optional<double> j_max, double v0, double a0, double tolerance);

}  // namespace dispkin::detail
