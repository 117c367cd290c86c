//! Rigid poses in SE(3), body twists, the exponential and logarithm maps, XYZUVW and pivots.
//!
//! doc/disp-metric.md §1–3. A pose T = (R, t) maps body (tool) coordinates to world coordinates,
//! x_w = R x_b + t. It is stored as a unit quaternion and a translation, never as angles.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <string>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "dispkin/error.hpp"

namespace dispkin {

//! A body twist (v, ω): T⁻¹ Ṫ = ([ω]ₓ, v), both in body coordinates. As a 6-vector: (v, ω).
template <typename Scalar>
struct Twist {
  using Vector3 = Eigen::Matrix<Scalar, 3, 1>;  //!< v or ω
  using Vector6 = Eigen::Matrix<Scalar, 6, 1>;  //!< (v, ω) stacked

  Vector3 linear = Vector3::Zero();   //!< v: velocity of the body origin, body coordinates
  Vector3 angular = Vector3::Zero();  //!< ω: angular velocity, body coordinates

  Twist() = default;
  //! From v and ω.
  Twist(const Vector3& v, const Vector3& w) : linear(v), angular(w) {}
  //! From the stacked 6-vector (v, ω).
  explicit Twist(const Vector6& vw) : linear(vw.template head<3>()), angular(vw.template tail<3>()) {}

  //! The stacked 6-vector (v, ω).
  Vector6 vector() const {
    Vector6 vw;
    vw << linear, angular;
    return vw;
  }
  //! The twist scaled by k: (k v, k ω).
  Twist operator*(Scalar k) const { return Twist(k * linear, k * angular); }
};

//! How far a quaternion's norm may be from 1 before it is refused as "not a unit quaternion";
//! within this it is normalised. Loose enough for quaternions that went through float32 or a
//! text file, tight enough that a real mistake (a raw axis, a zero quaternion) is caught.
template <typename Scalar>
constexpr Scalar unit_quaternion_tolerance() {
  return std::max(Scalar(1e-6), Scalar(100) * std::numeric_limits<Scalar>::epsilon());
}

//! Below this cos V an XYZUVW orientation is gimbal-locked: W is then set to 0 and U carries
//! the whole rotation about the (then common) X/Z axis. 16ε: an input of exactly V = ±90°
//! comes back from the rotation matrix with cos V up to 4ε, and must count as locked. Inside
//! this band setting W = 0 moves R by at most cos V · |W| < 2e-14. Above it U and W are both
//! computed (W from the residual rotation), which reproduces R to rounding however close V
//! is to ±90°; only the split of U and W is ill-conditioned there.
template <typename Scalar>
constexpr Scalar gimbal_lock_tolerance() {
  return Scalar(16) * std::numeric_limits<Scalar>::epsilon();
}

namespace detail {

// Coefficients of the SE(3)/SO(3) maps as functions of the rotation angle θ, each with the
// Taylor series where the closed form loses digits (doc/disp-metric.md eqs. 11–12).
// B(θ) = (1 − cos θ)/θ² = 2 sin²(θ/2)/θ² is stable in its half-angle form everywhere.
template <typename Scalar>
Scalar coefficient_b(Scalar theta) {
  using std::sin;
  if (theta < Scalar(1e-4)) return Scalar(0.5) - theta * theta / Scalar(24);
  const Scalar s = sin(theta / 2) / theta;
  return 2 * s * s;
}

// C(θ) = (θ − sin θ)/θ³ cancels for small θ.
template <typename Scalar>
Scalar coefficient_c(Scalar theta) {
  using std::sin;
  const Scalar t2 = theta * theta;
  if (theta < Scalar(1e-2)) return Scalar(1) / 6 - t2 / 120 + t2 * t2 / 5040 - t2 * t2 * t2 / 362880;
  return (theta - sin(theta)) / (t2 * theta);
}

// sin(θ/2)/θ, the quaternion's vector-part factor in exp.
template <typename Scalar>
Scalar half_sine_over_angle(Scalar theta) {
  using std::sin;
  const Scalar t2 = theta * theta;
  if (theta < Scalar(1e-4)) return Scalar(0.5) - t2 / 48;
  return sin(theta / 2) / theta;
}

// The unit quaternion of a turn by `angle` (rad) about the unit `axis`: (cos ½α, sin ½α â),
// one sine/cosine pair (cheaper than through an AngleAxis and its rotation matrix).
template <typename Scalar>
Eigen::Quaternion<Scalar> axis_turn(const Eigen::Matrix<Scalar, 3, 1>& axis, Scalar angle) noexcept {
  using std::cos;
  using std::sin;
  const Scalar s = sin(angle / 2);
  return Eigen::Quaternion<Scalar>(cos(angle / 2), s * axis.x(), s * axis.y(), s * axis.z());
}

template <typename Scalar>
Eigen::Matrix<Scalar, 3, 3> hat(const Eigen::Matrix<Scalar, 3, 1>& w) {
  Eigen::Matrix<Scalar, 3, 3> m;
  m << Scalar(0), -w.z(), w.y(), w.z(), Scalar(0), -w.x(), -w.y(), w.x(), Scalar(0);
  return m;
}

}  // namespace detail

//! Rotation exponential: the unit quaternion of the rotation vector ω (axis · angle).
template <typename Scalar>
Eigen::Quaternion<Scalar> quaternion_exp(const Eigen::Matrix<Scalar, 3, 1>& w) {
  using std::cos;
  const Scalar theta = w.norm();
  const Eigen::Matrix<Scalar, 3, 1> v = detail::half_sine_over_angle(theta) * w;
  return Eigen::Quaternion<Scalar>(cos(theta / 2), v.x(), v.y(), v.z());
}

//! Rotation logarithm: the rotation vector of a unit quaternion, angle in [0, π]. At exactly π
//! both ±axis are valid; the sign of the quaternion's vector part decides.
template <typename Scalar>
Eigen::Matrix<Scalar, 3, 1> quaternion_log(const Eigen::Quaternion<Scalar>& q_in) {
  using std::atan2;
  // q and −q are the same rotation; w ≥ 0 selects the angle in [0, π].
  const Eigen::Quaternion<Scalar> q = q_in.w() < Scalar(0) ? Eigen::Quaternion<Scalar>(-q_in.coeffs()) : q_in;
  const Scalar s = q.vec().norm();
  const Scalar w = q.w();
  Scalar angle_over_s;
  if (s < Scalar(1e-5) * w) {
    // 2 atan(s/w)/s = (2/w)(1 − (s/w)²/3 + (s/w)⁴/5 − …)
    const Scalar r2 = (s / w) * (s / w);
    angle_over_s = (Scalar(2) / w) * (Scalar(1) - r2 / 3 + r2 * r2 / 5);
  } else {
    angle_over_s = 2 * atan2(s, w) / s;
  }
  return angle_over_s * q.vec();
}

//! A rigid transform in SE(3): unit quaternion plus translation.
//!
//! Invariant: `quaternion()` has norm 1 to rounding. Constructors that take user data check
//! it (and finiteness) and throw std::invalid_argument naming the argument; the arithmetic
//! (composition, inverse, exp) is noexcept and keeps the invariant.
template <typename Scalar>
class Pose {
 public:
  using Vector3 = Eigen::Matrix<Scalar, 3, 1>;   //!< a point or a translation
  using Vector6 = Eigen::Matrix<Scalar, 6, 1>;   //!< XYZUVW or a twist (v, ω)
  using Matrix3 = Eigen::Matrix<Scalar, 3, 3>;   //!< a rotation matrix
  using Matrix4 = Eigen::Matrix<Scalar, 4, 4>;   //!< a homogeneous transform
  using Quaternion = Eigen::Quaternion<Scalar>;  //!< the orientation, unit norm

