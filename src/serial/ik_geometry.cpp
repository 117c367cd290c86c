// The special geometry of a 6R chain's axes (which lines meet, which are parallel), the
// family it implies (doc/inverse-kinematics.md §4), and the positioning stage shared by the spherical-wrist and
// offset-wrist solvers.
#include <cmath>
#include <string>

#include "dispkin/error.hpp"
#include "ik_internal.hpp"

namespace dispkin {
namespace serial {
namespace detail {
namespace {

// The axis of joint i (0-based) as a line.
struct Line {
  Eigen::Vector3d point;
  Eigen::Vector3d direction;
};

Line axis(const RevoluteChain& chain, int i) {
  return {chain.points[static_cast<std::size_t>(i)], chain.axes[static_cast<std::size_t>(i)]};
}

bool parallel(const Line& a, const Line& b, double tolerance) {
  return a.direction.cross(b.direction).norm() <= tolerance;
}

// Distance between two parallel lines.
double parallel_gap(const Line& a, const Line& b) { return (b.point - a.point).cross(a.direction).norm(); }

double distance_to_line(const Eigen::Vector3d& x, const Line& l) { return (x - l.point).cross(l.direction).norm(); }

// Whether two non-parallel lines meet (common normal shorter than `tolerance`), and where:
// the midpoint of the common normal.
bool meet(const Line& a, const Line& b, double tolerance, Eigen::Vector3d& point) {
  const Eigen::Vector3d n = a.direction.cross(b.direction);
  const double n2 = n.squaredNorm();
  if (n2 <= tolerance * tolerance) return false;
  const Eigen::Vector3d d = b.point - a.point;
  if (std::abs(d.dot(n)) / std::sqrt(n2) > tolerance) return false;
  // a.point + s a.dir and b.point + t b.dir closest: s = (d × b.dir)·n / n², t = (d × a.dir)·n / n².
  const double s = d.cross(b.direction).dot(n) / n2;
  const double t = d.cross(a.direction).dot(n) / n2;
  point = 0.5 * (a.point + s * a.direction + b.point + t * b.direction);
  return true;
}

}  // namespace

void validate_chain(const RevoluteChain& chain) {
  if (chain.axes.size() != chain.points.size())
    throw std::invalid_argument(describe("chain.points", static_cast<long>(chain.points.size()),
                                         "expected one point per axis (" + std::to_string(chain.axes.size()) + ")"));
  if (chain.dof() != 6)
    throw std::invalid_argument(describe("chain.axes", static_cast<long>(chain.axes.size()),
                                         "analytic IK needs a 6R chain, expected 6 joints"));
  for (std::size_t i = 0; i < 6; ++i) {
    const bool fine =
        chain.axes[i].allFinite() && chain.points[i].allFinite() && std::abs(chain.axes[i].norm() - 1.0) <= 1e-9;
    if (fine) continue;  // messages are only built on failure: the real-time path checks too
    const std::string index = "[" + std::to_string(i) + "]";
    require_finite(chain.axes[i], "chain.axes" + index);
    require_finite(chain.points[i], "chain.points" + index);
    require(false, "chain.axes" + index, chain.axes[i],
            "must be a unit vector, its norm is " + std::to_string(chain.axes[i].norm()));
  }
}

namespace {

// The family and the special lines of the axes with `tolerance` (analyse without the constants).
ChainGeometry classify(const RevoluteChain& chain, double tolerance) {
  ChainGeometry g;
  const Line a1 = axis(chain, 0), a2 = axis(chain, 1), a3 = axis(chain, 2);
  const Line a4 = axis(chain, 3), a5 = axis(chain, 4), a6 = axis(chain, 5);

  // Positioning stage: axes 2 ∥ 3 as distinct lines with axis 1 crossing their direction, or a
  // shoulder point 1 ∩ 2 off axis 3.
  g.axes_12_meet = meet(a1, a2, tolerance, g.shoulder);
  if (parallel(a2, a3, tolerance) && !parallel(a1, a2, tolerance) && parallel_gap(a2, a3) > tolerance) {
    g.layout = PositionLayout::parallel_23;
  } else if (g.axes_12_meet && distance_to_line(g.shoulder, a3) > tolerance) {
    g.layout = PositionLayout::intersecting_12;
  }

  g.axes_45_meet = meet(a4, a5, tolerance, g.point_45);
  Eigen::Vector3d p56;
  const bool meet_56 = meet(a5, a6, tolerance, p56);
  g.wrist_meets = g.axes_45_meet && meet_56 && (g.point_45 - p56).norm() <= tolerance;
  if (g.wrist_meets) g.wrist_centre = 0.5 * (g.point_45 + p56);

  // Spherical wrist (Pieper): the wrist centre is placed by joints 1–3, off axis 3.
  if (!g.wrist_meets) {
    g.why_not_spherical = "the last three axes do not meet in one point";
  } else if (g.layout == PositionLayout::none) {
    g.why_not_spherical = "the wrist is spherical but the first three axes have neither 2 ∥ 3 nor 1 ∩ 2";
  } else if (distance_to_line(g.wrist_centre, a3) <= tolerance) {
    g.why_not_spherical = "the wrist centre lies on axis 3";
  }

  // Three parallel (UR): 2 ∥ 3 ∥ 4 as distinct lines, 5 ∩ 6, and axes 1 and 5 not parallel to 2.
  g.point_56 = p56;
  if (!(parallel(a2, a3, tolerance) && parallel(a3, a4, tolerance))) {
    g.why_not_three_parallel = "axes 2, 3, 4 are not parallel";
  } else if (parallel_gap(a2, a3) <= tolerance || parallel_gap(a3, a4) <= tolerance) {
    g.why_not_three_parallel = "two of the parallel axes 2, 3, 4 coincide";
  } else if (!meet_56) {
    g.why_not_three_parallel = "axes 5 and 6 do not meet";
  } else if (parallel(a1, a2, tolerance) || parallel(a5, a2, tolerance)) {
    g.why_not_three_parallel = "axis 1 or axis 5 is parallel to axes 2, 3, 4";
  } else {
    g.three_parallel = true;
  }

  // Offset wrist: axes 4 ∩ 5 off axis 6 — their meeting point circles axis 6 as q₆
  // turns — placed by joints 1–3.
  if (!g.axes_45_meet) {
    g.why_not_offset = "axes 4 and 5 do not meet";
  } else if (distance_to_line(g.point_45, a6) <= tolerance) {
    g.why_not_offset = "axes 4 and 5 meet on axis 6 (a spherical wrist)";
  } else if (g.layout == PositionLayout::none) {
    g.why_not_offset = "the first three axes have neither 2 ∥ 3 nor 1 ∩ 2";
  } else if (distance_to_line(g.point_45, a3) <= tolerance) {
    g.why_not_offset = "axes 4 and 5 meet on axis 3";
  }

  if (*g.why_not_spherical == '\0') {
    g.family = IkFamily::spherical_wrist;
  } else if (g.three_parallel) {
    g.family = IkFamily::three_parallel;
  } else if (*g.why_not_offset == '\0') {
    g.family = IkFamily::offset_wrist;
  }
  return g;
}

// A unit vector normal to k (for subproblem 1 on a whole rotation).
Eigen::Vector3d normal_to(const Eigen::Vector3d& k) {
  const Eigen::Vector3d seed = std::abs(k.x()) < 0.9 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY();
  return k.cross(seed).normalized();
}

}  // namespace

ChainGeometry analyse(const RevoluteChain& chain, double tolerance) {
  ChainGeometry g = classify(chain, tolerance);
  const Motion m = Motion::of(chain.tip_at_zero);
  g.tip_inverse = m.inverse();
  g.tool = JointThen(chain, 5, m);
  g.normal_4 = normal_to(chain.axes[3]);
  g.normal_6 = normal_to(chain.axes[5]);
  if (g.family == IkFamily::spherical_wrist || g.family == IkFamily::three_parallel) {
    const ChainGeometry strict = classify(chain, exact_fit_tolerance);
    g.exact_fit = strict.family == g.family && strict.layout == g.layout;
    const Eigen::Vector3d& w4 = chain.axes[3];
    const Eigen::Vector3d& w5 = chain.axes[4];
    const Eigen::Vector3d& w6 = chain.axes[5];
    g.wrist_flips = g.exact_fit && g.family == IkFamily::spherical_wrist &&
                    std::abs(w4.dot(w5)) <= exact_fit_tolerance && std::abs(w5.dot(w6)) <= exact_fit_tolerance &&
                    w4.cross(w6).norm() <= exact_fit_tolerance;
    if (g.wrist_flips && g.layout == PositionLayout::parallel_23)
      g.ortho_parallel = make_ortho_parallel(chain, g.wrist_centre, g.ortho);
    if (g.exact_fit && g.family == IkFamily::three_parallel)
      g.three_parallel_plane = make_three_parallel_plane(chain, g.point_56, g.plane);
  }
  return g;
}

namespace {

// ‖e₃ x − o‖ = ‖y − o‖ as an equation of q₃ (subproblem 3), o = axes 1 ∩ 2: e₁e₂ fix o.
Harmonic shoulder_distance_harmonic(const RevoluteChain& chain, const ChainGeometry& geometry, const Eigen::Vector3d& x,
                                    const Eigen::Vector3d& y) noexcept {
  const Eigen::Vector3d& o = geometry.shoulder;
  const Eigen::Vector3d& p3 = chain.points[2];
  return subproblem3_harmonic(chain.axes[2], x - p3, o - p3, (y - o).squaredNorm());
}

}  // namespace

Harmonic first_positioning_harmonic(const RevoluteChain& chain, const ChainGeometry& geometry, const Eigen::Vector3d& x,
                                    const Eigen::Vector3d& y) noexcept {
  if (geometry.layout == PositionLayout::parallel_23) {
    // e₂e₃ keeps the component along ω₂: ω₂ · e₁⁻¹ y = ω₂ · x (subproblem 4 in −q₁).
    const Eigen::Vector3d& p1 = chain.points[0];
    return subproblem4_harmonic(chain.axes[1], chain.axes[0], y - p1, chain.axes[1].dot(x - p1));
  }
  return shoulder_distance_harmonic(chain, geometry, x, y);
}

bool elbow_independent_of_q1(const ChainGeometry& geometry) noexcept {
  return geometry.layout == PositionLayout::parallel_23 && geometry.axes_12_meet;
}

Harmonic elbow_harmonic(const RevoluteChain& chain, const ChainGeometry& geometry, const Eigen::Vector3d& x,
                        const Eigen::Vector3d& y) noexcept {
  // q₃ keeps ‖e₃ x − o‖ = ‖e₁⁻¹ y − o‖ for any point o of axis 2; o on axis 1 too makes the
  // right side ‖y − o‖, whatever q₁ is.
  return shoulder_distance_harmonic(chain, geometry, x, y);
}

PositionSolutions solve_position(const RevoluteChain& chain, const ChainGeometry& geometry, const Eigen::Vector3d& x,
                                 const Eigen::Vector3d& y) noexcept {
  PositionSolutions out;
  const Eigen::Vector3d& w1 = chain.axes[0];
  const Eigen::Vector3d& w2 = chain.axes[1];
  const Eigen::Vector3d& w3 = chain.axes[2];
  const Eigen::Vector3d& p1 = chain.points[0];
  const Eigen::Vector3d& p2 = chain.points[1];
  const Eigen::Vector3d& p3 = chain.points[2];
  if (geometry.layout == PositionLayout::parallel_23) {
    // q₁ by subproblem 4 (first_positioning_harmonic); then the distance to axis 2 fixes q₃
    // (subproblem 3) and q₂ turns it into place (subproblem 1).
    const Angles q1 = solve_harmonic(first_positioning_harmonic(chain, geometry, x, y));
    out.margin.fill(q1.margin);
    if (!q1.exists) return out;
    for (int l1 = 0; l1 < 2; ++l1) {
      const CosSin minus_q1 = l1 == 0 ? q1.plus : q1.minus;          // the subproblem's angle is −q₁
      const Eigen::Vector3d y1 = rotate(w1, minus_q1, y - p1) + p1;  // e₁⁻¹ y
      const Angles q3 = subproblem3(w3, x - p3, p2 - p3, (y1 - p2).squaredNorm());
      out.margin[static_cast<std::size_t>(2 * l1)] = out.margin[static_cast<std::size_t>(2 * l1 + 1)] =
          std::min(q1.margin, q3.margin);
      if (!q3.exists) continue;
      for (int l3 = 0; l3 < 2; ++l3) {
        const CosSin t3 = l3 == 0 ? q3.plus : q3.minus;
        const Eigen::Vector3d x3 = rotate(w3, t3, x - p3) + p3;  // e₃ x
        const auto b = static_cast<std::size_t>(2 * l1 + l3);
        out.q[b] = {minus_q1.inverse(), subproblem1_cs(w2, x3 - p2, y1 - p2), t3};
        out.exists[b] = true;
      }
    }
  } else if (geometry.layout == PositionLayout::intersecting_12) {
    // q₃ by subproblem 3 (first_positioning_harmonic), then q₁, q₂ by subproblem 2.
    const Eigen::Vector3d& o = geometry.shoulder;
    const Angles q3 = solve_harmonic(first_positioning_harmonic(chain, geometry, x, y));
    out.margin.fill(q3.margin);
    if (!q3.exists) return out;
    for (int l3 = 0; l3 < 2; ++l3) {
      const CosSin t3 = l3 == 0 ? q3.plus : q3.minus;
      const Eigen::Vector3d x3 = rotate(w3, t3, x - p3) + p3;
      const AnglePairs q12 = subproblem2(w1, w2, x3 - o, y - o);
      out.margin[static_cast<std::size_t>(2 * l3)] = out.margin[static_cast<std::size_t>(2 * l3 + 1)] =
          std::min(q3.margin, q12.margin);
      if (!q12.exists) continue;
      for (int l = 0; l < 2; ++l) {
        const auto b = static_cast<std::size_t>(2 * l3 + l);
        out.q[b] = {q12.first[static_cast<std::size_t>(l)], q12.second[static_cast<std::size_t>(l)], t3};
        out.exists[b] = true;
      }
    }
  }
  return out;
}

}  // namespace detail
}  // namespace serial
}  // namespace dispkin
