// Real-time claims, proven by counting: this executable replaces the global operator new and delete
// with versions that count every call, and checks that the sampling paths allocate nothing
// (doc/guarantees-and-measurements.md: sampling never allocates; Drake's LimitMalloc idea).
#include <atomic>
#include <cmath>
#include <cstddef>
#include <cstdlib>
#include <new>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

// Eigen allocates with malloc, not operator new: its own guard (EIGEN_RUNTIME_NO_MALLOC) sees
// those, and eigen_assert is redefined to count failures even in a release (NDEBUG) build.
#include <atomic>
namespace {
std::atomic<long> eigen_assert_failures{0};
}  // namespace
#define EIGEN_RUNTIME_NO_MALLOC
#define eigen_assert(x)                \
  do {                                 \
    if (!(x)) ++eigen_assert_failures; \
  } while (false)
#include "dispkin/planning/motion_stream.hpp"
#include "dispkin/planning/overlap.hpp"
#include "dispkin/planning/planner.hpp"
#include "dispkin/profile.hpp"
#include "dispkin/shapes.hpp"
#ifdef DISPKIN_HAS_SERIAL
#include "dispkin/serial/joint_overlap.hpp"
#include "dispkin/serial/mixed_overlap.hpp"
#include "dispkin/serial/ptp.hpp"
#include "dispkin/serial/analytic_ik.hpp"
#include "dispkin/serial/followed_trajectory.hpp"
#include "ptp_moves.hpp"
#include "serial_test_chains.hpp"
#endif

namespace {
std::atomic<long> allocations{0};
}  // namespace

void* operator new(std::size_t size) {
  ++allocations;
  if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
  throw std::bad_alloc();
}
void* operator new[](std::size_t size) {
  ++allocations;
  if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
  throw std::bad_alloc();
}
void* operator new(std::size_t size, const std::nothrow_t&) noexcept {
  ++allocations;
  return std::malloc(size == 0 ? 1 : size);
}
void* operator new[](std::size_t size, const std::nothrow_t&) noexcept {
  ++allocations;
  return std::malloc(size == 0 ? 1 : size);
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }

