// Sampling a path by its DISP arc length (sampled_path.hpp): the sampling forms of the sections
// and the section holding a path position.
#include "dispkin/path/sampled_path.hpp"

#include <algorithm>
#include <string>
#include <type_traits>
#include <variant>
#include <utility>

#include "dispkin/error.hpp"
#include "path_geometry.hpp"

namespace dispkin {

void SectionMotions::reserve(const std::vector<Section>& sections, std::size_t parts) {
  std::size_t lines = 0, arcs = 0, screws = 0;
  for (const Section& s : sections) {
    if (const auto* lin = std::get_if<LinSection>(&s)) {
      ++(lin->interpolation == Interpolation::screw ? screws : lines);
    } else if (std::holds_alternative<ArcSection>(s)) {
      ++arcs;
    }
  }
  entries_.reserve(parts);
  lines_.reserve(lines);
  arcs_.reserve(arcs);
  screws_.reserve(screws);
}

std::pair<SectionMotions::Kind, std::size_t> SectionMotions::make_form(const Section& section) {
  if (const auto* lin = std::get_if<LinSection>(&section)) {
    if (lin->interpolation == Interpolation::screw) {
      screws_.push_back(ScrewMotion{lin->start, (lin->start.inverse() * lin->end).log()});
      return {Kind::screw, screws_.size() - 1};
    }
    const Eigen::Quaterniond q0 = lin->start.quaternion();
    const Eigen::Vector3d rotation = q0 * quaternion_log(Eigen::Quaterniond(q0.conjugate() * lin->end.quaternion()));
    const double theta = rotation.norm();
    const Eigen::Vector3d w_hat = theta > 0.0 ? Eigen::Vector3d(rotation / theta) : Eigen::Vector3d::UnitZ();
    const Eigen::Vector3d c0 = lin->start * lin->pivot;
    lines_.emplace_back(TurningFrame(q0, w_hat, theta, lin->pivot), c0, (lin->end * lin->pivot) - c0);
    return {Kind::line, lines_.size() - 1};
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
  arcs_.push_back(m);
  return {Kind::arc, arcs_.size() - 1};
}

void SectionMotions::append(const Section& section, std::size_t k, double t0, double t1) {
  // Curves and blends: the part's curve parameter as the planner's cut gives it (doc/planning.md
  // eq. 40), so that a part samples as the section cut from it would.
  const auto curve_part = [&](const auto& curve, Kind kind) {
    const double v0 = detail::cut_parameter(curve, t0), v1 = detail::cut_parameter(curve, t1);
    entries_.push_back({kind, k, v0, v1 - v0});
  };
  if (const auto* curve = std::get_if<CurveSection>(&section)) return curve_part(*curve, Kind::curve);
  if (const auto* blend = std::get_if<SlerpBlendSection>(&section)) return curve_part(*blend, Kind::slerp_blend);
  if (k != last_section_) {
    last_form_ = make_form(section);
    last_section_ = k;
  }
  entries_.push_back({last_form_.first, last_form_.second, t0, t1 - t0});
}

namespace {

std::string part_name(std::size_t k) { return "parts[" + std::to_string(k) + "]"; }

// Whether `next` goes on along the curve of `last` from where that ends: the same coefficients,
// bit for bit, from the same v (a curve the path cut into sections).
bool goes_on(const Section& last, const Section& next) {
  if (const auto* a = std::get_if<CurveSection>(&last)) {
    const auto* b = std::get_if<CurveSection>(&next);
    return b && a->v1 == b->v0 && detail::same_curve(a->q0, a->position, a->rotation, a->pivot, *b);
  }
  if (const auto* a = std::get_if<SlerpBlendSection>(&last)) {
    const auto* b = std::get_if<SlerpBlendSection>(&next);
    return b && a->v1 == b->v0 && a->same_blend(*b);
  }
  return false;
}

// τ of the run `into` (the longer part of its curve that `given` was kept in) where `given` is
// at τ: the run's own end where both end together.
double tau_in_run(const Section& given, const Section& into, double tau) {
  return std::visit(
      [&](const auto& c) -> double {
        using T = std::decay_t<decltype(c)>;
        if constexpr (std::is_same_v<T, CurveSection> || std::is_same_v<T, SlerpBlendSection>) {
          const T& run = std::get<T>(into);
          if (tau >= 1.0 && c.v1 == run.v1) return 1.0;
          return std::clamp((detail::cut_parameter(c, tau) - run.v0) / run.span(), 0.0, 1.0);
        } else {
          return tau;  // only curves are kept in runs
        }
      },
      given);
}

// `run` taken on to where `next`, the next part of its curve, ends.
void extend_to(Section& run, const Section& next) {
  if (auto* curve = std::get_if<CurveSection>(&run)) curve->v1 = std::get<CurveSection>(next).v1;
  if (auto* blend = std::get_if<SlerpBlendSection>(&run)) blend->v1 = std::get<SlerpBlendSection>(next).v1;
}

}  // namespace

SampledPath::SampledPath(std::vector<Section> sections, std::vector<double> lengths)
    : SampledPath(std::move(sections), {}, std::move(lengths)) {}

SampledPath::SampledPath(std::vector<Section> sections, std::vector<SectionSource> parts, std::vector<double> lengths)
    : parts_(std::move(parts)), lengths_(std::move(lengths)) {
  for (std::size_t k = 0; k < parts_.size(); ++k) {
    const SectionSource& p = parts_[k];
    require_lazily(
        p.section < sections.size(), [k] { return part_name(k) + ".section"; }, static_cast<unsigned long>(p.section),
        [&] { return "must name one of the " + std::to_string(sections.size()) + " sections"; });
    require_lazily(
        p.tau_start >= 0.0 && p.tau_start <= p.tau_end && p.tau_end <= 1.0, [k] { return part_name(k); },
        Eigen::Vector2d(p.tau_start, p.tau_end), [] { return "must be a part [tau_start, tau_end] of [0, 1]"; });
  }
  const std::size_t n = parts_.empty() ? sections.size() : parts_.size();
  require(lengths_.size() == n, "section_lengths size", static_cast<unsigned long>(lengths_.size()),
          "must be the part count " + std::to_string(n));
  // Sections that go on along one curve (a curve the path cut where its speed varies) are kept
  // as one: `kept[i]` is where section i is kept.
  std::vector<std::size_t> kept(sections.size());
  sections_.reserve(sections.size());
  for (std::size_t i = 0; i < sections.size(); ++i) {
    if (!sections_.empty() && goes_on(sections_.back(), sections[i])) {
      extend_to(sections_.back(), sections[i]);
    } else {
      sections_.push_back(sections[i]);
    }
    kept[i] = sections_.size() - 1;
  }
  sections_.shrink_to_fit();
  // The parts, in the sections as kept: a section kept as it was keeps its τ; one kept inside a
  // longer run of its curve takes the τ of that run where its curve parameter lies.
  if (sections_.size() < sections.size() && parts_.empty()) {
    parts_.resize(n);
    for (std::size_t k = 0; k < n; ++k) parts_[k] = {k, 0.0, 1.0};
  }
  const auto in_run = [&](std::size_t i) {
    return (i > 0 && kept[i - 1] == kept[i]) || (i + 1 < kept.size() && kept[i + 1] == kept[i]);
  };
  for (SectionSource& p : parts_) {
    if (in_run(p.section)) {
      const Section &given = sections[p.section], &into = sections_[kept[p.section]];
      p.tau_start = tau_in_run(given, into, p.tau_start);
      p.tau_end = tau_in_run(given, into, p.tau_end);
    }
    p.section = kept[p.section];
  }
  // The sampling forms, from what is kept alone: a state of the path (sections, parts, lengths)
  // makes the same path again, bit for bit.
  motions_.reserve(sections_, n);
  for (std::size_t k = 0; k < n; ++k) {
    const SectionSource p = part(k);
    motions_.append(sections_[p.section], p.section, p.tau_start, p.tau_end);
  }
  starts_.resize(n);
  double s = 0.0;
  for (std::size_t k = 0; k < n; ++k) {
    starts_[k] = {s, 1.0 / lengths_[k]};
    s += lengths_[k];
  }
}

Section SampledPath::section(std::size_t k) const {
  const SectionSource p = part(k);
  return detail::planned_part(sections_[p.section], p.tau_start, p.tau_end);
}

SectionSource SampledPath::part(std::size_t k) const noexcept {
  return parts_.empty() ? SectionSource{k, 0.0, 1.0} : parts_[k];
}

void SampledPath::state(double s, Posed& pose, Twistd& twist_per_s) const noexcept {
  if (starts_.empty()) return;
  const std::size_t k = section_state(s, starts_.size(), pose, twist_per_s);
  twist_per_s = twist_per_s * starts_[k].inverse_length;
}

}  // namespace dispkin
