//! A serial chain of revolute joints in product-of-exponentials form: the geometry every
//! analytic inverse-kinematics family works on, independent of how the chain was loaded
//! (URDF → KDL in dispkin::serial, or written down by hand from DH tables in tests).
//!
//!   T(q) = exp([ξ₁] q₁) · … · exp([ξₙ] qₙ) · M,   ξᵢ = (−ωᵢ × pᵢ, ωᵢ)  (spatial twists)
//!
//! with ωᵢ the unit axis and pᵢ any point on the axis of joint i, both in the base frame at
//! q = 0, and M the tip (flange) pose at q = 0.
#pragma once

#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "dispkin/pose.hpp"

namespace dispkin {
namespace serial {

//! A chain of revolute joints as the axes (ωᵢ, pᵢ) and the tip pose M at q = 0:
//! T(q) = exp([ξ₁] q₁) · … · exp([ξₙ] qₙ) · M.
struct RevoluteChain {
  std::vector<Eigen::Vector3d> axes;    //!< ωᵢ: unit joint axes, base frame, q = 0
  std::vector<Eigen::Vector3d> points;  //!< pᵢ: a point on each axis, base frame, q = 0
  Posed tip_at_zero;                    //!< M: the tip pose in the base frame at q = 0

  int dof() const noexcept { return static_cast<int>(axes.size()); }  //!< the number of joints
};

//! The pose of a rigid motion rotating by `angle` about the line through `point` along the
//! unit vector `axis`: x ↦ R (x − p) + p.
inline Posed rotation_about_line(const Eigen::Vector3d& axis, const Eigen::Vector3d& point, double angle) noexcept {
  const Eigen::Quaterniond q(Eigen::AngleAxisd(angle, axis));
  return Posed::unchecked(q, point - q * point);
}

//! Forward kinematics T(q) by the product of exponentials (chain_kinematics.hpp). Throws
//! std::invalid_argument for a q of the wrong size or with non-finite values.
Posed forward(const RevoluteChain& chain, const Eigen::VectorXd& q);

}  // namespace serial
}  // namespace dispkin
