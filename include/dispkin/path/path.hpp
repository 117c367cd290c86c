//! Pose paths: LIN and CIRC moves cut into sections whose DISP length bounds every point's
//! speed (doc/disp-metric.md eqs. 13–14, doc/section-length.md; the interpolations follow the
//! Mamezou trajectory article, Ishii, "Algorithm 2 for Robot Manipulator Control").
//!
//! A path is geometry only. It is a chain of sections; section k moves from its start to its
//! end pose as τ runs over [0, 1], and `section_length` gives L_k with: along the section, no
//! point of the metric set moves faster than L_k per unit τ. The planner maps the cumulative
//! DISP arc length s onto (k, τ = (s − s_k)/L_k).
#pragma once

#include <cmath>
#include <functional>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "dispkin/path/curve_section.hpp"
#include "dispkin/path/slerp_blend_section.hpp"
#include "dispkin/disp.hpp"
#include "dispkin/error.hpp"
#include "dispkin/metric_set.hpp"
#include "dispkin/numbers.hpp"
#include "dispkin/pose.hpp"

namespace dispkin {

namespace detail {
struct BlendPlan;
}  // namespace detail

//! A straight section: the decoupled LIN (pivot on a line, SLERP about one axis) or a screw.
struct LinSection {
  //! Its start and end poses.
  //!@{
  Posed start, end;
  //!@}
  Interpolation interpolation = Interpolation::decoupled;  //!< how it moves between them
  Eigen::Vector3d pivot = Eigen::Vector3d::Zero();         //!< body coordinates

  //! The pose at τ ∈ [0, 1].
  Posed pose(double tau) const noexcept { return interpolate(start, end, tau, interpolation, pivot); }

  //! Body twist per unit τ at τ.
  Twistd twist(double tau) const noexcept {
    if (interpolation == Interpolation::screw) return (start.inverse() * end).log();
    // Pivot velocity Δc and rotation θk: the body origin t = c − R p moves at Δc − θŵ × R p.
    const Eigen::Vector3d omega_body =
        quaternion_log(Eigen::Quaterniond(start.quaternion().conjugate() * end.quaternion()));
    const Posed at = pose(tau);
    const Eigen::Vector3d delta_c = (end * pivot) - (start * pivot);
    return Twistd(at.quaternion().conjugate() * delta_c - omega_body.cross(pivot), omega_body);
  }

  //! Exact (doc/section-length.md eq. 4 for screw, eqs. 5–11 for decoupled sections).
  double length(const MetricSetd& set, std::optional<double> system_velocity) const {
    return section_length(set, start, end, interpolation, pivot, system_velocity);
  }

  //! A bound of every object's acceleration per unit τ² (see CurveSection::acceleration_bound):
  //! the decoupled line has a constant pivot velocity and angular velocity; a screw's pivot
  //! turns about the screw axis (|c̈| = |ω × ċ|).
  double acceleration_bound(const MetricSetd& set) const;

  //! length() and acceleration_bound() together (see CurveSection::bounds).
  SectionBounds bounds(const GroupFactors& factors) const;
};

//! A circular section: the pivot turns by `angle` about the axis (center, normal) while the
//! orientation turns by `rotation_angle` about the fixed world axis `rotation_axis`.
struct ArcSection {
  Posed start;                                               //!< the pose at τ = 0
  Eigen::Vector3d center = Eigen::Vector3d::Zero();          //!< world
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();         //!< world, unit; the pivot turns about it
  double angle = 0.0;                                        //!< of the pivot about `normal`
  Eigen::Vector3d rotation_axis = Eigen::Vector3d::UnitZ();  //!< world, unit
  double rotation_angle = 0.0;                               //!< of the orientation about `rotation_axis` (rad)
  Eigen::Vector3d pivot = Eigen::Vector3d::Zero();           //!< body coordinates

  //! The pose at τ ∈ [0, 1].
  Posed pose(double tau) const noexcept {
    const Eigen::Vector3d c = center + detail::axis_turn(normal, tau * angle) * (start * pivot - center);
    const Eigen::Quaterniond q =
        (detail::axis_turn(rotation_axis, tau * rotation_angle) * start.quaternion()).normalized();
    return Posed::unchecked(q, c - q * pivot);
  }

  //! The pose at τ = 1.
  Posed end() const noexcept { return pose(1.0); }

