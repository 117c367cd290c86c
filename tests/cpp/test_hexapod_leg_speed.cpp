// Hexapod leg speeds: rule (a), the leg speed group along planned trajectories, and rule (b), the
// joint-space metric (leg rate bounds, section lengths, planned trajectories).
#include <cstdio>
#include <string>

#include <gtest/gtest.h>

#include <dispkin/hexapod/hexapod.hpp>
#include <dispkin/path/path.hpp>
#include <dispkin/planning/planner.hpp>

#include "hexapod_test_rig.hpp"
#include "random_cases.hpp"

namespace dispkin {
namespace {

using hexapod::Hexapod;
using hexapod::LegExcursion;
using hexapod::TrajectoryCheck;
using testing::message_of;
using testing::Random;
using testing::reachable_pose;
using testing::test_hexapod;
using Legs = Hexapod::Legs;
using Vector6 = Eigen::Matrix<double, 6, 1>;
constexpr double pi = 3.14159265358979323846;

// --- leg speed along planned trajectories ------------------------------------------------------

TEST(HexapodTrajectory, LegSpeedGroupHoldsEveryLegToItsSpeedLimit) {
  const Hexapod h = test_hexapod();
  Random rnd(508);
  double largest_ratio = 0.0;
  for (int c = 0; c < testing::case_count(200) / 4 + 1; ++c) {
    MetricSetd set;
    set.add_relative(Eigen::Vector3d(0.0, 0.0, 0.05));  // a tool point, group 0
    set.add_relative(Eigen::Vector3d(0.02, 0.0, 0.05));
    set.add_relative(Eigen::Vector3d(0.0, 0.02, 0.05));
    h.add_leg_speed_group(set, 1);
    ASSERT_EQ(set.find_group(1)->speed_limit, h.leg_speed().minCoeff());
    const Posed a = reachable_pose(h, rnd), b = reachable_pose(h, rnd);
    const Path path = c % 2 ? Path::lin(a, b) : Path::lin(a, b, Interpolation::screw);
    // System velocity 10× the leg speed: only the leg group holds the trajectory back.
    const Trajectory trajectory = plan(path, set, Limits{0.1, 1.0, 20.0});
    const TrajectoryCheck check = h.check_trajectory(trajectory, trajectory.duration() / 2000);
    for (int i = 0; i < 6; ++i) {
      ASSERT_LE(check.max_speed(i), h.leg_speed()(i) * (1 + 1e-9)) << "case " << c << " leg " << i;
      largest_ratio = std::max(largest_ratio, check.max_speed(i) / h.leg_speed()(i));
    }
    // The analytic leg speed J ξ agrees with finite differences of the leg lengths.
    const double t = rnd.uniform(0.1, 0.9) * trajectory.duration(), dt = 1e-6;
    const Legs numeric =
        (h.leg_lengths(trajectory.sample(t + dt).pose) - h.leg_lengths(trajectory.sample(t - dt).pose)) / (2 * dt);
    const TrajectorySample s = trajectory.sample(t);
    ASSERT_LT((h.leg_jacobian(s.pose) * s.body_twist.vector() - numeric).cwiseAbs().maxCoeff(), 1e-9);
  }
  // The bound is not vacuous: some leg comes close to its limit.
  EXPECT_GT(largest_ratio, 0.5);
}

TEST(HexapodTrajectory, WithoutTheGroupLegsAreTooFastAndTheCheckSaysWhich) {
  const Hexapod h = test_hexapod();
  MetricSetd set;
  set.add_relative(Eigen::Vector3d(0.0, 0.0, 0.05));
  set.add_relative(Eigen::Vector3d(0.02, 0.0, 0.05));
  set.add_relative(Eigen::Vector3d(0.0, 0.02, 0.05));
  const Posed a = h.home() * Posed::exp(Twistd(Eigen::Vector3d(0, 0, -0.02), Eigen::Vector3d::Zero()));
  const Posed b = h.home() * Posed::exp(Twistd(Eigen::Vector3d(0, 0, 0.02), Eigen::Vector3d::Zero()));
  const Trajectory trajectory = plan(Path::lin(a, b), set, Limits{0.1, 1.0, 20.0});
  const TrajectoryCheck check = h.check_trajectory(trajectory, 1e-3);
  ASSERT_EQ(check.excursions.size(), 6u);  // a vertical move drives all legs equally
  for (int i = 0; i < 6; ++i) {
    const LegExcursion& e = check.excursions[static_cast<std::size_t>(i)];
    EXPECT_EQ(e.kind, LegExcursion::Kind::speed);
    EXPECT_EQ(e.leg, i);
    EXPECT_GT(e.start_time, 0.0);
    EXPECT_LT(e.end_time, trajectory.duration());
    EXPECT_NEAR(e.excess, e.worst_value - h.leg_speed()(i), 1e-15);
    EXPECT_GT(e.worst_value, 5 * h.leg_speed()(i));
  }
}

TEST(HexapodTrajectory, MoveBetweenReachablePosesThroughAnUnreachableOneIsReported) {
  const Hexapod s = test_hexapod();
  // Sideways across the base: a leg's length ‖a + τ d‖ is convex in τ, so it is shortest
  // inside the move. Limits just below the shorter end length of each leg.
  const Posed a = s.home() * Posed::exp(Twistd(Eigen::Vector3d(0.08, 0, 0), Eigen::Vector3d::Zero()));
  const Posed b = s.home() * Posed::exp(Twistd(Eigen::Vector3d(-0.08, 0, 0), Eigen::Vector3d::Zero()));
  const Legs lo = s.leg_lengths(a).cwiseMin(s.leg_lengths(b)).array() - 1e-3;
  const Hexapod h(s.base_joints(), s.platform_joints(), lo, Legs::Constant(0.5), Legs::Constant(1.0), s.home());
  ASSERT_TRUE(h.check(a).reachable());
  ASSERT_TRUE(h.check(b).reachable());
  MetricSetd set;
  h.add_leg_speed_group(set, 0);
  const Trajectory trajectory = plan(Path::lin(a, b), set, Limits{0.01, 0.1, 2.0});
  const TrajectoryCheck check = h.check_trajectory(trajectory, trajectory.duration() / 10000);
  ASSERT_FALSE(check.ok());
  for (const LegExcursion& e : check.excursions) {
    EXPECT_EQ(e.kind, LegExcursion::Kind::length);
    EXPECT_GT(e.start_time, 0.0);
    EXPECT_LT(e.end_time, trajectory.duration());
    EXPECT_LE(e.start_time, e.worst_time);
    EXPECT_LE(e.worst_time, e.end_time);
    // The reported length is the leg's length at the reported time.
    EXPECT_EQ(e.worst_value, h.leg_lengths(trajectory.sample(e.worst_time).pose)(e.leg));
    EXPECT_NEAR(e.excess, lo(e.leg) - e.worst_value, 1e-15);
    EXPECT_FALSE(h.check(trajectory.sample(e.worst_time).pose).reachable());
  }
  // Every leg that dips below its range inside the move is reported, and only those.
  for (int i = 0; i < 6; ++i) {
    bool reported = false;
    for (const LegExcursion& e : check.excursions) reported = reported || e.leg == i;
    EXPECT_EQ(reported, check.min_length(i) < lo(i)) << "leg " << i;
  }
}

// --- leg speed, rule (b): the joint-space metric ------------------------------------------------

// A tool: three points 5 cm above the platform, group 0.
MetricSetd tool_points() {
  MetricSetd set;
  set.add_relative(Eigen::Vector3d(0.0, 0.0, 0.05));
  set.add_relative(Eigen::Vector3d(0.02, 0.0, 0.05));
  set.add_relative(Eigen::Vector3d(0.0, 0.02, 0.05));
  return set;
}

// A random path of each kind between reachable poses: decoupled LIN about a random pivot,
// screw LIN, CIRC.
Path random_hexapod_path(const Hexapod& h, Random& rnd, int family) {
  const Posed a = reachable_pose(h, rnd), b = reachable_pose(h, rnd);
  if (family % 4 == 0) return Path::lin(a, b, Interpolation::decoupled, rnd.vector(0.1));
  if (family % 4 == 1) return Path::lin(a, b, Interpolation::screw);
  if (family % 4 == 3) return Path::spline({a, reachable_pose(h, rnd), b}, rnd.vector(0.05), 1e-2);
  const Posed via = h.home() * Posed::exp(Twistd(rnd.vector(0.02), Eigen::Vector3d::Zero()));
  return Path::circ(a, Posed(a.quaternion(), via.translation()), b, rnd.vector(0.05), 0.05);
}

// At most `count` sections of the path, spread over it.
std::vector<Section> some_sections(const Path& path, std::size_t count) {
  std::vector<Section> out;
  const std::size_t step = std::max<std::size_t>(1, path.size() / count);
  for (std::size_t k = 0; k < path.size(); k += step) out.push_back(path.sections()[k]);
  return out;
}

// max over τ of |dℓ_i/dτ| on a dense grid, dℓ/dτ = J ξ (the quantity leg_rate_bounds bounds).
Legs dense_leg_rates(const Hexapod& h, const Section& section, int n) {
  Legs best = Legs::Zero();
  for (int k = 0; k <= n; ++k) {
    const double tau = static_cast<double>(k) / n;
    best =
        best.cwiseMax((h.leg_jacobian(section_pose(section, tau)) * section_twist(section, tau).vector()).cwiseAbs());
  }
  return best;
}

TEST(HexapodJointMetric, LegRateIsTheDerivativeOfTheLegLengthAlongTheSection) {
  const Hexapod h = test_hexapod();
  Random rnd(520);
  for (int c = 0; c < 30; ++c) {
    const Path path = random_hexapod_path(h, rnd, c);
    for (const Section& section : some_sections(path, 10)) {
      const double tau = rnd.uniform(0.01, 0.99), d = 1e-6;
      const Legs numeric =
          (h.leg_lengths(section_pose(section, tau + d)) - h.leg_lengths(section_pose(section, tau - d))) / (2 * d);
      const Legs exact = h.leg_jacobian(section_pose(section, tau)) * section_twist(section, tau).vector();
      ASSERT_LT((exact - numeric).cwiseAbs().maxCoeff(), 1e-8) << "case " << c;
    }
  }
}

TEST(HexapodJointMetric, BoundIsNeverBelowTheDenseMaximumAndWithinTheTolerance) {
  const Hexapod h = test_hexapod();
  Random rnd(521);
  const double tolerance = 1e-3;
  int sections = 0;
  // 20000 dense samples per section make each case costly (minutes under the sanitizers at the
  // sweep counts), so this oracle runs a sixteenth of the requested count, 20 to 40 cases.
  for (int c = 0; c < std::min(testing::case_count(200) / 16 + 8, 40); ++c) {
    const Path path = random_hexapod_path(h, rnd, c);
    for (const Section& section : some_sections(path, 10)) {
      const Legs bound = h.leg_rate_bounds(section, tolerance);
      const Legs dense = dense_leg_rates(h, section, 20000);
      const double demand = (dense.array() / h.leg_speed().array()).maxCoeff();
      for (int i = 0; i < 6; ++i) {
        ASSERT_GE(bound(i), dense(i)) << "case " << c << " leg " << i;
        // Tight: within the stated tolerance of the section's demand (plus what 20000 samples miss).
        ASSERT_LE(bound(i), dense(i) + tolerance * demand * h.leg_speed()(i) * (1 + 1e-3) + 1e-12)
            << "case " << c << " leg " << i;
      }
      ++sections;
    }
  }
  EXPECT_GT(sections, 100);
}

TEST(HexapodJointMetric, BoundOfAStandingSectionIsZero) {
  const Hexapod h = test_hexapod();
  EXPECT_EQ(h.leg_rate_bounds(Section(LinSection{h.home(), h.home()})), Legs::Zero());
}

TEST(HexapodJointMetric, SectionLengthsScaleWithTheSystemVelocity) {
  const Hexapod h = test_hexapod();
  Random rnd(522);
  const Path path = random_hexapod_path(h, rnd, 2);
  const std::vector<double> slow = h.leg_section_lengths(path, 0.05), fast = h.leg_section_lengths(path, 0.1);
  ASSERT_EQ(slow.size(), path.size());
  for (std::size_t k = 0; k < path.size(); ++k) {
    EXPECT_NEAR(fast[k], 2 * slow[k], 1e-15 * fast[k]);
    EXPECT_NEAR(slow[k], 0.05 * (h.leg_rate_bounds(path.sections()[k]).array() / h.leg_speed().array()).maxCoeff(),
                1e-15);
  }
  // A single section: joint_metric's lengths are exactly the leg lengths.
  const Path lin = Path::lin(reachable_pose(h, rnd), reachable_pose(h, rnd));
  EXPECT_EQ(h.joint_metric(lin, Limits{0.1, 1.0, 20.0}).min_section_lengths, h.leg_section_lengths(lin, 0.1));
}

// Along a CIRC the lengths are raised to one common speed: the planner runs through the arc
// without stopping, and the legs stay within their speed.
TEST(HexapodJointMetric, CircIsOnePieceAndKeepsTheLegs) {
  const Hexapod h = test_hexapod();
  const auto shifted = [&](double x, double y) {
    return h.home() * Posed::exp(Twistd(Eigen::Vector3d(x, y, 0.0), Eigen::Vector3d(0.0, 0.0, 0.05)));
  };
  const Path arc =
      Path::circ(shifted(0.02, 0.0), shifted(0.0, 0.02), shifted(-0.02, 0.0), Eigen::Vector3d::Zero(), 0.01);
  ASSERT_GT(arc.size(), 5u);
  const Limits limits{0.1, 1.0, 20.0};
  const PlanOptions options = h.joint_metric(arc, limits);
  const std::vector<double> needed = h.leg_section_lengths(arc, limits.velocity);
  for (std::size_t k = 0; k < arc.size(); ++k) ASSERT_GE(options.min_section_lengths[k], needed[k]);
  const Trajectory trajectory = plan(arc, tool_points(), limits, ProfileKind::scurve, options);
  EXPECT_EQ(trajectory.piece_count(), 1u);
  const TrajectoryCheck check = h.check_trajectory(trajectory, trajectory.duration() / 20000);
  EXPECT_TRUE(check.ok());
  EXPECT_LE(check.max_speed.maxCoeff(), h.leg_speed().maxCoeff() * (1 + 1e-9));
  MetricSetd with_group = tool_points();
  h.add_leg_speed_group(with_group, 1);
  const Trajectory rule_a = plan(arc, with_group, limits);
  std::printf("CIRC of %zu sections: rule (b) %.3f s, rule (a) %.3f s\n", arc.size(), trajectory.duration(),
              rule_a.duration());
}

// PlanOptions::joint_metric is evaluated on the path as planned: with corners blended it plans
// exactly what the joint metric of the blended path does, and the corners left keep the blend's
// reason for stopping.
TEST(HexapodJointMetric, OptionsEvaluateItOnTheBlendedPath) {
  const Hexapod h = test_hexapod();
  const auto shifted = [&](double x, double y) {
    return h.home() * Posed::exp(Twistd(Eigen::Vector3d(x, y, 0.0), Eigen::Vector3d::Zero()));
  };
  // A right-angle corner (blended) and a reversal (not blendable).
  Path path = Path::lin(shifted(0.0, 0.0), shifted(0.02, 0.0));
  path.then(Path::lin(shifted(0.02, 0.0), shifted(0.02, 0.02)))
      .then(Path::lin(shifted(0.02, 0.02), shifted(0.02, 0.0)));
  const Limits limits{0.1, 1.0, 20.0};
  PlanOptions options;
  options.corner_tolerance = 0.005;
  options.joint_metric = h.joint_metric();
  const Trajectory planned = plan(path, tool_points(), limits, ProfileKind::scurve, options);
  const Path blended = path.blended(options.corner_tolerance);
  const Trajectory reference =
      plan(blended, tool_points(), limits, ProfileKind::scurve, h.joint_metric(blended, limits));
  EXPECT_EQ(planned.duration(), reference.duration());
  EXPECT_EQ(planned.section_lengths(), reference.section_lengths());
  ASSERT_EQ(planned.stops().size(), 1u);
  EXPECT_NE(planned.stops()[0].reason.find("reverses"), std::string::npos) << planned.stops()[0].reason;
  // Its lengths and min_section_lengths are one or the other.
  options.min_section_lengths.assign(path.size(), 0.0);
  options.corner_tolerance = 0.0;
  EXPECT_NE(
      message_of([&] { plan(path, tool_points(), limits, ProfileKind::scurve, options); }).find("with a joint_metric"),
      std::string::npos);
}

TEST(HexapodJointMetric, PlannedTrajectoriesKeepEveryLegWithinItsSpeed) {
  const Hexapod h = test_hexapod();
  Random rnd(523);
  const MetricSetd set = tool_points();  // no leg group: rule (b) alone holds the legs
  const Limits limits{0.1, 1.0, 20.0};   // system velocity 10× the leg speed
  double fastest_without = 0.0;
  for (int c = 0; c < testing::case_count(200) / 10 + 3; ++c) {
    const Path path = random_hexapod_path(h, rnd, c);
    const Trajectory trajectory = plan(path, set, limits, ProfileKind::scurve, h.joint_metric(path, limits));
    const TrajectoryCheck check = h.check_trajectory(trajectory, trajectory.duration() / 20000);
    for (int i = 0; i < 6; ++i)
      ASSERT_LE(check.max_speed(i), h.leg_speed()(i) * (1 + 1e-9)) << "case " << c << " leg " << i;
    for (const LegExcursion& e : check.excursions) ASSERT_NE(e.kind, LegExcursion::Kind::speed) << "case " << c;
    fastest_without = std::max(fastest_without, h.check_trajectory(plan(path, set, limits), 1e-3).max_speed.maxCoeff());
  }
  // Without rule (b) the same plans drive legs far beyond their limit.
  EXPECT_GT(fastest_without, 3 * h.leg_speed().maxCoeff());
}

TEST(HexapodJointMetric, LegSpeedDominatedMoveReachesTheLegLimit) {
  // A move whose fastest leg (leg 3) peaks in the middle, where the trajectory cruises.
  const Hexapod h = test_hexapod();
  Vector6 va, vb;
  va << -0.011, 0.021, 0.162, -0.032, -0.077, -0.014;
  vb << -0.030, -0.022, 0.205, -0.067, 0.175, 0.063;
  const Path path = Path::lin(Posed::from_xyzuvw(va), Posed::from_xyzuvw(vb));
  const Limits limits{0.1, 1.0, 20.0};
  const Trajectory trajectory = plan(path, tool_points(), limits, ProfileKind::scurve, h.joint_metric(path, limits));
  const TrajectoryCheck check = h.check_trajectory(trajectory, trajectory.duration() / 20000);
  ASSERT_TRUE(check.ok());
  const double ratio = (check.max_speed.array() / h.leg_speed().array()).maxCoeff();
  EXPECT_GE(ratio, 0.99);
  EXPECT_LE(ratio, 1.0 + 1e-9);
}

// Rule (b) never plans slower than rule (a) on a single section: r_i ≤ V, the joints' speed
// bound that rule (a) uses, and every leg's limit is at least the group's (the smallest). On
// screws. A decoupled LIN under rule (a) is cut into pieces (doc/planning.md §9) whose joint
// speeds are bounded piece by piece, while rule (b)'s leg bound is one per section: there
// rule (b) can be the slower (by up to 1.6 % in 2000 random moves), and only the ratio is printed.
TEST(HexapodJointMetric, NeverSlowerThanTheLegSpeedGroupOnSingleMoves) {
  const Hexapod h = test_hexapod();
  Random rnd(524);
  const Limits limits{0.1, 1.0, 20.0};
  double sum_ratio = 0.0, smallest = 1e300, largest = 0.0;
  const int n = testing::case_count(200) / 4 + 3;
  for (int c = 0; c < n; ++c) {
    const Path path = Path::lin(reachable_pose(h, rnd), reachable_pose(h, rnd),
                                c % 2 ? Interpolation::screw : Interpolation::decoupled);
    MetricSetd with_group = tool_points();
    h.add_leg_speed_group(with_group, 1);
    const double a = plan(path, with_group, limits).duration();
    const double b = plan(path, tool_points(), limits, ProfileKind::scurve, h.joint_metric(path, limits)).duration();
    if (c % 2) {
      ASSERT_LE(b, a * (1 + 1e-12)) << "case " << c;
    }
    sum_ratio += b / a;
    smallest = std::min(smallest, b / a);
    largest = std::max(largest, b / a);
  }
  std::printf("rule (b) / rule (a) duration over %d random LIN moves: mean %.4f, min %.4f, max %.4f\n", n,
              sum_ratio / n, smallest, largest);
}

TEST(HexapodJointMetricBadInput, ToleranceAndSystemVelocity) {
  const Hexapod h = test_hexapod();
  const Path path =
      Path::lin(h.home(), h.home() * Posed::exp(Twistd(Eigen::Vector3d(0, 0, 0.01), Eigen::Vector3d::Zero())));
  EXPECT_NE(
      message_of([&] { h.leg_rate_bounds(path.sections().front(), 0.0); }).find("tolerance = 0: must be in (0, 1]"),
      std::string::npos);
  EXPECT_NE(message_of([&] { h.leg_rate_bounds(path.sections().front(), std::nan("")); }).find("tolerance = nan"),
            std::string::npos);
  EXPECT_NE(message_of([&] { h.leg_rate_bounds(path.sections().front(), 2.0); }).find("tolerance = 2"),
            std::string::npos);
  EXPECT_NE(message_of([&] { h.leg_section_lengths(path, 0.0); }).find("system_velocity = 0"), std::string::npos);
  EXPECT_NE(message_of([&] { h.leg_section_lengths(path, -1.0); }).find("system_velocity = -1"), std::string::npos);
  EXPECT_NE(message_of([&] {
              h.joint_metric(path, Limits{std::nan(""), 1.0, 1.0});
            }).find("system_velocity = nan"),
            std::string::npos);
}

}  // namespace
}  // namespace dispkin
