//! The DISP metric: chord distance, point and sphere speeds, and exact section lengths.
//!
//! doc/disp-metric.md §5–8, doc/section-length.md §2–3. Pure functions of a MetricSet and poses;
//! none allocates. They throw only on bad input (a set that is not well-formed, a missing system
//! velocity for a group limit).
#pragma once

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "dispkin/error.hpp"
#include "dispkin/metric_set.hpp"
#include "dispkin/pose.hpp"

namespace dispkin {

//! How a section moves between its end poses (doc/disp-metric.md eqs. 13–15).
enum class Interpolation {
  screw,      //!< T(τ) = Ta·exp(τ ξ): constant body twist
  decoupled,  //!< pivot on a straight line, orientation by SLERP about one fixed axis (LIN)
};

//! The interpolation's name: "screw" or "decoupled" (read back by interpolation_from_string).
inline const char* to_string(Interpolation kind) { return kind == Interpolation::screw ? "screw" : "decoupled"; }

//! "screw" or "decoupled"; anything else throws std::invalid_argument naming the value.
inline Interpolation interpolation_from_string(const std::string& name) {
  if (name == "screw") return Interpolation::screw;
  if (name == "decoupled") return Interpolation::decoupled;
  throw std::invalid_argument(describe("interpolation", name, "must be \"decoupled\" or \"screw\""));
}

// ---------------------------------------------------------------------------------------------
// Norm policies for the chord distance ("metric form", doc/disp-metric.md eq. 22). Each gives the
// norm of a vector and its maximum over a flat disk {u + x : x ⊥ n̂, ‖x‖₂ ≤ r}, the set of chords
// of a ball under a rigid motion (used for spheres).

//! The Euclidean norm (the default, and the only one under which speeds are rotation-invariant).
struct EuclideanNorm {
  //! ‖u‖₂.
  template <typename Scalar>
  static Scalar of(const Eigen::Matrix<Scalar, 3, 1>& u) {
    return u.norm();
  }
  //! Over many points (Eigen arrays of coordinates): a key monotone in the norm (here its
  //! square), so that one root is taken at the end, not one per point.
  template <typename X, typename Y, typename Z>
  static auto key(const X& x, const Y& y, const Z& z) {
    return x.square() + y.square() + z.square();
  }
  //! The norm of a key: its square root.
  template <typename Scalar>
  static Scalar from_key(Scalar key) {
    using std::sqrt;
    return sqrt(key);
  }
  //! The largest norm of u + x over the disk x ⊥ n̂, ‖x‖₂ ≤ r (n̂ a unit vector).
  template <typename Scalar>
  static Scalar max_over_disk(const Eigen::Matrix<Scalar, 3, 1>& u, const Eigen::Matrix<Scalar, 3, 1>& n, Scalar r) {
    using std::sqrt;
    const Scalar along = u.dot(n);
    const Scalar across = (u - along * n).norm();
    return sqrt(along * along + (across + r) * (across + r));
  }
};

//! The maximum norm max |uᵢ|.
struct MaxNorm {
  //! max |uᵢ|.
  template <typename Scalar>
  static Scalar of(const Eigen::Matrix<Scalar, 3, 1>& u) {
    return u.cwiseAbs().maxCoeff();
  }
  //! Over many points: the norm itself, coordinate-wise.
  template <typename X, typename Y, typename Z>
  static auto key(const X& x, const Y& y, const Z& z) {
    return x.abs().max(y.abs()).max(z.abs());
  }
  //! The norm of a key: the key.
  template <typename Scalar>
  static Scalar from_key(Scalar key) {
    return key;
  }
  //! The largest norm of u + x over the disk x ⊥ n̂, ‖x‖₂ ≤ r: the max over the disk of ±eᵢ·x
  //! is r‖eᵢ − (eᵢ·n̂)n̂‖ = r √(1 − n̂ᵢ²).
  template <typename Scalar>
  static Scalar max_over_disk(const Eigen::Matrix<Scalar, 3, 1>& u, const Eigen::Matrix<Scalar, 3, 1>& n, Scalar r) {
    using std::abs;
    using std::sqrt;
    Scalar best(0);
    for (int i = 0; i < 3; ++i) {
      const Scalar reach = abs(u(i)) + r * sqrt(std::max(Scalar(0), Scalar(1) - n(i) * n(i)));
      best = std::max(best, reach);
    }
    return best;
  }
};

//! The L1 norm Σ |uᵢ|.
struct L1Norm {
  //! Σ |uᵢ|.
  template <typename Scalar>
  static Scalar of(const Eigen::Matrix<Scalar, 3, 1>& u) {
    return u.cwiseAbs().sum();
  }
  //! Over many points: the norm itself, coordinate-wise.
  template <typename X, typename Y, typename Z>
  static auto key(const X& x, const Y& y, const Z& z) {
    return x.abs() + y.abs() + z.abs();
  }
  //! The norm of a key: the key.
  template <typename Scalar>
  static Scalar from_key(Scalar key) {
    return key;
  }
  //! The largest norm of u + x over the disk x ⊥ n̂, ‖x‖₂ ≤ r: ‖x‖₁ = max over sign vectors s
  //! of s·x, and over the disk s·x peaks at s·u + r‖s − (s·n̂)n̂‖.
  template <typename Scalar>
  static Scalar max_over_disk(const Eigen::Matrix<Scalar, 3, 1>& u, const Eigen::Matrix<Scalar, 3, 1>& n, Scalar r) {
    using std::sqrt;
    Scalar best(0);
    for (int mask = 0; mask < 8; ++mask) {
      const Eigen::Matrix<Scalar, 3, 1> s((mask & 1) ? -1 : 1, (mask & 2) ? -1 : 1, (mask & 4) ? -1 : 1);
      const Scalar sn = s.dot(n);
      best = std::max(best, s.dot(u) + r * sqrt(std::max(Scalar(0), Scalar(3) - sn * sn)));
    }
    return best;
  }
};

namespace detail {

// A system velocity, when given, must be a speed even if no group needs it.
template <typename Scalar>
void require_system_velocity(const std::optional<Scalar>& system_velocity) {
  if (system_velocity) require_limit(*system_velocity, "system_velocity");
}

}  // namespace detail

// ---------------------------------------------------------------------------------------------
// Speeds for a twist (doc/disp-metric.md eqs. 23–25).

//! Speed of the body point p under body twist (v, ω): ‖v + ω × p‖. Also the apparent speed
//! of an absolute point whose current body coordinates are p.
template <typename Scalar>
Scalar point_speed(const Twist<Scalar>& xi, const non_deduced<Eigen::Matrix<Scalar, 3, 1>>& p) noexcept {
  return (xi.linear + xi.angular.cross(p)).norm();
}

//! Largest speed of any point of the ball (centre c, radius ρ) under body twist (v, ω), exact:
//! √((v_c·ω̂)² + (‖v_c − (v_c·ω̂)ω̂‖ + ‖ω‖ρ)²) with v_c = v + ω × c; ‖v_c‖ when ω = 0.
template <typename Scalar>
Scalar sphere_speed(const Twist<Scalar>& xi, const non_deduced<Eigen::Matrix<Scalar, 3, 1>>& center,
                    non_deduced<Scalar> radius) noexcept {
  using std::sqrt;
  const Eigen::Matrix<Scalar, 3, 1> vc = xi.linear + xi.angular.cross(center);
  const Scalar w2 = xi.angular.squaredNorm();
  if (w2 == Scalar(0)) return vc.norm();
  const Eigen::Matrix<Scalar, 3, 1> w_hat = xi.angular / sqrt(w2);
  const Scalar along = vc.dot(w_hat);
  // The across-axis part as a norm (not √(‖v_c‖² − along²), which cancels on the axis).
  const Scalar rim = (vc - along * w_hat).norm() + sqrt(w2) * radius;
  return sqrt(along * along + rim * rim);
}

namespace detail {

// The body twist (v, ω) at pose T seen in world coordinates as a spatial twist (v_s, ω_s):
// the apparent speed of the absolute point a, ‖v + ω × T⁻¹a‖, equals ‖v_s + ω_s × a‖ with
// ω_s = R ω, v_s = R v − ω_s × t. One rotation for the whole set instead of one per point.
template <typename Scalar>
Twist<Scalar> world_view(const Pose<Scalar>& pose, const Twist<Scalar>& body) noexcept {
  const Eigen::Matrix<Scalar, 3, 1> ws = pose.quaternion() * body.angular;
  const Eigen::Matrix<Scalar, 3, 1> vs = pose.quaternion() * body.linear - ws.cross(pose.translation());
  return Twist<Scalar>(vs, ws);
}

// max over the points p of ‖v + ω × p‖²: the speed of a twist (v, ω) at every point, one
// vectorised pass over the coordinate columns, no temporaries.
template <typename Scalar>
Scalar max_speed2(const PointColumns<Scalar>& points, const Eigen::Matrix<Scalar, 3, 1>& v,
                  const Eigen::Matrix<Scalar, 3, 1>& w) noexcept {
  if (points.empty()) return Scalar(0);
  const auto x = points.x(), y = points.y(), z = points.z();
  if (points.size() <= 32) {
    // A tool's handful of points: a plain loop (the same sums in the same order) is cheaper than
    // setting up the array expression. The squared speeds go to a buffer first and the maximum
    // is taken after: without -ffast-math GCC vectorises only a loop without the max reduction.
    const Scalar *xs = x.data(), *ys = y.data(), *zs = z.data();
    const std::size_t n = points.size();
    Scalar speed2[32];
    const Scalar vx = v.x(), vy = v.y(), vz = v.z(), wx = w.x(), wy = w.y(), wz = w.z();
    for (std::size_t i = 0; i < n; ++i) {
      const Scalar ex = vx + wy * zs[i] - wz * ys[i];
      const Scalar ey = vy + wz * xs[i] - wx * zs[i];
      const Scalar ez = vz + wx * ys[i] - wy * xs[i];
      speed2[i] = ex * ex + ey * ey + ez * ez;
    }
    Scalar best(0);
    for (std::size_t i = 0; i < n; ++i) best = std::max(best, speed2[i]);
    return best;
  }
  return ((v.x() + w.y() * z - w.z() * y).square() + (v.y() + w.z() * x - w.x() * z).square() +
          (v.z() + w.x() * y - w.y() * x).square())
      .maxCoeff();
}

// max over the points p of the key of ‖M p + c‖ under `Norm` (chords are affine in p).
template <typename Norm, typename Scalar>
Scalar max_affine_key(const PointColumns<Scalar>& points, const Eigen::Matrix<Scalar, 3, 3>& m,
                      const Eigen::Matrix<Scalar, 3, 1>& c) noexcept {
  if (points.empty()) return Scalar(0);
  const auto x = points.x(), y = points.y(), z = points.z();
  return Norm::key(m(0, 0) * x + m(0, 1) * y + m(0, 2) * z + c.x(), m(1, 0) * x + m(1, 1) * y + m(1, 2) * z + c.y(),
                   m(2, 0) * x + m(2, 1) * y + m(2, 2) * z + c.z())
      .maxCoeff();
}

// Largest speed of the group's objects under `body` at `pose`.
template <typename Scalar>
Scalar group_max_speed(const MetricGroup<Scalar>& g, const Pose<Scalar>& pose, const Twist<Scalar>& body) noexcept {
  using std::sqrt;
  Scalar best2 = max_speed2(g.relative_points, body.linear, body.angular);
  Scalar best(0);
  for (const auto& s : g.relative_spheres) best = std::max(best, sphere_speed(body, s.center, s.radius));
  if (!g.absolute_points.empty() || !g.absolute_spheres.empty()) {
    const Twist<Scalar> world = world_view(pose, body);
    best2 = std::max(best2, max_speed2(g.absolute_points, world.linear, world.angular));
    for (const auto& s : g.absolute_spheres) best = std::max(best, sphere_speed(world, s.center, s.radius));
  }
  return std::max(best, sqrt(best2));
}

}  // namespace detail

//! The DISP speed of the set at `pose` moving with body twist `body`: the largest speed of any
//! of its points and spheres, each group's speed multiplied by its weight v_sys / v_g.
template <typename Scalar>
Scalar max_point_speed(const MetricSet<Scalar>& set, const Pose<Scalar>& pose, const Twist<Scalar>& body,
                       std::optional<non_deduced<Scalar>> system_velocity = std::nullopt) {
  // A speed of 0 must mean "standing still", never "nothing was measured". (A collinear set
  // is fine here: its speed is well defined, only its distance is not a metric.)
  if (set.empty())
    throw std::invalid_argument(
        describe("metric_set", std::string("MetricSet"), "is empty: there is no point whose speed could be measured"));
  require_finite(body.vector(), "twist");
  detail::require_system_velocity(system_velocity);
  Scalar best(0);
  for (const auto& g : set.groups())
    best = std::max(best, g.weight(system_velocity) * detail::group_max_speed(g, pose, body));
  return best;
}

// ---------------------------------------------------------------------------------------------
// Chord distance (doc/disp-metric.md eqs. 18–22)

namespace detail {

// Chord length of every object of a group between poses a and b, under `Norm`.
template <typename Norm, typename Scalar>
Scalar group_chord(const MetricGroup<Scalar>& g, const Pose<Scalar>& a, const Pose<Scalar>& b) {
  using Vector3 = Eigen::Matrix<Scalar, 3, 1>;
  using Matrix3 = Eigen::Matrix<Scalar, 3, 3>;
  using std::sin;
  const bool relative = !g.relative_points.empty() || !g.relative_spheres.empty();
  const bool absolute = !g.absolute_points.empty() || !g.absolute_spheres.empty();
  const bool spheres = !g.relative_spheres.empty() || !g.absolute_spheres.empty();

  // Spheres only: the relative rotation Q = Raᵀ Rb turns by φ about k (body coordinates of
  // a), and a ball of radius ρ under x ↦ (Q − I)x becomes a flat disk ⊥ k of radius
  // 2ρ sin(φ/2).
  Vector3 k = Vector3::UnitZ();
  Scalar disk_scale(0);
  if (spheres) {
    const Vector3 rotvec = quaternion_log(Eigen::Quaternion<Scalar>(a.quaternion().conjugate() * b.quaternion()));
    const Scalar phi = rotvec.norm();
    if (phi > Scalar(0)) k = rotvec / phi;
    disk_scale = 2 * sin(phi / 2);
  }

  Scalar best(0);
  if (relative) {
    // Tb r − Ta r = (Rb − Ra) r + (tb − ta), in world coordinates.
    const Matrix3 dr = b.rotation() - a.rotation();
    const Vector3 dt = b.translation() - a.translation();
    best = Norm::from_key(max_affine_key<Norm>(g.relative_points, dr, dt));
    const Vector3 axis_world = a.quaternion() * k;
    for (const auto& s : g.relative_spheres)
      best = std::max(best, Norm::max_over_disk(Vector3(dr * s.center + dt), axis_world, disk_scale * s.radius));
  }
  if (absolute) {
    // Tb⁻¹ x − Ta⁻¹ x = (Rbᵀ − Raᵀ) x − (Rbᵀ tb − Raᵀ ta), in body coordinates.
    const Matrix3 ra_t = a.rotation().transpose();
    const Matrix3 rb_t = b.rotation().transpose();
    const Matrix3 dr = rb_t - ra_t;
    const Vector3 dt = rb_t * b.translation() - ra_t * a.translation();
    best = std::max(best, Norm::from_key(max_affine_key<Norm>(g.absolute_points, dr, Vector3(-dt))));
    for (const auto& s : g.absolute_spheres)
      best = std::max(best, Norm::max_over_disk(Vector3(dr * s.center - dt), k, disk_scale * s.radius));
  }
  return best;
}

}  // namespace detail

//! The DISP distance d(a, b) = max over groups of weight · (largest chord of any object), chords
//! measured with `Norm` (doc/disp-metric.md eq. 19). A metric on SE(3) for a well-formed set.
template <typename Norm = EuclideanNorm, typename Scalar>
Scalar disp_distance(const MetricSet<Scalar>& set, const Pose<Scalar>& a, const Pose<Scalar>& b,
                     std::optional<non_deduced<Scalar>> system_velocity = std::nullopt) {
  set.require_well_formed();
  detail::require_system_velocity(system_velocity);
  Scalar best(0);
  for (const auto& g : set.groups())
    best = std::max(best, g.weight(system_velocity) * detail::group_chord<Norm>(g, a, b));
  return best;
}

// ---------------------------------------------------------------------------------------------
// Section length (doc/section-length.md eq. 1; screw eq. 4, decoupled eqs. 5–11): the largest
// speed of any object per unit of τ ∈ [0, 1].

namespace detail {

// q·v·q̄ with exactly the operations of Eigen's Quaternion * Vector3 — u = 2 (q_v × v), then
// v + w u + q_v × u — so with the same rounding, written out in scalars and always inlined: a
// decoupled section's set-up is a handful of rotations, and GCC keeps Eigen's cross products
// out of line in a large translation unit.
template <typename Scalar>
EIGEN_ALWAYS_INLINE Eigen::Matrix<Scalar, 3, 1> rotate(const Eigen::Quaternion<Scalar>& q,
                                                       const Eigen::Matrix<Scalar, 3, 1>& v) noexcept {
  const Scalar x = q.x(), y = q.y(), z = q.z(), w = q.w();
  Scalar ux = y * v.z() - z * v.y(), uy = z * v.x() - x * v.z(), uz = x * v.y() - y * v.x();
  ux += ux;
  uy += uy;
  uz += uz;
  return Eigen::Matrix<Scalar, 3, 1>(v.x() + w * ux + (y * uz - z * uy), v.y() + w * uy + (z * ux - x * uz),
                                     v.z() + w * uz + (x * uy - y * ux));
}

// q̄·v·q: world to body coordinates (the conjugate's sign flips are exact).
template <typename Scalar>
EIGEN_ALWAYS_INLINE Eigen::Matrix<Scalar, 3, 1> rotate_back(const Eigen::Quaternion<Scalar>& q,
                                                            const Eigen::Matrix<Scalar, 3, 1>& v) noexcept {
  return rotate(Eigen::Quaternion<Scalar>(q.w(), -q.x(), -q.y(), -q.z()), v);
}

// A decoupled section, precomputed once for all objects: the pivot travels Δc (world) while
// the orientation turns by θ about k (body coordinates of a) — ω per unit τ is Ω = θ k.
template <typename Scalar>
struct DecoupledSection {
  using Vector3 = Eigen::Matrix<Scalar, 3, 1>;

