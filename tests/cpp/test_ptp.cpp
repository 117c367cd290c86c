// PTP moves under the DISP limit (ptp.hpp): the section bound against dense sampling, the guarantee
// (doc/planning.md eqs. 5, 25) by finite differences of every point and sphere over random moves
// and sets on two arms, tightness, joint limits, exact ends, bad input.
#include <cmath>
#include <limits>
#include <string>

#include <gtest/gtest.h>

#include "dispkin/serial/chain_kinematics.hpp"
#include "dispkin/serial/ptp.hpp"
#include "dispkin/serial/serial_arm.hpp"
#include "ptp_moves.hpp"
#include "ptp_section.hpp"
#include "random_paths.hpp"

namespace dispkin {
namespace {

using serial::JointSection;
using serial::JointTrajectory;
using serial::JointTrajectorySample;
using serial::PtpOptions;
using serial::SerialArm;
using testing::Random;
using testing::random_set;
using testing::worst_speed_ratio;

Limits scurve_limits(double v) { return Limits{v, 4.0 * v, 40.0 * v}; }

// The weighted fastest speed of the set per unit τ of `section`, densely at `count` points (exact
// body twist from the arm's Jacobian).
double dense_section_maximum(const SerialArm& arm, const JointTrajectory& traj, const JointSection& section,
                             const MetricSetd& set, double v_sys, int count) {
  const Eigen::VectorXd delta = traj.end() - traj.start();
  double best = 0.0;
  for (int i = 0; i <= count; ++i) {
    const double u = section.u0 + (section.u1 - section.u0) * i / count;
    const Eigen::VectorXd q = traj.start() + u * delta;
    const Twistd twist(Eigen::Matrix<double, 6, 1>(arm.body_jacobian(q) * delta * (section.u1 - section.u0)));
    best = std::max(best, max_point_speed(set, arm.forward(q), twist, v_sys));
  }
  return best;
}

TEST(Ptp, ChainPoseAndTwistMatchTheArm) {
  Random rnd(801);
  for (const SerialArm& arm : {testing::ur5e_arm(), testing::kr6_arm()}) {
    for (int c = 0; c < 50; ++c) {
      const Eigen::VectorXd q = testing::random_joints(rnd, arm), qd = Eigen::VectorXd::Random(arm.dof());
      Posed pose;
      Twistd twist;
      serial::chain_pose_and_twist(arm.chain(), q.data(), qd.data(), pose, twist);
      EXPECT_TRUE(pose.is_approx(arm.forward(q), 1e-12));
      EXPECT_LT((twist.vector() - arm.body_jacobian(q) * qd).norm(), 1e-12);
    }
  }
}

// The section bound is never below the dense maximum of the weighted speeds, and within the
// (default) tolerance of it where the section moves at more than 2 % of the move's pace; no
// section needs the smallest span 2⁻¹⁶ (where the cutting would stop short of the tolerance).
TEST(Ptp, SectionBoundNeverBelowDenseMaximumAndTight) {
  Random rnd(802);
  const double v = 0.5;
  int checked_tight = 0;
  for (const SerialArm& arm : {testing::ur5e_arm(), testing::kr6_arm()}) {
    for (int c = 0; c < 20; ++c) {
      const MetricSetd set = random_set(rnd, v);
      const JointTrajectory traj = plan(testing::random_ptp(rnd, arm), set, scurve_limits(v), ProfileKind::scurve, arm);
      double pace = 0.0;
      for (const JointSection& s : traj.sections()) pace = std::max(pace, s.middle_speed / (s.u1 - s.u0));
      for (std::size_t k = 0; k < traj.sections().size(); k += 1 + traj.sections().size() / 40) {
        const JointSection& s = traj.sections()[k];
        const double dense = dense_section_maximum(arm, traj, s, set, v, 64);
        EXPECT_LE(dense, s.length * (1.0 + 1e-12)) << "case " << c << " section " << k;
        EXPECT_GT(s.u1 - s.u0, std::ldexp(1.0, -16))
            << "case " << c << " section " << k << ": cut down to the smallest span";
        if (s.middle_speed > 0.02 * pace * (s.u1 - s.u0)) {
          EXPECT_LE(s.length, dense * (1.0 + PtpOptions{}.tolerance + 1e-12))
              << "case " << c << " section " << k << " of " << traj.sections().size() << ", span " << s.u1 - s.u0
              << ", middle " << s.middle_speed << ", pace " << pace;
          ++checked_tight;
        }
      }
    }
  }
  EXPECT_GT(checked_tight, 500);
}

// The acceleration bound A (per τ²) of relative and absolute points against finite differences.
TEST(Ptp, AccelerationBoundHoldsForEveryPoint) {
  Random rnd(803);
  for (const SerialArm& arm : {testing::ur5e_arm(), testing::kr6_arm()}) {
    for (int c = 0; c < 40; ++c) {
      MetricSetd set;
      const Eigen::Vector3d r = rnd.vector(0.3), a = rnd.vector(1.0);
      set.add_relative({r, rnd.vector(0.3), rnd.vector(0.3)});
      set.add_absolute(a, 1);
      const JointPath move = testing::random_ptp(rnd, arm);
      const Eigen::VectorXd delta = move.end() - move.start();
      const double u0 = rnd.uniform(0.0, 0.9), u1 = u0 + rnd.uniform(0.01, 0.1);
      GroupFactors factors(set, 1.0);
      factors.use_pivot(Eigen::Vector3d::Zero());
      const JointSection s = serial::detail::joint_section_bounds(arm.chain(), move.start(), delta, u0, u1, factors);
      const double h = u1 - u0, dt = 1e-3;
      double worst = 0.0;
      for (int i = 1; i < 1000; ++i) {
        const auto pose_at = [&](double tau) { return arm.forward(move.start() + (u0 + h * tau) * delta); };
        const double tau = i / 1000.0;
        const Posed p0 = pose_at(tau - dt), p1 = pose_at(tau), p2 = pose_at(tau + dt);
        worst = std::max(worst, ((p2 * r) - 2.0 * (p1 * r) + (p0 * r)).norm() / (dt * dt));
        // The absolute point's apparent velocity V(a) = R (v + ω × b) changes at most at A:
        const auto apparent = [&](double t) {
          const Eigen::VectorXd q = move.start() + (u0 + h * t) * delta;
          const Posed pose = arm.forward(q);
          const Eigen::Matrix<double, 6, 1> xi = arm.body_jacobian(q) * delta * h;
          const Eigen::Vector3d b = pose.inverse() * a;
          return Eigen::Vector3d(pose.quaternion() * (xi.head<3>() + xi.tail<3>().cross(b)));
        };
        worst = std::max(worst, (apparent(tau + dt) - apparent(tau - dt)).norm() / (2.0 * dt));
      }
      EXPECT_LE(worst, s.acceleration * (1.0 + 1e-4) + 1e-9) << "case " << c;
    }
  }
}

// The guarantee's oracle (doc/planning.md eq. 25) by dense finite differences (10⁴ chords per
// trajectory) over random PTP moves and random sets (relative and absolute points and spheres,
// groups with their own limits), both profiles, on the UR5e and the KR6-like arm: 2 × 500 cases.
class PtpGuarantee : public ::testing::TestWithParam<int> {};

TEST_P(PtpGuarantee, NoPointOrSphereExceedsItsLimit) {
  const int arm_index = GetParam();
  const SerialArm arm = arm_index == 0 ? testing::ur5e_arm() : testing::kr6_arm();
  Random rnd(810 + static_cast<unsigned long>(arm_index));
  double worst = 0.0;
  for (int c = 0; c < 500; ++c) {
    const double v = rnd.uniform(0.05, 2.0);
    const MetricSetd set = random_set(rnd, v);
    const JointPath move = testing::random_ptp(rnd, arm);
    const bool scurve = rnd.integer(0, 1);
    const Limits limits = scurve ? scurve_limits(v) : Limits{v, 4.0 * v, std::nullopt};
    const JointTrajectory traj = plan(move, set, limits, scurve ? ProfileKind::scurve : ProfileKind::trapezoid, arm);
    const double ratio = worst_speed_ratio(traj, set, v, 10000);
    EXPECT_LE(ratio, 1.0 + 1e-6) << "case " << c;
    worst = std::max(worst, ratio);
  }
  RecordProperty("worst_ratio", std::to_string(worst));
}

INSTANTIATE_TEST_SUITE_P(Arms, PtpGuarantee, ::testing::Values(0, 1));

// Tightness: in a long cruise the fastest point reaches at least 99 % of v_sys.
TEST(Ptp, FastestPointReachesTheLimitInALongCruise) {
  const SerialArm arm = testing::ur5e_arm().with_joint_limits([&] {
    JointLimits l = testing::ur5e_arm().joint_limits();
    l.velocity.setConstant(std::numeric_limits<double>::infinity());
    return l;
  }());
  MetricSetd set;
  set.add_relative({Eigen::Vector3d(0.1, 0, 0), Eigen::Vector3d(0, 0.1, 0), Eigen::Vector3d(0, 0, 0.2)});
  Eigen::VectorXd q_a(6), q_b(6);
  q_a << 0.0, -1.2, 1.4, -1.5, -1.57, 0.0;
  q_b << 2.5, -0.8, 0.9, -1.0, -1.2, 1.0;
  const double v = 0.2;
  const JointTrajectory traj = plan(JointPath(q_a, q_b), set, Limits{v, 50.0, 500.0}, ProfileKind::scurve, arm);
  double fastest = 0.0;
  for (int i = 0; i <= 4000; ++i) {
    const JointTrajectorySample s = traj.sample(traj.duration() * i / 4000.0);
    fastest = std::max(fastest, max_point_speed(set, s.pose, s.body_twist));
  }
  EXPECT_GE(fastest, 0.99 * v);
  EXPECT_LE(fastest, v * (1.0 + 1e-9));
}

// Joint velocity (and acceleration) limits hold, bind (a synchronized move reaches at least
// 95 % of the binding joint's limit: the 5 % staircase), q̇ is continuous and the derivative of q.
TEST(Ptp, JointLimitsHoldAndBind) {
  Random rnd(820);
  for (const SerialArm& base : {testing::ur5e_arm(), testing::kr6_arm()}) {
    JointLimits l = base.joint_limits();
    l.velocity.setConstant(0.3);
    const SerialArm arm = base.with_joint_limits(l);
    PtpOptions options;
    options.joint_acceleration = Eigen::VectorXd::Constant(arm.dof(), 0.6);
    for (int c = 0; c < 20; ++c) {
      MetricSetd set;
      set.add_relative({Eigen::Vector3d(0.05, 0, 0), Eigen::Vector3d(0, 0.05, 0), Eigen::Vector3d(0, 0, 0.05)});
      // A move long enough to cruise: the largest joint travels at least 1.5 rad.
      JointPath move = testing::random_ptp(rnd, arm);
      while ((move.end() - move.start()).cwiseAbs().maxCoeff() < 1.5) move = testing::random_ptp(rnd, arm);
      const JointTrajectory traj = plan(move, set, Limits{5.0, 50.0, 500.0}, ProfileKind::scurve, arm, options);
      double velocity_ratio = 0.0, acceleration_ratio = 0.0;
      const int steps = 4000;
      const double dt = traj.duration() / steps;
      for (int i = 0; i <= steps; ++i) {
        const JointTrajectorySample s = traj.sample(i * dt);
        velocity_ratio = std::max(velocity_ratio, s.qd.cwiseAbs().maxCoeff() / 0.3);
        acceleration_ratio = std::max(acceleration_ratio, s.qdd.cwiseAbs().maxCoeff() / 0.6);
        // q̇ is continuous (du/ds is, across section junctions too): over δ = 10⁻⁷ s it changes by
        // at most δ q̈max (a step of 1 % of 0.3 rad/s would be 5·10⁴ times that).
        const double delta = 1e-7;
        const JointTrajectorySample next = traj.sample(i * dt + delta);
        EXPECT_LE((next.qd - s.qd).cwiseAbs().maxCoeff(), delta * 0.6 * (1.0 + 1e-6) + 1e-12)
            << "case " << c << " t " << i * dt;
        if (i > 0 && i < steps) {
          const JointTrajectorySample before = traj.sample((i - 0.5) * dt), after = traj.sample((i + 0.5) * dt);
          // q̇ is the derivative of q: the central difference over dt errs by at most dt q̈max / 2.
          EXPECT_LE((Eigen::VectorXd(after.q - before.q) / dt - Eigen::VectorXd(s.qd)).cwiseAbs().maxCoeff(),
                    0.5 * dt * 0.6 + 1e-9);
        }
      }
      // Across section junctions in particular: find when u passes u0 of every tenth section.
      for (std::size_t k = 1; k < traj.sections().size(); k += 1 + traj.sections().size() / 10) {
        const double u_k = traj.sections()[k].u0;
        double lo = 0.0, hi = traj.duration();
        for (int it = 0; it < 60; ++it) (traj.sample(0.5 * (lo + hi)).u < u_k ? lo : hi) = 0.5 * (lo + hi);
        const double delta = 1e-7;
        const JointTrajectorySample before = traj.sample(hi - delta), after = traj.sample(hi + delta);
        EXPECT_LE((after.qd - before.qd).cwiseAbs().maxCoeff(), 2.0 * delta * 0.6 * (1.0 + 1e-6) + 1e-12)
            << "case " << c << " junction " << k;
      }
      EXPECT_LE(velocity_ratio, 1.0 + 1e-9) << "case " << c;
      EXPECT_GE(velocity_ratio, 0.95) << "case " << c;
      EXPECT_LE(acceleration_ratio, 1.0 + 1e-9) << "case " << c;
    }
  }
}

TEST(Ptp, EndsAreReachedExactlyAtRest) {
  Random rnd(830);
  const SerialArm arm = testing::kr6_arm();
  for (int c = 0; c < 20; ++c) {
    const JointPath move = testing::random_ptp(rnd, arm);
    const JointTrajectory traj = plan(move, random_set(rnd, 0.5), scurve_limits(0.5), ProfileKind::scurve, arm);
    const JointTrajectorySample a = traj.sample(0.0), b = traj.sample(traj.duration()),
                                late = traj.sample(traj.duration() + 1.0);
    EXPECT_EQ(Eigen::VectorXd(a.q), move.start());
    EXPECT_EQ(Eigen::VectorXd(b.q), move.end());
    EXPECT_EQ(Eigen::VectorXd(late.q), move.end());
    EXPECT_EQ(a.qd.norm(), 0.0);
    EXPECT_EQ(b.qd.norm(), 0.0);
    EXPECT_TRUE(b.pose.is_approx(arm.forward(move.end()), 1e-12));
    EXPECT_DOUBLE_EQ(b.s, traj.length());
  }
}

// The sampled body twist is the derivative of the sampled pose.
TEST(Ptp, BodyTwistIsTheDerivativeOfThePose) {
  Random rnd(840);
  const SerialArm arm = testing::ur5e_arm();
  const JointTrajectory traj =
      plan(testing::random_ptp(rnd, arm), random_set(rnd, 0.5), scurve_limits(0.5), ProfileKind::scurve, arm);
  const double dt = traj.duration() * 1e-6;
  for (int i = 1; i < 100; ++i) {
    const double t = traj.duration() * i / 100.0;
    const JointTrajectorySample s = traj.sample(t);
    const Twistd fd = (traj.sample(t - dt).pose.inverse() * traj.sample(t + dt).pose).log() * (0.5 / dt);
    EXPECT_LT((fd.vector() - s.body_twist.vector()).norm(), 2e-2 * s.body_twist.vector().norm() + 1e-6) << i;
  }
}

TEST(Ptp, BadInputIsRefusedWithClearErrors) {
  const SerialArm arm = testing::ur5e_arm();
  MetricSetd set;
  set.add_relative({Eigen::Vector3d(0.1, 0, 0), Eigen::Vector3d(0, 0.1, 0), Eigen::Vector3d(0, 0, 0.1)});
  const Eigen::VectorXd q0 = Eigen::VectorXd::Zero(6), q1 = Eigen::VectorXd::Constant(6, 0.5);
  const Limits ok = scurve_limits(0.5);
  const auto throws_with = [&](auto&& call, const std::string& text) {
    try {
      call();
      ADD_FAILURE() << "no exception, expected one mentioning " << text;
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find(text), std::string::npos) << e.what();
    }
  };
  throws_with(
      [&] { plan(JointPath(Eigen::VectorXd::Zero(5), Eigen::VectorXd::Ones(5)), set, ok, ProfileKind::scurve, arm); },
      "q_a size");
  throws_with([&] { JointPath(q0, Eigen::VectorXd::Ones(5)); }, "q_end size");
  Eigen::VectorXd nan = q1;
  nan(2) = std::nan("");
  throws_with([&] { JointPath(q0, nan); }, "q_end");
  throws_with([&] { plan(JointPath(q0, q1), set, Limits{0.0, 1.0, 1.0}, ProfileKind::scurve, arm); }, "velocity");
  throws_with([&] { plan(JointPath(q0, q1), set, Limits{1.0, -1.0, 1.0}, ProfileKind::scurve, arm); }, "acceleration");
  throws_with([&] { plan(JointPath(q0, q1), set, Limits{1.0, 1.0, std::nullopt}, ProfileKind::scurve, arm); }, "jerk");
  throws_with([&] { plan(JointPath(q0, q0), set, ok, ProfileKind::scurve, arm); }, "equals q_a");
  Eigen::VectorXd outside = q1;
  outside(1) = 7.0;
  throws_with([&] { plan(JointPath(q0, outside), set, ok, ProfileKind::scurve, arm); }, "q_b[1]");
  throws_with([&] { plan(JointPath(outside, q0), set, ok, ProfileKind::scurve, arm); }, "position limits");
  PtpOptions bad_tolerance;
  bad_tolerance.tolerance = 0.0;
  throws_with([&] { plan(JointPath(q0, q1), set, ok, ProfileKind::scurve, arm, bad_tolerance); }, "tolerance");
  PtpOptions bad_acceleration;
  bad_acceleration.joint_acceleration = Eigen::VectorXd::Ones(3);
  throws_with([&] { plan(JointPath(q0, q1), set, ok, ProfileKind::scurve, arm, bad_acceleration); },
              "joint_acceleration size");
  bad_acceleration.joint_acceleration = Eigen::VectorXd::Ones(6);
  bad_acceleration.joint_acceleration(4) = 0.0;
  throws_with([&] { plan(JointPath(q0, q1), set, ok, ProfileKind::scurve, arm, bad_acceleration); },
              "joint_acceleration[4]");
  MetricSetd single;
  single.add_relative(Eigen::Vector3d(0.1, 0, 0));
  throws_with([&] { plan(JointPath(q0, q1), single, ok, ProfileKind::scurve, arm); }, "");
}

}  // namespace
}  // namespace dispkin
