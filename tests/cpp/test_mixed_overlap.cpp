// A Cartesian move as joint motion on the arm's IK branch (followed_trajectory.hpp, doc/ptp.md
// doc/ptp.md eqs. 17–20) and the overlapped velocity method for a PTP move and a Cartesian move
// (mixed_overlap.hpp, doc/ptp.md eq. 21): poses reproduced, the article's joint formula, continuity at the
// overlap's ends, the exact end, the peak speed reported, bad input.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>

#include <gtest/gtest.h>

#include <dispkin/planning/planner.hpp>
#include <dispkin/serial/chain_kinematics.hpp>
#include <dispkin/serial/mixed_overlap.hpp>

#include "ptp_moves.hpp"
#include "random_cases.hpp"
#include "random_paths.hpp"

namespace dispkin {
namespace {

using serial::FollowedTrajectory;
using serial::JointTrajectory;
using serial::JointTrajectorySample;
using serial::JointVector;
using serial::OverlappedMixedTrajectory;
using serial::SerialArm;
using testing::message_of;
using testing::Random;

Limits limits_at(double v) { return Limits{v, 1.0, 20.0}; }

MetricSetd tool_set() {
  MetricSetd set;
  set.add_relative({Eigen::Vector3d(0.1, 0, 0), Eigen::Vector3d(0, 0.1, 0), Eigen::Vector3d(0, 0, 0.1)});
  return set;
}

double largest(const Eigen::VectorXd& v) { return v.cwiseAbs().maxCoeff(); }
Eigen::VectorXd joints(const JointVector& v) { return Eigen::VectorXd(v); }

// A random configuration and a LIN from (ptp_first) or to its pose, 5–15 cm and up to 0.3 rad
// away; nullopt where the arm cannot follow it (a singular pose or a joint limit on the way:
// random cases meet them; the callers require most cases to be followed).
struct Case {
  JointTrajectory ptp;
  FollowedTrajectory lin;
};
std::optional<Case> random_case(Random& rnd, const SerialArm& arm, bool ptp_first) {
  const Eigen::VectorXd other = testing::random_joints(rnd, arm), via = testing::random_joints(rnd, arm);
  const Posed at_via = arm.forward(via);
  const Posed away = rnd.nearby(at_via, 0.15, 0.3);
  if ((away.translation() - at_via.translation()).norm() < 0.05) return std::nullopt;
  const Trajectory lin = ptp_first ? plan(Path::lin(at_via, away), tool_set(), limits_at(0.5))
                                   : plan(Path::lin(away, at_via), tool_set(), limits_at(0.5));
  try {
    if (ptp_first) {
      return Case{plan(JointPath(other, via), tool_set(), limits_at(0.5), ProfileKind::scurve, arm),
                  FollowedTrajectory::from_start(lin, arm, via)};
    }
    return Case{plan(JointPath(via, other), tool_set(), limits_at(0.5), ProfileKind::scurve, arm),
                FollowedTrajectory::to_end(lin, arm, via)};
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("trajectory = "), std::string::npos) << e.what();
    return std::nullopt;
  }
}

TEST(FollowedTrajectory, ReproducesTheCartesianPosesByForwardKinematics) {
  Random rnd(4301);
  double worst_pose = 0.0, worst_rate = 0.0, worst_midpoint = 0.0;
  std::size_t nodes = 0;
  for (const SerialArm& arm : {testing::ur5e_arm(), testing::kr6_arm()}) {
    for (const bool forward : {true, false}) {
      int followed = 0, tried = 0;
      while (followed < 6 && tried < 40) {
        ++tried;
        const std::optional<Case> c = random_case(rnd, arm, forward);
        if (!c) continue;
        ++followed;
        const FollowedTrajectory& f = c->lin;
        const Trajectory& cart = f.trajectory();
        worst_midpoint = std::max(worst_midpoint, f.midpoint_error());
        nodes = std::max(nodes, f.node_count());
        ASSERT_LE(f.midpoint_error(), FollowedTrajectory::midpoint_tolerance);
        // The given joints exactly at their end, and the other end on the trajectory's pose.
        if (forward) {
          ASSERT_EQ(joints(f.sample(0.0).q), c->ptp.end());
          ASSERT_EQ(joints(f.sample(-1.0).q), f.start());
        } else {
          ASSERT_EQ(joints(f.sample(f.duration()).q), c->ptp.start());
          ASSERT_EQ(joints(f.sample(f.duration() + 1.0).q), f.end());
        }
        ASSERT_TRUE(f.sample(f.duration()).pose.is_approx(arm.forward(f.end()), 1e-12));
        for (int i = 0; i <= 1500; ++i) {
          // Evenly spread times and random ones (between grid nodes).
          const double t = i <= 1000 ? f.duration() * i / 1000.0 : rnd.uniform(0.0, f.duration());
          const JointTrajectorySample s = f.sample(t);
          const TrajectorySample want = cart.sample(t);
          const Posed fk = arm.forward(joints(s.q));
          // The pose is the arm's forward kinematics of q, and that is the trajectory's pose.
          ASSERT_TRUE(s.pose.is_approx(fk, 1e-12));
          const double pose_error = std::max((fk.rotation() - want.pose.rotation()).cwiseAbs().maxCoeff(),
                                             (fk.translation() - want.pose.translation()).cwiseAbs().maxCoeff());
          ASSERT_LE(pose_error, 1e-9) << "t = " << t;
          worst_pose = std::max(worst_pose, pose_error);
          // q̇ is the trajectory's twist through the body Jacobian (doc/ptp.md eq. 19).
          const double rate_error = (s.body_twist.vector() - want.body_twist.vector()).cwiseAbs().maxCoeff();
          ASSERT_LE(rate_error, 1e-7) << "t = " << t;
          worst_rate = std::max(worst_rate, rate_error);
          ASSERT_EQ(s.s, want.s);
          ASSERT_EQ(s.s_dot, want.s_dot);
        }
        // q̇ and q̈ are the derivatives of q (central differences over 1e-5 s).
        for (int i = 1; i < 50; ++i) {
          const double t = f.duration() * i / 50.0, h = 1e-5;
          const JointTrajectorySample l = f.sample(t - h), m = f.sample(t), r = f.sample(t + h);
          ASSERT_LE(largest((joints(r.q) - joints(l.q)) / (2 * h) - joints(m.qd)), 1e-6) << "t = " << t;
          ASSERT_LE(largest((joints(r.qd) - joints(l.qd)) / (2 * h) - joints(m.qdd)),
                    1e-3 * (1.0 + largest(joints(m.qdd))))
              << "t = " << t;
        }
      }
      ASSERT_GE(followed, 6) << "too few random LINs were followable (" << tried << " tried)";
    }
  }
  std::printf("followed LINs: worst pose error %.3g, twist error %.3g, midpoint error %.3g rad, at most %zu nodes\n",
              worst_pose, worst_rate, worst_midpoint, nodes);
}

// θ(t) = θ_b(t) + θ_f(t − (T_b − t_ov)) − θ₂ during the overlap, each move alone outside it.
void check_overlap(const OverlappedMixedTrajectory& o, const SerialArm& arm, double& worst_ratio) {
  const bool ptp_first = o.ptp_first();
  const auto before = [&](double t) { return ptp_first ? o.ptp().sample(t) : o.cartesian().sample(t); };
  const auto after = [&](double t) { return ptp_first ? o.cartesian().sample(t) : o.ptp().sample(t); };
  const double t_b = ptp_first ? o.ptp().duration() : o.cartesian().duration();
  const double begin = o.overlap_start();
  const Eigen::VectorXd via = joints(after(0.0).q);
  ASSERT_EQ(via, joints(before(t_b).q));
  ASSERT_NEAR(o.duration(), o.ptp().duration() + o.cartesian().duration() - o.overlap(), 1e-12);
  for (int i = 0; i <= 400; ++i) {
    const double t = o.duration() * i / 400.0;
    const JointTrajectorySample s = o.sample(t);
    ASSERT_TRUE(s.pose.is_approx(arm.forward(joints(s.q)), 1e-12));
    if (i == 400) continue;  // the end: checked exactly below
    if (t <= begin || t >= t_b) {
      // One move alone: the PTP's joints exactly, the Cartesian move's poses by FK to 1e-9.
      const bool first = t <= begin;
      const JointTrajectorySample own = first ? before(t) : after(t - begin);
      const bool is_ptp = first == ptp_first;
      if (is_ptp) {
        ASSERT_EQ(joints(s.q), joints(own.q)) << "t = " << t;
      } else {
        const double local = first ? t : t - begin;
        ASSERT_TRUE(arm.forward(joints(s.q)).is_approx(o.cartesian().trajectory().sample(local).pose, 1e-9))
            << "t = " << t;
      }
      continue;
    }
    const JointTrajectorySample b = before(t), f = after(t - begin);
    ASSERT_LE(largest(joints(s.q) - (joints(b.q) + joints(f.q) - via)), 1e-12) << "t = " << t;
    ASSERT_LE(largest(joints(s.qd) - (joints(b.qd) + joints(f.qd))), 1e-12) << "t = " << t;
    ASSERT_LE(largest(joints(s.qdd) - (joints(b.qdd) + joints(f.qdd))), 1e-12) << "t = " << t;
  }
  // Continuity of θ and θ̇ at both ends of the overlap.
  for (const double edge : {begin, t_b}) {
    const JointTrajectorySample l = o.sample(edge - 1e-9), r = o.sample(edge + 1e-9);
    ASSERT_LE(largest(joints(l.q) - joints(r.q)), 1e-7);
    ASSERT_LE(largest(joints(l.qd) - joints(r.qd)), 1e-6);
  }
  // The end reached exactly.
  const Eigen::VectorXd end = ptp_first ? o.cartesian().end() : o.ptp().end();
  ASSERT_EQ(joints(o.sample(o.duration()).q), end);
  ASSERT_EQ(joints(o.sample(o.duration() + 1.0).q), end);
  ASSERT_EQ(joints(o.sample(0.0).q), joints(before(0.0).q));
  worst_ratio = std::max(worst_ratio, testing::worst_speed_ratio(o, tool_set(), 0.5, 2000));
}

TEST(MixedOverlap, IsTheArticlesJointSpaceFormula) {
  Random rnd(4302);
  for (const bool ptp_first : {true, false}) {
    double worst_ratio = 0.0;
    for (const SerialArm& arm : {testing::ur5e_arm(), testing::kr6_arm()}) {
      int followed = 0, tried = 0;
      while (followed < 5 && tried < 40) {
        ++tried;
        const std::optional<Case> c = random_case(rnd, arm, ptp_first);
        if (!c) continue;
        ++followed;
        const double shorter = std::min(c->ptp.duration(), c->lin.duration());
        for (const double share : {0.0, rnd.uniform(0.0, 1.0), 1.0}) {
          const OverlappedMixedTrajectory o = ptp_first ? OverlappedMixedTrajectory(c->ptp, c->lin, share * shorter)
                                                        : OverlappedMixedTrajectory(c->lin, c->ptp, share * shorter);
          ASSERT_EQ(o.ptp_first(), ptp_first);
          check_overlap(o, arm, worst_ratio);
        }
      }
      ASSERT_GE(followed, 5);
    }
    // No guarantee is claimed; the peak point speed is what a user checks.
    std::printf("overlapped %s: peak point speed / limit %.4g\n", ptp_first ? "PTP -> LIN" : "LIN -> PTP", worst_ratio);
  }
}

TEST(MixedOverlap, BadInputIsRefused) {
  const SerialArm ur = testing::ur5e_arm(), kr = testing::kr6_arm();
  Eigen::VectorXd q(6), other(6);
  q << 0.3, -1.2, 1.4, -1.6, -1.3, 0.4;
  other << 1.0, -1.0, 1.0, -1.0, -1.0, 1.0;
  const Posed at_q = ur.forward(q);
  const Posed away = at_q * Posed(Eigen::Quaterniond::Identity(), Eigen::Vector3d(0.05, 0.03, 0.02));
  const Trajectory lin = plan(Path::lin(at_q, away), tool_set(), limits_at(0.5));
  const FollowedTrajectory followed = FollowedTrajectory::from_start(lin, ur, q);
  const JointTrajectory ptp = plan(JointPath(other, q), tool_set(), limits_at(0.5), ProfileKind::scurve, ur);

  // The trajectory does not start (end) where the joints given put the tip.
  EXPECT_NE(message_of([&] { FollowedTrajectory::from_start(lin, ur, other); }).find("q_start = "), std::string::npos);
  EXPECT_NE(message_of([&] { FollowedTrajectory::to_end(lin, ur, q); }).find("q_end = "), std::string::npos);
  EXPECT_NE(message_of([&] { FollowedTrajectory::from_start(lin, ur, Eigen::VectorXd::Zero(5)); }).find("q_start = 5"),
            std::string::npos);
  EXPECT_NE(message_of([&] { FollowedTrajectory::from_start(lin, ur, q, 0.0); }).find("spacing = 0"),
            std::string::npos);
  EXPECT_NE(message_of([&] { FollowedTrajectory::from_start(lin, ur, q, 1e-9); }).find("spacing = 1e-09"),
            std::string::npos);
  EXPECT_NE(message_of([&] { FollowedTrajectory::from_start(lin, ur, q, std::nan("")); }).find("spacing = nan"),
            std::string::npos);
  // Out of reach on the way: a LIN 3 m long.
  const Posed far = at_q * Posed(Eigen::Quaterniond::Identity(), Eigen::Vector3d(3.0, 0.0, 0.0));
  const std::string out_of_reach = message_of(
      [&] { FollowedTrajectory::from_start(plan(Path::lin(at_q, far), tool_set(), limits_at(0.5)), ur, q); });
  EXPECT_NE(out_of_reach.find("trajectory = "), std::string::npos) << out_of_reach;
  EXPECT_NE(out_of_reach.find("no inverse-kinematics solution"), std::string::npos) << out_of_reach;
  // A joint limit on the way: the same LIN on an arm whose joint 1 may barely move.
  JointLimits tight = ur.joint_limits();
  tight.lower(0) = q(0) - 1e-3;  // joint 1 turns when the tip moves sideways
  tight.upper(0) = q(0) + 1e-3;
  const std::string limited = message_of([&] { FollowedTrajectory::from_start(lin, ur.with_joint_limits(tight), q); });
  EXPECT_NE(limited.find("trajectory = "), std::string::npos) << limited;
  EXPECT_NE(limited.find("outside its range"), std::string::npos) << limited;
  // A singular pose on the way: the KR6's wrist stretched (q5 = 0) at the LIN's end.
  Eigen::VectorXd bent(6), straight(6);
  bent << 0.2, -1.6, 1.5, 0.3, 0.4, 0.2;
  straight << 0.2, -1.6, 1.5, 0.3, 0.0, 0.2;
  const Trajectory to_singular = plan(Path::lin(kr.forward(bent), kr.forward(straight)), tool_set(), limits_at(0.5));
  const std::string singular = message_of([&] { FollowedTrajectory::from_start(to_singular, kr, bent); });
  EXPECT_NE(singular.find("trajectory = "), std::string::npos) << singular;
  EXPECT_NE(singular.find("singular"), std::string::npos) << singular;

  // The overlap: its range, the joints where the moves meet, the arm.
  EXPECT_NE(message_of([&] { OverlappedMixedTrajectory(ptp, followed, -0.1); }).find("overlap = -0.1"),
            std::string::npos);
  EXPECT_NE(message_of([&] { OverlappedMixedTrajectory(ptp, followed, 1e6); }).find("overlap"), std::string::npos);
  EXPECT_NE(message_of([&] { OverlappedMixedTrajectory(ptp, followed, std::nan("")); }).find("overlap = nan"),
            std::string::npos);
  EXPECT_NE(message_of([&] { OverlappedMixedTrajectory(followed, ptp, 0.1); }).find("must start where"),
            std::string::npos);
  const JointTrajectory kr_ptp = plan(JointPath(other, q), tool_set(), limits_at(0.5), ProfileKind::scurve, kr);
  EXPECT_NE(message_of([&] { OverlappedMixedTrajectory(kr_ptp, followed, 0.1); }).find("arm the PTP move"),
            std::string::npos);
  EXPECT_NO_THROW(OverlappedMixedTrajectory(ptp, followed, 0.1));
}

}  // namespace
}  // namespace dispkin
