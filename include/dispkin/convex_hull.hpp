//! Reduction of large point clouds to their convex-hull vertices (Qhull).
//!
//! doc/disp-metric.md (eq. 27), the vertex shortcut: a point's speed ‖v + ω × p‖ and its chord
//! ‖(R2 − R1) p + (t2 − t1)‖ are convex in p, so over a cloud only the vertices of its
//! convex hull can be the fastest. Reducing once makes every later evaluation cheaper.
//! Compiled into dispkin::dispkin (the header-only core does not need Qhull).
#pragma once

#include <vector>

#include <Eigen/Core>

#include "dispkin/metric_set.hpp"

namespace dispkin {

//! The vertices of the convex hull of `points`, each an exact copy of an input point, in input
//! order. Coplanar clouds get their 2-D hull, collinear ones their two extremes, coincident
//! ones a single point. Throws std::invalid_argument for non-finite input.
std::vector<Eigen::Vector3d> convex_hull_vertices(const std::vector<Eigen::Vector3d>& points);

//! The same set with every group's relative and absolute points replaced by their hull
//! vertices (relative and absolute separately; spheres and group limits unchanged). Every
//! DISP distance and section length is the same as for the original set.
MetricSetd reduced_to_hull_vertices(const MetricSetd& set);

}  // namespace dispkin
