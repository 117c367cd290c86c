// What the rows of the C++ bad-input table share (tests/cpp/test_bad_input_table.cpp): a Row,
// `row` to append one, and the objects most rows start from. One source per API area appends
// its rows (tests/cpp/bad_input/*.cpp); the table calls them in the order declared here.
#pragma once

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <limits>
#include <ostream>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include <dispkin/convex_hull.hpp>
#include <dispkin/disp.hpp>
#include <dispkin/frames.hpp>
#include <dispkin/hexapod/hexapod.hpp>
#include <dispkin/metric_set.hpp>
#include <dispkin/planning/overlap.hpp>
#include <dispkin/path/path.hpp>
#include <dispkin/planning/planner.hpp>
#include <dispkin/pose.hpp>
#include <dispkin/profile.hpp>
#include <dispkin/shapes.hpp>
#if defined(DISPKIN_HAS_SERIAL)
#include <dispkin/serial/ptp.hpp>
#include <dispkin/hexapod/hexapod_retiming.hpp>
#include <dispkin/serial/serial_retiming.hpp>
#include <dispkin/serial/serial_arm.hpp>
#endif


namespace bad_input {

using namespace dispkin;
using Eigen::Matrix4d;
using Eigen::Quaterniond;
using Eigen::Vector3d;
using hexapod::ForwardOptions;
using hexapod::Hexapod;
using Vector6d = Eigen::Matrix<double, 6, 1>;

inline const double nan_ = std::numeric_limits<double>::quiet_NaN();
inline const double inf_ = std::numeric_limits<double>::infinity();
inline const double pi = 3.14159265358979323846;

enum class Expect { invalid_argument, runtime_error };

struct Row {
  std::string entry;
  std::string bad;
  std::function<void()> call;
  Expect expect;
  std::string fragment;
  std::string observed;  // non-empty: the input is NOT rejected (strict xfail), what happens instead
};

inline Vector6d v6(double a, double b, double c, double d, double e, double f) {
  Vector6d v;
  v << a, b, c, d, e, f;
  return v;
}

inline MetricSetd good_set() {
  MetricSetd s;
  s.add_relative(std::vector<Vector3d>{Vector3d::UnitX(), Vector3d::UnitY(), Vector3d::UnitZ()});
  return s;
}

inline MetricSetd collinear_set() {
  MetricSetd s;
  s.add_relative(std::vector<Vector3d>{Vector3d(0, 0, 0), Vector3d(1, 0, 0), Vector3d(2, 0, 0)});
  return s;
}

inline Hexapod hexapod() {
  return Hexapod::symmetric(0.15, 20 * pi / 180, 0.10, 20 * pi / 180, 0.20, 0.15, 0.32, 0.01);
}

inline const Posed A;
inline const Posed B = Posed::from_xyzuvw(v6(0.1, 0, 0, 0, 0, 0.5));
inline const Posed C = Posed::from_xyzuvw(v6(0.1, 0.1, 0, 0, 0, 0));
inline const Twistd XI(Vector3d(0.1, 0, 0), Vector3d(0, 0, 1));

inline Limits limits(double v, double a, std::optional<double> j) {
  Limits l;
  l.velocity = v;
  l.acceleration = a;
  l.jerk = j;
  return l;
}

inline std::string replace_once(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

inline std::string temp_file(const std::string& name, const std::string& content) {
  const std::string path = ::testing::TempDir() + name;
  std::ofstream(path) << content;
  return path;
}


inline constexpr Expect IA = Expect::invalid_argument;
inline constexpr Expect RT = Expect::runtime_error;

// Readable test parameters in gtest's output (instead of a byte dump).
inline void PrintTo(const Row& row, std::ostream* out) { *out << row.entry << " / " << row.bad; }

//! `row(entry, bad, call, expect, fragment[, observed])` appends a row to the table.
struct RowAdder {
  std::vector<Row>& table;
  void operator()(std::string entry, std::string bad, std::function<void()> call, Expect e, std::string fragment,
                  std::string observed = "") const {
    table.push_back({std::move(entry), std::move(bad), std::move(call), e, std::move(fragment), std::move(observed)});
  }
};

#if defined(DISPKIN_HAS_SERIAL)
using serial::PtpOptions;
using serial::SerialArm;
//! The folder of the test URDFs.
inline const std::string urdf = std::string(DISPKIN_SOURCE_DIR) + "/tests/data/urdf/";
#endif

void pose_rows(std::vector<Row>& table);
void metric_set_rows(std::vector<Row>& table);
void disp_functions_rows(std::vector<Row>& table);
void paths_rows(std::vector<Row>& table);
void profiles_rows(std::vector<Row>& table);
void planning_rows(std::vector<Row>& table);
void hexapod_rows(std::vector<Row>& table);
void frames_rows(std::vector<Row>& table);
#if defined(DISPKIN_HAS_SERIAL)
void serial_arm_rows(std::vector<Row>& table);
void joint_motion_rows(std::vector<Row>& table);
#endif

}  // namespace bad_input
