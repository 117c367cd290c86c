// Pose paths: LIN, CIRC and PTP geometry and the cutting of arcs into sections.
#include "dispkin/path/path.hpp"

#include <algorithm>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>

#include "path_geometry.hpp"
#include "section_bounds.hpp"

namespace dispkin {
namespace {

using detail::geometric_size;
using detail::rotation_angle;


void require_pose_distinct(const Posed& a, const Posed& b, const char* what) {
  if (a.is_approx(b, 1e-12)) {
    throw std::invalid_argument(
        describe(what, a.translation(), "start and end poses coincide: the move has no length"));
  }
}

}  // namespace

CircleThroughPoints circle_through(const Eigen::Vector3d& start, const Eigen::Vector3d& via,
                                   const Eigen::Vector3d& end) {
  require_finite(start, "start");
  require_finite(via, "via");
  require_finite(end, "end");
  const Eigen::Vector3d u = via - start;
  const Eigen::Vector3d v = end - start;
  const double scale = std::max({u.norm(), v.norm(), (end - via).norm()});
  require(u.norm() > 1e-12 * std::max(scale, 1.0), "via", via, "coincides with the start point of the arc");
  require(v.norm() > 1e-12 * std::max(scale, 1.0), "end", end, "coincides with the start point of the arc");
  require((end - via).norm() > 1e-12 * std::max(scale, 1.0), "end", end, "coincides with the via point of the arc");
  const Eigen::Vector3d w = u.cross(v);
  // |u × v| = |u||v| sin(angle at start): collinear when the sine is below 1e-9.
  require(w.norm() > 1e-9 * u.norm() * v.norm(), "via", via,
          "is collinear with the start and end points: no circle passes through them");
  // Circumcentre of the triangle (start, via, end), relative to start.
  const Eigen::Vector3d offset =
      (u.squaredNorm() * v.cross(w) + v.squaredNorm() * w.cross(u)) / (2.0 * w.squaredNorm());
  CircleThroughPoints circle;
  circle.center = start + offset;
  circle.normal = w.normalized();
  circle.radius = offset.norm();
  // The triangle (start, via, end) turns counter-clockwise about w, so does the arc start →
  // via → end: its angle is the counter-clockwise angle from start to end.
  const Eigen::Vector3d ra = start - circle.center;
  const Eigen::Vector3d rb = end - circle.center;
  double angle = std::atan2(circle.normal.dot(ra.cross(rb)), ra.dot(rb));
  if (angle <= 0.0) angle += 2.0 * pi;
  circle.angle = angle;
  // A via point almost on the line through start and end but outside the segment between
  // them makes a circle of huge radius that the arc goes almost all the way round (1e-9 m
  // off a 0.1 m line: a 9.4e7 m arc). No real arc is that much longer than the polyline
  // start → via → end; a full circle through three well-spread points is at most π times it.
  const double polyline = u.norm() + (end - via).norm();
  constexpr double max_arc_to_polyline = 1000.0;
  if (!(circle.radius * angle <= max_arc_to_polyline * polyline)) {
    std::ostringstream why;
    why.precision(6);
    why << "is almost collinear with the start and end points and outside the segment between them: the arc through "
           "the three points would be "
        << circle.radius * angle << " m long, more than " << max_arc_to_polyline
        << " times the distance start → via → end (" << polyline << " m)";
    throw std::invalid_argument(describe("via", via, why.str()));
  }
  return circle;
}

Path Path::lin(const Posed& a, const Posed& b, Interpolation interpolation, const Eigen::Vector3d& pivot) {
  require_translation(pivot, "pivot");
  require_pose_distinct(a, b, "b");
  Path path;
  path.append(LinSection{a, b, interpolation, pivot});
  path.first_move_size_ = path.last_move_size_ = path.cumulative_.back();
  return path;
}

Path Path::circ(const Posed& a, const Posed& via, const Posed& b, const Eigen::Vector3d& pivot, double tolerance) {
  require_translation(pivot, "pivot");
  require(std::isfinite(tolerance) && tolerance > 0.0 && tolerance <= 0.1, "tolerance", tolerance,
          "must be in (0, 0.1]");
  const CircleThroughPoints circle = circle_through(a * pivot, via * pivot, b * pivot);

  // The orientation turns about one world axis, shortest way, proportionally to the arc.
  const Eigen::Vector3d rotvec = quaternion_log(Eigen::Quaterniond(b.quaternion() * a.quaternion().conjugate()));
  const double total_rotation = rotvec.norm();
  const Eigen::Vector3d axis =
      total_rotation > 0.0 ? Eigen::Vector3d(rotvec / total_rotation) : Eigen::Vector3d::UnitZ();

  // Sections so that the arc bound is within `tolerance` of the pivot's speed φρ:
  // (2 + θ/N) · 2 sin(φ/(4N)) ≤ tolerance.
  auto slack = [&](double n) { return (2.0 + total_rotation / n) * 2.0 * std::sin(circle.angle / (4.0 * n)); };
  double n = std::max(1.0, std::ceil(circle.angle / tolerance));
  while (slack(n) > tolerance) n = std::ceil(n * 1.05);
  // A tolerance far below what a section bound needs would ask for more sections than memory
  // holds (1e-12 on a half circle: 3e12, beyond int as well).
  constexpr double max_sections = 1e6;
  if (!(n <= max_sections)) {
    std::ostringstream why;
    why << "is too fine for this arc: it needs " << n << " sections, at most " << max_sections << " are made";
    throw std::invalid_argument(describe("tolerance", tolerance, why.str()));
  }
  const int count = static_cast<int>(n);

  // Each section starts at the exact point of the whole arc (no accumulated rounding).
  const Eigen::Vector3d radius_vector = (a * pivot) - circle.center;
  auto pose_at = [&](double fraction) {
    const Eigen::Vector3d c = circle.center + Eigen::AngleAxisd(fraction * circle.angle, circle.normal) * radius_vector;
    const Eigen::Quaterniond q =
        (Eigen::Quaterniond(Eigen::AngleAxisd(fraction * total_rotation, axis)) * a.quaternion()).normalized();
    return Posed::unchecked(q, c - q * pivot);
  };
  Path path;
  for (int k = 0; k < count; ++k) {
    ArcSection arc;
    arc.start = k == 0 ? a : pose_at(double(k) / count);
    arc.center = circle.center;
    arc.normal = circle.normal;
    arc.angle = circle.angle / count;
    arc.rotation_axis = axis;
    arc.rotation_angle = total_rotation / count;
    arc.pivot = pivot;
    path.append(arc);
  }
  path.first_move_size_ = path.last_move_size_ = path.cumulative_.back();
  return path;
}

Path Path::from_sections(const std::vector<Section>& sections, double first_move_size, double last_move_size,
                         const std::vector<MoveLimits>& section_limits, const std::vector<std::size_t>& move_starts) {
  require(!sections.empty(), "sections", 0L, "must hold at least one section");
  require(std::isfinite(first_move_size) && first_move_size > 0.0, "first_move_size", first_move_size,
          "must be finite and > 0");
  require(std::isfinite(last_move_size) && last_move_size > 0.0, "last_move_size", last_move_size,
          "must be finite and > 0");
  Path path;
  for (const Section& section : sections) {
    const std::size_t k = path.sections_.size();
    require_valid(section, [k] { return "sections[" + std::to_string(k) + "]"; });
    if (!path.sections_.empty()) {
      Path next;
      next.sections_.push_back(section);
      path.require_joins(next);
    }
    path.append(section);
  }
  path.first_move_size_ = first_move_size;
  path.last_move_size_ = last_move_size;
  if (!section_limits.empty()) {
    require(section_limits.size() == sections.size(), "section_limits size",
            static_cast<unsigned long>(section_limits.size()),
            "must be the section count " + std::to_string(sections.size()));
    for (std::size_t k = 0; k < section_limits.size(); ++k) {
      section_limits[k].validate("section_limits[" + std::to_string(k) + "]");
    }
    path.limits_ = section_limits;
  }
  if (!move_starts.empty()) {
    require(move_starts.front() == 0, "move_starts[0]", static_cast<unsigned long>(move_starts.front()), "must be 0");
    for (std::size_t m = 1; m < move_starts.size(); ++m) {
      require(move_starts[m] >= move_starts[m - 1] && move_starts[m] <= sections.size(),
              "move_starts[" + std::to_string(m) + "]", static_cast<unsigned long>(move_starts[m]),
              "must not decrease and be at most the section count");
    }
    path.move_starts_ = move_starts;
  }
  return path;
}

namespace {

using Name = std::function<std::string()>;

// Each check names `name()` + `field` only when it fails.
Name field(const Name& name, const char* sub) {
  return [&name, sub] { return name() + sub; };
}

void require_stored_pose(const Posed& pose, const Name& name) {
  try {
    Posed::from_stored(pose.quaternion(), pose.translation());
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(name() + " " + e.what());
  }
}

void require_point(const Eigen::Vector3d& x, const Name& name) {
  if (!within_translation_range(x)) require_translation(x, name());
}

void require_unit(const Eigen::Vector3d& axis, const Name& name) {
  require_lazily(axis.allFinite() && std::abs(axis.norm() - 1.0) <= Posed::stored_quaternion_tolerance(), name, axis,
                 [] { return "must be a unit vector"; });
}

void require_unit(const Eigen::Quaterniond& q, const Name& name) {
  require_lazily(q.coeffs().allFinite() && std::abs(q.norm() - 1.0) <= Posed::stored_quaternion_tolerance(), name,
                 q.coeffs(), [] { return "must be a unit quaternion (x, y, z, w)"; });
}

void require_angle(double angle, const Name& name) {
  require_lazily(std::isfinite(angle) && std::abs(angle) <= 2.0 * pi, name, angle,
                 [] { return "must be finite and at most 2 pi rad"; });
}

void require_cubic(const Cubic3& c, const Name& name) {
  for (std::size_t k = 0; k < c.a.size(); ++k) {
    const Eigen::Vector3d& x = c.a[k];
    require_lazily(
        x.allFinite() && x.cwiseAbs().maxCoeff() <= 1e14, [&] { return name() + ".a[" + std::to_string(k) + "]"; }, x,
        [] { return "must have coordinates within ±1e14 (dispkin's numeric range)"; });
  }
}

void require_curve_part(double v0, double v1, const Name& name) {
  require_lazily(0.0 <= v0 && v0 < v1 && v1 <= 1.0, field(name, " (v0, v1)"), Eigen::Vector2d(v0, v1),
                 [] { return "must satisfy 0 <= v0 < v1 <= 1"; });
}

}  // namespace

void require_valid(const Section& section, const Name& name) {
  if (const auto* lin = std::get_if<LinSection>(&section)) {
    require_stored_pose(lin->start, field(name, ".start"));
    require_stored_pose(lin->end, field(name, ".end"));
    require_point(lin->pivot, field(name, ".pivot"));
  } else if (const auto* arc = std::get_if<ArcSection>(&section)) {
    require_stored_pose(arc->start, field(name, ".start"));
    require_point(arc->center, field(name, ".center"));
    require_unit(arc->normal, field(name, ".normal"));
    require_angle(arc->angle, field(name, ".angle"));
    require_unit(arc->rotation_axis, field(name, ".rotation_axis"));
    require_angle(arc->rotation_angle, field(name, ".rotation_angle"));
    require_point(arc->pivot, field(name, ".pivot"));
  } else if (const auto* curve = std::get_if<CurveSection>(&section)) {
    require_unit(curve->q0, field(name, ".q0"));
    require_cubic(curve->position, field(name, ".position"));
    require_cubic(curve->rotation, field(name, ".rotation"));
    require_curve_part(curve->v0, curve->v1, name);
    require_point(curve->pivot, field(name, ".pivot"));
  } else {
    const auto& blend = std::get<SlerpBlendSection>(section);
    require_unit(blend.q_start, field(name, ".q_start"));
    // Each turn of the nested SLERP is below π (a blend takes at most half a LIN's turn ≤ π):
    // its logarithms, and so the motion, are smooth only there.
    require_lazily(blend.a.allFinite() && blend.a.norm() < pi, field(name, ".a"), blend.a,
                   [] { return "must be a turn below pi rad"; });
    require_lazily(blend.b.allFinite() && blend.b.norm() < pi, field(name, ".b"), blend.b,
                   [] { return "must be a turn below pi rad"; });
    require_cubic(blend.position, field(name, ".position"));
    require_curve_part(blend.v0, blend.v1, name);
    require_point(blend.pivot, field(name, ".pivot"));
  }
}

void require_join(const Posed& end, const Posed& start, const Name& name) {
  const double gap = (end.translation() - start.translation()).norm();
  const double turn = rotation_angle(end, start);
  const double size = std::max(end.translation().cwiseAbs().maxCoeff(), start.translation().cwiseAbs().maxCoeff());
  if (!(gap <= 1e-9 + 64.0 * std::numeric_limits<double>::epsilon() * size) || !(turn <= 1e-9)) {
    throw std::invalid_argument(describe(
        name(), start.translation(),
        "must start where the path ends (gap " + std::to_string(gap) + " m, " + std::to_string(turn) + " rad)"));
  }
}

void Path::require_joins(const Path& next) const {
  require_join(end(), next.start(), [] { return std::string("next"); });
}

Path& Path::then(const Path& next) {
  // A closed path appended to itself: the loop below would read what it appends (forever).
  if (&next == this) return then(Path(next));
  require_joins(next);
  const std::size_t offset = sections_.size();
  for (std::size_t i = 0; i < next.sections_.size(); ++i) append(next.sections_[i], next.limits_[i]);
  for (const std::size_t start : next.move_starts_) move_starts_.push_back(offset + start);
  last_move_size_ = next.last_move_size_;
  return *this;
}

void Path::append(Section section, const MoveLimits& limits) {
  const double before = cumulative_.empty() ? 0.0 : cumulative_.back();
  cumulative_.push_back(before + geometric_size(section));
  sections_.push_back(std::move(section));
  limits_.push_back(limits);
}

MoveLimits MoveLimits::tighter(const MoveLimits& a, const MoveLimits& b) noexcept {
  auto least = [](const std::optional<double>& x, const std::optional<double>& y) -> std::optional<double> {
    if (x && y) return std::min(*x, *y);
    return x ? x : y;
  };
  return {least(a.velocity, b.velocity), least(a.acceleration, b.acceleration)};
}

void MoveLimits::validate(const std::string& argument) const {
  const std::string prefix = argument.empty() ? "" : argument + ".";
  if (velocity) require_limit(*velocity, prefix + "velocity");
  if (acceleration) require_limit(*acceleration, prefix + "acceleration");
}

Path& Path::with_limits(const MoveLimits& limits) {
  limits.validate("");
  std::fill(limits_.begin(), limits_.end(), limits);
  return *this;
}

Path Path::move(std::size_t m) const {
  const std::size_t first = move_starts_[m];
  const std::size_t last = m + 1 < move_starts_.size() ? move_starts_[m + 1] : sections_.size();
  Path part;
  for (std::size_t i = first; i < last; ++i) part.append(sections_[i], limits_[i]);
  part.first_move_size_ = part.last_move_size_ = part.cumulative_.back();
  return part;
}

std::vector<double> Path::section_lengths(const MetricSetd& set, std::optional<double> system_velocity) const {
  set.require_well_formed();
  detail::require_system_velocity(system_velocity);
  // The groups' weights and reaches are per path: once, not once per section.
  GroupFactors factors(set, system_velocity);
  std::vector<double> lengths;
  lengths.reserve(sections_.size());
  for (const Section& s : sections_) lengths.push_back(detail::section_bounds(s, factors).length);
  return lengths;
}

Posed Path::sample(double u) const noexcept {
  const double total = cumulative_.back();
  if (!(u > 0.0) || total == 0.0) return start();
  if (u >= 1.0) return end();
  const double target = u * total;
  const auto it = std::upper_bound(cumulative_.begin(), cumulative_.end(), target);
  const std::size_t k = std::min<std::size_t>(static_cast<std::size_t>(it - cumulative_.begin()), sections_.size() - 1);
  const double begin = k == 0 ? 0.0 : cumulative_[k - 1];
  const double size = cumulative_[k] - begin;
  const double tau = size > 0.0 ? std::clamp((target - begin) / size, 0.0, 1.0) : 0.0;
  return section_pose(sections_[k], tau);
}

namespace {

double set_acceleration_bound(const MetricSetd& set, const Eigen::Vector3d& pivot, const Eigen::Vector3d& pivot_middle,
                              const MotionBounds& bounds) {
  double best = 0.0;
  for (const auto& g : set.groups())
    best = std::max(best, detail::group_acceleration_bound(g, pivot, pivot_middle, bounds));
  return best;
}

}  // namespace

namespace {

// The motion bounds of a LIN section (see LinSection::acceleration_bound) and its screw twist
// (only for a screw).
MotionBounds lin_motion_bounds(const LinSection& lin, Twistd& screw) {
  if (lin.interpolation == Interpolation::screw) {
    screw = lin.twist(0.0);
    const double speed = (screw.linear + screw.angular.cross(lin.pivot)).norm(), omega = screw.angular.norm();
    return {speed, omega * speed, omega, 0.0};
  }
  const double speed = ((lin.end * lin.pivot) - (lin.start * lin.pivot)).norm();
  return {speed, 0.0, rotation_angle(lin.start, lin.end), 0.0};
}

}  // namespace

double LinSection::acceleration_bound(const MetricSetd& set) const {
  Twistd screw;
  return set_acceleration_bound(set, pivot, pose(0.5) * pivot, lin_motion_bounds(*this, screw));
}

SectionBounds LinSection::bounds(const GroupFactors& factors) const {
  // As length() (section_length) and acceleration_bound(), with the groups' weights and reaches
  // at hand.
  const MetricSetd& set = factors.set();
  Twistd screw;
  const MotionBounds motion = lin_motion_bounds(*this, screw);
  const Eigen::Vector3d pivot_middle = pose(0.5) * pivot;
  double length = 0.0, acceleration = 0.0;
  if (interpolation == Interpolation::screw) {
    for (std::size_t i = 0; i < set.groups().size(); ++i)
      length = std::max(length, factors.weight(i) * detail::group_max_speed(set.groups()[i], start, screw));
  } else {
    const detail::DecoupledSection<double> section(start, end, pivot);
    for (std::size_t i = 0; i < set.groups().size(); ++i)
      length = std::max(length, factors.weight(i) * detail::group_decoupled_length(set.groups()[i], section));
  }
  for (std::size_t i = 0; i < set.groups().size(); ++i)
    acceleration = std::max(acceleration,
                            detail::group_acceleration_bound(set.groups()[i], factors.reach(i), pivot_middle, motion));
  return {length, acceleration, motion.omega, motion.omega_dot};
}

Section section_part(const Section& section, double t0, double t1) { return detail::section_part(section, t0, t1); }

SectionBounds detail::section_bounds(const Section& section, GroupFactors& factors) {
  return std::visit(
      [&](const auto& s) {
        factors.use_pivot(s.pivot);
        return s.bounds(factors);
      },
      section);
}

double ArcSection::acceleration_bound(const MetricSetd& set) const {
  const double radius = ((start * pivot) - center).norm();
  const double phi = std::abs(angle);
  return set_acceleration_bound(set, pivot, pose(0.5) * pivot,
                                {phi * radius, phi * phi * radius, std::abs(rotation_angle), 0.0});
}

JointPath::JointPath(const Eigen::VectorXd& q_start, const Eigen::VectorXd& q_end) : q_start_(q_start), q_end_(q_end) {
  require(q_start.size() > 0, "q_start", static_cast<long>(q_start.size()), "must have at least one joint");
  require(q_end.size() == q_start.size(), "q_end size", static_cast<long>(q_end.size()),
          "must equal q_start size " + std::to_string(q_start.size()));
  require_finite(q_start, "q_start");
  require_finite(q_end, "q_end");
}

Eigen::VectorXd JointPath::sample(double u) const {
  const double t = std::clamp(u, 0.0, 1.0);
  return q_start_ + t * (q_end_ - q_start_);
}

SectionBounds detail::section_bounds_from_middle(const Section& section, GroupFactors& factors) {
  const auto* lin = std::get_if<LinSection>(&section);
  if (!lin) return section_bounds(section, factors);
  // The LIN's exact speed at its middle plus half the rate bound (doc/section-length.md eqs. 23–24).
  factors.use_pivot(lin->pivot);
  Twistd screw;
  const MotionBounds motion = lin_motion_bounds(*lin, screw);
  const Posed middle = lin->pose(0.5);
  const Twistd twist_middle = lin->twist(0.5);
  return bounds_from_middle(factors, middle, twist_middle, middle * lin->pivot, motion);
}

}  // namespace dispkin
