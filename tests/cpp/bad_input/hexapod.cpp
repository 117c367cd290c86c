// The rows of the C++ bad-input table (tests/cpp/test_bad_input_table.cpp) of one area: Hexapod: descriptions (hostile
// ones too), kinematics, leg checks.
#include "rows.hpp"

namespace bad_input {

void hexapod_rows(std::vector<Row>& table) {
  const RowAdder row{table};
  // --- Hexapod ---
  row(
      "Hexapod(...)", "NaN base joint",
      [] {
        Hexapod h = hexapod();
        Hexapod::Joints b = h.base_joints();
        b(0, 0) = nan_;
        Hexapod(b, h.platform_joints(), h.leg_min(), h.leg_max(), h.leg_speed());
      },
      IA, "base_joints = (nan, -0.02604722665, 0");
  row(
      "Hexapod(...)", "+inf platform joint",
      [] {
        Hexapod h = hexapod();
        Hexapod::Joints p = h.platform_joints();
        p(2, 5) = inf_;
        Hexapod(h.base_joints(), p, h.leg_min(), h.leg_max(), h.leg_speed());
      },
      IA, "platform_joints = (0.0642787609687, -0.0766044443119, 0");
  row(
      "Hexapod(...)", "base joint beyond the numeric range (1e13 m)",
      [] {
        Hexapod h = hexapod();
        Hexapod::Joints b = h.base_joints();
        b(1, 2) = 1e13;
        Hexapod(b, h.platform_joints(), h.leg_min(), h.leg_max(), h.leg_speed());
      },
      IA, "must have coordinates within ±1e12 m");
  row(
      "Hexapod(...)", "collinear base joints",
      [] {
        Hexapod h = hexapod();
        Hexapod::Joints b = Hexapod::Joints::Zero();
        b.row(0).setLinSpaced(0.0, 1.0);
        Hexapod(b, h.platform_joints(), h.leg_min(), h.leg_max(), h.leg_speed());
      },
      IA, "base_joints = (0, 0, 0, 0.2, 0, 0, 0.4, 0, 0, 0.6, 0, 0, 0.8, 0, 0, 1, 0, 0): must not be collinear");
  row(
      "Hexapod(...)", "leg_max below leg_min",
      [] {
        Hexapod h = hexapod();
        Hexapod::Legs mx = h.leg_max();
        mx(3) = 0.1;
        Hexapod(h.base_joints(), h.platform_joints(), h.leg_min(), mx, h.leg_speed());
      },
      IA, "leg_max[3] = 0.1");
  row(
      "Hexapod(...)", "negative leg_min",
      [] {
        Hexapod h = hexapod();
        Hexapod::Legs mn = h.leg_min();
        mn(0) = -0.1;
        Hexapod(h.base_joints(), h.platform_joints(), mn, h.leg_max(), h.leg_speed());
      },
      IA, "leg_min[0] = -0.1");
  row(
      "Hexapod(...)", "zero leg_speed",
      [] {
        Hexapod h = hexapod();
        Hexapod::Legs s = h.leg_speed();
        s(5) = 0.0;
        Hexapod(h.base_joints(), h.platform_joints(), h.leg_min(), h.leg_max(), s);
      },
      IA, "leg_speed[5] = 0");
  row(
      "Hexapod(...)", "NaN leg_max",
      [] {
        Hexapod h = hexapod();
        Hexapod::Legs mx = h.leg_max();
        mx(1) = nan_;
        Hexapod(h.base_joints(), h.platform_joints(), h.leg_min(), mx, h.leg_speed());
      },
      IA, "leg_max[1] = nan");
  row(
      "Hexapod(...)", "unreachable home",
      [] {
        Hexapod h = hexapod();
        Hexapod(h.base_joints(), h.platform_joints(), h.leg_min(), h.leg_max(), h.leg_speed(),
                Posed(Quaterniond::Identity(), Vector3d(0, 0, 5)));
      },
      IA, "home", "accepted: home at z = 5 m (legs ~5 m, range [0.15, 0.32]) is not checked against the leg ranges");
  row(
      "Hexapod::symmetric", "zero base_radius", [] { Hexapod::symmetric(0.0, 0.3, 0.1, 0.3, 0.2, 0.1, 0.3, 0.01); }, IA,
      "base_radius = 0");
  row(
      "Hexapod::symmetric", "NaN height", [] { Hexapod::symmetric(0.15, 0.3, 0.1, 0.3, nan_, 0.1, 0.3, 0.01); }, IA,
      "height = nan");
  row(
      "Hexapod::symmetric", "negative leg_speed", [] { Hexapod::symmetric(0.15, 0.3, 0.1, 0.3, 0.2, 0.1, 0.3, -0.01); },
      IA, "leg_speed[0] = -0.01");
  row(
      "Hexapod::symmetric", "+inf platform_radius",
      [] { Hexapod::symmetric(0.15, 0.3, inf_, 0.3, 0.2, 0.1, 0.3, 0.01); }, IA, "platform_radius = inf");
  row(
      "Hexapod::symmetric", "negative base_gap", [] { Hexapod::symmetric(0.15, -0.3, 0.1, 0.3, 0.2, 0.1, 0.3, 0.01); },
      IA, "base_gap = -0.3");
  row(
      "Hexapod::symmetric", "both gaps zero", [] { Hexapod::symmetric(0.15, 0.0, 0.1, 0.0, 0.2, 0.1, 0.3, 0.01); }, IA,
      "base_gap = 0");
  row(
      "Hexapod::from_json", "truncated JSON", [] { Hexapod::from_json("{"); }, IA,
      "description = \"<text>\": is not JSON");
  row(
      "Hexapod::from_json", "empty text", [] { Hexapod::from_json(""); }, IA, "description = \"<text>\": is not JSON");
  row(
      "Hexapod::from_json", "not an object", [] { Hexapod::from_json("[1, 2]"); }, IA,
      "description = \"[1,2]\": must be a JSON object");
  row(
      "Hexapod::from_json", "negative speed",
      [] { Hexapod::from_json(replace_once(hexapod().to_json(), "\"speed\": 0.01", "\"speed\": -1.0")); }, IA,
      "leg_speed[0] = -1: must be in [1e-12, 1e12]");
  row(
      "Hexapod::from_json", "string speed",
      [] { Hexapod::from_json(replace_once(hexapod().to_json(), "\"speed\": 0.01", "\"speed\": \"fast\"")); }, IA,
      "legs[0].speed = \"fast\": must be a number");
  row(
      "Hexapod::from_json", "NaN literal",
      [] { Hexapod::from_json(replace_once(hexapod().to_json(), "\"speed\": 0.01", "\"speed\": NaN")); }, IA,
      "description = \"<text>\": is not JSON");
  row(
      "Hexapod::from_json", "wrong format tag",
      [] { Hexapod::from_json(replace_once(hexapod().to_json(), "\"dispkin.hexapod\"", "\"urdf\"")); }, IA,
      "format = \"urdf\": must be");
  row(
      "Hexapod::load", "missing file", [] { Hexapod::load("/nonexistent/hexapod.json"); }, IA,
      "path = \"/nonexistent/hexapod.json\": cannot be opened");
  row(
      "Hexapod::load", "malformed file",
      [] {
        const std::string path =
            temp_file("dispkin_bad_input_malformed.json", "{\"format\": \"dispkin.hexapod\", \"legs\": [");
        try {
          Hexapod::load(path);
        } catch (...) {
          std::remove(path.c_str());
          throw;
        }
        std::remove(path.c_str());
      },
      IA, "dispkin_bad_input_malformed.json: description = \"<text>\": is not JSON");
  // Hostile hexapod descriptions: depth, size, unknown keys, numbers beyond the range, bytes.
  row(
      "Hexapod::from_json", "arrays nested 10⁵ deep",
      [] { Hexapod::from_json(std::string(100000, '[') + std::string(100000, ']')); }, IA,
      "description nesting depth = 101: arrays and objects nest at most 100 deep");
  row(
      "Hexapod::from_json", "objects nested 10⁵ deep",
      [] {
        std::string text;
        for (int i = 0; i < 100000; ++i) text += "{\"a\":";
        Hexapod::from_json(text + "1" + std::string(100000, '}'));
      },
      IA, "description nesting depth = 101");
  row(
      "Hexapod::from_json", "text over 1 MiB", [] { Hexapod::from_json(std::string((1 << 20) + 1, ' ')); }, IA,
      "description size = 1048577: more than 1048576 bytes, the limit of a hexapod description");
  row(
      "Hexapod::from_json", "10⁴ legs (message not echoing them)",
      [] {
        std::string legs = "[";
        for (int i = 0; i < 10000; ++i) legs += std::string(i ? "," : "") + "{\"min\": 0.1}";
        Hexapod::from_json("{\"format\": \"dispkin.hexapod\", \"version\": 1, \"legs\": " + legs + "]}");
      },
      IA, ", … 10000 items]\": must be an array of 6 leg objects");
  row(
      "Hexapod::from_json", "misspelt per-leg key",
      [] { Hexapod::from_json(replace_once(hexapod().to_json(), "\"speed\"", "\"sped\"")); }, IA,
      "legs[0].sped = 0.01: unknown key (allowed here: base, platform, min, max, speed)");
  row(
      "Hexapod::from_json", "unknown top-level key",
      [] { Hexapod::from_json(replace_once(hexapod().to_json(), "\"units\"", "\"leg_speed\": -1, \"units\"")); }, IA,
      "leg_speed = -1: unknown key (allowed here: format, version, units, legs, home)");
  row(
      "Hexapod::from_json", "leg speed 5e-324",
      [] { Hexapod::from_json(replace_once(hexapod().to_json(), "\"speed\": 0.01", "\"speed\": 5e-324")); }, IA,
      "leg_speed[0] = 4.94065645841e-324: must be in [1e-12, 1e12]");
  row(
      "Hexapod::from_json", "leg speed 1e300",
      [] { Hexapod::from_json(replace_once(hexapod().to_json(), "\"speed\": 0.01", "\"speed\": 1e300")); }, IA,
      "leg_speed[0] = 1e+300: must be in [1e-12, 1e12]");
  row(
      "Hexapod::from_json", "leg max 1e300",
      [] { Hexapod::from_json(replace_once(hexapod().to_json(), "\"max\": 0.32", "\"max\": 1e300")); }, IA,
      "leg_max[0] = 1e+300: must be at most 1e12 m");
  row(
      "Hexapod::from_json", "invalid UTF-8 in a string",
      [] { Hexapod::from_json(replace_once(hexapod().to_json(), "\"m, m/s\"", "\"m\xff\xfe\"")); }, IA,
      "invalid string: ill-formed UTF-8 byte; last read: '\"m\\xff");
  row(
      "Hexapod::forward", "NaN legs",
      [] {
        Hexapod::Legs l = Hexapod::Legs::Constant(0.2);
        l(0) = nan_;
        hexapod().forward(l);
      },
      IA, "legs[0] = nan");
  row(
      "Hexapod::forward", "negative legs", [] { hexapod().forward(Hexapod::Legs(Hexapod::Legs::Constant(-0.2))); }, IA,
      "legs[0] = -0.2");
  row(
      "Hexapod::forward", "zero tolerance",
      [] {
        ForwardOptions o;
        o.tolerance = 0;
        Hexapod h = hexapod();
        h.forward(Hexapod::Legs(Hexapod::Legs::Constant(0.2)), h.home(), o);
      },
      IA, "tolerance = 0");
  row(
      "Hexapod::forward", "wrong size q (5)",
      [] {
        const Hexapod h = hexapod();
        h.forward(Eigen::VectorXd(Eigen::VectorXd::Constant(5, 0.2)));
      },
      IA, "q size = 5: a hexapod has 6 legs");
  row(
      "Hexapod::forward", "out-of-range legs", [] { hexapod().forward(Hexapod::Legs(Hexapod::Legs::Constant(5.0))); },
      IA, "legs");
  row(
      "Hexapod::require_reachable", "unreachable pose",
      [] { hexapod().require_reachable(Posed(Quaterniond::Identity(), Vector3d(0, 0, 5))); }, IA,
      "leg 0 length = 5.00095177608: outside the leg's range [0.15, 0.32]");
  row(
      "Hexapod::check_trajectory", "zero dt",
      [] {
        Hexapod h = hexapod();
        h.check_trajectory(plan(Path::lin(h.home(), h.home() * B), good_set(), limits(0.1, 1, 10)), 0.0);
      },
      IA, "dt = 0");
  row(
      "Hexapod::check_trajectory", "negative dt",
      [] {
        Hexapod h = hexapod();
        h.check_trajectory(plan(Path::lin(h.home(), h.home() * B), good_set(), limits(0.1, 1, 10)), -0.01);
      },
      IA, "dt = -0.01");
  row(
      "Hexapod::check_trajectory", "NaN dt",
      [] {
        Hexapod h = hexapod();
        h.check_trajectory(plan(Path::lin(h.home(), h.home() * B), good_set(), limits(0.1, 1, 10)), nan_);
      },
      IA, "dt = nan");
  row(
      "Hexapod::check_trajectory", "+inf dt",
      [] {
        Hexapod h = hexapod();
        h.check_trajectory(plan(Path::lin(h.home(), h.home() * B), good_set(), limits(0.1, 1, 10)), inf_);
      },
      IA, "dt = inf");
  row(
      "Hexapod::add_leg_speed_group", "negative group",
      [] {
        MetricSetd s = good_set();
        hexapod().add_leg_speed_group(s, -1);
      },
      IA, "group = -1");
  row(
      "Hexapod::leg_rate_bounds", "zero tolerance",
      [] {
        Hexapod h = hexapod();
        h.leg_rate_bounds(Path::lin(h.home(), h.home() * B).sections().front(), 0.0);
      },
      IA, "tolerance = 0: must be in (0, 1]");
  row(
      "Hexapod::leg_rate_bounds", "NaN tolerance",
      [] {
        Hexapod h = hexapod();
        h.leg_rate_bounds(Path::lin(h.home(), h.home() * B).sections().front(), nan_);
      },
      IA, "tolerance = nan");
  row(
      "Hexapod::leg_rate_bounds", "tolerance above 1",
      [] {
        Hexapod h = hexapod();
        h.leg_rate_bounds(Path::lin(h.home(), h.home() * B).sections().front(), 1.5);
      },
      IA, "tolerance = 1.5");
  row(
      "Hexapod::leg_section_lengths", "zero system_velocity",
      [] {
        Hexapod h = hexapod();
        h.leg_section_lengths(Path::lin(h.home(), h.home() * B), 0.0);
      },
      IA, "system_velocity = 0");
  row(
      "Hexapod::leg_section_lengths", "NaN system_velocity",
      [] {
        Hexapod h = hexapod();
        h.leg_section_lengths(Path::lin(h.home(), h.home() * B), nan_);
      },
      IA, "system_velocity = nan");
  row(
      "Hexapod::leg_section_lengths", "+inf system_velocity",
      [] {
        Hexapod h = hexapod();
        h.leg_section_lengths(Path::lin(h.home(), h.home() * B), inf_);
      },
      IA, "system_velocity = inf");
  row(
      "Hexapod::joint_metric", "negative velocity",
      [] {
        Hexapod h = hexapod();
        h.joint_metric(Path::lin(h.home(), h.home() * B), limits(-1, 1, 10));
      },
      IA, "system_velocity = -1");
}

}  // namespace bad_input
