//! Point-set builders for metric sets: box, regular icosahedron, icosphere, spherical shell.
//!
//! doc/disp-metric.md (eq. 26): a regular icosahedron with its vertices ON a sphere under-estimates
//! the sphere's speed; one whose faces touch the sphere (circumscribed, vertex radius 1.2584 ρ)
//! bounds it from above by at most 25.8 %; subdivided icospheres scaled to circumscribe converge to
//! it.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <utility>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "dispkin/error.hpp"

namespace dispkin {
namespace shapes {

//! A triangulated convex polyhedron: vertices and counter-clockwise (outward) faces.
template <typename Scalar>
struct Polyhedron {
  std::vector<Eigen::Matrix<Scalar, 3, 1>> vertices;  //!< the corners
  std::vector<std::array<int, 3>> faces;              //!< triangles as indices into vertices, outward

  //! Smallest distance from `center` to a face plane: the radius of the largest ball around
  //! `center` that the polyhedron contains.
  Scalar inradius(const Eigen::Matrix<Scalar, 3, 1>& center) const {
    Scalar best = std::numeric_limits<Scalar>::infinity();
    for (const auto& f : faces) {
      const auto& p0 = vertices[f[0]];
      const Eigen::Matrix<Scalar, 3, 1> n = (vertices[f[1]] - p0).cross(vertices[f[2]] - p0).normalized();
      best = std::min(best, n.dot(p0 - center));
    }
    return best;
  }
};

//! Circumradius / inradius of a regular icosahedron (= 1.2584): vertex radius of the
//! icosahedron whose faces touch the unit sphere.
template <typename Scalar>
Scalar icosahedron_circumradius_ratio() {
  using std::sqrt;
  // For edge length 1: circumradius √(10 + 2√5)/4, inradius √3 (3 + √5)/12.
  const Scalar r_circ = sqrt(Scalar(10) + 2 * sqrt(Scalar(5))) / 4;
  const Scalar r_in = sqrt(Scalar(3)) * (Scalar(3) + sqrt(Scalar(5))) / 12;
  return r_circ / r_in;
}

//! The 8 corners of an axis-aligned box with edge lengths `size` around `center`.
template <typename Scalar>
std::vector<Eigen::Matrix<Scalar, 3, 1>> box(
    const Eigen::Matrix<Scalar, 3, 1>& size,
    const non_deduced<Eigen::Matrix<Scalar, 3, 1>>& center = Eigen::Matrix<Scalar, 3, 1>::Zero()) {
  require_translation(center, "center");
  require(size.allFinite() && (size.array() > Scalar(0)).all(), "size", size,
          "edge lengths must be finite and positive");
  std::vector<Eigen::Matrix<Scalar, 3, 1>> corners;
  corners.reserve(8);
  for (int i = 0; i < 8; ++i) {
    const Eigen::Matrix<Scalar, 3, 1> sign((i & 1) ? 1 : -1, (i & 2) ? 1 : -1, (i & 4) ? 1 : -1);
    corners.push_back(center + Scalar(0.5) * sign.cwiseProduct(size));
  }
  return corners;
}

namespace detail {

// The 12 vertices (±1, ±φ, 0) cyclically, on the unit sphere, with the 20 outward faces.
template <typename Scalar>
Polyhedron<Scalar> unit_icosahedron() {
  using std::sqrt;
  const Scalar phi = (Scalar(1) + sqrt(Scalar(5))) / 2;
  Polyhedron<Scalar> p;
  const Scalar raw[12][3] = {{-1, phi, 0},  {1, phi, 0},  {-1, -phi, 0}, {1, -phi, 0}, {0, -1, phi},  {0, 1, phi},
                             {0, -1, -phi}, {0, 1, -phi}, {phi, 0, -1},  {phi, 0, 1},  {-phi, 0, -1}, {-phi, 0, 1}};
  for (const auto& v : raw) p.vertices.push_back(Eigen::Matrix<Scalar, 3, 1>(v[0], v[1], v[2]).normalized());
  p.faces = {{0, 11, 5},  {0, 5, 1},  {0, 1, 7},  {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
             {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
             {3, 8, 9},   {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
  return p;
}

// One Loop-style split of every face into four, new vertices pushed onto the unit sphere.
template <typename Scalar>
Polyhedron<Scalar> subdivide(const Polyhedron<Scalar>& in) {
  Polyhedron<Scalar> out;
  out.vertices = in.vertices;
  std::map<std::pair<int, int>, int> midpoint;
  auto middle = [&](int i, int j) {
    const std::pair<int, int> key(std::min(i, j), std::max(i, j));
    auto it = midpoint.find(key);
    if (it != midpoint.end()) return it->second;
    out.vertices.push_back((out.vertices[i] + out.vertices[j]).normalized());
    const int index = static_cast<int>(out.vertices.size()) - 1;
    midpoint.emplace(key, index);
    return index;
  };
  for (const auto& f : in.faces) {
    const int a = middle(f[0], f[1]);
    const int b = middle(f[1], f[2]);
    const int c = middle(f[2], f[0]);
    out.faces.push_back({f[0], a, c});
    out.faces.push_back({f[1], b, a});
    out.faces.push_back({f[2], c, b});
    out.faces.push_back({a, b, c});
  }
  return out;
}

template <typename Scalar>
std::vector<Eigen::Matrix<Scalar, 3, 1>> placed(const Polyhedron<Scalar>& unit, Scalar scale,
                                                const Eigen::Matrix<Scalar, 3, 1>& center) {
  std::vector<Eigen::Matrix<Scalar, 3, 1>> out;
  out.reserve(unit.vertices.size());
  for (const auto& v : unit.vertices) out.push_back(center + scale * v);
  return out;
}

}  // namespace detail

//! A regular icosahedron (12 vertices) for the sphere of `radius` around `center`:
//! circumscribed (default) — its faces touch the sphere, so it contains it and never
//! under-estimates the sphere's speed; otherwise its vertices lie on the sphere.
template <typename Scalar>
std::vector<Eigen::Matrix<Scalar, 3, 1>> icosahedron(
    Scalar radius, const non_deduced<Eigen::Matrix<Scalar, 3, 1>>& center = Eigen::Matrix<Scalar, 3, 1>::Zero(),
    bool circumscribed = true) {
  require_positive(radius, "radius");
  require_translation(center, "center");
  const Scalar scale = circumscribed ? radius * icosahedron_circumradius_ratio<Scalar>() : radius;
  return detail::placed(detail::unit_icosahedron<Scalar>(), scale, center);
}

//! An icosphere: the icosahedron subdivided `subdivisions` times (12, 42, 162, 642, …
//! vertices), scaled so its faces circumscribe the sphere of `radius` — it contains the sphere,
//! and its speed bound converges to the sphere's exact speed as subdivisions grow.
template <typename Scalar>
std::vector<Eigen::Matrix<Scalar, 3, 1>> icosphere(
    Scalar radius, int subdivisions,
    const non_deduced<Eigen::Matrix<Scalar, 3, 1>>& center = Eigen::Matrix<Scalar, 3, 1>::Zero()) {
  require_positive(radius, "radius");
  require_translation(center, "center");
  require(subdivisions >= 0 && subdivisions <= 7, "subdivisions", subdivisions,
          "must be between 0 and 7 (7 gives 163842 vertices)");
  Polyhedron<Scalar> p = detail::unit_icosahedron<Scalar>();
  for (int i = 0; i < subdivisions; ++i) p = detail::subdivide(p);
  const Scalar scale = radius / p.inradius(Eigen::Matrix<Scalar, 3, 1>::Zero());
  return detail::placed(p, scale, center);
}

//! `count` points spread evenly ON the sphere of `radius` around `center` (a Fibonacci lattice):
//! the spherical shell of relative points around a pivot of the DISP patent JP7742490B2, which ties
//! the angular speed about the pivot to the system velocity through the radius.
template <typename Scalar>
std::vector<Eigen::Matrix<Scalar, 3, 1>> spherical_shell(
    Scalar radius, int count,
    const non_deduced<Eigen::Matrix<Scalar, 3, 1>>& center = Eigen::Matrix<Scalar, 3, 1>::Zero()) {
  using std::cos;
  using std::sin;
  using std::sqrt;
  require_positive(radius, "radius");
  require_translation(center, "center");
  require(count >= 4, "count", count, "must be at least 4 so the shell spans space");
  const Scalar golden_angle = Scalar(EIGEN_PI) * (Scalar(3) - sqrt(Scalar(5)));
  std::vector<Eigen::Matrix<Scalar, 3, 1>> out;
  out.reserve(static_cast<std::size_t>(count));
  for (int i = 0; i < count; ++i) {
    const Scalar z = Scalar(1) - Scalar(2) * (Scalar(i) + Scalar(0.5)) / Scalar(count);
    const Scalar r = sqrt(std::max(Scalar(0), Scalar(1) - z * z));
    const Scalar angle = golden_angle * Scalar(i);
    out.push_back(center + radius * Eigen::Matrix<Scalar, 3, 1>(r * cos(angle), r * sin(angle), z));
  }
  return out;
}

}  // namespace shapes
}  // namespace dispkin