  //! Body twist per unit τ at τ: pivot velocity φ n × (c − o), rotation θ ŵ.
  Twistd twist(double tau) const noexcept {
    const Posed at = pose(tau);
    const Eigen::Vector3d c = at * pivot;
    const Eigen::Vector3d pivot_velocity = angle * normal.cross(c - center);
    const Eigen::Vector3d omega_body = at.quaternion().conjugate() * (rotation_angle * rotation_axis);
    return Twistd(at.quaternion().conjugate() * pivot_velocity - omega_body.cross(pivot), omega_body);
  }

  //! An upper bound of the speed of every object per unit τ, conservative by at most
  //! (2 + θ) δ with δ = 2 φ ρ sin(φ/4) (φ = angle, ρ = radius of the pivot's circle, θ =
  //! rotation_angle). Reference: the decoupled section whose pivot moves with the constant
  //! velocity ċ(½) of the arc's middle. Along the arc ‖ċ(τ) − ċ(½)‖ ≤ δ, which bounds the
  //! difference of every relative point's velocity by δ; for an absolute point the pivot's
  //! position also differs by at most δ, adding θ δ through the rotation.
  double length(const MetricSetd& set, std::optional<double> system_velocity) const {
    set.require_well_formed();
    detail::require_system_velocity(system_velocity);
    require_translation(pivot, "pivot");
    GroupFactors factors(set, system_velocity);
    factors.use_pivot(pivot);
    return bounds(factors).length;
  }

  //! A bound of every object's acceleration per unit τ² (see CurveSection::acceleration_bound):
  //! the pivot moves on its circle (|c̈| = φ²ρ), the angular velocity is constant.
  double acceleration_bound(const MetricSetd& set) const;

  //! δ = 2 φ ρ sin(φ/4): how far the pivot velocity along the arc strays from its middle value.
  double deviation_bound() const noexcept { return deviation_bound((start * pivot - center).norm()); }

  //! The end pose of the reference (straight, constant-velocity) section.
  Posed reference_section_end() const noexcept {
    const Eigen::Vector3d c0 = start * pivot;
    const Eigen::Quaterniond q = end_orientation();
    return Posed::unchecked(q, c0 + middle_velocity(pivot_at_middle(c0)) - q * pivot);
  }

  //! length() and acceleration_bound() together (see CurveSection::bounds), sharing the
  //! pivot's positions: its middle gives both the reference velocity and the absolute
  //! objects' distances.
  SectionBounds bounds(const GroupFactors& factors) const {
    const MetricSetd& set = factors.set();
    const Eigen::Vector3d c0 = start * pivot;
    // The turns (and the sine of the deviation bound) are those of every section of the CIRC:
    // `factors` remembers them (the same values as pivot_at_middle and end_orientation give).
    const Eigen::Vector3d middle = center + factors.turn(normal, 0.5 * angle) * (c0 - center);
    // The reference section from its parts: its rotation is the arc's, θ ŵ seen from the start
    // (no logarithm needed while |θ| ≤ π, the range of the logarithm).
    const Eigen::Quaterniond q1 = (factors.turn(rotation_axis, rotation_angle) * start.quaternion()).normalized();
    const Eigen::Vector3d rotation =
        std::abs(rotation_angle) <= pi
            ? Eigen::Vector3d(rotation_angle * (start.quaternion().conjugate() * rotation_axis))
            : quaternion_log(Eigen::Quaterniond(start.quaternion().conjugate() * q1));
    const detail::DecoupledSection<double> reference(start.quaternion(), q1, c0, middle_velocity(middle), rotation,
                                                     pivot);
    const double radius = (c0 - center).norm();
    const double phi = std::abs(angle);
    const MotionBounds motion{phi * radius, phi * phi * radius, std::abs(rotation_angle), 0.0};
    double length = 0.0, acceleration = 0.0;
    for (std::size_t i = 0; i < set.groups().size(); ++i) {
      const auto& g = set.groups()[i];
      length = std::max(length, factors.weight(i) * detail::group_decoupled_length(g, reference));
      acceleration = std::max(acceleration, detail::group_acceleration_bound(g, factors.reach(i), middle, motion));
    }
    const double deviation =
        2.0 * std::abs(angle) * radius * factors.sine(std::abs(angle) / 4.0);  // deviation_bound(radius)
    return {length + (1.0 + std::abs(rotation_angle)) * deviation * factors.max_weight(), acceleration, motion.omega,
            0.0};
  }

