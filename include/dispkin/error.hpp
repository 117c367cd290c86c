//! Input checks for the planning side: each failure names the argument and its value.
//!
//! Only planning code throws. Sampling code never includes a check that can throw.
#pragma once

#include <cmath>
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
  using type = T;
};
template <typename T>
using non_deduced = typename non_deduced_wrapper<T>::type;

namespace detail {

inline void append_value(std::ostringstream& out, double value) { out << value; }
inline void append_value(std::ostringstream& out, float value) { out << value; }
inline void append_value(std::ostringstream& out, long double value) { out << value; }
inline void append_value(std::ostringstream& out, int value) { out << value; }
inline void append_value(std::ostringstream& out, long value) { out << value; }
inline void append_value(std::ostringstream& out, long long value) { out << value; }
inline void append_value(std::ostringstream& out, unsigned long value) { out << value; }
inline void append_value(std::ostringstream& out, const std::string& value) { out << '"' << value << '"'; }
inline void append_value(std::ostringstream& out, const char* value) { out << '"' << value << '"'; }

template <typename Derived>
void append_value(std::ostringstream& out, const Eigen::DenseBase<Derived>& value) {
  out << '(';
  for (Eigen::Index i = 0; i < value.size(); ++i) {
    if (i > 0) out << ", ";
    out << value.derived().coeff(i);
  }
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
  out << ": " << reason;
  return out.str();
}

//! Throws std::invalid_argument("<argument> = <value>: <reason>") unless `condition` holds.
template <typename Value>
void require(bool condition, std::string_view argument, const Value& value, std::string_view reason) {
  if (!condition) throw std::invalid_argument(describe(argument, value, reason));
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
constexpr double min_limit = 1e-12;
constexpr double max_limit = 1e12;
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
  throw std::invalid_argument(describe(argument, value, "must have coordinates within ±1e12 m (dispkin's numeric range)"));
}

}  // namespace dispkin
