// How closely a pose fixes the joint values of a 6R chain: the bound within which the analytic-IK
// round trips (tests/cpp/test_analytic_ik.cpp, benchmarks/ik_recovery.cpp) must find the q a pose
// was made from.
#pragma once

#include <algorithm>
#include <cstddef>
#include <limits>

#include <Eigen/Core>
#include <Eigen/SVD>

#include <dispkin/pose.hpp>
#include <dispkin/serial/revolute_chain.hpp>

namespace dispkin::testing {

//! The space Jacobian of the product of exponentials at q.
inline Eigen::Matrix<double, 6, 6> space_jacobian(const serial::RevoluteChain& chain, const Eigen::VectorXd& q) {
  Eigen::Matrix<double, 6, 6> j;
  Posed t;
  const Posed tip = serial::forward(chain, q);
  for (int i = 0; i < 6; ++i) {
    const auto k = static_cast<std::size_t>(i);
    const Eigen::Vector3d w = t.quaternion() * chain.axes[k];
    const Eigen::Vector3d p = t * chain.points[k];
    j.block<3, 1>(0, i) = w.cross(tip.translation() - p);
    j.block<3, 1>(3, i) = w;
    t = t * serial::rotation_about_line(chain.axes[k], chain.points[k], q(i));
  }
  return j;
}

//! The sum of the chain's link lengths (base to joint 1, joint point to joint point, then to
//! the tip): a bound on its reach, and the size of the numbers its forward kinematics rounds.
inline double link_length_sum(const serial::RevoluteChain& chain) {
  double sum = chain.points.front().norm();
  for (std::size_t i = 0; i + 1 < chain.points.size(); ++i) sum += (chain.points[i + 1] - chain.points[i]).norm();
  return sum + (chain.tip_at_zero.translation() - chain.points.back()).norm();
}

//! Forward kinematics rounds the tip to a few ulps of the arm's size, ε = 8 u L (u = 2⁻⁵²,
//! L = link_length_sum; Newton's polish stops at residuals of 1e-15 m on the 3.5 m IRB 6640),
//! and a pose error ε moves q by up to ε / σ_min(J(q)) along J's most singular direction. So
//! "q is among the solutions" means within max(1e-8, ε / σ_min): 1e-8 rad except where q is
//! within ~1e-7 of a singularity.
inline double recovery_bound(const serial::RevoluteChain& chain, const Eigen::VectorXd& q) {
  const double pose_precision = 8.0 * std::numeric_limits<double>::epsilon() * link_length_sum(chain);
  const double sigma_min = Eigen::JacobiSVD<Eigen::Matrix<double, 6, 6>>(space_jacobian(chain, q)).singularValues()(5);
  return std::max(1e-8, pose_precision / sigma_min);
}

}  // namespace dispkin::testing