 private:
  double deviation_bound(double radius) const noexcept {
    return 2.0 * std::abs(angle) * radius * std::sin(std::abs(angle) / 4.0);
  }
  // The pivot's world position at τ = ½, from its start c₀.
  Eigen::Vector3d pivot_at_middle(const Eigen::Vector3d& c0) const noexcept {
    return center + detail::axis_turn(normal, 0.5 * angle) * (c0 - center);
  }
  // The pivot's velocity per unit τ there, φ n × (c(½) − o): the reference section's.
  Eigen::Vector3d middle_velocity(const Eigen::Vector3d& middle) const noexcept {
    return angle * normal.cross(middle - center);
  }
  Eigen::Quaterniond end_orientation() const noexcept {
    return (detail::axis_turn(rotation_axis, rotation_angle) * start.quaternion()).normalized();
  }
};

//! A section of a path, of any kind.
using Section = std::variant<LinSection, ArcSection, CurveSection, SlerpBlendSection>;

//! The pose at τ of any section.
inline Posed section_pose(const Section& section, double tau) noexcept {
  return std::visit([tau](const auto& s) { return s.pose(tau); }, section);
}

//! The body twist per unit τ of any section at τ.
inline Twistd section_twist(const Section& section, double tau) noexcept {
  return std::visit([tau](const auto& s) { return s.twist(tau); }, section);
}

//! The start pose of any section.
inline Posed section_start(const Section& section) noexcept {
  return std::visit([](const auto& s) { return s.pose(0.0); }, section);
}
//! The end pose of any section.
inline Posed section_end(const Section& section) noexcept {
  return std::visit([](const auto& s) { return s.pose(1.0); }, section);
}

//! Throws std::invalid_argument naming `name` (e.g. "sections[3]") unless every number of the
//! section lies in dispkin's numeric range, as the moves that make sections ensure: poses as
//! Pose::from_stored takes them, points within ±1e12 m, axes and quaternions unit (to
//! Pose::stored_quaternion_tolerance()), angles finite and at most 2π a section (a CIRC is cut
//! into arcs of at most 2π, a LIN turns at most π), the curves' polynomial coefficients within
//! ±1e14 (differences of points within ±1e12, scaled by the few units of a Hermite or Bézier
//! form), and a curve's parameter part 0 ≤ v0 < v1 ≤ 1.
//! `name()` is called only to name what fails (a trajectory checks every section it is made of).
void require_valid(const Section& section, const std::function<std::string()>& name);

//! Throws std::invalid_argument naming `name` unless `start` is where `end` is: the chain of a
//! path (Path::then, Path::from_sections) and of a trajectory's sections. To 1e-9 m and
//! 1e-9 rad, and for translations far from the origin 64ε of their size besides: a section cut
//! at τ (section_part) starts at the pose its neighbour ends at as computed by another
//! formula, which rounds to a few ε of the coordinates.
void require_join(const Posed& end, const Posed& start, const std::function<std::string()>& name);

//! L of any section under the set (exact for LIN, a tight upper bound for arcs).
inline double section_length(const Section& section, const MetricSetd& set,
                             std::optional<double> system_velocity = std::nullopt) {
  return std::visit([&](const auto& s) { return s.length(set, system_velocity); }, section);
}

//! A bound of every object's acceleration per unit τ² of any section (unweighted by groups).
inline double section_acceleration_bound(const Section& section, const MetricSetd& set) {
  return std::visit([&](const auto& s) { return s.acceleration_bound(set); }, section);
}

//! The part τ ∈ [t0, t1] of a section, as a section of the same kind run over its own τ (the
//! same motion between the same poses).
Section section_part(const Section& section, double t0, double t1);

//! Geometry of a circle through three points (doc/section-length.md §4: circumcentre), with the arc
//! from the first to the last point passing through the middle one.
struct CircleThroughPoints {
  Eigen::Vector3d center;  //!< the circumcentre
  Eigen::Vector3d normal;  //!< unit; the arc runs counter-clockwise about it
  double radius;           //!< the circle's radius (m)
  double angle;            //!< of the arc from start to end through via, in (0, 2π)
};

//! Throws std::invalid_argument if two points coincide or the three are collinear (relative
//! tolerance 1e-9 of the triangle's sides).
CircleThroughPoints circle_through(const Eigen::Vector3d& start, const Eigen::Vector3d& via,
                                   const Eigen::Vector3d& end);

//! The speed and acceleration of one move (robot programs' per-motion $VEL/$ACC, G-code F):
//! each optional, and capped by the plan's Limits. The velocity bounds ṡ, i.e. the speed of
//! the fastest point of the metric set (groups: scaled like the system velocity).
struct MoveLimits {
  std::optional<double> velocity;      //!< m/s, > 0
  std::optional<double> acceleration;  //!< m/s², > 0