namespace dispkin {
namespace {

// Runs `body` with Eigen's no-malloc guard on and returns how often operator new was called.
template <typename Body>
long allocations_during(Body&& body) {
  const long before = allocations.load();
  Eigen::internal::set_is_malloc_allowed(false);
  body();
  Eigen::internal::set_is_malloc_allowed(true);
  return allocations.load() - before;
}

// Eigen's guard works: a dynamic matrix made while malloc is disallowed is seen.
TEST(Realtime, EigenGuardSeesAllocations) {
  const long before = eigen_assert_failures.load();
  Eigen::internal::set_is_malloc_allowed(false);
  Eigen::VectorXd v(100);
  Eigen::internal::set_is_malloc_allowed(true);
  v.setZero();
  EXPECT_GT(eigen_assert_failures.load(), before);
  eigen_assert_failures = 0;
}

// The counter itself works: a vector allocates and is counted.
TEST(Realtime, CounterSeesAllocations) {
  const long before = allocations.load();
  std::vector<double> v(100);
  v[0] = 1.0;
  EXPECT_GT(allocations.load(), before);
}

TEST(Realtime, ProfileSamplingDoesNotAllocate) {
  const Profile profiles[] = {
      Profile::trapezoid(1.0, 1.0, 2.0),
      Profile::trapezoid(0.3, 1.0, 2.0, 0.5, 0.2),
      Profile::scurve(1.0, 1.0, 2.0, 5.0),
      Profile::scurve(1e-6, 1.0, 2.0, 5.0),
      Profile::scurve(2.0, 1.0, 2.0, 5.0, 0.7, 0.1),
      Profile::scurve(0.0, 1.0, 2.0, 5.0),
  };
  constexpr int kTimes = 100000;
  std::vector<double> times(kTimes);
  std::vector<ProfileState> out(kTimes);
  double checksum = 0.0;
  for (const Profile& p : profiles) {
    for (int i = 0; i < kTimes; ++i) times[static_cast<std::size_t>(i)] = p.duration() * (1.2 * i / kTimes - 0.1);
    const long before = allocations.load();
    for (int i = 0; i < kTimes; ++i) checksum += p.state_at(times[static_cast<std::size_t>(i)]).s;
    p.sample(times.data(), out.data(), times.size());
    EXPECT_EQ(allocations.load(), before) << "state_at or sample allocated";
  }
  EXPECT_TRUE(checksum >= 0.0);  // keeps the loop from being optimised away
}

// Sampling planned trajectories (LIN, screw, CIRC with ~1000 sections, a cornered chain, a
// blend, a SPLINE), at single times, in a batch and with a cursor:
// no operator new, and Eigen's own no-malloc guard on.
TEST(Realtime, TrajectorySamplingDoesNotAllocate) {
  MetricSetd set;
  set.add_relative(shapes::icosahedron(0.1));
  set.add_sphere(Eigen::Vector3d(0, 0, 0.3), 0.05, Frame::absolute);
  using V = Eigen::Vector3d;
  const Posed a, b(Eigen::Quaterniond(Eigen::AngleAxisd(0.8, V::UnitZ())), V(0.3, 0.1, 0));
  const Posed via(Eigen::Quaterniond::Identity(), V(0.15, 0.2, 0));
  Path chain = Path::lin(a, b);
  chain.then(Path::lin(b, Posed(b.quaternion(), V(0.3, 0.4, 0.1))));
  Path blended = Path::lin(a, b);
  blended.then(Path::lin(b, Posed(b.quaternion(), V(0.3, 0.4, 0.1))), 0.05);
  std::vector<Trajectory> trajectories = {
      plan(Path::lin(a, b), set, Limits{0.1, 0.5, 5.0}),
      plan(Path::lin(a, b, Interpolation::screw), set, Limits{0.1, 0.5, std::nullopt}, ProfileKind::trapezoid),
      plan(Path::circ(a, via, b), set, Limits{0.1, 0.5, 5.0}),
      plan(chain, set, Limits{0.1, 0.5, 5.0}),
      plan(blended, set, Limits{0.1, 0.5, 5.0}),
      plan(Path::spline({a, via, b, Posed(b.quaternion(), V(0.3, 0.4, 0.1))}), set, Limits{0.1, 0.5, 5.0}),
  };
  // After events (doc/events.md): a stop, an override, a stop resumed; their cut laws included.
  const Trajectory chained = trajectories[3], blended_traj = trajectories[4], screw = trajectories[1];
  trajectories.push_back(chained.stopped_at(0.4 * chained.duration()));
  trajectories.push_back(
      chained.with_override(0.3 * chained.duration(), 0.5).with_override(0.6 * chained.duration(), 1.0));
  trajectories.push_back(blended_traj.stopped_at(0.5 * blended_traj.duration()).resumed_at(blended_traj.duration()));
  trajectories.push_back(screw.stopped_at(0.5 * screw.duration()));
  constexpr int kTimes = 20000;
  std::vector<double> times(kTimes);
  std::vector<TrajectorySample> out(kTimes);
  double checksum = 0.0;
  for (const Trajectory& traj : trajectories) {
    for (int i = 0; i < kTimes; ++i) times[static_cast<std::size_t>(i)] = traj.duration() * (1.2 * i / kTimes - 0.1);
    const long allocated = allocations_during([&] {
      for (int i = 0; i < kTimes; ++i) checksum += traj.sample(times[static_cast<std::size_t>(i)]).s_dot;
      traj.sample(times.data(), out.data(), times.size());
      // With a cursor: forwards (the control loop), then backwards.
      Trajectory::Cursor cursor;
      for (int i = 0; i < kTimes; ++i) checksum += traj.sample(times[static_cast<std::size_t>(i)], cursor).s_dot;
      for (int i = kTimes; i-- > 0;) checksum += traj.sample(times[static_cast<std::size_t>(i)], cursor).s_dot;
    });
    EXPECT_EQ(allocated, 0) << "Trajectory::sample (plain, batch or with a cursor) allocated";
    EXPECT_EQ(eigen_assert_failures.load(), 0) << "Eigen allocated (or an Eigen assertion failed) while sampling";
  }
  EXPECT_TRUE(checksum >= 0.0);
}

// The overlapped velocity method samples two trajectories and composes them: no allocation.
TEST(Realtime, OverlappedSamplingDoesNotAllocate) {
  MetricSetd set;
  set.add_relative(shapes::icosahedron(0.1));
  using V = Eigen::Vector3d;
  const Posed a, via(Eigen::Quaterniond(Eigen::AngleAxisd(0.4, V::UnitZ())), V(0.3, 0, 0));
  const Posed b(Eigen::Quaterniond(Eigen::AngleAxisd(0.8, V::UnitZ())), V(0.3, 0.3, 0));
  const Limits limits{0.1, 0.5, 5.0};
  const OverlappedTrajectory o(plan(Path::lin(a, via), set, limits), plan(Path::lin(via, b), set, limits), 0.2);
  double checksum = 0.0;
  const long allocated = allocations_during([&] {
    for (int i = 0; i < 20000; ++i) checksum += o.sample(o.duration() * (1.2 * i / 20000 - 0.1)).s_dot;
  });
  EXPECT_EQ(allocated, 0) << "OverlappedTrajectory::sample allocated";
  EXPECT_EQ(eigen_assert_failures.load(), 0);
  EXPECT_TRUE(checksum >= 0.0);
}
// A MotionStream of two legs (a move joined to the running one, a late one from rest), stopped,
// resumed and overridden: sampling it, plain or with a cursor, allocates nothing.
TEST(Realtime, MotionStreamSamplingDoesNotAllocate) {
  MetricSetd set;
  set.add_relative(shapes::icosahedron(0.1));
  using V = Eigen::Vector3d;
  const Posed a, b(Eigen::Quaterniond(Eigen::AngleAxisd(0.2, V::UnitZ())), V(0.1, 0.02, 0));
  const Posed c(Eigen::Quaterniond(Eigen::AngleAxisd(0.4, V::UnitZ())), V(0.2, 0.0, 0));
  const Posed d(Eigen::Quaterniond(Eigen::AngleAxisd(0.5, V::UnitZ())), V(0.3, 0.03, 0));
  MotionStream stream(set, Limits{0.1, 0.5, 5.0}, ProfileKind::scurve, 0.002);
  stream.append(Path::lin(a, b), 0.0);
  stream.append(Path::lin(b, c), 0.0);
  stream.stop(0.5);
  stream.resume(2.0);
  stream.set_override(2.5, 0.5);
  stream.append(Path::lin(c, d), stream.duration() + 0.5);
  ASSERT_EQ(stream.leg_count(), 2u);
  double checksum = 0.0;
  const double end = stream.duration();
  const long allocated = allocations_during([&] {
    for (int i = 0; i < 20000; ++i) checksum += stream.sample(end * (1.2 * i / 20000 - 0.1)).s_dot;
    MotionStream::Cursor cursor;
    for (int i = 0; i < 20000; ++i) checksum += stream.sample(end * (1.2 * i / 20000 - 0.1), cursor).s_dot;
    for (int i = 20000; i-- > 0;) checksum += stream.sample(end * (1.2 * i / 20000 - 0.1), cursor).s_dot;
  });
  EXPECT_EQ(allocated, 0) << "MotionStream::sample allocated";
  EXPECT_EQ(eigen_assert_failures.load(), 0);
  EXPECT_TRUE(checksum >= 0.0);
}

// Sampling a path blended by nested SLERP (SlerpBlendSection::at: exp, log and right Jacobians on
// fixed-size vectors) allocates nothing.
TEST(Realtime, SlerpBlendSamplingDoesNotAllocate) {
  MetricSetd set;
  set.add_relative(shapes::icosahedron(0.1));
  using V = Eigen::Vector3d;
  const Posed a, via(Eigen::Quaterniond(Eigen::AngleAxisd(0.4, V::UnitZ())), V(0.3, 0, 0));
  const Posed b(Eigen::Quaterniond(Eigen::AngleAxisd(0.8, V::UnitX())), V(0.3, 0.3, 0));
  Path path = Path::lin(a, via);
  path.then_weighted(Path::lin(via, b), 0.4, OrientationBlend::nested_slerp);
  const Trajectory traj = plan(path, set, Limits{0.1, 0.5, 5.0});
  double checksum = 0.0;
  const long allocated = allocations_during([&] {
    for (int i = 0; i < 20000; ++i)
      checksum += traj.sample(traj.duration() * (1.2 * i / 20000 - 0.1)).body_twist.angular.norm();
  });
  EXPECT_EQ(allocated, 0) << "Trajectory::sample allocated on a nested-SLERP blend";
  EXPECT_EQ(eigen_assert_failures.load(), 0);
  EXPECT_TRUE(checksum > 0.0);
}
#ifdef DISPKIN_HAS_SERIAL
using serial::FollowedTrajectory;
using serial::JointTrajectory;
using serial::JointTrajectorySample;
using serial::OverlappedJointTrajectory;
using serial::OverlappedMixedTrajectory;

// The closed-form IK families write into a fixed IkSolutionSet: no allocation at all (checks,
// subproblems, Newton polish, de-duplication), over random poses of every closed-form robot
// including wrist-singular ones (q5 = 0 exactly).
// Planning a LIN allocates a small fixed number of blocks (at most 32: the path's, the time
// law's and the trajectory's arrays), however many pieces the cut makes of a rotating one —
// the planned sections' arrays are sized once for the whole cut (doc/planning.md §9).
TEST(Realtime, PlanningALinAllocatesAFixedNumberOfBlocks) {
  MetricSetd set;
  set.add_relative(shapes::icosahedron(0.3));
  const Limits limits{1.0, 2.0};
  const Posed start;
  std::vector<long> counts;
  std::vector<std::size_t> pieces;
  for (const double turn : {0.0, 0.3, 1.0, 2.5}) {
    const Posed end(Eigen::Quaterniond(Eigen::AngleAxisd(turn, Eigen::Vector3d(0.3, 0.2, 1.0).normalized())),
                    Eigen::Vector3d(0.4, 0.1, 0.05));
    const Path path = Path::lin(start, end);
    Trajectory trajectory;
    const long n = allocations_during([&] { trajectory = plan(path, set, limits, ProfileKind::trapezoid); });
    counts.push_back(n);
    pieces.push_back(trajectory.path().section_count());
  }
  for (std::size_t i = 0; i < counts.size(); ++i)
    EXPECT_LE(counts[i], 32) << "a LIN cut into " << pieces[i] << " pieces";
  EXPECT_EQ(pieces.front(), 1u);
  EXPECT_GT(pieces.back(), 50u);  // the cut is exercised
}

TEST(Realtime, ClosedFormInverseKinematicsDoesNotAllocate) {
  const std::vector<testing::NamedChain> robots = {{"kuka_kr6_r900", testing::kuka_kr6_r900()},
                                                   {"abb_irb120", testing::abb_irb120()},
                                                   {"abb_irb6640", testing::abb_irb6640()},
                                                   {"ur5", testing::ur5()},
                                                   {"ur10e", testing::ur10e()}};
  std::mt19937_64 engine(20261122);
  std::uniform_real_distribution<double> angle(-3.14159, 3.14159);
  for (const auto& robot : robots) {
    const serial::IkFamily family = serial::recognise(robot.chain);
    std::vector<Posed> poses;
    for (int n = 0; n < 500; ++n) {
      Eigen::VectorXd q(6);
      for (int i = 0; i < 6; ++i) q(i) = angle(engine);
      if (n % 10 == 0) q(4) = 0.0;
      poses.push_back(serial::forward(robot.chain, q));
    }
    serial::IkSolutionSet set;
    int total = 0;
    const long allocated = allocations_during([&] {
      for (const Posed& pose : poses) {
        serial::analytic_inverse(robot.chain, family, pose, set);
        total += set.count;
      }
    });
    EXPECT_EQ(allocated, 0) << robot.name << ": analytic_inverse (IkSolutionSet) allocated";
    EXPECT_EQ(eigen_assert_failures.load(), 0) << robot.name << ": Eigen allocated during analytic_inverse";
    EXPECT_GE(total, 500) << robot.name;  // every pose is reachable: at least one solution each
  }
}

// A PTP move of the UR5e and the KR6-like arm (both profiles), sampled at single times and in a
// batch: q, q̇, q̈ in inline JointVectors, the pose and twist by the product of exponentials —
// no operator new, Eigen's no-malloc guard on.
TEST(Realtime, JointTrajectorySamplingDoesNotAllocate) {
  MetricSetd set;
  set.add_relative(shapes::icosahedron(0.1));
  set.add_sphere(Eigen::Vector3d(0.3, 0, 0.3), 0.05, Frame::absolute);
  Eigen::VectorXd q_a(6), q_b(6);
  q_a << 0.1, -1.2, 1.3, -1.0, -1.2, 0.2;
  q_b << 1.4, -0.6, 0.7, -1.6, -0.9, 1.1;
  std::vector<JointTrajectory> trajectories;
  for (const serial::SerialArm& arm : {testing::ur5e_arm(), testing::kr6_arm()}) {
    trajectories.push_back(plan(JointPath(q_a, q_b), set, Limits{0.5, 2.0, 20.0}, ProfileKind::scurve, arm));
    trajectories.push_back(plan(JointPath(q_b, q_a), set, Limits{0.5, 2.0, std::nullopt}, ProfileKind::trapezoid, arm));
  }
  constexpr int kTimes = 20000;
  std::vector<double> times(kTimes);
  std::vector<JointTrajectorySample> out(kTimes);
  double checksum = 0.0;
  for (const JointTrajectory& traj : trajectories) {
    for (int i = 0; i < kTimes; ++i) times[static_cast<std::size_t>(i)] = traj.duration() * (1.2 * i / kTimes - 0.1);
    const long allocated = allocations_during([&] {
      for (int i = 0; i < kTimes; ++i) checksum += traj.sample(times[static_cast<std::size_t>(i)]).qd.norm();
      traj.sample(times.data(), out.data(), times.size());
    });
    EXPECT_EQ(allocated, 0) << "JointTrajectory::sample allocated";
    EXPECT_EQ(eigen_assert_failures.load(), 0) << "Eigen allocated (or an Eigen assertion failed) while sampling";
  }
  EXPECT_TRUE(checksum > 0.0);
}

// Two PTP moves overlapped (OverlappedJointTrajectory::sample: inline JointVectors, FK of the sum).
TEST(Realtime, OverlappedJointSamplingDoesNotAllocate) {
  MetricSetd set;
  set.add_relative(shapes::icosahedron(0.1));
  Eigen::VectorXd q_a(6), via(6), q_b(6);
  q_a << 0.1, -1.2, 1.3, -1.0, -1.2, 0.2;
  via << 1.4, -0.6, 0.7, -1.6, -0.9, 1.1;
  q_b << 0.5, -1.0, 1.0, -1.2, -1.5, 0.4;
  const serial::SerialArm arm = testing::ur5e_arm();
  const Limits limits{0.5, 2.0, 20.0};
  const JointTrajectory first = plan(JointPath(q_a, via), set, limits, ProfileKind::scurve, arm);
  const JointTrajectory second = plan(JointPath(via, q_b), set, limits, ProfileKind::scurve, arm);
  const OverlappedJointTrajectory o(first, second, 0.5 * std::min(first.duration(), second.duration()));
  double checksum = 0.0;
  const long allocated = allocations_during([&] {
    for (int i = 0; i < 20000; ++i) checksum += o.sample(o.duration() * (1.2 * i / 20000 - 0.1)).qd.norm();
  });
  EXPECT_EQ(allocated, 0) << "OverlappedJointTrajectory::sample allocated";
  EXPECT_EQ(eigen_assert_failures.load(), 0);
  EXPECT_TRUE(checksum > 0.0);
}

// A PTP move and a LIN overlapped, both orders (FollowedTrajectory::sample: the time law, a
// Hermite interval of the grid built at construction, FK; OverlappedMixedTrajectory::sample).
TEST(Realtime, MixedOverlapSamplingDoesNotAllocate) {
  MetricSetd set;
  set.add_relative(shapes::icosahedron(0.1));
  Eigen::VectorXd q_a(6), via(6);
  q_a << 0.1, -1.2, 1.3, -1.0, -1.2, 0.2;
  via << 0.6, -1.0, 1.1, -1.4, -1.1, 0.5;
  const serial::SerialArm arm = testing::ur5e_arm();
  const Limits limits{0.5, 2.0, 20.0};
  const Posed at_via = arm.forward(via);
  const Posed away = at_via * Posed(Eigen::Quaterniond(Eigen::AngleAxisd(0.2, Eigen::Vector3d::UnitX())),
                                    Eigen::Vector3d(0.06, -0.04, 0.05));
  const JointTrajectory to_via = plan(JointPath(q_a, via), set, limits, ProfileKind::scurve, arm);
  const JointTrajectory from_via = plan(JointPath(via, q_a), set, limits, ProfileKind::scurve, arm);
  const FollowedTrajectory lin_out =
      FollowedTrajectory::from_start(plan(Path::lin(at_via, away), set, limits), arm, via);
  const FollowedTrajectory lin_in = FollowedTrajectory::to_end(plan(Path::lin(away, at_via), set, limits), arm, via);
  const OverlappedMixedTrajectory ptp_lin(to_via, lin_out, 0.5 * std::min(to_via.duration(), lin_out.duration()));
  const OverlappedMixedTrajectory lin_ptp(lin_in, from_via, 0.5 * std::min(lin_in.duration(), from_via.duration()));
  double checksum = 0.0;
  const long allocated = allocations_during([&] {
    for (const OverlappedMixedTrajectory* o : {&ptp_lin, &lin_ptp}) {
      for (int i = 0; i < 20000; ++i) checksum += o->sample(o->duration() * (1.2 * i / 20000 - 0.1)).qd.norm();
    }
    for (int i = 0; i < 5000; ++i) checksum += lin_out.sample(lin_out.duration() * (1.2 * i / 5000 - 0.1)).qdd.norm();
  });
  EXPECT_EQ(allocated, 0) << "OverlappedMixedTrajectory::sample allocated";
  EXPECT_EQ(eigen_assert_failures.load(), 0);
  EXPECT_TRUE(checksum > 0.0);
}

// A seven-joint arm (the iiwa14) following a LIN with its redundancy parameter moved along the
// path (doc/inverse-kinematics.md eqs. 47–50): the nodes hold all seven joints, so sampling is the
// same Hermite interval and FK as for six.
TEST(Realtime, SevenJointFollowedSamplingDoesNotAllocate) {
  MetricSetd set;
  set.add_relative(shapes::icosahedron(0.1));
  const serial::SerialArm arm = serial::SerialArm::from_urdf_file(
      std::string(DISPKIN_SOURCE_DIR) + "/tests/data/urdf/arm_iiwa14_dh.urdf", "link_0", "tool0");
  Eigen::VectorXd q(7);
  q << 0.3, 0.5, 0.2, -1.6, -0.3, 1.0, 0.4;
  const Posed start = arm.forward(q);
  const Posed end = start * Posed(Eigen::Quaterniond(Eigen::AngleAxisd(0.2, Eigen::Vector3d::UnitZ())),
                                  Eigen::Vector3d(0.08, -0.05, 0.04));
  const FollowedTrajectory lin =
      FollowedTrajectory::from_start(plan(Path::lin(start, end), set, Limits{0.5, 2.0, 20.0}), arm, q,
                                     FollowedTrajectory::default_spacing, serial::RedundancyRule{});
  ASSERT_EQ(lin.start(), q);
  ASSERT_GT(std::abs(lin.end()(6) - q(6)), 1e-6) << "the parameter did not move";
  double checksum = 0.0;
  const long allocated = allocations_during([&] {
    for (int i = 0; i < 20000; ++i) checksum += lin.sample(lin.duration() * (1.2 * i / 20000 - 0.1)).qdd.norm();
  });
  EXPECT_EQ(allocated, 0) << "FollowedTrajectory::sample allocated for seven joints";
  EXPECT_EQ(eigen_assert_failures.load(), 0);
  EXPECT_TRUE(checksum > 0.0);
}
#endif

}  // namespace
}  // namespace dispkin
