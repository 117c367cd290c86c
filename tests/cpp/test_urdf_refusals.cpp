// URDFs and arguments the serial-arm loader refuses, each with its reason, and damaged texts that
// are refused or loaded but never crash (cases found by fuzzing and the sanitizers among them).
#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <string>


#include <dispkin/serial/serial_arm.hpp>

#include "random_cases.hpp"
#include "serial_test_arms.hpp"


namespace dispkin::serial {
namespace {

using dispkin::testing::contains;
using dispkin::testing::message_of;
using dispkin::testing::planar;
using dispkin::testing::Random;
using dispkin::testing::urdf_dir;

constexpr double pi = 3.14159265358979323846;

TEST(SerialArmErrors, BadUrdfFilesAreRefusedWithTheirReason) {
  struct Case {
    const char* file;
    const char* base;
    const char* tip;
    const char* expected;  // part of the message
  };
  const Case cases[] = {
      {"arm_bad_not_xml.urdf", "base", "l1", "URDF"},
      {"arm_bad_no_robot.urdf", "base", "l1", "URDF"},
      {"arm_bad_missing_link.urdf", "base", "l2", "l2"},
      {"arm_bad_prismatic.urdf", "base", "l2", "joint \"slide\""},
      {"arm_bad_limits.urdf", "base", "l1", "joint \"j1\" limit (lower, upper)"},
      {"arm_bad_no_limit.urdf", "base", "l1", "j1"},
      {"arm_bad_zero_axis.urdf", "base", "l1", "joint \"j1\" axis"},
      {"arm_bad_nan_origin.urdf", "base", "l1", "j1"},
      {"arm_bad_negative_mass.urdf", "base", "l1", "link \"l1\" inertial mass"},
      {"arm_bad_two_roots.urdf", "base", "l1", "URDF"},
      {"arm_bad_only_fixed.urdf", "base", "l1", "no revolute or continuous joint"},
      {"arm_bad_negative_velocity.urdf", "base", "l1", "joint \"j1\" limit velocity"},
      {"no_such_file.urdf", "base", "l1", "cannot be opened"},
  };
  for (const Case& c : cases) {
    const std::string message = message_of([&] { SerialArm::from_urdf_file(urdf_dir + c.file, c.base, c.tip); });
    EXPECT_NE(message.find(c.expected), std::string::npos) << c.file << ": " << message;
  }
}

TEST(SerialArmErrors, DamagedUrdfTextIsRefusedOrLoadedNeverACrash) {
  // Every prefix of a good URDF (a file cut off anywhere), and the file with one character
  // replaced at many places: either it still describes the arm or loading throws
  // std::invalid_argument — no other exception, no crash.
  std::ifstream in(urdf_dir + "arm_ur5e_dh.urdf");
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  ASSERT_GT(text.size(), 1000u);
  int refused = 0;
  int loaded = 0;
  const auto attempt = [&](const std::string& xml) {
    try {
      const SerialArm arm = SerialArm::from_urdf_string(xml, "base_link", "tool0");
      EXPECT_EQ(arm.dof(), 6);
      ++loaded;
    } catch (const std::invalid_argument&) {
      ++refused;
    }
  };
  for (std::size_t cut = 0; cut < text.size(); cut += 7) attempt(text.substr(0, cut));
  Random random(611);
  const char garbage[] = {'<', '>', '"', '/', 'x', '-', '9', ' ', '\0'};
  for (int k = 0; k < 300; ++k) {
    std::string damaged = text;
    damaged[static_cast<std::size_t>(random.integer(0, static_cast<int>(text.size()) - 1))] =
        garbage[random.integer(0, 8)];
    attempt(damaged);
  }
  EXPECT_GT(refused, 0);
  EXPECT_GT(loaded, 0);
}

// Found by fuzzing (tests/fuzz/fuzz_urdf): urdfdom accepts a joint whose parent is its own
// child, and the walk from the tip towards the base then never ended (memory grew until killed).
TEST(SerialArmErrors, JointCycleIsRefused) {
  const std::string xml = R"(<robot name="loop">
  <link name="base_link"/> <link name="l1"/> <link name="l2"/>
  <joint name="j1" type="continuous"><parent link="base_link"/><child link="l1"/><axis xyz="0 0 1"/></joint>
  <joint name="j2" type="continuous"><parent link="l2"/><child link="l2"/><axis xyz="0 0 1"/></joint>
</robot>)";
  EXPECT_EQ(message_of([&] { SerialArm::from_urdf_string(xml, "base_link", "l2"); }),
            "link = \"l2\": is its own ancestor: the URDF's joints form a cycle \"l2\" -(j2)-> \"l2\"");
}

// A joint cycle that leaves no root link is refused by urdfdom itself, which then
// leaked the ring of links it had built (LeakSanitizer). The joint graph is read first now, so
// urdfdom never sees a cycle: under `make sanitize` this test fails if anything leaks.
TEST(SerialArmErrors, JointCycleIsRefusedBeforeUrdfdomReadsIt) {
  const std::string two = R"(<robot name="r"><link name="base_link"/><link name="tool0"/>
  <joint name="j" type="continuous"><parent link="base_link"/><child link="tool0"/><axis xyz="0 0 1"/></joint>
  <joint name="k" type="continuous"><parent link="tool0"/><child link="base_link"/></joint></robot>)";
  EXPECT_EQ(message_of([&] { SerialArm::from_urdf_string(two, "base_link", "tool0"); }),
            "link = \"base_link\": is its own ancestor: the URDF's joints form a cycle "
            "\"base_link\" -(j)-> \"tool0\" -(k)-> \"base_link\"");
  // A longer cycle hanging off a proper tree (a root exists, so urdfdom would accept it).
  const std::string branch = R"(<robot name="r">
  <link name="base_link"/><link name="a"/><link name="b"/><link name="c"/><link name="tool0"/>
  <joint name="j0" type="fixed"><parent link="base_link"/><child link="tool0"/></joint>
  <joint name="j1" type="fixed"><parent link="base_link"/><child link="a"/></joint>
  <joint name="j2" type="fixed"><parent link="a"/><child link="b"/></joint>
  <joint name="j3" type="fixed"><parent link="b"/><child link="c"/></joint>
  <joint name="j4" type="fixed"><parent link="c"/><child link="a"/></joint></robot>)";
  EXPECT_EQ(message_of([&] { SerialArm::from_urdf_string(branch, "base_link", "tool0"); }),
            "link = \"a\": is its own ancestor: the URDF's joints form a cycle "
            "\"a\" -(j2)-> \"b\" -(j3)-> \"c\" -(j4)-> \"a\"");
}