  //! The identity.
  Pose() noexcept : q_(Quaternion::Identity()), t_(Vector3::Zero()) {}

  //! From a unit quaternion (w, x, y, z) and a translation. Throws if anything is not finite
  //! or |‖q‖ − 1| exceeds unit_quaternion_tolerance(); a quaternion within it is normalised.
  Pose(const Quaternion& quaternion, const Vector3& translation) : t_(translation) {
    q_ = Quaternion(quaternion.coeffs() / require_pose(quaternion, translation, unit_quaternion_tolerance<Scalar>()));
  }

  //! A pose as stored (a pickle): the quaternion is taken as it is, not normalised again, so that
  //! the pose is the same bit for bit. The constructor's checks, with the unit norm to rounding:
  //! a stored quaternion was normalised, so |‖q‖ − 1| is a few ε (stored_quaternion_tolerance()).
  static Pose from_stored(const Quaternion& unit_quaternion, const Vector3& translation) {
    require_pose(unit_quaternion, translation, stored_quaternion_tolerance());
    return unchecked(unit_quaternion, translation);
  }

  //! How far from 1 the norm of a stored (already normalised) quaternion may be: dividing by the
  //! norm leaves it within 2ε of 1; 4096ε (9·10⁻¹³ for double) also takes a quaternion written
  //! out with 17 digits and composed a few times.
  static constexpr Scalar stored_quaternion_tolerance() {
    return Scalar(4096) * std::numeric_limits<Scalar>::epsilon();
  }

  //! From an orthonormal rotation matrix (det +1, checked to 1e-6) and a translation.
  Pose(const Matrix3& rotation, const Vector3& translation) : Pose(checked_quaternion(rotation), translation) {}

