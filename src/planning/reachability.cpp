// Reachability analysis: controllable sets by polygon clipping, then the greedy forward pass.
#include "reachability.hpp"

#include <algorithm>
#include <cmath>

namespace dispkin::detail {

ConvexPolygon::ConvexPolygon(double u_bound, double x_bound)
    : vertices_{{-u_bound, 0.0}, {u_bound, 0.0}, {u_bound, x_bound}, {-u_bound, x_bound}},
      tolerance_(1e-12 * (u_bound + x_bound)) {
  vertices_.reserve(reserved_vertices);
  scratch_.reserve(reserved_vertices);
}

ConvexPolygon::ConvexPolygon(const ConvexPolygon& other)
    : tolerance_(other.tolerance_), deduplicated_(other.deduplicated_) {
  vertices_.reserve(std::max(reserved_vertices, other.vertices_.size()));
  vertices_.assign(other.vertices_.begin(), other.vertices_.end());
  scratch_.reserve(std::max(reserved_vertices, other.vertices_.size() + 1));
}

ConvexPolygon& ConvexPolygon::operator=(const ConvexPolygon& other) {
  vertices_.assign(other.vertices_.begin(), other.vertices_.end());
  tolerance_ = other.tolerance_;
  deduplicated_ = other.deduplicated_;
  return *this;
}

void ConvexPolygon::clip(const HalfPlane& h) {
  // Sutherland–Hodgman against one half-plane. A vertex on the line within rounding counts as
  // inside, so that clipping by a·u + b·x ≤ c and by its reverse leaves the segment on the line.
  // The kept vertices go into the scratch buffer, which then becomes the polygon: both keep their
  // capacity, so a polygon allocates only while it grows.
  const double scale = std::abs(h.a) + std::abs(h.b) + std::abs(h.c);
  const double slack = tolerance_ * std::max(1.0, scale);
  const std::size_t n = vertices_.size();
  // Most limits do not cut a polygon that is already clipped (its repeated vertices dropped):
  // then it stays as it is, as the full pass below would leave it.
  if (deduplicated_ && std::all_of(vertices_.begin(), vertices_.end(),
                                   [&](const Eigen::Vector2d& v) { return h.a * v.x() + h.b * v.y() - h.c <= slack; }))
    return;
  std::vector<Eigen::Vector2d>& kept = scratch_;
  kept.clear();
  auto side = [&h](const Eigen::Vector2d& v) { return h.a * v.x() + h.b * v.y() - h.c; };
  const double f_first = n ? side(vertices_.front()) : 0.0;
  double fp = f_first;  // each vertex's side evaluated once, carried to the next edge
  for (std::size_t k = 0; k < n; ++k) {
    const Eigen::Vector2d& p = vertices_[k];
    const Eigen::Vector2d& q = vertices_[k + 1 == n ? 0 : k + 1];
    const double fq = k + 1 == n ? f_first : side(q);
    const bool p_in = fp <= slack, q_in = fq <= slack;
    if (p_in) kept.push_back(p);
    if (p_in != q_in && fp != fq) {
      const double t = fp / (fp - fq);
      kept.push_back(p + t * (q - p));
    }
    fp = fq;
  }
  // Drop repeated vertices (clipping a degenerate polygon creates them), in place.
  std::size_t unique = 0;
  for (std::size_t k = 0; k < kept.size(); ++k) {
    if (unique == 0 || (kept[k] - kept[unique - 1]).lpNorm<Eigen::Infinity>() > tolerance_) kept[unique++] = kept[k];
  }
  while (unique > 1 && (kept.front() - kept[unique - 1]).lpNorm<Eigen::Infinity>() <= tolerance_) --unique;
  kept.resize(unique);
  vertices_.swap(kept);
  deduplicated_ = true;
}

void ConvexPolygon::x_range(double& lo, double& hi) const noexcept {
  lo = hi = vertices_.front().y();
  for (const Eigen::Vector2d& v : vertices_) {
    lo = std::min(lo, v.y());
    hi = std::max(hi, v.y());
  }
}

bool ConvexPolygon::largest_u_at(double x, double& u) const noexcept {
  bool found = false;
  const std::size_t n = vertices_.size();
  for (std::size_t k = 0; k < n; ++k) {
    const Eigen::Vector2d& p = vertices_[k];
    const Eigen::Vector2d& q = vertices_[k + 1 == n ? 0 : k + 1];
    double candidate;
    if (std::abs(p.y() - x) <= tolerance_) {
      candidate = p.x();
    } else if ((p.y() - x) * (q.y() - x) < 0.0) {
      candidate = p.x() + (x - p.y()) / (q.y() - p.y()) * (q.x() - p.x());
    } else {
      continue;
    }
    if (!found || candidate > u) u = candidate;
    found = true;
  }
  return found;
}

Parameterisation fastest_parameterisation(std::vector<GridInterval> intervals, double x_start, double x_end) {
  return fastest_parameterisation_clipping(intervals, x_start, x_end);
}

Parameterisation fastest_parameterisation_clipping(std::vector<GridInterval>& intervals, double x_start, double x_end) {
  const std::size_t n = intervals.size();
  Parameterisation result;
  std::vector<double> lo(n + 1), hi(n + 1);
  lo[n] = hi[n] = x_end;
  // Backward: each interval's polygon is cut to the controls that land in K_{i+1}.
  for (std::size_t i = n; i-- > 0;) {
    ConvexPolygon& p = intervals[i].admissible;
    const double two_delta = 2.0 * intervals[i].delta;
    p.clip({two_delta, 1.0, hi[i + 1]});
    p.clip({-two_delta, -1.0, -lo[i + 1]});
    if (p.empty()) {
      result.infeasible_interval = static_cast<std::ptrdiff_t>(i);
      return result;
    }
    p.x_range(lo[i], hi[i]);
  }
  if (x_start < lo[0] - 1e-12 * std::max(1.0, hi[0]) || x_start > hi[0] + 1e-12 * std::max(1.0, hi[0])) {
    result.infeasible_interval = 0;
    return result;
  }
  // Forward: the largest control that stays controllable. Values outside the sets by rounding
  // (the clipping tolerance) are moved back onto them.
  result.x.resize(n + 1);
  result.u.resize(n);
  double x = std::clamp(x_start, lo[0], hi[0]);
  result.x[0] = x;
  for (std::size_t i = 0; i < n; ++i) {
    double u = 0.0;
    if (!intervals[i].admissible.largest_u_at(x, u)) {
      // x sits on the set's boundary within rounding and the line just misses a vertex.
      const double nearest = std::abs(x - lo[i]) < std::abs(x - hi[i]) ? lo[i] : hi[i];
      if (!intervals[i].admissible.largest_u_at(nearest, u)) {
        result.infeasible_interval = static_cast<std::ptrdiff_t>(i);
        result.x.clear();
        result.u.clear();
        return result;
      }
      x = nearest;
      result.x[i] = x;
    }
    const double two_delta = 2.0 * intervals[i].delta;
    const double next = std::clamp(x + two_delta * u, lo[i + 1], hi[i + 1]);
    result.u[i] = (next - x) / two_delta;  // consistent with the stored x after rounding
    result.x[i + 1] = x = next;
  }
  return result;
}

}  // namespace dispkin::detail
