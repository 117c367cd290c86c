// The arm-frame closed forms (src/serial/ik_ortho_parallel.cpp, ik_three_parallel_plane.cpp;
// doc/inverse-kinematics.md §10) against the general subproblem path they stand in for: the same
// solution sets on random poses, on poses near the wrist, shoulder and elbow singularities (where
// the fast path must hand over), on arms mounted with a turned and shifted base, with joint
// offsets and with negated axes; and the analysed chain's cache must know the tip.
#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include <Eigen/SVD>
#include <gtest/gtest.h>

#include "angle_batch.hpp"
#include "dispkin/serial/analytic_ik.hpp"
#include "ik_internal.hpp"
#include "ik_recovery_bound.hpp"
#include "random_cases.hpp"
#include "serial_test_chains.hpp"

namespace dispkin {
namespace {

using serial::IkFamily;
using serial::IkSolutionSet;
using serial::RevoluteChain;
using Vector6d = Eigen::Matrix<double, 6, 1>;
namespace detail = serial::detail;

// The chain seen from a base turned by `r` and shifted by `t` (the same arm, mounted elsewhere).
RevoluteChain mounted(RevoluteChain chain, const Posed& base) {
  for (std::size_t i = 0; i < chain.axes.size(); ++i) {
    chain.axes[i] = base.quaternion() * chain.axes[i];
    chain.points[i] = base * chain.points[i];
  }
  chain.tip_at_zero = base * chain.tip_at_zero;
  return chain;
}

// Joint i turned the other way: the same line, its angle negated.
RevoluteChain negated(RevoluteChain chain, std::initializer_list<std::size_t> joints) {
  for (std::size_t i : joints) chain.axes[i] = -chain.axes[i];
  return chain;
}

struct Case {
  std::string name;
  RevoluteChain chain;
  double wrist_singular = 0.0;  //!< a q₅ of the wrist singularity (minus joint 5's DH offset)
};

std::vector<Case> ortho_parallel_arms() {
  const Posed base(Eigen::Quaterniond(Eigen::AngleAxisd(0.7, Eigen::Vector3d(1.0, -2.0, 0.5).normalized())),
                   Eigen::Vector3d(0.3, -1.2, 0.45));
  // A KR6-like table with joint offsets and a lateral (b) offset on joint 2; joint 5's offset is π
  // (axis 6 against axis 4 at q = 0: an offset that bends the wrist there leaves the flip of doc/inverse-kinematics.md
  // eq. 27 and this fast path out).
  const RevoluteChain offsets = testing::chain_from_dh({{0.025, -testing::half_pi, 0.400, 0.3},
                                                        {0.455, 0.0, 0.06, -testing::half_pi + 0.2},
                                                        {0.035, -testing::half_pi, 0.0, -0.4},
                                                        {0.0, testing::half_pi, 0.420, 1.1},
                                                        {0.0, -testing::half_pi, 0.0, testing::pi},
                                                        {0.0, 0.0, 0.080, 2.0}});
  return {{"kuka_kr6_r900", testing::kuka_kr6_r900()},
          {"abb_irb120", testing::abb_irb120()},
          {"abb_irb6640", testing::abb_irb6640()},
          {"kr6 with offsets, mounted", mounted(offsets, base)},
          {"kr6 negated axes, mounted", negated(mounted(testing::kuka_kr6_r900(), base), {0, 2, 3, 5})},
          {"irb6640 negated axes 2 and 5", negated(testing::abb_irb6640(), {1, 4})}};
}

std::vector<Case> three_parallel_arms() {
  const Posed base(Eigen::Quaterniond(Eigen::AngleAxisd(-2.1, Eigen::Vector3d(0.2, 0.9, -0.4).normalized())),
                   Eigen::Vector3d(-0.5, 0.25, 1.1));
  const RevoluteChain offsets = testing::chain_from_dh({{0.0, testing::half_pi, 0.089159, 0.5},
                                                        {-0.425, 0.0, 0.0, -0.3},
                                                        {-0.39225, 0.0, 0.0, 0.8},
                                                        {0.0, testing::half_pi, 0.10915, -1.2},
                                                        {0.0, -testing::half_pi, 0.09465, 0.4},
                                                        {0.0, 0.0, 0.0823, 2.5}});
  return {{"ur5", testing::ur5()},
          {"ur10e", testing::ur10e()},
          {"ur5 with offsets, mounted", mounted(offsets, base), -0.4},
          {"ur10e negated axes, mounted", negated(mounted(testing::ur10e(), base), {0, 2, 4})},
          {"ur5 negated axes 3 and 4", negated(testing::ur5(), {2, 3})}};
}

// Both sets hold the same joint vectors (mod 2π), each to the precision the pose fixes it: the
// pose's rounding, 8 u L, moved along J's most singular direction, ε / σ_min (or 1e-10 rad).
// With the wrist centre on axis 1 (`joints` false) q₁ is fixed by rounding alone; there the sets
// only have to be as many and reproduce the pose.
void expect_same_sets(const RevoluteChain& chain, const IkSolutionSet& fast, const IkSolutionSet& general,
                      const std::string& what, bool joints = true) {
  ASSERT_EQ(fast.count, general.count) << what;
  if (!joints) return;
  const auto distance = [](const Vector6d& a, const Vector6d& b) {
    double d = 0.0;
    for (int i = 0; i < 6; ++i) d = std::max(d, std::abs(std::remainder(a(i) - b(i), 2.0 * testing::pi)));
    return d;
  };
  const double pose_precision = 8.0 * std::numeric_limits<double>::epsilon() * testing::link_length_sum(chain);
  const auto bound = [&](const Vector6d& q) {
    const double sigma_min =
        Eigen::JacobiSVD<Eigen::Matrix<double, 6, 6>>(testing::space_jacobian(chain, Eigen::VectorXd(q)))
            .singularValues()(5);
    return std::max(1e-10, pose_precision / sigma_min);
  };
  for (int i = 0; i < fast.count; ++i) {
    double nearest = 1e300;
    for (int j = 0; j < general.count; ++j) nearest = std::min(nearest, distance(fast[i], general[j]));
    EXPECT_LE(nearest, bound(fast[i])) << what << ": fast " << fast[i].transpose();
  }
  for (int j = 0; j < general.count; ++j) {
    double nearest = 1e300;
    for (int i = 0; i < fast.count; ++i) nearest = std::min(nearest, distance(fast[i], general[j]));
    EXPECT_LE(nearest, bound(general[j])) << what << ": general " << general[j].transpose();
  }
}

// Solves `pose` with and without the fast path; counts the poses the fast path took.
struct Comparison {
  RevoluteChain chain;
  detail::ChainGeometry fast, general;
  int taken = 0, poses = 0;