  //! From a homogeneous 4×4 matrix [R t; 0 0 0 1]; R must be a rotation to 1e-6.
  static Pose from_matrix(const Matrix4& m) {
    require_finite(m, "matrix");
    using std::abs;
    const bool last_row = abs(m(3, 0)) <= Scalar(1e-9) && abs(m(3, 1)) <= Scalar(1e-9) &&
                          abs(m(3, 2)) <= Scalar(1e-9) && abs(m(3, 3) - Scalar(1)) <= Scalar(1e-9);
    require(last_row, "matrix last row", Eigen::Matrix<Scalar, 4, 1>(m.row(3).transpose()),
            "must be (0, 0, 0, 1) for a rigid transform");
    return Pose(Matrix3(m.template topLeftCorner<3, 3>()), Vector3(m.template topRightCorner<3, 1>()));
  }

  //! From XYZUVW with U, V, W about the X, Y, Z axes in the order U→V→W about moving axes,
  //! R = Rx(U)·Ry(V)·Rz(W), the rotation acting about `pivot` (body coordinates, default the
  //! origin): x_w = R (x_b − p) + p + (X, Y, Z). With p = 0 this is the plain T = (R, XYZ).
  static Pose from_xyzuvw(const Vector6& xyzuvw, const Vector3& pivot = Vector3::Zero()) {
    require_finite(xyzuvw, "xyzuvw");
    require_translation(xyzuvw.template head<3>(), "xyzuvw (X, Y, Z)");
    require_translation(pivot, "pivot");
    const Quaternion q = Quaternion(Eigen::AngleAxis<Scalar>(xyzuvw(3), Vector3::UnitX())) *
                         Quaternion(Eigen::AngleAxis<Scalar>(xyzuvw(4), Vector3::UnitY())) *
                         Quaternion(Eigen::AngleAxis<Scalar>(xyzuvw(5), Vector3::UnitZ()));
    const Vector3 t = xyzuvw.template head<3>() + pivot - q * pivot;
    return unchecked(q, t);
  }

  //! The inverse of from_xyzuvw: U, W in (−π, π], V in [−π/2, π/2]. At gimbal lock
  //! (cos V < gimbal_lock_tolerance()) V = ±π/2 as computed, W = 0 and U carries the rotation.
  Vector6 to_xyzuvw(const Vector3& pivot = Vector3::Zero()) const {
    require_translation(pivot, "pivot");
    using std::atan2;
    using std::sqrt;
    const Matrix3 r = rotation();
    const Scalar cos_v = sqrt(r(0, 0) * r(0, 0) + r(0, 1) * r(0, 1));
    const Scalar v = atan2(r(0, 2), cos_v);
    const Matrix3 ry_t = Eigen::AngleAxis<Scalar>(-v, Vector3::UnitY()).toRotationMatrix();
    Scalar u;
    Scalar w;
    if (cos_v < gimbal_lock_tolerance<Scalar>()) {
      // Rz(W) and Rx(U) turn about the same world axis: fold everything into U.
      const Matrix3 rx = r * ry_t;  // = Rx(U) when W = 0
      u = atan2(rx(2, 1), rx(1, 1));
      w = Scalar(0);
    } else {
      u = atan2(-r(1, 2), r(2, 2));
      // W from the residual rotation, so that U's rounding is absorbed and R is reproduced
      // to rounding even close to gimbal lock.
      const Matrix3 rz = ry_t * Eigen::AngleAxis<Scalar>(-u, Vector3::UnitX()).toRotationMatrix() * r;
      w = atan2(rz(1, 0), rz(0, 0));
    }
    Vector6 out;
    out.template head<3>() = t_ - pivot + q_ * pivot;
    out(3) = u;
    out(4) = v;
    out(5) = w;
    return out;
  }

  //! The SE(3) exponential of a body twist: T = exp(([ω]ₓ, v)), closed form, stable at θ → 0.
  static Pose exp(const Twist<Scalar>& xi) noexcept {
    const Scalar theta = xi.angular.norm();
    const Matrix3 w = detail::hat(xi.angular);
    // t = V v with V = I + B [ω] + C [ω]²
    const Vector3 t = xi.linear + detail::coefficient_b(theta) * (w * xi.linear) +
                      detail::coefficient_c(theta) * (w * (w * xi.linear));
    return unchecked(quaternion_exp(xi.angular), t);
  }

