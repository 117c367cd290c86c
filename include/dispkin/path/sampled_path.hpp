//! A path ready to be sampled by its DISP arc length s: the sections' lengths L_k under a metric
//! set (doc/section-length.md), where each starts (s_k) and the sampling form of each. Section k
//! is run through at τ = (s − s_k)/L_k (doc/planning.md (eq. 1)); a trajectory is a SampledPath
//! and a TimeLaw s(t). Immutable once built; sampling is noexcept and allocation-free.
#pragma once

#include <algorithm>
#include <cstddef>
#include <vector>

#include "dispkin/path/path.hpp"
#include "dispkin/path/section_motion.hpp"
#include "dispkin/pose.hpp"

namespace dispkin {

//! A path ready to be sampled by its DISP arc length s: its sections with their lengths L_k
//! under a metric set, and where each starts.
class SampledPath {
 public:
  SampledPath() = default;
  //! The sections of a path with their lengths L_k (one per section, each > 0; planning side,
  //! allocates).
  SampledPath(std::vector<Section> sections, std::vector<double> lengths);

  //! Σ L_k, m.
  double length() const noexcept { return starts_.empty() ? 0.0 : starts_.back().s + lengths_.back(); }
  std::size_t section_count() const noexcept { return motions_.size(); }            //!< the number of sections
  const std::vector<double>& section_lengths() const noexcept { return lengths_; }  //!< L_k of each section, m
  //! The sections it was made from (what storing it keeps; sampling uses their motions).
  const std::vector<Section>& sections() const noexcept { return sections_; }
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
    motions_.at(k, tau, pose, twist_per_tau);
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
  motions_.at(k, tau, pose, twist_per_tau);
  return k;
}

}  // namespace dispkin
