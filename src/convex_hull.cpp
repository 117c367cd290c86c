// Convex-hull vertex reduction with Qhull's reentrant library (libqhull_r).
#include "dispkin/convex_hull.hpp"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>

#include <Eigen/Eigenvalues>

extern "C" {
#include <libqhull_r/qhull_ra.h>
}

#include "dispkin/error.hpp"

namespace dispkin {
namespace {

// Runs Qhull on `dim`-dimensional rows and returns the input indices of the hull vertices,
// or an empty vector when Qhull cannot build a hull (it reports a flat or degenerate input).
std::vector<int> qhull_vertex_indices(std::vector<coordT>& coordinates, int dim) {
  const int count = static_cast<int>(coordinates.size()) / dim;
  qhT qh_storage;
  qhT* qh = &qh_storage;
  // Qhull writes its diagnostics to a FILE*; keep them out of the user's terminal.
  char* error_text = nullptr;
  std::size_t error_size = 0;
  FILE* errors = open_memstream(&error_text, &error_size);
  QHULL_LIB_CHECK
  qh_zero(qh, errors);
  char command[] = "qhull";
  const int exit_code = qh_new_qhull(qh, dim, count, coordinates.data(), False, command, nullptr, errors);
  std::vector<int> indices;
  if (exit_code == 0) {
    vertexT* vertex;
    FORALLvertices { indices.push_back(qh_pointid(qh, vertex->point)); }
  }
  qh_freeqhull(qh, !qh_ALL);
  int still_long = 0;
  int total_long = 0;
  qh_memfreeshort(qh, &still_long, &total_long);
  std::fclose(errors);
  std::free(error_text);
  std::sort(indices.begin(), indices.end());
  return indices;
}

}  // namespace

std::vector<Eigen::Vector3d> convex_hull_vertices(const std::vector<Eigen::Vector3d>& points) {
  for (std::size_t i = 0; i < points.size(); ++i)
    if (!within_translation_range(points[i])) require_translation(points[i], "points[" + std::to_string(i) + "]");
  if (points.size() <= 3) return points;

  // Principal axes decide the dimension of the hull: Qhull refuses flat input in 3-D. The
  // eigenvalues only suggest the axes; flatness is then measured directly as the largest
  // distance from the plane (or line), so that only points within rounding of it — 1e-12 of
  // the cloud's extent — are treated as lying in it. Anything thicker goes to the 3-D hull.
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (const auto& p : points) mean += p;
  mean /= static_cast<double>(points.size());
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
  for (const auto& p : points) covariance += (p - mean) * (p - mean).transpose();
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(covariance);
  const Eigen::Matrix3d axes = eig.eigenvectors();  // columns by ascending spread
  Eigen::Vector3d reach = Eigen::Vector3d::Zero();  // largest |coordinate| along each axis
  for (const auto& p : points) reach = reach.cwiseMax((axes.transpose() * (p - mean)).cwiseAbs());
  const double extent = reach(2);
  const double within_rounding = 1e-12 * extent;

  if (!(extent > 0.0)) return {points.front()};  // all coincide
  if (reach(1) <= within_rounding && reach(0) <= within_rounding) {
    // Collinear: the two extremes along the line.
    const Eigen::Vector3d dir = axes.col(2);
    auto [lo, hi] = std::minmax_element(points.begin(), points.end(), [&](const auto& a, const auto& b) {
      return (a - mean).dot(dir) < (b - mean).dot(dir);
    });
    std::vector<Eigen::Vector3d> out{*lo, *hi};
    if (lo > hi) std::swap(out[0], out[1]);
    return out;
  }
  const int dim = reach(0) <= within_rounding ? 2 : 3;
  std::vector<coordT> coordinates;
  coordinates.reserve(points.size() * static_cast<std::size_t>(dim));
  for (const auto& p : points) {
    const Eigen::Vector3d x = axes.transpose() * (p - mean);  // x(2) along the main axis
    for (int d = 0; d < dim; ++d) coordinates.push_back(x(2 - d));
  }
  const std::vector<int> indices = qhull_vertex_indices(coordinates, dim);
  // If Qhull could not build a hull, keeping every point is still exact (only not reduced).
  if (indices.empty()) return points;
  std::vector<Eigen::Vector3d> out;
  out.reserve(indices.size());
  for (int i : indices) out.push_back(points[static_cast<std::size_t>(i)]);
  return out;
}

MetricSetd reduced_to_hull_vertices(const MetricSetd& set) {
  MetricSetd out;
  for (const auto& g : set.groups()) {
    if (g.speed_limit) out.set_group_speed(g.id, *g.speed_limit);
    if (!g.relative_points.empty()) out.add_relative(convex_hull_vertices(g.relative_points.to_vectors()), g.id);
    if (!g.absolute_points.empty()) out.add_absolute(convex_hull_vertices(g.absolute_points.to_vectors()), g.id);
    for (const auto& s : g.relative_spheres) out.add_sphere(s.center, s.radius, Frame::relative, g.id);
    for (const auto& s : g.absolute_spheres) out.add_sphere(s.center, s.radius, Frame::absolute, g.id);
  }
  return out;
}

}  // namespace dispkin
