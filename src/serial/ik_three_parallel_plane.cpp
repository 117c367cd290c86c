// Three parallel axes (Universal Robots) in the arm frame, with Hawkins' order of the unknowns
// (q₁, q₅, q₆, then the planar q₃, q₂ and q₄ as what the parallel axes leave of their sum): the
// subproblems of doc/inverse-kinematics.md eq. 12 on per-chain constants (doc/inverse-kinematics.md §10, eq. 35). Joint
// 5's rotations of the fixed wrist vectors are split into three parts once per chain, the pose enters through one 3 × 3
// product, and q₄ needs no arctangent of its own.
#include "ik_arm_frame.hpp"

namespace dispkin {
namespace serial {
namespace detail {

namespace {

// The wrist singularity test of the general path (ik_closed_form.cpp): R₅ᵀ ω₂ within this of ω₆.
constexpr double singular_wrist = 1e-6;

ThreeParallelPlane::Split split_about(const Eigen::Vector3d& k, const Eigen::Vector3d& v) {
  const double kv = k.dot(v);
  return {kv * k, v - kv * k, k.cross(v)};
}


}  // namespace

bool make_three_parallel_plane(const RevoluteChain& chain, const Eigen::Vector3d& centre, ThreeParallelPlane& out) {
  const Eigen::Vector3d& w2 = chain.axes[1];
  const Eigen::Vector3d& w5 = chain.axes[4];
  const Eigen::Vector3d& w6 = chain.axes[5];
  if (std::abs(chain.axes[0].dot(w2)) > exact_fit_tolerance) return false;
  out.frame = arm_frame(chain);
  out.elbow = plane_elbow(chain, out.frame, chain.points[3]);
  out.lateral = out.frame.point(centre).y();
  out.sign4 = chain.axes[3].dot(w2) > 0.0 ? 1.0 : -1.0;
  // Subproblem 4 in q₅ (doc/inverse-kinematics.md eq. 8, as the general path): h = ω₂, k = ω₅, p = ω₆.
  const double a = w2.dot(w6 - w5.dot(w6) * w5), b = w2.dot(w5.cross(w6));
  out.q5_offset = w5.dot(w6) * w5.dot(w2);
  out.q5_r = std::sqrt(a * a + b * b);
  if (!(out.q5_r > 1e-13 * std::sqrt(w2.squaredNorm() * w6.squaredNorm()))) return false;
  out.q5_phase = {a / out.q5_r, b / out.q5_r};
  out.q5_phase_angle = out.q5_phase.angle();
  const Posed& m = chain.tip_at_zero;
  const Eigen::Matrix3d rm_t = m.rotation().transpose();
  out.centre_in_tip = rm_t * (centre - m.translation());
  out.axis6 = rm_t * w6;
  const Eigen::Vector3d k5 = rm_t * w5;
  out.axis2 = split_about(k5, rm_t * w2);
  out.arm_to_p4 = split_about(k5, rm_t * (chain.points[3] - centre));
  out.arm_x = split_about(k5, rm_t * out.frame.to_arm.row(0).transpose());
  return out.elbow.r > 0.0;
}

bool three_parallel_plane_inverse(const ThreeParallelPlane& arm, const Posed& pose, IkSolutionSet& out) {
  const int start = out.count;
  const auto general = [&] {
    out.count = start;
    return false;
  };
  // A = to_arm R_T: a vector of the tip frame at q = 0 (R_Mᵀ-rotated) into the arm frame through G.
  const Eigen::Matrix3d into_arm = arm.frame.to_arm * pose.rotation();
  const Eigen::Vector3d w = into_arm * arm.centre_in_tip + arm.frame.point(pose.translation());  // G c
  const Eigen::Vector3d g6 = into_arm * arm.axis6;                                               // R_G ω₆
  const Eigen::Vector3d& k6 = arm.axis6;
  const PlaneElbow& elbow = arm.elbow;
  // q₁: ω₂ · e₁⁻¹ G c = ω₂ · c (doc/inverse-kinematics.md eq. 30).
  const ShoulderTurn shoulder = shoulder_turn(w, arm.lateral);
  if (shoulder.step != FastStep::exact) return shoulder.step == FastStep::none;
  const std::array<double, 2> q1_angles = shoulder_angles(shoulder, arm.lateral);
  for (std::size_t l1 = 0; l1 < 2; ++l1) {
    const CosSin q1 = shoulder.q1[l1];
    const double q1_angle = q1_angles[l1];
    // q₅: ω₂ · R₅ ω₆ = (R₁ ω₂) · R_G ω₆ (subproblem 4, doc/inverse-kinematics.md eq. 12).
    const double x = (q1.c * g6.y() - q1.s * g6.x() - arm.q5_offset) / arm.q5_r;
    const double margin5 = 1.0 - std::abs(x);
    if (margin5 < well_inside) {
      if (margin5 <= -well_inside) continue;
      return general();
    }
    const double sd = std::sqrt((1.0 - x) * (1.0 + x));
    const CosSin& p = arm.q5_phase;
    const std::array<CosSin, 2> q5s{
        {{p.c * x - p.s * sd, p.s * x + p.c * sd}, {p.c * x + p.s * sd, p.s * x - p.c * sd}}};
    const double half5 = CosSin{x, sd}.angle();
    // R_Gᵀ R₁ ω₂ in the tip frame: Aᵀ (−sin q₁, cos q₁, 0).
    const Eigen::Vector3d t = q1.c * into_arm.row(1).transpose() - q1.s * into_arm.row(0).transpose();
    for (std::size_t l5 = 0; l5 < 2; ++l5) {
      const CosSin q5 = q5s[l5];
      const double q5_angle = wrap_angle(arm.q5_phase_angle + (l5 == 0 ? half5 : -half5));
      // −q₆ = subproblem 1 (ω₆, R₅ᵀ ω₂, R_Gᵀ R₁ ω₂) (doc/inverse-kinematics.md eq. 12).
      const Eigen::Vector3d u = arm.axis2.back(q5);
      const Eigen::Vector3d u_x_k6 = u.cross(k6);
      if (u_x_k6.norm() < singular_wrist) return general();
      const double sine = -t.dot(u_x_k6);  // ω₆ · (u × t)
      const double cosine = u.dot(t) - k6.dot(u) * k6.dot(t);
      const double h6 = std::sqrt(sine * sine + cosine * cosine);
      if (!(h6 > 1e-300)) return general();
      const CosSin q6{cosine / h6, -sine / h6};
      const double q6_angle = q6.angle();
      // H = e₁⁻¹ G e₆⁻¹ e₅⁻¹ = e₂e₃e₄: the point y = H p₄ and the turn θ_H of R_H about y (doc/inverse-kinematics.md
      // eq. 35).
      const CosSin back6 = q6.inverse();
      const Eigen::Vector3d to_p4 = w + into_arm * rotate(k6, back6, arm.arm_to_p4.back(q5));
      const Eigen::Vector3d hx = into_arm * rotate(k6, back6, arm.arm_x.back(q5));
      const PlaneVector target{to_p4.z(), q1.c * to_p4.x() + q1.s * to_p4.y()};
      const double theta_h = CosSin{q1.c * hx.x() + q1.s * hx.y(), -hx.z()}.angle();
      const ElbowTurn q3s = elbow_turn(elbow, target);
      if (q3s.step == FastStep::none) continue;
      if (q3s.step == FastStep::general) return general();
      const PlaneVector to_target = target - elbow.p2;
      const std::array<double, 2> q3_angles = elbow_angles(elbow, q3s.half.angle());
      for (std::size_t l3 = 0; l3 < 2; ++l3) {
        const PlaneVector reach = elbow_reach(elbow, q3s.q3[l3]);
        const double q2 = CosSin{dot(reach, to_target), cross(reach, to_target)}.angle();
        const double q3 = q3_angles[l3];
        // R₂R₃R₄ = R_H about y: q₂ + σ₃q₃ + σ₄q₄ = θ_H.
        const double q4 = arm.sign4 * (theta_h - q2 - elbow.sign3 * q3);
        push_exact(out, {q1_angle, q2, q3, q4, q5_angle, q6_angle});
      }
    }
  }
  return true;
}

}  // namespace detail
}  // namespace serial
}  // namespace dispkin
