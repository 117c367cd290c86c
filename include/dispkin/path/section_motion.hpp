//! The sampling forms of path sections: what SampledPath (and so Trajectory::sample) evaluates,
//! precomputed when the path is sampled so that a sample costs at most two sine/cosine pairs (one
//! per turning angle; short polynomials for the small turns of arc sections, power series for a
//! curve's rotation up to 1 rad), no logarithm and no matrix: the sampling path is noexcept and
//! allocation-free. The numeric kernels they share (sin_cos, the series exp and right Jacobian)
//! are in namespace detail.
//!
//! Each form gives the pose and the body twist per unit τ of its section at τ ∈ [0, 1], the
//! same motion as the section's own pose()/twist() (to rounding). The parts a section is cut
//! into share its form.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstring>
#include <utility>
#include <variant>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "dispkin/path/curve_section.hpp"
#include "dispkin/path/path.hpp"
#include "dispkin/pose.hpp"

namespace dispkin {
namespace detail {

//! Angles up to which sin_cos uses its polynomials: |x| ≤ 1/8 rad. A CIRC section's pivot
//! turns by at most its tolerance (≤ 0.1 rad) and its orientation by a share of the whole turn,
//! so the sections of arcs (and short LINs) take this branch; larger turns call std::sin and
//! std::cos.
constexpr double small_angle = 0.125;

//! sin x and cos x. For |x| ≤ small_angle their Taylor polynomials (to x⁹ and x¹⁰: the first
//! terms left out, x¹¹/11! and x¹²/12!, are below 3·10⁻¹⁷ and 10⁻¹⁹ relative there, a
//! fraction of an ulp), cheaper than the library pair on the sampling path and within 2 ulp
//! of std::sin and std::cos (SectionMotion.SmallAngleSineCosine). Otherwise the library's.
inline void sin_cos(double x, double& sine, double& cosine) noexcept {
  if (!(std::abs(x) <= small_angle)) {
    sine = std::sin(x);
    cosine = std::cos(x);
    return;
  }
  const double x2 = x * x;
  sine = x * (1.0 + x2 * (-1.0 / 6.0 + x2 * (1.0 / 120.0 + x2 * (-1.0 / 5040.0 + x2 * (1.0 / 362880.0)))));
  cosine = 1.0 + x2 * (-0.5 + x2 * (1.0 / 24.0 + x2 * (-1.0 / 720.0 + x2 * (1.0 / 40320.0 + x2 * (-1.0 / 3628800.0)))));
}

//! Rotation angles up to which exp_and_right_jacobian_sampled uses power series: θ ≤ 1 rad.
constexpr double series_angle = 1.0;

//! exp(φ) and J_r(φ) u as exp_and_right_jacobian, for sampling: for θ = |φ| ≤ series_angle
//! from power series in θ² (all four coefficients are even functions of θ), so no square
//! root, sine, cosine or division is on the sampling path:
//!   cos(θ/2) = Σ (−y)ᵏ/(2k)!,  sin(θ/2)/θ = ½ Σ (−y)ᵏ/(2k+1)!   (y = θ²/4, k ≤ 7),
//!   B = (1 − cos θ)/θ² = 2 (sin(θ/2)/θ)²,  C = (θ − sin θ)/θ³ = Σ (−θ²)ᵏ/(2k+3)!  (k ≤ 8).
//! The first terms left out are below 10⁻¹⁸ relative at θ = 1; C is then more accurate than its
//! closed form, which cancels for small θ. Within 10⁻¹⁵ of a long-double evaluation
//! (SectionMotion.SeriesExpAndRightJacobian). Larger angles: exp_and_right_jacobian.
inline void exp_and_right_jacobian_sampled(const Eigen::Vector3d& phi, const Eigen::Vector3d& u,
                                           Eigen::Quaterniond& exp_phi, Eigen::Vector3d& jacobian_u) noexcept {
  const double t2 = phi.squaredNorm();
  if (!(t2 <= series_angle * series_angle)) {
    exp_and_right_jacobian(phi, u, exp_phi, jacobian_u);
    return;
  }
  // Coefficients 1/n! (exact to rounding), summed in Estrin's order (pairs, then pairs of pairs)
  // so that the three sums are short chains: they lie on the sampling path's critical path.
  const double y = 0.25 * t2, y2 = y * y, y4 = y2 * y2;
  const double cos_half =
      (1.0 - y * (1.0 / 2.0)) + y2 * (1.0 / 24.0 - y * (1.0 / 720.0)) +
      y4 * ((1.0 / 40320.0 - y * (1.0 / 3628800.0)) + y2 * (1.0 / 479001600.0 - y * (1.0 / 87178291200.0)));
  const double half_sine =
      0.5 *
      ((1.0 - y * (1.0 / 6.0)) + y2 * (1.0 / 120.0 - y * (1.0 / 5040.0)) +
       y4 * ((1.0 / 362880.0 - y * (1.0 / 39916800.0)) + y2 * (1.0 / 6227020800.0 - y * (1.0 / 1307674368000.0))));
  const double t4 = t2 * t2, t8 = t4 * t4;
  const double cc =
      (1.0 / 6.0 - t2 * (1.0 / 120.0)) + t4 * (1.0 / 5040.0 - t2 * (1.0 / 362880.0)) +
      t8 * ((1.0 / 39916800.0 - t2 * (1.0 / 6227020800.0)) +
            t4 * (1.0 / 1307674368000.0 - t2 * (1.0 / 355687428096000.0)) + t8 * (1.0 / 121645100408832000.0));
  const double b = 2.0 * half_sine * half_sine;
  exp_phi = Eigen::Quaterniond(cos_half, half_sine * phi.x(), half_sine * phi.y(), half_sine * phi.z());
  const Eigen::Vector3d pu = phi.cross(u);
  jacobian_u = u - b * pu + cc * phi.cross(pu);
}

}  // namespace detail

//! An orientation turning by α about a fixed world axis ŵ, q(α) = turn(ŵ, α) q₀, carrying
//! the body point p (the pivot). With r = (0, ŵ) q₀ (a unit quaternion orthogonal to q₀):
//!   q(α) = cos(α/2) q₀ + sin(α/2) r,
//!   q(α) p = P∥ + cos α P⊥ + sin α ŵ × P⊥   (P = q₀ p split along ŵ and across it),
//! and the body angular velocity per unit α, q(α)⁻¹ ŵ = q₀⁻¹ ŵ, is constant.
struct TurningFrame {
  //! q₀, the orientation at α = 0, and r = (0, ŵ) q₀.
  //!@{
  Eigen::Quaterniond q0 = Eigen::Quaterniond::Identity(), r = Eigen::Quaterniond::Identity();
  //!@}
  Eigen::Vector3d w_hat = Eigen::Vector3d::UnitZ();  //!< ŵ, the unit axis (world)
  Eigen::Vector3d pivot = Eigen::Vector3d::Zero();   //!< p, body
  //! P∥, P⊥, ŵ × P⊥ (world).
  //!@{
  Eigen::Vector3d pivot_along = Eigen::Vector3d::Zero(), pivot_across = Eigen::Vector3d::Zero(),
                  pivot_side = Eigen::Vector3d::Zero();
  //!@}
  Eigen::Vector3d omega_body = Eigen::Vector3d::Zero();         //!< θ q₀⁻¹ ŵ: ω_b per unit τ
  Eigen::Vector3d omega_cross_pivot = Eigen::Vector3d::Zero();  //!< ω_b × p, constant too
  double theta = 0.0;                                           //!< the turn over the section, rad

