// The overlapped velocity method for a PTP move and a Cartesian move (mixed_overlap.hpp,
// doc/ptp.md eq. 21).
#include "dispkin/serial/mixed_overlap.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include "dispkin/error.hpp"
#include "dispkin/serial/chain_kinematics.hpp"
#include "overlapped_joint_sample.hpp"
#include "same_chain.hpp"

namespace dispkin::serial {

OverlappedMixedTrajectory::OverlappedMixedTrajectory(JointTrajectory before, FollowedTrajectory after, double overlap)
    : ptp_(std::move(before)), cartesian_(std::move(after)), ptp_first_(true), overlap_(overlap) {
  check(overlap);
  via_ = cartesian_.start();
}

OverlappedMixedTrajectory::OverlappedMixedTrajectory(FollowedTrajectory before, JointTrajectory after, double overlap)
    : ptp_(std::move(after)), cartesian_(std::move(before)), ptp_first_(false), overlap_(overlap) {
  check(overlap);
  via_ = ptp_.start();
}

void OverlappedMixedTrajectory::check(double overlap) const {
  // The Cartesian move's joints are the `after` argument when the PTP move comes first.
  const char* cartesian = ptp_first_ ? "after" : "before";
  require(ptp_.dof() == cartesian_.dof(), cartesian, static_cast<long>(cartesian_.dof()),
          "joints: must move as many joints as the PTP move (" + std::to_string(ptp_.dof()) + ")");
  require(detail::same_chain(ptp_.chain(), cartesian_.chain()), cartesian, static_cast<long>(cartesian_.dof()),
          "joints: must be followed on the arm the PTP move was planned on");
  const double shorter = std::min(ptp_.duration(), cartesian_.duration());
  require(std::isfinite(overlap) && overlap >= 0.0 && overlap <= shorter, "overlap", overlap,
          "must be between 0 and the shorter move's duration (" + std::to_string(shorter) + " s)");
  const Eigen::VectorXd& first_end = ptp_first_ ? ptp_.end() : cartesian_.end();
  const Eigen::VectorXd& next_start = ptp_first_ ? cartesian_.start() : ptp_.start();
  const double gap = (first_end - next_start).cwiseAbs().maxCoeff();
  require(gap <= 1e-9, "after", next_start,
          "must start where `before` ends (largest joint gap " + std::to_string(gap) + " rad)");
}

JointTrajectorySample OverlappedMixedTrajectory::sample(double t) const noexcept {
  // doc/ptp.md eq. 21
  return detail::overlapped_joint_sample(
      t, overlap_, before_duration(), before_length(), after_duration(), duration(), via_, ptp_.chain(),
      [this](double u) { return before_at(u); }, [this](double u) { return after_at(u); });
}

}  // namespace dispkin::serial
