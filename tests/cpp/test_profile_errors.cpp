// Profiles refuse bad input with a message naming the argument and its value (dispkin/profile.hpp).
#include <cmath>
#include <limits>
#include <string>

#include <gtest/gtest.h>

#include "dispkin/profile.hpp"
#include "random_cases.hpp"

namespace dispkin {
namespace {

using testing::message_of;

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// --- bad input: one test per kind, the message names the argument --------------------------------

bool starts_with(const std::string& text, const std::string& prefix) { return text.rfind(prefix, 0) == 0; }

TEST(ProfileErrors, DistanceNotFinite) {
  EXPECT_TRUE(starts_with(message_of([] { Profile::trapezoid(kNaN, 1, 1); }), "distance = nan: must be finite"));
  EXPECT_TRUE(starts_with(message_of([] { Profile::scurve(kInf, 1, 1, 1); }), "distance = inf: must be finite"));
}
TEST(ProfileErrors, DistanceNegative) {
  EXPECT_TRUE(starts_with(message_of([] { Profile::scurve(-1e-9, 1, 1, 1); }),
                          "distance = -1e-09: must be finite and not negative"));
}
TEST(ProfileErrors, VelocityLimitNotPositive) {
  EXPECT_TRUE(
      starts_with(message_of([] { Profile::trapezoid(1, 0, 1); }), "v_max = 0: must be finite and greater than zero"));
  EXPECT_TRUE(starts_with(message_of([] { Profile::scurve(1, kNaN, 1, 1); }), "v_max = nan: "));
}
TEST(ProfileErrors, AccelerationLimitNotPositive) {
  EXPECT_TRUE(starts_with(message_of([] { Profile::trapezoid(1, 1, -2); }),
                          "a_max = -2: must be finite and greater than zero"));
  EXPECT_TRUE(starts_with(message_of([] { Profile::scurve(1, 1, kInf, 1); }), "a_max = inf: "));
}
TEST(ProfileErrors, JerkLimitNotPositive) {
  EXPECT_TRUE(
      starts_with(message_of([] { Profile::scurve(1, 1, 1, 0); }), "j_max = 0: must be finite and greater than zero"));
  EXPECT_TRUE(starts_with(message_of([] { Profile::scurve(1, 1, 1, kNaN); }), "j_max = nan: "));
}
TEST(ProfileErrors, StartVelocityOutOfRange) {
  EXPECT_TRUE(starts_with(message_of([] { Profile::trapezoid(1, 1, 1, 1.5); }),
                          "v_start = 1.5: must be finite and within [0, v_max = 1]"));
  EXPECT_TRUE(starts_with(message_of([] { Profile::scurve(1, 1, 1, 1, -0.1); }), "v_start = -0.1: "));
}
TEST(ProfileErrors, EndVelocityOutOfRange) {
  EXPECT_TRUE(starts_with(message_of([] { Profile::scurve(1, 1, 1, 1, 0, kNaN); }),
                          "v_end = nan: must be finite and within [0, v_max = 1]"));
  EXPECT_TRUE(starts_with(message_of([] { Profile::trapezoid(1, 1, 1, 0, 2); }), "v_end = 2: "));
}
TEST(ProfileErrors, TrapezoidTooShort) {
  // From 1 to 0 at a = 1 needs 0.5.
  const std::string m = message_of([] { Profile::trapezoid(0.4, 1, 1, 1, 0); });
  EXPECT_TRUE(starts_with(m,
                          "distance = 0.4: too short to change the velocity from v_start = 1 to v_end = 0 under a_max "
                          "= 1: it needs at least 0.5"))
      << m;
}
// Subnormal boundary velocities (fuzzed in strict mode): S = 0 between boundary velocities of
// 1.4e-308 and 2.8e-309 m/s at a_max = 5.5e-299 — the distance the change needs, 6e-318 m,
// underflowed to 0, and a law over S = 0 was built that moved 1.1e-318 m. A change of velocity
// needs a positive distance.
TEST(ProfileErrors, ZeroDistanceBetweenDifferentTinyVelocities) {
  const double a = 5.4502595765602775e-299, v0 = 1.3906733001411379e-308, v1 = 2.7894907876201549e-309;
  for (const bool scurve : {false, true}) {
    const std::string message = message_of([&] {
      if (scurve)
        Profile::scurve(0.0, 0.5, a, 1.0, v0, v1);
      else
        Profile::trapezoid(0.0, 0.5, a, v0, v1);
    });
    EXPECT_EQ(message.rfind("distance = 0: too short to change the velocity from v_start = 1.39067330014e-308", 0), 0u)
        << message;
  }
}

TEST(ProfileErrors, ScurveTooShort) {
  // From 0 to 1 at a = j = 1 needs (0 + 1)/2 · (1/1 + 1/1) = 1.
  const std::string m = message_of([] { Profile::scurve(0.9, 1, 1, 1, 0, 1); });
  EXPECT_TRUE(starts_with(m,
                          "distance = 0.9: too short to change the velocity from v_start = 0 to v_end = 1 under a_max "
                          "= 1, j_max = 1: it needs at least 1"))
      << m;
}

}  // namespace
}  // namespace dispkin
