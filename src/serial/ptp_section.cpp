// The DISP bound of a joint section of a PTP move (ptp_section.hpp; derivation also in doc/ptp.md).
//
// Notation, all in world (base) coordinates at the joint positions of the moment: joint i has
// the unit axis ωᵢ through the point pᵢ (revolute) or the direction eᵢ (prismatic); the joint
// rates per unit τ are dᵢ = h Δqᵢ (q̈ = 0 along a joint line). The velocity per τ of a point x
// carried by the tool is
//   x′ = Σⱼ dⱼ uⱼ(x),   uⱼ(x) = ωⱼ × (x − pⱼ) (revolute),  eⱼ (prismatic).
// Joints before j turn both x and pⱼ rigidly, with the angular velocity Ω₍<ⱼ₎ = Σ_{i<j, revolute}
// dᵢ ωᵢ, so ωⱼ′ = Ω₍<ⱼ₎ × ωⱼ and (x − pⱼ)′ = Ω₍<ⱼ₎ × (x − pⱼ) + Σ_{i≥j} dᵢ uᵢ(x). Differentiating
// and using the Jacobi identity (Ω × ω) × r + ω × (Ω × r) = Ω × (ω × r):
//   x″ = Σⱼ dⱼ (Ω₍<ⱼ₎ + Ω₍≤ⱼ₎) × uⱼ(x)                                      (relative objects)
// hence ‖x″‖ ≤ Σⱼ |dⱼ| (2 Σ_{i<j} |dᵢ| + |dⱼ|) ρⱼ with ρⱼ ≥ ‖x − pⱼ‖ (revolute; a prismatic
// joint has ‖uⱼ‖ = 1 and no |dⱼ| of its own in the bracket).
// An absolute point a stays put; its apparent speed seen from the tool is the speed of the
// tool-fixed point that is at a at the moment (doc/disp-metric.md §4 and §6), ‖V(a)‖ with V(a) = Σⱼ dⱼ uⱼ(a). With
// a fixed, pⱼ′ = Σ_{i<j} dᵢ ωᵢ × (pⱼ − pᵢ) = −Ω₍<ⱼ₎ × (a − pⱼ) + S₍<ⱼ₎(a), S₍<ⱼ₎(a) = Σ_{i<j} dᵢ uᵢ(a):
//   V(a)′ = Σⱼ dⱼ [ Ω₍<ⱼ₎ × (ωⱼ × (a − pⱼ)) − ωⱼ × S₍<ⱼ₎(a) ]                   (absolute objects)
// hence ‖V(a)′‖ ≤ Σⱼ |dⱼ| ( Σ_{i<j} |dᵢ| ) eⱼ + Σⱼ |dⱼ| Σ_{i<j} |dᵢ| eᵢ with eⱼ ≥ ‖a − pⱼ‖.
// A sphere's surface points are points: the same with the distances raised by its radius.
//
// The distances over the section: the exact value at its middle plus half the largest rate of
// change. ‖x − pⱼ‖ does not change under joints before j (a rigid motion of both), so it changes
// at most at Σ_{i≥j} |dᵢ| ρ̄ᵢ, ρ̄ᵢ a bound over every configuration: pᵢ and pᵢ₊₁ both lie on
// link i (pᵢ on its axis), so ℓᵢ = ‖pᵢ₊₁ − pᵢ‖ is a constant of the chain, and ρ̄ᵢ = Σ_{k≥i} ℓₖ +
// ‖o − pₙ‖ + (the object's reach from the tool origin o). For an absolute object pⱼ moves at
// most at Σ_{i<j} |dᵢ| Σ_{k=i}^{j−1} ℓₖ.
//
// The arm of dispkin::serial has revolute joints only (the URDF loader refuses prismatic ones),
// so the code below is the revolute case; doc/ptp.md states the prismatic terms.
#include "ptp_section.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "dispkin/disp.hpp"
#include "dispkin/serial/chain_kinematics.hpp"
#include "dispkin/serial/ptp.hpp"

