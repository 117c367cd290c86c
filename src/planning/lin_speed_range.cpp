// The exact speed range of a decoupled LIN's objects over a part of it (lin_speed_range.hpp,
// doc/planning.md §9, eqs. 27–31).
#include "lin_speed_range.hpp"

#include <algorithm>
#include <cmath>

#include "dispkin/path/section_motion.hpp"

namespace dispkin {
namespace detail {

namespace {

// Smallest ‖e − t u‖² over t ∈ [t0, t1]: the distance of the origin from a segment (doc/planning.md eq. 30).
double segment_min2(const Eigen::Vector3d& e, const Eigen::Vector3d& u, double t0, double t1) noexcept {
  const double uu = u.squaredNorm();
  const double t = uu > 0.0 ? std::clamp(e.dot(u) / uu, t0, t1) : t0;
  return (e - t * u).squaredNorm();
}

}  // namespace

DecoupledSpeeds::DecoupledSpeeds(const LinSection& lin, const GroupFactors& factors) noexcept : factors_(&factors) {
  const Eigen::Quaterniond& qa = lin.start.quaternion();
  omega_ = quaternion_log(Eigen::Quaterniond(qa.conjugate() * lin.end.quaternion()));
  theta_ = omega_.norm();
  k_ = theta_ > 0.0 ? Eigen::Vector3d(omega_ / theta_) : Eigen::Vector3d::UnitZ();
  pivot_ = lin.pivot;
  pivot_start_ = lin.start * lin.pivot;
  delta_c_ = lin.end * lin.pivot - pivot_start_;
  const Eigen::Vector3d d_a = qa.conjugate() * delta_c_;
  along_ = d_a.dot(k_);
  across_ = d_a - along_ * k_;
  across_side_ = k_.cross(across_);
  across_size_ = across_.norm();
  w_hat_ = qa * k_;
  omega_world_ = theta_ * w_hat_;
  drift_ = omega_world_.cross(delta_c_);
  along_world_ = delta_c_.dot(w_hat_);
}

Eigen::Vector3d DecoupledSpeeds::across_at(double t) const noexcept {
  // Parts are asked for in order of τ, each starting where the last one ended: one sine/cosine
  // pair per end.
  for (const TurnMemo& m : turns_)
    if (m.t == t) return m.across;
  TurnMemo& m = turns_[next_turn_];
  next_turn_ = 1 - next_turn_;
  double s, c;
  sin_cos(theta_ * t, s, c);
  m = {t, c * across_ - s * across_side_};
  return m.across;
}

SpeedRange DecoupledSpeeds::range(double t0, double t1) const noexcept {
  // Δc⊥ seen from the body at both ends, turned back by θτ about k (doc/planning.md eq. 27), and the normals
  // m₀ = d₀ × Ω, m₁ = Ω × d₁ of the arc it sweeps: a direction u lies on that arc when u·m₀ ≥ 0
  // and u·m₁ ≥ 0 (the arc spans θ(t₁ − t₀) ≤ π).
  const Eigen::Vector3d d0 = across_at(t0), d1 = across_at(t1);
  const Eigen::Vector3d m0 = d0.cross(omega_), m1 = omega_.cross(d1);
  const double along2 = along_ * along_;
  const MetricSetd& set = factors_->set();
  SpeedRange best;
  for (std::size_t g = 0; g < set.groups().size(); ++g) {
    const MetricGroup<double>& group = set.groups()[g];
    // Body objects: |d(τ) + q|² with q = Ω × (r − p) fixed (doc/planning.md eq. 28). Peak where d⊥ points
    // along q, trough where it points against q, else at an end.
    auto across_range = [&](const Eigen::Vector3d& q, double& low, double& high) {
      const double a = (d0 + q).norm(), b = (d1 + q).norm(), q_size = q.norm();
      const double on_arc0 = q.dot(m0), on_arc1 = q.dot(m1);
      high = on_arc0 >= 0.0 && on_arc1 >= 0.0 ? across_size_ + q_size : std::max(a, b);
      low = on_arc0 <= 0.0 && on_arc1 <= 0.0 ? std::abs(across_size_ - q_size) : std::min(a, b);
    };
    double high2 = 0.0, low2 = 0.0, high = 0.0, low = 0.0;
    // Points by their squares: only ‖q‖ at a peak or trough needs a square root.
    const PointColumns<double>& points = group.relative_points;
    const double* xs = points.x().data();
    const double* ys = points.y().data();
    const double* zs = points.z().data();
    const double across2 = across_size_ * across_size_;
    for (std::size_t i = 0; i < points.size(); ++i) {
      const double rx = xs[i] - pivot_.x(), ry = ys[i] - pivot_.y(), rz = zs[i] - pivot_.z();
      const double qx = omega_.y() * rz - omega_.z() * ry, qy = omega_.z() * rx - omega_.x() * rz,
                   qz = omega_.x() * ry - omega_.y() * rx;
      const double ax = d0.x() + qx, ay = d0.y() + qy, az = d0.z() + qz;
      const double bx = d1.x() + qx, by = d1.y() + qy, bz = d1.z() + qz;
      const double a2 = ax * ax + ay * ay + az * az, b2 = bx * bx + by * by + bz * bz;
      const double on_arc0 = qx * m0.x() + qy * m0.y() + qz * m0.z(), on_arc1 = qx * m1.x() + qy * m1.y() + qz * m1.z();
      const double q2 = qx * qx + qy * qy + qz * qz;
      double h2 = std::max(a2, b2), l2 = std::min(a2, b2);
      if (on_arc0 >= 0.0 && on_arc1 >= 0.0) h2 = across2 + q2 + 2.0 * across_size_ * std::sqrt(q2);
      if (on_arc0 <= 0.0 && on_arc1 <= 0.0) {
        const double gap = across_size_ - std::sqrt(q2);
        l2 = gap * gap;
      }
      high2 = std::max(high2, h2);
      low2 = std::max(low2, l2);
    }
    if (!points.empty()) {
      high2 += along2;
      low2 += along2;
    }
    // A sphere's fastest point adds θρ across k to its centre's speed (doc/planning.md eq. 29).
    for (const Sphere<double>& s : group.relative_spheres) {
      double l, h;
      across_range(omega_.cross(s.center - pivot_), l, h);
      high = std::max(high, std::hypot(along_, h + theta_ * s.radius));
      low = std::max(low, std::hypot(along_, l + theta_ * s.radius));
    }
    // Absolute objects: g(τ) = e − τ u, convex in τ: the peak at an end, the trough at the
    // point of the segment nearest the origin (doc/planning.md eq. 30); spheres as body ones (eq. 31).
    const PointColumns<double>& fixed = group.absolute_points;
    for (std::size_t i = 0; i < fixed.size(); ++i) {
      const Eigen::Vector3d x(fixed.x()[i], fixed.y()[i], fixed.z()[i]);
      const Eigen::Vector3d e = delta_c_ + omega_world_.cross(x - pivot_start_);
      high2 = std::max(high2, std::max((e - t0 * drift_).squaredNorm(), (e - t1 * drift_).squaredNorm()));
      low2 = std::max(low2, segment_min2(e, drift_, t0, t1));
    }
    for (const Sphere<double>& s : group.absolute_spheres) {
      const Eigen::Vector3d e = delta_c_ + omega_world_.cross(s.center - pivot_start_);
      const Eigen::Vector3d e_across = e - e.dot(w_hat_) * w_hat_;
      const double h = std::max((e_across - t0 * drift_).norm(), (e_across - t1 * drift_).norm());
      const double l = std::sqrt(segment_min2(e_across, drift_, t0, t1));
      high = std::max(high, std::hypot(along_world_, h + theta_ * s.radius));
      low = std::max(low, std::hypot(along_world_, l + theta_ * s.radius));
    }
    const double w = factors_->weight(g);
    best.high = std::max(best.high, w * std::max(high, std::sqrt(high2)));
    best.low = std::max(best.low, w * std::max(low, std::sqrt(low2)));
  }
  return best;
}

}  // namespace detail
}  // namespace dispkin
