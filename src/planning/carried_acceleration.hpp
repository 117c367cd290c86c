// The jerk-limited law under a velocity-limit staircase that carries acceleration across segment
// boundaries (internal to velocity_limited_law; doc/profiles.md §8).
#pragma once

#include <optional>
#include <vector>

#include "dispkin/planning/velocity_limit.hpp"
#include "dispkin/profile.hpp"

namespace dispkin::detail {

//! The staircase law of doc/profiles.md §8: in time, always the largest jerk (+j, 0, or the
//! jerk of the fastest stop) after which the fastest stop to rest stays under the staircase and
//! ends on the path; segment i is crossed with |s̈| ≤ accelerations[i]. From (0, v_start, 0)
//! to rest at the end of the last segment. Returns laws in order, each within one segment (a
//! segment may hold several), or nothing where the law does not settle (too many phases, a check
//! of the result fails); the caller keeps the chain of §5 then. Input is validated by the caller.
std::optional<std::vector<Profile>> carried_acceleration_law(const std::vector<LimitedSegment>& segments,
                                                             const std::vector<double>& accelerations, double j_max,
                                                             double v_start, double v_end, bool settle_in_troughs);

//! The same motion run backwards: laws in reverse order, each from its end state to its start
//! state with the acceleration's sign turned (s⃛ keeps its sign). A law of the reversed staircase
//! reversed in time is a law of the staircase.
std::vector<Profile> reversed_in_time(const std::vector<Profile>& laws);

}  // namespace dispkin::detail
