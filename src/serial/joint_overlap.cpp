// The overlapped velocity method for PTP moves (joint_overlap.hpp, doc/ptp.md eq. 16).
#include "dispkin/serial/joint_overlap.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "dispkin/error.hpp"
#include "dispkin/serial/chain_kinematics.hpp"
#include "overlapped_joint_sample.hpp"
#include "same_chain.hpp"

namespace dispkin::serial {

OverlappedJointTrajectory::OverlappedJointTrajectory(JointTrajectory before, JointTrajectory after, double overlap)
    : before_(std::move(before)), after_(std::move(after)), overlap_(overlap) {
  require(before_.dof() == after_.dof(), "after", static_cast<long>(after_.dof()),
          "joints: must move as many joints as `before` (" + std::to_string(before_.dof()) + ")");
  require(detail::same_chain(before_.chain(), after_.chain()), "after", static_cast<long>(after_.dof()),
          "joints: must be planned on the same arm as `before`");
  const double shorter = std::min(before_.duration(), after_.duration());
  require(std::isfinite(overlap) && overlap >= 0.0 && overlap <= shorter, "overlap", overlap,
          "must be between 0 and the shorter move's duration (" + std::to_string(shorter) + " s)");
  const double gap = (before_.end() - after_.start()).cwiseAbs().maxCoeff();
  require(gap <= 1e-9, "after", after_.start(),
          "must start where `before` ends (largest joint gap " + std::to_string(gap) + " rad)");
  via_ = after_.start();
}

JointTrajectorySample OverlappedJointTrajectory::sample(double t) const noexcept {
  // doc/ptp.md eq. 16
  return detail::overlapped_joint_sample(
      t, overlap_, before_.duration(), before_.length(), after_.duration(), duration(), via_, after_.chain(),
      [this](double u) { return before_.sample(u); }, [this](double u) { return after_.sample(u); });
}

}  // namespace dispkin::serial
