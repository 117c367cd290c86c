// A lexical pass over XML text that bounds what the parsers would build from it. TinyXML
// (read by urdfdom and by urdf_joint_graph.cpp) parses and frees elements recursively, one
// stack frame per level, so 4·10⁴ nested elements overflow the stack; and it looks every new
// attribute up among an element's earlier ones, so 4·10⁴ attributes take half a minute. The
// pass reads tags the way TinyXML does (comments, CDATA, declarations and quoted attribute
// values skipped) and counts depth and attributes, without building anything.
#include "xml_bounds.hpp"

#include <stdexcept>
#include <string>

#include "dispkin/error.hpp"
#include "dispkin/input_budget.hpp"

namespace dispkin {
namespace serial {
namespace {

class Scanner {
 public:
  explicit Scanner(const std::string& xml) : xml_(xml) {}

  void run() {
    while (i_ < xml_.size()) {
      if (xml_[i_] != '<') {
        step();
        continue;
      }
      if (starts("<!--")) {
        skip_past("-->");
      } else if (starts("<![CDATA[")) {
        skip_past("]]>");
      } else if (starts("<?") || starts("<!")) {
        // TinyXML ends declarations and DOCTYPEs at the first '>'; so does this pass, so it
        // never skips text that TinyXML reads as elements.
        skip_past(">");
      } else if (starts("</")) {
        skip_past(">");
        if (depth_ > 0) --depth_;
      } else {
        open_tag();
      }
    }
  }

 private:
  bool starts(const char* s) const { return xml_.compare(i_, std::char_traits<char>::length(s), s) == 0; }

  void step() {
    if (xml_[i_] == '\n') {
      ++line_;
      line_start_ = i_ + 1;
    }
    ++i_;
  }

  void skip_past(const char* end) {
    const std::size_t n = std::char_traits<char>::length(end);
    while (i_ < xml_.size() && xml_.compare(i_, n, end) != 0) step();
    for (std::size_t k = 0; k < n && i_ < xml_.size(); ++k) step();
  }

  std::string where(std::size_t at_line, std::size_t at_column) const {
    return "line " + std::to_string(at_line) + ", column " + std::to_string(at_column);
  }

  // '<name attr="…" …>' or '… />': attributes are counted by their '=' outside quotes.
  void open_tag() {
    const std::size_t line = line_, column = i_ - line_start_ + 1;
    step();  // '<'
    int attributes = 0;
    bool closed_here = false;
    while (i_ < xml_.size() && xml_[i_] != '>') {
      const char c = xml_[i_];
      if (c == '"' || c == '\'') {
        step();
        while (i_ < xml_.size() && xml_[i_] != c) step();
        if (i_ < xml_.size()) step();
        continue;
      }
      if (c == '=' && ++attributes > input_budget::max_xml_attributes) {
        throw std::invalid_argument(describe(
            "URDF element at", where(line, column),
            "has more than " + std::to_string(input_budget::max_xml_attributes) + " attributes (doc/input-budget.md)"));
      }
      closed_here = c == '/';
      step();
    }
    if (i_ < xml_.size()) step();  // '>'
    if (closed_here) return;
    if (++depth_ > input_budget::max_nesting_depth) {
      throw std::invalid_argument(describe(
          "URDF element at", where(line, column),
          "nests deeper than " + std::to_string(input_budget::max_nesting_depth) + " elements (doc/input-budget.md)"));
    }
  }

  const std::string& xml_;
  std::size_t i_ = 0;
  std::size_t line_ = 1;
  std::size_t line_start_ = 0;
  int depth_ = 0;
};

}  // namespace

void require_bounded_xml(const std::string& xml) {
  require(xml.size() <= input_budget::max_urdf_bytes, "URDF size", static_cast<unsigned long>(xml.size()),
          "more than " + std::to_string(input_budget::max_urdf_bytes) +
              " bytes, the limit of a URDF (doc/input-budget.md)");
  Scanner(xml).run();
}

}  // namespace serial
}  // namespace dispkin
