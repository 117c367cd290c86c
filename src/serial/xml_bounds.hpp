// The input budget of a URDF's XML text, checked before any XML parser reads it
// (xml_bounds.cpp, doc/input-budget.md).
#pragma once

#include <string>

namespace dispkin {
namespace serial {

// Throws std::invalid_argument naming the line and column when the text is larger than
// input_budget::max_urdf_bytes, nests elements deeper than input_budget::max_nesting_depth or
// gives one element more than input_budget::max_xml_attributes attributes. Malformed XML
// otherwise passes: the parsers report it.
void require_bounded_xml(const std::string& xml);

}  // namespace serial
}  // namespace dispkin
