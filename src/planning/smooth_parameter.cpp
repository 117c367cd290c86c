// The smooth parameter σ of a planned path (smooth_parameter.hpp).
#include "smooth_parameter.hpp"

namespace dispkin::detail {

SmoothParameter::SmoothParameter(const Trajectory& planned, double acceleration) : planned_(planned) {
  const std::vector<double>& lengths = planned.section_lengths();
  const std::vector<double>& rests = planned.rest_positions();
  const std::size_t n = lengths.size();
  ell_.resize(n);
  sigma_start_.resize(n + 1);
  speed_.resize(n);
  acceleration_.resize(n);
  sigma_start_[0] = 0.0;
  Posed pose;
  Twistd out, in;
  for (std::size_t k = 0; k < n; ++k) {
    const bool run_start = std::binary_search(rests.begin(), rests.end(), planned.path().section_start(k));
    ell_[k] = lengths[k];
    if (k > 0 && !run_start && lengths[k] > 0.0) {
      planned.path().section_state_at(k - 1, 1.0, pose, out);
      planned.path().section_state_at(k, 0.0, pose, in);
      const double n_out = out.vector().norm(), n_in = in.vector().norm();
      if (n_out > 0.0 && n_in > 0.0 && ell_[k - 1] > 0.0) ell_[k] = ell_[k - 1] * n_in / n_out;
    }
    sigma_start_[k + 1] = sigma_start_[k] + ell_[k];
    // The DISP velocity limit of the section: the span of the plan's curve that holds it.
    double cap = std::numeric_limits<double>::infinity();
    const double middle = planned.path().section_start(k) + 0.5 * lengths[k];
    for (const SpeedLimit& span : planned.speed_limits()) {
      if (span.start_s <= middle && middle <= span.start_s + span.length) cap = std::min(cap, span.limit);
    }
    const double ratio = lengths[k] > 0.0 ? ell_[k] / lengths[k] : 1.0;  // σ per unit s
    speed_[k] = cap * ratio;
    acceleration_[k] = acceleration * ratio;
  }
  for (const double rest : rests) rest_sigma_.push_back(sigma_at(rest));
}

}  // namespace dispkin::detail