  //! The SE(3) logarithm: the body twist ξ with exp(ξ) = *this, angle in [0, π]; stable at
  //! θ → 0 and at θ → π (uses the quaternion's half angle, never 1 − cos θ).
  Twist<Scalar> log() const noexcept {
    const Quaternion q = q_.w() < Scalar(0) ? Quaternion(-q_.coeffs()) : q_;
    const Vector3 w = quaternion_log(q);
    const Scalar theta = w.norm();
    // v = V⁻¹ t with V⁻¹ = I − ½[ω] + D [ω]², D = (1 − (θ/2) cot(θ/2)) / θ², cot(θ/2) = w/‖q.vec‖.
    Scalar d;
    if (theta < Scalar(1e-2)) {
      const Scalar t2 = theta * theta;
      d = Scalar(1) / 12 + t2 / 720 + t2 * t2 / 30240;
    } else {
      d = (Scalar(1) - (theta / 2) * q.w() / q.vec().norm()) / (theta * theta);
    }
    const Matrix3 wx = detail::hat(w);
    const Vector3 v = t_ - Scalar(0.5) * (wx * t_) + d * (wx * (wx * t_));
    return Twist<Scalar>(v, w);
  }

  //! Composition: (this · other) x = this(other(x)).
  Pose operator*(const Pose& other) const noexcept {
    // Renormalise: composition chains (e.g. integrating a path) must not drift off unit norm.
    Quaternion q = q_ * other.q_;
    q.normalize();
    return unchecked(q, t_ + q_ * other.t_);
  }

  //! Transform a point from body to world coordinates.
  Vector3 operator*(const Vector3& x_body) const noexcept { return q_ * x_body + t_; }

  //! T⁻¹ = (Rᵀ, −Rᵀ t): world to body coordinates.
  Pose inverse() const noexcept {
    const Quaternion qi = q_.conjugate();
    return unchecked(qi, -(qi * t_));
  }

  //! The pose with orientation `orientation` and the same world position of the body point
  //! `pivot`: R' p + t' = R p + t (a rotation commanded about a pivot point).
  Pose rotated_about_pivot(const Pose& orientation, const Vector3& pivot) const {
    require_translation(pivot, "pivot");
    const Vector3 anchor = *this * pivot;
    return unchecked(orientation.q_, anchor - orientation.q_ * pivot);
  }

  const Quaternion& quaternion() const noexcept { return q_; }         //!< the unit quaternion of R
  const Vector3& translation() const noexcept { return t_; }           //!< t: the body origin in world coordinates
  Matrix3 rotation() const noexcept { return q_.toRotationMatrix(); }  //!< R

  //! The 4×4 homogeneous matrix [R t; 0 1].
  Matrix4 matrix() const noexcept {
    Matrix4 m = Matrix4::Identity();
    m.template topLeftCorner<3, 3>() = rotation();
    m.template topRightCorner<3, 1>() = t_;
    return m;
  }

  //! Same transform to within `tolerance` (rotation as matrix entries, translation in length).
  bool is_approx(const Pose& other, Scalar tolerance) const noexcept {
    return (rotation() - other.rotation()).cwiseAbs().maxCoeff() <= tolerance &&
           (t_ - other.t_).cwiseAbs().maxCoeff() <= tolerance;
  }

  //! No checks: for code that already holds a unit quaternion and finite data.
  static Pose unchecked(const Quaternion& unit_quaternion, const Vector3& translation) noexcept {
    Pose p;
    p.q_ = unit_quaternion;
    p.t_ = translation;
    return p;
  }

 private:
  //! What every pose holds: a finite quaternion of norm 1 to `tolerance` and a translation within
  //! dispkin's numeric range. Returns the norm.
  static Scalar require_pose(const Quaternion& quaternion, const Vector3& translation, Scalar tolerance) {
    const Eigen::Matrix<Scalar, 4, 1> wxyz(quaternion.w(), quaternion.x(), quaternion.y(), quaternion.z());
    require_finite(wxyz, "quaternion (w, x, y, z)");
    require_translation(translation, "translation");
    using std::abs;
    const Scalar norm = quaternion.norm();
    if (!(abs(norm - Scalar(1)) <= tolerance)) {
      std::ostringstream reason;
      reason.precision(17);  // a stored quaternion may be off by 1e-12: show the digits that differ
      reason << "must be a unit quaternion, its norm is " << norm << " (within " << tolerance << " of 1 expected)";
      throw std::invalid_argument(describe("quaternion (w, x, y, z)", wxyz, reason.str()));
    }
    return norm;
  }

  static Quaternion checked_quaternion(const Matrix3& r) {
    require_finite(r, "rotation");
    const Scalar orthogonality = (r.transpose() * r - Matrix3::Identity()).cwiseAbs().maxCoeff();
    // The message only on failure: formatting a number costs more than the whole check.
    if (!(orthogonality <= Scalar(1e-6) && r.determinant() > Scalar(0))) {
      throw std::invalid_argument(
          describe("rotation", r,
                   "must be orthonormal with determinant +1 (max |RᵀR − I| = " + std::to_string(orthogonality) + ")"));
    }
    Quaternion q(r);
    q.normalize();
    return q;
  }

  Quaternion q_;
  Vector3 t_;
};

using Posed = Pose<double>;    //!< a pose in double precision
using Twistd = Twist<double>;  //!< a twist in double precision

}  // namespace dispkin
