//! A path ready to be sampled by its DISP arc length s: the sections' lengths L_k under a metric
//! set (doc/section-length.md), where each starts (s_k) and the sampling form of each. Section k
//! is run through at τ = (s − s_k)/L_k (doc/planning.md (eq. 1)); a trajectory is a SampledPath
//! and a TimeLaw s(t). Its sections may be parts of the sections it was made from (the planner
//! cuts sections whose fastest point's speed varies, doc/planning.md §9): a part is kept as where
//! it lies in its section, not as a section of its own, so that memory grows with the sections,
//! not with the cuts. Immutable once built; sampling is noexcept and allocation-free.
#pragma once

#include <algorithm>
#include <cstddef>
#include <vector>

#include "dispkin/path/path.hpp"
#include "dispkin/path/section_motion.hpp"
#include "dispkin/pose.hpp"

namespace dispkin {

//! Where a section of a sampled path lies in the sections it was made from: the part
//! τ ∈ [tau_start, tau_end] of section `section` (for a trajectory: of the path as planned, the
//! blended path in continuous-path mode).
struct SectionSource {
  std::size_t section = 0;  //!< the index of the section it is a part of
  //! The part of it, τ ∈ [tau_start, tau_end] ⊂ [0, 1].
  //!@{
  double tau_start = 0.0, tau_end = 1.0;
  //!@}
};

//! A path ready to be sampled by its DISP arc length s: its sections (each a section of the path
//! or a part of one) with their lengths L_k under a metric set, and where each starts.
class SampledPath {
 public:
  SampledPath() = default;
  //! The sections of a path with their lengths L_k (one per section, each > 0; planning side,
  //! allocates).
  SampledPath(std::vector<Section> sections, std::vector<double> lengths);
  //! The parts `parts` of `sections` (in order along the path) with their lengths L_k (one per
  //! part, each > 0; planning side, allocates). Throws std::invalid_argument naming a part that
  //! names no section or no part [tau_start, tau_end] of [0, 1], and lengths not one per part.
  SampledPath(std::vector<Section> sections, std::vector<SectionSource> parts, std::vector<double> lengths);

  //! Σ L_k, m.
  double length() const noexcept { return starts_.empty() ? 0.0 : starts_.back().s + lengths_.back(); }
  std::size_t section_count() const noexcept { return motions_.size(); }            //!< the number of sections
  const std::vector<double>& section_lengths() const noexcept { return lengths_; }  //!< L_k of each section, m
  //! Section k, run over its own τ (a part of a section made a section of the same kind;
  //! planning side).
  Section section(std::size_t k) const;
  //! The sections it was made from, each once — sections that go on along one curve (as the
  //! path cuts a curve where its speed varies) kept as one (what storing it keeps; sampling uses
  //! their forms).
  const std::vector<Section>& whole_sections() const noexcept { return sections_; }
  //! Where each section lies in whole_sections() (empty when made from sections alone, each one
  //! of them, whole, in order, and none kept as part of a longer run of its curve).
  const std::vector<SectionSource>& parts() const noexcept { return parts_; }
  //! Where section k lies in whole_sections().
  SectionSource part(std::size_t k) const noexcept;
  //! s_k, the path position where section k starts.
  double section_start(std::size_t k) const noexcept { return starts_[k].s; }

  //! The section holding s: the last whose start is ≤ s (the first for s below it), found from
  //! the hint `section` when that or the next one is it (any hint is valid; section_count() means
  //! none: binary search).
  std::size_t section_at(double s, std::size_t section) const noexcept;
  //! The pose at s (clamped to its section) and the body twist per unit τ of section
  //! section_at(s, hint), which it returns; callers scale the twist once (by 1/L_k, or by ṡ/L_k).
  std::size_t section_state(double s, std::size_t hint, Posed& pose, Twistd& twist_per_tau) const noexcept;
  //! The pose at τ ∈ [0, 1] of section k and its body twist per unit τ.
  void section_state_at(std::size_t k, double tau, Posed& pose, Twistd& twist_per_tau) const noexcept {
    motions_.at(sections_, k, tau, pose, twist_per_tau);
  }
  //! 1 / L_k.
  double inverse_length(std::size_t k) const noexcept { return starts_[k].inverse_length; }
  //! The pose at path position s (clamped to [0, length()]) and its body twist per unit of s.
  void state(double s, Posed& pose, Twistd& twist_per_s) const noexcept;

 private:
  // What sampling needs of section k: s at its start, and 1 / L_k (sampling multiplies).
  struct SectionStart {
    double s, inverse_length;
  };
  SectionMotions motions_;
  std::vector<Section> sections_;
  std::vector<SectionSource> parts_;
  std::vector<double> lengths_;
  std::vector<SectionStart> starts_;
};

// Inline: both lie on the sampling path of every trajectory.
inline std::size_t SampledPath::section_at(double s, std::size_t section) const noexcept {
  const std::size_t last = starts_.size() - 1;
  // Section k is it when it starts at or before s (or is the first) and the next one starts
  // after s (or k is the last).
  const auto is_it = [&](std::size_t k) {
    return (k == 0 || starts_[k].s <= s) && (k == last || s < starts_[k + 1].s);
  };
  if (section <= last && is_it(section)) return section;
  if (section < last && is_it(section + 1)) return section + 1;
  const auto next =
      std::upper_bound(starts_.begin(), starts_.end(), s, [](double x, const SectionStart& k) { return x < k.s; });
  const std::size_t k = next == starts_.begin() ? 0 : static_cast<std::size_t>(next - starts_.begin()) - 1;
  return std::min(k, last);
}

inline std::size_t SampledPath::section_state(double s, std::size_t hint, Posed& pose,
                                              Twistd& twist_per_tau) const noexcept {
  const std::size_t k = section_at(s, hint);
  const SectionStart& start = starts_[k];
  const double tau = std::clamp((s - start.s) * start.inverse_length, 0.0, 1.0);
  motions_.at(sections_, k, tau, pose, twist_per_tau);
  return k;
}

}  // namespace dispkin
