// urdfdom (Debian 3.0) builds some of its error messages from the text of an attribute it
// cannot read and hands them to console_bridge as a printf format: a '%' there ("%n", "%s")
// makes urdf::parseURDF write or read memory it does not own. A '%' has no place in a robot
// description outside comments, so it is refused before urdfdom sees the document.
//
// The check runs on the text as TinyXML decoded it, not on the raw bytes: TinyXML turns a
// numeric character reference into a character by its own rules — digits accumulated with a
// multiplier that wraps at 2³² ("&#x100000025;" is '%'), any number of leading zeros, and in a
// document declared in another encoding than UTF-8 only the low byte of the code point
// ("&#293;" is '%'). Decoding first and checking the decoded text leaves no spelling of a '%'
// unchecked, whatever the decoder's quirks, since urdfdom reads the same parser's output.
#include "urdf_format_text.hpp"

#include <cstring>
#include <stdexcept>
#include <string>

#include <tinyxml.h>

#include "dispkin/error.hpp"

namespace dispkin {
namespace serial {
namespace {

[[noreturn]] void refuse(const TiXmlBase& where, const std::string& what, const char* text) {
  throw std::invalid_argument(
      describe("URDF line " + std::to_string(where.Row()) + ", column " + std::to_string(where.Column()) + ", " + what,
               std::string(text),
               "contains '%' (character references decoded); urdfdom would pass it to "
               "printf as a format (remove it)"));
}

bool has_percent(const char* text) { return text != nullptr && std::strchr(text, '%') != nullptr; }

void require_no_percent(const TiXmlElement& element) {
  const std::string tag = std::string("<") + element.Value() + ">";
  if (has_percent(element.Value())) refuse(element, "element name", element.Value());
  for (const TiXmlAttribute* a = element.FirstAttribute(); a != nullptr; a = a->Next()) {
    if (has_percent(a->Name())) refuse(*a, tag + " attribute name", a->Name());
    if (has_percent(a->Value())) refuse(*a, tag + " attribute \"" + a->Name() + "\"", a->Value());
  }
}

// Every node but comments, in document order; iterative, so the walk needs no stack of its own
// (the nesting depth is bounded before parsing anyway, xml_bounds.cpp).
const TiXmlNode* next_node(const TiXmlNode* node) {
  if (node->FirstChild() != nullptr) return node->FirstChild();
  for (; node != nullptr; node = node->Parent()) {
    if (node->NextSibling() != nullptr) return node->NextSibling();
  }
  return nullptr;
}

}  // namespace

void require_no_printf_directive(const TiXmlDocument& document) {
  for (const TiXmlNode* node = document.FirstChild(); node != nullptr; node = next_node(node)) {
    if (const TiXmlElement* element = node->ToElement()) {
      require_no_percent(*element);
    } else if (node->ToComment() == nullptr && has_percent(node->Value())) {
      // Text (CDATA too), declarations and unknown tags such as <!DOCTYPE …>.
      refuse(*node, node->ToText() != nullptr ? "text" : "markup", node->Value());
    }
  }
}

}  // namespace serial
}  // namespace dispkin
