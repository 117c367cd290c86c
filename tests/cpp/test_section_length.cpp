// Section length (doc/section-length.md §2–3) against the actual motion: the largest speed of every
// point and sphere, sampled densely along the section by finite differences, is never above L and L
// is within 1e-6 of it — for screw and decoupled sections, relative and absolute objects.
#include <functional>

#include <gtest/gtest.h>

#include <dispkin/disp.hpp>

#include "random_cases.hpp"

namespace dispkin {
namespace {

using V = Eigen::Vector3d;
using testing::Random;

// The sampling runs in long double (the core is templated on the scalar): central differences
// of positions lose ε·|x|/h, which in double would be 1e-8 of a short section's speed.
using Real = long double;
using PoseL = Pose<Real>;
using VL = Eigen::Matrix<Real, 3, 1>;
constexpr Real h = 1e-5L;  // finite-difference step in τ

PoseL extended(const Posed& p) { return PoseL::unchecked(p.quaternion().cast<Real>(), p.translation().cast<Real>()); }

struct Section {
  Posed a, b;
  Interpolation kind;
  V pivot;
  PoseL at(Real tau) const { return interpolate(extended(a), extended(b), tau, kind, VL(pivot.cast<Real>())); }
  // Body twist per unit τ by central differences of the motion itself.
  Twist<Real> twist(Real tau) const {
    const PoseL t = at(tau);
    const Twist<Real> forward = (t.inverse() * at(tau + h)).log();
    const Twist<Real> backward = (t.inverse() * at(tau - h)).log();
    return Twist<Real>((forward.linear - backward.linear) / (2 * h), (forward.angular - backward.angular) / (2 * h));
  }
};

// Largest value of f over τ ∈ [0, 1]: a 401-point grid, then golden-section search around the
// best grid point (each object's speed is smooth in τ and has one peak per grid cell).
double sampled_max(const std::function<Real(Real)>& f) {
  const int n = 400;
  int best_i = 0;
  Real best = -1;
  for (int i = 0; i <= n; ++i) {
    const Real value = f(Real(i) / n);
    if (value > best) best = value, best_i = i;
  }
  Real lo = std::max(Real(0), Real(best_i - 1) / n), hi = std::min(Real(1), Real(best_i + 1) / n);
  const Real g = (std::sqrt(Real(5)) - 1) / 2;
  Real x1 = hi - g * (hi - lo), x2 = lo + g * (hi - lo), f1 = f(x1), f2 = f(x2);
  for (int it = 0; it < 60; ++it) {
    if (f1 < f2) {
      lo = x1, x1 = x2, f1 = f2, x2 = lo + g * (hi - lo), f2 = f(x2);
    } else {
      hi = x2, x2 = x1, f2 = f1, x1 = hi - g * (hi - lo), f1 = f(x1);
    }
  }
  return static_cast<double>(std::max({best, f1, f2}));
}

// The sampled maximum speed of every object of the (single-group) set along the section.
double sampled_section_speed(const MetricSetd& set, const Section& s) {
  double best = 0;
  const auto& g = set.groups().front();
  for (const auto& rd : g.relative_points) {
    const VL r = rd.cast<Real>();
    best =
        std::max(best, sampled_max([&](Real t) { return ((s.at(t + h) * r) - (s.at(t - h) * r)).norm() / (2 * h); }));
  }
  for (const auto& xd : g.absolute_points) {
    const VL x = xd.cast<Real>();
    best = std::max(best, sampled_max([&](Real t) {
                      return ((s.at(t + h).inverse() * x) - (s.at(t - h).inverse() * x)).norm() / (2 * h);
                    }));
  }
  // Spheres through the instantaneous twist and the exact sphere speed (itself checked
  // against surface samples, doc/planning.md §8 item 3).
  for (const auto& sp : g.relative_spheres) {
    const VL c = sp.center.cast<Real>();
    best = std::max(best, sampled_max([&](Real t) { return sphere_speed<Real>(s.twist(t), c, sp.radius); }));
  }
  for (const auto& sp : g.absolute_spheres) {
    const VL c = sp.center.cast<Real>();
    best = std::max(best, sampled_max([&](Real t) {
                      return sphere_speed<Real>(s.twist(t), VL(s.at(t).inverse() * c), sp.radius);
                    }));
  }
  return best;
}

void check_against_sampling(Interpolation kind, Frame frame, bool spheres, unsigned long salt) {
  Random rnd(salt);
  const int n = std::max(20, testing::case_count(10000) / 20);
  for (int i = 0; i < n; ++i) {
    MetricSetd set;
    if (spheres) {
      set.add_sphere(rnd.vector(0.5), rnd.uniform(0.0, 0.4), frame);
    } else {
      std::vector<V> points;
      for (int k = rnd.integer(3, 6); k > 0; --k) points.push_back(rnd.vector(frame == Frame::absolute ? 1.5 : 0.5));
      set.add_points(points, frame);
    }
    const Posed a = rnd.pose(0.5);
    // Translations from none to large, rotations from none to nearly half a turn.
    const double step = i % 7 == 0 ? 0.0 : rnd.uniform(0.0, 1.0);
    const double angle = i % 5 == 0 ? 0.0 : rnd.uniform(0.0, 3.1);
    const Section s{a, rnd.nearby(a, step, angle), kind, rnd.vector(0.3)};
    if (s.a.is_approx(s.b, 1e-9)) continue;
    const double length = section_length(set, s.a, s.b, kind, s.pivot);
    const double sampled = sampled_section_speed(set, s);
    ASSERT_GE(length, sampled * (1 - 1e-9)) << "never below the sampled maximum, case " << i;
    ASSERT_LE(length, sampled * (1 + 1e-6)) << "within 1e-6 of the sampled maximum, case " << i;
  }
}

TEST(SectionLength, ScrewRelativePoints) { check_against_sampling(Interpolation::screw, Frame::relative, false, 71); }
TEST(SectionLength, ScrewAbsolutePoints) { check_against_sampling(Interpolation::screw, Frame::absolute, false, 72); }
TEST(SectionLength, ScrewRelativeSphere) { check_against_sampling(Interpolation::screw, Frame::relative, true, 73); }
TEST(SectionLength, ScrewAbsoluteSphere) { check_against_sampling(Interpolation::screw, Frame::absolute, true, 74); }
TEST(SectionLength, DecoupledRelativePoints) {
  check_against_sampling(Interpolation::decoupled, Frame::relative, false, 75);
}
TEST(SectionLength, DecoupledAbsolutePoints) {
  check_against_sampling(Interpolation::decoupled, Frame::absolute, false, 76);
}
TEST(SectionLength, DecoupledRelativeSphere) {
  check_against_sampling(Interpolation::decoupled, Frame::relative, true, 77);
}
TEST(SectionLength, DecoupledAbsoluteSphere) {
  check_against_sampling(Interpolation::decoupled, Frame::absolute, true, 78);
}

// A screw section moves every object at constant speed: the fastest moves at exactly L.
TEST(SectionLength, ScrewSpeedsAreConstantAlongTheSection) {
  Random rnd(79);
  for (int i = 0; i < 200; ++i) {
    const Section s{rnd.pose(), rnd.pose(), Interpolation::screw, V::Zero()};
    const VL r = rnd.vector(1.0).cast<Real>(), x = rnd.vector(1.0).cast<Real>();
    const Real r0 = ((s.at(h) * r) - (s.at(-h) * r)).norm();
    const Real x0 = ((s.at(h).inverse() * x) - (s.at(-h).inverse() * x)).norm();
    for (const Real t : {0.3L, 0.7L, 1.0L}) {
      ASSERT_NEAR(double(((s.at(t + h) * r) - (s.at(t - h) * r)).norm()), double(r0), 1e-12 * double(1 + r0));
      ASSERT_NEAR(double(((s.at(t + h).inverse() * x) - (s.at(t - h).inverse() * x)).norm()), double(x0),
                  1e-12 * double(1 + x0));
    }
  }
}

// The decoupled section is the industrial LIN: the pivot travels the straight line and the
// orientation is the SLERP of the end quaternions.
TEST(SectionLength, DecoupledInterpolationIsLinAboutThePivot) {
  Random rnd(80);
  for (int i = 0; i < 200; ++i) {
    const Posed a = rnd.pose(), b = rnd.pose();
    const V pivot = rnd.vector(0.3);
    for (const double t : {0.0, 0.25, 0.5, 1.0}) {
      const Posed p = interpolate(a, b, t, Interpolation::decoupled, pivot);
      ASSERT_LT(((p * pivot) - ((1 - t) * (a * pivot) + t * (b * pivot))).norm(), 1e-14);
      ASSERT_LT(p.quaternion().angularDistance(a.quaternion().slerp(t, b.quaternion())), 1e-7);
    }
    ASSERT_TRUE(interpolate(a, b, 1.0, Interpolation::decoupled, pivot).is_approx(b, 1e-14));
    ASSERT_TRUE(interpolate(a, b, 1.0, Interpolation::screw, pivot).is_approx(b, 1e-13));
  }
}

// The relative points are taken four at a time, the last lanes filled by repeating a point: the
// peak over a set of any size is exactly the largest of its points' own peaks (each taken as four
// copies, a full set of lanes), so no point is dropped or replaced by a filler that moves. The
// points lie around a pivot far from the body origin, where a filler at the origin would be the
// fastest point.
TEST(SectionLength, DecoupledPointsPeakIsTheLargestOfTheirOwn) {
  Random rnd(81);
  for (int i = 0; i < 300; ++i) {
    const Posed a = rnd.pose(0.5);
    const Posed b = rnd.nearby(a, i % 5 == 0 ? 0.0 : rnd.uniform(0.0, 1.0), i % 7 == 0 ? 0.0 : rnd.uniform(0.0, 3.1));
    const V pivot = V(0.3, 0.4, 0.5) + rnd.vector(0.1);
    const detail::DecoupledSection<double> section(a, b, pivot);
    PointColumns<double> all;
    double largest = 0;
    for (int n = 1 + i % 13; n > 0; --n) {
      const V p = pivot + rnd.vector(0.05);
      all.push_back(p);
      PointColumns<double> copies;
      for (int c = 0; c < 4; ++c) copies.push_back(p);
      largest = std::max(largest, section.relative_points_speed2(copies));
    }
    ASSERT_EQ(section.relative_points_speed2(all), largest) << "case " << i << ", " << all.size() << " points";
  }
}

}  // namespace
}  // namespace dispkin