  DecoupledSection(const Pose<Scalar>& a, const Pose<Scalar>& b, const Vector3& pivot) noexcept
      : DecoupledSection(a.quaternion(), b.quaternion(), pivot_at(a, pivot), pivot_at(b, pivot) - pivot_at(a, pivot),
                         quaternion_log(Eigen::Quaternion<Scalar>(a.quaternion().conjugate() * b.quaternion())),
                         pivot) {}

  // From its parts, when the caller knows them without a logarithm: the orientations at both
  // ends, the pivot's start ca and travel Δc (world), and Ω = log(Raᵀ Rb) (body of a, angle
  // in [0, π]).
  DecoupledSection(const Eigen::Quaternion<Scalar>& qa, const Eigen::Quaternion<Scalar>& qb, const Vector3& ca,
                   const Vector3& travel, const Vector3& rotation, const Vector3& pivot) noexcept {
    q_a = qa;
    delta_c = travel;
    omega = rotation;
    theta = omega.norm();
    k = theta > Scalar(0) ? Vector3(omega / theta) : Vector3::UnitZ();
    pivot_body = pivot;
    // Body-frame views of Δc at both ends (Rb = Ra·exp(θk), so they differ by a turn about k).
    d_a = rotate_back(qa, delta_c);
    d_b = rotate_back(qb, delta_c);
    along = d_a.dot(k);
    d_a_across = d_a - along * k;
    d_b_across = d_b - along * k;
    across = d_a_across.norm();
    // q·m_a ≥ 0 and q·m_b ≥ 0 say that the direction of Δc⊥ lies on the arc swept by the
    // direction of ω × (r − p) (θ ≤ π): there the speed peaks between the ends.
    m_a = d_a.cross(omega);
    m_b = omega.cross(d_b);
    pivot_start = ca;
  }

