// The DISP trajectory planner (doc/planning.md).
#include "dispkin/planning/planner.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <type_traits>
#include <utility>

#include "../path/path_geometry.hpp"
#include "../path/section_bounds.hpp"
#include "dispkin/error.hpp"
#include "dispkin/planning/velocity_limit.hpp"
#include "../message_number.hpp"
#include "lin_speed_range.hpp"

namespace dispkin {
namespace {

// The junction rule. The path runs through the junction of sections k and k + 1 without
// stopping when the twist per unit of s keeps its direction (to 1e-6 rad) and changes its
// size by at most 1 %. Then every point keeps its velocity direction and its speed steps by at
// most 1 % of ṡ — the residue of mapping s linearly onto sections whose speed varies. Any other
// junction is a corner: the path stops there (a velocity direction that jumps needs an
// unbounded acceleration at any speed above zero).
constexpr double junction_direction_tolerance = 1e-6;

// Whether `after` continues the motion of `before`: the same cubic curve (or nested-SLERP
// blend) from the parameter where `before` ends, or the same circular motion (its body twist is then a function of the
// pose alone, and the path joins its sections to 1e-9).
bool continues(const CurveSection& before, const CurveSection& after) {
  return before.v1 == after.v0 && detail::same_curve(before.q0, before.position, before.rotation, before.pivot, after);
}
bool continues(const SlerpBlendSection& before, const SlerpBlendSection& after) {
  return before.v1 == after.v0 && before.same_blend(after);
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
bool moving(const SlerpBlendSection& after) { return after.twist(0.0).vector() != Eigen::Matrix<double, 6, 1>::Zero(); }
bool moving(const ArcSection& after) {
  return after.rotation_angle != 0.0 ||
         (after.angle != 0.0 &&
          after.normal.cross(after.start * after.pivot - after.center) != Eigen::Vector3d::Zero());
}

// The twist sizes per unit τ at the end of `before` and the start of `after`, when the junction
// keeps the twist's direction (doc/planning.md eq. 9, first part): per unit of s the speeds are
// then out/L_k and in/L_k+1. Empty at a corner (or where the motion stands still).
struct JunctionSpeeds {
  double out, in;
};
std::optional<JunctionSpeeds> direction_continuous(const Section& before, const Section& after) {
  const auto* curve_before = std::get_if<CurveSection>(&before);
  const auto* curve_after = std::get_if<CurveSection>(&after);
  const auto* arc_before = std::get_if<ArcSection>(&before);
  const auto* arc_after = std::get_if<ArcSection>(&after);
  if (curve_before && curve_after && continues(*curve_before, *curve_after)) {
    if (!moving(*curve_after)) return std::nullopt;
    return JunctionSpeeds{curve_before->span(), curve_after->span()};
  }
  const auto* slerp_before = std::get_if<SlerpBlendSection>(&before);
  const auto* slerp_after = std::get_if<SlerpBlendSection>(&after);
  if (slerp_before && slerp_after && continues(*slerp_before, *slerp_after)) {
    if (!moving(*slerp_after)) return std::nullopt;
    return JunctionSpeeds{slerp_before->span(), slerp_after->span()};
  }
  if (arc_before && arc_after && continues(*arc_before, *arc_after)) {
    if (!moving(*arc_after)) return std::nullopt;
    return JunctionSpeeds{1.0, 1.0};
  }
  const Eigen::Matrix<double, 6, 1> out = section_twist(before, 1.0).vector(), in = section_twist(after, 0.0).vector();
  const double out_size = out.norm(), in_size = in.norm();
  if (!(out_size > 0.0) || !(in_size > 0.0)) return std::nullopt;
  if ((out * (1.0 / out_size) - in * (1.0 / in_size)).norm() > junction_direction_tolerance) return std::nullopt;
  return JunctionSpeeds{out_size, in_size};
}

// The sections of the path as planned — each a section of the path or a piece of one — as
// where they lie in the path's sections, with their bounds and their lengths as planned. Kept as
// parallel arrays: the sources move on into the sampled path without being copied, and no piece
// is made a section of its own.
struct PlannedSections {
  std::vector<SectionSource> sources;
  std::vector<SectionBounds> bounds;
  std::vector<double> lengths;

  std::size_t size() const noexcept { return sources.size(); }
  void reserve(std::size_t n) {
    sources.reserve(n);
    bounds.reserve(n);
    lengths.reserve(n);
  }
  void push_back(const SectionSource& source, const SectionBounds& b) {
    sources.push_back(source);
    bounds.push_back(b);
    lengths.push_back(b.length);
  }
};

// A curved section (a SPLINE piece or a blend) as planned: cut where, for this set, the fastest
// object's speed or the curvature rule's speed varies along it (doc/planning.md §9, eq. 33). Each
// part's bound is its exact peak to 0.1 % however far the velocity turns within it
// (doc/section-length.md eqs. 25–27); a part's pieces tell how far its speed (the least speed
// sampled against the peak) and its acceleration bound vary. A part is cut into as many equal parts
// as that variation asks for: 0.4 % of speed where the limit v_sys binds (the cruise), one step
// of the staircase (10 %) where the curvature rule binds (doc/planning.md eq. 11); at most 4096
// parts a section.
template <class Curve>
void append_curve_cut(const Curve& curve, std::size_t source, const GroupFactors& factors, double minimum,
                      double rotation_scale, double speed_cap, double acceleration, PlannedSections& out) {
  constexpr double cruise_ratio_loss = 0.004, curvature_ratio_loss = 0.1;
  constexpr std::size_t max_parts = 4096;
  constexpr double max_split = 64.0;
  // How many equal parts the part [t0, t1] with refined bounds r asks to be cut into.
  const auto parts_wanted = [&](double t0, double t1, const RefinedBounds& r) {
    const SectionBounds& b = r.bounds;
    // The floor every part is lengthened to (per unit of its τ): a part at the floor runs at
    // one speed whatever its fastest object does.
    const double floor = std::max(minimum * (t1 - t0), b.omega * rotation_scale);
    if (!(b.length > floor)) return 1.0;
    double loss;
    const double v_lim = b.acceleration > 0.0 ? b.length * std::sqrt(acceleration / b.acceleration) : speed_cap;
    if (v_lim < speed_cap) {
      // v_lim = L √(a / A) (doc/planning.md eq. 11) binds: the fastest object runs at V √(a / A), lowered by
      // the part's largest A from what its gentlest piece would allow (at most the cap).
      const double best = r.least_acceleration > 0.0
                              ? std::min(speed_cap, b.length * std::sqrt(acceleration / r.least_acceleration))
                              : speed_cap;
      loss = (1.0 - v_lim / best) / curvature_ratio_loss;
    } else {
      loss = (b.length - std::max(r.least_speed, floor)) / b.length / cruise_ratio_loss;
    }
    return std::min(max_split, std::ceil(loss));
  };
  // The weighted speed at τ and the refined bounds of the part [t0, t1] whose ends have the
  // speeds w0, w1. A cubic curve's parts are bounded from the exact speeds at the ends of their
  // pieces (doc/section-length.md eq. 25): parts that meet share the speed where they meet. A
  // blend's parts from the middles of theirs.
  constexpr bool from_ends = std::is_same_v<Curve, CurveSection>;
  const auto speed = [&](double t) {
    if constexpr (from_ends) return curve.weighted_speed(factors, t);
    (void)t;
    return 0.0;
  };
  // Where the curvature rule (doc/planning.md eq. 11) sets the part's speed, its acceleration
  // bound is refined to 1 % as well: its pieces' bounds then tell how it varies (eq. 33).
  constexpr double acceleration_precision = 0.01;
  const auto measure = [&](double t0, double t1, double w0, double w1) {
    if constexpr (from_ends) {
      RefinedBounds r = curve.refined_part(factors, t0, t1, w0, w1);
      const SectionBounds& b = r.bounds;
      if (b.acceleration > 0.0 && b.length * std::sqrt(acceleration / b.acceleration) < speed_cap)
        r = curve.refined_part(factors, t0, t1, w0, w1, acceleration_precision);
      return r;
    }
    (void)w0, (void)w1;
    Curve part = curve;
    part.v0 = detail::cut_parameter(curve, t0);
    part.v1 = detail::cut_parameter(curve, t1);
    return part.refined(factors);
  };
  std::size_t count = 1;  // parts emitted or promised
  const auto cut = [&](const auto& self, double t0, double t1, const RefinedBounds& r, double w0, double w1) -> void {
    const double parts = parts_wanted(t0, t1, r);
    if (!(parts > 1.0) || count + static_cast<std::size_t>(parts) - 1 > max_parts) {
      out.push_back({source, t0, t1}, r.bounds);
      return;
    }
    count += static_cast<std::size_t>(parts) - 1;
    double a = t0, wa = w0;
    for (double i = 0; i < parts; ++i) {
      const bool last = i + 1.0 >= parts;
      const double b = last ? t1 : t0 + (t1 - t0) * (i + 1.0) / parts;
      const double wb = last ? w1 : speed(b);
      self(self, a, b, measure(a, b, wa, wb), wa, wb);
      a = b;
      wa = wb;
    }
  };
  const double w0 = speed(0.0), w1 = speed(1.0);
  cut(cut, 0.0, 1.0, measure(0.0, 1.0, w0, w1), w0, w1);
}

// Appends `section` to `out`; a decoupled LIN cut into pieces until the fastest object's speed
// varies by at most 0.4 % within each (doc/planning.md §9). The range of that speed over a part
// is exact (lin_speed_range.hpp, doc/planning.md eqs. 27–31), so a LIN is cut only where its speed does vary, as
// finely as it varies: a part whose range is too wide is cut into as many equal parts as its
// relative width asks for at 0.4 % each, and those are checked again (at most 4096 pieces per
// section; a piece's length is its exact peak, so a coarser piece is only slower, never unsafe).
void append_cut(const Section& section, std::size_t source, GroupFactors& factors, double rotation_scale,
                double minimum, double speed_cap, double acceleration, PlannedSections& out) {
  // 0.4 %: the cruise keeps ≥ 99.5 %, and neighbouring pieces stay within the junction rule's
  // 1 % (doc/planning.md eq. 34) without lengthening.
  constexpr double cruise_ratio_loss = 0.004;
  constexpr std::size_t max_pieces = 4096;
  constexpr double max_split = 64.0;
  // Curves (SPLINE pieces, blends) are cut by their own rule (append_curve_cut) and decoupled
  // LINs here. Along a screw every point keeps its speed; arcs are cut where they are made, to
  // their `tolerance` (CIRC).
  if (const auto* curve = std::get_if<CurveSection>(&section)) {
    factors.use_pivot(curve->pivot);
    return append_curve_cut(*curve, source, factors, minimum, rotation_scale, speed_cap, acceleration, out);
  }
  if (const auto* blend = std::get_if<SlerpBlendSection>(&section)) {
    factors.use_pivot(blend->pivot);
    return append_curve_cut(*blend, source, factors, minimum, rotation_scale, speed_cap, acceleration, out);
  }
  const SectionBounds whole = detail::section_bounds(section, factors);
  const auto* lin = std::get_if<LinSection>(&section);
  // A minimum length at least the section's own runs the whole section at one speed: its
  // fastest object is not what binds. Nor where the curvature rule (doc/planning.md eq. 11) holds the speed
  // below the limit (v_lim = L √(a / A) is the same for every piece): there is no cruise at
  // the limit to keep. Nor where the rotational limit (doc/planning.md eq. 36) makes the length.
  const bool curvature_binds =
      whole.acceleration > 0.0 && whole.length * std::sqrt(acceleration / whole.acceleration) < speed_cap;
  const double floor = std::max(minimum, whole.omega * rotation_scale);  // per unit τ of the section
  if (!lin || lin->interpolation != Interpolation::decoupled || floor >= whole.length || curvature_binds) {
    out.push_back({source, 0.0, 1.0}, whole);
    return;
  }
  const detail::DecoupledSpeeds speeds(*lin, factors);
  // The relative width of a part's speed range, with the floor every piece is lengthened to.
  const auto variation = [&](const detail::SpeedRange& r) {
    const double high = std::max(r.high, floor);
    return high > 0.0 ? (high - std::max(r.low, floor)) / high : 0.0;
  };
  const detail::SpeedRange all = speeds.range(0.0, 1.0);
  if (variation(all) <= cruise_ratio_loss) {
    out.push_back({source, 0.0, 1.0}, whole);
    return;
  }
  const MetricSetd& set = factors.set();
  const double travel = ((lin->end * lin->pivot) - (lin->start * lin->pivot)).norm();
  const Eigen::Vector3d pivot_start = lin->start * lin->pivot, pivot_travel = lin->end * lin->pivot - pivot_start;
  std::size_t count = 1;  // pieces emitted or promised
  const std::size_t expected =
      static_cast<std::size_t>(std::min(max_split, std::ceil(variation(all) / cruise_ratio_loss)));
  if (out.size() + expected > out.sources.capacity())
    out.reserve(std::max(out.size() + 2 * expected, 2 * out.sources.capacity()));
  // A piece [t0, t1]: its exact peak as length, and the acceleration bound of the part (the
  // pivot's and the rotation's rates scale with the part's share h).
  const auto emit = [&](double t0, double t1, const detail::SpeedRange& r) {
    const double h = t1 - t0;
    const MotionBounds motion{travel * h, 0.0, whole.omega * h, 0.0};
    const Eigen::Vector3d pivot_middle = pivot_start + (0.5 * (t0 + t1)) * pivot_travel;
    double rate = 0.0;
    for (std::size_t i = 0; i < set.groups().size(); ++i)
      rate = std::max(rate, detail::group_acceleration_bound(set.groups()[i], factors.reach(i), pivot_middle, motion));
    out.push_back({source, t0, t1}, {h * r.high, rate, motion.omega, 0.0});
  };
  // Depth first, in order of τ: a part is emitted when its range is narrow enough (or the piece
  // budget is spent), else cut into equal parts.
  const auto cut = [&](const auto& self, double t0, double t1, const detail::SpeedRange& r) -> void {
    const double v = variation(r);
    const double parts = std::min(max_split, std::ceil(v / cruise_ratio_loss));
    if (v <= cruise_ratio_loss || count + static_cast<std::size_t>(parts) - 1 > max_pieces) return emit(t0, t1, r);
    count += static_cast<std::size_t>(parts) - 1;
    for (double i = 0; i < parts; ++i) {
      const double a = t0 + (t1 - t0) * i / parts, b = i + 1.0 >= parts ? t1 : t0 + (t1 - t0) * (i + 1.0) / parts;
      self(self, a, b, speeds.range(a, b));
    }
  };
  cut(cut, 0.0, 1.0, all);
}

// The velocity-limit staircase over planned sections [first, last) (doc/planning.md §4): the path
// curvature rule (doc/planning.md eq. 11) with each move's own acceleration, its rotational twin for the
// angular acceleration, each move's own velocity, rounded down to 10 % steps below v_sys; and
// each segment's acceleration: the move's own, lowered where the angular acceleration needs.
// Each span also keeps its ceiling, the level before a move's own velocity lowered it (what a
// speed override above 1 may reach).
std::vector<SpeedLimit> speed_limit_segments(const PlannedSections& planned, const std::vector<MoveLimits>& moves,
                                             std::size_t first, std::size_t last, const Limits& limits) {
  constexpr double step = 0.9;
  std::vector<SpeedLimit> segments;
  for (std::size_t k = first; k < last; ++k) {
    const SectionBounds& bounds = planned.bounds[k];
    const double length = planned.lengths[k];
    const MoveLimits& move = moves[planned.sources[k].section];
    const double a = move.acceleration ? std::min(*move.acceleration, limits.acceleration) : limits.acceleration;
    double v_lim = limits.velocity;
    if (bounds.acceleration > 0.0) v_lim = std::min(v_lim, length * std::sqrt(a / bounds.acceleration));
    if (limits.angular_acceleration && bounds.omega_dot > 0.0)
      v_lim = std::min(v_lim, length * std::sqrt(*limits.angular_acceleration / bounds.omega_dot));
    double level = limits.velocity;
    if (v_lim < limits.velocity)
      level = limits.velocity * std::pow(step, std::ceil(std::log(v_lim / limits.velocity) / std::log(step)));
    const double ceiling = level;
    if (move.velocity) level = std::min(level, *move.velocity);
    // The angular acceleration from s̈, |ω_τ| |s̈| / L ≤ α_max, caps the section's path
    // acceleration (doc/planning.md eq. 37).
    double own_acceleration = move.acceleration ? a : 0.0;
    if (limits.angular_acceleration && bounds.omega > 0.0) {
      const double angular_cap = *limits.angular_acceleration * length / bounds.omega;
      if (angular_cap < a) own_acceleration = angular_cap;
    }
    if (!segments.empty() && segments.back().limit == level && segments.back().acceleration == own_acceleration &&
        segments.back().top() == ceiling) {
      segments.back().length += length;
    } else {
      segments.push_back({0.0, length, level, own_acceleration, ceiling > level ? ceiling : 0.0});
    }
  }
  return segments;
}

std::string corner_reason(const std::vector<CornerStop>& corner_stops, std::size_t section, double corner_tolerance) {
  for (const CornerStop& c : corner_stops)
    if (c.section == section) return c.reason;
  if (corner_tolerance > 0.0) return "the twist direction changes inside a move";
  return "corner: the twist direction changes (corner_tolerance = 0 keeps the exact stop)";
}


// The options that cannot be combined, and the state of a moving start.
void require_compatible(const PlanOptions& options) {
  require(options.corner_tolerance == 0.0 || options.min_section_lengths.empty(), "corner_tolerance",
          options.corner_tolerance,
          "cannot be combined with min_section_lengths (given per section of the unblended path): give a "
          "joint_metric, which is evaluated on the blended path");
  require(!options.joint_metric || options.min_section_lengths.empty(), "min_section_lengths size",
          static_cast<unsigned long>(options.min_section_lengths.size()),
          "must be 0 with a joint_metric (it gives the minimum lengths)");
  require(std::isfinite(options.start_velocity) && options.start_velocity >= 0.0, "start_velocity",
          options.start_velocity, "must be finite and ≥ 0 (m/s)");
  require(std::isfinite(options.start_acceleration), "start_acceleration", options.start_acceleration,
          "must be finite (m/s²)");
}

// The minimum length of every section of the path as planned (doc/planning.md eq. 6): the joint
// metric's, evaluated on that path, or the lengths given; none when neither is.
std::vector<double> minimum_lengths(const Path& path, const Limits& limits, const PlanOptions& options) {
  const std::size_t n = path.sections().size();
  // A joint metric is per section of the path as planned, so it is evaluated after blending.
  std::vector<double> minimum = options.joint_metric ? options.joint_metric(path, limits) : options.min_section_lengths;
  const std::string minimum_name = options.joint_metric ? "joint_metric(path, limits)" : "min_section_lengths";
  if (!(minimum.empty() || minimum.size() == n)) {
    require(false, minimum_name + " size", static_cast<unsigned long>(minimum.size()),
            "must be 0 or the path's section count " + std::to_string(n));
  }
  for (std::size_t k = 0; k < minimum.size(); ++k) {
    if (!(std::isfinite(minimum[k]) && minimum[k] >= 0.0))
      require(false, minimum_name + "[" + std::to_string(k) + "]", minimum[k], "must be finite and not negative");
  }
  return minimum;
}

// The sections as planned: a length and an acceleration bound each, cut where the fastest point's
// speed varies, lengthened for the rotational limit and the minimum lengths.
PlannedSections planned_sections(const Path& path, const MetricSetd& set, const Limits& limits,
                                 const std::vector<double>& minimum) {
  const std::vector<Section>& sections = path.sections();
  const std::size_t n = sections.size();
  // Group weights v_sys / v_g are part of the lengths: path speed ≤ v_sys keeps every group
  // under its own limit. Lengths and acceleration bounds come from one evaluation per section
  // (the same as Path::section_lengths and section_acceleration_bound give); sections whose
  // fastest point's speed varies are cut into pieces.
  GroupFactors factors(set, limits.velocity);
  const double rotation_scale = limits.angular_velocity ? limits.velocity / *limits.angular_velocity : 0.0;
  PlannedSections planned;
  planned.reserve(n);
  const std::vector<MoveLimits>& moves = path.section_limits();
  for (std::size_t k = 0; k < n; ++k) {
    const MoveLimits& move = moves[k];
    const double speed_cap = move.velocity ? std::min(*move.velocity, limits.velocity) : limits.velocity;
    const double a = move.acceleration ? std::min(*move.acceleration, limits.acceleration) : limits.acceleration;
    append_cut(sections[k], k, factors, rotation_scale, minimum.empty() ? 0.0 : minimum[k], speed_cap, a, planned);
  }
  std::vector<double>& lengths = planned.lengths;
  if (limits.angular_velocity) {
    // The rotational limit as one more term of the length (doc/planning.md eq. 36):
    // |ω| = |ω_τ| ṡ / L ≤ ω_max.
    for (std::size_t k = 0; k < planned.size(); ++k)
      lengths[k] = std::max(lengths[k], planned.bounds[k].omega * rotation_scale);
  }
  // A longer section is traversed more slowly (τ̇ = ṡ/L), so every point still moves at most at
  // ṡ·L_k/L ≤ ṡ: the DISP guarantee survives any lengthening (doc/planning.md eq. 6). A piece
  // of a section spans a share h of its τ and takes that share of its minimum.
  if (!minimum.empty()) {
    for (std::size_t k = 0; k < planned.size(); ++k) {
      const SectionSource& source = planned.sources[k];
      lengths[k] = std::max(lengths[k], (source.tau_end - source.tau_start) * minimum[source.section]);
    }
  }

  return planned;
}

// The junctions passed at speed (none where the twist turns), the lengths on either side raised
// until the speed per unit of s steps by less than 1 % there.
std::vector<std::optional<JunctionSpeeds>> junctions_at_speed(const std::vector<Section>& sections,
                                                              PlannedSections& planned) {
  std::vector<double>& lengths = planned.lengths;
  // Junctions that keep the twist's direction are passed at speed once the speed per unit of s
  // steps by less than 1 % there (doc/planning.md eq. 9): lengthening the faster side, forward then backward,
  // brings every such junction within 1 % (doc/planning.md eq. 34); junctions already within it
  // are left as they are.
  const std::size_t count = planned.size();
  std::vector<std::optional<JunctionSpeeds>> junctions(count > 0 ? count - 1 : 0);
  for (std::size_t k = 0; k + 1 < count; ++k) {
    const SectionSource& before = planned.sources[k];
    const SectionSource& after = planned.sources[k + 1];
    // Two pieces of one section: the same motion, each piece's twist per unit of its τ the
    // section's own times the share of τ it spans.
    if (before.section == after.section && before.tau_end == after.tau_start) {
      junctions[k] = JunctionSpeeds{before.tau_end - before.tau_start, after.tau_end - after.tau_start};
      continue;
    }
    junctions[k] =
        direction_continuous(detail::planned_part(sections[before.section], before.tau_start, before.tau_end),
                             detail::planned_part(sections[after.section], after.tau_start, after.tau_end));
  }
  constexpr double step_ratio = 0.99;
  for (std::size_t k = 0; k + 1 < count; ++k) {
    if (!junctions[k]) continue;
    const double out = junctions[k]->out / lengths[k];
    lengths[k + 1] = std::max(lengths[k + 1], junctions[k]->in * step_ratio / out);
  }
  for (std::size_t k = count - 1; k-- > 0;) {
    if (!junctions[k]) continue;
    const double in = junctions[k]->in / lengths[k + 1];
    lengths[k] = std::max(lengths[k], junctions[k]->out * step_ratio / in);
  }
  return junctions;
}

// The time law: rest-to-rest runs between the corners the motion stops at, each run under the
// law of its velocity-limit curve. The trajectory's sections are the planned parts of `path`'s
// sections (SampledPath keeps each section once, however finely it was cut).
Trajectory timed_runs(const Path& path, PlannedSections& planned,
                      const std::vector<std::optional<JunctionSpeeds>>& junctions, const Limits& limits,
                      ProfileKind profile, const std::vector<CornerStop>& corner_stops, double corner_tolerance) {
  const std::vector<MoveLimits>& moves = path.section_limits();
  const std::vector<double>& lengths = planned.lengths;
  const std::size_t count = planned.size();
  // The sources and lengths stay for the staircase and the stops.
  SampledPath sampled(path.sections(), planned.sources, lengths);

  // Rest-to-rest runs between corners; within a run the velocity-limit curve.
  const std::optional<double> jerk = profile == ProfileKind::scurve ? limits.jerk : std::nullopt;
  TimeLaw law;
  std::vector<SpeedLimit> speed_limits;
  std::vector<double> rests{0.0};
  std::vector<Stop> stops;
  std::size_t first = 0;
  for (std::size_t k = 0; k < count; ++k) {
    if (k + 1 < count && junctions[k]) continue;
    const std::vector<SpeedLimit> spans = speed_limit_segments(planned, moves, first, k + 1, limits);
    double start_s = sampled.section_start(first);
    double span_s = start_s;
    // The law's staircase: spans of the same limit and acceleration are one step (whatever their
    // ceilings).
    std::vector<LimitedSegment> segments;
    for (SpeedLimit span : spans) {
      span.start_s = span_s;
      span_s += span.length;
      speed_limits.push_back(span);
      if (!segments.empty() && segments.back().limit == span.limit && segments.back().acceleration == span.acceleration)
        segments.back().length += span.length;
      else
        segments.push_back({span.length, span.limit, span.acceleration});
    }
    for (const Profile& piece : velocity_limited_law(segments, limits.acceleration, jerk)) {
      law.append(piece, start_s);
      start_s += piece.distance();
    }
    law.end_run();
    const double rest = k + 1 == count ? sampled.section_start(k) + lengths[k] : sampled.section_start(k + 1);
    rests.push_back(rest);
    if (k + 1 < count)
      stops.push_back({rest, corner_reason(corner_stops, planned.sources[k].section, corner_tolerance)});
    first = k + 1;
  }
  // The sources are the sampled path's parts unless it keeps runs of one curve as one section.
  std::vector<SectionSource> sources;
  if (sampled.whole_sections().size() != path.sections().size()) sources = std::move(planned.sources);
  return Trajectory(std::move(sampled), std::move(law), std::move(speed_limits), std::move(rests), std::move(stops),
                    std::move(sources), TimeLawLimits{limits.acceleration, jerk});
}

// A moving start: the first run's law from that state (doc/events.md §3).
Trajectory moving_start(const Trajectory& from_rest, const PlanOptions& options) {
  const double v_start = from_rest.speed_limits().front().limit;
  require(options.start_velocity <= v_start, "start_velocity", options.start_velocity,
          "must be at most the velocity limit at the start of the path, " + detail::number(v_start) + " m/s");
  // The messages name starting_from's arguments; here they are the options.
  try {
    return from_rest.starting_from(options.start_velocity, options.start_acceleration);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument("start_" + std::string(e.what()));
  }
}

}  // namespace


void Limits::validate(ProfileKind kind) const {
  require_limit(velocity, "velocity");
  require_limit(acceleration, "acceleration");
  if (kind == ProfileKind::scurve) {
    if (!jerk)
      throw std::invalid_argument("jerk is missing: the S-curve profile needs a jerk limit (or use the trapezoid)");
    require_limit(*jerk, "jerk");
  } else if (jerk) {
    throw std::invalid_argument(describe("jerk", *jerk, "is not used by the trapezoidal profile; leave it unset"));
  }
  if (angular_velocity) require_limit(*angular_velocity, "angular_velocity");
  if (angular_acceleration) require_limit(*angular_acceleration, "angular_acceleration");
}

std::optional<Path> continuous_path(const Path& path, const PlanOptions& options, std::vector<CornerStop>* stops) {
  require(std::isfinite(options.corner_tolerance) && options.corner_tolerance >= 0.0, "corner_tolerance",
          options.corner_tolerance, "must be a finite distance ≥ 0 (m)");
  if (options.corner_tolerance == 0.0) return std::nullopt;
  return path.blended(options.corner_tolerance, stops, options.blend_tolerance);
}

Trajectory plan(const Path& path, const MetricSetd& set, const Limits& limits, ProfileKind profile) {
  return plan(path, set, limits, profile, PlanOptions{});
}

Trajectory plan(const Path& given_path, const MetricSetd& set, const Limits& limits, ProfileKind profile,
                const PlanOptions& options) {
  limits.validate(profile);
  // With a rotational limit every rotation has a length of its own (doc/planning.md eq. 36):
  // a set that does not see some rotation (one tool-centre point, as Pilz's TCP speed and
  // rotation limits) is enough then, if it is not empty.
  if (!limits.angular_velocity || set.empty()) set.require_well_formed();
  // Continuous-path mode: the corners blended first (doc/planning.md §10).
  std::vector<CornerStop> corner_stops;
  const std::optional<Path> blended = continuous_path(given_path, options, &corner_stops);
  require_compatible(options);
  const Path& path = blended ? *blended : given_path;
  PlannedSections planned = planned_sections(path, set, limits, minimum_lengths(path, limits, options));
  const std::vector<std::optional<JunctionSpeeds>> junctions = junctions_at_speed(path.sections(), planned);
  Trajectory from_rest = timed_runs(path, planned, junctions, limits, profile, corner_stops, options.corner_tolerance);
  if (options.start_velocity == 0.0 && options.start_acceleration == 0.0) return from_rest;
  return moving_start(from_rest, options);
}

}  // namespace dispkin
