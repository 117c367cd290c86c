// The overlapped velocity method for PTP moves (joint_overlap.hpp, doc/ptp.md eq. 16): the
// article's joint-space formula, continuity at the overlap's ends, the peak speed reported, bad input.
#include <algorithm>
#include <cstdio>

#include <gtest/gtest.h>

#include <dispkin/serial/joint_overlap.hpp>

#include "ptp_moves.hpp"
#include "random_cases.hpp"
#include "random_paths.hpp"

namespace dispkin {
namespace {

using serial::JointTrajectory;
using serial::JointTrajectorySample;
using serial::OverlappedJointTrajectory;
using serial::SerialArm;
using testing::message_of;
using testing::Random;

Limits limits_at(double v) { return Limits{v, 1.0, 20.0}; }

MetricSetd tool_set() {
  MetricSetd set;
  set.add_relative({Eigen::Vector3d(0.1, 0, 0), Eigen::Vector3d(0, 0.1, 0), Eigen::Vector3d(0, 0, 0.1)});
  return set;
}

// Two random PTP moves joined at a random via configuration, on the UR5e and the KR6.
struct TwoMoves {
  JointTrajectory before, after;
};
TwoMoves two_moves(Random& rnd, const SerialArm& arm) {
  const Eigen::VectorXd a = testing::random_joints(rnd, arm), via = testing::random_joints(rnd, arm),
                        b = testing::random_joints(rnd, arm);
  const MetricSetd set = tool_set();
  return {plan(JointPath(a, via), set, limits_at(0.5), ProfileKind::scurve, arm),
          plan(JointPath(via, b), set, limits_at(0.5), ProfileKind::scurve, arm)};
}

TEST(JointOverlap, IsTheArticlesJointSpaceFormula) {
  Random rnd(4201);
  double worst_ratio = 0.0;
  for (const SerialArm& arm : {testing::ur5e_arm(), testing::kr6_arm()}) {
    for (int c = 0; c < 10; ++c) {
      TwoMoves m = two_moves(rnd, arm);
      const double t_ov = rnd.uniform(0.0, 1.0) * std::min(m.before.duration(), m.after.duration());
      const OverlappedJointTrajectory o(m.before, m.after, t_ov);
      const Eigen::VectorXd via = m.after.start();
      const double begin = m.before.duration() - t_ov;
      ASSERT_NEAR(o.duration(), m.before.duration() + m.after.duration() - t_ov, 1e-12);
      for (int i = 0; i <= 200; ++i) {
        const double t = o.duration() * i / 200.0;
        const JointTrajectorySample s = o.sample(t);
        Eigen::VectorXd q = Eigen::VectorXd(m.before.sample(t).q), qd = Eigen::VectorXd(m.before.sample(t).qd);
        if (t > begin) {
          // θ(t) = θ_b(t) + θ_f(t + t_ov − T_b) − θ₂ (θ_b stays at θ₂ after its end).
          q += Eigen::VectorXd(m.after.sample(t - begin).q) - via;
          qd += Eigen::VectorXd(m.after.sample(t - begin).qd);
        }
        ASSERT_LE((Eigen::VectorXd(s.q) - q).cwiseAbs().maxCoeff(), 1e-12) << "t = " << t;
        ASSERT_LE((Eigen::VectorXd(s.qd) - qd).cwiseAbs().maxCoeff(), 1e-12) << "t = " << t;
        ASSERT_TRUE(s.pose.is_approx(arm.forward(Eigen::VectorXd(s.q)), 1e-12));
      }
      // Continuity of θ and θ̇ at both ends of the overlap.
      for (const double edge : {begin, m.before.duration()}) {
        const JointTrajectorySample l = o.sample(edge - 1e-9), r = o.sample(edge + 1e-9);
        ASSERT_LE((Eigen::VectorXd(l.q) - Eigen::VectorXd(r.q)).cwiseAbs().maxCoeff(), 1e-7);
        ASSERT_LE((Eigen::VectorXd(l.qd) - Eigen::VectorXd(r.qd)).cwiseAbs().maxCoeff(), 1e-6);
      }
      ASSERT_EQ(Eigen::VectorXd(o.sample(o.duration()).q), m.after.end());
      // No guarantee is claimed; the peak point speed is what a user checks.
      worst_ratio = std::max(worst_ratio, testing::worst_speed_ratio(o, tool_set(), 0.5, 2000));
    }
  }
  std::printf("overlapped PTP moves: peak point speed / limit %.4g\n", worst_ratio);
}

TEST(JointOverlap, BadInputIsRefused) {
  Random rnd(4202);
  const SerialArm arm = testing::ur5e_arm();
  TwoMoves m = two_moves(rnd, arm);
  EXPECT_NE(message_of([&] { OverlappedJointTrajectory(m.before, m.after, -0.1); }).find("overlap = -0.1"),
            std::string::npos);
  EXPECT_NE(message_of([&] { OverlappedJointTrajectory(m.before, m.after, 1e6); }).find("overlap"), std::string::npos);
  EXPECT_NE(message_of([&] { OverlappedJointTrajectory(m.before, m.after, std::nan("")); }).find("overlap = nan"),
            std::string::npos);
  EXPECT_NE(message_of([&] { OverlappedJointTrajectory(m.after, m.after, 0.1); }).find("must start where"),
            std::string::npos);
  const SerialArm other = testing::kr6_arm();
  const JointTrajectory elsewhere = plan(JointPath(m.before.end(), testing::random_joints(rnd, other)), tool_set(),
                                         limits_at(0.5), ProfileKind::scurve, other);
  EXPECT_NE(message_of([&] { OverlappedJointTrajectory(m.before, elsewhere, 0.1); }).find("same arm"),
            std::string::npos);
}

}  // namespace
}  // namespace dispkin
