// The DISP trajectory planner (doc/planning.md).
#include "dispkin/planning/planner.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <utility>

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
  std::vector<double> lengths(n), accelerations(n);
  for (std::size_t k = 0; k < n; ++k) {
    const detail::SectionBounds bounds = detail::section_bounds(sections[k], factors);
    lengths[k] = bounds.length;
    accelerations[k] = bounds.acceleration;
  }
  // A longer section is traversed more slowly (τ̇ = ṡ/L), so every point still moves at most at
  // ṡ·L_k/L ≤ ṡ: the DISP guarantee survives any lengthening.
  for (std::size_t k = 0; k < minimum.size(); ++k) lengths[k] = std::max(lengths[k], minimum[k]);
  SampledPath sampled(sections, lengths);

  // Rest-to-rest runs between corners; within a run the velocity-limit curve.
  const std::optional<double> jerk = profile == ProfileKind::scurve ? limits.jerk : std::nullopt;
  TimeLaw law;
  std::vector<SpeedLimit> speed_limits;
  std::vector<double> rests{0.0};
  std::size_t first = 0;
  for (std::size_t k = 0; k < n; ++k) {
    if (k + 1 < n && tangent_continuous(sections[k], lengths[k], sections[k + 1], lengths[k + 1])) continue;
    const std::vector<LimitedSegment> segments = speed_limit_segments(accelerations, lengths, first, k + 1, limits);
    double start_s = sampled.section_start(first);
    double span_s = start_s;
    for (const LimitedSegment& segment : segments) {
      speed_limits.push_back({span_s, segment.length, segment.limit});
      span_s += segment.length;
    }
    for (const Profile& piece : velocity_limited_law(segments, limits.acceleration, jerk)) {
      law.append(piece, start_s);
      start_s += piece.distance();
    }
    law.end_run();
    rests.push_back(k + 1 == n ? sampled.section_start(k) + lengths[k] : sampled.section_start(k + 1));
    first = k + 1;
  }
  return Trajectory(std::move(sampled), std::move(law), std::move(speed_limits), std::move(rests));
}

}  // namespace dispkin
