// Whether a time law keeps under a velocity-limit curve everywhere, not only at its peak
// (internal to the trajectory checks and the events: trajectory.cpp, trajectory_events.cpp).
#pragma once

#include <cstddef>
#include <vector>

#include "dispkin/planning/trajectory.hpp"
#include "dispkin/profile.hpp"

namespace dispkin::detail {

//! The highest ṡ of `law`, run up to t_end, while its position is in [s0, s1] (relative to its
//! start): where it enters and leaves (found by bisection on s(t), which never decreases), where
//! its phases meet and where ṡ peaks inside a phase (s̈ = 0).
double peak_between(const Profile& law, double t_end, double s0, double s1);

//! Whether `law` (from path position start_s, run up to t_end, peak ṡ `peak`) keeps under the
//! top of every span of `spans` it crosses — the limit, or the ceiling an override may reach —
//! to 1e-8. A law that eases down from a state above the curve ahead (an event's) crosses spans
//! of several limits, and its peak at the start says nothing of where it meets a lower one; a
//! law whose peak is under the lowest top it crosses passes without a search. `first`: the
//! first span it may cross; positions agree to tol_s.
bool keeps_under_tops(const Profile& law, double t_end, double start_s, double peak,
                      const std::vector<SpeedLimit>& spans, std::size_t first, double tol_s);

}  // namespace dispkin::detail
