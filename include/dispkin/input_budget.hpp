//! The input budget of dispkin's readers (doc/input-budget.md): how large and how deep
//! a file, and how many IK solutions, one call accepts. Each is checked once, where the
//! reader first sees its input, before anything is built from it, so that a short hostile
//! file cannot take the stack (deep nesting) or the memory (a huge count) and a real robot or
//! job stays far below them.
#pragma once

#include <cstddef>
#include <istream>
#include <string>

namespace dispkin {
namespace input_budget {

//! Deepest nesting of arrays/objects (JSON) or elements (XML). Parsers and destructors
//! recurse once per level; a hexapod description is 4 deep, a URDF 5 or 6.
constexpr int max_nesting_depth = 100;

//! Largest hexapod description (JSON text), bytes: a six-leg description is about 2 kB.
constexpr std::size_t max_hexapod_json_bytes = std::size_t(1) << 20;

//! Largest URDF text, bytes: real robots are below 1 MB (meshes are separate files), and
//! the XML trees of TinyXML and urdfdom take about ten times the text.
constexpr std::size_t max_urdf_bytes = std::size_t(16) << 20;

//! Most attributes on one XML element: TinyXML looks each new attribute up among the ones
//! before it (quadratic time), and URDF elements have at most ten.
constexpr int max_xml_attributes = 100;

//! Most IK solutions SerialArm::inverse_solutions returns when asked for the 2π copies too
//! (InverseOptions::offer_equivalents): 8 branches × 2⁶ copies of a 6R arm with ±2π limits
//! are 512; the copies of wide limits (±20 rad: 5·10⁵, ±100 rad: 10¹⁰) are refused, not
//! enumerated.
constexpr std::size_t max_ik_solutions = 10000;

//! Reads the stream into `text` in blocks, stopping once it holds more than `limit` bytes:
//! false then (the file is too large, and was not read to its end).
inline bool read_at_most(std::istream& in, std::size_t limit, std::string& text) {
  text.clear();
  char block[1 << 16];
  while (text.size() <= limit && (in.read(block, sizeof block) || in.gcount() > 0))
    text.append(block, static_cast<std::size_t>(in.gcount()));
  return text.size() <= limit;
}

}  // namespace input_budget
}  // namespace dispkin
