// SPLINE moves (the "Spline Curve" of the Mamezou trajectory article, Ishii, "Algorithm 2 for
// Robot Manipulator Control"; doc/section-length.md §7) and the cutting of cubic pose curves
// into sections.
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include <Eigen/LU>
#include <Eigen/SparseCore>
#include <Eigen/SparseLU>

#include "dispkin/path/path.hpp"
#include "path_geometry.hpp"

namespace dispkin {
namespace {

using detail::metres_per_radian;

// Slopes mᵢ of the natural cubic spline through the points pᵢ at knots spaced hᵢ:
//   hᵢ mᵢ₋₁ + 2(hᵢ₋₁ + hᵢ) mᵢ + hᵢ₋₁ mᵢ₊₁ = 3(hᵢ Δᵢ₋₁ + hᵢ₋₁ Δᵢ),  Δᵢ = (pᵢ₊₁ − pᵢ)/hᵢ,
// and p″ = 0 at both ends: 2m₀ + m₁ = 3Δ₀, mₙ₋₂ + 2mₙ₋₁ = 3Δₙ₋₂. Tridiagonal, solved by
// sparse LU for all three coordinates at once.
Eigen::MatrixX3d natural_spline_slopes(const Eigen::MatrixX3d& p, const Eigen::VectorXd& h) {
  const Eigen::Index n = p.rows();
  Eigen::MatrixX3d delta(n - 1, 3);
  for (Eigen::Index i = 0; i + 1 < n; ++i) delta.row(i) = (p.row(i + 1) - p.row(i)) / h(i);
  std::vector<Eigen::Triplet<double>> entries;
  Eigen::MatrixX3d rhs(n, 3);
  entries.emplace_back(0, 0, 2.0);
  entries.emplace_back(0, 1, 1.0);
  rhs.row(0) = 3.0 * delta.row(0);
  for (Eigen::Index i = 1; i + 1 < n; ++i) {
    entries.emplace_back(i, i - 1, h(i));
    entries.emplace_back(i, i, 2.0 * (h(i - 1) + h(i)));
    entries.emplace_back(i, i + 1, h(i - 1));
    rhs.row(i) = 3.0 * (h(i) * delta.row(i - 1) + h(i - 1) * delta.row(i));
  }
  entries.emplace_back(n - 1, n - 2, 1.0);
  entries.emplace_back(n - 1, n - 1, 2.0);
  rhs.row(n - 1) = 3.0 * delta.row(n - 2);
  Eigen::SparseMatrix<double> a(n, n);
  a.setFromTriplets(entries.begin(), entries.end());
  Eigen::SparseLU<Eigen::SparseMatrix<double>> lu(a);
  // Diagonally dominant for positive spacings: the factorisation fails only when the sums of
  // spacings overflow, and then solve() must not be called (it reads past its buffers).
  require(lu.info() == Eigen::Success, "knot spacings", h,
          "are beyond the range of double precision: the spline system cannot be solved");
  return lu.solve(rhs);
}

}  // namespace

void Path::cut_curve(const Eigen::Quaterniond& q0, const Cubic3& position, const Cubic3& rotation,
                     const Eigen::Vector3d& pivot, double tolerance) {
  // The speed |ċ| + ρ|φ′| per unit v, ρ = 0.1 m, sampled along the curve; the curve is cut where
  // that speed varies (doc/section-length.md eq. 29). Each section's bound is its exact peak to
  // 0.1 % however far its velocity turns (CurveSection::bounds, doc/section-length.md eqs. 25–27).
  constexpr int samples = 64;
  double min_speed = std::numeric_limits<double>::infinity(), max_speed = 0.0;
  for (int i = 0; i <= samples; ++i) {
    const double v = double(i) / samples;
    const double speed = position.first(v).norm() + metres_per_radian * rotation.first(v).norm();
    min_speed = std::min(min_speed, speed);
    max_speed = std::max(max_speed, speed);
  }
  const int count = detail::sections_for_speed_range(min_speed, max_speed, tolerance);
  for (int k = 0; k < count; ++k) {
    CurveSection section;
    section.q0 = q0;
    section.position = position;
    section.rotation = rotation;
    section.v0 = double(k) / count;
    section.v1 = k + 1 == count ? 1.0 : double(k + 1) / count;
    section.pivot = pivot;
    append(section);
  }
}

Path Path::spline(const std::vector<Posed>& poses, const Eigen::Vector3d& pivot, double tolerance) {
  require_translation(pivot, "pivot");
  require(std::isfinite(tolerance) && tolerance > 0.0 && tolerance <= 0.1, "tolerance", tolerance,
          "must be in (0, 0.1]");
  const auto n = static_cast<Eigen::Index>(poses.size());
  require(n >= 3, "poses", static_cast<long>(n),
          "key poses given: a SPLINE needs at least three (use Path::lin for two)");

  // Knots spaced by the geometric size of each step; relative rotations rᵢ = log(Rᵢ⁻¹Rᵢ₊₁).
  Eigen::MatrixX3d p(n, 3);
  for (Eigen::Index i = 0; i < n; ++i) p.row(i) = (poses[i] * pivot).transpose();
  Eigen::VectorXd h(n - 1);
  std::vector<Eigen::Vector3d> r(n - 1);
  for (Eigen::Index i = 0; i + 1 < n; ++i) {
    r[i] = quaternion_log(Eigen::Quaterniond(poses[i].quaternion().conjugate() * poses[i + 1].quaternion()));
    h(i) = (p.row(i + 1) - p.row(i)).norm() + metres_per_radian * r[i].norm();
    if (!std::isfinite(h(i))) {
      throw std::invalid_argument(describe("poses[" + std::to_string(i + 1) + "]", poses[i + 1].translation(),
                                           "is too far from the key pose before it: their distance overflows"));
    }
    if (!(h(i) > 1e-12)) {
      throw std::invalid_argument(describe("poses[" + std::to_string(i + 1) + "]", poses[i + 1].translation(),
                                           "coincides with the key pose before it"));
    }
  }
  const Eigen::MatrixX3d m = natural_spline_slopes(p, h);

  // Body angular velocity per unit of the knot parameter at each key: the three-point rule
  // inside (exact for a constant angular acceleration), the natural condition at the ends
  // (zero second derivative of the Hermite piece: m₀ = (3r₀/h₀ − m₁)/2, m₁ seen from R₀).
  std::vector<Eigen::Vector3d> omega(n);
  for (Eigen::Index i = 1; i + 1 < n; ++i) {
    omega[i] = (h(i) * r[i - 1] / h(i - 1) + h(i - 1) * r[i] / h(i)) / (h(i - 1) + h(i));
  }
  omega[0] = 0.5 * (3.0 * r[0] / h(0) - quaternion_exp(r[0]) * omega[1]);
  omega[n - 1] = 0.5 * (3.0 * r[n - 2] / h(n - 2) - quaternion_exp(r[n - 2]).conjugate() * omega[n - 2]);

  Path path;
  for (Eigen::Index i = 0; i + 1 < n; ++i) {
    // Per unit of the local v ∈ [0, 1]: slopes scale with hᵢ. The end slope of φ gives the
    // body rate ωᵢ₊₁ through J_r(rᵢ), so the next piece (which starts at φ = 0, J_r = I)
    // continues with the same angular velocity.
    const Cubic3 position = Cubic3::hermite(p.row(i).transpose(), h(i) * m.row(i).transpose(), p.row(i + 1).transpose(),
                                            h(i) * m.row(i + 1).transpose());
    const Eigen::Vector3d end_slope = right_jacobian(r[i]).partialPivLu().solve(h(i) * omega[i + 1]);
    const Cubic3 rotation = Cubic3::hermite(Eigen::Vector3d::Zero(), h(i) * omega[i], r[i], end_slope);
    path.cut_curve(poses[i].quaternion(), position, rotation, pivot, tolerance);
  }
  path.first_move_size_ = path.last_move_size_ = path.cumulative_.back();
  return path;
}

}  // namespace dispkin