  // Squared speed peak over τ of every relative point r, where v(τ) = Δc + θ ŵ × u(τ): in the
  // body frame of a, q = Ω × (r − p) and the velocity at the ends is d_a + q, d_b + q; between
  // them the speed peaks at along² + (across + ‖q‖)² when the arc swept by the direction of q
  // contains that of Δc⊥ (q·m_a ≥ 0 and q·m_b ≥ 0).
  Scalar relative_points_speed2(const PointColumns<Scalar>& points) const noexcept {
    const std::size_t n = points.size();
    if (n == 0) return Scalar(0);
    // Four points at a time in fixed-size arrays, which Eigen evaluates in SIMD packets (GCC
    // vectorises neither a floating max reduction nor a select without -ffast-math); each lane
    // keeps its own maxima, and the maxima are exact whatever the order they are taken in.
    using Lanes = Eigen::Array<Scalar, 4, 1>;
    const Scalar px = pivot_body.x(), py = pivot_body.y(), pz = pivot_body.z();
    const Scalar ox = omega.x(), oy = omega.y(), oz = omega.z();
    const Scalar dax = d_a.x(), day = d_a.y(), daz = d_a.z(), dbx = d_b.x(), dby = d_b.y(), dbz = d_b.z();
    const Scalar max_ = m_a.x(), may = m_a.y(), maz = m_a.z(), mbx = m_b.x(), mby = m_b.y(), mbz = m_b.z();
    Lanes ends2 = Lanes::Zero();
    Lanes inside_q2 = Lanes::Constant(Scalar(-1));  // the peak grows with ‖q‖: the largest ‖q‖² inside
    const auto four_points = [&](const Lanes& x, const Lanes& y, const Lanes& z) {
      const Lanes rx = x - px, ry = y - py, rz = z - pz;
      const Lanes qx = oy * rz - oz * ry;
      const Lanes qy = oz * rx - ox * rz;
      const Lanes qz = ox * ry - oy * rx;
      const Lanes ax = dax + qx, ay = day + qy, az = daz + qz;
      const Lanes bx = dbx + qx, by = dby + qy, bz = dbz + qz;
      ends2 = ends2.max((ax * ax + ay * ay + az * az).max(bx * bx + by * by + bz * bz));
      const Lanes q2 = qx * qx + qy * qy + qz * qz;
      const Lanes on_arc = (qx * max_ + qy * may + qz * maz).min(qx * mbx + qy * mby + qz * mbz);
      inside_q2 = inside_q2.max((on_arc >= Scalar(0)).select(q2, Scalar(-1)));
    };
    const Scalar* xs = points.x().data();
    const Scalar* ys = points.y().data();
    const Scalar* zs = points.z().data();
    std::size_t i = 0;
    for (; i + 4 <= n; i += 4)
      four_points(Eigen::Map<const Lanes>(xs + i), Eigen::Map<const Lanes>(ys + i), Eigen::Map<const Lanes>(zs + i));
    if (i < n) {
      Lanes x, y, z;
      for (Eigen::Index j = 0; j < 4; ++j) {
        const std::size_t at = std::min(i + static_cast<std::size_t>(j), n - 1);  // a point twice: same maxima
        x[j] = xs[at];
        y[j] = ys[at];
        z[j] = zs[at];
      }
      four_points(x, y, z);
    }
    const Scalar end_max = ends2.maxCoeff(), q2_max = inside_q2.maxCoeff();
    if (q2_max < Scalar(0)) return end_max;
    using std::sqrt;
    const Scalar rim = across + sqrt(q2_max);
    return std::max(end_max, along * along + rim * rim);
  }

