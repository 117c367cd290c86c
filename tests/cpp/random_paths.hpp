// Random paths and metric sets for the guarantee oracle (doc/planning.md eq. 25), shared by the
// planner tests and the sweeps, and the oracle itself: point speeds by finite differences of
// the planned motion.
#pragma once

#include <algorithm>
#include <vector>

#include <dispkin/disp.hpp>
#include <dispkin/path/path.hpp>
#include <dispkin/planning/planner.hpp>

#include "random_cases.hpp"

namespace dispkin {
namespace testing {

using V = Eigen::Vector3d;

// A random path: a LIN (decoupled or screw), a CIRC, a chain with a corner, a SPLINE, or a
// chain of LINs blended at their via points; it starts near `offset` (m, world coordinates).
inline Path random_path(Random& rnd, int family, const V& offset = V::Zero()) {
  const Posed a = Posed(Eigen::Quaterniond::Identity(), offset) * rnd.pose(0.5);
  const V pivot = rnd.vector(0.1);
  switch (family % 6) {
    case 0:
      return Path::lin(a, rnd.nearby(a, 0.4, 1.5), Interpolation::decoupled, pivot);
    case 1:
      return Path::lin(a, rnd.nearby(a, 0.4, 1.5), Interpolation::screw, pivot);
    case 2: {
      // The pivot on an arc through two random points; random orientations at via and end.
      auto with_pivot_at = [&](const Eigen::Quaterniond& q, const V& point) { return Posed(q, point - q * pivot); };
      const V start = a * pivot;
      const Posed via = with_pivot_at(rnd.rotation(),
                                      start + V(rnd.uniform(0.1, 0.3), rnd.uniform(0.1, 0.3), rnd.uniform(-0.1, 0.1)));
      const Posed b = with_pivot_at(rnd.rotation(),
                                    start + V(rnd.uniform(-0.3, -0.1), rnd.uniform(0.1, 0.3), rnd.uniform(-0.1, 0.1)));
      return Path::circ(a, via, b, pivot, 1e-2);
    }
    case 3: {
      const Posed b = rnd.nearby(a, 0.3, 1.0);
      Path path = Path::lin(a, b, Interpolation::decoupled, pivot);
      path.then(Path::lin(b, rnd.nearby(b, 0.3, 1.0), Interpolation::decoupled, pivot));
      return path;
    }
    case 4: {
      std::vector<Posed> keys{a};
      for (int k = rnd.integer(2, 4); k > 0; --k) keys.push_back(rnd.nearby(keys.back(), 0.3, 1.0));
      return Path::spline(keys, pivot, 1e-2);
    }
    default: {
      const Posed b = rnd.nearby(a, 0.3, 1.0), c = rnd.nearby(b, 0.3, 1.0), d = rnd.nearby(c, 0.3, 1.0);
      // Blends of 10–40 % of each move's geometric size (pivot travel + 0.1 m/rad).
      auto size = [&](const Posed& p, const Posed& q) {
        return ((q * pivot) - (p * pivot)).norm() +
               0.1 * quaternion_log(Eigen::Quaterniond(p.quaternion().conjugate() * q.quaternion())).norm();
      };
      const double ab = size(a, b), bc = size(b, c), cd = size(c, d);
      Path path = Path::lin(a, b, Interpolation::decoupled, pivot);
      path.then(Path::lin(b, c, Interpolation::decoupled, pivot), rnd.uniform(0.1, 0.4) * ab,
                rnd.uniform(0.1, 0.4) * bc, 1e-2)
          .then(Path::lin(c, d, Interpolation::decoupled, pivot), rnd.uniform(0.1, 0.4) * bc,
                rnd.uniform(0.1, 0.4) * cd, 1e-2);
      return path;
    }
  }
}

// A chain of three random decoupled LINs about a random pivot, blended at both via points by
// nested SLERP (OrientationBlend::nested_slerp) with weights of 10–50 % of each move.
inline Path random_slerp_blended_chain(Random& rnd, double tolerance = 1e-2) {
  const Posed a = rnd.pose(0.5);
  const V pivot = rnd.vector(0.1);
  const Posed b = rnd.nearby(a, 0.3, 1.0), c = rnd.nearby(b, 0.3, 1.0), d = rnd.nearby(c, 0.3, 1.0);
  Path path = Path::lin(a, b, Interpolation::decoupled, pivot);
  path.then_weighted(Path::lin(b, c, Interpolation::decoupled, pivot), rnd.uniform(0.1, 0.5),
                     OrientationBlend::nested_slerp, tolerance)
      .then_weighted(Path::lin(c, d, Interpolation::decoupled, pivot), rnd.uniform(0.1, 0.5),
                     OrientationBlend::nested_slerp, tolerance);
  return path;
}

// A random list of 4–8 poses joined by decoupled LINs about a random pivot, and a corner
// tolerance of 1–30 % of its shortest move's pivot travel: a CAM-style path for continuous-path
// mode (PlanOptions::corner_tolerance).
struct PoseListPath {
  Path path;
  double corner_tolerance;
};
inline PoseListPath random_pose_list_path(Random& rnd) {
  const V pivot = rnd.vector(0.1);
  std::vector<Posed> poses{rnd.pose(0.5)};
  for (int k = rnd.integer(3, 7); k > 0; --k) poses.push_back(rnd.nearby(poses.back(), 0.3, 1.0));
  Path path = Path::lin(poses[0], poses[1], Interpolation::decoupled, pivot);
  double shortest = ((poses[1] * pivot) - (poses[0] * pivot)).norm();
  for (std::size_t k = 2; k < poses.size(); ++k) {
    path.then(Path::lin(poses[k - 1], poses[k], Interpolation::decoupled, pivot));
    shortest = std::min(shortest, ((poses[k] * pivot) - (poses[k - 1] * pivot)).norm());
  }
  return {path, rnd.uniform(0.01, 0.3) * std::max(shortest, 1e-3)};
}

// A random well-formed set with, sometimes, a second group held to a lower limit.
inline MetricSetd random_set(Random& rnd, double v_sys) {
  MetricSetd set;
  std::vector<V> tool;
  for (int k = rnd.integer(3, 6); k > 0; --k) tool.push_back(rnd.vector(0.3));
  set.add_relative(tool);
  if (rnd.integer(0, 1)) set.add_absolute(rnd.vector(1.0), 0);
  if (rnd.integer(0, 1))
    set.add_sphere(rnd.vector(0.2), rnd.uniform(0.01, 0.2), rnd.integer(0, 1) ? Frame::relative : Frame::absolute);
  if (rnd.integer(0, 1)) {
    set.add_relative(rnd.vector(0.5), 1);
    set.add_sphere(rnd.vector(1.0), 0.05, Frame::absolute, 1);
    set.set_group_speed(1, v_sys * rnd.uniform(0.2, 1.5));
  }
  return set;
}

// The largest speed / limit ratio of the set's points and spheres over [t, t + dt], by the chord
// of the motion itself (a chord over dt is never longer than the arc, so this never over-estimates).
// Any trajectory whose sample(t) has a pose: Trajectory, JointTrajectory.
// Random DISP limits at the system velocity v for a profile kind: a ∈ [0.2, 5], and for an S-curve
// j ∈ [1, 50] (drawn in that order).
inline Limits random_limits(Random& rnd, double v, ProfileKind kind) {
  Limits limits{v, rnd.uniform(0.2, 5.0), std::nullopt};
  if (kind == ProfileKind::scurve) limits.jerk = rnd.uniform(1.0, 50.0);
  return limits;
}

template <typename Traj>
inline double chord_speed_ratio(const Traj& traj, const MetricSetd& set, double v_sys, double t, double dt) {
  const Posed p = traj.sample(t).pose, q = traj.sample(t + dt).pose;
  const Twistd xi = (p.inverse() * q).log() * (1.0 / dt);
  double worst = 0;
  for (const auto& g : set.groups()) {
    const double limit = g.speed_limit.value_or(v_sys);
    double speed = 0;
    for (const V& r : g.relative_points) speed = std::max(speed, ((q * r) - (p * r)).norm() / dt);
    for (const V& x : g.absolute_points) speed = std::max(speed, ((q.inverse() * x) - (p.inverse() * x)).norm() / dt);
    for (const auto& s : g.relative_spheres) speed = std::max(speed, sphere_speed(xi, s.center, s.radius));
    for (const auto& s : g.absolute_spheres)
      speed = std::max(speed, sphere_speed(xi, V(p.inverse() * s.center), s.radius));
    worst = std::max(worst, speed / limit);
  }
  return worst;
}

// Largest speed / limit ratio over the whole trajectory, in `steps` consecutive chords.
template <typename Traj>
inline double worst_speed_ratio(const Traj& traj, const MetricSetd& set, double v_sys, int steps) {
  const double dt = traj.duration() / steps;
  double worst = 0;
  for (int i = 0; i < steps; ++i) worst = std::max(worst, chord_speed_ratio(traj, set, v_sys, i * dt, dt));
  return worst;
}

// The same oracle at `count` random times (a chord over dt = duration·1e-4 each): the sweeps'
// cheaper check, which over many cases still visits every part of every law.
template <typename Traj>
inline double worst_speed_ratio_at_random_times(const Traj& traj, const MetricSetd& set, double v_sys, int count,
                                                Random& rnd) {
  const double dt = traj.duration() * 1e-4;
  double worst = 0;
  for (int i = 0; i < count; ++i) {
    worst = std::max(worst, chord_speed_ratio(traj, set, v_sys, rnd.uniform(0.0, traj.duration() - dt), dt));
  }
  return worst;
}

}  // namespace testing
}  // namespace dispkin
