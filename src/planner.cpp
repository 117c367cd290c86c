// The DISP trajectory planner (MATH.md §5–7).
#include "dispkin/planner.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "dispkin/error.hpp"
#include "dispkin/velocity_limit.hpp"

namespace dispkin {
namespace {

// The junction rule. The path runs through the junction of sections k and k + 1 without
// stopping when the twist per unit of s keeps its direction (to 1e-6 rad) and changes its
// size by at most 1 %. Then every point keeps its velocity direction and its speed steps by at
// most 1 % of ṡ — the residue of mapping s linearly onto each section of a curve whose speed
// varies (curved sections are cut so that this stays near their `tolerance`, 10⁻³ by
// default). Any other junction is a corner: the path stops there (a velocity direction that
// jumps needs an unbounded acceleration at any speed above zero).
constexpr double junction_direction_tolerance = 1e-6;
constexpr double junction_speed_step = 1e-2;

bool tangent_continuous(const Section& before, double length_before, const Section& after, double length_after) {
  const Eigen::Matrix<double, 6, 1> out = section_twist(before, 1.0).vector() / length_before;
  const Eigen::Matrix<double, 6, 1> in = section_twist(after, 0.0).vector() / length_after;
  const double out_norm = out.norm(), in_norm = in.norm();
  if (!(out_norm > 0.0) || !(in_norm > 0.0)) return false;
  const double direction_change = (out / out_norm - in / in_norm).norm();
  return direction_change <= junction_direction_tolerance &&
         std::abs(out_norm - in_norm) <= junction_speed_step * std::max(out_norm, in_norm);
}

// The velocity-limit curve over sections [first, last): the path curvature rule. Along a
// section of length L, a point whose acceleration per unit τ² is at most A (the section's
// acceleration_bound) accelerates at ṡ² A / L² from the curvature alone; keeping that within
// the acceleration limit a gives ṡ ≤ v_lim = L √(a / A). With s̈ ≤ a on top, no point of the
// set accelerates faster than 2a inside a section. The limit is rounded down to a staircase of
// 10 % steps (v, 0.9 v, 0.81 v, …) so that a smoothly varying curvature gives a few long
// segments instead of a velocity that hunts from section to section.
std::vector<LimitedSegment> speed_limit_segments(const std::vector<Section>& sections, const std::vector<double>& lengths,
                                                 std::size_t first, std::size_t last, const MetricSetd& set,
                                                 const Limits& limits) {
  constexpr double step = 0.9;
  std::vector<LimitedSegment> segments;
  for (std::size_t k = first; k < last; ++k) {
    const double a = section_acceleration_bound(sections[k], set);
    double level = limits.velocity;
    if (a > 0.0) {
      const double v_lim = lengths[k] * std::sqrt(limits.acceleration / a);
      if (v_lim < limits.velocity) level = limits.velocity * std::pow(step, std::ceil(std::log(v_lim / limits.velocity) / std::log(step)));
    }
    if (!segments.empty() && segments.back().limit == level) {
      segments.back().length += lengths[k];
    } else {
      segments.push_back({lengths[k], level});
    }
  }
  return segments;
}

// The unit quaternion of a turn by `angle` about the unit axis `axis`.
Eigen::Quaterniond turn(const Eigen::Vector3d& axis, double angle) noexcept {
  const double half = 0.5 * angle;
  const double s = std::sin(half);
  return Eigen::Quaterniond(std::cos(half), s * axis.x(), s * axis.y(), s * axis.z());
}

}  // namespace

Trajectory::Motion Trajectory::Motion::of(const Section& section) {
  Motion m;
  if (const auto* lin = std::get_if<LinSection>(&section)) {
    m.pivot = lin->pivot;
    if (lin->interpolation == Interpolation::screw) {
      m.kind = Kind::screw;
      m.start = lin->start;
      m.xi = (lin->start.inverse() * lin->end).log();
      return m;
    }
    m.kind = Kind::line;
    m.q0 = lin->start.quaternion();
    m.c0 = lin->start * lin->pivot;
    m.delta_c = (lin->end * lin->pivot) - m.c0;
    const Eigen::Vector3d rotation = m.q0 * quaternion_log(Eigen::Quaterniond(m.q0.conjugate() * lin->end.quaternion()));
    m.theta = rotation.norm();
    if (m.theta > 0.0) m.w_hat = rotation / m.theta;
    return m;
  }
  if (const auto* curve = std::get_if<CurveSection>(&section)) {
    m.kind = Kind::curve;
    m.curve = *curve;
    return m;
  }
  const auto& arc = std::get<ArcSection>(section);
  m.kind = Kind::arc;
  m.pivot = arc.pivot;
  m.q0 = arc.start.quaternion();
  m.c0 = arc.start * arc.pivot;
  m.center = arc.center;
  m.normal = arc.normal;
  m.angle = arc.angle;
  m.w_hat = arc.rotation_axis;
  m.theta = arc.rotation_angle;
  return m;
}

void Trajectory::Motion::at(double tau, Posed& pose, Twistd& twist) const noexcept {
  if (kind == Kind::screw) {
    pose = start * Posed::exp(xi * tau);
    twist = xi;
    return;
  }
  if (kind == Kind::curve) {
    curve.at(tau, pose, twist);
    return;
  }
  const Eigen::Quaterniond q = turn(w_hat, tau * theta) * q0;
  Eigen::Vector3d c, c_dot;
  if (kind == Kind::line) {
    c = c0 + tau * delta_c;
    c_dot = delta_c;
  } else {
    c = center + turn(normal, tau * angle) * (c0 - center);
    c_dot = angle * normal.cross(c - center);
  }
  pose = Posed::unchecked(q, c - q * pivot);
  // Body twist: ω_b = Rᵀ θŵ, v_b = Rᵀ ċ − ω_b × p (the body origin is t = c − R p).
  const Eigen::Quaterniond q_inv = q.conjugate();
  twist.angular = q_inv * (theta * w_hat);
  twist.linear = q_inv * c_dot - twist.angular.cross(pivot);
}

void Limits::validate(ProfileKind kind) const {
  require_positive(velocity, "velocity");
  require_positive(acceleration, "acceleration");
  if (kind == ProfileKind::scurve) {
    if (!jerk) throw std::invalid_argument("jerk is missing: the S-curve profile needs a jerk limit (or use the trapezoid)");
    require_positive(*jerk, "jerk");
  } else if (jerk) {
    throw std::invalid_argument(describe("jerk", *jerk, "is not used by the trapezoidal profile; leave it unset"));
  }
}

Trajectory plan(const Path& path, const MetricSetd& set, const Limits& limits, ProfileKind profile) {
  return plan(path, set, limits, profile, PlanOptions{});
}

Trajectory plan(const Path& path, const MetricSetd& set, const Limits& limits, ProfileKind profile,
                const PlanOptions& options) {
  limits.validate(profile);
  set.require_well_formed();
  Trajectory trajectory;
  const std::vector<Section>& sections = path.sections();
  const std::size_t n = sections.size();
  const std::vector<double>& minimum = options.min_section_lengths;
  require(minimum.empty() || minimum.size() == n, "min_section_lengths size", static_cast<unsigned long>(minimum.size()),
          "must be 0 or the path's section count " + std::to_string(n));
  for (std::size_t k = 0; k < minimum.size(); ++k) {
    require(std::isfinite(minimum[k]) && minimum[k] >= 0.0, "min_section_lengths[" + std::to_string(k) + "]",
            minimum[k], "must be finite and not negative");
  }
  // Group weights v_sys / v_g are part of the lengths: path speed ≤ v_sys keeps every group
  // under its own limit.
  trajectory.lengths_ = path.section_lengths(set, limits.velocity);
  // A longer section is traversed more slowly (τ̇ = ṡ/L), so every point still moves at most at
  // ṡ·L_k/L ≤ ṡ: the DISP guarantee survives any lengthening.
  for (std::size_t k = 0; k < minimum.size(); ++k) trajectory.lengths_[k] = std::max(trajectory.lengths_[k], minimum[k]);
  trajectory.motions_.reserve(n);
  for (const Section& section : sections) trajectory.motions_.push_back(Trajectory::Motion::of(section));
  trajectory.section_s_.resize(n);
  double s = 0.0;
  for (std::size_t k = 0; k < n; ++k) {
    trajectory.section_s_[k] = s;
    s += trajectory.lengths_[k];
  }

  // Rest-to-rest runs between corners; within a run the velocity-limit curve.
  const std::optional<double> jerk = profile == ProfileKind::scurve ? limits.jerk : std::nullopt;
  double time = 0.0;
  std::size_t first = 0;
  trajectory.rest_s_.push_back(0.0);
  for (std::size_t k = 0; k < n; ++k) {
    const bool last = k + 1 == n;
    if (!last && tangent_continuous(sections[k], trajectory.lengths_[k], sections[k + 1], trajectory.lengths_[k + 1]))
      continue;
    const std::vector<LimitedSegment> segments = speed_limit_segments(sections, trajectory.lengths_, first, k + 1, set, limits);
    double start_s = trajectory.section_s_[first];
    double span_s = start_s;
    for (const LimitedSegment& segment : segments) {
      trajectory.speed_limits_.push_back({span_s, segment.length, segment.limit});
      span_s += segment.length;
    }
    for (const Profile& law : velocity_limited_law(segments, limits.acceleration, jerk)) {
      trajectory.pieces_.push_back(Trajectory::Piece{law, time, time + law.duration(), start_s});
      time += law.duration();
      start_s += law.distance();
    }
    ++trajectory.rest_pieces_;
    trajectory.rest_s_.push_back(last ? trajectory.section_s_[k] + trajectory.lengths_[k] : trajectory.section_s_[k + 1]);
    first = k + 1;
  }
  return trajectory;
}

std::vector<double> Trajectory::characteristic_times() const {
  std::vector<double> times{0.0};
  for (const Piece& piece : pieces_) {
    const Profile& law = piece.profile;
    for (int i = 0; i < law.phase_count(); ++i) {
      const double begin = law.phase_start_time(i), end = law.phase_start_time(i + 1);
      times.push_back(piece.start_time + 0.5 * (begin + end));
      times.push_back(piece.start_time + end);
    }
  }
  std::sort(times.begin(), times.end());
  // Phases of vanishing length (a cruise over 10⁻⁹ of a law's distance, left by rounding) add
  // instants that coincide within 10⁻⁹ of the duration: one of each is kept.
  const double same = 1e-9 * duration();
  times.erase(std::unique(times.begin(), times.end(), [same](double a, double b) { return b - a <= same; }), times.end());
  return times;
}

TrajectorySample Trajectory::sample(double t) const noexcept {
  TrajectorySample out;
  if (pieces_.empty()) return out;
  if (!(t > 0.0)) t = 0.0;
  // The piece running at t: the first that ends after t (the last one for t ≥ duration).
  auto piece = std::upper_bound(pieces_.begin(), pieces_.end(), t, [](double x, const Piece& p) { return x < p.end_time; });
  if (piece == pieces_.end()) --piece;
  const ProfileState law = piece->profile.state_at(t - piece->start_time);
  out.s = piece->start_s + law.s;
  out.s_dot = law.v;
  out.s_ddot = law.a;
  path_state(out.s, out.pose, out.body_twist);
  out.body_twist = out.body_twist * out.s_dot;
  return out;
}

void Trajectory::path_state(double s, Posed& pose, Twistd& twist_per_s) const noexcept {
  if (motions_.empty()) return;
  // The section holding s, and τ within it.
  auto next = std::upper_bound(section_s_.begin(), section_s_.end(), s);
  std::size_t k = next == section_s_.begin() ? 0 : static_cast<std::size_t>(next - section_s_.begin()) - 1;
  k = std::min(k, motions_.size() - 1);
  const double tau = std::clamp((s - section_s_[k]) / lengths_[k], 0.0, 1.0);
  motions_[k].at(tau, pose, twist_per_s);
  twist_per_s = twist_per_s * (1.0 / lengths_[k]);
}

void Trajectory::sample(const double* times, TrajectorySample* out, std::size_t count) const noexcept {
  for (std::size_t i = 0; i < count; ++i) out[i] = sample(times[i]);
}

}  // namespace dispkin
