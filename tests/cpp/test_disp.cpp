// doc/planning.md §8 items 1–3: metric axioms, the vertex shortcut, the exact sphere formula; plus
// chords of spheres under all three norms, group weights, and chord ≤ section length.
#include <gtest/gtest.h>

#include <dispkin/disp.hpp>

#include "random_cases.hpp"

namespace dispkin {
namespace {

using V = Eigen::Vector3d;
using testing::Random;

// ---- doc/planning.md §8 item 1: metric axioms ----------------------------------------------

template <typename Norm>
void check_metric_axioms(unsigned long salt) {
  Random rnd(salt);
  const int n = testing::case_count(10000);
  for (int i = 0; i < n; ++i) {
    const MetricSetd set = rnd.metric_set();
    const double v_sys = rnd.uniform(0.1, 2.0);
    const Posed a = rnd.pose(), b = rnd.pose(), c = rnd.pose();
    const double ab = disp_distance<Norm>(set, a, b, v_sys);
    const double ba = disp_distance<Norm>(set, b, a, v_sys);
    const double bc = disp_distance<Norm>(set, b, c, v_sys);
    const double ac = disp_distance<Norm>(set, a, c, v_sys);
    ASSERT_EQ(disp_distance<Norm>(set, a, a, v_sys), 0.0);
    ASSERT_NEAR(ab, ba, 1e-12 * (1 + ab)) << "symmetry, case " << i;
    ASSERT_LE(ac, ab + bc + 1e-12 * (1 + ac)) << "triangle inequality, case " << i;
    // Positive for any other pose, even one a tiny turn away about a random axis.
    const Posed near = rnd.nearby(a, 1e-7, 1e-7);
    ASSERT_GT(disp_distance<Norm>(set, a, near, v_sys), 0.0) << "case " << i;
  }
}

TEST(DispMetric, AxiomsEuclidean) { check_metric_axioms<EuclideanNorm>(31); }
TEST(DispMetric, AxiomsMaxNorm) { check_metric_axioms<MaxNorm>(32); }
TEST(DispMetric, AxiomsL1Norm) { check_metric_axioms<L1Norm>(33); }

TEST(DispMetric, RotationAboutTheLineOfTwoPointsIsSeenByAThird) {
  MetricSetd set;
  set.add_relative(V(0, 0, 0));
  set.add_relative(V(1, 0, 0));
  set.add_relative(V(0.5, 0.01, 0));
  const Posed turned(Eigen::Quaterniond(Eigen::AngleAxisd(1e-6, V::UnitX())), V::Zero());
  const double expected = 0.01 * 2 * std::sin(0.5e-6);
  // (Rb − Ra) p cancels to about 1e-16 absolute: 1e-8 relative at this 1e-8 m chord.
  EXPECT_NEAR(disp_distance(set, Posed(), turned), expected, 1e-8 * expected);
}

TEST(DispMetric, GroupsCombineAsWeightedMaximum) {
  Random rnd(34);
  for (int i = 0; i < 1000; ++i) {
    MetricSetd g0, g1, both;
    const auto p0 = std::vector<V>{rnd.vector(1), rnd.vector(1), rnd.vector(1)};
    const auto p1 = std::vector<V>{rnd.vector(1), rnd.vector(1), rnd.vector(1)};
    g0.add_relative(p0);
    g1.add_relative(p1);
    both.add_relative(p0, 0);
    both.add_relative(p1, 7);
    const double v_sys = 1.5, v_7 = rnd.uniform(0.1, 3.0);
    both.set_group_speed(7, v_7);
    const Posed a = rnd.pose(), b = rnd.pose();
    const double expected = std::max(disp_distance(g0, a, b), disp_distance(g1, a, b) * v_sys / v_7);
    ASSERT_NEAR(disp_distance(both, a, b, v_sys), expected, 1e-14);
    const double expected_len = std::max(section_length(g0, a, b, Interpolation::decoupled),
                                         section_length(g1, a, b, Interpolation::decoupled) * v_sys / v_7);
    ASSERT_NEAR(section_length(both, a, b, Interpolation::decoupled, V::Zero(), v_sys), expected_len, 1e-14);
  }
}

// ---- doc/planning.md §8 item 2: the vertex shortcut (doc/disp-metric.md eq. 27) ------------

TEST(DispVertexShortcut, InteriorPointsNeverBeatTheVertices) {
  Random rnd(41);
  const int n = testing::case_count(10000);
  for (int i = 0; i < n; ++i) {
    std::vector<V> vertices;
    for (int k = rnd.integer(4, 10); k > 0; --k) vertices.push_back(rnd.vector(1.0));
    const Twistd xi(rnd.vector(1.0), rnd.vector(2.0));
    const Posed a = rnd.pose(), b = rnd.pose();
    double speed_max = 0, rel_chord_max = 0, abs_chord_max = 0;
    for (const auto& p : vertices) {
      speed_max = std::max(speed_max, point_speed(xi, p));
      rel_chord_max = std::max(rel_chord_max, ((b * p) - (a * p)).norm());
      abs_chord_max = std::max(abs_chord_max, ((b.inverse() * p) - (a.inverse() * p)).norm());
    }
    for (int k = 0; k < 10; ++k) {
      // A random convex combination: a point of the hull.
      Eigen::VectorXd w(vertices.size());
      for (Eigen::Index j = 0; j < w.size(); ++j) w(j) = -std::log(rnd.uniform(1e-12, 1.0));
      w /= w.sum();
      V x = V::Zero();
      for (std::size_t j = 0; j < vertices.size(); ++j) x += w(static_cast<Eigen::Index>(j)) * vertices[j];
      ASSERT_LE(point_speed(xi, x), speed_max * (1 + 1e-12));
      ASSERT_LE(((b * x) - (a * x)).norm(), rel_chord_max * (1 + 1e-12));
      ASSERT_LE(((b.inverse() * x) - (a.inverse() * x)).norm(), abs_chord_max * (1 + 1e-12));
    }
  }
}

// ---- doc/planning.md §8 item 3: the exact sphere speed against surface samples -------------

// Largest ‖vc + ω × ρn‖ over unit n: the best of `samples` random directions, then refined by
// projected gradient ascent — still a point of the surface, so never above the true maximum.
double sampled_sphere_speed(const Twistd& xi, const V& center, double radius, int samples, Random& rnd) {
  const V vc = xi.linear + xi.angular.cross(center);
  auto speed = [&](const V& n) { return (vc + radius * xi.angular.cross(n)).norm(); };
  V best = V::UnitX();
  double best_speed = -1;
  for (int i = 0; i < samples; ++i) {
    const V n = rnd.unit_vector();
    const double s = speed(n);
    if (s > best_speed) best_speed = s, best = n;
  }
  double step = 0.1;
  for (int it = 0; it < 2000 && step > 1e-15; ++it) {
    // ∇ of ½‖vc + ρ ω × n‖² is ρ (vc + ρ ω × n) × ω; keep its part tangent to the sphere.
    V g = radius * (vc + radius * xi.angular.cross(best)).cross(xi.angular);
    g -= g.dot(best) * best;
    if (g.norm() == 0) break;
    const V trial = (best + step * g / g.norm()).normalized();
    const double s = speed(trial);
    if (s > best_speed) {
      best = trial, best_speed = s, step *= 1.5;
    } else {
      step *= 0.5;
    }
  }
  return best_speed;
}

void check_sphere_formula(unsigned long salt, int cases, int samples) {
  Random rnd(salt);
  for (int i = 0; i < cases; ++i) {
    Twistd xi(rnd.vector(1.0), rnd.vector(3.0));
    if (i % 10 == 0) xi.angular.setZero();                           // pure translation
    if (i % 10 == 1) xi.linear = xi.angular * rnd.uniform(-1, 1);    // a pure screw along ω
    if (i % 10 == 2) xi.linear = xi.angular.cross(rnd.vector(1.0));  // a pure rotation
    const V center = rnd.vector(0.5);
    const double radius = rnd.uniform(0.01, 1.0);
    const double exact = sphere_speed(xi, center, radius);
    const double sampled = sampled_sphere_speed(xi, center, radius, samples, rnd);
    ASSERT_GE(exact, sampled * (1 - 1e-14)) << "never below a sample, case " << i;
    ASSERT_LE(exact, sampled * (1 + 1e-6)) << "within 1e-6 of the samples' maximum, case " << i;
  }
}

// doc/planning.md §8 item 3 as written: 10⁵ random surface samples per motion.
TEST(DispSphere, ExactFormulaAgainstDenseSurfaceSamples) {
  check_sphere_formula(51, std::max(10, testing::case_count(10000) / 100), 100000);
}

// The sweep: many more motions, fewer samples each (the ascent refines the best one).
TEST(DispSphere, ExactFormulaSweep) { check_sphere_formula(56, testing::case_count(10000), 1000); }

TEST(DispSphere, ZeroRadiusIsAPointAndTheInsideIsNeverFaster) {
  Random rnd(52);
  for (int i = 0; i < 10000; ++i) {
    const Twistd xi(rnd.vector(1.0), rnd.vector(3.0));
    const V c = rnd.vector(1.0);
    ASSERT_NEAR(sphere_speed(xi, c, 0.0), point_speed(xi, c), 1e-14);
    const double r = rnd.uniform(0.0, 1.0);
    ASSERT_LE(point_speed(xi, V(c + rnd.uniform(0, r) * rnd.unit_vector())), sphere_speed(xi, c, r) * (1 + 1e-14));
  }
}

// Chords of a sphere's points, under each norm: the disk formulas against samples.
template <typename Norm>
void check_sphere_chords(unsigned long salt) {
  Random rnd(salt);
  for (int i = 0; i < 100; ++i) {
    const Posed a = rnd.pose(), b = rnd.nearby(a, 0.5, 2.0);
    const V c = rnd.vector(0.5);
    const double radius = rnd.uniform(0.05, 0.5);
    for (const Frame frame : {Frame::relative, Frame::absolute}) {
      MetricSetd set;
      set.add_sphere(c, radius, frame);
      const double formula = disp_distance<Norm>(set, a, b);
      double sampled = 0;
      for (int k = 0; k < 20000; ++k) {
        const V x = c + radius * rnd.unit_vector();
        const V chord = frame == Frame::relative ? V((b * x) - (a * x)) : V((b.inverse() * x) - (a.inverse() * x));
        sampled = std::max(sampled, Norm::of(chord));
      }
      ASSERT_GE(formula, sampled * (1 - 1e-12)) << to_string(frame) << " case " << i;
      ASSERT_LE(formula, sampled * (1 + 2e-3)) << to_string(frame) << " case " << i;
    }
  }
}

TEST(DispSphere, ChordsEuclidean) { check_sphere_chords<EuclideanNorm>(53); }
TEST(DispSphere, ChordsMaxNorm) { check_sphere_chords<MaxNorm>(54); }
TEST(DispSphere, ChordsL1Norm) { check_sphere_chords<L1Norm>(55); }

// ---- the chord is never longer than the arc ------------------------------------------------

TEST(DispSection, ChordNeverExceedsSectionLength) {
  Random rnd(61);
  const int n = testing::case_count(10000);
  for (int i = 0; i < n; ++i) {
    const MetricSetd set = rnd.metric_set();
    const Posed a = rnd.pose(), b = rnd.nearby(a, 1.0, 3.1);
    const V pivot = rnd.vector(0.3);
    const double chord = disp_distance(set, a, b, 1.0);
    ASSERT_LE(chord, section_length(set, a, b, Interpolation::screw, pivot, 1.0) * (1 + 1e-12)) << i;
    ASSERT_LE(chord, section_length(set, a, b, Interpolation::decoupled, pivot, 1.0) * (1 + 1e-12)) << i;
  }
}

TEST(DispSection, PureTranslationHasTheChordAsLength) {
  Random rnd(62);
  for (int i = 0; i < 1000; ++i) {
    const MetricSetd set = rnd.metric_set(false);
    const Posed a = rnd.pose();
    const Posed b = Posed::unchecked(a.quaternion(), a.translation() + rnd.vector(1.0));
    const double d = (b.translation() - a.translation()).norm();
    ASSERT_NEAR(disp_distance(set, a, b), d, 1e-14);
    ASSERT_NEAR(section_length(set, a, b, Interpolation::screw), d, 1e-14);
    ASSERT_NEAR(section_length(set, a, b, Interpolation::decoupled, rnd.vector(1.0)), d, 1e-14);
  }
}

TEST(DispBadInput, InterpolationNames) {
  EXPECT_EQ(interpolation_from_string("screw"), Interpolation::screw);
  EXPECT_EQ(interpolation_from_string("decoupled"), Interpolation::decoupled);
  try {
    interpolation_from_string("slerp");
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("interpolation = \"slerp\""), std::string::npos) << e.what();
  }
}

TEST(DispBadInput, NonFinitePivot) {
  MetricSetd set;
  set.add_sphere(V::Zero(), 1.0);
  EXPECT_THROW(section_length(set, Posed(), Posed(), Interpolation::decoupled, V(0, std::nan(""), 0)),
               std::invalid_argument);
}

}  // namespace
}  // namespace dispkin