  // Peak over τ of a relative sphere: the centre's velocity across k is maximised as for a
  // point, then the rim adds θρ across the axis (exact: doc/disp-metric.md eq. 25 with ω = θ ŵ;
  // doc/section-length.md eq. 9).
  Scalar relative_sphere_speed(const Sphere<Scalar>& s) const noexcept {
    using std::sqrt;
    const Vector3 q = omega.cross(s.center - pivot_body);
    Scalar across_peak = std::max((d_a_across + q).norm(), (d_b_across + q).norm());
    if (q.dot(m_a) >= Scalar(0) && q.dot(m_b) >= Scalar(0)) across_peak = std::max(across_peak, across + q.norm());
    const Scalar rim = across_peak + theta * s.radius;
    return sqrt(along * along + rim * rim);
  }

  // World view for absolute objects: g(τ) = Δc + θ ŵ × (x − c(τ)), affine in τ; Ω_w = Ra Ω and
  // ŵ = Ra k, made only for a group that has absolute objects.
  struct World {
    Vector3 omega, w_hat;
  };
  World world() const noexcept { return {rotate(q_a, omega), rotate(q_a, k)}; }

  // Absolute points: the apparent velocity g(τ) = Δc + Ω_w × (x − c(τ)) is affine in τ, so
  // the peak is at an end; at each end it is the speed of the twist (e, Ω_w) at x, with
  // e₀ = Δc − Ω_w × c_a and e₁ = e₀ − Ω_w × Δc.
  Scalar absolute_points_speed2(const PointColumns<Scalar>& points, const World& world) const noexcept {
    const Vector3 e0 = delta_c - world.omega.cross(pivot_start);
    const Vector3 e1 = e0 - world.omega.cross(delta_c);
    return std::max(max_speed2(points, e0, world.omega), max_speed2(points, e1, world.omega));
  }