  TurningFrame() = default;
  //! The turn by `angle` about the unit world `axis` from orientation `start`, carrying body point p.
  TurningFrame(const Eigen::Quaterniond& start, const Eigen::Vector3d& axis, double angle,
               const Eigen::Vector3d& p) noexcept
      : q0(start), w_hat(axis), pivot(p), theta(angle) {
    r = Eigen::Quaterniond(0.0, axis.x(), axis.y(), axis.z()) * start;
    const Eigen::Vector3d world = start * p;
    pivot_along = world.dot(axis) * axis;
    pivot_across = world - pivot_along;
    pivot_side = axis.cross(pivot_across);
    omega_body = angle * (start.conjugate() * axis);
    omega_cross_pivot = omega_body.cross(p);
  }

  //! The cosine and sine of the turn τθ and the orientation, from one sine/cosine pair of τθ/2.
  void at(double tau, Eigen::Quaterniond& q, double& cos_turn, double& sin_turn) const noexcept {
    double s, c;
    detail::sin_cos(0.5 * tau * theta, s, c);
    q = Eigen::Quaterniond(c * q0.coeffs() + s * r.coeffs());
    cos_turn = 1.0 - 2.0 * s * s;
    sin_turn = 2.0 * s * c;
  }

  //! q p for the turn with cosine c and sine s.
  Eigen::Vector3d pivot_world(double c, double s) const noexcept {
    return pivot_along + c * pivot_across + s * pivot_side;
  }
};

//! A decoupled LIN section: the pivot at c₀ + τ Δc, the orientation turned by τθ about ŵ.
//! The pivot velocity seen from the body, q(α)⁻¹ Δc = q₀⁻¹ turn(ŵ, −α) Δc, is
//! q₀⁻¹ D∥ + cos α q₀⁻¹ D⊥ − sin α q₀⁻¹ (ŵ × D⊥) with D = Δc split along ŵ and across it.
struct LineMotion {
  TurningFrame frame;  //!< the orientation's turn
  //! c₀ and Δc: the pivot's start and travel (world).
  //!@{
  Eigen::Vector3d c0 = Eigen::Vector3d::Zero(), delta_c = Eigen::Vector3d::Zero();
  //!@}
  //! v_b = linear_fixed + cos α linear_cos + sin α linear_sin (ω_b × p folded into the first).
  //!@{
  Eigen::Vector3d linear_fixed = Eigen::Vector3d::Zero(), linear_cos = Eigen::Vector3d::Zero(),
                  linear_sin = Eigen::Vector3d::Zero();
  //!@}

