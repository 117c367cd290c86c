// The spherical wrist on an ortho-parallel basis (Brandstötter, Angerer and Hofbaur 2014) in the
// arm frame: axis 1 ⊥ axes 2 ∥ 3, wrist axes 4 ⊥ 5 ⊥ 6 with 4 ∥ 6 at q = 0. The general path
// (ik_closed_form.cpp, doc/inverse-kinematics.md eq. 11) solves the same subproblems with rotations about general axes;
// here the positioning stage is the plane problem of doc/inverse-kinematics.md eqs. 30–32 on per-chain constants and
// the wrist reads its angles off two target vectors in the wrist's own basis (doc/inverse-kinematics.md eqs. 33–34), so
// a pose costs a few hundred multiplications, six square roots and twenty arctangents (taken in one batch) for its
// eight solutions. doc/inverse-kinematics.md §10.
#include "angle_batch.hpp"
#include "ik_arm_frame.hpp"

namespace dispkin {
namespace serial {
namespace detail {

namespace {

// The positioning residual ‖e₁e₂e₃ c − G c‖ (m) of doc/inverse-kinematics.md eq. 26 below which a branch counts as
// exact.
constexpr double exact_position = 4e-15;

// R_z(−q₁) v: a vector of arm coordinates into link 1's frame.
EIGEN_ALWAYS_INLINE Eigen::Vector3d unturn1(const CosSin& q1, const Eigen::Vector3d& v) noexcept {
  return {q1.c * v.x() + q1.s * v.y(), q1.c * v.y() - q1.s * v.x(), v.z()};
}

// R_y(−θ) v: undoes a turn θ about y (in the plane (ξ, η) = (z, x), doc/inverse-kinematics.md eq. 29).
EIGEN_ALWAYS_INLINE Eigen::Vector3d unturn_y(const CosSin& t, const Eigen::Vector3d& v) noexcept {
  return {t.c * v.x() - t.s * v.z(), v.y(), t.c * v.z() + t.s * v.x()};
}


}  // namespace

bool make_ortho_parallel(const RevoluteChain& chain, const Eigen::Vector3d& centre, OrthoParallel& out) {
  // Axis 1 ⊥ axis 2 to rounding: only then are the arm frame's solutions exact (doc/inverse-kinematics.md eq. 26).
  if (std::abs(chain.axes[0].dot(chain.axes[1])) > exact_fit_tolerance) return false;
  out.frame = arm_frame(chain);
  out.elbow = plane_elbow(chain, out.frame, centre);
  out.lateral = out.frame.point(centre).y();
  const Posed& m = chain.tip_at_zero;
  const Eigen::Matrix3d rm = m.rotation();
  out.centre_in_tip = rm.transpose() * (centre - m.translation());
  out.axis6_in_tip = rm.transpose() * chain.axes[5];
  out.axis5_in_tip = rm.transpose() * chain.axes[4];
  const Eigen::Vector3d w4 = out.frame.to_arm * chain.axes[3];
  const Eigen::Vector3d w5 = out.frame.to_arm * chain.axes[4];
  out.wrist_rows.row(0) = w4.transpose();
  out.wrist_rows.row(1) = w5.transpose();
  out.wrist_rows.row(2) = w4.cross(w5).transpose();
  out.sign6 = chain.axes[3].dot(chain.axes[5]) > 0.0 ? 1.0 : -1.0;
  return out.elbow.r > 0.0;
}

bool ortho_parallel_inverse(const OrthoParallel& arm, const Posed& pose, IkSolutionSet& out) {
  // The pose in the arm frame: W = G c (doc/inverse-kinematics.md eq. 30) and the target's wrist axes R_G ω₆, R_G ω₅.
  const Eigen::Matrix3d into_arm = arm.frame.to_arm * pose.rotation();
  const Eigen::Vector3d w = into_arm * arm.centre_in_tip + arm.frame.point(pose.translation());
  const Eigen::Vector3d g6 = into_arm * arm.axis6_in_tip;
  const Eigen::Vector3d g5 = into_arm * arm.axis5_in_tip;
  const ShoulderTurn shoulder = shoulder_turn(w, arm.lateral);
  if (shoulder.step != FastStep::exact) return shoulder.step == FastStep::none;
  const PlaneElbow& elbow = arm.elbow;
  const double b = arm.lateral;
  // Every joint as cosine and sine first, all twenty arctangents of the pose in one batch after
  // the last check (angle_batch.hpp). Slots: q₁ of both labels, arccos x of both elbows, then
  // q₂, q₄, q₅, q₆ of each branch (l₁, l₃).
  std::array<CosSin, 20> turns{};
  std::array<bool, 4> branch{};
  const auto slot = [](std::size_t l1, std::size_t l3) { return 4 + 4 * (2 * l1 + l3); };
  for (std::size_t l1 = 0; l1 < 2; ++l1) {
    const CosSin q1 = shoulder.q1[l1];
    turns[l1] = q1;
    const PlaneVector target{w.z(), shoulder.reach[l1]};  // e₁⁻¹ W in the arm plane
    const ElbowTurn q3s = elbow_turn(elbow, target);
    if (q3s.step == FastStep::none) continue;
    if (q3s.step == FastStep::general) return false;
    turns[2 + l1] = q3s.half;
    const Eigen::Vector3d h6 = unturn1(q1, g6), h5 = unturn1(q1, g5);
    const PlaneVector to_target = target - elbow.p2;
    for (std::size_t l3 = 0; l3 < 2; ++l3) {
      const CosSin q3 = q3s.q3[l3];
      // q₂: the plane rotation from L₂ + R(σ₃q₃) L₃ onto w − p₂ (doc/inverse-kinematics.md eq. 32).
      const PlaneVector reach = elbow_reach(elbow, q3);
      const double c2 = dot(reach, to_target), s2 = cross(reach, to_target);
      const double inverse2 = 1.0 / std::sqrt(c2 * c2 + s2 * s2);
      const CosSin q2{c2 * inverse2, s2 * inverse2};
      // The positioning residual of doc/inverse-kinematics.md eq. 26 in the plane (eq. 34): e₁e₂e₃ c against W.
      const PlaneVector placed = elbow.p2 + turn(q2, reach);
      const double rx = q1.c * placed.eta - q1.s * b - w.x();
      const double ry = q1.s * placed.eta + q1.c * b - w.y();
      const double rz = placed.xi - w.z();
      if (!(rx * rx + ry * ry + rz * rz <= exact_position * exact_position)) return false;
      // The wrist (doc/inverse-kinematics.md eq. 33): a = R_w ω₆ and v = R_w ω₅ in the basis (ω₄, ω₅, ω₄ × ω₅), R_w =
      // (R₁R₂R₃)ᵀ R_G.
      const CosSin q23 = add(q2, plane_turn3(elbow, q3));
      const Eigen::Vector3d a = arm.wrist_rows * unturn_y(q23, h6);
      const Eigen::Vector3d v = arm.wrist_rows * unturn_y(q23, h5);
      const double gamma2 = a.y() * a.y() + a.z() * a.z();
      // Subproblem 2's margin sin² q₅ (doc/inverse-kinematics.md eq. 26).
      if (!(gamma2 >= well_inside * a.squaredNorm())) return false;
      const double gamma = std::sqrt(gamma2);
      CosSin* q = &turns[slot(l1, l3)];
      q[0] = q2;
      q[1] = {a.z(), -a.y()};
      q[2] = {arm.sign6 * a.x(), -arm.sign6 * gamma};
      q[3] = {a.z() * v.y() - a.y() * v.z(), a.x() * (a.y() * v.y() + a.z() * v.z()) - gamma2 * v.x()};
      branch[2 * l1 + l3] = true;
    }
  }
  std::array<double, 20> angle{};
  angles_of(turns.data(), turns.size(), angle.data());
  for (std::size_t l1 = 0; l1 < 2; ++l1) {
    const std::array<double, 2> q3 = elbow_angles(elbow, angle[2 + l1]);
    for (std::size_t l3 = 0; l3 < 2; ++l3) {
      if (!branch[2 * l1 + l3]) continue;
      const double* q = &angle[slot(l1, l3)];
      push_exact(out, {angle[l1], q[0], q3[l3], q[1], q[2], q[3]});
      // The wrist flip (doc/inverse-kinematics.md eq. 27).
      push_exact(out, {angle[l1], q[0], q3[l3], half_turn(q[1]), -q[2], half_turn(q[3])});
    }
  }
  return true;
}

}  // namespace detail
}  // namespace serial
}  // namespace dispkin