namespace dispkin::serial {
namespace detail {

JointSection joint_section_bounds(const RevoluteChain& chain, const Eigen::VectorXd& q_a, const Eigen::VectorXd& delta,
                                  double u0, double u1, const GroupFactors& factors) {
  const int n = chain.dof();
  const auto un = static_cast<std::size_t>(n);
  const double h = u1 - u0, um = 0.5 * (u0 + u1);
  std::vector<double> q(un), rate(un), d(un);
  for (std::size_t i = 0; i < un; ++i) {
    const auto e = static_cast<Eigen::Index>(i);
    q[i] = q_a(e) + um * delta(e);
    rate[i] = h * delta(e);
    d[i] = std::abs(rate[i]);
  }
  // World axes' points at the middle, the pose and the body twist per τ.
  std::vector<Eigen::Vector3d> p(un);
  Posed pose;
  Twistd twist;
  chain_pose_and_twist(chain, q.data(), rate.data(), pose, twist, p.data());
  const Eigen::Vector3d o = pose.translation();

  // Chain constants: ℓᵢ = ‖pᵢ₊₁ − pᵢ‖ and the tool origin's distance from the last axis point.
  std::vector<double> ell(un, 0.0);
  for (std::size_t i = 0; i + 1 < un; ++i) ell[i] = (chain.points[i + 1] - chain.points[i]).norm();
  const double tip = (chain.tip_at_zero.translation() - chain.points[un - 1]).norm();
  // tail[j] = Σ_{k≥j} ℓₖ + tip: the distance from pⱼ to the tool origin, over every configuration.
  std::vector<double> tail(un + 1, tip);
  for (std::size_t j = un; j-- > 0;) tail[j] = tail[j + 1] + ell[j];
  // before[j] = Σ_{i<j} dᵢ.
  std::vector<double> before(un + 1, 0.0);
  for (std::size_t j = 0; j < un; ++j) before[j + 1] = before[j] + d[j];

  const MetricSetd& set = factors.set();
  JointSection out;
  out.u0 = u0;
  out.u1 = u1;
  std::vector<double> rho(un), e(un);
  for (std::size_t g = 0; g < set.groups().size(); ++g) {
    const MetricGroup<double>& group = set.groups()[g];
    double a_group = 0.0;
    if (!group.relative_points.empty() || !group.relative_spheres.empty()) {
      const double reach = factors.reach(g);  // from the tool origin (pivot 0)
      // ρⱼ: the middle distance plus half the largest change, never above the uniform bound.
      double change = 0.0;  // Σ_{i≥j} dᵢ ρ̄ᵢ, built from the tip down
      for (std::size_t j = un; j-- > 0;) {
        change += d[j] * (tail[j] + reach);
        rho[j] = std::min((o - p[j]).norm() + reach + 0.5 * change, tail[j] + reach);
      }
      double a = 0.0;
      for (std::size_t j = 0; j < un; ++j) a += d[j] * (2.0 * before[j] + d[j]) * rho[j];
      a_group = a;
    }
    // Absolute objects, one by one (centre, radius).
    const auto absolute = [&](const Eigen::Vector3d& c, double radius) {
      for (std::size_t j = 0; j < un; ++j) {
        double drift = 0.0;  // Σ_{i<j} dᵢ Σ_{k=i}^{j−1} ℓₖ: how fast pⱼ can move
        double span = 0.0;
        for (std::size_t i = j; i-- > 0;) {
          span += ell[i];
          drift += d[i] * span;
        }
        e[j] = (c - p[j]).norm() + radius + 0.5 * drift;
      }
      double a = 0.0, carried = 0.0;  // carried = Σ_{i<j} dᵢ eᵢ
      for (std::size_t j = 0; j < un; ++j) {
        a += d[j] * (before[j] * e[j] + carried);
        carried += d[j] * e[j];
      }
      a_group = std::max(a_group, a);
    };
    for (const Eigen::Vector3d c : group.absolute_points) absolute(c, 0.0);
    for (const auto& s : group.absolute_spheres) absolute(s.center, s.radius);

    const double speed = dispkin::detail::group_max_speed(group, pose, twist);
    const double w = factors.weight(g);
    out.length = std::max(out.length, w * (speed + 0.5 * a_group));
    out.middle_speed = std::max(out.middle_speed, w * speed);
    out.acceleration = std::max(out.acceleration, a_group);
  }
  return out;
}

}  // namespace detail
}  // namespace dispkin::serial
