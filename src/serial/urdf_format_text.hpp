// The decoded text of a URDF, checked for what urdfdom would hand to printf as a format
// (urdf_format_text.cpp, doc/input-budget.md).
#pragma once

class TiXmlDocument;

namespace dispkin {
namespace serial {

// Throws std::invalid_argument naming the line, column, element and attribute (or text) when a
// name, attribute value or text of the parsed document holds a '%'. The document is the one
// TinyXML built from the same text urdfdom will parse, so character references, whatever their
// spelling, are already decoded exactly as urdfdom will see them.
void require_no_printf_directive(const TiXmlDocument& document);

}  // namespace serial
}  // namespace dispkin