  //! The tighter of two limits, field by field (a blend between two moves keeps both).
  static MoveLimits tighter(const MoveLimits& a, const MoveLimits& b) noexcept;
  //! std::invalid_argument naming `argument`.velocity or .acceleration unless each given limit
  //! is inside dispkin's numeric range [1e-12, 1e12], as the plan's Limits are: a smaller one
  //! would make the move last longer than any duration the time laws represent.
  void validate(const std::string& argument) const;
  //! Whether both fields are equal (both unset, or the same value).
  bool operator==(const MoveLimits& other) const noexcept {
    return velocity == other.velocity && acceleration == other.acceleration;
  }
};

//! How a blend at a via point turns the orientation (Path::then with a blend, doc/planning.md §6).
enum class OrientationBlend {
  //! A cubic in the rotation vector whose end angular velocities are the neighbours' (doc/planning.md eq. 15);
  //! any neighbouring sections, the pivot on a cubic Hermite curve.
  rotation_vector,
  //! The Mamezou article's nested SLERP with the corner orientation as control point (doc/planning.md eq. 17),
  //! the pivot on the quadratic Bézier curve with the corner as control point; both neighbours
  //! must be decoupled LIN sections at the sub-points.
  nested_slerp,
};

//! The blend's name: "rotation_vector" or "nested_slerp".
inline const char* to_string(OrientationBlend kind) {
  return kind == OrientationBlend::nested_slerp ? "nested_slerp" : "rotation_vector";
}

//! "rotation_vector" or "nested_slerp"; anything else throws std::invalid_argument naming the
//! value (argument name `orientation_blend`).
inline OrientationBlend orientation_blend_from_string(const std::string& name) {
  if (name == "rotation_vector") return OrientationBlend::rotation_vector;
  if (name == "nested_slerp") return OrientationBlend::nested_slerp;
  throw std::invalid_argument(describe("orientation_blend", name, "must be \"rotation_vector\" or \"nested_slerp\""));
}

//! A junction where corner blending (Path::blended) leaves the path with a corner, and why.
struct CornerStop {
  std::size_t section;  //!< the corner lies at the end of this section of the blended path
  std::string reason;   //!< why the junction is not blended
};

//! A path: a chain of sections, each starting where the previous one ends.
class Path {
 public:
  //! A LIN move from a to b: one section. `pivot` (body coordinates) travels the straight
  //! line; `interpolation` "screw" gives the constant-twist variant instead.
  static Path lin(const Posed& a, const Posed& b, Interpolation interpolation = Interpolation::decoupled,
                  const Eigen::Vector3d& pivot = Eigen::Vector3d::Zero());

  //! A CIRC move: the pivot on the circular arc from a through via to b (arcs over 180° are
  //! fine), the orientation turning from a's to b's about one fixed axis, proportionally to the
  //! arc angle (the via pose's orientation is not used). Cut into equal arc sections, as many
  //! as needed for ArcSection::length to exceed the exact speed by at most `tolerance`
  //! relative to the pivot's own speed ((2 + θ) δ ≤ tolerance · φ ρ).
  static Path circ(const Posed& a, const Posed& via, const Posed& b,
                   const Eigen::Vector3d& pivot = Eigen::Vector3d::Zero(), double tolerance = 1e-3);

