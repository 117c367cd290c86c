// The DISP trajectory planner (MATH.md §5–7).
#include "dispkin/planning/planner.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>

#include "dispkin/error.hpp"
#include "dispkin/planning/velocity_limit.hpp"

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

// The twists per unit of s are ξ/L on both sides; the direction of ξ/L is that of ξ.
bool tangent_continuous(const Twistd& out_twist, double length_before, const Twistd& in_twist, double length_after) {
  const Eigen::Matrix<double, 6, 1> out = out_twist.vector(), in = in_twist.vector();
  const double out_size = out.norm(), in_size = in.norm();
  if (!(out_size > 0.0) || !(in_size > 0.0) || !(length_before > 0.0) || !(length_after > 0.0)) return false;
  const double direction_change = (out * (1.0 / out_size) - in * (1.0 / in_size)).norm();
  const double out_speed = out_size / length_before, in_speed = in_size / length_after;
  return direction_change <= junction_direction_tolerance &&
         std::abs(out_speed - in_speed) <= junction_speed_step * std::max(out_speed, in_speed);
}

// Whether `after` continues the motion of `before`: the same cubic curve from the parameter
// where `before` ends, or the same circular motion (its body twist is then a function of the
// pose alone, and the path joins its sections to 1e-9).
bool continues(const CurveSection& before, const CurveSection& after) {
  return before.v1 == after.v0 && detail::same_curve(before.q0, before.position, before.rotation, before.pivot, after);
}
bool continues(const ArcSection& before, const ArcSection& after) {
  return before.center == after.center && before.normal == after.normal && before.angle == after.angle &&
         before.rotation_axis == after.rotation_axis && before.rotation_angle == after.rotation_angle &&
         before.pivot == after.pivot;
}

// Whether the motion's twist at the start of `after` is not zero. For a curve: ξ = (Rᵀ c′ −
// ω × p, ω) with ω = J_r(φ) φ′ (per unit v), zero iff c′ = 0 and ω = 0. For an arc: ω = θ
// q⁻¹ŵ, and with θ = 0 the pivot's velocity φ n × (c − o).
bool moving(const CurveSection& after) {
  if (after.position.first(after.v0) != Eigen::Vector3d::Zero()) return true;
  const Eigen::Vector3d slope = after.rotation.first(after.v0);
  return slope != Eigen::Vector3d::Zero() &&
         right_jacobian_times(after.rotation.value(after.v0), slope) != Eigen::Vector3d::Zero();
}
bool moving(const ArcSection& after) {
  return after.rotation_angle != 0.0 ||
         (after.angle != 0.0 && after.normal.cross(after.start * after.pivot - after.center) != Eigen::Vector3d::Zero());
}

// The junction rule where `after` continues the motion of `before`, without evaluating a twist:
// both sides see the motion's one twist ξ at the junction, per unit τ scaled by the sections'
// spans h (the curve parameter per unit τ; arcs of one motion have equal spans), so per unit
// of s ξ h_k / L_k and ξ h_k+1 / L_k+1. The directions agree; what is left is ξ ≠ 0 and a
// step of at most 1 % in h / L. Empty when `after` does not continue `before`.
std::optional<bool> continuing_junction(const Section& before, double length_before, const Section& after,
                                        double length_after) {
  double span_before = 1.0, span_after = 1.0;
  bool is_moving = false;
  const auto* curve_before = std::get_if<CurveSection>(&before);
  const auto* curve_after = std::get_if<CurveSection>(&after);
  const auto* arc_before = std::get_if<ArcSection>(&before);
  const auto* arc_after = std::get_if<ArcSection>(&after);
  if (curve_before && curve_after && continues(*curve_before, *curve_after)) {
    span_before = curve_before->span();
    span_after = curve_after->span();
    is_moving = moving(*curve_after);
  } else if (arc_before && arc_after && continues(*arc_before, *arc_after)) {
    is_moving = moving(*arc_after);
  } else {
    return std::nullopt;
  }
  if (!is_moving || !(length_before > 0.0) || !(length_after > 0.0)) return false;
  const double out_speed = span_before / length_before, in_speed = span_after / length_after;
  return std::abs(out_speed - in_speed) <= junction_speed_step * std::max(out_speed, in_speed);
}

// The junction rule for any two sections.
bool tangent_continuous(const Section& before, double length_before, const Section& after, double length_after) {
  if (const std::optional<bool> continuing = continuing_junction(before, length_before, after, length_after))
    return *continuing;
  return tangent_continuous(section_twist(before, 1.0), length_before, section_twist(after, 0.0), length_after);
}