// TinyXML (urdfdom's XML parser, and the joint-graph check's) read past the end of a text that ends
// inside a UTF-8 sequence (here "link\xe6\xe6\xe6\xe6"); ASan saw the read beyond the buffer. The
// text is now handed over with NULs appended: refused, no overflow (under `make sanitize` an
// over-read fails this test).
TEST(SerialArmErrors, TextEndingInsideAUtf8SequenceIsRefusedWithoutOverread) {
  std::ifstream in(
      std::string(DISPKIN_SOURCE_DIR) + "/tests/fuzz/corpus/fuzz_urdf/finding_12_utf8_lead_byte_at_end.urdf",
      std::ios::binary);
  ASSERT_TRUE(in.good());
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  text = text.substr(text.find('\n') + 1);  // the fuzzer's "@base tip" line
  EXPECT_THROW(SerialArm::from_urdf_string(text, "base_link", "flange"), std::invalid_argument);
}

// A '%' in an attribute: urdfdom used the text of an attribute it could not parse as a printf
// format, so "%n" there crashed inside urdf::parseURDF. A '%' outside comments, spelled out or as a
// character reference, is refused before urdfdom sees the text; inside a comment it is harmless and
// kept.
TEST(SerialArmErrors, PercentSignOutsideCommentsIsRefused) {
  const std::string arm = R"(<robot name="r">
  <link name="base_link"/> <link name="tool0"/>
  <joint name="j1" type="continuous"><parent link="base_link"/><child link="tool0"/>
    <origin xyz="ORIGIN"/><axis xyz="0 0 1"/></joint>
</robot>)";
  auto with = [&](const std::string& origin, const std::string& before = "") {
    std::string xml = arm;
    xml.replace(xml.find("ORIGIN"), 6, origin);
    return before + xml;
  };
  EXPECT_EQ(message_of([&] { SerialArm::from_urdf_string(with("n%n 0 0"), "base_link", "tool0"); }),
            "URDF line 4, column 13, <origin> attribute \"xyz\" = \"n%n 0 0\": contains '%' (character references "
            "decoded); urdfdom would pass it to printf as a format (remove it)");
  EXPECT_NE(message_of([&] { SerialArm::from_urdf_string(with("%s%s%s 0 0"), "base_link", "tool0"); }).find("'%'"),
            std::string::npos);
  // The attribute as TinyXML decodes it, whatever the spelling of the reference: leading zeros
  // without end, a hexadecimal multiplier that wraps at 2³².
  for (const char* reference : {"&#37;n 0 0", "&#x25;n 0 0", "&#037;n 0 0", "&#00000000000000000000000000037;n 0 0",
                                "&#x100000025;n 0 0", "&#xFFFFFFFF00000025;n 0 0"}) {
    EXPECT_NE(message_of([&] {
                SerialArm::from_urdf_string(with(reference), "base_link", "tool0");
              }).find("<origin> attribute \"xyz\" = \"%n 0 0\": contains '%'"),
              std::string::npos)
        << reference;
  }
  // "&#X…;" is no reference to TinyXML (only a lower-case x marks hexadecimal): a parse error.
  EXPECT_NE(message_of([&] {
              SerialArm::from_urdf_string(with("&#X0025;s 0 0"), "base_link", "tool0");
            }).find("not a valid robot description"),
            std::string::npos);
  // In a comment (before the robot, or spanning lines) a '%' is fine; the arm loads.
  const SerialArm ok =
      SerialArm::from_urdf_string(with("0 0 0.5", "<!-- 100% \n scale: 50% -->\n"), "base_link", "tool0");
  EXPECT_EQ(ok.dof(), 1);
  EXPECT_NEAR(ok.forward(Eigen::VectorXd::Zero(1)).translation().z(), 0.5, 1e-15);
}

