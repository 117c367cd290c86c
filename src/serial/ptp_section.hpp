// The DISP bound of one joint section of a PTP move (ptp_section.cpp, doc/ptp.md): internal to
// the serial plugin; the planner (ptp.cpp) and the tests of the bound call it.
#pragma once

#include <Eigen/Core>

#include "dispkin/path/group_factors.hpp"
#include "dispkin/serial/ptp.hpp"
#include "dispkin/serial/revolute_chain.hpp"

namespace dispkin::serial::detail {

//! The bounds of the joint section u ∈ [u0, u1] of the line q_a + u Δq on `chain`, with the
//! groups' weights and relative reaches (from the tool origin) in `factors`. See
//! ptp_section.cpp for the derivation of the acceleration bound.
JointSection joint_section_bounds(const RevoluteChain& chain, const Eigen::VectorXd& q_a, const Eigen::VectorXd& delta,
                                  double u0, double u1, const GroupFactors& factors);

}  // namespace dispkin::serial::detail
