// The joint path on the σ grid and the limits of each run (joint_grid.hpp).
#include "joint_grid.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <utility>

namespace dispkin::detail {

namespace {

// The other values of p.q2 near σ (JointModel::rate_steps) and the torque_x of each.
void add_rate_steps(GridPoint& p, const SmoothParameter& path, const JointModel& model, const PathPlace& place,
                    double spacing, double lo, double hi, bool torques) {
  model.rate_steps(p.q, p.q2, place, path.s_of(std::max(lo, p.sigma - spacing)),
                   path.s_of(std::min(hi, p.sigma + spacing)), p.q2_other);
  if (!torques) return;
  Eigen::VectorXd gravity, torque_u;
  for (const Eigen::VectorXd& q2 : p.q2_other) {
    p.torque_x_other.emplace_back();
    model.torque_coefficients(p.q, p.q1, q2, gravity, torque_u, p.torque_x_other.back());
  }
}

}  // namespace

GridPoint grid_point(const SmoothParameter& path, const JointModel& model, double sigma, double h, double spacing,
                     double lo, double hi, const Eigen::VectorXd& q_ref, const Eigen::VectorXd* guess, bool torques) {
  // The path position and ds/dσ at σ (the section's own, the later one at a junction).
  auto place = [&](double at) { return PathPlace{path.s_of(at), path.s_per_sigma(path.section_at(at))}; };
  auto joint_path = [&](double at, const Eigen::VectorXd& reference, const Eigen::VectorXd* start, Eigen::VectorXd& q,
                        Eigen::VectorXd& q1) {
    Posed pose;
    Twistd per_sigma;
    path.state(at, pose, per_sigma);
    model.joints(pose, per_sigma, reference, start, place(at), q, q1);
  };
  GridPoint p;
  p.sigma = sigma;
  const double before = std::max(lo, sigma - h), after = std::min(hi, sigma + h);
  // The pose's second derivative is continuous inside a section: there q″ comes with q′ (doc/retiming.md eq. 28).
  if (sigma - h >= lo && sigma + h <= hi && path.section_at(sigma - h) == path.section_at(sigma + h)) {
    Posed pose;
    Twistd per_sigma;
    path.state(sigma, pose, per_sigma);
    if (model.joints_with_rate(pose, per_sigma, path.twist_rate(sigma), q_ref, guess, place(sigma), p.q, p.q1, p.q2)) {
      if (torques) model.torque_coefficients(p.q, p.q1, p.q2, p.gravity, p.torque_u, p.torque_x);
      add_rate_steps(p, path, model, place(sigma), spacing, lo, hi, torques);
      return p;
    }
  } else {
    joint_path(sigma, q_ref, guess, p.q, p.q1);
  }
  // Predicted to first order, so that Newton needs a single step.
  const Eigen::VectorXd guess_before = p.q - (sigma - before) * p.q1, guess_after = p.q + (after - sigma) * p.q1;
  Eigen::VectorXd q_before, q1_before, q_after, q1_after;
  joint_path(before, p.q, &guess_before, q_before, q1_before);
  joint_path(after, p.q, &guess_after, q_after, q1_after);
  p.q2 = (q1_after - q1_before) / (after - before);
  if (torques) model.torque_coefficients(p.q, p.q1, p.q2, p.gravity, p.torque_u, p.torque_x);
  add_rate_steps(p, path, model, place(sigma), spacing, lo, hi, torques);
  const std::size_t k_before = path.section_at(before), k_after = path.section_at(after);
  if (model.rates_step() && k_before != k_after) {
    // A junction inside the run, where q″ of a moving redundancy parameter steps with ds/dσ
    // (doc/inverse-kinematics.md eq. 51): the limits hold for either section's own q″ as well.
    Eigen::VectorXd q, q1, q2, gravity, torque_u;
    for (const std::size_t k : {k_before, k_after}) {
      Posed pose;
      Twistd per_sigma, rate;
      path.state_in(k, sigma, pose, per_sigma, rate);
      if (!model.joints_with_rate(pose, per_sigma, rate, p.q, &p.q, PathPlace{path.s_of(sigma), path.s_per_sigma(k)}, q,
                                  q1, q2))
        continue;
      p.q2_other.push_back(q2);
      if (!torques) continue;
      p.torque_x_other.emplace_back();
      model.torque_coefficients(p.q, p.q1, q2, gravity, torque_u, p.torque_x_other.back());
    }
  }
  return p;
}

void append_limits(const GridPoint& p, const JointBounds& bounds, double scale, std::vector<HalfPlane>& out) {
  for (Eigen::Index k = 0; k < p.q.size(); ++k) {
    if (std::isfinite(bounds.velocity(k))) {
      const double v = scale * bounds.velocity(k);
      out.push_back({0.0, p.q1(k) * p.q1(k), v * v});
    }
    if (std::isfinite(bounds.acceleration(k))) {
      const double a = scale * bounds.acceleration(k);
      out.push_back({p.q1(k), p.q2(k), a});
      out.push_back({-p.q1(k), -p.q2(k), a});
      for (const Eigen::VectorXd& q2 : p.q2_other) {
        out.push_back({p.q1(k), q2(k), a});
        out.push_back({-p.q1(k), -q2(k), a});
      }
    }
    if (std::isfinite(bounds.effort(k)) && p.gravity.size()) {
      const double t = scale * bounds.effort(k);
      out.push_back({p.torque_u(k), p.torque_x(k), t - p.gravity(k)});
      out.push_back({-p.torque_u(k), -p.torque_x(k), t + p.gravity(k)});
      for (const Eigen::VectorXd& torque_x : p.torque_x_other) {
        out.push_back({p.torque_u(k), torque_x(k), t - p.gravity(k)});
        out.push_back({-p.torque_u(k), -torque_x(k), t + p.gravity(k)});
      }
    }
  }
}

double joint_speed_cap(const GridPoint& p, const JointBounds& bounds, double scale) {
  double cap = std::numeric_limits<double>::infinity();
  for (Eigen::Index k = 0; k < p.q.size(); ++k) {
    if (std::isfinite(bounds.velocity(k)) && p.q1(k) != 0.0) {
      const double v = scale * bounds.velocity(k) / std::abs(p.q1(k));
      cap = std::min(cap, v * v);
    }
  }
  return cap;
}

std::string interval_text(double s0, double s1) {
  std::ostringstream out;
  out << "[" << s0 << ", " << s1 << "] m";
  return out.str();
}

RunProblem::RunProblem(const SmoothParameter& smooth, const std::vector<GridPoint>& grid, const JointBounds& bounds,
                       double scale, Run run)
    : smooth_(smooth), grid_(grid), run_(run) {
  admissible_.reserve(run_.count);
  speed_cap_.reserve(run_.count + 1);
  std::vector<HalfPlane> at_start, at_end;
  for (std::size_t i = run_.first; i < run_.first + run_.count; ++i) {
    const GridPoint &p = grid_[i], &p_next = grid_[i + 1];
    const double delta = p_next.sigma - p.sigma;
    double speed, accel;
    smooth_.limits_over(p.sigma, p_next.sigma, speed, accel);
    GridInterval interval{delta, ConvexPolygon(accel, speed * speed)};
    interval.admissible.clip({2.0 * delta, 1.0, speed * speed});  // at the interval's end as well
    at_start.clear();
    at_end.clear();
    append_limits(p, bounds, scale, at_start);
    append_limits(p_next, bounds, scale, at_end);
    for (const HalfPlane& h : at_start) interval.admissible.clip(h);
    for (const HalfPlane& h : at_end) interval.admissible.clip({h.a + 2.0 * delta * h.b, h.b, h.c});
    admissible_.push_back(std::move(interval));
  }
  for (std::size_t g = run_.first; g <= run_.first + run_.count; ++g)
    speed_cap_.push_back(joint_speed_cap(grid_[g], bounds, scale));
}

Parameterisation RunProblem::solve(double reach, double run_acceleration, double run_speed) const {
  std::vector<GridInterval>& intervals = clipped_;
  intervals = admissible_;                   // into the storage of the last solve: no allocation
  std::size_t near_begin = 0, near_end = 0;  // the grid points within ±reach of the interval
  for (std::size_t i = 0; i < run_.count; ++i) {
    ConvexPolygon& polygon = intervals[i].admissible;
    const double delta = intervals[i].delta;
    const double sigma = grid_[run_.first + i].sigma, sigma_next = grid_[run_.first + i + 1].sigma;
    if (run_acceleration > 0.0) {
      polygon.clip({1.0, 0.0, run_acceleration});
      polygon.clip({-1.0, 0.0, run_acceleration});
    }
    double speed = run_speed;
    if (reach > 0.0) {
      double disp_speed, unused;
      smooth_.limits_over(std::max(start(), sigma - reach), std::min(end(), sigma_next + reach), disp_speed, unused);
      speed = std::min(speed, disp_speed);
    }
    if (std::isfinite(speed)) {  // at both ends of the interval
      polygon.clip({0.0, 1.0, speed * speed});
      polygon.clip({2.0 * delta, 1.0, speed * speed});
    }
    if (reach > 0.0) {
      // σ̇² cap of the joint speeds nearby; the window of grid points moves on with the interval.
      while (near_begin <= run_.count && grid_[run_.first + near_begin].sigma < sigma - reach) ++near_begin;
      near_end = std::max(near_end, near_begin);
      while (near_end <= run_.count && grid_[run_.first + near_end].sigma <= sigma_next + reach) ++near_end;
      double joint_speed = std::numeric_limits<double>::infinity();
      for (std::size_t g = near_begin; g < near_end; ++g) joint_speed = std::min(joint_speed, speed_cap_[g]);
      if (std::isfinite(joint_speed)) {
        polygon.clip({0.0, 1.0, joint_speed});
        polygon.clip({2.0 * delta, 1.0, joint_speed});
      }
    }
  }
  Parameterisation fastest = fastest_parameterisation_clipping(intervals, 0.0, 0.0);
  if (fastest.infeasible_interval >= 0) {
    const std::size_t i = run_.first + static_cast<std::size_t>(fastest.infeasible_interval);
    throw std::runtime_error("no speed keeps every joint limit on the path interval " +
                             interval_text(smooth_.s_of(grid_[i].sigma), smooth_.s_of(grid_[i + 1].sigma)) +
                             " while still reaching the next rest");
  }
  for (std::size_t i = 0; i < run_.count; ++i) {
    if (!(fastest.x[i] + fastest.x[i + 1] > 0.0)) {
      throw std::runtime_error(
          "the joint limits allow no motion on the path interval " +
          interval_text(smooth_.s_of(grid_[run_.first + i].sigma), smooth_.s_of(grid_[run_.first + i + 1].sigma)));
    }
  }
  return fastest;
}

}  // namespace dispkin::detail
