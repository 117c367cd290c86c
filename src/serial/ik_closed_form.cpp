// The closed-form families: spherical wrist (Pieper) and three parallel axes (Universal
// Robots), each a fixed sequence of subproblems giving at most 8 solutions, without heap
// allocation. With G = T_target M⁻¹ the unknowns satisfy e₁e₂e₃e₄e₅e₆ = G.
#include "ik_internal.hpp"

namespace dispkin {
namespace serial {
namespace detail {

// Both closed forms work on cosines and sines end to end: every joint's motion is composed from
// the (cos, sin) its subproblem gives, so is the forward kinematics that checks a candidate,
// and only the returned joint values take an atan2. The check compares e₁ ⋯ e₆ M with the
// target seen from a link the candidates of a branch share, e.g. e_k⁻¹ ⋯ e₁⁻¹ T against
// e_{k+1} ⋯ e₆ M: a rigid motion applied to both sides changes neither the distance of the
// origins nor ‖R − R_target‖_F, so this is the full pose error, at a fraction of the products.

namespace {

// The positioning residual ‖e₁e₂e₃ c − G c‖ (m) below which a branch counts as exact: the
// polish threshold of offer().
constexpr double exact_position = 4e-15;

// Keeps a candidate exact to rounding (its joints from atan2, in [−π, π]; wrapped to (−π, π]).
// Exact candidates of different labels differ in the joint where their labels part, by more than
// the margin allows (≫ ik_duplicate_tolerance), so only a measured one, which Newton may have
// moved onto another root, can repeat one: `measured` says whether one was kept before.
void keep_exact(const RevoluteChain& chain, const Posed& pose, Vector6d q, bool measured, IkSolutionSet& out) {
  if (measured) return offer(chain, pose, q, PoseError{}, out);
  for (int i = 0; i < 6; ++i) q(i) = wrap_angle(q(i));
  out.push(q, 0.0);
}

// The measured path of the spherical wrist for one arm branch: every candidate's full pose error
// by the motions composed in link 3's frame, polished by offer() above 4e-15.
void spherical_wrist_measured(const RevoluteChain& chain, const ChainGeometry& geometry, const Posed& pose,
                              const Motion& target, const std::array<CosSin, 3>& t, const Eigen::Vector3d& arm_angles,
                              const Eigen::Vector3d& g_w6, const Eigen::Vector3d& g_x6, IkSolutionSet& out) {
  const Eigen::Vector3d& w4 = chain.axes[3];
  const Eigen::Vector3d& w5 = chain.axes[4];
  const Eigen::Vector3d& w6 = chain.axes[5];
  const Eigen::Vector3d& x6 = geometry.normal_6;
  const Motion e123 = joint_motion(chain, 0, t[0]) * joint_motion(chain, 1, t[1]) * joint_motion(chain, 2, t[2]);
  // R₄R₅R₆ = (R₁R₂R₃)ᵀ R_G: R₄R₅ ω₆ = R_w ω₆ (subproblem 2), then q₆ (subproblem 1).
  const AnglePairs q45 = subproblem2(w4, w5, w6, e123.r.transpose() * g_w6);
  if (!q45.exists) return;
  const Eigen::Vector3d x6_target = e123.r.transpose() * g_x6;
  const Motion target_from_3 = e123.inverse() * target;  // e₃⁻¹e₂⁻¹e₁⁻¹ T
  for (std::size_t l = 0; l < (q45.single ? 1u : 2u); ++l) {
    const Motion e4 = joint_motion(chain, 3, q45.first[l]);
    const Motion e5 = joint_motion(chain, 4, q45.second[l]);
    const CosSin q6 = subproblem1_cs(w6, x6, e5.r.transpose() * (e4.r.transpose() * x6_target));
    const Motion fk_from_3 = e4 * e5 * geometry.tool.at(q6);  // e₄e₅e₆ M
    Vector6d q;
    q << arm_angles, q45.first[l].angle(), q45.second[l].angle(), q6.angle();
    offer(chain, pose, q, motion_error(fk_from_3, target_from_3), out);
  }
}

}  // namespace

void spherical_wrist_inverse(const RevoluteChain& chain, const ChainGeometry& geometry, const Posed& pose,
                             IkSolutionSet& out) {
  if (geometry.ortho_parallel && ortho_parallel_inverse(geometry.ortho, pose, out)) return;
  const Motion target = Motion::of(pose);
  const Motion g = target * geometry.tip_inverse;
  const Eigen::Vector3d& c = geometry.wrist_centre;
  const Eigen::Vector3d& w1 = chain.axes[0];
  const Eigen::Vector3d& w2 = chain.axes[1];
  const Eigen::Vector3d& w3 = chain.axes[2];
  const Eigen::Vector3d& w4 = chain.axes[3];
  const Eigen::Vector3d& w5 = chain.axes[4];
  const Eigen::Vector3d& w6 = chain.axes[5];
  const Eigen::Vector3d& x6 = geometry.normal_6;
  const Eigen::Vector3d g_w6 = g.r * w6, g_x6 = g.r * x6;
  // e₄e₅e₆ fix the wrist centre: e₁e₂e₃ c = G c.
  const Eigen::Vector3d g_c = g * c;
  const PositionSolutions arm = solve_position(chain, geometry, c, g_c);
  bool measured = false;  // a measured candidate was offered
  double q1_angle = 0.0;
  CosSin q1_of_angle{2.0, 0.0};  // the q₁ whose angle q1_angle is (none yet)
  for (std::size_t b = 0; b < 4; ++b) {
    if (!arm.exists[b]) continue;
    const std::array<CosSin, 3>& t = arm.q[b];
    if (!(t[0] == q1_of_angle)) {  // branches of one q₁ share its atan2
      q1_angle = t[0].angle();
      q1_of_angle = t[0];
    }
    const Eigen::Vector3d arm_angles(q1_angle, t[1].angle(), t[2].angle());
    // R_w ω₆ and R_w x₆ with R_w = (R₁R₂R₃)ᵀ R_G (doc/inverse-kinematics.md eq. 11), and e₁e₂e₃ c: rotations of vectors
    // only.
    const auto from_base = [&](const Eigen::Vector3d& v) {
      return rotate(w3, t[2].inverse(), rotate(w2, t[1].inverse(), rotate(w1, t[0].inverse(), v)));
    };
    const Eigen::Vector3d a6 = from_base(g_w6);
    const AnglePairs q45 = subproblem2(w4, w5, w6, a6);
    bool exact = geometry.exact_fit && arm.margin[b] >= well_inside && q45.exists && q45.margin >= well_inside;
    if (exact) {
      const Eigen::Vector3d& p1 = chain.points[0];
      const Eigen::Vector3d& p2 = chain.points[1];
      const Eigen::Vector3d& p3 = chain.points[2];
      const Eigen::Vector3d placed =
          rotate(w1, t[0], rotate(w2, t[1], rotate(w3, t[2], c - p3) + p3 - p2) + p2 - p1) + p1;
      exact = (placed - g_c).norm() <= exact_position;
    }
    if (!exact) {
      spherical_wrist_measured(chain, geometry, pose, target, t, arm_angles, g_w6, g_x6, out);
      measured = true;
      continue;
    }
    // Exact to rounding (doc/inverse-kinematics.md eq. 26): q₆ by subproblem 1 for each wrist solution, or the flip
    // (eq. 27).
    const Eigen::Vector3d b6 = from_base(g_x6);
    const auto q6_of = [&](std::size_t l) {
      return subproblem1_cs(w6, x6, rotate(w5, q45.second[l].inverse(), rotate(w4, q45.first[l].inverse(), b6)));
    };
    Vector6d q;
    q << arm_angles, q45.first[0].angle(), q45.second[0].angle(), q6_of(0).angle();
    keep_exact(chain, pose, q, measured, out);
    if (geometry.wrist_flips) {
      q(3) = half_turn(q(3));
      q(4) = -q(4);
      q(5) = half_turn(q(5));
    } else {
      q << arm_angles, q45.first[1].angle(), q45.second[1].angle(), q6_of(1).angle();
    }
    keep_exact(chain, pose, q, measured, out);
  }
}

// At the wrist singularity of a three-parallel arm: the two q₆ that put the elbow distance
// ‖H p₄ − p₂‖ mid-way in the range both the elbow (q₃) and the circle of q₆ allow (subproblem 3
// in −q₆), given e₁⁻¹ G and e₅. Writes them to `out` and returns how many there are (0 or 2).
std::size_t elbow_reaching_q6(const RevoluteChain& chain, const Motion& e1_inverse_g, const Motion& e5, CosSin* out) {
  const Eigen::Vector3d& w3 = chain.axes[2];
  const Eigen::Vector3d& w6 = chain.axes[5];
  const Eigen::Vector3d& p2 = chain.points[1];
  const Eigen::Vector3d& p3 = chain.points[2];
  const Eigen::Vector3d& p4 = chain.points[3];
  const Eigen::Vector3d& p6 = chain.points[5];
  const Eigen::Vector3d u6 = e5.inverse() * p4 - p6;
  const Eigen::Vector3d v6 = e1_inverse_g.inverse() * p2 - p6;  // (e₁⁻¹ G)⁻¹ p₂
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
  if (lo > hi) return 0;
  const Angles minus_q6 = subproblem3(w6, u6, v6, std::max(0.0, 0.5 * (lo + hi)));
  if (!minus_q6.exists) return 0;
  out[0] = minus_q6.plus.inverse();
  out[1] = minus_q6.minus.inverse();
  return 2;
}

bool three_parallel_inverse(const RevoluteChain& chain, const ChainGeometry& geometry, const Posed& pose,
                            IkSolutionSet& out) {
  if (geometry.three_parallel_plane && three_parallel_plane_inverse(geometry.plane, pose, out)) return false;
  bool near_singular = false;
  bool measured = false;  // a measured candidate was offered
  const Motion target = Motion::of(pose);
  const Motion g = target * geometry.tip_inverse;
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
  const Eigen::Vector3d& x4 = geometry.normal_4;
  // e₂e₃e₄ keep the component along ω₂, e₅e₆ fix c = axes 5 ∩ 6: ω₂ · e₁⁻¹ G c = ω₂ · c.
  const Angles q1s = subproblem4(w2, w1, g * c - p1, w2.dot(c - p1));
  if (!q1s.exists) return false;
  for (int l1 = 0; l1 < (q1s.single() ? 1 : 2); ++l1) {
    const CosSin q1 = (l1 == 0 ? q1s.plus : q1s.minus).inverse();  // the subproblem's angle is −q₁
    const Motion e1 = joint_motion(chain, 0, q1);
    const Motion a_m = e1.inverse() * target;  // e₁⁻¹ G M = e₂ ⋯ e₆ M
    const Eigen::Vector3d r1_w2 = e1.r * w2;
    const double q1_angle = q1.angle();
    // Orientation along ω₂: ω₂ᵀ R₅ ω₆ = (R₁ ω₂)ᵀ R_G ω₆ (subproblem 4 in q₅).
    const Angles q5s = subproblem4(w2, w5, w6, r1_w2.dot(g.r * w6));
    if (!q5s.exists) continue;
    for (int l5 = 0; l5 < (q5s.single() ? 1 : 2); ++l5) {
      const CosSin q5 = l5 == 0 ? q5s.plus : q5s.minus;
      const Motion e5 = joint_motion(chain, 4, q5);
      const double q5_angle = q5.angle();
      // R₆ᵀ R₅ᵀ ω₂ = R_Gᵀ R₁ ω₂ (subproblem 1 in −q₆).
      const Eigen::Vector3d u = e5.r.transpose() * w2;
      std::array<CosSin, 3> q6_candidates{{subproblem1_cs(w6, u, g.r.transpose() * r1_w2).inverse(), {}, {}}};
      std::size_t q6_count = 1;
      // Wrist singularity (R₅ᵀω₂ ∥ ω₆: axes 2, 3, 4, 6 parallel): q₆ and q₂ + q₃ + q₄ share one
      // planar motion, so q₆ is (nearly) free, but only an interval of q₆ leaves the elbow in
      // reach — a tiny one near the stretched elbow. Besides subproblem 1's value, take the q₆
      // that puts the elbow distance ‖H p₄ − p₂‖ mid-way in the range both the elbow (q₃) and
      // the circle of q₆ allow (subproblem 3 in −q₆); Newton then settles each on the pose.
      const bool singular_wrist = u.cross(w6).norm() < 1e-6;
      if (singular_wrist) {
        near_singular = true;
        q6_count += elbow_reaching_q6(chain, e1.inverse() * g, e5, &q6_candidates[1]);
      }
      for (std::size_t k6 = 0; k6 < q6_count; ++k6) {
        const CosSin q6 = q6_candidates[k6];
        const Motion e56m = e5 * geometry.tool.at(q6);  // e₅e₆M
        // H = e₁⁻¹ G e₆⁻¹ e₅⁻¹ = e₂e₃e₄; e₄ fixes p₄, so e₂e₃ p₄ = H p₄: subproblems 3 and 1.
        const Motion h = a_m * e56m.inverse();
        const double q6_angle = q6.angle();
        const Eigen::Vector3d y = h * p4;
        const Eigen::Vector3d h_x4 = h.r * x4;
        const Angles q3s = subproblem3(w3, p4 - p3, p2 - p3, (y - p2).squaredNorm());
        if (!q3s.exists) continue;
        // Exact to rounding (doc/inverse-kinematics.md eq. 26) away from the wrist singularity and every tangency.
        const bool exact = geometry.exact_fit && !singular_wrist && k6 == 0 &&
                           std::min(std::min(q1s.margin, q5s.margin), q3s.margin) >= well_inside;
        for (int l3 = 0; l3 < (q3s.single() ? 1 : 2); ++l3) {
          const CosSin q3 = l3 == 0 ? q3s.plus : q3s.minus;
          if (exact) {
            // q₂ and q₄ by subproblem 1 from rotated vectors (no motion composed, nothing measured).
            const CosSin q2 = subproblem1_cs(w2, rotate(w3, q3, p4 - p3) + p3 - p2, y - p2);
            const CosSin q4 = subproblem1_cs(w4, x4, rotate(w3, q3.inverse(), rotate(w2, q2.inverse(), h_x4)));
            Vector6d q;
            q << q1_angle, q2.angle(), q3.angle(), q4.angle(), q5_angle, q6_angle;
            keep_exact(chain, pose, q, measured, out);
            continue;
          }
          measured = true;
          const Motion e3 = joint_motion(chain, 2, q3);
          const CosSin q2 = subproblem1_cs(w2, e3 * p4 - p2, y - p2);
          const Motion e23 = joint_motion(chain, 1, q2) * e3;
          // R₄ = R₃ᵀ R₂ᵀ R_H about ω₄.
          const CosSin q4 = subproblem1_cs(w4, x4, e23.r.transpose() * h_x4);
          const Motion e4 = joint_motion(chain, 3, q4);
          // The check in link 1's frame: the tool origin e₂e₃e₄(e₅e₆M origin) against that of
          // e₁⁻¹T, and R₂R₃R₄ against R_H = R(e₁⁻¹T) (R₅R₆R_M)ᵀ (‖R − R'‖_F is unchanged by a
          // rotation on either side): the full pose error with one matrix product.
          PoseError error;
          error.position = (e23 * (e4 * e56m.t) - a_m.t).norm();
          error.rotation = rotation_error(e23.r * e4.r, h.r);
          Vector6d q;
          q << q1_angle, q2.angle(), q3.angle(), q4.angle(), q5_angle, q6_angle;
          offer(chain, pose, q, error, out);
        }
      }
    }
  }
  return near_singular;
}

}  // namespace detail
}  // namespace serial
}  // namespace dispkin
