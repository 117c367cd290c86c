// Trigonometric polynomials on the circle and where they change sign (internal to the
// offset-wrist search): the positioning stage's first subproblem is solvable exactly where a
// trigonometric polynomial of degree 2 in q₆ is ≥ 0 (ik_offset_wrist.cpp), so its sign changes
// are the ends of every branch's first gap, however narrow.
#pragma once

#include <array>
#include <cmath>
#include <vector>

#include "ik_subproblems.hpp"  // pi

namespace dispkin {
namespace serial {
namespace detail {

//! p(θ) = c₀ + Σₖ (aₖ cos kθ + bₖ sin kθ), k = 1 … degree.
class TrigPolynomial {
 public:
  static constexpr int degree = 3;
  static constexpr int nodes = 2 * degree + 2;  //!< equally spaced: the fit is exact up to `degree`

  //! The trigonometric interpolant of f at θⱼ = −π + 2πj / nodes (a discrete Fourier
  //! transform): f itself when f is a trigonometric polynomial of degree ≤ `degree`.
  template <class F>
  static TrigPolynomial interpolate(F f) {
    TrigPolynomial p;
    for (int j = 0; j < nodes; ++j) {
      const double theta = -pi + 2.0 * pi * j / nodes;
      const double value = f(theta);
      p.c0_ += value / nodes;
      for (int k = 1; k <= degree; ++k) {
        p.a_[static_cast<std::size_t>(k)] += 2.0 * value * std::cos(k * theta) / nodes;
        p.b_[static_cast<std::size_t>(k)] += 2.0 * value * std::sin(k * theta) / nodes;
      }
    }
    return p;
  }

  //! p(θ) and p′(θ); cos kθ, sin kθ by the angle-addition recurrence from one sincos.
  void evaluate(double theta, double& value, double& slope) const noexcept {
    const double c1 = std::cos(theta), s1 = std::sin(theta);
    double ck = 1.0, sk = 0.0;
    value = c0_;
    slope = 0.0;
    for (int k = 1; k <= degree; ++k) {
      const double c = ck * c1 - sk * s1;
      sk = sk * c1 + ck * s1;
      ck = c;
      const auto i = static_cast<std::size_t>(k);
      value += a_[i] * ck + b_[i] * sk;
      slope += k * (b_[i] * ck - a_[i] * sk);
    }
  }

  double value(double theta) const noexcept {
    double v, s;
    evaluate(theta, v, s);
    return v;
  }

  //! A bound on the rounding error of evaluate()'s value: a few ulps of |c₀| + Σ (|aₖ| + |bₖ|).
  double rounding_bound() const noexcept {
    double m = std::abs(c0_);
    for (int k = 1; k <= degree; ++k)
      m += std::abs(a_[static_cast<std::size_t>(k)]) + std::abs(b_[static_cast<std::size_t>(k)]);
    return 8.0 * (2 * degree + 1) * 1.1102230246251565e-16 * m;
  }

  //! Σ k² (|aₖ| + |bₖ|) ≥ |p″(θ)| for every θ.
  double curvature_bound() const noexcept {
    double m = 0.0;
    for (int k = 1; k <= degree; ++k)
      m += k * k * (std::abs(a_[static_cast<std::size_t>(k)]) + std::abs(b_[static_cast<std::size_t>(k)]));
    return m;
  }

 private:
  double c0_ = 0.0;
  std::array<double, degree + 1> a_{};  // aₖ at index k (index 0 unused)
  std::array<double, degree + 1> b_{};
};

//! The θ in [−π, π) where p changes sign, increasing, each within about `resolution` (rad).
//! Subdivision with a certificate: on [m − h, m + h] p keeps the sign of p(m) if
//! |p(m)| > |p′(m)| h + ½ max|p″| h² + δ (Taylor; δ bounds the rounding of p(m), so that a p
//! touching 0 is not given a sign it does not have), so only intervals near a zero are split, about
//! log₂(1/resolution) times per zero; near a double zero (p touching 0) the linear term
//! vanishes with the value and the intervals still shrink geometrically. A zero is reported
//! between two consecutive certified intervals of opposite sign, in the middle of what lies
//! between them, where p is within rounding of 0 (≈ δ / |p′| rad around a simple zero). Zeros
//! closer together than `resolution` are not reported; neither are zeros of even multiplicity. Subdivision stops after
//! `max_intervals` intervals: that bound is reached only by a p that is zero to rounding along an arc (no sign to
//! follow there).
inline std::vector<double> sign_changes(const TrigPolynomial& p, double resolution, int max_intervals = 4096) {
  constexpr int start = 32;
  const double curvature = p.curvature_bound();
  const double rounding = p.rounding_bound();
  struct Interval {
    double lo, hi;
  };
  std::vector<Interval> pending;  // a stack; the lower half is taken first, so θ increases
  pending.reserve(64);
  for (int j = start - 1; j >= 0; --j)
    pending.push_back({-pi + 2.0 * pi * j / start, -pi + 2.0 * pi * (j + 1) / start});
  std::vector<double> zeros;
  bool first_sign = false, last_sign = false, any = false;
  double first_lo = 0.0, last_hi = 0.0;
  for (int visited = 0; !pending.empty() && visited < max_intervals; ++visited) {
    const Interval i = pending.back();
    pending.pop_back();
    const double h = 0.5 * (i.hi - i.lo);
    const double mid = i.lo + h;
    double value, slope;
    p.evaluate(mid, value, slope);
    if (std::abs(value) > std::abs(slope) * h + 0.5 * curvature * h * h + rounding) {
      const bool negative = value < 0.0;
      if (!any) {
        any = true;
        first_sign = negative;
        first_lo = i.lo;
      } else if (negative != last_sign) {
        zeros.push_back(0.5 * (last_hi + i.lo));
      }
      last_sign = negative;
      last_hi = i.hi;
    } else if (2.0 * h > resolution && std::abs(value) + std::abs(slope) * h + 0.5 * curvature * h * h > rounding) {
      // (an interval on which p is within rounding of 0 throughout has no sign to resolve)
      pending.push_back({mid, i.hi});
      pending.push_back({i.lo, mid});
    }
  }
  // Round the turn: from the last certified interval to the first.
  if (any && last_sign != first_sign) {
    const double zero = 0.5 * (last_hi + first_lo + 2.0 * pi);
    if (zero < pi) {
      zeros.push_back(zero);
    } else {
      zeros.insert(zeros.begin(), zero - 2.0 * pi);
    }
  }
  return zeros;
}

}  // namespace detail
}  // namespace serial
}  // namespace dispkin
