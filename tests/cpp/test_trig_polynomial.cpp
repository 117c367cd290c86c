// The sign changes of a trigonometric polynomial (src/serial/trig_polynomial.hpp): what the
// offset-wrist search relies on to find the gaps of its first subproblem however narrow.
#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "trig_polynomial.hpp"

namespace dispkin {
namespace {

using serial::detail::sign_changes;
using serial::detail::TrigPolynomial;

TEST(TrigPolynomial, InterpolationIsExactUpToItsDegree) {
  auto f = [](double t) { return 0.3 - 1.2 * std::cos(t) + 0.7 * std::sin(2.0 * t) + 0.05 * std::cos(3.0 * t); };
  const TrigPolynomial p = TrigPolynomial::interpolate(f);
  for (double t = -3.0; t <= 3.0; t += 0.37) {
    double value, slope;
    p.evaluate(t, value, slope);
    EXPECT_NEAR(value, f(t), 1e-14);
    EXPECT_NEAR(slope, 1.2 * std::sin(t) + 1.4 * std::cos(2.0 * t) - 0.15 * std::sin(3.0 * t), 1e-14);
  }
}

// An arc of width 2w around θ₀ where p = cos(θ − θ₀) − cos w ≥ 0: both its ends are found,
// down to w = 1e-6 (below, cos w rounds towards 1 and p no longer has the arc to rounding).
TEST(TrigPolynomial, FindsBothEndsOfANarrowArc) {
  for (double width : {1.0, 1e-2, 1e-4, 1e-6}) {
    for (double centre : {-3.0, -0.4, 0.0, 1.7, 3.1}) {
      const TrigPolynomial p =
          TrigPolynomial::interpolate([&](double t) { return std::cos(t - centre) - std::cos(width); });
      const std::vector<double> zeros = sign_changes(p, 1e-10);
      ASSERT_EQ(zeros.size(), 2u) << "width " << width << " centre " << centre;
      // The zeros are ±w from the centre, to the rounding of p (≈ u / w in θ) or the resolution.
      for (double z : zeros) EXPECT_LT(std::abs(std::abs(std::remainder(z - centre, 2.0 * M_PI)) - width), 1e-9) << z;
      EXPECT_LT(zeros[0], zeros[1]);
    }
  }
}

TEST(TrigPolynomial, ReportsNoSignChangeForATouchingOrSignDefinitePolynomial) {
  // 1 − cos θ touches zero at θ = 0 without changing sign; 2 + sin θ never vanishes.
  EXPECT_TRUE(sign_changes(TrigPolynomial::interpolate([](double t) { return 1.0 - std::cos(t); }), 1e-10).empty());
  EXPECT_TRUE(sign_changes(TrigPolynomial::interpolate([](double t) { return 2.0 + std::sin(t); }), 1e-10).empty());
}

// Random polynomials of degree 2 (what the search fits): the sign changes found agree with a
// dense sampling wherever the sampling resolves them, and p has one sign between them.
TEST(TrigPolynomial, AgreesWithADenseSamplingOnRandomPolynomials) {
  std::mt19937 random(625);
  std::uniform_real_distribution<double> coefficient(-1.0, 1.0);
  for (int n = 0; n < 200; ++n) {
    const double c0 = coefficient(random), a1 = coefficient(random), b1 = coefficient(random), a2 = coefficient(random),
                 b2 = coefficient(random);
    auto f = [&](double t) {
      return c0 + a1 * std::cos(t) + b1 * std::sin(t) + a2 * std::cos(2 * t) + b2 * std::sin(2 * t);
    };
    const std::vector<double> zeros = sign_changes(TrigPolynomial::interpolate(f), 1e-10);
    EXPECT_EQ(zeros.size() % 2, 0u) << n;  // a periodic function changes sign an even number of times
    int dense = 0;
    const int samples = 100000;
    for (int j = 0; j < samples; ++j) {
      const double t0 = -M_PI + 2.0 * M_PI * j / samples, t1 = -M_PI + 2.0 * M_PI * (j + 1) / samples;
      if ((f(t0) < 0.0) != (f(t1) < 0.0)) ++dense;
    }
    EXPECT_EQ(static_cast<int>(zeros.size()), dense) << n;
    for (std::size_t i = 0; i + 1 < zeros.size(); ++i) {
      const double mid = 0.5 * (zeros[i] + zeros[i + 1]);
      for (double t = zeros[i] + 1e-9; t < zeros[i + 1] - 1e-9; t += (zeros[i + 1] - zeros[i]) / 64.0)
        EXPECT_EQ(f(t) < 0.0, f(mid) < 0.0) << n;
    }
  }
}

}  // namespace
}  // namespace dispkin
