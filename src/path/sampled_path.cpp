// Sampling a path by its DISP arc length (sampled_path.hpp): the sampling forms of the sections
// and the section holding a path position.
#include "dispkin/path/sampled_path.hpp"

#include <algorithm>
#include <utility>

namespace dispkin {

void SectionMotions::reserve(const std::vector<Section>& sections) {
  std::size_t lines = 0, arcs = 0, screws = 0, slerp_blends = 0;
  for (const Section& s : sections) {
    if (const auto* lin = std::get_if<LinSection>(&s)) {
      ++(lin->interpolation == Interpolation::screw ? screws : lines);
    } else if (std::holds_alternative<ArcSection>(s)) {
      ++arcs;
    } else if (std::holds_alternative<SlerpBlendSection>(s)) {
      ++slerp_blends;
    }
  }
  entries_.reserve(sections.size());
  lines_.reserve(lines);
  arcs_.reserve(arcs);
  screws_.reserve(screws);
  slerp_blends_.reserve(slerp_blends);
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
  if (const auto* blend = std::get_if<SlerpBlendSection>(&section)) {
    entries_.push_back({Kind::slerp_blend, slerp_blends_.size()});
    slerp_blends_.push_back(*blend);
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

SampledPath::SampledPath(std::vector<Section> sections, std::vector<double> lengths)
    : sections_(std::move(sections)), lengths_(std::move(lengths)) {
  const std::size_t n = sections_.size();
  motions_.reserve(sections_);
  for (const Section& section : sections_) motions_.append(section);
  starts_.resize(n);
  double s = 0.0;
  for (std::size_t k = 0; k < n; ++k) {
    starts_[k] = {s, 1.0 / lengths_[k]};
    s += lengths_[k];
  }
}

void SampledPath::state(double s, Posed& pose, Twistd& twist_per_s) const noexcept {
  if (starts_.empty()) return;
  const std::size_t k = section_state(s, starts_.size(), pose, twist_per_s);
  twist_per_s = twist_per_s * starts_[k].inverse_length;
}

}  // namespace dispkin
