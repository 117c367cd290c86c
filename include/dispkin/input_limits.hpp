//! Deprecated: the former name of dispkin/input_budget.hpp, kept so that code written against
//! it still compiles. Include `dispkin/input_budget.hpp` and name `dispkin::input_budget`; this
//! header and the namespace alias go in a later release.
#pragma once

#include "dispkin/input_budget.hpp"

namespace dispkin {

//! Deprecated alias of dispkin::input_budget, the readers' input budget (doc/input-budget.md).
namespace input_limits = input_budget;

}  // namespace dispkin
