// Seven-joint chains solved with a locked joint (redundancy.hpp, doc/inverse-kinematics.md §11):
// the lock found for the Panda and the iiwa14 (written from their published DH tables), round trips
// at the generating joint value, and random SRS arms.
#include <cmath>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include <dispkin/serial/analytic_ik.hpp>
#include <dispkin/serial/redundancy.hpp>

#include "ik_recovery_bound.hpp"
#include "random_cases.hpp"
#include "serial_test_chains.hpp"

namespace {

using dispkin::Posed;
namespace serial = dispkin::serial;

// The largest joint difference (mod 2π) between q and the nearest of `solutions`.
double nearest_distance(const std::vector<Eigen::VectorXd>& solutions, const Eigen::VectorXd& q) {
  double best = INFINITY;
  for (const Eigen::VectorXd& s : solutions) {
    double worst = 0.0;
    for (Eigen::Index i = 0; i < q.size(); ++i)
      worst = std::max(worst, std::abs(std::remainder(s(i) - q(i), 2.0 * M_PI)));
    best = std::min(best, worst);
  }
  return best;
}

// How closely the pose fixes the six joints that move when the last one is locked at q₇: the
// 6R chain of joints 1…6 with the tip e₇(q₇) M (doc/inverse-kinematics.md eq. 37) and its
// recovery bound (ik_recovery_bound.hpp: 1e-8 rad except near a singular pose of that chain).
double recovery_bound_at(const serial::RevoluteChain& chain, const Eigen::VectorXd& q) {
  serial::RevoluteChain rest;
  rest.axes.assign(chain.axes.begin(), chain.axes.begin() + 6);
  rest.points.assign(chain.points.begin(), chain.points.begin() + 6);
  rest.tip_at_zero = serial::rotation_about_line(chain.axes[6], chain.points[6], q(6)) * chain.tip_at_zero;
  return dispkin::testing::recovery_bound(rest, q.head(6));
}

// Round trips at the generating value of the locked joint (the last): q is among the solutions
// (within its recovery bound), every solution reproduces the pose and keeps the value.
void expect_round_trips(const serial::RevoluteChain& chain, int count, unsigned seed) {
  const serial::LockedJoint lock = serial::find_locked_joint(chain);
  ASSERT_TRUE(lock.found());
  ASSERT_EQ(lock.joint, 6);
  std::mt19937_64 engine(seed);
  std::uniform_real_distribution<double> angle(-M_PI, M_PI);
  std::vector<Eigen::VectorXd> found;
  for (int k = 0; k < count; ++k) {
    Eigen::VectorXd q(7);
    for (int i = 0; i < 7; ++i) q(i) = angle(engine);
    const Posed pose = serial::forward(chain, q);
    found.clear();
    serial::locked_joint_inverse(chain, lock, q(lock.joint), pose, found);
    ASSERT_LE(nearest_distance(found, q), recovery_bound_at(chain, q)) << "case " << k;
    for (const Eigen::VectorXd& s : found) {
      EXPECT_EQ(s(lock.joint), q(lock.joint));
      EXPECT_TRUE(serial::forward(chain, s).is_approx(pose, 1e-10)) << "case " << k;
    }
  }
}

TEST(LockedJoint, PandaAndIiwaLockTheLastJointAndSolveTheChainFromTheTip) {
  for (const serial::RevoluteChain& chain : {dispkin::testing::franka_panda(), dispkin::testing::kuka_iiwa14()}) {
    EXPECT_EQ(serial::recognise(chain), serial::IkFamily::locked_joint);
    const serial::LockedJoint lock = serial::find_locked_joint(chain);
    EXPECT_EQ(lock.joint, 6);
    EXPECT_TRUE(lock.reversed);
    EXPECT_EQ(lock.family, serial::IkFamily::spherical_wrist);
  }
}

TEST(LockedJoint, RoundTripsOnThePandaAndTheIiwa) {
  const int count = dispkin::testing::case_count(2000);
  expect_round_trips(dispkin::testing::franka_panda(), count, 1);
  expect_round_trips(dispkin::testing::kuka_iiwa14(), count, 2);
}

// Random SRS arms: every a = 0, link offsets d and twists α drawn at random (axes 1, 2, 3 and
// 5, 6, 7 meet wherever d₂ = d₆ = 0).
TEST(LockedJoint, RoundTripsOnRandomSrsArms) {
  std::mt19937_64 engine(3);
  std::uniform_real_distribution<double> length(0.1, 0.6), twist(0.3, 2.8);
  for (int arm = 0; arm < 10; ++arm) {
    std::vector<dispkin::testing::DhRow> rows;
    for (int i = 0; i < 7; ++i) {
      const double d = (i == 0 || i == 2 || i == 4 || i == 6) ? length(engine) : 0.0;
      rows.push_back({0.0, i == 6 ? 0.0 : (twist(engine) * (i % 2 ? 1.0 : -1.0)), d, 0.0});
    }
    const serial::RevoluteChain chain = dispkin::testing::chain_from_dh(rows);
    ASSERT_EQ(serial::recognise(chain), serial::IkFamily::locked_joint) << "arm " << arm;
    expect_round_trips(chain, dispkin::testing::case_count(2000) / 10, 10 + arm);
  }
}

TEST(LockedJoint, ABadValueIsNamed) {
  const serial::RevoluteChain chain = dispkin::testing::franka_panda();
  std::vector<Eigen::VectorXd> out;
  const std::string why = dispkin::testing::message_of(
      [&] { serial::locked_joint_inverse(chain, serial::find_locked_joint(chain), NAN, chain.tip_at_zero, out); });
  EXPECT_NE(why.find("redundancy"), std::string::npos) << why;
}

}  // namespace
