// The speed range of a part of a decoupled LIN (src/planning/lin_speed_range.hpp, doc/planning.md
// doc/planning.md eqs. 27–31) against the motion itself: its largest speed equals the section length of the part
// (the exact kernel of doc/section-length.md), no densely sampled speed of the set lies above it
// or below its lower bound, and for a set whose fastest object does not change the lower bound is
// the sampled minimum.
#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include <dispkin/path/group_factors.hpp>
#include <dispkin/path/path.hpp>
#include <dispkin/planning/planner.hpp>
#include <dispkin/shapes.hpp>

#include "lin_speed_range.hpp"
#include "random_cases.hpp"
#include "random_paths.hpp"

namespace dispkin {
namespace {

using V = Eigen::Vector3d;
using testing::Random;

// The fastest weighted speed per unit τ of the LIN at τ, from its own pose and twist.
double envelope(const LinSection& lin, const MetricSetd& set, double v_sys, double tau) {
  return max_point_speed(set, lin.pose(tau), lin.twist(tau), v_sys);
}

TEST(LinSpeedRange, PeakIsThePartsLengthAndBoundsHoldDensely) {
  Random rnd(3401);
  for (int i = 0; i < 400; ++i) {
    const double v = rnd.uniform(0.05, 0.5);
    const MetricSetd set = testing::random_set(rnd, v);
    const Posed a = rnd.pose(0.5);
    const LinSection lin{a, rnd.nearby(a, 0.4, i % 4 == 0 ? 3.1 : 2.0), Interpolation::decoupled, rnd.vector(0.1)};
    GroupFactors factors(set, v);
    factors.use_pivot(lin.pivot);
    const detail::DecoupledSpeeds speeds(lin, factors);
    double t0 = rnd.uniform(0.0, 1.0), t1 = rnd.uniform(0.0, 1.0);
    if (i % 5 == 0) t0 = 0.0, t1 = 1.0;
    if (t1 < t0) std::swap(t0, t1);
    if (t1 - t0 < 1e-3) t1 = std::min(1.0, t0 + 1e-3);
    const detail::SpeedRange range = speeds.range(t0, t1);
    // The part as a section of its own: the same motion, its τ a share h of the LIN's.
    const double h = t1 - t0;
    const double part = section_length(set, lin.pose(t0), lin.pose(t1), Interpolation::decoupled, lin.pivot, v) / h;
    EXPECT_NEAR(range.high, part, 1e-10 * part) << "case " << i;
    double lowest = HUGE_VAL, highest = 0.0;
    for (int k = 0; k <= 2000; ++k) {
      const double f = envelope(lin, set, v, t0 + h * k / 2000.0);
      lowest = std::min(lowest, f);
      highest = std::max(highest, f);
    }
    EXPECT_LE(highest, range.high * (1.0 + 1e-12)) << "case " << i;
    EXPECT_GE(lowest, range.low * (1.0 - 1e-12)) << "case " << i;
    EXPECT_LE(range.low, range.high) << "case " << i;
  }
}

// One object: the lower bound is its exact minimum (doc/planning.md eq. 28 for a point, 36 for a body sphere,
// 37 and 38 for absolute ones) — the cut then stops where the speed itself stops varying.
TEST(LinSpeedRange, LowerBoundIsExactForOneObject) {
  Random rnd(3402);
  for (int i = 0; i < 200; ++i) {
    MetricSetd set;
    switch (i % 4) {
      case 0:
        set.add_relative(rnd.vector(0.3));
        break;
      case 1:
        set.add_sphere(rnd.vector(0.3), rnd.uniform(0.01, 0.2), Frame::relative);
        break;
      case 2:
        set.add_absolute(rnd.vector(1.0));
        break;
      default:
        set.add_sphere(rnd.vector(1.0), rnd.uniform(0.01, 0.2), Frame::absolute);
        break;
    }
    const Posed a = rnd.pose(0.5);
    const LinSection lin{a, rnd.nearby(a, 0.4, 2.5), Interpolation::decoupled, rnd.vector(0.1)};
    GroupFactors factors(set, std::nullopt);
    factors.use_pivot(lin.pivot);
    const detail::DecoupledSpeeds speeds(lin, factors);
    double t0 = rnd.uniform(0.0, 1.0), t1 = rnd.uniform(0.0, 1.0);
    if (t1 < t0) std::swap(t0, t1);
    const detail::SpeedRange range = speeds.range(t0, t1);
    double lowest = HUGE_VAL;
    for (int k = 0; k <= 5000; ++k) {
      const double tau = t0 + (t1 - t0) * k / 5000.0;
      lowest = std::min(lowest, max_point_speed(set, lin.pose(tau), lin.twist(tau)));
    }
    EXPECT_GE(lowest, range.low * (1.0 - 1e-12)) << "case " << i;
    // The sampled minimum lies within the speed's change over half a sample step of the exact one.
    EXPECT_LE(lowest, range.low + 1e-6 * range.high) << "case " << i;
  }
}

// The planner's pieces of a rotating LIN: few where the fastest speed hardly varies (the LIN of
// the plan_lin_icosahedron benchmark varies by 2.5 % along its whole length), each within 0.4 %.
TEST(LinSpeedRange, CutFollowsTheSpeedNotItsBound) {
  MetricSetd set;
  set.add_relative(shapes::icosahedron(0.1));
  const Posed end(Eigen::Quaterniond(Eigen::AngleAxisd(0.8, V(0.3, 0.2, 1.0).normalized())), V(0.3, 0.1, 0.05));
  const Trajectory traj = plan(Path::lin(Posed(), end), set, Limits{0.1, 0.5, 5.0});
  const std::size_t pieces = traj.path().section_count();
  EXPECT_GE(pieces, 7u);   // (max − min)/max of the whole LIN / 0.4 %, at least
  EXPECT_LE(pieces, 29u);  // half of the 59 the bound of the speed's rate (doc/planning.md eq. 26) asked for
  const LinSection lin{Posed(), end, Interpolation::decoupled, V::Zero()};
  for (std::size_t k = 0; k < pieces; ++k) {
    const SectionSource& source = traj.section_sources()[k];
    double lowest = HUGE_VAL, highest = 0.0;
    for (int i = 0; i <= 200; ++i) {
      const double f = envelope(lin, set, 0.1, source.tau_start + (source.tau_end - source.tau_start) * i / 200.0);
      lowest = std::min(lowest, f);
      highest = std::max(highest, f);
    }
    EXPECT_GE(lowest, 0.996 * highest * (1.0 - 1e-12)) << "piece " << k;
  }
}

}  // namespace
}  // namespace dispkin
