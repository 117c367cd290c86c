// The Paden–Kahan subproblems (and IK-Geo's subproblem 4) in product-of-exponentials form.
// Internal to the analytic IK: every solver of src/serial/ik_*.cpp is a sequence of these.
//
// A rotation by θ about the unit axis k acts on a vector p as
//   R(k, θ) p = (k·p) k + cos θ p⊥ + sin θ (k × p),   p⊥ = p − (k·p) k,
// so every scalar subproblem below is the harmonic equation A cos θ + B sin θ = C.
#pragma once

#include <array>
#include <cmath>

#include <Eigen/Core>

#include "angles.hpp"

namespace dispkin {
namespace serial {
namespace detail {

//! An angle as its cosine and sine: the search evaluates thousands of subproblem chains, and
//! composing these needs no trigonometric function (only the final joint values do).
struct CosSin {
  double c = 1.0;
  double s = 0.0;
  //! The angle atan2(s, c) in [−π, π], by reduction to atan on [−1, 1]: glibc's atan2 saves
  //! and restores the floating-point environment on every call, and the closed forms take ~30
  //! of these per pose; this costs about two thirds of it, within 3e-16 rad of atan2.
  //! The quadrant is chosen by table look-ups rather than branches: the closed forms take the
  //! angles of random poses, whose quadrants a branch predictor cannot guess.
  double angle() const noexcept {
    constexpr double half_pi = 0.5 * pi;
    if (c == 0.0 && s == 0.0) return std::atan2(s, c);  // (0, 0): atan2's convention
    const std::size_t steep = std::abs(s) > std::abs(c) ? 1 : 0;
    const double numerator[2] = {s, c};
    const double denominator[2] = {c, s};
    const double a = std::atan(numerator[steep] / denominator[steep]);
    const double flat[2] = {a + std::copysign(2.0 * half_pi, s), a};  // c < 0, c > 0
    const double value[2] = {flat[c > 0.0 ? 1 : 0], std::copysign(half_pi, s) - a};
    return value[steep];
  }
  CosSin inverse() const noexcept { return {c, -s}; }
  bool operator==(const CosSin& o) const noexcept { return c == o.c && s == o.s; }
};

//! R(k, θ) p for a unit axis k, θ given by its cosine and sine.
inline Eigen::Vector3d rotate(const Eigen::Vector3d& k, const CosSin& r, const Eigen::Vector3d& p) noexcept {
  const double kp = k.dot(p);
  return kp * k + r.c * (p - kp * k) + r.s * k.cross(p);
}

//! R(k, θ) p for a unit axis k.
inline Eigen::Vector3d rotate(const Eigen::Vector3d& k, double angle, const Eigen::Vector3d& p) noexcept {
  const double kp = k.dot(p);
  return kp * k + std::cos(angle) * (p - kp * k) + std::sin(angle) * k.cross(p);
}

//! The 3×3 rotation R(k, θ) = cos θ I + sin θ [k]× + (1 − cos θ) k kᵀ (Rodrigues), θ given by
//! its cosine and sine: no trigonometric function.
EIGEN_ALWAYS_INLINE Eigen::Matrix3d rotation(const Eigen::Vector3d& k, const CosSin& r) noexcept {
  const double v = 1.0 - r.c;
  const double x = k.x(), y = k.y(), z = k.z();
  const double vxy = v * x * y, vxz = v * x * z, vyz = v * y * z;
  Eigen::Matrix3d m;
  m(0, 0) = r.c + v * x * x;
  m(1, 1) = r.c + v * y * y;
  m(2, 2) = r.c + v * z * z;
  m(0, 1) = vxy - r.s * z;
  m(1, 0) = vxy + r.s * z;
  m(0, 2) = vxz + r.s * y;
  m(2, 0) = vxz - r.s * y;
  m(1, 2) = vyz - r.s * x;
  m(2, 1) = vyz + r.s * x;
  return m;
}

//! The 3×3 rotation R(k, θ) (Rodrigues).
inline Eigen::Matrix3d rotation(const Eigen::Vector3d& k, double angle) noexcept {
  const double c = std::cos(angle);
  const double s = std::sin(angle);
  Eigen::Matrix3d kx;
  kx << 0.0, -k.z(), k.y(), k.z(), 0.0, -k.x(), -k.y(), k.x(), 0.0;
  return Eigen::Matrix3d::Identity() + s * kx + (1.0 - c) * (kx * kx);
}

//! The (at most two) angles of a scalar subproblem, labelled: `plus` = φ + acos, `minus` =
//! φ − acos (as cosine and sine; .angle() gives the value). At a tangency both labels hold the same angle (one
//! solution). `free`: every angle solves it (the geometry is degenerate there); `plus` = `minus` = 0 represents them.
struct Angles {
  CosSin plus;
  CosSin minus;
  bool exists = false;
  bool free = false;
  double margin = -1.0;  //!< 1 − |C|/r: ≥ 0 where solvable, its distance from the tangency
  bool single() const noexcept { return free || plus == minus; }
};

//! How far past |C| = r (relative) a harmonic equation is still solved at its tangency:
//! rounding puts stretched-elbow and shoulder-boundary poses on either side of it. A
//! candidate admitted this way is only kept if the full pose error is ≤ 1e-10 afterwards.
constexpr double tangency_slack = 1e-9;

//! The harmonic equation A cos θ + B sin θ = C; `scale` is the size of A, B, C for a
//! well-posed problem (it tells a degenerate A = B = 0 from a small one).
struct Harmonic {
  double a = 0.0;
  double b = 0.0;
  double c = 0.0;
  double scale = 1.0;
  //! A² + B² − C²: ≥ 0 exactly where the equation has a solution. Where A, B, C are affine in
  //! cos φ, sin φ of some parameter φ, this is a trigonometric polynomial of degree 2 in φ.
  double discriminant() const noexcept { return a * a + b * b - c * c; }
};

//! Solves A cos θ + B sin θ = C.
inline Angles solve_harmonic(double a, double b, double c, double scale) noexcept {
  Angles out;
  const double r = std::sqrt(a * a + b * b);
  if (r <= 1e-13 * scale) {
    // Degenerate: θ does not enter; solvable (by every θ) iff C vanishes too.
    out.exists = std::abs(c) <= 1e-10 * scale;
    out.free = out.exists;
    out.margin = out.exists ? 0.0 : -1.0;
    return out;
  }
  double x = c / r;
  out.margin = 1.0 - std::abs(x);
  if (std::abs(x) > 1.0 + tangency_slack) return out;
  x = std::max(-1.0, std::min(1.0, x));
  // φ = atan2(B, A), d = acos(x): cos(φ ± d) and sin(φ ± d) by the addition formulas.
  const double cp = a / r, sp = b / r;
  const double sd = std::sqrt(std::max(0.0, 1.0 - x * x));
  out.exists = true;
  out.plus = {cp * x - sp * sd, sp * x + cp * sd};
  out.minus = {cp * x + sp * sd, sp * x - cp * sd};
  return out;
}

inline Angles solve_harmonic(const Harmonic& h) noexcept { return solve_harmonic(h.a, h.b, h.c, h.scale); }

//! Subproblem 1: the θ with R(k, θ) p = q (least squares in the plane normal to k), as
//! cosine and sine. If p or q lies on the axis θ is free; 0 is returned.
inline CosSin subproblem1_cs(const Eigen::Vector3d& k, const Eigen::Vector3d& p, const Eigen::Vector3d& q) noexcept {
  // With p⊥ = p − (k·p) k: sin θ ∝ k · (p⊥ × q⊥) = k · (p × q), cos θ ∝ p⊥ · q⊥ = p · q − (k·p)(k·q).
  const double sine = k.dot(p.cross(q));
  const double cosine = p.dot(q) - k.dot(p) * k.dot(q);
  const double h = std::sqrt(sine * sine + cosine * cosine);
  if (!(h > 1e-300)) return {};
  const double inverse_h = 1.0 / h;
  return {cosine * inverse_h, sine * inverse_h};
}

//! Subproblem 1 as an angle.
inline double subproblem1(const Eigen::Vector3d& k, const Eigen::Vector3d& p, const Eigen::Vector3d& q) noexcept {
  return subproblem1_cs(k, p, q).angle();
}

//! Subproblem 3 (distance): θ with ‖R(k, θ) u − v‖² = δ², u and v relative to a point on the
//! axis (the distance is given squared: the callers have it so, and it enters squared).
inline Harmonic subproblem3_harmonic(const Eigen::Vector3d& k, const Eigen::Vector3d& u, const Eigen::Vector3d& v,
                                     double delta_squared) noexcept {
  const double ku = k.dot(u);
  const Eigen::Vector3d up = u - ku * k;
  const double u2 = u.squaredNorm(), v2 = v.squaredNorm();
  return {v.dot(up), v.dot(k.cross(u)), 0.5 * (u2 + v2 - delta_squared) - ku * k.dot(v), std::sqrt(u2 * v2) + 1e-300};
}
inline Angles subproblem3(const Eigen::Vector3d& k, const Eigen::Vector3d& u, const Eigen::Vector3d& v,
                          double delta_squared) noexcept {
  return solve_harmonic(subproblem3_harmonic(k, u, v, delta_squared));
}

//! Subproblem 4 (projection, IK-Geo): θ with h · R(k, θ) p = d.
inline Harmonic subproblem4_harmonic(const Eigen::Vector3d& h, const Eigen::Vector3d& k, const Eigen::Vector3d& p,
                                     double d) noexcept {
  const double kp = k.dot(p);
  return {h.dot(p - kp * k), h.dot(k.cross(p)), d - kp * k.dot(h),
          std::sqrt(h.squaredNorm() * p.squaredNorm()) + 1e-300};
}
inline Angles subproblem4(const Eigen::Vector3d& h, const Eigen::Vector3d& k, const Eigen::Vector3d& p,
                          double d) noexcept {
  return solve_harmonic(subproblem4_harmonic(h, k, p, d));
}

//! Subproblem 2's two solutions (θ₁, θ₂) labelled by the sign of the out-of-plane component.
struct AnglePairs {
  std::array<CosSin, 2> first{};   //!< θ₁ for the labels + and −
  std::array<CosSin, 2> second{};  //!< θ₂ for the labels + and −
  bool exists = false;
  bool single = false;   //!< tangency: both labels hold the same pair
  double margin = -1.0;  //!< γ² (1 − (k₁·k₂)²) / ‖p‖²: ≥ 0 where solvable
};

//! Subproblem 2: (θ₁, θ₂) with R(k₁, θ₁) R(k₂, θ₂) p = q for non-parallel unit axes through a
//! common point, ‖p‖ = ‖q‖. The intermediate x = R(k₂, θ₂) p = R(k₁, −θ₁) q satisfies
//! k₂·x = k₂·p, k₁·x = k₁·q, ‖x‖ = ‖p‖; in the basis (k₁, k₂, k₁ × k₂) that is two linear
//! equations and one quadratic.
inline AnglePairs subproblem2(const Eigen::Vector3d& k1, const Eigen::Vector3d& k2, const Eigen::Vector3d& p,
                              const Eigen::Vector3d& q) noexcept {
  AnglePairs out;
  const double c12 = k1.dot(k2);
  const Eigen::Vector3d n = k1.cross(k2);
  const double den = n.squaredNorm();  // 1 − c12²
  const double b1 = k1.dot(q);
  const double b2 = k2.dot(p);
  const double alpha = (b1 - c12 * b2) / den;
  const double beta = (b2 - c12 * b1) / den;
  const double length2 = 0.5 * (p.squaredNorm() + q.squaredNorm());
  const Eigen::Vector3d in_plane = alpha * k1 + beta * k2;
  double gamma2 = (length2 - in_plane.squaredNorm()) / den;
  out.margin = gamma2 * den / (length2 + 1e-300);
  if (gamma2 < -tangency_slack * (length2 + 1e-300) / den) return out;
  out.exists = true;
  out.single = gamma2 <= 0.0;
  const double gamma = std::sqrt(std::max(0.0, gamma2));
  for (int label = 0; label < 2; ++label) {
    const Eigen::Vector3d x = in_plane + (label == 0 ? gamma : -gamma) * n;
    out.second[label] = subproblem1_cs(k2, p, x);
    out.first[label] = subproblem1_cs(k1, x, q);
  }
  return out;
}

}  // namespace detail
}  // namespace serial
}  // namespace dispkin