  //! A SPLINE move through the key poses (at least three, consecutive ones distinct): the
  //! pivot on the natural cubic spline (C², zero curvature at both ends) with knots spaced by
  //! the geometric size of each step (pivot chord + 0.1 m per radian), the orientation
  //! R_i · exp(φ(v)) with φ a cubic Hermite per step whose end slopes are matched through the
  //! right Jacobian, so the angular velocity is continuous (C¹) through every key; key slopes
  //! by the three-point rule, ends by the natural (zero second derivative) condition.
  //! Passes through every key pose exactly. Cut into sections as described at cut_curve.
  static Path spline(const std::vector<Posed>& poses, const Eigen::Vector3d& pivot = Eigen::Vector3d::Zero(),
                     double tolerance = 1e-3);

  //! Append `next`, which must start where this path ends (to 1e-9 m and 1e-9 rad).
  Path& then(const Path& next);

  //! Append `next` with the corner blended (the Mamezou article's boundary smoothing,
  //! doc/planning.md §6): the path leaves its last move at the sub-point `before` ahead of the
  //! corner and joins `next` at the sub-point `after` past it (both in geometric size: pivot travel
  //! + 0.1 m per radian of rotation, so a via point that only rotates blends too), along a cubic
  //! pose curve whose pivot velocity and angular velocity at both ends are those of the neighbours,
  //! scaled alike — the twist keeps its direction through both joins, so the planner does not stop
  //! there. The pivot stays within max(before, after) of the corner. Throws if a distance is not
  //! positive or exceeds half of its neighbouring move (two blends on one move must not overlap).
  //!
  //! With `orientation` = OrientationBlend::nested_slerp the blend is the Mamezou article's
  //! "Fitting Posture" instead (doc/planning.md §6.1): the orientation by nested SLERP from the
  //! sub-point's orientation q₁ through the corner's q_m (control point) to q₂, the pivot on
  //! the quadratic Bézier curve with the corner as control point, over one blend parameter; the
  //! twist at each join is twice the neighbouring LIN's own (doc/planning.md eq. 18), so the planner passes both
  //! joins. It needs the sub-points on decoupled LIN sections with one pivot — the last section of
  //! this path and the first of `next` — and throws std::invalid_argument naming
  //! `orientation_blend` or `next` otherwise.
  Path& then(const Path& next, double before, double after, double tolerance = 1e-3,
             OrientationBlend orientation = OrientationBlend::rotation_vector);
  //! then() with the same blend distance on both sides of the corner.
  Path& then(const Path& next, double blend) { return then(next, blend, blend); }

  //! The article's form of a blend: by a weight w ∈ (0, 0.5] of the neighbouring moves
  //! (before = w × the size of the last move, after = w × the size of next's first move; with
  //! nested_slerp, q₁ = Slerp(1 − w, q[m−1], q[m]) and q₂ = Slerp(w, q[m], q[m+1]) between
  //! LINs). Throws std::invalid_argument naming `weight` outside (0, 0.5], else as then().
  Path& then_weighted(const Path& next, double weight, OrientationBlend orientation = OrientationBlend::rotation_vector,
                      double tolerance = 1e-3);

  //! Gives every move of this path the speed and acceleration `limits` (see MoveLimits; a
  //! path built by lin/circ/spline is one move). then() keeps each move's limits; a blend
  //! between two moves runs under the tighter of both. Throws std::invalid_argument naming
  //! the field when a value is not finite and positive.
  Path& with_limits(const MoveLimits& limits);

  //! The path with every corner between two moves blended, continuous-path mode (as
  //! LinuxCNC's G64 P, KUKA's C_DIS; doc/planning.md §10): each junction whose twist direction
  //! changes gets the largest blend (then(next, ℓ, ℓ)) whose pivot stays within
  //! `corner_tolerance` (m) of the corner's two legs and that takes at most half of each
  //! neighbouring move. Junctions that cannot be blended — a reversal, a neighbour that stands
  //! still, a tolerance too small for the turn — stay corners and are listed in `stops` (if
  //! given) with the reason. Throws std::invalid_argument unless corner_tolerance is finite and
  //! positive.
  Path blended(double corner_tolerance, std::vector<CornerStop>* stops = nullptr, double tolerance = 1e-3) const;

  //! The path of `sections` (as sections() gives them) whose first and last moves had the
  //! geometric sizes given (what a later blend may take from them), with the move limits of
  //! every section and the first section of every move (empty: no limits, one move): a path
  //! made again from what storing it kept (a pickle), bit for bit. Throws
  //! std::invalid_argument if there is no section, a size is not finite and positive, a section
  //! does not start where the one before it ends (to 1e-9 m and 1e-9 rad), a limit is not
  //! finite and positive, or the move starts do not begin with 0 and grow up to the size.
  static Path from_sections(const std::vector<Section>& sections, double first_move_size, double last_move_size,
                            const std::vector<MoveLimits>& section_limits = {},
                            const std::vector<std::size_t>& move_starts = {});

