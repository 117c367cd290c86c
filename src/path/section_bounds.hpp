// The bounds of any section of a path, for the planner's cut (src/planning/planner.cpp) and a
// path's lengths (path.cpp): internal to the library.
#pragma once

#include "dispkin/path/group_factors.hpp"
#include "dispkin/path/path.hpp"

namespace dispkin::detail {

//! Length and acceleration bound of any section from `factors` (whose pivot it sets).
SectionBounds section_bounds(const Section& section, GroupFactors& factors);
//! The same with a LIN's length bounded from its middle instead of solved exactly: the
//! fastest object's speed at the middle plus half the weighted acceleration bound. Tight on
//! short pieces of a LIN (the planner's cut, doc/planning.md §9), and cheaper.
SectionBounds section_bounds_from_middle(const Section& section, GroupFactors& factors);

}  // namespace dispkin::detail
