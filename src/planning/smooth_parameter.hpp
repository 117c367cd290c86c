// The smooth parameter σ of a planned path (internal to the re-timing; doc/retiming.md §4).
#pragma once

#include <algorithm>
#include <cstddef>
#include <limits>
#include <vector>

#include "dispkin/planning/trajectory.hpp"
#include "dispkin/planning/trajectory_acceleration.hpp"
#include "dispkin/pose.hpp"

namespace dispkin::detail {

//! The planned path by the smooth parameter σ (doc/retiming.md (eq. 9)): section k gets a σ-length
//! ℓ_k with ℓ_{k+1}/ℓ_k = |ξ_{k+1}(0)| / |ξ_k(1)|, so that the pose derivative per unit σ is
//! continuous through tangent junctions, and its DISP limits become σ̇ ≤ v_lim ℓ_k/L_k and
//! |σ̈| ≤ a ℓ_k/L_k (doc/retiming.md eq. 10).
class SmoothParameter {
 public:
  SmoothParameter(const Trajectory& planned, double acceleration);

  double length() const noexcept { return sigma_start_.back(); }
  const std::vector<double>& rests() const noexcept { return rest_sigma_; }
  std::size_t sections() const noexcept { return ell_.size(); }
  double start(std::size_t k) const noexcept { return sigma_start_[k]; }
  double ell(std::size_t k) const noexcept { return ell_[k]; }
  //! ds/dσ on section k.
  double s_per_sigma(std::size_t k) const noexcept {
    return ell_[k] > 0.0 ? planned_.section_lengths()[k] / ell_[k] : 1.0;
  }

  //! The path position s of σ (for messages and results).
  double s_of(double sigma) const noexcept {
    const std::size_t k = section_at(sigma);
    return planned_.path().section_start(k) + (sigma - start(k)) * s_per_sigma(k);
  }

  //! The section holding σ (the later one at a junction).
  std::size_t section_at(double sigma) const noexcept {
    const auto next = std::upper_bound(sigma_start_.begin(), sigma_start_.end() - 1, sigma);
    const std::size_t k = next == sigma_start_.begin() ? 0 : static_cast<std::size_t>(next - sigma_start_.begin()) - 1;
    return std::min(k, ell_.size() - 1);
  }

  //! Pose and body twist per unit σ.
  void state(double sigma, Posed& pose, Twistd& per_sigma) const {
    const std::size_t k = section_at(sigma);
    const double tau = ell_[k] > 0.0 ? std::clamp((sigma - sigma_start_[k]) / ell_[k], 0.0, 1.0) : 0.0;
    planned_.path().section_state_at(k, tau, pose, per_sigma);
    per_sigma = per_sigma * (ell_[k] > 0.0 ? 1.0 / ell_[k] : 0.0);
  }

  //! The derivative per unit σ of that body twist (per σ²), inside section_at(σ).
  Twistd twist_rate(double sigma) const noexcept {
    const std::size_t k = section_at(sigma);
    if (!(ell_[k] > 0.0)) return Twistd(Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero());
    const double tau = std::clamp((sigma - sigma_start_[k]) / ell_[k], 0.0, 1.0);
    return section_twist_rate(planned_.path(), k, tau) * (1.0 / (ell_[k] * ell_[k]));
  }

  //! state() and twist_rate() at σ as section k gives them (at a junction: either side's).
  void state_in(std::size_t k, double sigma, Posed& pose, Twistd& per_sigma, Twistd& rate) const {
    const double tau = ell_[k] > 0.0 ? std::clamp((sigma - sigma_start_[k]) / ell_[k], 0.0, 1.0) : 0.0;
    planned_.path().section_state_at(k, tau, pose, per_sigma);
    per_sigma = per_sigma * (ell_[k] > 0.0 ? 1.0 / ell_[k] : 0.0);
    rate = ell_[k] > 0.0 ? section_twist_rate(planned_.path(), k, tau) * (1.0 / (ell_[k] * ell_[k]))
                         : Twistd(Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero());
  }

  //! The DISP limits in σ over [σ0, σ1]: the lowest of the sections it touches.
  void limits_over(double sigma0, double sigma1, double& speed, double& acceleration) const noexcept {
    speed = acceleration = std::numeric_limits<double>::infinity();
    for (std::size_t k = section_at(sigma0); k < ell_.size() && sigma_start_[k] < sigma1; ++k) {
      speed = std::min(speed, speed_[k]);
      acceleration = std::min(acceleration, acceleration_[k]);
    }
  }

 private:
  double sigma_at(double s) const noexcept {
    const std::size_t k = planned_.path().section_at(s, planned_.section_count());
    const double length = planned_.section_lengths()[k];
    return sigma_start_[k] + (length > 0.0 ? (s - planned_.path().section_start(k)) / length * ell_[k] : 0.0);
  }

  const Trajectory& planned_;
  std::vector<double> ell_, sigma_start_, speed_, acceleration_, rest_sigma_;
};

}  // namespace dispkin::detail