  //! The sections, in order along the path.
  const std::vector<Section>& sections() const noexcept { return sections_; }
  //! The move limits of every section (parallel to sections()).
  const std::vector<MoveLimits>& section_limits() const noexcept { return limits_; }
  //! The index of the first section of every move, in order (starts with 0).
  const std::vector<std::size_t>& move_starts() const noexcept { return move_starts_; }
  //! The number of sections.
  std::size_t size() const noexcept { return sections_.size(); }
  //! Geometric sizes (pivot travel + 0.1 m per radian) of the first and the last move before
  //! any blend: a blend may take at most half of each.
  //!@{
  double first_move_size() const noexcept { return first_move_size_; }
  double last_move_size() const noexcept { return last_move_size_; }
  //!@}
  Posed start() const noexcept { return section_start(sections_.front()); }  //!< the first section's start pose
  Posed end() const noexcept { return section_end(sections_.back()); }       //!< the last section's end pose

  //! L_k of every section under the set.
  std::vector<double> section_lengths(const MetricSetd& set,
                                      std::optional<double> system_velocity = std::nullopt) const;

  //! Geometry only: the pose at u ∈ [0, 1], with u spread over the sections in proportion to
  //! their geometric size (pivot travel plus 0.1 m per radian of rotation). Clamped outside.
  Posed sample(double u) const noexcept;

 private:
  Path() = default;
  void append(Section section, const MoveLimits& limits = {});
  //! Builds a blend planned by Path::then / Path::blended (blend.cpp).
  void apply_blend(const detail::BlendPlan& plan, const Path& next, double tolerance);
  //! The sections [move_starts_[m], move_starts_[m + 1]) as a path of one move.
  Path move(std::size_t m) const;
  //! Throws unless `next` starts where this path ends (to 1e-9 m and 1e-9 rad).
  void require_joins(const Path& next) const;
  //! Append the cubic pose curve R₀ exp(φ(v)), c(v), v ∈ [0, 1], cut into equal-v sections so
  //! that within each the speed |ċ| + 0.1 m·|ω| varies by about `tolerance` of its largest
  //! value (doc/section-length.md eq. 29); each section's length is its exact peak to 0.1 % for
  //! any set (doc/section-length.md eqs. 25–27), and the planner cuts further where the set's own speed varies.
  void cut_curve(const Eigen::Quaterniond& q0, const Cubic3& position, const Cubic3& rotation,
                 const Eigen::Vector3d& pivot, double tolerance);
  //! Append a nested-SLERP blend (its section over v ∈ [0, 1]) cut into equal-v sections where
  //! its speed varies, as cut_curve.
  void cut_slerp_blend(const SlerpBlendSection& blend, double tolerance);

  std::vector<Section> sections_;
  // Geometric sizes of the first and of the last move, before any blend (blends may take at
  // most half of a move, so that two blends on one move never overlap).
  double first_move_size_ = 0.0, last_move_size_ = 0.0;
  std::vector<double> cumulative_;  // geometric size up to the end of each section
  std::vector<MoveLimits> limits_;  // per section
  std::vector<std::size_t> move_starts_{0};
};

//! A PTP move: the straight line between two joint vectors (joint space, no pose yet; the
//! kinematics plugins map it to poses).
class JointPath {
 public:
  //! From q_start to q_end (rad or m per joint). Throws std::invalid_argument naming the
  //! argument unless both are finite and of one non-zero size.
  JointPath(const Eigen::VectorXd& q_start, const Eigen::VectorXd& q_end);
  const Eigen::VectorXd& start() const noexcept { return q_start_; }  //!< q_a, the joints at u = 0
  const Eigen::VectorXd& end() const noexcept { return q_end_; }      //!< q_b, the joints at u = 1
  //! q(u) = q_a + u (q_b − q_a), u clamped to [0, 1].
  Eigen::VectorXd sample(double u) const;

 private:
  Eigen::VectorXd q_start_, q_end_;
};

}  // namespace dispkin