// The velocity-limit curve over sections [first, last): the path curvature rule. Along a
// section of length L, a point whose acceleration per unit τ² is at most A (the section's
// acceleration_bound) accelerates at ṡ² A / L² from the curvature alone; keeping that within
// the acceleration limit a gives ṡ ≤ v_lim = L √(a / A). With s̈ ≤ a on top, no point of the
// set accelerates faster than 2a inside a section. The limit is rounded down to a staircase of
// 10 % steps (v, 0.9 v, 0.81 v, …) so that a smoothly varying curvature gives a few long
// segments instead of a velocity that hunts from section to section.
std::vector<LimitedSegment> speed_limit_segments(const std::vector<double>& accelerations, const std::vector<double>& lengths,
                                                 std::size_t first, std::size_t last, const Limits& limits) {
  constexpr double step = 0.9;
  std::vector<LimitedSegment> segments;
  for (std::size_t k = first; k < last; ++k) {
    const double a = accelerations[k];
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

}  // namespace

namespace detail {

void SectionMotions::reserve(const std::vector<Section>& sections) {
  std::size_t lines = 0, arcs = 0, screws = 0;
  for (const Section& s : sections) {
    if (const auto* lin = std::get_if<LinSection>(&s)) {
      ++(lin->interpolation == Interpolation::screw ? screws : lines);
    } else if (std::holds_alternative<ArcSection>(s)) {
      ++arcs;
    }
  }
  entries_.reserve(sections.size());
  lines_.reserve(lines);
  arcs_.reserve(arcs);
  screws_.reserve(screws);
}

void SectionMotions::append(const Section& section) {
  if (const auto* lin = std::get_if<LinSection>(&section)) {
    if (lin->interpolation == Interpolation::screw) {
      entries_.push_back({Kind::screw, screws_.size()});
      screws_.push_back(ScrewMotion{lin->start, (lin->start.inverse() * lin->end).log()});
      return;
    }
    const Eigen::Quaterniond q0 = lin->start.quaternion();
    const Eigen::Vector3d rotation = q0 * quaternion_log(Eigen::Quaterniond(q0.conjugate() * lin->end.quaternion()));
    const double theta = rotation.norm();
    const Eigen::Vector3d w_hat = theta > 0.0 ? Eigen::Vector3d(rotation / theta) : Eigen::Vector3d::UnitZ();
    const Eigen::Vector3d c0 = lin->start * lin->pivot;
    entries_.push_back({Kind::line, lines_.size()});
    lines_.emplace_back(TurningFrame(q0, w_hat, theta, lin->pivot), c0, (lin->end * lin->pivot) - c0);
    return;
  }
  if (const auto* curve = std::get_if<CurveSection>(&section)) {
    // Sections of one curve come in a run: compare with the latest curve only.
    if (curves_.empty() || !curves_.back().holds(*curve)) {
      curves_.push_back(CurveMotion{curve->q0, curve->position, curve->rotation, curve->pivot});
    }
    entries_.push_back({Kind::curve, curves_.size() - 1, curve->v0, curve->span()});
    return;
  }
  const auto& arc = std::get<ArcSection>(section);
  ArcMotion m;
  m.frame = TurningFrame(arc.start.quaternion(), arc.rotation_axis, arc.rotation_angle, arc.pivot);
  const Eigen::Vector3d radius = arc.start * arc.pivot - arc.center;
  const Eigen::Vector3d along = radius.dot(arc.normal) * arc.normal;
  m.center_along = arc.center + along;
  m.radius_across = radius - along;
  m.radius_side = arc.normal.cross(m.radius_across);
  m.angle = arc.angle;
  entries_.push_back({Kind::arc, arcs_.size()});
  arcs_.push_back(m);
}

}  // namespace detail

void Limits::validate(ProfileKind kind) const {
  require_limit(velocity, "velocity");
  require_limit(acceleration, "acceleration");
  if (kind == ProfileKind::scurve) {
    if (!jerk) throw std::invalid_argument("jerk is missing: the S-curve profile needs a jerk limit (or use the trapezoid)");
    require_limit(*jerk, "jerk");
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
  // under its own limit. Lengths and acceleration bounds come from one evaluation per section
  // (the same as Path::section_lengths and section_acceleration_bound give).
  detail::GroupFactors factors(set, limits.velocity);
  trajectory.lengths_.resize(n);
  std::vector<double> accelerations(n);
  for (std::size_t k = 0; k < n; ++k) {
    const detail::SectionBounds bounds = detail::section_bounds(sections[k], factors);
    trajectory.lengths_[k] = bounds.length;
    accelerations[k] = bounds.acceleration;
  }
  // A longer section is traversed more slowly (τ̇ = ṡ/L), so every point still moves at most at
  // ṡ·L_k/L ≤ ṡ: the DISP guarantee survives any lengthening.
  for (std::size_t k = 0; k < minimum.size(); ++k) trajectory.lengths_[k] = std::max(trajectory.lengths_[k], minimum[k]);
  trajectory.motions_.reserve(sections);
  for (const Section& section : sections) trajectory.motions_.append(section);
  trajectory.starts_.resize(n);
  double s = 0.0;
  for (std::size_t k = 0; k < n; ++k) {
    trajectory.starts_[k] = {s, 1.0 / trajectory.lengths_[k]};
    s += trajectory.lengths_[k];
  }

  // Rest-to-rest runs between corners; within a run the velocity-limit curve.
  const std::optional<double> jerk = profile == ProfileKind::scurve ? limits.jerk : std::nullopt;
  double time = 0.0;
  std::size_t first = 0;
  trajectory.rest_s_.push_back(0.0);
  for (std::size_t k = 0; k < n; ++k) {
    if (k + 1 < n && tangent_continuous(sections[k], trajectory.lengths_[k], sections[k + 1], trajectory.lengths_[k + 1]))
      continue;
    const std::vector<LimitedSegment> segments = speed_limit_segments(accelerations, trajectory.lengths_, first, k + 1, limits);
    double start_s = trajectory.starts_[first].s;
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
    trajectory.rest_s_.push_back(k + 1 == n ? trajectory.starts_[k].s + trajectory.lengths_[k] : trajectory.starts_[k + 1].s);
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

std::size_t Trajectory::piece_at(double t, std::size_t piece) const noexcept {
  const std::size_t last = pieces_.size() - 1;
  // Piece p is it when the one before ends at or before t and p ends after t (or is the last).
  const auto is_it = [&](std::size_t p) {
    return (p == 0 || pieces_[p - 1].end_time <= t) && (p == last || t < pieces_[p].end_time);
  };
  if (piece <= last && is_it(piece)) return piece;
  if (piece < last && is_it(piece + 1)) return piece + 1;
  const auto it = std::upper_bound(pieces_.begin(), pieces_.end(), t, [](double x, const Piece& p) { return x < p.end_time; });
  return it == pieces_.end() ? last : static_cast<std::size_t>(it - pieces_.begin());
}

std::size_t Trajectory::section_at(double s, std::size_t section) const noexcept {
  const std::size_t last = starts_.size() - 1;
  // Section k is it when it starts at or before s (or is the first) and the next one starts
  // after s (or k is the last).
  const auto is_it = [&](std::size_t k) {
    return (k == 0 || starts_[k].s <= s) && (k == last || s < starts_[k + 1].s);
  };
  if (section <= last && is_it(section)) return section;
  if (section < last && is_it(section + 1)) return section + 1;
  const auto next = std::upper_bound(starts_.begin(), starts_.end(), s, [](double x, const SectionStart& k) { return x < k.s; });
  const std::size_t k = next == starts_.begin() ? 0 : static_cast<std::size_t>(next - starts_.begin()) - 1;
  return std::min(k, last);
}

TrajectorySample Trajectory::sample(double t) const noexcept {
  Cursor search{pieces_.size(), starts_.size()};  // no hint: binary search
  return sample(t, search);
}

TrajectorySample Trajectory::sample(double t, Cursor& cursor) const noexcept {
  TrajectorySample out;
  if (pieces_.empty()) return out;
  if (!(t > 0.0)) t = 0.0;
  const std::size_t p = cursor.piece = piece_at(t, cursor.piece);
  const Piece& piece = pieces_[p];
  const ProfileState law = piece.profile.state_at(t - piece.start_time);
  out.s = piece.start_s + law.s;
  out.s_dot = law.v;
  out.s_ddot = law.a;
  const std::size_t k = cursor.section = section_state(out.s, cursor.section, out.pose, out.body_twist);
  out.body_twist = out.body_twist * (out.s_dot * starts_[k].inverse_length);  // per τ → per second
  return out;
}

void Trajectory::path_state(double s, Posed& pose, Twistd& twist_per_s) const noexcept {
  if (starts_.empty()) return;
  const std::size_t k = section_state(s, starts_.size(), pose, twist_per_s);
  twist_per_s = twist_per_s * starts_[k].inverse_length;
}

std::size_t Trajectory::section_state(double s, std::size_t hint, Posed& pose, Twistd& twist_per_tau) const noexcept {
  const std::size_t k = section_at(s, hint);
  const SectionStart& start = starts_[k];
  const double tau = std::clamp((s - start.s) * start.inverse_length, 0.0, 1.0);
  motions_.at(k, tau, pose, twist_per_tau);
  return k;
}

void Trajectory::sample(const double* times, TrajectorySample* out, std::size_t count) const noexcept {
  Cursor cursor;
  for (std::size_t i = 0; i < count; ++i) out[i] = sample(times[i], cursor);
}

}  // namespace dispkin
