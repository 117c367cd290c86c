// Large random sweeps: the guarantee (doc/planning.md eq. 5; oracle eq. 25) per path family,
// profile invariants per law, hexapod IK → FK round trips. The count per family comes from
// DISPKIN_SWEEP_COUNT (CMake cache variable of the same name: 10⁵ in `make test`, 10⁷ in
// `make sweep`); the analytic-IK round trips run as the `sweep_analytic_ik_round_trips` test
// (tests/CMakeLists.txt). Every family reports its count and worst figure as test properties.
#include <algorithm>
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include <dispkin/hexapod/hexapod.hpp>
#include <dispkin/planning/planner.hpp>
#include <dispkin/profile.hpp>

#include "random_cases.hpp"
#include "random_paths.hpp"
#ifdef DISPKIN_HAS_SERIAL
#include <dispkin/serial/ptp.hpp>

#include "ptp_moves.hpp"
#endif

namespace dispkin {
namespace {

using hexapod::Hexapod;
using testing::Random;

int sweep_count() { return static_cast<int>(testing::env_or("DISPKIN_SWEEP_COUNT", 1000)); }

void record(const std::string& family, int count, double worst) {
  ::testing::Test::RecordProperty(family + "_count", std::to_string(count));
  ::testing::Test::RecordProperty(family + "_worst", std::to_string(worst));
  std::printf("%s: %d cases, worst %.9g\n", family.c_str(), count, worst);
}

// The guarantee for one path family of testing::random_path: random sets (relative and absolute
// points, spheres, a second group with its own limit), random limits and profile kind, every
// point's speed / limit at `instants` random instants per case by finite differences of the
// motion, over the count's `share` of cases. The curved families (CIRC, SPLINE, blended chains)
// plan hundreds of sections a case, so their cost is the planning: they run a third of the cases
// at three times the instants, the same number of instants checked.
void guarantee_sweep(int family, unsigned long salt, int share = 1, int instants = 32) {
  Random rnd(salt);
  const int n = std::max(100, sweep_count() / share);
  double worst = 0.0;
  for (int i = 0; i < n; ++i) {
    const double v = rnd.uniform(0.05, 1.0);
    const MetricSetd set = testing::random_set(rnd, v);
    const Path path = testing::random_path(rnd, family);
    const ProfileKind kind = rnd.integer(0, 1) ? ProfileKind::scurve : ProfileKind::trapezoid;
    const Limits limits = testing::random_limits(rnd, v, kind);
    const Trajectory traj = plan(path, set, limits, kind);
    const double ratio = testing::worst_speed_ratio_at_random_times(traj, set, v, instants, rnd);
    worst = std::max(worst, ratio);
    ASSERT_LE(ratio, 1.0 + 1e-6) << "family " << family << " case " << i;
    ASSERT_TRUE(traj.sample(traj.duration()).pose.is_approx(path.end(), 1e-9)) << "family " << family << " case " << i;
  }
  record("guarantee_family_" + std::to_string(family), n, worst);
}

// The guarantee along pose lists planned in continuous-path mode (corners blended within a
// tolerance, doc/planning.md §10): as guarantee_sweep, and the end pose reached.
TEST(Sweep, GuaranteeBlendedPoseList) {
  Random rnd(9106);
  // A tenth of the count: a case plans some 3000 sections (tight blends cut to the cruise rule).
  const int n = std::max(100, sweep_count() / 10);
  double worst = 0.0;
  for (int i = 0; i < n; ++i) {
    const double v = rnd.uniform(0.05, 1.0);
    const MetricSetd set = testing::random_set(rnd, v);
    const testing::PoseListPath list = testing::random_pose_list_path(rnd);
    const ProfileKind kind = rnd.integer(0, 1) ? ProfileKind::scurve : ProfileKind::trapezoid;
    const Limits limits = testing::random_limits(rnd, v, kind);
    PlanOptions options;
    options.corner_tolerance = list.corner_tolerance;
    options.blend_tolerance = 1e-2;  // as the other families' curves: fewer sections, the same guarantee
    const Trajectory traj = plan(list.path, set, limits, kind, options);
    const double ratio = testing::worst_speed_ratio_at_random_times(traj, set, v, 32, rnd);
    worst = std::max(worst, ratio);
    ASSERT_LE(ratio, 1.0 + 1e-6) << "blended pose list, case " << i;
    ASSERT_TRUE(traj.sample(traj.duration()).pose.is_approx(list.path.end(), 1e-9)) << "blended pose list, case " << i;
  }
  record("guarantee_blended_pose_list", n, worst);
}

// The guarantee along chains of LINs blended by nested SLERP (doc/planning.md §6.1): as
// guarantee_sweep, on a twentieth of the count (the family's other blends are swept in full).
TEST(Sweep, GuaranteeSlerpBlendedChain) {
  Random rnd(9107);
  const int n = std::max(50, sweep_count() / 20);
  double worst = 0.0;
  for (int i = 0; i < n; ++i) {
    const double v = rnd.uniform(0.05, 1.0);
    const MetricSetd set = testing::random_set(rnd, v);
    const Path path = testing::random_slerp_blended_chain(rnd);
    const ProfileKind kind = rnd.integer(0, 1) ? ProfileKind::scurve : ProfileKind::trapezoid;
    const Trajectory traj = plan(path, set, testing::random_limits(rnd, v, kind), kind);
    const double ratio = testing::worst_speed_ratio_at_random_times(traj, set, v, 32, rnd);
    worst = std::max(worst, ratio);
    ASSERT_LE(ratio, 1.0 + 1e-6) << "nested-SLERP chain, case " << i;
    ASSERT_TRUE(traj.sample(traj.duration()).pose.is_approx(path.end(), 1e-9)) << "nested-SLERP chain, case " << i;
  }
  record("guarantee_slerp_blended_chain", n, worst);
}

// Events on random plans (doc/events.md): each case a random path of every family, a random set
// and limits, then three events at random instants (a stop, a resumption of a stopped motion, an
// override of 0.1–2); after each the motion before it is the same bit for bit (at 4 random
// instants), and the result keeps the point-set limit (32 random instants), |s̈| ≤ a_max, ṡ ≥ 0,
// and ends at rest where it should: the path's end, or its pose where it stopped. A tenth of the
// count: a case plans once and applies three events.
TEST(Sweep, GuaranteeWithEvents) {
  Random rnd(9108);
  const int n = std::max(50, sweep_count() / 10);
  double worst = 0.0;
  for (int i = 0; i < n; ++i) {
    const double v = rnd.uniform(0.05, 1.0);
    const MetricSetd set = testing::random_set(rnd, v);
    const Path path = testing::random_path(rnd, i % 6);
    const ProfileKind kind = rnd.integer(0, 1) ? ProfileKind::scurve : ProfileKind::trapezoid;
    const Limits limits = testing::random_limits(rnd, v, kind);
    Trajectory traj = plan(path, set, limits, kind);
    for (int e = 0; e < 3; ++e) {
      const double t = rnd.uniform(0.0, traj.duration() * 1.05);
      const Trajectory next = traj.stopped()      ? traj.resumed_at(t)
                              : rnd.integer(0, 1) ? traj.stopped_at(t)
                                                  : traj.with_override(t, rnd.uniform(0.1, 2.0));
      for (int k = 0; k < 4; ++k) {
        const double before = rnd.uniform(0.0, std::min(t, traj.duration()));
        const TrajectorySample a = traj.sample(before), b = next.sample(before);
        ASSERT_TRUE(a.s == b.s && a.s_dot == b.s_dot && a.pose.matrix() == b.pose.matrix())
            << "events, case " << i << " event " << e << " at " << t << ": changed at " << before;
      }
      traj = next;
      const double ratio = testing::worst_speed_ratio_at_random_times(traj, set, v, 32, rnd);
      worst = std::max(worst, ratio);
      ASSERT_LE(ratio, 1.0 + 1e-6) << "events, case " << i << " event " << e;
      for (int k = 0; k < 8; ++k) {
        const TrajectorySample x = traj.sample(rnd.uniform(0.0, traj.duration()));
        ASSERT_LE(std::abs(x.s_ddot), limits.acceleration * (1.0 + 1e-9)) << "events, case " << i << " event " << e;
        ASSERT_GE(x.s_dot, -1e-12 * v) << "events, case " << i << " event " << e;
      }
      const TrajectorySample end = traj.sample(traj.duration());
      Posed expected;
      Twistd twist;
      traj.path_state(traj.end_position(), expected, twist);
      ASSERT_TRUE(end.pose.is_approx(traj.stopped() ? expected : path.end(), 1e-9))
          << "events, case " << i << " event " << e;
      ASSERT_LE(std::abs(end.s_dot), 1e-9 * v) << "events, case " << i << " event " << e;
    }
  }
  record("guarantee_with_events", n, worst);
}

// Where the request that made `after` from `before` takes over (changed_from): the motion before
// it is the same, bit for bit, at `probes`; there both give the same pose and body twist, to
// rounding (a join plans the path ahead afresh, its s in other units, doc/events.md eq. 7).
void expect_continuous_handover(const MotionStream& before, const MotionStream& after,
                                const std::vector<double>& probes, const std::string& what) {
  const double from = after.changed_from();
  for (const double t : probes) {
    if (t >= from) continue;
    const TrajectorySample a = before.sample(t), b = after.sample(t);
    ASSERT_TRUE(a.s == b.s && a.pose.matrix() == b.pose.matrix() && a.body_twist.vector() == b.body_twist.vector())
        << what << ": changed at " << t << ", before " << from;
  }
  if (!std::isfinite(from)) return;
  const TrajectorySample a = before.sample(from), b = after.sample(from);
  ASSERT_TRUE(b.pose.is_approx(a.pose, 1e-9)) << what << ": the pose jumps at " << from;
  ASSERT_LE((b.body_twist.vector() - a.body_twist.vector()).norm(), 1e-6 * std::max(1.0, a.body_twist.vector().norm()))
      << what << ": the velocity jumps at " << from << " (" << a.body_twist.vector().transpose() << " → "
      << b.body_twist.vector().transpose() << ")";
}

// Streams (doc/events.md §5): random LIN moves appended at random times — in time or late —
// with stops, resumptions and overrides between them; after each request the motion before it is
// the same bit for bit, and the whole stream keeps the point-set limit and ends at rest at the
// last pose. A twentieth of the count: a case plans its leg again at every append.
TEST(Sweep, StreamsWithRandomRequests) {
  Random rnd(9109);
  const int n = std::max(20, sweep_count() / 20);
  double worst = 0.0;
  for (int i = 0; i < n; ++i) {
    const double v = rnd.uniform(0.05, 1.0);
    const MetricSetd set = testing::random_set(rnd, v);
    const ProfileKind kind = rnd.integer(0, 1) ? ProfileKind::scurve : ProfileKind::trapezoid;
    const Limits limits = testing::random_limits(rnd, v, kind);
    MotionStream stream(set, limits, kind, rnd.integer(0, 2) ? rnd.uniform(1e-4, 1e-2) : 0.0);
    Posed last = rnd.pose(0.5);
    double t = 0.0;
    for (int r = 0; r < 8; ++r) {
      const bool moving = stream.leg_count() > 0;  // before the first move the samples are defaults
      const double probe = rnd.uniform(0.0, t);
      const TrajectorySample at_probe = stream.sample(probe);
      const MotionStream before = stream;  // a value: copying shares its trajectories
      const int what = stream.stopped() ? 3 : rnd.integer(0, 5);
      if (what <= 3 && !stream.stopped()) {
        const Posed next = rnd.nearby(last, rnd.uniform(0.01, 0.3), rnd.uniform(0.0, 0.5));
        stream.append(Path::lin(last, next), t);
        last = next;
      } else if (what == 3) {
        stream.resume(t);
      } else if (what == 4 && stream.leg_count() > 0) {
        stream.stop(t);
      } else {
        stream.set_override(t, rnd.uniform(0.2, 1.5));
      }
      const TrajectorySample again = stream.sample(probe);
      ASSERT_TRUE(!moving || (again.s == at_probe.s && again.pose.matrix() == at_probe.pose.matrix()))
          << "stream " << i << " request " << r << " (" << what << ") at " << t << ": changed at " << probe;
      // Where the request takes over, the pose and its velocity go on (to rounding: a join
      // plans the path ahead afresh, its s in other units, doc/events.md eq. 7).
      if (moving) {
        std::vector<double> probes{t};
        for (int k = 0; k < 16; ++k) probes.push_back(rnd.uniform(0.0, before.duration()));
        expect_continuous_handover(before, stream, probes,
                                   "stream " + std::to_string(i) + " request " + std::to_string(r));
      }
      t += rnd.uniform(0.0, 1.2) * std::max(stream.duration() - t, 0.05);
    }
    if (stream.stopped()) stream.resume(t);
    const double ratio = testing::worst_speed_ratio_at_random_times(stream, set, v, 64, rnd);
    worst = std::max(worst, ratio);
    ASSERT_LE(ratio, 1.0 + 1e-6) << "stream " << i;
    ASSERT_TRUE(stream.sample(stream.duration()).pose.is_approx(last, 1e-9)) << "stream " << i;
  }
  record("streams_with_random_requests", n, worst);
}

TEST(Sweep, GuaranteeDecoupledLin) { guarantee_sweep(0, 9100); }
TEST(Sweep, GuaranteeScrewLin) { guarantee_sweep(1, 9101); }
TEST(Sweep, GuaranteeCirc) { guarantee_sweep(2, 9102, 3, 96); }
TEST(Sweep, GuaranteeChainWithACorner) { guarantee_sweep(3, 9103); }
TEST(Sweep, GuaranteeSpline) { guarantee_sweep(4, 9104, 3, 96); }
TEST(Sweep, GuaranteeBlendedChain) { guarantee_sweep(5, 9105, 3, 96); }

// Profiles: the final state is reached and no limit is exceeded at the phase ends or at random
// instants; rest to rest over S from 1e-6 to 10 and limits over three decades each.
void profile_sweep(ProfileKind kind, unsigned long salt) {
  Random rnd(salt);
  const int n = sweep_count();
  double worst = 0.0;  // largest excess over a limit, relative
  for (int i = 0; i < n; ++i) {
    const double distance = std::pow(10.0, rnd.uniform(-6.0, 1.0));
    const double v = std::pow(10.0, rnd.uniform(-2.0, 1.0)), a = std::pow(10.0, rnd.uniform(-2.0, 1.0));
    const double j = std::pow(10.0, rnd.uniform(-1.0, 2.0));
    const Profile law =
        kind == ProfileKind::scurve ? Profile::scurve(distance, v, a, j) : Profile::trapezoid(distance, v, a);
    const ProfileState end = law.state_at(law.duration());
    ASSERT_NEAR(end.s, distance, 1e-9 * std::max(1.0, distance)) << "case " << i;
    ASSERT_NEAR(end.v, 0.0, 1e-9 * v) << "case " << i;
    for (int k = 0; k < 8; ++k) {
      const ProfileState x = law.state_at(rnd.uniform(0.0, law.duration()));
      const double excess = std::max({x.v / v - 1.0, std::abs(x.a) / a - 1.0,
                                      kind == ProfileKind::scurve ? std::abs(x.j) / j - 1.0 : -1.0, -x.v / v});
      worst = std::max(worst, excess);
      ASSERT_LE(excess, 1e-12) << "case " << i << " t-sample " << k;
      ASSERT_GE(x.s, -1e-12 * distance) << "case " << i;
      ASSERT_LE(x.s, distance * (1 + 1e-12)) << "case " << i;
    }
  }
  record(kind == ProfileKind::scurve ? "profile_scurve" : "profile_trapezoid", n, worst);
}

TEST(Sweep, ProfileTrapezoid) { profile_sweep(ProfileKind::trapezoid, 9200); }
TEST(Sweep, ProfileScurve) { profile_sweep(ProfileKind::scurve, 9201); }

// Hexapod: leg lengths of a random reachable pose → forward kinematics from home → the pose
// again, to 1e-12 m in every leg (the solver's tolerance) and 1e-9 in the pose.
TEST(Sweep, HexapodInverseThenForward) {
  constexpr double pi = 3.14159265358979323846;
  const Hexapod h = Hexapod::symmetric(0.15, 20 * pi / 180, 0.10, 20 * pi / 180, 0.20, 0.15, 0.32, 0.01);
  Random rnd(9300);
  const int n = sweep_count();
  double worst = 0.0;
  for (int i = 0; i < n; ++i) {
    Posed pose;
    do {
      pose = h.home() * Posed::exp(Twistd(rnd.vector(0.04), rnd.unit_vector() * rnd.uniform(0.0, 0.25)));
    } while (!h.check(pose).reachable());
    const Hexapod::Legs legs = h.leg_lengths(pose);
    const Posed found = h.forward(legs);
    const double leg_error = (h.leg_lengths(found) - legs).cwiseAbs().maxCoeff();
    worst = std::max(worst, leg_error);
    ASSERT_LE(leg_error, 1e-12) << "case " << i;
    ASSERT_TRUE(found.is_approx(pose, 1e-9)) << "case " << i;
  }
  record("hexapod_round_trip_leg_error", n, worst);
}

#ifdef DISPKIN_HAS_SERIAL
using serial::JointTrajectory;
using serial::JointTrajectorySample;

// The guarantee for PTP moves (ptp.hpp) of one serial test arm: random joint lines inside its
// ranges, random sets and limits, both profiles, 32 random instants per case; the joint velocity
// limits and the exact end too. A PTP plan cuts about 10³ joint sections (each a forward
// kinematics and a set evaluation), some 100 times the work of a LIN plan: this family runs
// DISPKIN_SWEEP_COUNT / 100 cases (at least 10), 10³ in `make test`, 10⁵ in `make sweep`.
void ptp_sweep(const serial::SerialArm& arm, const std::string& name, unsigned long salt) {
  Random rnd(salt);
  const int n = std::max(10, sweep_count() / 100);
  const Eigen::VectorXd joint_speed = arm.joint_limits().velocity;
  double worst = 0.0;
  for (int i = 0; i < n; ++i) {
    const double v = rnd.uniform(0.05, 2.0);
    const MetricSetd set = testing::random_set(rnd, v);
    const JointPath move = testing::random_ptp(rnd, arm);
    const ProfileKind kind = rnd.integer(0, 1) ? ProfileKind::scurve : ProfileKind::trapezoid;
    const Limits limits = testing::random_limits(rnd, v, kind);
    const JointTrajectory traj = plan(move, set, limits, kind, arm);
    const double ratio = testing::worst_speed_ratio_at_random_times(traj, set, v, 32, rnd);
    worst = std::max(worst, ratio);
    ASSERT_LE(ratio, 1.0 + 1e-6) << name << " case " << i;
    const JointTrajectorySample s = traj.sample(rnd.uniform(0.0, traj.duration()));
    ASSERT_LE((s.qd.cwiseAbs().array() / joint_speed.array()).maxCoeff(), 1.0 + 1e-9) << name << " case " << i;
    ASSERT_EQ(Eigen::VectorXd(traj.sample(traj.duration()).q), move.end()) << name << " case " << i;
  }
  record("ptp_guarantee_" + name, n, worst);
}

TEST(Sweep, PtpGuaranteeUr5e) { ptp_sweep(testing::ur5e_arm(), "ur5e", 9400); }
TEST(Sweep, PtpGuaranteeKr6) { ptp_sweep(testing::kr6_arm(), "kr6", 9401); }
#endif

}  // namespace
}  // namespace dispkin