  LineMotion() = default;
  //! The pivot from `start` by `travel` (world) while `turning` turns the orientation.
  LineMotion(const TurningFrame& turning, const Eigen::Vector3d& start, const Eigen::Vector3d& travel) noexcept
      : frame(turning), c0(start), delta_c(travel) {
    const Eigen::Quaterniond to_body = frame.q0.conjugate();
    const Eigen::Vector3d along = travel.dot(frame.w_hat) * frame.w_hat, across = travel - along;
    linear_fixed = to_body * along - frame.omega_cross_pivot;
    linear_cos = to_body * across;
    linear_sin = -(to_body * frame.w_hat.cross(across));
  }

  //! Pose and body twist per unit τ at τ.
  void at(double tau, Posed& pose, Twistd& twist) const noexcept {
    Eigen::Quaterniond q;
    double c, s;
    frame.at(tau, q, c, s);
    pose = Posed::unchecked(q, c0 + tau * delta_c - frame.pivot_world(c, s));
    // Body twist: ω_b, v_b = q⁻¹ Δc − ω_b × p (the body origin is t = c − q p).
    twist.angular = frame.omega_body;
    twist.linear = linear_fixed + c * linear_cos + s * linear_sin;
  }
};

//! A CIRC section: the pivot turned by τφ about the axis (centre o, normal n̂) from c₀, the
//! orientation by τθ about ŵ. c(β) = o + R∥ + cos β R⊥ + sin β n̂ × R⊥ with R = c₀ − o.
struct ArcMotion {
  TurningFrame frame;                                      //!< the orientation's turn
  Eigen::Vector3d center_along = Eigen::Vector3d::Zero();  //!< o + R∥
  //! R⊥ and n̂ × R⊥ (world).
  //!@{
  Eigen::Vector3d radius_across = Eigen::Vector3d::Zero(), radius_side = Eigen::Vector3d::Zero();
  //!@}
  double angle = 0.0;  //!< φ, rad

  //! Pose and body twist per unit τ at τ.
  void at(double tau, Posed& pose, Twistd& twist) const noexcept {
    Eigen::Quaterniond q;
    double c, s;
    frame.at(tau, q, c, s);
    double sb, cb;
    detail::sin_cos(tau * angle, sb, cb);
    pose = Posed::unchecked(q, center_along + cb * radius_across + sb * radius_side - frame.pivot_world(c, s));
    // ċ = φ n̂ × (c − o) = φ (cos β n̂ × R⊥ − sin β R⊥).
    const Eigen::Vector3d c_dot = angle * (cb * radius_side - sb * radius_across);
    twist.angular = frame.omega_body;
    twist.linear = q.conjugate() * c_dot - frame.omega_cross_pivot;
  }
};

//! A screw section: T₀ exp(τ ξ), constant body twist ξ.
struct ScrewMotion {
  Posed start;  //!< T₀
  Twistd xi;    //!< ξ, the body twist per unit τ

