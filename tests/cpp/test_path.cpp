// Paths: LIN, CIRC (circle geometry, arcs over 180° and tiny arcs), sections and their length
// bound against the sampled motion, path sampling, PTP, bad input.
#include <functional>

#include <gtest/gtest.h>

#include <dispkin/path/path.hpp>

#include "random_cases.hpp"

namespace dispkin {
namespace {

using V = Eigen::Vector3d;
using testing::message_of;
using testing::Random;
constexpr double pi = 3.14159265358979323846;

// Largest speed of every object of a single-group set along τ ∈ [0, 1] of `pose`, by central
// differences on a 2001-point grid.
double sampled_speed(const MetricSetd& set, const std::function<Posed(double)>& pose) {
  const double h = 1e-6;
  double best = 0;
  const auto& g = set.groups().front();
  for (int i = 0; i <= 2000; ++i) {
    const double t = i / 2000.0;
    const Posed p = pose(t + h), m = pose(t - h);
    for (const V& r : g.relative_points) best = std::max(best, ((p * r) - (m * r)).norm() / (2 * h));
    for (const V& x : g.absolute_points)
      best = std::max(best, ((p.inverse() * x) - (m.inverse() * x)).norm() / (2 * h));
  }
  return best;
}

TEST(Path, LinPassesThroughItsEnds) {
  Random rnd(101);
  for (int i = 0; i < 1000; ++i) {
    const Posed a = rnd.pose(), b = rnd.pose();
    for (const auto kind : {Interpolation::decoupled, Interpolation::screw}) {
      const Path path = Path::lin(a, b, kind, rnd.vector(0.2));
      ASSERT_EQ(path.size(), 1u);
      ASSERT_TRUE(path.sample(0.0).is_approx(a, 1e-12));
      ASSERT_TRUE(path.sample(1.0).is_approx(b, 1e-12));
      ASSERT_TRUE(path.end().is_approx(b, 1e-12));
    }
  }
}

// Found by fuzzing (tests/fuzz/fuzz_path_plan): a tolerance of 1e-12 asked for 3e12 sections,
// converted to int out of range (undefined behaviour) and would have exhausted memory.
TEST(Path, CircWithATooFineToleranceIsRefused) {
  const Eigen::Quaterniond q = Eigen::Quaterniond::Identity();
  const Posed a(q, V(1, 0, 0)), via(q, V(0, 1, 0)), b(q, V(-1, 0, 0));
  const std::string m = message_of([&] { Path::circ(a, via, b, V::Zero(), 1e-12); });
  EXPECT_EQ(m.rfind("tolerance = 1e-12: is too fine for this arc: it needs ", 0), 0u) << m;
  EXPECT_EQ(Path::circ(a, via, b, V::Zero(), 1e-5).size(), 314160u);  // a fine tolerance still works
}

TEST(Path, CircleThroughThreePoints) {
  Random rnd(102);
  const int n = testing::case_count(10000);
  for (int i = 0; i < n; ++i) {
    const V center = rnd.vector(2.0), normal = rnd.unit_vector();
    const double radius = std::exp(rnd.uniform(std::log(1e-3), std::log(10.0)));
    const V e1 = normal.unitOrthogonal(), e2 = normal.cross(e1);
    auto on_circle = [&](double phi) { return V(center + radius * (std::cos(phi) * e1 + std::sin(phi) * e2)); };
    // Arcs from tiny to nearly a full turn, via anywhere strictly inside.
    const double start = rnd.uniform(-pi, pi);
    const double span = i % 10 == 0 ? rnd.uniform(1e-4, 1e-2) : rnd.uniform(0.01, 2 * pi - 0.01);
    const double via = start + span * rnd.uniform(0.1, 0.9);
    const CircleThroughPoints c = circle_through(on_circle(start), on_circle(via), on_circle(start + span));
    const double scale = radius + center.norm();
    ASSERT_LT((c.center - center).norm(), 1e-9 * scale / std::min(1.0, span)) << i;
    ASSERT_NEAR(c.radius, radius, 1e-9 * scale / std::min(1.0, span)) << i;
    ASSERT_NEAR(std::abs(c.normal.dot(normal)), 1.0, 1e-9);
    ASSERT_NEAR(c.angle, span, 1e-7 / std::min(1.0, span)) << "span " << span;
  }
}

TEST(Path, CircFollowsTheArcAndSlerpsTheOrientation) {
  Random rnd(103);
  for (int i = 0; i < 40; ++i) {
    const V center = rnd.vector(0.5), normal = rnd.unit_vector();
    const double radius = rnd.uniform(0.05, 1.0);
    const V e1 = normal.unitOrthogonal(), e2 = normal.cross(e1);
    auto on_circle = [&](double phi) { return V(center + radius * (std::cos(phi) * e1 + std::sin(phi) * e2)); };
    const double span = i % 2 ? rnd.uniform(3.5, 6.0) : rnd.uniform(0.1, 3.0);  // over and under 180°
    const V pivot = rnd.vector(0.2);
    const Eigen::Quaterniond qa = rnd.rotation();
    const Eigen::Quaterniond qb = qa * Eigen::Quaterniond(Eigen::AngleAxisd(rnd.uniform(0, 3.0), rnd.unit_vector()));
    auto pose_with_pivot_at = [&](const Eigen::Quaterniond& q, const V& c) { return Posed(q, c - q * pivot); };
    const Posed a = pose_with_pivot_at(qa, on_circle(0.0));
    const Posed via = pose_with_pivot_at(rnd.rotation(), on_circle(span * 0.3));
    const Posed b = pose_with_pivot_at(qb, on_circle(span));
    const Path path = Path::circ(a, via, b, pivot);
    ASSERT_GE(path.size(), static_cast<std::size_t>(span / 1e-3)) << "a curved path is cut finely";
    ASSERT_TRUE(path.start().is_approx(a, 1e-12));
    ASSERT_TRUE(path.end().is_approx(b, 1e-12)) << i;
    const Eigen::Vector3d total = quaternion_log(Eigen::Quaterniond(qb * qa.conjugate()));
    for (int k = 0; k <= 200; ++k) {
      const double u = k / 200.0;
      const Posed p = path.sample(u);
      const V c = p * pivot;
      ASSERT_NEAR((c - center).norm(), radius, 1e-12 * (1 + center.norm()));
      ASSERT_NEAR((c - center).dot(normal), 0.0, 1e-12 * (1 + center.norm()));
      // The orientation has turned by the same fraction of the total as the pivot's angle.
      const V rc = c - center;
      double phi = std::atan2(normal.dot(e1.cross(rc)), e1.dot(rc));
      if (phi < -1e-9) phi += 2 * pi;
      const Eigen::Quaterniond expected =
          Eigen::Quaterniond(Eigen::AngleAxisd(phi / span * total.norm(), total.normalized())) * qa;
      ASSERT_LT(p.quaternion().angularDistance(expected), 1e-9) << "u " << u;
    }
  }
}

TEST(Path, CircSectionsJoinWithContinuousVelocity) {
  Random rnd(104);
  const Posed a = rnd.pose(), via = Posed(rnd.rotation(), a.translation() + V(0.3, 0.1, 0)),
              b = Posed(rnd.rotation(), a.translation() + V(0.1, 0.4, 0.05));
  const Path path = Path::circ(a, via, b);
  const auto& sections = path.sections();
  const double h = 1e-6;
  for (std::size_t k = 0; k + 1 < sections.size(); ++k) {
    const Posed end = section_end(sections[k]), next = section_start(sections[k + 1]);
    ASSERT_TRUE(end.is_approx(next, 1e-14)) << "sections join, k = " << k;
    // Velocity per unit τ at the end of k equals that at the start of k + 1 (equal sections).
    const V v_end =
        (section_pose(sections[k], 1.0).translation() - section_pose(sections[k], 1.0 - h).translation()) / h;
    const V v_next =
        (section_pose(sections[k + 1], h).translation() - section_pose(sections[k + 1], 0.0).translation()) / h;
    ASSERT_LT((v_end - v_next).norm(), 1e-6 * (1 + v_end.norm())) << k;
  }
}

// The arc bound: never below the sampled speed, above it by at most (2 + θ) δ — the reference
// section may itself be δ faster than the arc, and the bound adds (1 + θ) δ (doc/section-length.md
// doc/section-length.md eq. 14, which keeps the guarantee of doc/planning.md eq. 5 for arcs: conservative, tight as
// sections shrink).
TEST(Path, ArcSectionLengthBoundsTheSampledMotion) {
  Random rnd(105);
  const int n = std::max(20, testing::case_count(10000) / 50);
  for (int i = 0; i < n; ++i) {
    ArcSection arc;
    arc.start = rnd.pose(0.5);
    arc.pivot = rnd.vector(0.2);
    arc.center = arc.start * arc.pivot + rnd.vector(0.5);
    arc.normal = (arc.start * arc.pivot - arc.center).unitOrthogonal();
    arc.angle = rnd.uniform(1e-3, 0.5) * (i % 2 ? 1 : -1);
    arc.rotation_axis = rnd.unit_vector();
    arc.rotation_angle = i % 5 == 0 ? 0.0 : rnd.uniform(0, 0.5);
    MetricSetd set;
    const bool absolute = i % 3 == 0;
    for (int k = 0; k < 4; ++k)
      set.add_points({rnd.vector(absolute ? 1.0 : 0.4)}, absolute ? Frame::absolute : Frame::relative);
    const double length = arc.length(set, std::nullopt);
    const double sampled = sampled_speed(set, [&](double t) { return arc.pose(t); });
    ASSERT_GE(length, sampled * (1 - 1e-7)) << "case " << i;
    ASSERT_LE(length - sampled, (2 + arc.rotation_angle) * arc.deviation_bound() + 1e-7 * sampled) << "case " << i;
  }
}

// Cut with the default tolerance, a CIRC's sections exceed the exact speed of a set containing
// the pivot by at most that tolerance.
TEST(Path, CircSectionLengthsAreTight) {
  Random rnd(106);
  for (int i = 0; i < 5; ++i) {
    const Posed a = rnd.pose(0.2);
    const Posed via(rnd.rotation(), a.translation() + rnd.vector(0.3));
    const Posed b(a.quaternion() * Eigen::Quaterniond(Eigen::AngleAxisd(0.7, rnd.unit_vector())),
                  a.translation() + rnd.vector(0.3));
    const double tolerance = 1e-3;
    const Path path = Path::circ(a, via, b, V::Zero(), tolerance);
    MetricSetd set;  // the TCP (the pivot) and a small tool around it
    set.add_relative(std::vector<V>{V::Zero(), V(0.02, 0, 0), V(0, 0.02, 0), V(0, 0, 0.02)});
    const auto lengths = path.section_lengths(set);
    for (int k = 0; k < 10; ++k) {
      const std::size_t j = static_cast<std::size_t>(rnd.integer(0, static_cast<int>(path.size()) - 1));
      const double sampled = sampled_speed(set, [&](double t) { return section_pose(path.sections()[j], t); });
      ASSERT_GE(lengths[j], sampled * (1 - 1e-7));
      ASSERT_LE(lengths[j], sampled * (1 + tolerance)) << "section " << j << " of " << path.size();
    }
  }
}

TEST(Path, SampleSpreadsUOverTheSectionsByTheirSize) {
  Random rnd(107);
  const Posed a = rnd.pose();
  const Posed b = a * Posed(Eigen::Quaterniond::Identity(), V(0.2, 0, 0));
  const Posed c = b * Posed(Eigen::Quaterniond::Identity(), V(0, 0.1, 0));
  const Posed d = c * Posed(Eigen::Quaterniond(Eigen::AngleAxisd(1.0, V::UnitZ())), V::Zero());
  Path path = Path::lin(a, b);
  path.then(Path::lin(b, c)).then(Path::lin(c, d));
  ASSERT_EQ(path.size(), 3u);
  // Sizes 0.2 m, 0.1 m and 1 rad = 0.1 m: u = 0.25 is halfway along the first, 0.625 halfway
  // along the second, 0.875 halfway through the turn.
  EXPECT_TRUE(path.sample(0.25).is_approx(a * Posed(Eigen::Quaterniond::Identity(), V(0.1, 0, 0)), 1e-14));
  EXPECT_TRUE(path.sample(0.625).is_approx(b * Posed(Eigen::Quaterniond::Identity(), V(0, 0.05, 0)), 1e-14));
  EXPECT_TRUE(path.sample(0.875).is_approx(c * Posed(Eigen::Quaterniond(Eigen::AngleAxisd(0.5, V::UnitZ())), V::Zero()),
                                           1e-14));
  EXPECT_TRUE(path.sample(1.0).is_approx(d, 1e-14));
  EXPECT_TRUE(path.sample(-3.0).is_approx(a, 1e-15));
  EXPECT_TRUE(path.sample(7.0).is_approx(d, 1e-14));
}

TEST(Path, PtpIsALineInJointSpace) {
  Eigen::VectorXd qa(6), qb(6);
  qa << 0, 1, 2, 3, 4, 5;
  qb << 1, 1, 0, 3, -4, 5;
  const JointPath ptp(qa, qb);
  EXPECT_LT((ptp.sample(0.25) - (qa + 0.25 * (qb - qa))).norm(), 1e-15);
  EXPECT_LT((ptp.sample(2.0) - qb).norm(), 1e-15);
  Eigen::VectorXd short_q(5);
  short_q.setZero();
  EXPECT_NE(message_of([&] { JointPath(qa, short_q); }).find("q_end size = 5"), std::string::npos);
  qb(2) = std::nan("");
  EXPECT_NE(message_of([&] { JointPath(qa, qb); }).find("q_end"), std::string::npos);
}

// Matrix ↔ quaternion (Eigen's largest-component method) near 180°.
TEST(Path, RotationConversionsNearHalfTurn) {
  Random rnd(108);
  for (const double gap : {0.0, 1e-15, 1e-12, 1e-9, 1e-6, 1e-3}) {
    for (int i = 0; i < 1000; ++i) {
      const Eigen::Matrix3d r = Eigen::AngleAxisd(pi - gap, rnd.unit_vector()).toRotationMatrix();
      const Posed p(r, V::Zero());
      ASSERT_LT((p.rotation() - r).cwiseAbs().maxCoeff(), 4e-15) << gap;
      ASSERT_NEAR(p.log().angular.norm(), pi - gap, 1e-9) << gap;
    }
  }
}

// A path made again from its sections and move sizes samples the same, bit for bit, and a
// blend appended to it takes what it would have taken from the original.
TEST(Path, FromSectionsMakesTheSamePath) {
  Random rnd(107);
  for (int i = 0; i < 200; ++i) {
    const V pivot = rnd.vector(0.2);
    const Posed a = rnd.pose(), b = rnd.pose(), c = rnd.pose(), d = rnd.pose();
    Path path = Path::lin(a, b, Interpolation::decoupled, pivot);
    path.then(Path::circ(b, c, d, pivot));
    const Path copy = Path::from_sections(path.sections(), path.first_move_size(), path.last_move_size());
    ASSERT_EQ(copy.size(), path.size());
    for (int k = 0; k <= 100; ++k) {
      const Posed x = copy.sample(k / 100.0), y = path.sample(k / 100.0);
      ASSERT_EQ(x.quaternion().coeffs(), y.quaternion().coeffs());
      ASSERT_EQ(x.translation(), y.translation());
    }
    EXPECT_EQ(copy.first_move_size(), path.first_move_size());
    EXPECT_EQ(copy.last_move_size(), path.last_move_size());
  }
}

TEST(PathBadInput, FromSections) {
  const Posed a;
  const Posed b = Posed::from_xyzuvw((Eigen::Matrix<double, 6, 1>() << 1, 0, 0, 0, 0, 0).finished());
  const Posed off = Posed::from_xyzuvw((Eigen::Matrix<double, 6, 1>() << 0.5, 0.5, 0, 0, 0, 0).finished());
  const std::vector<Section> gap{LinSection{a, b}, LinSection{off, a}};
  EXPECT_NE(message_of([&] { Path::from_sections(gap, 1.0, 1.0); }).find("must start where the path ends"),
            std::string::npos);
  EXPECT_NE(message_of([&] { Path::from_sections({}, 1.0, 1.0); }).find("sections"), std::string::npos);
  EXPECT_NE(message_of([&] {
              Path::from_sections({LinSection{a, b}}, 0.0, 1.0);
            }).find("first_move_size = 0"),
            std::string::npos);
}

TEST(PathBadInput, Arguments) {
  const Posed a;
  const Posed b = Posed::from_xyzuvw((Eigen::Matrix<double, 6, 1>() << 1, 0, 0, 0, 0, 0).finished());
  const Posed mid = Posed::from_xyzuvw((Eigen::Matrix<double, 6, 1>() << 0.5, 0, 0, 0, 0, 0).finished());
  const Posed off = Posed::from_xyzuvw((Eigen::Matrix<double, 6, 1>() << 0.5, 0.5, 0, 0, 0, 0).finished());
  EXPECT_NE(message_of([&] { Path::circ(a, mid, b); }).find("collinear"), std::string::npos);
  EXPECT_NE(message_of([&] { Path::circ(a, a, b); }).find("via"), std::string::npos);
  EXPECT_NE(message_of([&] { Path::circ(a, off, a); }).find("end"), std::string::npos);
  EXPECT_NE(message_of([&] { Path::circ(a, off, b, V::Zero(), 0.0); }).find("tolerance = 0"), std::string::npos);
  EXPECT_NE(message_of([&] { Path::lin(a, a); }).find("coincide"), std::string::npos);
  EXPECT_NE(message_of([&] { Path::lin(a, b, Interpolation::decoupled, V(std::nan(""), 0, 0)); }).find("pivot"),
            std::string::npos);
  Path path = Path::lin(a, b);
  EXPECT_NE(message_of([&] { path.then(Path::lin(off, a)); }).find("must start where the path ends"),
            std::string::npos);
}

}  // namespace
}  // namespace dispkin
