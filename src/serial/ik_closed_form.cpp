// The closed-form families: spherical wrist (Pieper) and three parallel axes (Universal
// Robots), each a fixed sequence of subproblems giving at most 8 solutions, without heap
// allocation. With G = T_target M⁻¹ the unknowns satisfy e₁e₂e₃e₄e₅e₆ = G.
#include "ik_internal.hpp"

namespace dispkin {
namespace serial {
namespace detail {

// A unit vector normal to k (for subproblem 1 on a whole rotation).
inline Eigen::Vector3d normal_to(const Eigen::Vector3d& k) {
  const Eigen::Vector3d seed = std::abs(k.x()) < 0.9 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY();
  return k.cross(seed).normalized();
}

void spherical_wrist_inverse(const RevoluteChain& chain, const ChainGeometry& geometry, const Posed& pose,
                             IkSolutionSet& out) {
  const Posed g = pose * chain.tip_at_zero.inverse();
  const Eigen::Matrix3d g_rotation = g.rotation();
  const Eigen::Vector3d& c = geometry.wrist_centre;
  const Eigen::Vector3d& w4 = chain.axes[3];
  const Eigen::Vector3d& w5 = chain.axes[4];
  const Eigen::Vector3d& w6 = chain.axes[5];
  const Eigen::Vector3d x6 = normal_to(w6);
  // e₄e₅e₆ fix the wrist centre: e₁e₂e₃ c = G c.
  const PositionSolutions arm = solve_position(chain, geometry, c, g * c);
  for (std::size_t b = 0; b < 4; ++b) {
    if (!arm.exists[b]) continue;
    const Eigen::Vector3d t = arm.angles(b);
    // R₄R₅R₆ = (R₁R₂R₃)ᵀ R_G: R₄R₅ ω₆ = R_w ω₆ (subproblem 2), then q₆ (subproblem 1).
    const Eigen::Matrix3d r123 = rotation(chain.axes[0], t(0)) * rotation(chain.axes[1], t(1)) * rotation(chain.axes[2], t(2));
    const Eigen::Matrix3d r_wrist = r123.transpose() * g_rotation;
    const AnglePairs q45 = subproblem2(w4, w5, w6, r_wrist * w6);
    if (!q45.exists) continue;
    for (std::size_t l = 0; l < (q45.single ? 1u : 2u); ++l) {
      const double q4 = q45.first[l].angle();
      const double q5 = q45.second[l].angle();
      const Eigen::Matrix3d r45 = rotation(w4, q4) * rotation(w5, q5);
      const double q6 = subproblem1(w6, x6, r45.transpose() * r_wrist * x6);
      Vector6d q;
      q << t, q4, q5, q6;
      offer(chain, pose, q, out);
    }
  }
}

bool three_parallel_inverse(const RevoluteChain& chain, const ChainGeometry& geometry, const Posed& pose,
                            IkSolutionSet& out) {
  bool near_singular = false;
  const Posed g = pose * chain.tip_at_zero.inverse();
  const Eigen::Matrix3d g_rotation = g.rotation();
  const Eigen::Vector3d& w1 = chain.axes[0];
  const Eigen::Vector3d& w2 = chain.axes[1];
  const Eigen::Vector3d& w3 = chain.axes[2];
  const Eigen::Vector3d& w4 = chain.axes[3];
  const Eigen::Vector3d& w5 = chain.axes[4];
  const Eigen::Vector3d& w6 = chain.axes[5];
  const Eigen::Vector3d& p1 = chain.points[0];
  const Eigen::Vector3d& p2 = chain.points[1];
  const Eigen::Vector3d& p3 = chain.points[2];
  const Eigen::Vector3d& p4 = chain.points[3];
  const Eigen::Vector3d& c = geometry.point_56;
  const Eigen::Vector3d x4 = normal_to(w4);
  // e₂e₃e₄ keep the component along ω₂, e₅e₆ fix c = axes 5 ∩ 6: ω₂ · e₁⁻¹ G c = ω₂ · c.
  const Angles q1s = subproblem4(w2, w1, g * c - p1, w2.dot(c - p1));
  if (!q1s.exists) return false;
  for (int l1 = 0; l1 < (q1s.single() ? 1 : 2); ++l1) {
    const double q1 = -(l1 == 0 ? q1s.plus : q1s.minus).angle();
    const Eigen::Matrix3d r1 = rotation(w1, q1);
    // Orientation along ω₂: ω₂ᵀ R₅ ω₆ = (R₁ ω₂)ᵀ R_G ω₆ (subproblem 4 in q₅).
    const Angles q5s = subproblem4(w2, w5, w6, (r1 * w2).dot(g_rotation * w6));
    if (!q5s.exists) continue;
    for (int l5 = 0; l5 < (q5s.single() ? 1 : 2); ++l5) {
      const double q5 = (l5 == 0 ? q5s.plus : q5s.minus).angle();
      // R₆ᵀ R₅ᵀ ω₂ = R_Gᵀ R₁ ω₂ (subproblem 1 in −q₆).
      const Eigen::Vector3d u = rotate(w5, -q5, w2);
      const double q6 = -subproblem1(w6, u, g_rotation.transpose() * (r1 * w2));
      // Wrist singularity (R₅ᵀω₂ ∥ ω₆: axes 2, 3, 4, 6 parallel): q₆ and q₂ + q₃ + q₄ share one
      // planar motion, so q₆ is (nearly) free, but only an interval of q₆ leaves the elbow in
      // reach — a tiny one near the stretched elbow. Besides subproblem 1's value, take the q₆
      // that puts the elbow distance ‖H p₄ − p₂‖ mid-way in the range both the elbow (q₃) and
      // the circle of q₆ allow (subproblem 3 in −q₆); Newton then settles each on the pose.
      std::array<double, 3> q6_candidates{{q6, 0.0, 0.0}};
      std::size_t q6_count = 1;
      if (u.cross(w6).norm() < 1e-6) {
        near_singular = true;
        const Posed a = rotation_about_line(w1, p1, -q1) * g;
        const Eigen::Vector3d& p6 = chain.points[5];
        const Eigen::Vector3d u6 = rotation_about_line(w5, chain.points[4], -q5) * p4 - p6;
        const Eigen::Vector3d v6 = a.inverse() * p2 - p6;
        // ‖R(k, θ) u − v‖² ranges over base ± 2 ‖u⊥‖ ‖v⊥‖.
        auto range = [](const Eigen::Vector3d& k, const Eigen::Vector3d& uu, const Eigen::Vector3d& vv) {
          const double base = uu.squaredNorm() + vv.squaredNorm() - 2.0 * k.dot(uu) * k.dot(vv);
          const double spread = 2.0 * (uu - k.dot(uu) * k).norm() * (vv - k.dot(vv) * k).norm();
          return std::array<double, 2>{{base - spread, base + spread}};
        };
        const auto elbow = range(w3, p4 - p3, p2 - p3);
        const auto circle = range(w6, u6, v6);
        const double lo = std::max(elbow[0], circle[0]);
        const double hi = std::min(elbow[1], circle[1]);
        if (lo <= hi) {
          const Angles minus_q6 = subproblem3(w6, u6, v6, std::sqrt(std::max(0.0, 0.5 * (lo + hi))));
          if (minus_q6.exists) {
            q6_candidates[q6_count++] = -minus_q6.plus.angle();
            q6_candidates[q6_count++] = -minus_q6.minus.angle();
          }
        }
      }
      for (std::size_t k6 = 0; k6 < q6_count; ++k6) {
        const double q6k = q6_candidates[k6];
        // H = e₁⁻¹ G e₆⁻¹ e₅⁻¹ = e₂e₃e₄; e₄ fixes p₄, so e₂e₃ p₄ = H p₄: subproblems 3 and 1.
        const Posed h = rotation_about_line(w1, p1, -q1) * g * rotation_about_line(w6, chain.points[5], -q6k) *
                        rotation_about_line(w5, chain.points[4], -q5);
        const Eigen::Vector3d y = h * p4;
        const Angles q3s = subproblem3(w3, p4 - p3, p2 - p3, (y - p2).norm());
        if (!q3s.exists) continue;
        const Eigen::Matrix3d h_rotation = h.rotation();
        for (int l3 = 0; l3 < (q3s.single() ? 1 : 2); ++l3) {
          const double q3 = (l3 == 0 ? q3s.plus : q3s.minus).angle();
          const Eigen::Vector3d y3 = rotate(w3, q3, p4 - p3) + p3;
          const double q2 = subproblem1(w2, y3 - p2, y - p2);
          // R₄ = R₃ᵀ R₂ᵀ R_H about ω₄.
          const Eigen::Matrix3d r4 = rotation(w3, -q3) * rotation(w2, -q2) * h_rotation;
          const double q4 = subproblem1(w4, x4, r4 * x4);
          Vector6d q;
          q << q1, q2, q3, q4, q5, q6k;
          offer(chain, pose, q, out);
        }
      }
    }
  }
  return near_singular;
}

}  // namespace detail
}  // namespace serial
}  // namespace dispkin