TEST(SerialArmErrors, BadLinksAndArguments) {
  const std::string file = urdf_dir + "arm_planar_two_link.urdf";
  EXPECT_NE(message_of([&] { SerialArm::from_urdf_file(file, "nowhere", "link2"); }).find("base_link = \"nowhere\""),
            std::string::npos);
  EXPECT_NE(message_of([&] { SerialArm::from_urdf_file(file, "base", "nowhere"); }).find("tip_link = \"nowhere\""),
            std::string::npos);
  EXPECT_NE(message_of([&] { SerialArm::from_urdf_file(file, "link2", "link1"); }).find("not an ancestor"),
            std::string::npos);
  EXPECT_NE(message_of([&] { SerialArm::from_urdf_file(file, "link1", "link1"); }).find("must differ"),
            std::string::npos);
  // A prismatic joint off the path is fine; on the path it is refused.
  EXPECT_NE(message_of([&] { SerialArm::from_urdf_file(file, "base", "finger"); }).find("finger_joint"),
            std::string::npos);
  EXPECT_NE(message_of([&] { SerialArm::from_urdf_string("", "base", "link2"); }).find("URDF"), std::string::npos);

  const SerialArm arm = planar();
  EXPECT_NE(message_of([&] { arm.forward(Eigen::VectorXd::Zero(3)); }).find("expected 2 joint values, got 3"),
            std::string::npos);
  EXPECT_NE(message_of([&] { arm.forward(Eigen::Vector2d(0, std::nan(""))); }).find("q = "), std::string::npos);
  EXPECT_NE(message_of([&] { arm.jacobian(Eigen::VectorXd::Zero(1)); }).find("q = "), std::string::npos);
  EXPECT_NE(message_of([&] {
              arm.torques(Eigen::Vector2d::Zero(), Eigen::VectorXd::Zero(1), Eigen::Vector2d::Zero());
            }).find("qd = "),
            std::string::npos);
  EXPECT_NE(message_of([&] {
              arm.torques(Eigen::Vector2d::Zero(), Eigen::Vector2d::Zero(), Eigen::Vector2d(INFINITY, 0));
            }).find("qdd = "),
            std::string::npos);
  InverseOptions options;
  options.max_attempts = 0;
  EXPECT_NE(message_of([&] { arm.inverse_solutions(Posed(), options); }).find("max_attempts"), std::string::npos);
  options = InverseOptions();
  options.time_budget = -1;
  EXPECT_NE(message_of([&] { arm.inverse_solutions(Posed(), options); }).find("time_budget"), std::string::npos);
}

}  // namespace
}  // namespace dispkin::serial
