// Hexapod descriptions: the JSON file round trip and every kind of bad key, type or file, and bad
// geometry, one kind per test.
#include <cstdio>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include <dispkin/hexapod/hexapod.hpp>
#include <dispkin/path/path.hpp>
#include <dispkin/planning/planner.hpp>

#include "hexapod_test_rig.hpp"
#include "random_cases.hpp"

namespace dispkin {
namespace {

using hexapod::Hexapod;
using testing::message_of;
using testing::Random;
using testing::test_hexapod;
using Legs = Hexapod::Legs;
constexpr double pi = 3.14159265358979323846;

// --- description files -----------------------------------------------------------------------

std::string temp_path(const std::string& name) { return ::testing::TempDir() + "dispkin_" + name; }

void write(const std::string& path, const std::string& text) { std::ofstream(path) << text; }

TEST(HexapodJson, SaveAndLoadRoundTripExactly) {
  Random rnd(507);
  Hexapod::Joints base = Hexapod::Joints::Random(), platform = Hexapod::Joints::Random();
  Legs lo, hi, speed;
  for (int i = 0; i < 6; ++i) {
    lo(i) = rnd.uniform(0.0, 0.3);
    hi(i) = lo(i) + rnd.uniform(0.01, 0.3);
    speed(i) = rnd.uniform(0.001, 0.1);
  }
  const Hexapod h(base, platform, lo, hi, speed, rnd.pose(0.3));
  const std::string path = temp_path("roundtrip.json");
  h.save(path);
  const Hexapod g = Hexapod::load(path);
  EXPECT_EQ(g.base_joints(), h.base_joints());
  EXPECT_EQ(g.platform_joints(), h.platform_joints());
  EXPECT_EQ(g.leg_min(), h.leg_min());
  EXPECT_EQ(g.leg_max(), h.leg_max());
  EXPECT_EQ(g.leg_speed(), h.leg_speed());
  EXPECT_EQ(g.home().translation(), h.home().translation());
  EXPECT_EQ(g.home().quaternion().coeffs(), h.home().quaternion().coeffs());
  std::remove(path.c_str());
}

// The description of test_hexapod() with `edit` applied to its text.
std::string edited(const std::string& from, const std::string& to) {
  std::string text = test_hexapod().to_json();
  const std::size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return text.replace(at, from.size(), to);
}

TEST(HexapodJson, MissingKeyIsNamed) {
  const std::string text = edited("\"min\": 0.15,", "");
  EXPECT_NE(message_of([&] { Hexapod::from_json(text); }).find("legs[0].min = \"<missing>\": required key is missing"),
            std::string::npos)
      << message_of([&] { Hexapod::from_json(text); });
}

TEST(HexapodJson, MisspeltKeyIsNamed) {
  const std::string text = edited("\"speed\"", "\"sped\"");
  EXPECT_EQ(message_of([&] {
              Hexapod::from_json(text);
            }).rfind("legs[0].sped = 0.01: unknown key (allowed here: base, platform, min, max, speed)", 0),
            0u)
      << message_of([&] { Hexapod::from_json(text); });
}

TEST(HexapodJson, WrongTypeIsNamed) {
  const std::string text = edited("\"min\": 0.15", "\"min\": \"short\"");
  EXPECT_NE(message_of([&] { Hexapod::from_json(text); }).find("legs[0].min = \"short\": must be a number"),
            std::string::npos)
      << message_of([&] { Hexapod::from_json(text); });
}

TEST(HexapodJson, WrongVectorLengthIsNamed) {
  std::string text = test_hexapod().to_json();
  const std::size_t at = text.find("\"translation\": [");
  text.insert(at + std::string("\"translation\": [").size(), "1.0, ");
  EXPECT_NE(message_of([&] { Hexapod::from_json(text); }).find("home.translation = "), std::string::npos);
}

TEST(HexapodJson, WrongLegCountIsNamed) {
  const std::string text = R"({"format": "dispkin.hexapod", "version": 1, "legs": []})";
  EXPECT_NE(message_of([&] { Hexapod::from_json(text); }).find("legs = \"[]\": must be an array of 6"),
            std::string::npos);
}

TEST(HexapodJson, WrongFormatIsNamed) {
  EXPECT_EQ(message_of([&] { Hexapod::from_json(edited("dispkin.hexapod", "robot")); }),
            "format = \"robot\": must be \"dispkin.hexapod\"");
}

TEST(HexapodJson, UnknownVersionIsNamed) {
  EXPECT_NE(message_of([&] { Hexapod::from_json(edited("\"version\": 1", "\"version\": 2")); }).find("version = \"2\""),
            std::string::npos);
}

TEST(HexapodJson, DescriptionThatIsNotAnObjectIsRefused) {
  EXPECT_EQ(
      message_of([&] { Hexapod::from_json("[1, 2]"); }).rfind("description = \"[1,2]\": must be a JSON object", 0), 0u);
}

TEST(HexapodJson, TextThatIsNotJsonIsRefused) {
  EXPECT_NE(message_of([&] { Hexapod::from_json("{\"legs\": [1, 2"); }).find("is not JSON"), std::string::npos);
}

// Found by fuzzing (tests/fuzz/fuzz_hexapod_json): nlohmann/json reports a number beyond the
// double range as out_of_range, not parse_error; it escaped as a foreign exception type.
TEST(HexapodJson, NumberBeyondDoubleRangeIsRefused) {
  const std::string m = message_of([&] { Hexapod::from_json(edited("\"speed\": 0.01", "\"speed\": 1e999")); });
  EXPECT_NE(m.find("description = \"<text>\": is not JSON"), std::string::npos) << m;
  EXPECT_NE(m.find("1e999"), std::string::npos) << m;
}

TEST(HexapodJson, BadGeometryInAFileIsNamedWithThePath) {
  const std::string path = temp_path("bad_speed.json");
  write(path, edited("\"speed\": 0.01", "\"speed\": -0.01"));
  const std::string m = message_of([&] { Hexapod::load(path); });
  EXPECT_NE(m.find(path + ": leg_speed[0] = -0.01"), std::string::npos) << m;
  std::remove(path.c_str());
}

TEST(HexapodJson, UnreadableFileIsNamed) {
  EXPECT_NE(
      message_of([&] { Hexapod::load("/nonexistent/hexapod.json"); }).find("path = \"/nonexistent/hexapod.json\""),
      std::string::npos);
}

// --- bad geometry, one kind per test ------------------------------------------------------------

struct Geometry {
  Hexapod::Joints base = test_hexapod().base_joints();
  Hexapod::Joints platform = test_hexapod().platform_joints();
  Legs lo = Legs::Constant(0.15), hi = Legs::Constant(0.32), speed = Legs::Constant(0.01);
  std::string error() const {
    return message_of([&] { Hexapod(base, platform, lo, hi, speed); });
  }
};

TEST(HexapodGeometry, TheTestGeometryIsValid) { EXPECT_EQ(Geometry().error(), "<no exception>"); }

TEST(HexapodGeometry, NonFiniteJointIsRefused) {
  Geometry g;
  g.platform(1, 4) = std::numeric_limits<double>::infinity();
  EXPECT_EQ(g.error().rfind("platform_joints = ", 0), 0u) << g.error();
  EXPECT_NE(g.error().find("must be finite"), std::string::npos);
}

TEST(HexapodGeometry, CollinearBaseJointsAreRefused) {
  Geometry g;
  for (int i = 0; i < 6; ++i) g.base.col(i) = Eigen::Vector3d(0.1 * i, 0.05 * i, 0.0);
  EXPECT_EQ(g.error().rfind("base_joints = ", 0), 0u) << g.error();
  EXPECT_NE(g.error().find("collinear"), std::string::npos);
}

TEST(HexapodGeometry, CoincidentPlatformJointsAreRefused) {
  Geometry g;
  g.platform.colwise() = Eigen::Vector3d(0.01, 0.02, 0.0);
  EXPECT_EQ(g.error().rfind("platform_joints = ", 0), 0u) << g.error();
}

TEST(HexapodGeometry, NegativeLegMinimumIsRefused) {
  Geometry g;
  g.lo(1) = -0.1;
  EXPECT_EQ(g.error().rfind("leg_min[1] = -0.1: ", 0), 0u) << g.error();
}

TEST(HexapodGeometry, LegMaximumNotAboveMinimumIsRefused) {
  Geometry g;
  g.hi(2) = g.lo(2);
  EXPECT_EQ(g.error().rfind("leg_max[2] = 0.15: must be finite and greater than leg_min[2]", 0), 0u) << g.error();
}

TEST(HexapodGeometry, NonPositiveLegSpeedIsRefused) {
  Geometry g;
  g.speed(4) = 0.0;
  EXPECT_EQ(g.error().rfind("leg_speed[4] = 0: ", 0), 0u) << g.error();
}

TEST(HexapodGeometry, SymmetricGeneratorRefusesANonPositiveRadius) {
  EXPECT_EQ(
      message_of([] { Hexapod::symmetric(-0.1, 0.2, 0.1, 0.2, 0.2, 0.1, 0.3, 0.01); }).rfind("base_radius = -0.1", 0),
      0u);
  EXPECT_EQ(
      message_of([] { Hexapod::symmetric(0.1, 0.2, 0.0, 0.2, 0.2, 0.1, 0.3, 0.01); }).rfind("platform_radius = 0", 0),
      0u);
}

TEST(HexapodGeometry, SymmetricGeneratorRefusesAGapOutsideZeroTo120Degrees) {
  EXPECT_EQ(message_of([] { Hexapod::symmetric(0.1, 2.1, 0.1, 0.2, 0.2, 0.1, 0.3, 0.01); }).rfind("base_gap = 2.1", 0),
            0u);
  EXPECT_EQ(
      message_of([] { Hexapod::symmetric(0.1, 0.2, 0.1, -0.2, 0.2, 0.1, 0.3, 0.01); }).rfind("platform_gap = -0.2", 0),
      0u);
}

TEST(HexapodGeometry, SymmetricGeneratorRefusesANonPositiveHeight) {
  EXPECT_EQ(message_of([] { Hexapod::symmetric(0.1, 0.2, 0.1, 0.2, 0.0, 0.1, 0.3, 0.01); }).rfind("height = 0", 0), 0u);
}

TEST(HexapodGeometry, SymmetricGeneratorRefusesTheThreeThreeLayout) {
  EXPECT_EQ(message_of([] {
              Hexapod::symmetric(0.1, 0.0, 0.1, 0.0, 0.2, 0.1, 0.3, 0.01);
            }).rfind("base_gap = 0: and platform_gap = 0 would make a 3-3 hexapod", 0),
            0u);
}

TEST(HexapodGeometry, SymmetricGeneratorChecksTheLegLimits) {
  EXPECT_EQ(
      message_of([] { Hexapod::symmetric(0.1, 0.2, 0.1, 0.2, 0.2, 0.3, 0.3, 0.01); }).rfind("leg_max[0] = 0.3", 0), 0u);
  EXPECT_EQ(
      message_of([] { Hexapod::symmetric(0.1, 0.2, 0.1, 0.2, 0.2, 0.1, 0.3, -0.01); }).rfind("leg_speed[0] = -0.01", 0),
      0u);
}

}  // namespace
}  // namespace dispkin
