// Serial-arm inverse kinematics (analytic family or numeric fallback) and the choice among
// solutions: configuration flags, the nearest solution, following a path of poses.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include <dispkin/serial/serial_arm.hpp>

#include "random_cases.hpp"
#include "serial_test_arms.hpp"


namespace dispkin::serial {
namespace {

using dispkin::testing::contains;
using dispkin::testing::message_of;
using dispkin::testing::planar;
using dispkin::testing::Random;
using dispkin::testing::random_q;
using dispkin::testing::ur5e;
using dispkin::testing::urdf_dir;

constexpr double pi = 3.14159265358979323846;

TEST(SerialArmInverse, PlanarNumericFallbackFindsTheOneSolution) {
  // A full pose fixes q₁ + q₂ (the tool's angle) and then the position fixes q₁: one solution,
  // and the continuous elbow has no 2π copies.
  const SerialArm arm = planar("payload");
  EXPECT_EQ(arm.family(), IkFamily::general);
  Random random(607);
  for (int k = 0; k < dispkin::testing::case_count(100); ++k) {
    const Eigen::VectorXd q = random_q(random, arm);
    const Posed pose = arm.forward(q);
    const InverseResult result = arm.inverse_solutions(pose);
    EXPECT_FALSE(result.complete);
    EXPECT_EQ(result.family, IkFamily::general);
    ASSERT_EQ(result.solutions.size(), 1u) << "q = " << q.transpose();
    EXPECT_LE((result.solutions[0] - q).cwiseAbs().maxCoeff(), 1e-9) << "q = " << q.transpose();
    EXPECT_TRUE(arm.forward(result.solutions[0]).is_approx(pose, inverse_tolerance));
  }
}

TEST(SerialArmInverse, SolutionsOutsideTheLimitsAreDroppedOrFlagged) {
  const SerialArm arm = planar("payload");
  // The shoulder's limits are ±3 rad, a range under 2π: q₁ = 3.1 has no copy inside.
  const Eigen::Vector2d q(3.1, 1.2);
  const Posed pose = arm.forward(q);
  EXPECT_TRUE(arm.inverse_solutions(pose).solutions.empty());
  InverseOptions options;
  options.keep_outside_limits = true;
  const InverseResult flagged = arm.inverse_solutions(pose, options);
  ASSERT_EQ(flagged.solutions.size(), 1u);
  EXPECT_FALSE(flagged.within_limits[0]);
  EXPECT_LE((flagged.solutions[0] - q).cwiseAbs().maxCoeff(), 1e-9);
  // Inside the limits the same call flags nothing.
  const InverseResult inside = arm.inverse_solutions(arm.forward(Eigen::Vector2d(2.9, 1.2)), options);
  ASSERT_EQ(inside.solutions.size(), 1u);
  EXPECT_TRUE(inside.within_limits[0]);
}

TEST(SerialArmInverse, General6RNumericFallbackFindsTheSolutions) {
  // The UR5e with joint 3's axis tilted by 0.3 rad and offset, and joint 5's tilted: no family
  // fits, the numeric search runs. It is not complete, but every returned solution holds, and
  // from 64 restarts it finds the original q (modulo 2π) in nearly every case (50 of 50 in the
  // default run; the bound below leaves room for other seeds).
  std::ifstream in(urdf_dir + "arm_ur5e_dh.urdf");
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const auto replace = [&](const std::string& from, const std::string& to) {
    const auto at = text.find(from);
    ASSERT_NE(at, std::string::npos) << from;
    text.replace(at, from.size(), to);
  };
  replace("<origin xyz=\"-0.425 0 0\" rpy=\"0 0 0\"/>", "<origin xyz=\"-0.425 0.03 0\" rpy=\"0.3 0 0\"/>");
  replace("<origin xyz=\"0 0 0.1333\" rpy=\"1.5707963267948966 0 0\"/>",
          "<origin xyz=\"0.02 0 0.1333\" rpy=\"1.3 0 0\"/>");
  const SerialArm arm = SerialArm::from_urdf_string(text, "base_link", "tool0");
  ASSERT_EQ(arm.family(), IkFamily::general);
  InverseOptions options;
  options.offer_equivalents = false;
  options.time_budget = 10.0;  // the attempts, not the clock, end the search here
  Random random(612);
  const int cases = dispkin::testing::case_count(50);
  int found = 0;
  for (int k = 0; k < cases; ++k) {
    const Eigen::VectorXd q = random_q(random, arm);
    const Posed pose = arm.forward(q);
    const InverseResult result = arm.inverse_solutions(pose, options);
    EXPECT_FALSE(result.complete);
    EXPECT_LE(result.solutions.size(), 16u);  // a 6R has at most 16
    bool has_q = false;
    for (const Eigen::VectorXd& s : result.solutions) {
      EXPECT_TRUE(arm.forward(s).is_approx(pose, inverse_tolerance));
      bool same = true;
      for (int i = 0; i < 6; ++i) same = same && std::abs(std::remainder(s(i) - q(i), 2 * pi)) <= 1e-9;
      has_q = has_q || same;
    }
    found += has_q ? 1 : 0;
  }
  EXPECT_GE(found, cases * 9 / 10);
  // One attempt: at most one solution.
  options.max_attempts = 1;
  EXPECT_LE(arm.inverse_solutions(arm.forward(random_q(random, arm)), options).solutions.size(), 1u);
}

TEST(SerialArmInverse, UnreachablePoseHasNoSolution) {
  const SerialArm arm = planar("payload");
  const Posed far = Posed::unchecked(Eigen::Quaterniond::Identity(), Eigen::Vector3d(5, 0, 0));
  EXPECT_TRUE(arm.inverse(far).empty());
}

TEST(SerialArmInverse, Ur5eSolutionsReproduceThePoseAndTheTwoPiCopiesOnRequest) {
  const SerialArm arm = ur5e();
  const JointLimits limits = arm.joint_limits();
  Random random(608);
  for (int k = 0; k < dispkin::testing::case_count(20); ++k) {
    const Eigen::VectorXd q = random_q(random, arm);
    const Posed pose = arm.forward(q);
    InverseOptions copies;
    copies.offer_equivalents = true;
    const InverseResult result = arm.inverse_solutions(pose, copies);
    EXPECT_TRUE(result.complete);
    EXPECT_EQ(result.family, IkFamily::three_parallel);
    EXPECT_TRUE(contains(result.solutions, q, 1e-9)) << "q = " << q.transpose();
    for (const Eigen::VectorXd& s : result.solutions) {
      EXPECT_TRUE(arm.forward(s).is_approx(pose, inverse_tolerance));
      EXPECT_TRUE(((s - limits.lower).array() >= -1e-10).all() && ((limits.upper - s).array() >= -1e-10).all());
      // ±2π limits: each joint value has exactly one 2π copy inside them, which is offered too.
      for (int i = 0; i < 6; ++i) {
        Eigen::VectorXd copy = s;
        copy(i) += s(i) <= 0.0 ? 2 * pi : -2 * pi;
        EXPECT_TRUE(contains(result.solutions, copy, 1e-9)) << "joint " << i << " of " << s.transpose();
      }
    }
    // By default: one joint vector per distinct solution, 2⁶ times fewer, every joint value the
    // copy nearest 0.
    const InverseResult base = arm.inverse_solutions(pose);
    EXPECT_EQ(result.solutions.size(), base.solutions.size() * 64u);
    for (const Eigen::VectorXd& s : base.solutions) EXPECT_LE(s.cwiseAbs().maxCoeff(), pi + 1e-9) << s.transpose();
  }
}

TEST(SerialArmInverse, EverySolutionReproducesThePoseAndNoneRepeats) {
  // inverse_solutions checks by forward kinematics only the solutions it moves by whole turns into
  // the limits, and looks for duplicates only among the numeric search's roots: the analytic
  // families' own acceptance implies the check (doc/inverse-kinematics.md (eq. 26)) and they
  // return no duplicates. Limits of [0, 2π] on the UR5e move every negative joint value by a
  // turn, the KR6-like arm's narrower limits drop some solutions and move others.
  const SerialArm ur = ur5e();
  JointLimits shifted = ur.joint_limits();
  shifted.lower.setZero();
  shifted.upper.setConstant(2 * pi);
  const SerialArm kr6 = SerialArm::from_urdf_file(urdf_dir + "arm_kr6_like_dh.urdf", "base_link", "flange");
  Random random(614);
  for (const SerialArm& arm : {ur, ur.with_joint_limits(shifted), kr6}) {
    const JointLimits limits = arm.joint_limits();
    for (int k = 0; k < dispkin::testing::case_count(500); ++k) {
      const Posed pose = arm.forward(random_q(random, ur));
      for (const bool keep : {false, true}) {
        InverseOptions options;
        options.keep_outside_limits = keep;
        const InverseResult result = arm.inverse_solutions(pose, options);
        ASSERT_EQ(result.solutions.size(), result.within_limits.size());
        for (std::size_t a = 0; a < result.solutions.size(); ++a) {
          const Eigen::VectorXd& s = result.solutions[a];
          EXPECT_TRUE(arm.forward(s).is_approx(pose, inverse_tolerance)) << arm.robot_name() << " " << s.transpose();
          const bool inside =
              ((s - limits.lower).array() >= -1e-10).all() && ((limits.upper - s).array() >= -1e-10).all();
          EXPECT_EQ(inside, static_cast<bool>(result.within_limits[a])) << s.transpose();
          for (std::size_t b = 0; b < a; ++b) {
            double apart = 0.0;
            for (int i = 0; i < 6; ++i)
              apart = std::max(apart, std::abs(std::remainder(s(i) - result.solutions[b](i), 2 * pi)));
            EXPECT_GT(apart, 1e-7) << "solutions " << b << " and " << a << " are one: " << s.transpose();
          }
        }
      }
    }
  }
}

TEST(SerialArmInverse, WideLimitsGiveTheDistinctSolutionsNearestZero) {
  // Limits of ±1e8 and ±1e16 rad (example-robot-data's iris) once gave no solution at all: the
  // representative was the copy just above the lower limit, 1e16 rad, where no digit of the
  // angle is left. The copy nearest 0 keeps every digit whatever the limits.
  const SerialArm ur = ur5e();
  Random random(613);
  for (const double bound : {20.0, 100.0, 1e8, 1e16}) {
    JointLimits wide = ur.joint_limits();
    wide.lower.setConstant(-bound);
    wide.upper.setConstant(bound);
    const SerialArm arm = ur.with_joint_limits(wide);
    for (int k = 0; k < dispkin::testing::case_count(20); ++k) {
      const Eigen::VectorXd q = random_q(random, ur);
      const Posed pose = arm.forward(q);
      const InverseResult result = arm.inverse_solutions(pose);
      EXPECT_EQ(result.solutions.size(), ur.inverse_solutions(pose).solutions.size()) << bound;
      bool has_q = false;
      for (const Eigen::VectorXd& s : result.solutions) {
        EXPECT_TRUE(arm.forward(s).is_approx(pose, inverse_tolerance));
        EXPECT_LE(s.cwiseAbs().maxCoeff(), pi + 1e-9) << s.transpose();
        bool same = true;
        for (int i = 0; i < 6; ++i) same = same && std::abs(std::remainder(s(i) - q(i), 2 * pi)) <= 1e-9;
        has_q = has_q || same;
      }
      EXPECT_TRUE(has_q) << "bound " << bound << ", q = " << q.transpose();
    }
  }
}

TEST(SerialArmChoice, FlagsTellTheAnalyticSolutionsApart) {
  // UR (three parallel axes) and a spherical wrist: the solutions of one pose (without 2π
  // copies) have pairwise different (shoulder, elbow, wrist) flags, so the flags of q pick q.
  const SerialArm kr6 = SerialArm::from_urdf_file(urdf_dir + "arm_kr6_like_dh.urdf", "base_link", "flange");
  EXPECT_EQ(kr6.family(), IkFamily::spherical_wrist);
  InverseOptions plain;
  plain.offer_equivalents = false;
  for (const SerialArm& arm : {ur5e(), kr6}) {
    Random random(610);
    int checked = 0;
    for (int k = 0; k < dispkin::testing::case_count(500); ++k) {
      const Eigen::VectorXd q = random_q(random, arm);
      const Configuration c = arm.configuration(q);
      if (c.shoulder == 0 || c.elbow == 0 || c.wrist == 0) continue;  // on a boundary (singular)
      const InverseResult result = arm.inverse_solutions(arm.forward(q), plain);
      ASSERT_TRUE(result.complete);
      for (std::size_t a = 0; a < result.solutions.size(); ++a)
        for (std::size_t b = a + 1; b < result.solutions.size(); ++b)
          EXPECT_NE(arm.configuration(result.solutions[a]), arm.configuration(result.solutions[b]))
              << arm.robot_name() << " q = " << q.transpose();
      const std::vector<Eigen::VectorXd> picked = with_configuration(arm, result.solutions, c);
      ASSERT_EQ(picked.size(), 1u) << arm.robot_name() << " q = " << q.transpose();
      // Without copies a joint may come back as another 2π-equivalent value than q's.
      for (int i = 0; i < arm.dof(); ++i)
        EXPECT_LE(std::abs(std::remainder(picked[0](i) - q(i), 2 * pi)), 1e-9) << arm.robot_name() << " joint " << i;
      ++checked;
    }
    EXPECT_GT(checked, 0);
  }
}

TEST(SerialArmChoice, NearestConfigurationAndFollow) {
  const SerialArm arm = ur5e();
  const std::vector<Eigen::VectorXd> set{Eigen::VectorXd::Constant(6, 0.0), Eigen::VectorXd::Constant(6, 1.0),
                                         Eigen::VectorXd::Constant(6, -2.0)};
  EXPECT_EQ(nearest(set, Eigen::VectorXd::Constant(6, 0.8)), set[1]);
  EXPECT_EQ(nearest(set, Eigen::VectorXd::Constant(6, -1.1)), set[2]);
  EXPECT_NE(message_of([&] { nearest({}, Eigen::VectorXd::Zero(6)); }).find("solutions"), std::string::npos);
  EXPECT_NE(message_of([&] { nearest(set, Eigen::VectorXd::Zero(5)); }).find("q_ref"), std::string::npos);

  // Flags: q₅ → −q₅ flips the wrist, q₃ → −q₃ flips the elbow (UR: joints 2, 3, 4 parallel).
  Random random(609);
  for (int k = 0; k < 100; ++k) {
    Eigen::VectorXd q = random_q(random, arm);
    q(2) = random.uniform(0.1, 3.0);
    q(4) = random.uniform(0.1, 3.0);
    const Configuration c = arm.configuration(q);
    EXPECT_NE(c.shoulder, 0);
    EXPECT_NE(c.elbow, 0);
    EXPECT_NE(c.wrist, 0);
    Eigen::VectorXd flipped = q;
    flipped(4) = -q(4);
    EXPECT_EQ(arm.configuration(flipped).wrist, -c.wrist);
    EXPECT_EQ(arm.configuration(flipped).elbow, c.elbow);
    flipped = q;
    flipped(2) = -q(2);
    EXPECT_EQ(arm.configuration(flipped).elbow, -c.elbow);
    EXPECT_EQ(arm.configuration(flipped).wrist, c.wrist);
    const std::vector<Eigen::VectorXd> same = with_configuration(arm, {q, flipped}, c);
    ASSERT_EQ(same.size(), 1u);
    EXPECT_EQ(same[0], q);
  }
  EXPECT_NE(message_of([&] { planar().configuration(Eigen::Vector2d::Zero()); }).find("dof"), std::string::npos);

  // Continuity: a joint path sampled finely comes back as itself.
  const SerialArm two = planar("payload");
  std::vector<Posed> poses;
  std::vector<Eigen::VectorXd> joints;
  for (int k = 0; k <= 50; ++k) {
    const Eigen::Vector2d q(-1.0 + 0.03 * k, 0.5 + 0.02 * k);
    joints.push_back(q);
    poses.push_back(two.forward(q));
  }
  const std::vector<Eigen::VectorXd> path = follow(two, poses, joints.front());
  ASSERT_EQ(path.size(), joints.size());
  for (std::size_t k = 0; k < path.size(); ++k) EXPECT_LE((path[k] - joints[k]).cwiseAbs().maxCoeff(), 1e-9);
  const Posed far = Posed::unchecked(Eigen::Quaterniond::Identity(), Eigen::Vector3d(5, 0, 0));
  try {
    follow(two, {poses[0], far}, joints.front());
    ADD_FAILURE() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("poses[1]"), std::string::npos) << e.what();
  }
}

// On a 6-joint arm follow tracks the branch by Newton's method: each step lands on the solution
// that enumerating every analytic solution picks (the nearest to the previous one), for small
// steps (tracked) and for steps too large to be tracked (every solution enumerated).
TEST(SerialArmChoice, FollowTrackingPicksTheNearestAnalyticSolution) {
  const SerialArm arm = ur5e();
  InverseOptions copies;
  copies.offer_equivalents = true;
  Random random(611);
  for (const double step : {0.002, 0.05, 0.6}) {
    for (int trial = 0; trial < 5; ++trial) {
      Eigen::VectorXd q = random_q(random, arm);
      Eigen::VectorXd direction(6);
      for (int i = 0; i < 6; ++i) direction(i) = random.uniform(-1.0, 1.0);
      std::vector<Posed> poses;
      std::vector<Eigen::VectorXd> joints;
      for (int k = 1; k <= 20; ++k) {
        joints.push_back(q + k * step * direction.normalized());
        poses.push_back(arm.forward(joints.back()));
      }
      const std::vector<Eigen::VectorXd> path = follow(arm, poses, q);
      ASSERT_EQ(path.size(), poses.size());
      Eigen::VectorXd previous = q;
      for (std::size_t k = 0; k < poses.size(); ++k) {
        EXPECT_TRUE(arm.forward(path[k]).is_approx(poses[k], inverse_tolerance)) << "step " << step << " pose " << k;
        // follow() turns on into the 2π copies inside the limits: nearest among them too.
        const Eigen::VectorXd enumerated = nearest(arm.inverse_solutions(poses[k], copies).solutions, previous);
        EXPECT_LE((path[k] - enumerated).cwiseAbs().maxCoeff(), 1e-9) << "step " << step << " pose " << k;
        previous = path[k];
      }
      // Inside the limits the fine path is the joint path itself.
      if (step == 0.002) {
        bool inside = true;
        const JointLimits limits = arm.joint_limits();
        for (const Eigen::VectorXd& j : joints)
          inside = inside && (j.array() >= limits.lower.array()).all() && (j.array() <= limits.upper.array()).all();
        for (std::size_t k = 0; inside && k < poses.size(); ++k)
          EXPECT_LE((path[k] - joints[k]).cwiseAbs().maxCoeff(), 1e-9);
      }
    }
  }
}

}  // namespace
}  // namespace dispkin::serial