  explicit Comparison(const RevoluteChain& c) : chain(c), fast(detail::analyse(c, 1e-9)), general(fast) {
    general.ortho_parallel = false;
    general.three_parallel_plane = false;
  }
  void check(const Posed& pose, const std::string& what, bool joints = true) {
    IkSolutionSet a, b, direct;
    if (fast.family == IkFamily::spherical_wrist) {
      detail::spherical_wrist_inverse(chain, fast, pose, a);
      detail::spherical_wrist_inverse(chain, general, pose, b);
      taken += detail::ortho_parallel_inverse(fast.ortho, pose, direct) ? 1 : 0;
    } else {
      detail::three_parallel_inverse(chain, fast, pose, a);
      detail::three_parallel_inverse(chain, general, pose, b);
      taken += detail::three_parallel_plane_inverse(fast.plane, pose, direct) ? 1 : 0;
    }
    ++poses;
    expect_same_sets(chain, a, b, what, joints);
    // Every solution reproduces the pose to ik_pose_tolerance; one kept as exact (error 0, doc/inverse-kinematics.md
    // eq. 26), which includes every one of the fast path, to 1e-12.
    for (int i = 0; i < a.count; ++i) {
      const detail::PoseError e = detail::pose_error(serial::forward(chain, Eigen::VectorXd(a[i])), pose);
      EXPECT_LE(e.worst(), a.error[static_cast<std::size_t>(i)] == 0.0 ? 1e-12 : serial::ik_pose_tolerance)
          << what << ": q = " << a[i].transpose();
    }
  }
};

Vector6d random_q(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> angle(-testing::pi, testing::pi);
  Vector6d q;
  for (int i = 0; i < 6; ++i) q(i) = angle(rng);
  return q;
}

void sweep(const Case& arm, bool spherical, unsigned seed) {
  Comparison c(arm.chain);
  ASSERT_TRUE(spherical ? c.fast.ortho_parallel : c.fast.three_parallel_plane) << arm.name;
  std::mt19937_64 rng(seed);
  const int n = testing::case_count(2000);
  for (int k = 0; k < n; ++k) {
    const Vector6d q = random_q(rng);
    c.check(serial::forward(arm.chain, Eigen::VectorXd(q)), arm.name + " random");
  }
  EXPECT_GE(c.taken, 9 * c.poses / 10) << arm.name << ": the fast path should take most random poses";
  // Near the wrist singularity (q₅ → 0, π) the fast path hands the pose to the general path.
  int near_wrist = 0;
  for (double q5 : {0.0, 1e-12, 1e-8, -1e-6, 1e-3, 5e-3, testing::pi - 1e-7, 0.02}) {
    Vector6d q = random_q(rng);
    q(4) = arm.wrist_singular + q5;
    const int before = c.taken;
    c.check(serial::forward(arm.chain, Eigen::VectorXd(q)), arm.name + " q5 = " + std::to_string(q5));
    near_wrist += c.taken - before;
  }
  EXPECT_LE(near_wrist, 2) << arm.name << ": within 0.005 rad of the wrist singularity the general path decides";
}

TEST(IkArmFrame, OrthoParallelMatchesTheGeneralPath) {
  unsigned seed = 900;
  for (const Case& arm : ortho_parallel_arms()) sweep(arm, true, ++seed);
}

TEST(IkArmFrame, ThreeParallelPlaneMatchesTheGeneralPath) {
  unsigned seed = 950;
  for (const Case& arm : three_parallel_arms()) sweep(arm, false, ++seed);
}

// Poses whose wrist centre (spherical) or axes-5-6 point (three parallel) is moved towards axis 1
// (the shoulder singularity) and poses at a stretched elbow: the fast path hands them over where
// a margin falls below 10⁻⁴, and the sets agree either way.
TEST(IkArmFrame, ShoulderAndElbowSingularitiesAgree) {
  std::vector<Case> arms = ortho_parallel_arms();
  for (const Case& c : three_parallel_arms()) arms.push_back(c);
  std::mt19937_64 rng(77);
  for (const Case& arm : arms) {
    Comparison c(arm.chain);
    const bool spherical = c.fast.family == IkFamily::spherical_wrist;
    const Eigen::Vector3d centre = spherical ? c.fast.wrist_centre : c.fast.point_56;
    const detail::ArmFrame& frame = spherical ? c.fast.ortho.frame : c.fast.plane.frame;
    const double lateral = spherical ? c.fast.ortho.lateral : c.fast.plane.lateral;
    for (double rho : {0.0, 1e-9, 1e-5, 1e-3}) {
      for (int k = 0; k < 4; ++k) {
        const Posed pose = serial::forward(arm.chain, Eigen::VectorXd(random_q(rng)));
        // G c in the arm frame, moved so that its distance from axis 1 is |b| + rho.
        const Posed g = pose * arm.chain.tip_at_zero.inverse();
        const Eigen::Vector3d w = frame.point(g * centre);
        const double radius = std::hypot(w.x(), w.y());
        const double wanted = std::abs(lateral) + rho;
        Eigen::Vector3d shift = Eigen::Vector3d::Zero();
        if (radius > 0.0) shift << w.x() * (wanted / radius - 1.0), w.y() * (wanted / radius - 1.0), 0.0;
        const Posed moved(pose.quaternion(), pose.translation() + frame.to_arm.transpose() * shift);
        c.check(moved, arm.name + " shoulder, rho = " + std::to_string(rho), rho > 0.0);
      }
    }
    // Stretched and folded elbows: q₃ where L₂ ∥ R(σ₃q₃) L₃ (doc/inverse-kinematics.md eq. 31), then nudged.
    const detail::PlaneElbow& e = spherical ? c.fast.ortho.elbow : c.fast.plane.elbow;
    const double aligned = std::atan2(e.upper.eta, e.upper.xi) - std::atan2(e.fore.eta, e.fore.xi);
    for (double fold : {0.0, testing::pi})
      for (double nudge : {0.0, 1e-9, -1e-6, 1e-4, 3e-3}) {
        Vector6d q = random_q(rng);
        q(2) = e.sign3 * (aligned + fold) + nudge;
        c.check(serial::forward(arm.chain, Eigen::VectorXd(q)), arm.name + " elbow " + std::to_string(nudge));
      }
  }
}

// The geometry cached for the last chain holds constants of its tip: a chain that differs only
// in its tip must not be solved with them.
// The batched arctangents (angle_batch.hpp) are atan2 within SLEEF's 3.5 ulp: on the axes and
// the signed zeros (atan2's conventions: ±π at (−1, ±0)), on pairs not of unit length, and on
// random pairs; for an even count and an odd one (its last pair alone), nothing written past n.
TEST(IkArmFrame, BatchedAnglesAreAtan2) {
  std::vector<detail::CosSin> pairs = {{1.0, 0.0},  {0.0, 1.0}, {-1.0, 0.0},    {0.0, -1.0},   {-1.0, -0.0},
                                       {1.0, -0.0}, {3.0, 3.0}, {-2e-3, -1e-3}, {-1.0, 1e-300}};
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> angle(-pi, pi);
  for (int i = 0; i < 41; ++i) {
    const double a = angle(random);
    pairs.push_back({std::cos(a), std::sin(a)});
  }
  for (const std::size_t n : {pairs.size(), pairs.size() - 1}) {
    std::vector<double> out(n + 1, 42.0);
    detail::angles_of(pairs.data(), n, out.data());
    for (std::size_t i = 0; i < n; ++i)
      EXPECT_NEAR(out[i], std::atan2(pairs[i].s, pairs[i].c), 3.5 * 4.5e-16) << "pair " << i;
    EXPECT_EQ(out[n], 42.0);
  }
}

TEST(IkArmFrame, AnalysedChainCacheKnowsTheTip) {
  const RevoluteChain a = testing::kuka_kr6_r900();
  RevoluteChain b = a;
  b.tip_at_zero = a.tip_at_zero * Posed(Eigen::Quaterniond(Eigen::AngleAxisd(0.4, Eigen::Vector3d::UnitX())),
                                        Eigen::Vector3d(0.0, 0.05, 0.12));
  const Vector6d q = (Vector6d() << 0.3, -0.8, 0.6, 1.1, 0.7, -0.4).finished();
  for (const RevoluteChain* chain : std::vector<const RevoluteChain*>{&a, &b, &a}) {
    const Posed pose = serial::forward(*chain, Eigen::VectorXd(q));
    const auto solutions = serial::analytic_inverse(*chain, IkFamily::spherical_wrist, pose);
    ASSERT_FALSE(solutions.empty());
    for (const Eigen::VectorXd& s : solutions)
      EXPECT_LE(detail::pose_error(serial::forward(*chain, s), pose).worst(), 1e-10) << s.transpose();
  }
}

}  // namespace
}  // namespace dispkin