  //! Pose and body twist per unit τ at τ.
  void at(double tau, Posed& pose, Twistd& twist) const noexcept {
    pose = start * Posed::exp(xi * tau);
    twist = xi;
  }
};

namespace detail {

//! Whether the curve (R₀, c, φ, p) is the one `section` is cut from: the same coefficients,
//! bit for bit (one block comparison each).
inline bool same_curve(const Eigen::Quaterniond& q0, const Cubic3& position, const Cubic3& rotation,
                       const Eigen::Vector3d& pivot, const CurveSection& section) noexcept {
  return same_bits(section.q0.coeffs().data(), q0.coeffs().data(), 4) &&
         same_bits(section.position.a[0].data(), position.a[0].data(), 12) &&
         same_bits(section.rotation.a[0].data(), rotation.a[0].data(), 12) &&
         same_bits(section.pivot.data(), pivot.data(), 3);
}

}  // namespace detail

//! A cubic pose curve sampled at curve parameter v for a part of span h = dv/dτ: R = R₀ exp(φ(v)),
//! ω_b = h J_r(φ) φ′, v_b = Rᵀ h c′ − ω_b × p per unit τ, as CurveSection::at, with the series
//! exp and right Jacobian of the sampling path.
inline void curve_motion_at(const CurveSection& curve, double v, double h, Posed& pose, Twistd& twist) noexcept {
  Eigen::Quaterniond turn;
  Eigen::Vector3d omega;
  detail::exp_and_right_jacobian_sampled(curve.rotation.value(v), curve.rotation.first(v), turn, omega);
  omega *= h;
  // A product of unit quaternions: unit to rounding without normalising.
  const Eigen::Quaterniond q = curve.q0 * turn;
  pose = Posed::unchecked(q, curve.position.value(v) - q * curve.pivot);
  twist.angular = omega;
  twist.linear = q.conjugate() * (h * curve.position.first(v)) - omega.cross(curve.pivot);
}

//! The sampling forms of the parts of a path's sections: one form per section, shared by every
//! part cut from it, so that a part costs only the place it runs over in its section. Lines,
//! arcs and screws keep a precomputed form; curves and blends are sampled from the section
//! itself (their coefficients are their form). A part over τ ∈ [t₀, t₁] of its section runs
//! through it at u = t₀ + τ (t₁ − t₀) (for curves v = v₀ + τ h, the curve parameter of the part as
//! section_part makes it), its twist per unit τ the section's per unit u times dt/dτ
//! (doc/planning.md eq. 40).
class SectionMotions {
 public:
  //! Room for `parts` parts of `sections` (planning side).
  void reserve(const std::vector<Section>& sections, std::size_t parts);

  //! Appends the form of the part [t0, t1] of `section`, kept as section k of those at() is
  //! given: the same curve (a curve kept over a longer run of v) or the same section (planning
  //! side; allocates).
  void append(const Section& section, std::size_t k, double t0, double t1);

  std::size_t size() const noexcept { return entries_.size(); }  //!< the number of parts

  //! Pose and body twist per unit τ of part k at τ; `sections`: those the parts were made of.
  void at(const std::vector<Section>& sections, std::size_t k, double tau, Posed& pose, Twistd& twist) const noexcept {
    const Entry& e = entries_[k];
    const double u = e.v0 + tau * e.span;
    switch (e.kind) {
      case Kind::line:
        lines_[e.index].at(u, pose, twist);
        break;
      case Kind::arc:
        arcs_[e.index].at(u, pose, twist);
        break;
      case Kind::screw:
        screws_[e.index].at(u, pose, twist);
        break;
      case Kind::curve:
        curve_motion_at(*std::get_if<CurveSection>(&sections[e.index]), u, e.span, pose, twist);
        return;
      case Kind::slerp_blend:
        std::get_if<SlerpBlendSection>(&sections[e.index])->at_curve(u, e.span, pose, twist);
        return;
    }
    // Per unit τ of the part: the form's twist per unit of its section's τ times dt/dτ
    // (exactly the form's own for a whole section, span 1).
    if (e.span != 1.0) twist = twist * e.span;
  }

 private:
  enum class Kind : unsigned char { line, arc, screw, curve, slerp_blend };
  struct Entry {
    Kind kind;
    std::size_t index;            // into the vector of its kind (curves, blends: into the sections)
    double v0 = 0.0, span = 1.0;  // the part: u = v₀ + τ h
  };
  // The form of a line, arc or screw section (appended to its vector), and its index.
  std::pair<Kind, std::size_t> make_form(const Section& section);

  std::vector<Entry> entries_;
  std::vector<LineMotion> lines_;
  std::vector<ArcMotion> arcs_;
  std::vector<ScrewMotion> screws_;
  // The section whose form was made last and where it is: parts of one section come in a run.
  std::size_t last_section_ = static_cast<std::size_t>(-1);
  std::pair<Kind, std::size_t> last_form_{Kind::line, 0};
};

}  // namespace dispkin
