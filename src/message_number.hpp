// A number in an error message (internal to the library's sources).
#pragma once

#include <sstream>
#include <string>

namespace dispkin::detail {

// A length, speed or time in a message: 12 digits, as describe() (error.hpp) writes values.
inline std::string number(double x) {
  std::ostringstream out;
  out.precision(12);
  out << x;
  return out.str();
}

}  // namespace dispkin::detail
