//! Input checks for the planning side: each failure names the argument and its value.
//!
//! Only planning code throws. Sampling code never includes a check that can throw.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <sstream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>

#include <Eigen/Core>

namespace dispkin {

//! T in a position that template argument deduction skips, so that `f(radius, V::Zero())` or
//! `f(set, a, b, 0.5)` deduce the scalar from the other arguments (std::type_identity, C++20).
template <typename T>
struct non_deduced_wrapper {
  using type = T;  //!< T itself
};
//! T, not deduced (non_deduced_wrapper<T>::type).
template <typename T>
using non_deduced = typename non_deduced_wrapper<T>::type;

//! How much of a value a message repeats: a message names the value, it does not echo a whole
//! file back (a 150 MB JSON array, a 10⁵-character attribute). Longer strings are cut, with
//! their length given; vectors and matrices show their first coefficients.
//!@{
constexpr std::size_t max_echoed_characters = 200;
constexpr Eigen::Index max_echoed_coefficients = 24;
//!@}

namespace detail {

//! Length of the valid UTF-8 sequence starting at text[i] (0 when there is none): the byte
//! ranges of RFC 3629 §4, which exclude overlong forms, surrogates and values beyond U+10FFFF.
inline std::size_t utf8_sequence(std::string_view text, std::size_t i) noexcept {
  const auto byte = [&](std::size_t k) { return k < text.size() ? static_cast<unsigned char>(text[k]) : 0u; };
  const unsigned c = byte(i);
  const auto tail = [&](std::size_t k) { return byte(k) >= 0x80 && byte(k) <= 0xBF; };
  if (c < 0x80) return 1;
  if (c >= 0xC2 && c <= 0xDF) return tail(i + 1) ? 2 : 0;
  if (c >= 0xE0 && c <= 0xEF) {
    const unsigned lo = c == 0xE0 ? 0xA0 : 0x80, hi = c == 0xED ? 0x9F : 0xBF;
    return byte(i + 1) >= lo && byte(i + 1) <= hi && tail(i + 2) ? 3 : 0;
  }
  if (c >= 0xF0 && c <= 0xF4) {
    const unsigned lo = c == 0xF0 ? 0x90 : 0x80, hi = c == 0xF4 ? 0x8F : 0xBF;
    return byte(i + 1) >= lo && byte(i + 1) <= hi && tail(i + 2) && tail(i + 3) ? 4 : 0;
  }
  return 0;
}

}  // namespace detail

//! The text with every byte that is not part of valid UTF-8 written as `\xNN`: a message is
//! shown as a Python str (and on terminals), which must decode, whatever bytes a file held.
inline std::string valid_utf8(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (std::size_t i = 0; i < text.size();) {
    const std::size_t n = detail::utf8_sequence(text, i);
    if (n > 0) {
      out.append(text.substr(i, n));
      i += n;
    } else {
      static const char hex[] = "0123456789abcdef";
      const auto c = static_cast<unsigned char>(text[i++]);
      out += "\\x";
      out += hex[c >> 4];
      out += hex[c & 15];
    }
  }
  return out;
}

//! At most max_echoed_characters of the text (cut on a character boundary), then
//! "… (N characters)"; valid UTF-8 either way.
inline std::string echoed(std::string_view text) {
  if (text.size() <= max_echoed_characters) return valid_utf8(text);
  std::size_t cut = max_echoed_characters;
  while (cut > 0 && (static_cast<unsigned char>(text[cut]) & 0xC0) == 0x80) --cut;
  return valid_utf8(text.substr(0, cut)) + "… (" + std::to_string(text.size()) + " characters)";
}

namespace detail {

inline void append_value(std::ostringstream& out, double value) { out << value; }
inline void append_value(std::ostringstream& out, float value) { out << value; }
inline void append_value(std::ostringstream& out, long double value) { out << value; }
inline void append_value(std::ostringstream& out, int value) { out << value; }
inline void append_value(std::ostringstream& out, long value) { out << value; }
inline void append_value(std::ostringstream& out, long long value) { out << value; }
inline void append_value(std::ostringstream& out, unsigned long value) { out << value; }
inline void append_value(std::ostringstream& out, const std::string& value) { out << '"' << echoed(value) << '"'; }
inline void append_value(std::ostringstream& out, const char* value) { out << '"' << echoed(value) << '"'; }

template <typename Derived>
void append_value(std::ostringstream& out, const Eigen::DenseBase<Derived>& value) {
  out << '(';
  const Eigen::Index shown = std::min(value.size(), max_echoed_coefficients);
  for (Eigen::Index i = 0; i < shown; ++i) {
    if (i > 0) out << ", ";
    out << value.derived().coeff(i);
  }
  if (shown < value.size()) out << ", … (" << value.size() << " values)";
  out << ')';
}

//! "t = … s (path position s = … m)": where on a trajectory a message is about; only the path
//! position when t is NaN.
inline std::string where(double t, double s) {
  std::ostringstream out;
  if (std::isnan(t)) {
    out << "path position s = " << s << " m";
  } else {
    out << "t = " << t << " s (path position s = " << s << " m)";
  }
  return out.str();
}

}  // namespace detail

//! The message "<argument> = <value>: <reason>", the shape every dispkin error has.
template <typename Value>
std::string describe(std::string_view argument, const Value& value, std::string_view reason) {
  std::ostringstream out;
  out.precision(12);  // enough to recognise a value, short enough to read
  out << argument << " = ";
  detail::append_value(out, value);
  out << ": " << valid_utf8(reason);
  return out.str();
}

//! Throws std::invalid_argument("<argument> = <value>: <reason>") unless `condition` holds.
template <typename Value>
void require(bool condition, std::string_view argument, const Value& value, std::string_view reason) {
  if (!condition) throw std::invalid_argument(describe(argument, value, reason));
}

//! require() for checks on the planning path of every object (each law, each section): the
//! argument's name and the reason are made by `argument()` and `reason()` only on failure.
template <typename Value, typename Argument, typename Reason>
void require_lazily(bool condition, Argument argument, const Value& value, Reason reason) {
  if (!condition) throw std::invalid_argument(describe(argument(), value, reason()));
}

//! A finite scalar (not NaN, not ±inf).
template <typename Scalar, typename = std::enable_if_t<!std::is_base_of_v<Eigen::EigenBase<Scalar>, Scalar>>>
void require_finite(Scalar value, std::string_view argument) {
  using std::isfinite;
  require(static_cast<bool>(isfinite(value)), argument, value, "must be finite");
}

//! Every coefficient finite.
template <typename Derived>
void require_finite(const Eigen::DenseBase<Derived>& value, std::string_view argument) {
  require(value.derived().allFinite(), argument, value, "must be finite (no NaN or infinity)");
}

//! A finite, strictly positive scalar (speed limits, accelerations, lengths of shapes).
template <typename Scalar>
void require_positive(Scalar value, std::string_view argument) {
  using std::isfinite;
  require(static_cast<bool>(isfinite(value)) && value > Scalar(0), argument, value,
          "must be finite and greater than zero");
}

//! dispkin's accepted numeric range (README, "Numeric range"): inputs beyond it are refused
//! where they would overflow to an infinite or NaN result; inside it every result is finite.
//! The stated tolerances hold over the narrower tested range the README gives.
namespace numeric_range {
//! Largest |coordinate| of a pose's translation (m): pose products, inverses and pivots of
//! translations up to 1e12 m stay far from overflow (1e308).
constexpr double max_translation = 1e12;
//! Speed, acceleration and jerk limits of a plan or metric set (m/s, m/s², m/s³): in
//! [min_limit, max_limit], so that durations, ramps and their products stay finite.
//!@{
constexpr double min_limit = 1e-12;
constexpr double max_limit = 1e12;
//!@}
}  // namespace numeric_range

//! A speed, acceleration or jerk limit inside numeric_range [min_limit, max_limit].
template <typename Scalar>
void require_limit(Scalar value, std::string_view argument) {
  using std::isfinite;
  require(static_cast<bool>(isfinite(value)) && value >= Scalar(numeric_range::min_limit) &&
              value <= Scalar(numeric_range::max_limit),
          argument, value, "must be in [1e-12, 1e12] (finite, positive, inside dispkin's numeric range)");
}

//! Whether every coordinate is finite and at most numeric_range::max_translation (the fast
//! test before require_translation in loops over many points).
template <typename Derived>
bool within_translation_range(const Eigen::DenseBase<Derived>& value) {
  using Scalar = typename Derived::Scalar;
  return value.allFinite() && value.derived().cwiseAbs().maxCoeff() <= Scalar(numeric_range::max_translation);
}

//! A translation whose coordinates are finite and at most numeric_range::max_translation.
template <typename Derived>
void require_translation(const Eigen::DenseBase<Derived>& value, std::string_view argument) {
  if (within_translation_range(value)) return;
  require_finite(value, argument);
  throw std::invalid_argument(
      describe(argument, value, "must have coordinates within ±1e12 m (dispkin's numeric range)"));
}

}  // namespace dispkin
