// MotionStream (doc/events.md §5): moves appended while the motion runs never change what was
// sampled before a request; fed in time the motion never stops between moves, fed late it stops
// at the last pose and starts again without a jump; stops, resumptions and overrides inside a
// stream; the point-set limit held throughout (oracle of doc/planning.md eq. 25).
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include <dispkin/planning/motion_stream.hpp>
#include <dispkin/shapes.hpp>

#include "random_cases.hpp"
#include "random_paths.hpp"

namespace dispkin {
namespace {

using V = Eigen::Vector3d;
using testing::message_of;
using testing::Random;
using testing::worst_speed_ratio;

MetricSetd tool_set() {
  MetricSetd set;
  set.add_relative(shapes::icosahedron(0.1));
  return set;
}

// A zig-zag of `count` LINs of 5–15 cm, turning the tool a little each move.
std::vector<Path> moves(Random& rnd, int count) {
  std::vector<Path> out;
  Posed p;
  for (int k = 0; k < count; ++k) {
    const Posed q(Eigen::Quaterniond(Eigen::AngleAxisd(rnd.uniform(-0.2, 0.2), V::UnitZ())) * p.quaternion(),
                  p.translation() + V(rnd.uniform(0.05, 0.15), rnd.uniform(-0.05, 0.05), rnd.uniform(-0.01, 0.01)));
    out.push_back(Path::lin(p, q));
    p = q;
  }
  return out;
}

struct Snapshot {
  std::vector<double> times;
  std::vector<TrajectorySample> samples;
};

Snapshot snapshot(const MotionStream& stream, double until, int count) {
  Snapshot out;
  for (int i = 0; i < count; ++i) {
    out.times.push_back(until * i / count);
    out.samples.push_back(stream.sample(out.times.back()));
  }
  return out;
}

void expect_unchanged(const MotionStream& stream, const Snapshot& before, const std::string& what) {
  for (std::size_t i = 0; i < before.times.size(); ++i) {
    const TrajectorySample x = stream.sample(before.times[i]);
    ASSERT_EQ(x.s_dot, before.samples[i].s_dot) << what << " t " << before.times[i];
    ASSERT_TRUE(x.pose.matrix() == before.samples[i].pose.matrix()) << what << " t " << before.times[i];
  }
}

TEST(MotionStream, FedInTimeItNeverStopsBetweenMoves) {
  Random rnd(4001);
  const MetricSetd set = tool_set();
  const Limits limits{0.2, 1.0, 10.0};
  for (const double tolerance : {0.0, 0.002}) {
    MotionStream stream(set, limits, ProfileKind::scurve, tolerance);
    const std::vector<Path> path = moves(rnd, 12);
    stream.append(path[0], 0.0);
    stream.append(path[1], 0.0);
    // Each next move arrives while the one before the last still runs: one move of look-ahead.
    double t = 0.0;
    for (std::size_t k = 2; k < path.size(); ++k) {
      t = std::max(t, stream.duration() - 0.6 * (stream.duration() - t));
      const Snapshot before = snapshot(stream, t, 200);
      stream.append(path[k], t);
      expect_unchanged(stream, before, "append " + std::to_string(k));
    }
    EXPECT_EQ(stream.leg_count(), 1u);
    EXPECT_LE(worst_speed_ratio(stream, set, limits.velocity, 20000), 1.0 + 1e-6);
    // Blended corners: ṡ never falls to 0 inside the motion; exact corners rest at each.
    int rests = 0;
    for (int i = 1; i < 4000; ++i) rests += stream.sample(stream.duration() * i / 4000).s_dot < 1e-9;
    if (tolerance > 0.0) {
      EXPECT_EQ(rests, 0);
    }
    EXPECT_TRUE(stream.sample(stream.duration()).pose.is_approx(path.back().end(), 1e-9));
    EXPECT_TRUE(stream.done(stream.duration()));
  }
}

TEST(MotionStream, FedLateItRestsAtTheLastPoseAndStartsAgainWithoutAJump) {
  Random rnd(4002);
  const MetricSetd set = tool_set();
  const Limits limits{0.2, 1.0, 10.0};
  MotionStream stream(set, limits, ProfileKind::scurve, 0.002);
  const std::vector<Path> path = moves(rnd, 4);
  stream.append(path[0], 0.0);
  const double late = stream.duration() + 0.5;
  const Snapshot before = snapshot(stream, late, 300);
  stream.append(path[1], late);
  expect_unchanged(stream, before, "late append");
  EXPECT_EQ(stream.leg_count(), 2u);
  // At rest at the end of the first move until the second starts; then on, continuously.
  EXPECT_TRUE(stream.sample(late - 0.25).pose.is_approx(path[0].end(), 1e-12));
  const double dt = 1e-6;
  const TrajectorySample a = stream.sample(late - dt), b = stream.sample(late + dt);
  EXPECT_LT((a.pose.translation() - b.pose.translation()).norm(), 1e-6);
  EXPECT_LE(worst_speed_ratio(stream, set, limits.velocity, 20000), 1.0 + 1e-6);
  // A move that comes during the final deceleration, after the join's blend has begun, starts
  // from rest too.
  const double t = stream.duration() - 1e-3;
  stream.append(path[2], t);
  EXPECT_TRUE(stream.sample(stream.duration()).pose.is_approx(path[2].end(), 1e-9));
  EXPECT_LE(worst_speed_ratio(stream, set, limits.velocity, 20000), 1.0 + 1e-6);
}

TEST(MotionStream, StopResumeAndOverrideInsideTheStream) {
  Random rnd(4003);
  const MetricSetd set = tool_set();
  const Limits limits{0.2, 1.0, 10.0};
  for (const ProfileKind kind : {ProfileKind::scurve, ProfileKind::trapezoid}) {
    MotionStream stream(set, kind == ProfileKind::scurve ? limits : Limits{0.2, 1.0, std::nullopt}, kind, 0.002);
    const std::vector<Path> path = moves(rnd, 6);
    stream.append(path[0], 0.0);
    stream.append(path[1], 0.0);
    double t = 0.4 * stream.duration();
    Snapshot before = snapshot(stream, t, 200);
    stream.stop(t);
    expect_unchanged(stream, before, "stop");
    EXPECT_TRUE(stream.stopped());
    // Moves appended while stopped wait; the motion stays at rest.
    stream.append(path[2], t + 0.01);
    EXPECT_EQ(stream.waiting_moves(), 1u);
    const double rest = stream.duration();
    EXPECT_NEAR(stream.sample(rest + 0.5).s_dot, 0.0, 1e-12);
    t = rest + 1.0;
    before = snapshot(stream, t, 200);
    stream.resume(t);
    expect_unchanged(stream, before, "resume");
    EXPECT_FALSE(stream.stopped());
    t += 0.5;
    before = snapshot(stream, t, 200);
    stream.set_override(t, 0.5);
    expect_unchanged(stream, before, "override");
    stream.append(path[3], t + 0.1);
    EXPECT_TRUE(stream.sample(stream.duration()).pose.is_approx(path[3].end(), 1e-9));
    EXPECT_LE(worst_speed_ratio(stream, set, limits.velocity, 20000), 1.0 + 1e-6);
  }
}

// changed_from: where each request takes over; before it nothing changed, there the pose and its
// velocity go on (a join plans the path ahead afresh from the state, doc/events.md §5).
TEST(MotionStream, SaysFromWhenARequestChangedTheMotion) {
  Random rnd(4005);
  const MetricSetd set = tool_set();
  MotionStream stream(set, Limits{0.2, 1.0, 10.0}, ProfileKind::scurve, 0.002);
  const std::vector<Path> path = moves(rnd, 5);
  stream.append(path[0], 0.0);
  EXPECT_EQ(stream.changed_from(), 0.0);
  for (std::size_t k = 1; k < 3; ++k) {
    const MotionStream before = stream;
    const double t = 0.5 * stream.duration();
    stream.append(path[k], t);
    EXPECT_GE(stream.changed_from(), t);
    EXPECT_LT(stream.changed_from(), before.duration());
    const TrajectorySample a = before.sample(stream.changed_from()), b = stream.sample(stream.changed_from());
    EXPECT_TRUE(b.pose.is_approx(a.pose, 1e-12));
    EXPECT_LE((b.body_twist.vector() - a.body_twist.vector()).norm(), 1e-9);
    EXPECT_EQ(stream.leg_count(), 1u);
  }
  stream.stop(1.0);
  EXPECT_EQ(stream.changed_from(), 1.0);
  stream.append(path[3], 1.1);
  EXPECT_EQ(stream.changed_from(), std::numeric_limits<double>::infinity());  // it waits
  stream.resume(stream.duration() + 1.0);
  EXPECT_EQ(stream.changed_from(), stream.duration() > 0.0 ? stream.changed_from() : 0.0);
  const double late = stream.duration() + 0.5;
  stream.append(path[4], late);
  EXPECT_EQ(stream.changed_from(), late);  // a leg from rest
  EXPECT_EQ(stream.leg_count(), 2u);
}

// A long stream keeps what it ran until told to let go: forget_before(t) keeps the stretch
// running at t and every later one, and the motion from t on the same, bit for bit.
TEST(MotionStream, ForgetsWhatItRanBeforeATime) {
  Random rnd(4006);
  MotionStream stream(tool_set(), Limits{0.2, 1.0, 10.0}, ProfileKind::scurve, 0.002);
  const std::vector<Path> path = moves(rnd, 12);
  stream.append(path[0], 0.0);
  double t = 0.0;
  for (std::size_t k = 1; k < path.size(); ++k) {
    t = 0.5 * (t + stream.duration());
    stream.append(path[k], t);
  }
  MotionStream kept = stream;
  const double cut = 0.5 * stream.duration();
  MotionStream::Cursor cursor;
  kept.sample(0.1, cursor);  // a cursor from before
  kept.forget_before(cut);
  for (int i = 0; i <= 200; ++i) {
    const double at = cut + (stream.duration() - cut) * i / 200;
    const TrajectorySample a = stream.sample(at), b = kept.sample(at, cursor);
    ASSERT_TRUE(a.pose.matrix() == b.pose.matrix() && a.s == b.s) << at;
  }
  EXPECT_EQ(kept.duration(), stream.duration());
  EXPECT_EQ(kept.leg_count(), stream.leg_count());
  // Before the cut: the state where the first stretch kept starts, at most the cut.
  EXPECT_LE(kept.sample(0.0).s, kept.sample(cut).s);
  kept.append(
      Path::lin(path.back().end(), Posed(Eigen::Matrix3d::Identity(), path.back().end().translation() + V(0.1, 0, 0))),
      stream.duration() - 0.5);
  EXPECT_GT(kept.duration(), stream.duration());
}

TEST(MotionStream, RefusesWithAClearMessage) {
  Random rnd(4004);
  MotionStream stream(tool_set(), Limits{0.2, 1.0, 10.0});
  const std::vector<Path> path = moves(rnd, 3);
  EXPECT_NE(message_of([&] { stream.stop(0.0); }).find("nothing was appended yet"), std::string::npos);
  stream.append(path[0], 1.0);
  EXPECT_NE(message_of([&] { stream.append(path[2], 1.5); }).find("path.start"), std::string::npos);
  EXPECT_NE(
      message_of([&] { stream.append(path[1], 0.5); }).find("t = 0.5: must be finite and not before the last request"),
      std::string::npos);
  EXPECT_NE(message_of([&] { stream.resume(1.6); }).find("resumes a stopped motion only"), std::string::npos);
  EXPECT_NE(message_of([&] { stream.set_override(1.7, 0.0); }).find("factor = 0"), std::string::npos);
  EXPECT_NE(message_of([] {
              MotionStream(tool_set(), Limits{0.2, 1.0, std::nullopt});
            }).find("jerk"),
            std::string::npos);
  EXPECT_NE(message_of([] {
              MotionStream(tool_set(), Limits{0.2, 1.0, 10.0}, ProfileKind::scurve, -1.0);
            }).find("corner_tolerance = -1"),
            std::string::npos);
  // Before the first move a default sample.
  EXPECT_EQ(MotionStream(tool_set(), Limits{0.2, 1.0, 10.0}).sample(1.0).s, 0.0);
}

}  // namespace
}  // namespace dispkin
