// Plans bit for bit: seeded random Cartesian plans of the six path families under both profile
// kinds, PTP moves of two arms, a hexapod's joint metric and the joint-limit re-timings are
// written as exact text (hexadecimal floating point: counts, duration and length, and a 64-bit
// FNV-1a hash of the sampled states at fixed fractions of the duration, every bit of them) and
// compared with tests/data/plan_fingerprint.txt.
// A change that must not change behaviour (a restructuring, a faster kernel) keeps this file as
// it is; a change that does change plans regenerates it on purpose:
//
//   DISPKIN_WRITE_FINGERPRINT=tests/data/plan_fingerprint.txt build/cmake/tests/dispkin_fingerprint_tests
//
// The reference is what a Release build with this project's compiler gives (the build types CI
// runs it in); another compiler may round differently.
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include <dispkin/hexapod/hexapod.hpp>
#include <dispkin/planning/planner.hpp>
#include <dispkin/serial/ptp.hpp>
#include <dispkin/hexapod/hexapod_retiming.hpp>
#include <dispkin/serial/serial_retiming.hpp>

#include "ptp_moves.hpp"
#include "random_paths.hpp"
#include "retiming_moves.hpp"

namespace dispkin {
namespace {

using hexapod::Hexapod;
using serial::JointTrajectory;
using serial::JointTrajectorySample;

constexpr double sampled_fractions[] = {0.0, 0.013, 0.25, 0.5, 0.618, 0.9, 1.0};

void put(std::ostringstream& out, double x) {
  char text[40];
  std::snprintf(text, sizeof text, " %a", x);
  out << text;
}

void put(std::ostringstream& out, const Posed& pose) {
  for (int i = 0; i < 4; ++i) put(out, pose.quaternion().coeffs()(i));
  for (int i = 0; i < 3; ++i) put(out, pose.translation()(i));
}

void put(std::ostringstream& out, const Twistd& twist) {
  for (int i = 0; i < 6; ++i) put(out, twist.vector()(i));
}

// Counts, duration, length and the state at the sampled fractions of a Cartesian trajectory.
std::string fingerprint(const Trajectory& traj) {
  std::ostringstream out;
  out << "sections " << traj.section_count() << " pieces " << traj.piece_count() << " laws " << traj.law_count();
  put(out, traj.duration());
  put(out, traj.length());
  for (const double f : sampled_fractions) {
    const TrajectorySample s = traj.sample(f * traj.duration());
    out << " |";
    put(out, s.pose);
    put(out, s.body_twist);
    put(out, s.s);
    put(out, s.s_dot);
    put(out, s.s_ddot);
  }
  return out.str();
}

std::string fingerprint(const JointTrajectory& traj) {
  std::ostringstream out;
  out << "sections " << traj.sections().size() << " laws " << traj.law_count();
  put(out, traj.duration());
  put(out, traj.length());
  for (const double f : sampled_fractions) {
    const JointTrajectorySample s = traj.sample(f * traj.duration());
    out << " |";
    for (Eigen::Index i = 0; i < s.q.size(); ++i) put(out, s.q(i));
    for (Eigen::Index i = 0; i < s.qd.size(); ++i) put(out, s.qd(i));
    for (Eigen::Index i = 0; i < s.qdd.size(); ++i) put(out, s.qdd(i));
    put(out, s.pose);
    put(out, s.body_twist);
    put(out, s.u);
    put(out, s.s);
    put(out, s.s_dot);
    put(out, s.s_ddot);
  }
  return out.str();
}

// The summary of a fingerprint (up to the first sample) and the hash of the whole text.
std::string compact(const std::string& text) {
  std::uint64_t hash = 14695981039346656037ull;
  for (const unsigned char c : text) hash = (hash ^ c) * 1099511628211ull;
  char digits[20];
  std::snprintf(digits, sizeof digits, "%016llx", static_cast<unsigned long long>(hash));
  return text.substr(0, text.find(" |")) + " hash " + digits;
}

std::vector<std::string> fingerprints() {
  std::vector<std::string> lines;
  testing::Random rnd(20261202);
  for (int i = 0; i < 300; ++i) {
    const double v = rnd.uniform(0.05, 1.0);
    const MetricSetd set = testing::random_set(rnd, v);
    const Path path = testing::random_path(rnd, i);
    const ProfileKind kind = i % 2 ? ProfileKind::scurve : ProfileKind::trapezoid;
    const Limits limits = testing::random_limits(rnd, v, kind);
    lines.push_back("plan " + std::to_string(i) + " " + compact(fingerprint(plan(path, set, limits, kind))));
  }
  const serial::SerialArm arms[] = {testing::ur5e_arm(), testing::kr6_arm()};
  for (int i = 0; i < 24; ++i) {
    const serial::SerialArm& arm = arms[i % 2];
    const double v = rnd.uniform(0.2, 1.0);
    const MetricSetd set = testing::random_set(rnd, v);
    const JointPath path = testing::random_ptp(rnd, arm);
    const ProfileKind kind = i % 4 < 2 ? ProfileKind::scurve : ProfileKind::trapezoid;
    const Limits limits = testing::random_limits(rnd, v, kind);
    lines.push_back("ptp " + std::to_string(i) + " " + compact(fingerprint(plan(path, set, limits, kind, arm))));
  }
  const Hexapod hexapod = Hexapod::symmetric(0.15, 0.35, 0.10, 0.35, 0.20, 0.15, 0.32, 0.01);
  for (int i = 0; i < 12; ++i) {
    const MetricSetd set = testing::random_set(rnd, 0.05);
    const Posed a = hexapod.home() * rnd.pose(0.01);
    const Posed b = a * rnd.pose(0.02);
    const Path path = i % 2 ? Path::lin(a, b) : Path::lin(a, b, Interpolation::screw);
    const Limits limits{0.05, 0.5, 5.0};
    lines.push_back(
        "hexapod " + std::to_string(i) + " " +
        compact(fingerprint(plan(path, set, limits, ProfileKind::scurve, hexapod.joint_metric(path, limits)))));
  }
  {
    const serial::SerialArm arm = testing::ur5e();
    const testing::Move move = testing::lin_move(arm);
    const Limits fast{1.0, 10.0, std::nullopt};
    OptimalRetimeOptions options;
    options.joint_acceleration = Eigen::VectorXd::Constant(6, 4.0);
    lines.push_back(
        "retime_optimal " +
        fingerprint(retime_optimal(move.path, testing::tool(), fast, arm, move.q_start, options).trajectory));
    const Limits jerk{1.0, 10.0, 200.0};
    lines.push_back(
        "retime_optimal_jerk " +
        fingerprint(retime_optimal(move.path, testing::tool(), jerk, arm, move.q_start, options).trajectory));
    const RetimeResult scaled =
        retime_by_scaling(move.path, testing::tool(), jerk, ProfileKind::scurve, arm, move.q_start);
    lines.push_back("retime_by_scaling " + fingerprint(scaled.trajectory));
    const MetricSetd set = testing::random_set(rnd, 0.05);
    const Path path = Path::lin(
        hexapod.home(), hexapod.home() * Posed(Eigen::Quaterniond(Eigen::AngleAxisd(0.2, Eigen::Vector3d::UnitX())),
                                               Eigen::Vector3d(0.02, 0.0, 0.01)));
    options.joint_acceleration = Eigen::VectorXd::Constant(6, 0.2);
    lines.push_back(
        "retime_optimal_hexapod " +
        fingerprint(retime_optimal(path, set, Limits{0.05, 0.5, std::nullopt}, hexapod, options).trajectory));
  }
  return lines;
}

TEST(PlanFingerprint, PlansAreBitForBitTheRecordedOnes) {
  const std::vector<std::string> lines = fingerprints();
  if (const char* target = std::getenv("DISPKIN_WRITE_FINGERPRINT")) {
    std::ofstream out(target);
    for (const std::string& line : lines) out << line << '\n';
    GTEST_SKIP() << "wrote " << lines.size() << " lines to " << target;
  }
  std::ifstream in(std::string(DISPKIN_SOURCE_DIR) + "/tests/data/plan_fingerprint.txt");
  ASSERT_TRUE(in) << "tests/data/plan_fingerprint.txt is missing";
  std::vector<std::string> recorded;
  for (std::string line; std::getline(in, line);) recorded.push_back(line);
  ASSERT_EQ(recorded.size(), lines.size());
  int differing = 0;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    if (lines[i] == recorded[i]) continue;
    if (++differing <= 3)
      ADD_FAILURE() << "line " << i + 1 << " differs:\n  now      " << lines[i] << "\n  recorded " << recorded[i];
  }
  EXPECT_EQ(differing, 0) << "of " << lines.size() << " plans";
}

}  // namespace
}  // namespace dispkin
