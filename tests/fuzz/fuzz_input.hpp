//! Shared pieces of the libFuzzer targets: numbers read from the fuzzer's bytes, and the rule
//! that decides what counts as a finding.
//!
//! A target feeds a public entry point whatever the bytes make of its arguments. Bad input must
//! end in std::invalid_argument or std::runtime_error (the project's error contract); anything
//! else — another exception type, a sanitizer report, a crash, or a NaN/infinity coming out of
//! a call that did not throw — is a finding and aborts, so that libFuzzer keeps the input.
//!
//! Numeric range: finite inputs far outside any physical scale (|x| > 1e12 or 0 < |x| < 1e-12,
//! e.g. a translation of 1e308 m or a speed limit of 1e-308 m/s) still must not crash, trip a
//! sanitizer or throw a foreign exception, but an infinite output they cause by overflow is not
//! counted. dispkin's accepted range (README, "Numeric range") refuses such translations and
//! limits at the constructors and laws, but not every argument of every function (the noexcept
//! pose arithmetic, Pose::exp of a huge twist, points of a metric set); DISPKIN_FUZZ_STRICT=1
//! counts those too. NaN and infinite inputs are always in play: they must be refused, whatever
//! else the input holds.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <limits>
#include <stdexcept>
#include <string>
#include <typeinfo>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <dispkin/pose.hpp>

namespace dispkin::fuzz {

//! The magnitudes the numeric range covers (see the file comment).
constexpr double range_max = 1e12;
constexpr double range_min = 1e-12;

namespace detail {
//! Whether every finite number of the current input lies in the numeric range.
inline bool& inputs_in_range() {
  static bool in_range = true;
  return in_range;
}
inline bool strict() {
  static const bool strict = std::getenv("DISPKIN_FUZZ_STRICT") != nullptr;
  return strict;
}
}  // namespace detail

//! Reads numbers from the fuzzer's bytes; past the end it yields zeros.
class Input {
 public:
  Input(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) { detail::inputs_in_range() = true; }

  std::uint8_t byte() { return pos_ < size_ ? data_[pos_++] : std::uint8_t(0); }
  bool flag() { return (byte() & 1) != 0; }
  //! An integer in [0, n).
  int below(int n) { return n <= 0 ? 0 : static_cast<int>(byte() % static_cast<unsigned>(n)); }
  std::size_t remaining() const { return size_ - pos_; }

  //! A double, chosen by a mode byte: raw IEEE bytes (any NaN payload, infinities, denormals,
  //! 1e±308), a special value, or a moderate number (int16 / 256, the range real data lives in,
  //! so that the deeper code is reached too).
  double number() {
    const double x = read_number();
    // DISPKIN_FUZZ_TRACE=1 prints every number, to turn a saved crash input into a test case.
    static const bool trace = std::getenv("DISPKIN_FUZZ_TRACE") != nullptr;
    if (trace) std::fprintf(stderr, "number %.17g\n", x);
    const double m = std::abs(x);
    if (std::isfinite(m) && (m > range_max || (m > 0.0 && m < range_min))) detail::inputs_in_range() = false;
    return x;
  }

  Eigen::Vector3d vector3() {
    const double x = number(), y = number(), z = number();
    return {x, y, z};
  }
  Eigen::Matrix<double, 6, 1> vector6() {
    Eigen::Matrix<double, 6, 1> v;
    for (int i = 0; i < 6; ++i) v(i) = number();
    return v;
  }

  //! A pose: mostly valid ones (a normalised quaternion, so construction succeeds and the
  //! callee is reached), sometimes straight from the bytes (the constructor's checks are fuzzed).
  Posed pose() {
    const double w = number(), x = number(), y = number(), z = number();
    const Eigen::Vector3d t = vector3();
    Eigen::Quaterniond q(w, x, y, z);
    if (flag()) {
      const double n = q.norm();
      if (std::isfinite(n) && n > 1e-150 && n < 1e150) q.coeffs() /= n;
    }
    return Posed(q, t);  // may throw std::invalid_argument: an expected outcome
  }

 private:
  double read_number() {
    switch (byte() % 8) {
      case 0: {
        unsigned char raw[sizeof(double)] = {};
        for (unsigned char& b : raw) b = byte();
        double x;
        std::memcpy(&x, raw, sizeof x);
        return x;
      }
      case 1: {
        static const double special[] = {0.0,
                                         -0.0,
                                         1.0,
                                         -1.0,
                                         std::numeric_limits<double>::quiet_NaN(),
                                         std::numeric_limits<double>::infinity(),
                                         -std::numeric_limits<double>::infinity(),
                                         std::numeric_limits<double>::max(),
                                         -std::numeric_limits<double>::max(),
                                         std::numeric_limits<double>::min(),
                                         std::numeric_limits<double>::denorm_min(),
                                         std::numeric_limits<double>::epsilon(),
                                         1e-300,
                                         1e300,
                                         1e-12,
                                         1e12};
        return special[byte() % (sizeof special / sizeof special[0])];
      }
      default: {
        const auto hi = static_cast<std::uint16_t>(byte()), lo = static_cast<std::uint16_t>(byte());
        return static_cast<double>(static_cast<std::int16_t>(static_cast<std::uint16_t>(hi << 8 | lo))) / 256.0;
      }
    }
  }

  const std::uint8_t* data_;
  std::size_t size_;
  std::size_t pos_ = 0;
};

//! Aborts with `what` (libFuzzer then saves the input as a crash).
[[noreturn]] inline void finding(const char* what) {
  std::fprintf(stderr, "dispkin fuzz finding: %s\n", what);
  std::abort();
}

//! A non-finite output: a finding unless an input was outside the numeric range.
inline void non_finite(const char* what) {
  if (detail::inputs_in_range() || detail::strict()) finding(what);
}

//! A relative bound (ṡ ≤ v_max to 1e-9, ...) broken: counted like a non-finite output, since
//! at magnitudes outside the range rounding alone can break a relative bound.
inline void out_of_bound(const char* what) { non_finite(what); }

//! A finite output of a call that did not throw.
inline void check_finite(double x, const char* what) {
  if (!std::isfinite(x)) non_finite(what);
}
template <typename Derived>
void check_finite(const Eigen::DenseBase<Derived>& x, const char* what) {
  if (!x.derived().allFinite()) non_finite(what);
}
inline void check_finite(const Posed& p, const char* what) {
  check_finite(p.quaternion().coeffs(), what);
  check_finite(p.translation(), what);
  if (p.quaternion().coeffs().allFinite() && std::abs(p.quaternion().norm() - 1.0) > 1e-9) finding(what);
}

//! Runs `body`; the project's error types are expected, every other exception is a finding.
template <typename Body>
void expect_clean(Body&& body) {
  try {
    body();
  } catch (const std::invalid_argument&) {
  } catch (const std::runtime_error&) {
  } catch (const std::exception& e) {
    std::fprintf(stderr, "dispkin fuzz finding: unexpected exception %s: %s\n", typeid(e).name(), e.what());
    std::abort();
  } catch (...) {
    finding("unexpected exception of a non-std type");
  }
}

}  // namespace dispkin::fuzz
