// The checks every law under a staircase makes of its input (velocity_limit.cpp,
// duration_bound.cpp; doc/profiles.md §5).
#pragma once

#include <optional>
#include <vector>

#include "dispkin/planning/velocity_limit.hpp"

namespace dispkin::detail {

// Throws std::invalid_argument naming the first bad value: an empty staircase, a segment's
// length or limit not positive and finite, its acceleration negative or not finite, a_max or
// j_max not positive, v_start / v_end outside [0, the limit of their segment].
void require_staircase(const std::vector<LimitedSegment>& segments, double a_max, std::optional<double> j_max,
                       double v_start, double v_end);

// Segment i's acceleration limit: its own where given, capped by a_max.
inline double segment_acceleration(const LimitedSegment& segment, double a_max) {
  return segment.acceleration > 0.0 ? (segment.acceleration < a_max ? segment.acceleration : a_max) : a_max;
}

}  // namespace dispkin::detail
