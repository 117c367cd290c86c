// Joint-limit prediction and the re-timing loop of the KUKA re-timing patent ("The robot drives
// through a preset working track") on a UR5e (doc/retiming.md §1–3).
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include <dispkin/hexapod/hexapod_retiming.hpp>
#include <dispkin/serial/serial_retiming.hpp>
#include <dispkin/shapes.hpp>

#include "random_cases.hpp"
#include "retiming_moves.hpp"

namespace dispkin {
namespace {

using testing::message_of;
using testing::runtime_message_of;
using V = Eigen::Vector3d;

using testing::lin_move;
using testing::Move;
using testing::tool;
using testing::ur5e;

// The check's joint velocities are the derivatives of its joint positions (and q follows the
// branch of q_start continuously).
TEST(Retiming, JointVelocitiesAreTheDerivativeOfTheJointPath) {
  const serial::SerialArm arm = ur5e();
  const Move m = lin_move(arm);
  const Trajectory traj = plan(m.path, tool(), Limits{0.2, 1.0, 10.0});
  JointCheckOptions options;
  options.samples_between = 40;
  const JointLimitReport r = check_joint_limits(traj, arm, m.q_start, options);
  ASSERT_LE((r.samples.front().q - m.q_start).norm(), 1e-9);
  for (std::size_t k = 1; k + 1 < r.samples.size(); ++k) {
    const JointSample &a = r.samples[k - 1], &b = r.samples[k + 1];
    if (b.time - a.time > 0.05) continue;
    const Eigen::VectorXd numeric = (b.q - a.q) / (b.time - a.time);
    ASSERT_LE((numeric - r.samples[k].qd).norm(), 2e-2 * (1 + numeric.norm())) << "t = " << r.samples[k].time;
  }
}

// Its joint accelerations (in closed form away from the steps of the time law, doc/retiming.md
// (doc/retiming.md eq. 27), by differences at them) are the derivatives of its joint velocities.
TEST(Retiming, JointAccelerationsAreTheDerivativeOfTheJointVelocities) {
  const serial::SerialArm arm = ur5e();
  const Move m = lin_move(arm);
  for (const ProfileKind profile : {ProfileKind::scurve, ProfileKind::trapezoid}) {
    const Limits limits{0.2, 1.0, profile == ProfileKind::scurve ? std::optional<double>(10.0) : std::nullopt};
    const Trajectory traj = plan(m.path, tool(), limits, profile);
    JointCheckOptions options;
    options.samples_between = 40;
    const JointLimitReport r = check_joint_limits(traj, arm, m.q_start, options);
    const std::vector<double> marks = traj.characteristic_times();
    int compared = 0;
    for (std::size_t k = 1; k + 1 < r.samples.size(); ++k) {
      const JointSample &a = r.samples[k - 1], &b = r.samples[k + 1];
      // Only where no step of the acceleration lies between the neighbours: a phase boundary
      // of the time law or a section junction (a rotating LIN is cut into sections).
      const auto step = std::lower_bound(marks.begin(), marks.end(), a.time);
      if (step != marks.end() && *step <= b.time) continue;
      const SampledPath& sections = traj.path();
      if (sections.section_at(a.s, sections.section_count()) != sections.section_at(b.s, sections.section_count()))
        continue;
      const Eigen::VectorXd numeric = (b.qd - a.qd) / (b.time - a.time);
      ASSERT_LE((numeric - r.samples[k].qdd).norm(), 2e-2 * (1 + numeric.norm())) << "t = " << r.samples[k].time;
      ++compared;
    }
    EXPECT_GT(compared, 100);
  }
}

// The check's torques are the arm's at its q, q̇, q̈ bit for bit (at most instants they come from
// the pass that gave the body Jacobian, doc/retiming.md §8).
TEST(Retiming, CheckedTorquesAreTheArmsTorques) {
  const serial::SerialArm arm = ur5e();
  const Move m = lin_move(arm);
  const JointLimitReport r =
      check_joint_limits(plan(m.path, tool(), Limits{0.5, 4.0, std::nullopt}, ProfileKind::trapezoid), arm, m.q_start);
  ASSERT_GT(r.samples.size(), 20u);
  for (const JointSample& sample : r.samples) {
    EXPECT_EQ(sample.static_torque, arm.static_torques(sample.q)) << "t = " << sample.time;
    const Eigen::VectorXd dynamic = arm.torques(sample.q, sample.qd, sample.qdd) - arm.static_torques(sample.q);
    EXPECT_EQ(sample.dynamic_torque, dynamic) << "t = " << sample.time;
  }
}

// A move that starts where the UR5e's wrist is singular (q₅ = 0: axes 4 and 6 aligned) is an
// error naming the place, not joint speeds from a near-singular solve.
TEST(Retiming, SingularJacobianIsAnErrorNamingThePlace) {
  const serial::SerialArm arm = ur5e();
  Eigen::VectorXd q(6);
  q << 0.3, -1.2, 1.5, -1.9, 0.0, 0.2;
  const Posed a = arm.forward(q);
  const Path path = Path::lin(a, Posed(a.quaternion(), a.translation() + V(0.05, 0.02, 0.0)));
  const std::string message = runtime_message_of([&] {
    check_joint_limits(plan(path, tool(), Limits{0.2, 1.0, 10.0}), arm, q);
  });
  EXPECT_NE(message.find("singular"), std::string::npos) << message;
  EXPECT_NE(message.find("t = 0"), std::string::npos) << message;
}

// Dense re-check of a re-timed trajectory: 400 samples between characteristic points.
JointLimitReport dense(const Trajectory& traj, const serial::SerialArm& arm, const Eigen::VectorXd& q) {
  JointCheckOptions options;
  options.samples_between = 400;
  return check_joint_limits(traj, arm, q, options);
}

TEST(Retiming, ScalingConvergesAndKeepsTheLimitsDensely) {
  const serial::SerialArm arm = ur5e();
  const Move m = lin_move(arm);
  const MetricSetd set = tool();
  // One move held back by a joint speed, one by a joint torque.
  for (const Limits& fast : {Limits{6.0, 100.0, 4000.0}, Limits{1.5, 400.0, 1e5}}) {
    const JointLimitReport before = check_joint_limits(plan(m.path, set, fast), arm, m.q_start);
    ASSERT_GT(std::max(before.velocity_factor, before.acceleration_factor), 1.5) << "the test move must overrun";
    const RetimeResult r = retime_by_scaling(m.path, set, fast, ProfileKind::scurve, arm, m.q_start);
    EXPECT_TRUE(r.report.within_limits());
    EXPECT_GE(r.iterations, 2);
    EXPECT_LT(r.limits.velocity, fast.velocity + 1e-12);
    const JointLimitReport check = dense(r.trajectory, arm, m.q_start);
    std::printf("FVEL %.4f -> %.4f (dense %.4f), FACC %.4f -> %.4f (dense %.4f), %d plans, %.3f s -> %.3f s\n",
                before.velocity_factor, r.report.velocity_factor, check.velocity_factor, before.acceleration_factor,
                r.report.acceleration_factor, check.acceleration_factor, r.iterations,
                plan(m.path, set, fast).duration(), r.trajectory.duration());
    EXPECT_LE(check.velocity_factor, 1.0 + 1e-3);
    EXPECT_LE(check.acceleration_factor, 1.0 + 1e-2);
    // One of the two binds: the scaled move is not needlessly slow.
    EXPECT_GT(std::max(r.report.velocity_factor, r.report.acceleration_factor), 0.98);
  }
}

TEST(Retiming, AlreadyFeasibleMovesAreLeftAlone) {
  const serial::SerialArm arm = ur5e();
  const Move m = lin_move(arm);
  const Limits slow{0.05, 0.2, 2.0};
  const RetimeResult r = retime_by_scaling(m.path, tool(), slow, ProfileKind::scurve, arm, m.q_start);
  EXPECT_EQ(r.iterations, 1);
  EXPECT_EQ(r.limits.velocity, slow.velocity);
}

TEST(Retiming, BadInputAndImpossibleMovesAreNamed) {
  const serial::SerialArm arm = ur5e();
  const Move m = lin_move(arm);
  const Trajectory traj = plan(m.path, tool(), Limits{0.2, 1.0, 10.0});
  JointCheckOptions bad;
  bad.samples_between = -1;
  EXPECT_NE(message_of([&] { check_joint_limits(traj, arm, m.q_start, bad); }).find("samples_between = -1"),
            std::string::npos);
  EXPECT_NE(message_of([&] { check_joint_limits(traj, arm, Eigen::VectorXd::Zero(5)); }).find("q_start size = 5"),
            std::string::npos);
  EXPECT_NE(message_of([&] {
              retime_by_scaling(m.path, tool(), Limits{0.2, 1.0, 10.0}, ProfileKind::scurve, arm, m.q_start, {}, 0);
            }).find("max_iterations = 0"),
            std::string::npos);
  // Out of reach: a LIN that leaves the workspace.
  const Posed a = arm.forward(m.q_start);
  const Path away = Path::lin(a, Posed(a.quaternion(), a.translation() + V(2.0, 0, 0)));
  EXPECT_NE(runtime_message_of([&] {
              check_joint_limits(plan(away, tool(), Limits{0.2, 1.0, 10.0}), arm, m.q_start);
            }).find("has no inverse-kinematics solution"),
            std::string::npos);
}

}  // namespace
}  // namespace dispkin
