// Joint torques of a revolute chain by the recursive Newton–Euler algorithm on its product-of-
// exponentials form (internal to the serial plugin; doc/retiming.md (eq. 23)–(eq. 25)): the one
// dynamics kernel behind SerialArm::torques, on the same pass as the forward kinematics and the
// Jacobians (chain_pass.hpp).
#pragma once

#include <vector>

#include <Eigen/Core>

#include "chain_pass.hpp"
#include "dispkin/serial/revolute_chain.hpp"
#include "dispkin/serial/serial_arm.hpp"

namespace dispkin {
namespace serial {
namespace detail {

//! The moving body of joint i at q = 0 in base coordinates: its frame there times its
//! BodyInertia. At q its frame is T₍≤ᵢ₎ times this one (chain_pass.hpp).
struct ChainBody {
  double mass = 0.0;
  Eigen::Vector3d centre_of_mass = Eigen::Vector3d::Zero();  //!< m, base coordinates at q = 0
  Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();         //!< about the centre of mass, base axes at q = 0
};

//! The bodies of `inertias` (one per joint, each in its link's frame) placed by the link frames
//! at q = 0 (`frames`, base coordinates).
std::vector<ChainBody> chain_bodies(const std::vector<BodyInertia>& inertias, const std::vector<Posed>& frames);

//! τ(q, q̇, q̈) = M(q) q̈ + C(q, q̇) q̇ + g(q) into `tau` and, if not null, the holding torque
//! g(q) = τ(q, 0, 0) of the same pass into `holding` (each chain.dof() values; `bodies` one per
//! joint; `gravity` in base coordinates, m/s²). Allocation-free up to 16 joints.
void chain_torques(const RevoluteChain& chain, const std::vector<ChainBody>& bodies, const Eigen::Vector3d& gravity,
                   const double* q, const double* qd, const double* qdd, double* tau, double* holding);

//! The same at the q of `record` (a pass recorded by the body Jacobian at that q), without a
//! second pass over the chain: the results are chain_torques' at that q bit for bit.
void chain_torques(const ChainPassRecord& record, const std::vector<ChainBody>& bodies, const Eigen::Vector3d& gravity,
                   const double* qd, const double* qdd, double* tau, double* holding) noexcept;

//! SerialArm::torques(q, qd, qdd, tau, holding) at the q of `record` (recorded by the body
//! Jacobian at q). Throws as SerialArm::torques.
void recorded_torques(const SerialArm& arm, const ChainPassRecord& record, const Eigen::VectorXd& qd,
                      const Eigen::VectorXd& qdd, Eigen::VectorXd& tau, Eigen::VectorXd& holding);

//! KDL's ChainIdSolver_RNE on the arm's KDL chain: the reference SerialArm::torques is tested
//! against (not on any hot path: it copies the chain per call).
Eigen::VectorXd torques_by_kdl(const SerialArm& arm, const Eigen::VectorXd& q, const Eigen::VectorXd& qd,
                               const Eigen::VectorXd& qdd);

}  // namespace detail
}  // namespace serial
}  // namespace dispkin
