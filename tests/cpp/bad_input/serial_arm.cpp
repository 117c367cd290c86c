// The rows of the C++ bad-input table (tests/cpp/test_bad_input_table.cpp) of one area: SerialArm
// (tests/data/urdf/arm_*.urdf), hostile URDFs too.
#if defined(DISPKIN_HAS_SERIAL)
#include "rows.hpp"

namespace bad_input {

void serial_arm_rows(std::vector<Row>& table) {
  const RowAdder row{table};
  // --- SerialArm (tests/data/urdf/arm_*.urdf) ---
  const auto arm = [] { return SerialArm::from_urdf_file(urdf + "arm_planar_two_link.urdf", "base", "link2"); };
  const Eigen::Vector2d q0 = Eigen::Vector2d::Zero();
  row(
      "SerialArm::from_urdf_file", "missing file", [] { SerialArm::from_urdf_file("/nonexistent/arm.urdf", "a", "b"); },
      IA, "path = \"/nonexistent/arm.urdf\": cannot be opened");
  row(
      "SerialArm::from_urdf_file", "not XML",
      [] { SerialArm::from_urdf_file(urdf + "arm_bad_not_xml.urdf", "base", "l1"); }, IA,
      "URDF: not a valid robot description");
  row(
      "SerialArm::from_urdf_file", "unknown base link",
      [] { SerialArm::from_urdf_file(urdf + "arm_planar_two_link.urdf", "nowhere", "link2"); }, IA,
      "base_link = \"nowhere\": is not a link of robot \"planar_two_link\"");
  row(
      "SerialArm::from_urdf_file", "unknown tip link",
      [] { SerialArm::from_urdf_file(urdf + "arm_planar_two_link.urdf", "base", "nowhere"); }, IA,
      "tip_link = \"nowhere\": is not a link");
  row(
      "SerialArm::from_urdf_file", "base not an ancestor",
      [] { SerialArm::from_urdf_file(urdf + "arm_planar_two_link.urdf", "link2", "link1"); }, IA,
      "base_link = \"link2\": is not an ancestor of tip_link \"link1\"");
  row(
      "SerialArm::from_urdf_file", "prismatic joint on the path",
      [] { SerialArm::from_urdf_file(urdf + "arm_bad_prismatic.urdf", "base", "l2"); }, IA,
      "joint \"slide\" between \"l1\" and \"l2\": only revolute, continuous and fixed joints");
  row(
      "SerialArm::from_urdf_file", "lower above upper",
      [] { SerialArm::from_urdf_file(urdf + "arm_bad_limits.urdf", "base", "l1"); }, IA,
      "joint \"j1\" limit (lower, upper) = (1, -1): needs lower < upper");
  row(
      "SerialArm::from_urdf_file", "zero axis",
      [] { SerialArm::from_urdf_file(urdf + "arm_bad_zero_axis.urdf", "base", "l1"); }, IA,
      "joint \"j1\" axis = (0, 0, 0): must not be zero");
  row(
      "SerialArm::from_urdf_file", "negative mass",
      [] { SerialArm::from_urdf_file(urdf + "arm_bad_negative_mass.urdf", "base", "l1"); }, IA,
      "link \"l1\" inertial mass = -1");
  row(
      "SerialArm::from_urdf_string", "empty text", [] { SerialArm::from_urdf_string("", "base", "link2"); }, IA,
      "URDF: not a valid robot description");
  row(
      "SerialArm::from_urdf_string", "'%' in an attribute (urdfdom printf format)",
      [] { SerialArm::from_urdf_string("<robot name=\"r\"><link name=\"a%n\"/></robot>", "a", "b"); }, IA,
      "URDF line 1, column 23, <link> attribute \"name\" = \"a%n\": contains '%'");
  // The same '%' as TinyXML decodes character references: zero-padded, wrapping at 2³² (its
  // multiplier is 32 bits), and the low byte of the code point in a document declared Latin-1.
  for (const char* spelling : {"&#37;", "&#x25;", "&#000000000000000000000000037;", "&#x0000000000000000000025;",
                               "&#x100000025;", "&#x1000000000000025;"}) {
    row(
        "SerialArm::from_urdf_string", std::string("'%' as the character reference ") + spelling,
        [spelling] {
          SerialArm::from_urdf_string(std::string("<robot name=\"r\"><link name=\"a") + spelling + "n\"/></robot>", "a",
                                      "b");
        },
        IA, "<link> attribute \"name\" = \"a%n\": contains '%'");
  }
  row(
      "SerialArm::from_urdf_string", "'%' as the low byte of &#293; in a Latin-1 document",
      [] {
        SerialArm::from_urdf_string(
            "<?xml version=\"1.0\" encoding=\"ISO-8859-1\"?><robot name=\"r\"><link name=\"a&#293;n\"/></robot>", "a",
            "b");
      },
      IA, "<link> attribute \"name\" = \"a%n\": contains '%'");
  row(
      "SerialArm::from_urdf_string", "'%' in element text (CDATA)",
      [] {
        SerialArm::from_urdf_string("<robot name=\"r\"><link name=\"a\"><![CDATA[%n%n]]></link></robot>", "a", "b");
      },
      IA, "text = \"%n%n\": contains '%'");
  row(
      "SerialArm::from_urdf_string", "empty base link", [] { SerialArm::from_urdf_string("<robot/>", "", "link2"); },
      IA, "base_link = \"\": must name a link");
  // Hostile URDFs: depth, attribute count, numbers, inertias, the joint graph.
  const auto planar_text = [] {
    std::ifstream in(urdf + "arm_planar_two_link.urdf");
    return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  };
  row(
      "SerialArm::from_urdf_string", "elements nested 4·10⁴ deep",
      [planar_text] {
        std::string deep;
        for (int i = 0; i < 40000; ++i) deep += "<a>";
        for (int i = 0; i < 40000; ++i) deep += "</a>";
        SerialArm::from_urdf_string(
            replace_once(planar_text(), "<link name=\"base\"/>", "<link name=\"base\"/>" + deep), "base", "link2");
      },
      IA, "nests deeper than 100 elements");
  row(
      "SerialArm::from_urdf_string", "4·10⁴ attributes on <robot>",
      [planar_text] {
        std::string attributes;
        for (int i = 0; i < 40000; ++i) attributes += " a" + std::to_string(i) + "=\"1\"";
        SerialArm::from_urdf_string(replace_once(planar_text(), "<robot name=\"planar_two_link\"",
                                                 "<robot name=\"planar_two_link\"" + attributes),
                                    "base", "link2");
      },
      IA, "has more than 100 attributes");
  row(
      "SerialArm::from_urdf_string", "NaN mass",
      [planar_text] {
        SerialArm::from_urdf_string(replace_once(planar_text(), "<mass value=\"2.0\"/>", "<mass value=\"nan\"/>"),
                                    "base", "link2");
      },
      IA, "link \"link1\" inertial mass = nan: must be finite");
  row(
      "SerialArm::from_urdf_string", "infinite ixx",
      [planar_text] {
        SerialArm::from_urdf_string(replace_once(planar_text(), "ixx=\"0.11\"", "ixx=\"inf\""), "base", "link2");
      },
      IA, "link \"link1\" inertial inertia ixx = inf: must be finite");
  row(
      "SerialArm::torques", "a link breaking the triangle inequality",
      [planar_text] {
        SerialArm::from_urdf_string(replace_once(planar_text(), "ixx=\"0.11\"", "ixx=\"0.5\""), "base", "link2")
            .static_torques(Eigen::Vector2d::Zero());
      },
      IA, "is not the inertia of a body: its principal moments break the triangle inequality");
  row(
      "SerialArm::from_urdf_string", "joint origin 1e300 m",
      [planar_text] {
        SerialArm::from_urdf_string(replace_once(planar_text(), "<origin xyz=\"0 0 0.3\"", "<origin xyz=\"0 0 1e300\""),
                                    "base", "link2");
      },
      IA, "joint \"mount_joint\" origin xyz = (0, 0, 1e+300): must be within ±1e12");
  row(
      "SerialArm::from_urdf_string", "a link with two parent joints",
      [planar_text] {
        SerialArm::from_urdf_string(
            replace_once(
                planar_text(), "</robot>",
                "<joint name=\"again\" type=\"fixed\"><parent link=\"base\"/><child link=\"link2\"/></joint></robot>"),
            "base", "link2");
      },
      IA, "is the child of two joints");
  row(
      "SerialArm::inverse_solutions", "2π copies of ±100 rad limits",
      [] {
        const SerialArm ur = SerialArm::from_urdf_file(urdf + "arm_ur5e_dh.urdf", "base_link", "tool0");
        JointLimits l = ur.joint_limits();
        l.lower.setConstant(-100.0);
        l.upper.setConstant(100.0);
        const SerialArm wide = ur.with_joint_limits(l);
        serial::InverseOptions o;
        o.offer_equivalents = true;
        wide.inverse_solutions(wide.forward((Eigen::VectorXd(6) << 0.3, -1.2, 1.5, -1.9, -1.57, 0.2).finished()), o);
      },
      IA, "offer_equivalents = \"true\": asks for the 2π copies of the 8 solutions inside the joint limits");
  row(
      "SerialArm::from_urdf_string", "tip equal to base", [] { SerialArm::from_urdf_string("<robot/>", "a", "a"); }, IA,
      "tip_link = \"a\": must differ from base_link");
  row(
      "SerialArm::forward", "wrong size q (3)", [arm] { arm().forward(Eigen::Vector3d::Zero()); }, IA,
      "q = (0, 0, 0): expected 2 joint values, got 3");
  row(
      "SerialArm::forward", "NaN q", [arm] { arm().forward(Eigen::Vector2d(0, nan_)); }, IA,
      "q = (0, nan): must be finite");
  row(
      "SerialArm::jacobian", "+inf q", [arm] { arm().jacobian(Eigen::Vector2d(inf_, 0)); }, IA,
      "q = (inf, 0): must be finite");
  row(
      "SerialArm::torques", "wrong size qd (1)", [arm, q0] { arm().torques(q0, Eigen::VectorXd::Zero(1), q0); }, IA,
      "qd = (0): expected 2 joint values, got 1");
  row(
      "SerialArm::torques", "NaN qdd", [arm, q0] { arm().torques(q0, q0, Eigen::Vector2d(nan_, 0)); }, IA,
      "qdd = (nan, 0): must be finite");
  row(
      "SerialArm::static_torques", "empty q", [arm] { arm().static_torques(Eigen::VectorXd()); }, IA,
      "q = (): expected 2 joint values, got 0");
  row(
      "SerialArm::set_gravity", "NaN gravity",
      [arm] {
        SerialArm a = arm();
        a.set_gravity(Vector3d(0, 0, nan_));
      },
      IA, "gravity = (0, 0, nan): must be finite");
  row(
      "SerialArm::inverse_solutions", "zero max_attempts",
      [arm] {
        serial::InverseOptions o;
        o.max_attempts = 0;
        arm().inverse_solutions(Posed(), o);
      },
      IA, "max_attempts = 0: must be greater than zero");
  row(
      "SerialArm::inverse_solutions", "negative time_budget",
      [arm] {
        serial::InverseOptions o;
        o.time_budget = -1;
        arm().inverse_solutions(Posed(), o);
      },
      IA, "time_budget = -1: must be finite and greater than zero");
  row(
      "SerialArm::configuration", "not a 6R arm", [arm, q0] { arm().configuration(q0); }, IA,
      "dof = 2: configuration flags are defined for 6R arms");
  row(
      "serial::nearest", "no solutions", [] { serial::nearest({}, Eigen::VectorXd::Zero(6)); }, IA,
      "solutions = 0: must not be empty");
  row(
      "serial::nearest", "wrong size q_ref",
      [] { serial::nearest({Eigen::VectorXd::Zero(6)}, Eigen::VectorXd::Zero(2)); }, IA,
      "q_ref = (0, 0): expected 6 joint values like the solutions, got 2");
  row(
      "serial::follow", "unreachable pose",
      [arm, q0] { serial::follow(arm(), {Posed(Quaterniond::Identity(), Vector3d(5, 0, 0))}, q0); }, RT,
      "poses[0] translation = (5, 0, 0): has no inverse-kinematics solution");
}

}  // namespace bad_input
#endif