  Scalar absolute_sphere_speed(const Sphere<Scalar>& s, const World& world) const noexcept {
    using std::sqrt;
    const Vector3 g0 = delta_c + world.omega.cross(s.center - pivot_start);
    const Vector3 g1 = g0 - world.omega.cross(delta_c);
    const Scalar along_w = delta_c.dot(world.w_hat);
    const Scalar across_peak =
        std::max((g0 - g0.dot(world.w_hat) * world.w_hat).norm(), (g1 - g1.dot(world.w_hat) * world.w_hat).norm());
    const Scalar rim = across_peak + theta * s.radius;
    return sqrt(along_w * along_w + rim * rim);
  }

  Eigen::Quaternion<Scalar> q_a;
  Vector3 delta_c, omega, k, pivot_body, d_a, d_b, d_a_across, d_b_across, m_a, m_b, pivot_start;
  Scalar theta, along, across;

 private:
  EIGEN_ALWAYS_INLINE static Vector3 pivot_at(const Pose<Scalar>& pose, const Vector3& pivot) noexcept {
    return rotate(pose.quaternion(), pivot) + pose.translation();
  }
};

template <typename Scalar>
Scalar group_decoupled_length(const MetricGroup<Scalar>& g, const DecoupledSection<Scalar>& section) noexcept {
  using std::sqrt;
  Scalar best2 = section.relative_points_speed2(g.relative_points);
  Scalar best(0);
  for (const auto& s : g.relative_spheres) best = std::max(best, section.relative_sphere_speed(s));
  if (!g.absolute_points.empty() || !g.absolute_spheres.empty()) {
    const typename DecoupledSection<Scalar>::World world = section.world();
    best2 = std::max(best2, section.absolute_points_speed2(g.absolute_points, world));
    for (const auto& s : g.absolute_spheres) best = std::max(best, section.absolute_sphere_speed(s, world));
  }
  return std::max(best, sqrt(best2));
}

}  // namespace detail

//! The exact length L of the section from `a` to `b` under the set: the largest speed of any point
//! or sphere per unit of the section parameter τ ∈ [0, 1] (doc/section-length.md eq. 1), each group
//! weighted by v_sys / v_g. With τ = (s − s_k)/L every object moves at most at speed ṡ.
//!
//! `pivot` (body coordinates) is the point that travels the straight line of a decoupled
//! section; a screw section does not depend on it.
template <typename Scalar>
Scalar section_length(const MetricSet<Scalar>& set, const Pose<Scalar>& a, const Pose<Scalar>& b,
                      Interpolation interpolation,
                      const non_deduced<Eigen::Matrix<Scalar, 3, 1>>& pivot = Eigen::Matrix<Scalar, 3, 1>::Zero(),
                      std::optional<non_deduced<Scalar>> system_velocity = std::nullopt) {
  set.require_well_formed();
  detail::require_system_velocity(system_velocity);
  require_translation(pivot, "pivot");
  Scalar best(0);
  if (interpolation == Interpolation::screw) {
    // Constant body twist: every object's speed is constant along the section
    // (doc/section-length.md eq. 3), so the speed at τ = 0 is the section length.
    const Twist<Scalar> xi = (a.inverse() * b).log();
    for (const auto& g : set.groups())
      best = std::max(best, g.weight(system_velocity) * detail::group_max_speed(g, a, xi));
  } else {
    const detail::DecoupledSection<Scalar> section(a, b, pivot);
    for (const auto& g : set.groups())
      best = std::max(best, g.weight(system_velocity) * detail::group_decoupled_length(g, section));
  }
  return best;
}

//! The pose at τ ∈ [0, 1] of a section — the motion whose speed section_length bounds.
template <typename Scalar>
Pose<Scalar> interpolate(
    const Pose<Scalar>& a, const Pose<Scalar>& b, non_deduced<Scalar> tau, Interpolation interpolation,
    const non_deduced<Eigen::Matrix<Scalar, 3, 1>>& pivot = Eigen::Matrix<Scalar, 3, 1>::Zero()) noexcept {
  if (interpolation == Interpolation::screw) return a * Pose<Scalar>::exp((a.inverse() * b).log() * tau);
  // Decoupled: R(τ) = Ra·exp(τ θ k), pivot c(τ) = ca + τ Δc, t = c − R p.
  const Eigen::Quaternion<Scalar> q_rel = a.quaternion().conjugate() * b.quaternion();
  const Eigen::Quaternion<Scalar> q = a.quaternion() * quaternion_exp<Scalar>(tau * quaternion_log(q_rel));
  const Eigen::Matrix<Scalar, 3, 1> c = a * pivot + tau * (b * pivot - a * pivot);
  return Pose<Scalar>::unchecked(q.normalized(), c - q * pivot);
}

}  // namespace dispkin
