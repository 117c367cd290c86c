// The planner and the guarantee (doc/planning.md eq. 5) with its oracle (eq. 25): along any planned
// trajectory, sampled densely by finite differences, no point or sphere of the set moves faster
// than its limit.
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include <dispkin/planning/planner.hpp>
#include <dispkin/path/section_motion.hpp>
#include <dispkin/shapes.hpp>

#include "random_cases.hpp"
#include "random_paths.hpp"

namespace dispkin {
namespace {

using V = Eigen::Vector3d;
using testing::message_of;
using testing::Random;
using testing::random_limits;
using testing::random_path;
using testing::random_set;
using testing::worst_speed_ratio;

TEST(Planner, TheGuaranteeOnRandomPathsAndSets) {
  Random rnd(201);
  const int n = std::max(40, testing::case_count(10000) / 10);
  for (int i = 0; i < n; ++i) {
    const double v = rnd.uniform(0.05, 1.0);
    const MetricSetd set = random_set(rnd, v);
    const Path path = random_path(rnd, i);
    const ProfileKind kind = i % 2 ? ProfileKind::scurve : ProfileKind::trapezoid;
    const Limits limits = random_limits(rnd, v, kind);
    const Trajectory traj = plan(path, set, limits, kind);
    ASSERT_GT(traj.duration(), 0.0);
    const double worst = worst_speed_ratio(traj, set, v, 10000);
    ASSERT_LE(worst, 1.0 + 1e-6) << "case " << i << " family " << i % 6;
    ASSERT_TRUE(traj.sample(traj.duration()).pose.is_approx(path.end(), 1e-9)) << "case " << i;
    ASSERT_TRUE(traj.sample(0.0).pose.is_approx(path.start(), 1e-12));
  }
}

// The guarantee at the edges of the stated numeric range (README, "Numeric range"): every path
// family 1e4 m from the origin (absolute points of the set near the origin, so their lever is
// 1e4 m), under the smallest and the largest stated limits (1e-6 m/s, m/s², m/s³; 1e3 m/s,
// 1e4 m/s², 1e6 m/s³) and mixes of them. Durations reach 1e6 s.
TEST(Planner, TheGuaranteeAtTheNumericRangeEdges) {
  Random rnd(207);
  const V far(1e4, -1e4, 1e4);
  const Limits edges[] = {{1e-6, 1e-6, 1e-6}, {1e3, 1e4, 1e6}, {1e-6, 1e4, 1e6}, {1e3, 1e-6, 1e-6}};
  double longest = 0.0;
  for (int i = 0; i < 48; ++i) {
    Limits limits = edges[(i / 6) % 4];
    const ProfileKind kind = (i / 24) % 2 ? ProfileKind::scurve : ProfileKind::trapezoid;
    if (kind == ProfileKind::trapezoid) limits.jerk.reset();
    const MetricSetd set = random_set(rnd, limits.velocity);
    const Path path = random_path(rnd, i % 6, far);
    const Trajectory traj = plan(path, set, limits, kind);
    ASSERT_TRUE(std::isfinite(traj.duration()) && traj.duration() > 0.0) << "case " << i;
    longest = std::max(longest, traj.duration());
    const double worst = worst_speed_ratio(traj, set, limits.velocity, 10000);
    ASSERT_LE(worst, 1.0 + 1e-6) << "case " << i << " family " << i % 6 << " v " << limits.velocity;
    ASSERT_TRUE(traj.sample(traj.duration()).pose.is_approx(path.end(), 1e-9)) << "case " << i;
  }
  EXPECT_GT(longest, 1e5);

  // The smallest stated moves: 1e-7 m and 1e-7 rad, LIN both ways, at the smallest and largest
  // limits (200 chords: a chord of ~1e-9 m keeps the oracle's rounding below 1e-7 relative).
  for (int i = 0; i < 8; ++i) {
    Limits limits = edges[i % 4];
    limits.jerk.reset();
    const MetricSetd set = random_set(rnd, limits.velocity);
    const Posed a = rnd.pose(0.5);
    const Path path = Path::lin(a, rnd.nearby(a, 1e-7, 1e-7), i < 4 ? Interpolation::screw : Interpolation::decoupled);
    const Trajectory traj = plan(path, set, limits, ProfileKind::trapezoid);
    ASSERT_TRUE(std::isfinite(traj.duration()) && traj.duration() > 0.0) << "tiny case " << i;
    ASSERT_LE(worst_speed_ratio(traj, set, limits.velocity, 200), 1.0 + 1e-6) << "tiny case " << i;
  }
}

// Not needlessly slow: on a long screw move the fastest point cruises at the limit.
TEST(Planner, FastestPointReachesTheLimitWhileCruising) {
  Random rnd(202);
  for (int i = 0; i < 20; ++i) {
    MetricSetd set;
    set.add_relative(shapes::icosahedron(0.1));
    const Posed a = rnd.pose();
    const Path path = Path::lin(a, a * Posed::exp(Twistd(rnd.vector(1.0), rnd.vector(1.0))), Interpolation::screw);
    const Limits limits{0.05, 1.0, 20.0};
    const Trajectory traj = plan(path, set, limits);
    const double t = 0.5 * traj.duration(), dt = 1e-4;
    const Posed p = traj.sample(t).pose, q = traj.sample(t + dt).pose;
    double fastest = 0;
    for (const V& r : set.groups().front().relative_points)
      fastest = std::max(fastest, ((q * r) - (p * r)).norm() / dt);
    ASSERT_GE(fastest, 0.999 * limits.velocity);
    ASSERT_LE(fastest, limits.velocity * (1 + 1e-6));
  }
}

TEST(Planner, StopsAtCornersAndPassesTangentJunctions) {
  MetricSetd set;
  set.add_sphere(V::Zero(), 0.1);
  const Posed a, b = Posed(Eigen::Quaterniond::Identity(), V(0.3, 0, 0)),
                 c = Posed(Eigen::Quaterniond::Identity(), V(0.3, 0.2, 0)),
                 d = Posed(Eigen::Quaterniond::Identity(), V(0.3, 0.4, 0));
  Path corner = Path::lin(a, b);
  corner.then(Path::lin(b, c)).then(Path::lin(c, d));  // a corner at b, straight on at c
  const Limits limits{0.1, 0.5, 5.0};
  const Trajectory traj = plan(corner, set, limits);
  EXPECT_EQ(traj.piece_count(), 2u);
  // At the corner the trajectory is at rest.
  const Profile first = Profile::scurve(0.3, 0.1, 0.5, 5.0);
  EXPECT_NEAR(traj.sample(first.duration()).s_dot, 0.0, 1e-12);
  EXPECT_NEAR(traj.duration(), first.duration() + Profile::scurve(0.4, 0.1, 0.5, 5.0).duration(), 1e-12);
  // A CIRC's sections are one piece.
  const Path arc = Path::circ(a, Posed(Eigen::Quaterniond::Identity(), V(0.1, 0.1, 0)),
                              Posed(Eigen::Quaterniond::Identity(), V(0.2, 0, 0)));
  EXPECT_EQ(plan(arc, set, limits).piece_count(), 1u);
}

// Whoever makes a trajectory (plan, a re-timing, a pickle), the constructor checks it: a law
// faster than the velocity-limit curve, a law that does not cover the path, sections that do
// not join are refused, naming the part.
TEST(Planner, ATrajectoryKeepsItsOwnLimitsAndJoinsUp) {
  MetricSetd set;
  set.add_sphere(V::Zero(), 0.1);
  const Posed a, b = Posed(Eigen::Quaterniond::Identity(), V(0.3, 0, 0));
  const Trajectory traj = plan(Path::lin(a, b), set, Limits{0.1, 0.5, 5.0});
  const double length = traj.length();
  const Trajectory same = traj.with_time_law(TimeLaw::consecutive({Profile::scurve(length, 0.1, 0.5, 5.0)}, 1));
  EXPECT_EQ(same.duration(), traj.duration());
  EXPECT_NE(message_of([&] {
              traj.with_time_law(TimeLaw::consecutive({Profile::scurve(length, 100.0, 500.0, 5000.0)}, 1));
            }).find(": must be at most the velocity limit over its span, 0.1 m/s"),
            std::string::npos);
  EXPECT_NE(message_of([&] {
              traj.with_time_law(TimeLaw::consecutive({Profile::scurve(2.0 * length, 0.1, 0.5, 5.0)}, 1));
            }).find("time_law distance = "),
            std::string::npos);
  std::vector<Section> sections;
  for (std::size_t k = 0; k < traj.section_count(); ++k) sections.push_back(traj.path().section(k));
  const Posed far = Posed(Eigen::Quaterniond::Identity(), V(8.6, 0, 0));
  sections.push_back(LinSection{far, far * Posed(Eigen::Quaterniond::Identity(), V(0.1, 0, 0))});
  std::vector<double> lengths = traj.section_lengths();
  lengths.push_back(0.1);
  EXPECT_NE(message_of([&] {
              Trajectory(SampledPath(sections, lengths), traj.time_law(), traj.speed_limits(), traj.rest_positions());
            }).find("must start where the path ends (gap 8.3"),
            std::string::npos);
}

// The section holding path position s (by walking the lengths, independently of the
// trajectory's own search) and τ within it.
std::pair<std::size_t, double> section_and_tau(const std::vector<double>& lengths, double s) {
  std::size_t j = 0;
  while (j + 1 < lengths.size() && s > lengths[j]) s -= lengths[j++];
  return {j, std::clamp(s / lengths[j], 0.0, 1.0)};
}

// Where path position s lies on the path as given: the path's section, τ on it, and the share
// of the section's τ that the trajectory's section spans (the planner cuts sections,
// doc/planning.md §9; Trajectory::section_sources says how).
struct OnPath {
  std::size_t section;
  double tau, share, length;
};
OnPath on_path(const Trajectory& traj, double s) {
  const auto [j, tau] = section_and_tau(traj.section_lengths(), s);
  const SectionSource& source = traj.section_sources()[j];
  const double share = source.tau_end - source.tau_start;
  return {source.section, source.tau_start + tau * share, share, traj.section_lengths()[j]};
}

TEST(Planner, SampleReportsTheTwistOfTheMotion) {
  Random rnd(203);
  MetricSetd set;
  set.add_relative(shapes::icosahedron(0.1));
  for (int i = 0; i < 20; ++i) {
    const Trajectory traj = plan(random_path(rnd, i), set, Limits{0.2, 1.0, 10.0});
    for (int k = 1; k < 50; ++k) {
      const double t = traj.duration() * k / 50.0, h = 1e-6;
      const TrajectorySample now = traj.sample(t);
      // The twist may step (by < 1 %) at a junction of sections (doc/planning.md eq. 9):
      // central differences across one do not measure it.
      if (section_and_tau(traj.section_lengths(), traj.sample(t - h).s).first !=
          section_and_tau(traj.section_lengths(), traj.sample(t + h).s).first)
        continue;
      const Twistd fd = (traj.sample(t - h).pose.inverse() * traj.sample(t + h).pose).log() * (0.5 / h);
      ASSERT_LT((now.body_twist.vector() - fd.vector()).norm(), 1e-5 * (1 + fd.vector().norm())) << i << " " << k;
    }
  }
}


// The precomputed sampling form of each section reproduces the path's own geometry.
TEST(Planner, SamplesLieOnThePath) {
  Random rnd(204);
  MetricSetd set;
  set.add_relative(shapes::icosahedron(0.1));
  for (int i = 0; i < 40; ++i) {
    const Path path = random_path(rnd, i);
    const Trajectory traj = plan(path, set, Limits{0.2, 1.0, 10.0});
    for (int k = 0; k <= 100; ++k) {
      const TrajectorySample now = traj.sample(traj.duration() * k / 100.0);
      const OnPath at = on_path(traj, now.s);
      ASSERT_TRUE(now.pose.is_approx(section_pose(path.sections()[at.section], at.tau), 1e-12)) << i << " " << k;
    }
  }
}

// The sampling forms' twists are the sections' own: ξ(τ) · ṡ / L_k, to rounding.
TEST(Planner, SampledTwistIsTheSectionsTwist) {
  Random rnd(205);
  MetricSetd set;
  set.add_relative(shapes::icosahedron(0.1));
  for (int i = 0; i < 40; ++i) {
    const Path path = random_path(rnd, i);
    const Trajectory traj = plan(path, set, Limits{0.2, 1.0, 10.0});
    for (int k = 0; k <= 100; ++k) {
      const TrajectorySample now = traj.sample(traj.duration() * k / 100.0);
      const OnPath at = on_path(traj, now.s);
      const Eigen::Matrix<double, 6, 1> expected =
          section_twist(path.sections()[at.section], at.tau).vector() * (at.share * now.s_dot / at.length);
      ASSERT_LE((now.body_twist.vector() - expected).norm(), 1e-12 * (1.0 + expected.norm())) << i << " " << k;
    }
  }
}

void expect_same_sample(const TrajectorySample& a, const TrajectorySample& b, const std::string& where) {
  EXPECT_EQ(a.pose.quaternion().coeffs(), b.pose.quaternion().coeffs()) << where;
  EXPECT_EQ(a.pose.translation(), b.pose.translation()) << where;
  EXPECT_EQ(a.body_twist.vector(), b.body_twist.vector()) << where;
  EXPECT_EQ(a.s, b.s) << where;
  EXPECT_EQ(a.s_dot, b.s_dot) << where;
  EXPECT_EQ(a.s_ddot, b.s_ddot) << where;
}

// sample(t, cursor) is sample(t), bit for bit, whatever the cursor holds: forwards at a
// controller's cycle, backwards, at random, outside [0, T], at NaN, at every law and section
// boundary, and with a cursor left by another trajectory.
TEST(Planner, CursorSamplesEqualPlainSamples) {
  Random rnd(206);
  MetricSetd set;
  set.add_relative(shapes::icosahedron(0.1));
  const Trajectory other = plan(Path::circ(Posed(), Posed(Eigen::Quaterniond::Identity(), V(0.15, 0.2, 0)),
                                           Posed(Eigen::Quaterniond::Identity(), V(0.3, 0, 0))),
                                set, Limits{0.2, 1.0, 10.0});
  for (int i = 0; i < 24; ++i) {
    const Trajectory traj = plan(random_path(rnd, i), set, Limits{0.2, 1.0, 10.0});
    const double T = traj.duration();
    std::vector<double> times;
    for (int k = -5; k <= 1005; ++k) times.push_back(T * k / 1000.0);               // forwards
    for (int k = 1000; k >= 0; k -= 7) times.push_back(T * k / 1000.0);             // backwards
    for (int k = 0; k < 300; ++k) times.push_back(rnd.uniform(-0.1 * T, 1.1 * T));  // random
    for (double t : traj.characteristic_times()) {                                  // law phases
      times.push_back(t);
      times.push_back(std::nextafter(t, -1.0));
      times.push_back(std::nextafter(t, 2.0 * T + 1.0));
    }
    times.push_back(std::numeric_limits<double>::quiet_NaN());
    times.push_back(std::numeric_limits<double>::infinity());
    times.push_back(-std::numeric_limits<double>::infinity());
    Trajectory::Cursor cursor;
    for (double t : times)
      expect_same_sample(traj.sample(t, cursor), traj.sample(t),
                         "case " + std::to_string(i) + " t = " + std::to_string(t));
    // A cursor from another trajectory (indices out of range here, or simply wrong).
    for (int k = 0; k < 50; ++k) {
      Trajectory::Cursor foreign;
      other.sample(other.duration() * k / 50.0, foreign);
      const double t = T * k / 50.0;
      expect_same_sample(traj.sample(t, foreign), traj.sample(t), "foreign cursor, case " + std::to_string(i));
    }
    // The batch form uses a cursor too.
    std::vector<TrajectorySample> batch(times.size());
    traj.sample(times.data(), batch.data(), times.size());
    for (std::size_t k = 0; k < times.size(); ++k) expect_same_sample(batch[k], traj.sample(times[k]), "batch");
  }
}

// Minimum section lengths lengthen exactly the sections they name, and only slow the plan down.
TEST(Planner, MinimumSectionLengthsLengthenSections) {
  MetricSetd set;
  set.add_sphere(V::Zero(), 0.1);
  const Posed a, b = Posed(Eigen::Quaterniond::Identity(), V(0.3, 0, 0)),
                 c = Posed(Eigen::Quaterniond::Identity(), V(0.3, 0.2, 0));
  Path path = Path::lin(a, b);
  path.then(Path::lin(b, c));
  const Limits limits{0.1, 0.5, 5.0};
  const Trajectory plain = plan(path, set, limits);
  PlanOptions options;
  options.min_section_lengths = {0.1, 0.5};  // shorter than section 0 (0.3), longer than section 1 (0.2)
  const Trajectory longer = plan(path, set, limits, ProfileKind::scurve, options);
  EXPECT_DOUBLE_EQ(longer.section_lengths()[0], plain.section_lengths()[0]);
  EXPECT_DOUBLE_EQ(longer.section_lengths()[1], 0.5);
  EXPECT_NEAR(longer.duration(),
              Profile::scurve(0.3, 0.1, 0.5, 5.0).duration() + Profile::scurve(0.5, 0.1, 0.5, 5.0).duration(), 1e-12);
  EXPECT_GT(longer.duration(), plain.duration());
  // Still on the path, and the sphere is slower than the system velocity on the long section.
  for (int k = 0; k <= 200; ++k) {
    const double t = longer.duration() * k / 200.0, h = 1e-6;
    const Twistd xi = (longer.sample(t).pose.inverse() * longer.sample(t + h).pose).log() * (1.0 / h);
    ASSERT_LE(sphere_speed(xi, V::Zero(), 0.1), limits.velocity * (1 + 1e-5));
  }
  options.min_section_lengths.clear();
  EXPECT_EQ(plan(path, set, limits, ProfileKind::scurve, options).duration(), plain.duration());
}

TEST(PlannerBadInput, MinimumSectionLengths) {
  MetricSetd set;
  set.add_sphere(V::Zero(), 0.1);
  const Path path = Path::lin(Posed(), Posed(Eigen::Quaterniond::Identity(), V(0.1, 0, 0)));
  const Limits limits{0.1, 1.0, 1.0};
  PlanOptions options;
  options.min_section_lengths = {0.1, 0.2};
  EXPECT_NE(message_of([&] {
              plan(path, set, limits, ProfileKind::scurve, options);
            }).find("min_section_lengths size = 2: must be 0 or the path's section count 1"),
            std::string::npos);
  options.min_section_lengths = {-0.1};
  EXPECT_NE(
      message_of([&] { plan(path, set, limits, ProfileKind::scurve, options); }).find("min_section_lengths[0] = -0.1"),
      std::string::npos);
  options.min_section_lengths = {std::nan("")};
  EXPECT_NE(
      message_of([&] { plan(path, set, limits, ProfileKind::scurve, options); }).find("min_section_lengths[0] = nan"),
      std::string::npos);
  options.min_section_lengths = {std::numeric_limits<double>::infinity()};
  EXPECT_NE(
      message_of([&] { plan(path, set, limits, ProfileKind::scurve, options); }).find("min_section_lengths[0] = inf"),
      std::string::npos);
}

TEST(PlannerBadInput, Limits) {
  MetricSetd set;
  set.add_sphere(V::Zero(), 0.1);
  const Path path = Path::lin(Posed(), Posed(Eigen::Quaterniond::Identity(), V(0.1, 0, 0)));
  EXPECT_NE(message_of([&] { plan(path, set, Limits{0.0, 1.0, 1.0}); }).find("velocity = 0"), std::string::npos);
  EXPECT_NE(message_of([&] { plan(path, set, Limits{0.1, -1.0, 1.0}); }).find("acceleration = -1"), std::string::npos);
  EXPECT_NE(message_of([&] { plan(path, set, Limits{0.1, 1.0, std::nan("")}); }).find("jerk = nan"), std::string::npos);
  EXPECT_NE(message_of([&] {
              plan(path, set, Limits{0.1, 1.0, std::nullopt});
            }).find("jerk is missing"),
            std::string::npos);
  EXPECT_NE(message_of([&] {
              plan(path, set, Limits{0.1, 1.0, 2.0}, ProfileKind::trapezoid);
            }).find("jerk = 2"),
            std::string::npos);
  MetricSetd line;
  line.add_relative(std::vector<V>{V::Zero(), V::UnitX()});
  EXPECT_NE(message_of([&] { plan(path, line, Limits{0.1, 1.0, 1.0}); }).find("not well-formed"), std::string::npos);
}


// The sampling forms' cheap sine and cosine: within 2 ulp of the library's for small angles
// (their Taylor polynomials), the library's own beyond.
TEST(SectionMotion, SmallAngleSineCosine) {
  Random rnd(207);
  const double limit = detail::small_angle;
  std::vector<double> xs{0.0, -0.0, limit, -limit, 1e-300, 5e-324, 1e-8, std::nextafter(limit, 0.0)};
  for (int i = 0; i < 100000; ++i) xs.push_back(rnd.uniform(-limit, limit));
  for (int i = 0; i < 1000; ++i) xs.push_back(limit * std::pow(10.0, -rnd.uniform(0.0, 12.0)));
  const double ulp = std::numeric_limits<double>::epsilon();
  for (double x : xs) {
    double s, c;
    detail::sin_cos(x, s, c);
    ASSERT_LE(std::abs(s - std::sin(x)), 2.0 * ulp * std::abs(std::sin(x))) << x;
    ASSERT_LE(std::abs(c - std::cos(x)), 2.0 * ulp * std::abs(std::cos(x))) << x;
  }
  // Beyond the small angles: the library's values, bit for bit; NaN stays NaN.
  for (double x : {std::nextafter(limit, 1.0), -0.2, 1.0, 3.0, -100.0}) {
    double s, c;
    detail::sin_cos(x, s, c);
    EXPECT_EQ(s, std::sin(x)) << x;
    EXPECT_EQ(c, std::cos(x)) << x;
  }
  double s, c;
  detail::sin_cos(std::numeric_limits<double>::quiet_NaN(), s, c);
  EXPECT_TRUE(std::isnan(s) && std::isnan(c));
}

// exp(φ) and J_r(φ) u of a curve's sampling form (power series in θ² for θ ≤ 1) against a
// long-double evaluation of the closed forms (their own series below 0.05 rad, where the closed
// forms cancel): within 10⁻¹⁵. Beyond 1 rad: the closed forms, bit for bit.
TEST(SectionMotion, SeriesExpAndRightJacobian) {
  using LV = Eigen::Matrix<long double, 3, 1>;
  Random rnd(208);
  const auto reference = [](const V& phi, const V& u, Eigen::Matrix<long double, 4, 1>& q, LV& ju) {
    const LV p = phi.cast<long double>(), w = u.cast<long double>();
    const long double t = p.norm(), t2 = t * t;
    long double cos_half, half_sine, b, cc;
    if (t >= 0.05L) {
      cos_half = std::cos(t / 2);
      half_sine = std::sin(t / 2) / t;
      b = (1 - std::cos(t)) / t2;
      cc = (t - std::sin(t)) / (t2 * t);
    } else {
      // Series to θ²⁰: the first term left out is below 10⁻²⁶ here.
      cos_half = half_sine = b = cc = 0;
      long double power = 1;  // θ^(2k)
      for (int k = 0; k <= 10; ++k) {
        const long double sign = k % 2 ? -1 : 1;
        long double f2k = 1;  // (2k)!, then (2k + 1)!, (2k + 2)!, (2k + 3)!
        for (int n = 2; n <= 2 * k; ++n) f2k *= n;
        const long double f2k1 = f2k * (2 * k + 1), f2k2 = f2k1 * (2 * k + 2), f2k3 = f2k2 * (2 * k + 3);
        cos_half += sign * power / (f2k * std::pow(4.0L, k));
        half_sine += sign * power / (f2k1 * std::pow(4.0L, k) * 2);
        b += sign * power / f2k2;
        cc += sign * power / f2k3;
        power *= t2;
      }
    }
    q << cos_half, half_sine * p.x(), half_sine * p.y(), half_sine * p.z();
    const LV pu = p.cross(w);
    ju = w - b * pu + cc * p.cross(pu);
  };
  for (int i = 0; i < 20000; ++i) {
    // Angles spread over [10⁻⁸, 1] (and exactly 0 and 1): every term of the series matters somewhere.
    const double theta = i == 0 ? 0.0 : i == 1 ? 1.0 : std::pow(10.0, -rnd.uniform(0.0, 8.0));
    const V phi = theta * rnd.unit_vector(), u = rnd.vector(2.0);
    Eigen::Quaterniond q;
    V ju;
    detail::exp_and_right_jacobian_sampled(phi, u, q, ju);
    Eigen::Matrix<long double, 4, 1> q_ref;
    LV ju_ref;
    reference(phi, u, q_ref, ju_ref);
    const Eigen::Matrix<long double, 4, 1> q_got(q.w(), q.x(), q.y(), q.z());
    ASSERT_LE(static_cast<double>((q_got - q_ref).norm()), 1e-15) << "theta " << theta;
    ASSERT_LE(static_cast<double>((ju.cast<long double>() - ju_ref).norm()), 1e-15 * u.norm()) << "theta " << theta;
  }
  for (double theta : {std::nextafter(1.0, 2.0), 1.5, 3.0}) {
    const V phi = theta * rnd.unit_vector(), u = rnd.vector(1.0);
    Eigen::Quaterniond q, q_closed;
    V ju, ju_closed;
    detail::exp_and_right_jacobian_sampled(phi, u, q, ju);
    detail::exp_and_right_jacobian(phi, u, q_closed, ju_closed);
    EXPECT_EQ(q.coeffs(), q_closed.coeffs()) << theta;
    EXPECT_EQ(ju, ju_closed) << theta;
  }
}

// The benchmark's paths (benchmarks/bench_planner.cpp) sample through the cheap forms: every
// CIRC section's turns are small angles, the SPLINE's rotation stays within the series' range;
// and their samples still lie on the path to 1e-12 with the sections' own twists.
// A trajectory keeps each section of the path as planned once, however finely the planner cuts
// it (doc/planning.md §9): its sections are parts of those, each sampled from its section's form,
// and section(k) makes a part a section of its own that runs as the part does.
TEST(Planner, APartIsKeptAsWhereItLiesNotAsASection) {
  MetricSetd set;
  set.add_relative(shapes::icosahedron(0.1));
  const auto turn = [](double a) { return Eigen::Quaterniond(Eigen::AngleAxisd(a, V(0.3, 0.2, 1.0).normalized())); };
  Path path = Path::lin(Posed(), Posed(turn(1.2), V(0.2, 0.0, 0.0)));
  path.then(Path::lin(Posed(turn(1.2), V(0.2, 0.0, 0.0)), Posed(turn(0.4), V(0.2, 0.3, 0.1))));
  PlanOptions options;
  options.corner_tolerance = 0.02;
  const Trajectory traj = plan(path, set, Limits{0.2, 1.0, 10.0}, ProfileKind::scurve, options);
  const SampledPath& sampled = traj.path();
  // Two LINs and their blend (which the path cuts where its speed varies), cut into many parts.
  ASSERT_EQ(sampled.whole_sections().size(), 3u);
  ASSERT_GT(traj.section_count(), 20u);
  for (std::size_t k = 0; k < traj.section_count(); ++k) {
    const SectionSource part = sampled.part(k);
    ASSERT_LT(part.section, 3u);
    const Section own = sampled.section(k);
    for (const double tau : {0.0, 0.37, 1.0}) {
      Posed pose;
      Twistd twist;
      sampled.section_state_at(k, tau, pose, twist);
      ASSERT_TRUE(pose.is_approx(section_pose(own, tau), 1e-12)) << k << " " << tau;
      const Eigen::Matrix<double, 6, 1> expected = section_twist(own, tau).vector();
      ASSERT_LE((twist.vector() - expected).norm(), 1e-12 * (1.0 + expected.norm())) << k << " " << tau;
    }
  }
  // Parts must name a section and lie in [0, 1]; one length per part.
  const std::vector<Section>& whole = sampled.whole_sections();
  EXPECT_NE(message_of([&] {
              SampledPath(whole, {{3, 0.0, 1.0}}, {0.1});
            }).find("parts[0].section = 3"),
            std::string::npos);
  EXPECT_NE(message_of([&] {
              SampledPath(whole, {{0, 0.0, 0.5}, {0, 0.5, 1.5}}, {0.1, 0.1});
            }).find("parts[1]"),
            std::string::npos);
  EXPECT_NE(message_of([&] {
              SampledPath(whole, {{0, 0.0, 1.0}}, {0.1, 0.2});
            }).find("section_lengths size = 2"),
            std::string::npos);
}

TEST(SectionMotion, CheapFormsOnLongPaths) {
  MetricSetd set;
  set.add_relative(shapes::icosahedron(0.1));
  const auto turn = [](double a) { return Eigen::Quaterniond(Eigen::AngleAxisd(a, V(0.3, 0.2, 1.0).normalized())); };
  const Posed end(turn(0.8), V(0.3, 0.1, 0.05)), via(Eigen::Quaterniond::Identity(), V(0.15, 0.2, 0.0));
  const std::vector<Path> paths{
      Path::circ(Posed(), via, end, V::Zero(), 2.2e-3),
      Path::spline({Posed(), Posed(turn(0.2), V(0.1, 0.1, 0.0)), Posed(turn(0.4), V(0.2, 0.0, 0.05)), end,
                    Posed(turn(0.8), V(0.4, 0.0, 0.0))},
                   V::Zero(), 8e-3)};
  for (const Path& path : paths) {
    const Trajectory traj = plan(path, set, Limits{0.1, 0.5, 5.0});
    for (const Section& section : path.sections()) {
      if (const auto* arc = std::get_if<ArcSection>(&section)) {
        ASSERT_LE(std::abs(arc->angle), detail::small_angle);
        ASSERT_LE(std::abs(0.5 * arc->rotation_angle), detail::small_angle);
      } else if (const auto* curve = std::get_if<CurveSection>(&section)) {
        for (double v : {curve->v0, 0.5 * (curve->v0 + curve->v1), curve->v1})
          ASSERT_LE(curve->rotation.value(v).norm(), detail::series_angle);
      }
    }
    Trajectory::Cursor cursor;
    for (int k = 0; k <= 4000; ++k) {
      const TrajectorySample now = traj.sample(traj.duration() * k / 4000.0, cursor);
      const OnPath at = on_path(traj, now.s);
      ASSERT_TRUE(now.pose.is_approx(section_pose(path.sections()[at.section], at.tau), 1e-12)) << k;
      const Eigen::Matrix<double, 6, 1> expected =
          section_twist(path.sections()[at.section], at.tau).vector() * (at.share * now.s_dot / at.length);
      ASSERT_LE((now.body_twist.vector() - expected).norm(), 1e-12 * (1.0 + expected.norm())) << k;
    }
  }
}

}  // namespace
}  // namespace dispkin
