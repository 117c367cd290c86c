// The arm frame of a 6R chain whose first axis is perpendicular to the parallel axes after it
// (internal to the analytic IK; doc/inverse-kinematics.md §10). In this frame joint 1 turns about
// z and the parallel joints about ±y, so the positioning stage is a two-link problem of the arm
// plane, solved by plane rotations of per-chain constants instead of rotations about general
// axes. The spherical-wrist fast path (ik_ortho_parallel.cpp) and the three-parallel one
// (ik_three_parallel_plane.cpp) both work in it.
#pragma once

#include <array>
#include <cmath>

#include <Eigen/Core>

#include "dispkin/pose.hpp"
#include "dispkin/serial/analytic_ik.hpp"
#include "dispkin/serial/revolute_chain.hpp"
#include "ik_subproblems.hpp"

namespace dispkin {
namespace serial {
namespace detail {

//! Where a closed-form fast path stands after a subproblem: its solutions are exact to rounding
//! (every margin ≥ well_inside), it has none (margin ≤ −well_inside, where no rounding of the
//! general path can make it solvable), or it is near a tangency or a degenerate case, which the
//! general subproblem path, with its measured and polished candidates, decides.
enum class FastStep { exact, none, general };

//! Lines that meet or are parallel to this (m, rad) do so to rounding: chains written from DH
//! tables or from URDF origins with exact angles are, those with rounded angles (1.5708 for π/2)
//! are not. Only then are the fast paths' solutions exact without a check.
constexpr double exact_fit_tolerance = 1e-14;

//! A point or vector of the arm plane in coordinates (ξ, η) = (z, x) of link 1's arm frame: a
//! turn by θ about +y is the plane rotation by θ (doc/inverse-kinematics.md (eq. 29)).
struct PlaneVector {
  double xi = 0.0;
  double eta = 0.0;
};

EIGEN_ALWAYS_INLINE PlaneVector operator+(const PlaneVector& a, const PlaneVector& b) noexcept {
  return {a.xi + b.xi, a.eta + b.eta};
}
EIGEN_ALWAYS_INLINE PlaneVector operator-(const PlaneVector& a, const PlaneVector& b) noexcept {
  return {a.xi - b.xi, a.eta - b.eta};
}
EIGEN_ALWAYS_INLINE double dot(const PlaneVector& a, const PlaneVector& b) noexcept {
  return a.xi * b.xi + a.eta * b.eta;
}
//! The plane's cross product a × b (its component along +y).
EIGEN_ALWAYS_INLINE double cross(const PlaneVector& a, const PlaneVector& b) noexcept {
  return a.xi * b.eta - a.eta * b.xi;
}
//! a turned by the angle θ (cosine and sine).
EIGEN_ALWAYS_INLINE PlaneVector turn(const CosSin& t, const PlaneVector& a) noexcept {
  return {t.c * a.xi - t.s * a.eta, t.s * a.xi + t.c * a.eta};
}
//! The sum of two angles as cosine and sine.
EIGEN_ALWAYS_INLINE CosSin add(const CosSin& a, const CosSin& b) noexcept {
  return {a.c * b.c - a.s * b.s, a.s * b.c + a.c * b.s};
}

//! Appends a solution exact to rounding (measured error 0, doc/inverse-kinematics.md eq. 26), its joints wrapped to
//! (−π, π].
EIGEN_ALWAYS_INLINE void push_exact(IkSolutionSet& out, const std::array<double, 6>& q) noexcept {
  if (out.count == 8) return;
  const auto k = static_cast<std::size_t>(out.count++);
  for (std::size_t i = 0; i < 6; ++i) out.q[k](static_cast<Eigen::Index>(i)) = wrap_angle(q[i]);
  out.error[k] = 0.0;
}

//! The arm frame: origin p₁ on axis 1, z = ω₁, y = ω₂, x = y × z (doc/inverse-kinematics.md eq. 29). Needs ω₁ ⊥ ω₂.
struct ArmFrame {
  Eigen::Matrix3d to_arm = Eigen::Matrix3d::Identity();  //!< Bᵀ: base vectors into arm coordinates
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();      //!< p₁
  Eigen::Vector3d point(const Eigen::Vector3d& x) const { return to_arm * (x - origin); }
  static PlaneVector in_plane(const Eigen::Vector3d& arm) noexcept { return {arm.z(), arm.x()}; }
};

//! The frame of `chain` (axes 1 and 2 perpendicular).
inline ArmFrame arm_frame(const RevoluteChain& chain) {
  ArmFrame f;
  const Eigen::Vector3d z = chain.axes[0].normalized();
  const Eigen::Vector3d y = chain.axes[1].normalized();
  f.to_arm.row(0) = y.cross(z).transpose();
  f.to_arm.row(1) = y.transpose();
  f.to_arm.row(2) = z.transpose();
  f.origin = chain.points[0];
  return f;
}

//! A candidate all of whose subproblems are this far inside their solvable range (margin, §2)
//! is exact to rounding and is kept without measuring its pose error (doc/inverse-kinematics.md
//! (doc/inverse-kinematics.md eq. 26)); nearer a tangency or a singularity rounding is amplified, and it is measured
//! and polished.
constexpr double well_inside = 1e-4;

//! Joint 1 of the arm frame: the turn about z that brings a point W (arm coordinates) to the
//! lateral offset b its point has at q = 0 (doc/inverse-kinematics.md eq. 30), labelled as subproblem 4 labels −q₁.
struct ShoulderTurn {
  FastStep step = FastStep::general;
  std::array<CosSin, 2> q1{};     //!< for the labels plus and minus
  std::array<double, 2> reach{};  //!< u: the x coordinate of e₁⁻¹ W in link 1's frame
};

inline ShoulderTurn shoulder_turn(const Eigen::Vector3d& w, double lateral) noexcept {
  ShoulderTurn out;
  const double rho2 = w.x() * w.x() + w.y() * w.y();
  const double rho = std::sqrt(rho2);
  // As subproblem 4 of the general path: A = w_y, B = w_x, C = b, r = ρ, scale ‖W‖.
  if (!(rho > 1e-13 * std::sqrt(rho2 + w.z() * w.z()) + 1e-300)) return out;  // on axis 1: q₁ free
  const double margin = 1.0 - std::abs(lateral) / rho;
  if (margin < well_inside) {
    if (margin <= -well_inside) out.step = FastStep::none;
    return out;
  }
  out.step = FastStep::exact;
  const double s = std::sqrt((rho - std::abs(lateral)) * (rho + std::abs(lateral)));
  const double inverse = 1.0 / rho2;
  for (std::size_t l = 0; l < 2; ++l) {
    const double u = l == 0 ? -s : s;  // the label plus of −q₁ reaches back (doc/inverse-kinematics.md eq. 30)
    out.q1[l] = {(w.x() * u + w.y() * lateral) * inverse, (w.y() * u - w.x() * lateral) * inverse};
    out.reach[l] = u;
  }
  return out;
}

//! q₁ of both labels of an exact shoulder turn (one arctangent where b = 0: they differ by π).
inline std::array<double, 2> shoulder_angles(const ShoulderTurn& turn, double lateral) noexcept {
  const double minus = turn.q1[1].angle();
  return {{lateral == 0.0 ? half_turn(minus) : turn.q1[0].angle(), minus}};
}

//! The two-link elbow of the arm plane (doc/inverse-kinematics.md eq. 31): axis 2 at p₂, axis 3 (along σ₃ y) at p₃, the
//! point X carried by joint 3; ‖L₂ + R(σ₃q₃) L₃‖ = ‖w − p₂‖ gives q₃, the plane rotation from
//! L₂ + R(σ₃q₃) L₃ to w − p₂ gives q₂ (doc/inverse-kinematics.md eq. 32).
struct PlaneElbow {
  PlaneVector p2;            //!< axis 2
  PlaneVector upper;         //!< L₂ = p₃ − p₂
  PlaneVector fore;          //!< L₃ = X − p₃
  double half_sum = 0.0;     //!< ½(‖L₂‖² + ‖L₃‖²)
  double r = 1.0;            //!< ‖L₂‖ ‖L₃‖: subproblem 3's √(A² + B²)
  CosSin phase;              //!< (A, B) / r: the angle φ of doc/inverse-kinematics.md eq. 4
  double phase_angle = 0.0;  //!< φ
  double sign3 = 1.0;        //!< σ₃ = ω₃ · ω₂
};

//! The elbow of `chain` in `frame` for the point `x` carried by joint 3 (base coordinates).
inline PlaneElbow plane_elbow(const RevoluteChain& chain, const ArmFrame& frame, const Eigen::Vector3d& x) {
  PlaneElbow e;
  const Eigen::Vector3d& w3 = chain.axes[2];
  const Eigen::Vector3d& p2 = chain.points[1];
  const Eigen::Vector3d& p3 = chain.points[2];
  e.p2 = ArmFrame::in_plane(frame.point(p2));
  e.upper = ArmFrame::in_plane(frame.point(p3)) - e.p2;
  e.fore = ArmFrame::in_plane(frame.point(x)) - ArmFrame::in_plane(frame.point(p3));
  e.half_sum = 0.5 * (dot(e.upper, e.upper) + dot(e.fore, e.fore));
  // A and B of subproblem 3 (doc/inverse-kinematics.md eq. 7) with u = x − p₃, v = p₂ − p₃: fixed by the chain.
  const Eigen::Vector3d u = x - p3, v = p2 - p3;
  const double a = v.dot(u - w3.dot(u) * w3), b = v.dot(w3.cross(u));
  e.r = std::sqrt(a * a + b * b);
  e.phase = {a / e.r, b / e.r};
  e.phase_angle = e.phase.angle();
  e.sign3 = w3.dot(chain.axes[1]) > 0.0 ? 1.0 : -1.0;
  return e;
}

//! q₃ of the elbow for the target w (arm plane) by subproblem 3's labels plus and minus.
struct ElbowTurn {
  FastStep step = FastStep::general;
  std::array<CosSin, 2> q3{};
  CosSin half;  //!< arccos x in [0, π] as (x, √(1 − x²)): q₃ = φ ± arccos x, one arctangent for both labels
};

inline ElbowTurn elbow_turn(const PlaneElbow& e, const PlaneVector& w) noexcept {
  ElbowTurn out;
  const PlaneVector d = w - e.p2;
  const double x = (e.half_sum - 0.5 * dot(d, d)) / e.r;
  const double margin = 1.0 - std::abs(x);
  if (margin < well_inside) {
    if (margin <= -well_inside) out.step = FastStep::none;
    return out;
  }
  out.step = FastStep::exact;
  const double sd = std::sqrt((1.0 - x) * (1.0 + x));
  const CosSin& p = e.phase;
  out.q3[0] = {p.c * x - p.s * sd, p.s * x + p.c * sd};
  out.q3[1] = {p.c * x + p.s * sd, p.s * x - p.c * sd};
  out.half = {x, sd};
  return out;
}

//! q₃ = φ ± arccos x of the labels plus and minus, from the angle of ElbowTurn::half.
inline std::array<double, 2> elbow_angles(const PlaneElbow& e, double half) noexcept {
  return {{wrap_angle(e.phase_angle + half), wrap_angle(e.phase_angle - half)}};
}

//! The joint-3 turn as a plane rotation: R(σ₃ q₃).
EIGEN_ALWAYS_INLINE CosSin plane_turn3(const PlaneElbow& e, const CosSin& q3) noexcept {
  return {q3.c, e.sign3 * q3.s};
}

//! L₂ + R(σ₃q₃) L₃: where joints 2–3 carry X relative to axis 2 before joint 2 turns.
EIGEN_ALWAYS_INLINE PlaneVector elbow_reach(const PlaneElbow& e, const CosSin& q3) noexcept {
  return e.upper + turn(plane_turn3(e, q3), e.fore);
}

//! A spherical wrist on an ortho-parallel basis (Brandstötter, Angerer and Hofbaur): axis 1 ⊥
//! axes 2 ∥ 3, wrist axes 4 ⊥ 5 ⊥ 6 with 4 ∥ 6 at q = 0, all to rounding. The per-chain constants
//! of its closed form in the arm frame (doc/inverse-kinematics.md §10, eqs. 29–34).
struct OrthoParallel {
  ArmFrame frame;
  PlaneElbow elbow;                                          //!< X = the wrist centre c
  double lateral = 0.0;                                      //!< b: the y coordinate of c in the arm frame
  Eigen::Vector3d centre_in_tip = Eigen::Vector3d::Zero();   //!< M⁻¹ c: c in the tip frame at q = 0
  Eigen::Vector3d axis6_in_tip = Eigen::Vector3d::UnitZ();   //!< R_Mᵀ ω₆
  Eigen::Vector3d axis5_in_tip = Eigen::Vector3d::UnitY();   //!< R_Mᵀ ω₅
  Eigen::Matrix3d wrist_rows = Eigen::Matrix3d::Identity();  //!< rows ω₄, ω₅, ω₄ × ω₅ (arm coordinates)
  double sign6 = 1.0;                                        //!< σ₆ = ω₄ · ω₆ (±1)
};

//! The constants of `chain` with wrist centre `centre`; false unless axis 1 ⊥ axis 2 to 10⁻¹⁴
//! (the caller has checked the rest: an exactly fitting parallel_23 spherical wrist that flips).
bool make_ortho_parallel(const RevoluteChain& chain, const Eigen::Vector3d& centre, OrthoParallel& out);

//! All solutions of the pose by doc/inverse-kinematics.md eqs. 29–34, appended to `out` as exact to rounding (eq. 26).
//! False when some subproblem is near its tangency, the wrist near its singularity, or a branch misses the positioning
//! residual of doc/inverse-kinematics.md eq. 26: then nothing is appended and the general path decides.
bool ortho_parallel_inverse(const OrthoParallel& arm, const Posed& pose, IkSolutionSet& out);

//! Three parallel axes (Universal Robots) with axis 1 ⊥ axes 2 ∥ 3 ∥ 4 to rounding: the per-chain
//! constants of the closed form (doc/inverse-kinematics.md eq. 12) in the arm frame (doc/inverse-kinematics.md §10, eq.
//! 35). The wrist vectors are kept in the tip frame at q = 0 (rotated by R_Mᵀ), so that a pose enters through one
//! product to_arm · R_T.
struct ThreeParallelPlane {
  ArmFrame frame;
  PlaneElbow elbow;                                         //!< X = p₄
  double lateral = 0.0;                                     //!< b of c = axes 5 ∩ 6
  double sign4 = 1.0;                                       //!< σ₄ = ω₄ · ω₂
  Eigen::Vector3d centre_in_tip = Eigen::Vector3d::Zero();  //!< M⁻¹ c
  Eigen::Vector3d axis6 = Eigen::Vector3d::UnitZ();         //!< R_Mᵀ ω₆
  // q₅ by subproblem 4 (doc/inverse-kinematics.md eq. 8) with h = ω₂, k = ω₅, p = ω₆: A cos q₅ + B sin q₅ = d − K.
  double q5_offset = 0.0;  //!< K = (ω₅·ω₆)(ω₅·ω₂)
  double q5_r = 1.0;       //!< √(A² + B²)
  CosSin q5_phase;         //!< (A, B) / r
  double q5_phase_angle = 0.0;
  //! R(ω₅, −q₅) v = along + cos q₅ normal − sin q₅ cross for v = ω₂, p₄ − c and x (the arm frame's
  //! x axis), all rotated by R_Mᵀ: the vectors joint 5 turns back, in three fixed parts each.
  struct Split {
    Eigen::Vector3d along, normal, cross;
    EIGEN_ALWAYS_INLINE Eigen::Vector3d back(const CosSin& q5) const noexcept {
      return along + q5.c * normal - q5.s * cross;
    }
  };
  Split axis2, arm_to_p4, arm_x;
};

//! The constants of a three_parallel `chain` with c = axes 5 ∩ 6; false unless axis 1 ⊥ axis 2 to
//! 10⁻¹⁴ and subproblem 4 in q₅ is not degenerate.
bool make_three_parallel_plane(const RevoluteChain& chain, const Eigen::Vector3d& centre, ThreeParallelPlane& out);

//! All solutions of the pose by doc/inverse-kinematics.md eq. 12 in the arm frame (eq. 35), appended to `out` as exact
//! to rounding. False (nothing appended) near a tangency or the wrist singularity.
bool three_parallel_plane_inverse(const ThreeParallelPlane& arm, const Posed& pose, IkSolutionSet& out);

}  // namespace detail
}  // namespace serial
}  // namespace dispkin
