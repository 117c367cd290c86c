// Blending at via points (doc/planning.md §6): the boundary smoothing of the Mamezou trajectory
// article (Ishii, "Algorithm 2 for Robot Manipulator Control", section "Smooth Position/Posture
// Trajectory Fitting Method"), with the orientation blended jointly with the position.
//
// The article fits a cubic F₀ between the sub-points Q₁, Q₂ with the neighbours' tangents, and
// blends the orientation separately by nested SLERP over its own zone (weight w ≈ 0.3). Under
// the DISP metric the planner sees one 6-D twist, and two separate zones would make its
// direction jump at each zone's ends (the planner would have to stop there). So here one zone
// serves both: the pivot follows the article's cubic, the orientation a cubic in the rotation
// vector whose end angular velocities are the neighbours', scaled by the same factors as the
// pivot tangents — at both joins the twist keeps its direction.
#include <algorithm>
#include <cmath>
#include <optional>
#include <sstream>
#include <string>

#include <Eigen/LU>

#include "dispkin/path/path.hpp"
#include "path_geometry.hpp"

namespace dispkin {
namespace {

using detail::metres_per_radian;


// World pivot velocity ċ = R (v_b + ω_b × p) of a body twist at `pose`.
Eigen::Vector3d pivot_velocity(const Posed& pose, const Twistd& body, const Eigen::Vector3d& pivot) {
  return pose.quaternion() * (body.linear + body.angular.cross(pivot));
}

Eigen::Vector3d pivot_of(const Section& section) {
  return std::visit([](const auto& s) { return s.pivot; }, section);
}

}  // namespace

namespace detail {

// A blend between the end of `path` and the start of `next` (Path::then with a blend), before
// it is built: where it leaves the path and joins `next`, and its pose curve.
struct BlendPlan {
  std::size_t k = 0;          // the section of `path` holding the sub-point KP₁ ...
  double tau_in = 0.0;        // ... at this τ
  Section incoming;           // its part up to KP₁
  std::size_t j = 0;          // the section of `next` holding KP₂ ...
  double tau_out = 0.0;       // ... at this τ
  Section outgoing;           // its part from KP₂
  Eigen::Quaterniond q0;      // orientation at KP₁
  Cubic3 position, rotation;  // pivot c(v) and rotation vector φ(v), v ∈ [0, 1]
  Eigen::Vector3d pivot;
  Eigen::Vector3d corner;                  // the pivot at the junction
  std::optional<SlerpBlendSection> slerp;  // with OrientationBlend::nested_slerp: the blend itself
};

}  // namespace detail

namespace {

// The blend of sizes `before` and `after` (geometric size) between the end of `sections`
// (cumulative sizes `cumulative`) and the start of `next`; false if a neighbour stands still
// at a sub-point (nothing to blend).
bool plan_blend(const std::vector<Section>& sections, const std::vector<double>& cumulative,
                const std::vector<Section>& next_sections, const std::vector<double>& next_cumulative, double before,
                double after, detail::BlendPlan& plan) {
  // Sub-point KP₁ at `before` ahead of the corner.
  const double total = cumulative.back();
  std::size_t k = sections.size() - 1;
  while (k > 0 && total - cumulative[k - 1] < before) --k;
  const double k_begin = k == 0 ? 0.0 : cumulative[k - 1];
  // Sub-points within 10⁻⁶ of a section's end snap to it: a sliver of a section would be left
  // otherwise, whose twist direction is lost to rounding.
  constexpr double snap = 1e-6;
  auto snapped = [](double tau) { return tau < snap ? 0.0 : tau > 1.0 - snap ? 1.0 : tau; };
  plan.k = k;
  plan.tau_in = snapped(std::clamp((total - before - k_begin) / (cumulative[k] - k_begin), 0.0, 1.0));
  plan.incoming = detail::section_part(sections[k], 0.0, plan.tau_in);

  // Sub-point KP₂ at `after` past the corner, in the first move of `next`.
  std::size_t j = 0;
  while (j + 1 < next_sections.size() && next_cumulative[j] < after) ++j;
  const double j_begin = j == 0 ? 0.0 : next_cumulative[j - 1];
  plan.j = j;
  plan.tau_out = snapped(std::clamp((after - j_begin) / (next_cumulative[j] - j_begin), 0.0, 1.0));
  plan.outgoing = detail::section_part(next_sections[j], plan.tau_out, 1.0);

  // The joins: poses and velocities of the neighbours there (per unit of the τ of the sections
  // holding them, so that a sub-point at a section's end still has its velocity; only their
  // directions matter, the scale is set below).
  const Eigen::Vector3d pivot = pivot_of(plan.incoming);
  const Posed a = section_pose(sections[k], plan.tau_in), b = section_pose(next_sections[j], plan.tau_out);
  const Twistd twist_a = section_twist(sections[k], plan.tau_in),
               twist_b = section_twist(next_sections[j], plan.tau_out);
  const Eigen::Vector3d c_dot_a = pivot_velocity(a, twist_a, pivot), c_dot_b = pivot_velocity(b, twist_b, pivot);
  const Eigen::Vector3d turn = quaternion_log(Eigen::Quaterniond(a.quaternion().conjugate() * b.quaternion()));

  // Tangent lengths equal to the geometric chord of the blend (the usual Hermite choice: no
  // loops, no flat spots), the same factor for the pivot and the rotation of each end.
  const double chord = ((b * pivot) - (a * pivot)).norm() + metres_per_radian * turn.norm();
  const double speed_a = c_dot_a.norm() + metres_per_radian * twist_a.angular.norm();
  const double speed_b = c_dot_b.norm() + metres_per_radian * twist_b.angular.norm();
  if (!(speed_a > 0.0 && speed_b > 0.0 && chord > 0.0)) return false;
  const double scale_a = chord / speed_a, scale_b = chord / speed_b;
  plan.position = Cubic3::hermite(a * pivot, scale_a * c_dot_a, b * pivot, scale_b * c_dot_b);
  const Eigen::Vector3d end_slope = right_jacobian(turn).partialPivLu().solve(scale_b * twist_b.angular);
  plan.rotation = Cubic3::hermite(Eigen::Vector3d::Zero(), scale_a * twist_a.angular, turn, end_slope);
  plan.q0 = a.quaternion();
  plan.pivot = pivot;
  plan.corner = section_end(sections.back()) * pivot;
  return true;
}

// The name of a section's kind, for messages.
const char* kind_name(const Section& section) {
  if (const auto* lin = std::get_if<LinSection>(&section))
    return lin->interpolation == Interpolation::screw ? "screw LIN" : "LIN";
  if (std::holds_alternative<ArcSection>(section)) return "CIRC";
  if (std::holds_alternative<CurveSection>(section)) return "curve (SPLINE or blend)";
  return "nested-SLERP blend";
}

const LinSection* decoupled_lin(const Section& section) {
  const auto* lin = std::get_if<LinSection>(&section);
  return lin && lin->interpolation == Interpolation::decoupled ? lin : nullptr;
}

// The nested-SLERP blend (doc/planning.md §6.1) of sizes `before` and `after` between the last
// section of `sections` and the first of `next_sections`, both decoupled LINs with one pivot:
// straight pivot lines and one-axis turns whose tangents point at the corner, so that the blend's
// end slopes 2(c_m − c₁), 2a and 2(c₂ − c_m), 2b are the neighbours' twists scaled alike (doc/planning.md eq. 18).
void plan_slerp_blend(const std::vector<Section>& sections, const std::vector<double>& cumulative,
                      const std::vector<Section>& next_sections, const std::vector<double>& next_cumulative,
                      double before, double after, detail::BlendPlan& plan) {
  const std::size_t k = sections.size() - 1;
  const LinSection* in = decoupled_lin(sections[k]);
  require(in != nullptr, "orientation_blend", std::string("nested_slerp"),
          std::string("needs the path to end in a decoupled LIN section at the via point; it ends in a ") +
              kind_name(sections[k]) + " section");
  const LinSection* out = decoupled_lin(next_sections.front());
  require(
      out != nullptr, "next", section_start(next_sections.front()).translation(),
      std::string("must start with a decoupled LIN section for orientation_blend = nested_slerp; it starts with a ") +
          kind_name(next_sections.front()) + " section");
  require((in->pivot - out->pivot).norm() <= 1e-12, "next", out->pivot,
          "has another pivot than the path: a nested_slerp blend moves one pivot on its Bézier curve");
  const double size_in = cumulative[k] - (k == 0 ? 0.0 : cumulative[k - 1]), size_out = next_cumulative.front();
  require(before <= size_in * (1.0 + 1e-12), "before", before,
          "exceeds the LIN section before the via point (" + std::to_string(size_in) +
              " m of geometric size): a nested_slerp blend starts within it");
  require(after <= size_out * (1.0 + 1e-12), "after", after,
          "exceeds the LIN section after the via point (" + std::to_string(size_out) +
              " m of geometric size): a nested_slerp blend ends within it");
  // Along a LIN the geometric size grows linearly in τ. Only slivers of the LINs left outside
  // the blend snap away (as in plan_blend); the blend itself never shrinks to nothing.
  constexpr double snap = 1e-6;
  double tau_in = std::clamp(1.0 - before / size_in, 0.0, 1.0), tau_out = std::clamp(after / size_out, 0.0, 1.0);
  if (tau_in < snap) tau_in = 0.0;
  if (tau_out > 1.0 - snap) tau_out = 1.0;
  plan.k = k;
  plan.tau_in = tau_in;
  plan.incoming = detail::section_part(sections[k], 0.0, tau_in);
  plan.j = 0;
  plan.tau_out = tau_out;
  plan.outgoing = detail::section_part(next_sections.front(), tau_out, 1.0);

  // q₁, c₁ at the first sub-point; q_m, c_m at the corner; q₂, c₂ at the second (doc/planning.md eq. 17).
  const Posed first = in->pose(tau_in), corner = in->end, second = out->pose(tau_out);
  const Eigen::Vector3d& p = in->pivot;
  const Eigen::Vector3d c1 = first * p, cm = corner * p, c2 = second * p;
  SlerpBlendSection blend;
  blend.q_start = first.quaternion();
  blend.a = quaternion_log(Eigen::Quaterniond(first.quaternion().conjugate() * corner.quaternion()));
  blend.b = quaternion_log(Eigen::Quaterniond(corner.quaternion().conjugate() * second.quaternion()));
  // The quadratic Bézier (1 − v)² c₁ + 2v(1 − v) c_m + v² c₂ in powers of v.
  blend.position.a[0] = c1;
  blend.position.a[1] = 2.0 * (cm - c1);
  blend.position.a[2] = c1 - 2.0 * cm + c2;
  blend.position.a[3].setZero();
  blend.pivot = p;
  plan.q0 = first.quaternion();
  plan.pivot = p;
  plan.corner = cm;
  plan.slerp = blend;
}

// The segment [p, q], ready for distances to many points.
struct Segment {
  Eigen::Vector3d p, d;
  double size2;
  Segment(const Eigen::Vector3d& from, const Eigen::Vector3d& to) : p(from), d(to - from), size2(d.squaredNorm()) {}
  double distance(const Eigen::Vector3d& x) const {
    const double t = size2 > 0.0 ? std::clamp((x - p).dot(d) / size2, 0.0, 1.0) : 0.0;
    return (x - (p + t * d)).norm();
  }
};

// How far the blend's pivot strays from the corner's two legs [KP₁, corner] ∪ [corner, KP₂]
// (the programmed path where the neighbours are straight), on a fine grid of the curve.
double corner_deviation(const detail::BlendPlan& plan) {
  const Segment leg_in(plan.position.value(0.0), plan.corner), leg_out(plan.corner, plan.position.value(1.0));
  double worst = 0.0;
  constexpr int samples = 128;
  for (int i = 1; i < samples; ++i) {
    const Eigen::Vector3d x = plan.position.value(double(i) / samples);
    worst = std::max(worst, std::min(leg_in.distance(x), leg_out.distance(x)));
  }
  return worst;
}

// Whether a blend between the end of `last` and the start of `first` deviates from the corner
// in proportion to its size: both are decoupled LINs (straight pivot lines, the legs
// themselves) turning about one world axis (or not turning), so that the turn between the
// sub-points grows linearly too. The blend of size ℓ is then the blend of size 1 scaled by ℓ
// about the corner — sub-points, tangents and turn alike.
bool proportional_corner(const Section& last, const Section& first) {
  const auto* in = std::get_if<LinSection>(&last);
  const auto* out = std::get_if<LinSection>(&first);
  if (!(in && out && in->interpolation == Interpolation::decoupled && out->interpolation == Interpolation::decoupled))
    return false;
  const Eigen::Vector3d turn_in = in->start.quaternion() * in->twist(0.0).angular;
  const Eigen::Vector3d turn_out = out->start.quaternion() * out->twist(0.0).angular;
  return turn_in.cross(turn_out).norm() <= 1e-12 * turn_in.norm() * turn_out.norm();
}

// The unit direction of a body twist in geometric size (pivot velocity and 0.1 m per radian),
// world frame: the direction a junction test compares.
Eigen::Matrix<double, 6, 1> geometric_direction(const Section& section, double tau) {
  const Posed at = section_pose(section, tau);
  const Twistd twist = section_twist(section, tau);
  Eigen::Matrix<double, 6, 1> d;
  d << pivot_velocity(at, twist, pivot_of(section)), metres_per_radian * (at.quaternion() * twist.angular);
  const double size = d.norm();
  return size > 0.0 ? Eigen::Matrix<double, 6, 1>(d / size) : Eigen::Matrix<double, 6, 1>::Zero();
}

std::string degrees(double radians) {
  std::ostringstream out;
  out.precision(3);
  out << radians * 180.0 / pi << "°";
  return out.str();
}

}  // namespace

Path& Path::then_weighted(const Path& next, double weight, OrientationBlend orientation, double tolerance) {
  require(std::isfinite(weight) && weight > 0.0 && weight <= 0.5, "weight", weight,
          "must be in (0, 0.5]: the share of each neighbouring move the blend takes");
  return then(next, weight * last_move_size_, weight * next.first_move_size_, tolerance, orientation);
}

Path& Path::then(const Path& next, double before, double after, double tolerance, OrientationBlend orientation) {
  // A closed path blended into itself: apply_blend cuts this path before it reads `next`.
  if (&next == this) return then(Path(next), before, after, tolerance, orientation);
  require(std::isfinite(before) && before > 0.0, "before", before, "must be a positive distance (m)");
  require(std::isfinite(after) && after > 0.0, "after", after, "must be a positive distance (m)");
  require(std::isfinite(tolerance) && tolerance > 0.0 && tolerance <= 0.1, "tolerance", tolerance,
          "must be in (0, 0.1]");
  require_joins(next);
  require(before <= 0.5 * last_move_size_ * (1.0 + 1e-12), "before", before,
          "exceeds half of the move before the via point (" + std::to_string(0.5 * last_move_size_) +
              " m of geometric size): shrink the blend");
  require(after <= 0.5 * next.first_move_size_ * (1.0 + 1e-12), "after", after,
          "exceeds half of the move after the via point (" + std::to_string(0.5 * next.first_move_size_) +
              " m of geometric size): shrink the blend");
  require(orientation == OrientationBlend::rotation_vector || orientation == OrientationBlend::nested_slerp,
          "orientation_blend", static_cast<long>(orientation), "must be rotation_vector or nested_slerp");
  detail::BlendPlan plan;
  if (orientation == OrientationBlend::nested_slerp) {
    plan_slerp_blend(sections_, cumulative_, next.sections_, next.cumulative_, before, after, plan);
  } else {
    require(plan_blend(sections_, cumulative_, next.sections_, next.cumulative_, before, after, plan), "blend", before,
            "meets a neighbour where it stands still: nothing to blend");
  }
  apply_blend(plan, next, tolerance);
  return *this;
}

void Path::apply_blend(const detail::BlendPlan& plan, const Path& next, double tolerance) {
  // Cut the section holding KP₁ and drop the rest; the blend runs under the tighter limits of
  // its two neighbours.
  const MoveLimits incoming_limits = limits_[plan.k];
  const MoveLimits blend_limits = MoveLimits::tighter(incoming_limits, next.limits_[plan.j]);
  sections_.resize(plan.k);
  cumulative_.resize(plan.k);
  limits_.resize(plan.k);
  if (plan.tau_in > 0.0) append(plan.incoming, incoming_limits);
  const std::size_t blend_first = sections_.size();
  if (plan.slerp) {
    cut_slerp_blend(*plan.slerp, tolerance);
  } else {
    cut_curve(plan.q0, plan.position, plan.rotation, plan.pivot, tolerance);
  }
  for (std::size_t i = blend_first; i < sections_.size(); ++i) limits_[i] = blend_limits;

  // `next` from KP₂ on; its moves keep their first sections (shifted).
  const std::size_t next_first = sections_.size();
  if (plan.tau_out < 1.0) append(plan.outgoing, next.limits_[plan.j]);
  for (std::size_t i = plan.j + 1; i < next.sections_.size(); ++i) append(next.sections_[i], next.limits_[i]);
  const std::size_t dropped = plan.tau_out < 1.0 ? plan.j : plan.j + 1;
  move_starts_.push_back(next_first);
  for (std::size_t m = 1; m < next.move_starts_.size(); ++m)
    move_starts_.push_back(next_first + next.move_starts_[m] - dropped);
  last_move_size_ = next.last_move_size_;
}

Path Path::blended(double corner_tolerance, std::vector<CornerStop>* stops, double tolerance) const {
  require(std::isfinite(corner_tolerance) && corner_tolerance > 0.0, "corner_tolerance", corner_tolerance,
          "must be a positive distance (m)");
  require(std::isfinite(tolerance) && tolerance > 0.0 && tolerance <= 0.1, "tolerance", tolerance,
          "must be in (0, 0.1]");
  // A junction is a corner where the twist direction changes (doc/planning.md eq. 9); within a
  // move none does. A reversal (the direction turns back to within 1e-6 of 180°) has no blend.
  constexpr double direction_tolerance = 1e-6, reversal = -1.0 + 1e-6;
  // The smallest blend worth building (m of geometric size): below it the turn is too sharp for
  // the tolerance and the motion stops instead.
  constexpr double smallest_blend = 1e-9;
  std::size_t m = 0;
  while (m + 1 < move_starts_.size() && move_starts_[m + 1] == move_starts_[m]) ++m;
  Path result = move(m);
  for (++m; m < move_starts_.size(); ++m) {
    const std::size_t last = m + 1 < move_starts_.size() ? move_starts_[m + 1] : sections_.size();
    if (last == move_starts_[m]) continue;
    const Path next = move(m);
    const Section& out = result.sections_.back();
    const Section& in = next.sections_.front();
    const Eigen::Matrix<double, 6, 1> d_out = geometric_direction(out, 1.0), d_in = geometric_direction(in, 0.0);
    if ((d_out - d_in).norm() <= direction_tolerance && d_out != Eigen::Matrix<double, 6, 1>::Zero()) {
      result.then(next);
      continue;
    }
    auto stop = [&](const std::string& why) {
      if (stops) stops->push_back({result.sections_.size() - 1, why});
      result.then(next);
    };
    if (d_out == Eigen::Matrix<double, 6, 1>::Zero() || d_in == Eigen::Matrix<double, 6, 1>::Zero()) {
      stop("a neighbouring move stands still at the corner: nothing to blend");
      continue;
    }
    const double turn = std::acos(std::clamp(d_out.dot(d_in), -1.0, 1.0));
    if (d_out.dot(d_in) < reversal) {
      stop("the motion reverses (turn " + degrees(turn) + "): a reversal cannot be blended");
      continue;
    }
    // The largest blend within half of each neighbour whose pivot keeps to the tolerance. The
    // deviation grows about linearly with the blend's size (exactly so between two straight
    // moves), so a few proportional steps find it.
    double size = 0.5 * std::min(result.last_move_size_, next.first_move_size_);
    const bool proportional = proportional_corner(result.sections_.back(), next.sections_.front());
    detail::BlendPlan plan;
    bool found = false, still = false, scaled = false;
    for (int step = 0; step < 60 && size >= smallest_blend; ++step) {
      if (!plan_blend(result.sections_, result.cumulative_, next.sections_, next.cumulative_, size, size, plan)) {
        still = true;
        break;
      }
      // Between straight legs a size scaled to 98 % of the tolerance keeps to it (the deviation
      // is proportional to the size), so it needs no second look.
      if (scaled && plan.k + 1 == result.sections_.size() && plan.j == 0) {
        found = true;
        break;
      }
      const double deviation = corner_deviation(plan);
      if (deviation <= corner_tolerance) {
        found = true;
        break;
      }
      size *= std::min(0.98 * corner_tolerance / deviation, 0.9);
      scaled = proportional && 0.98 * corner_tolerance / deviation <= 0.9;
    }
    if (still) {
      stop("a neighbouring move stands still where the blend would join it: nothing to blend");
      continue;
    }
    if (!found) {
      stop("corner_tolerance = " + std::to_string(corner_tolerance) + " m is too small for a turn of " + degrees(turn));
      continue;
    }
    result.apply_blend(plan, next, tolerance);
  }
  return result;
}

}  // namespace dispkin
