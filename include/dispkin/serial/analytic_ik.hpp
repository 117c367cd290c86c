//! Analytic inverse kinematics of 6R chains: all solutions, no initial guess.
//!
//! The family is recognised from the joint axes of a RevoluteChain (MATH.md §8):
//! - spherical_wrist: the last three axes meet in one point (Pieper; KUKA KR6, ABB IRB 120);
//! - three_parallel:  three consecutive parallel axes with the UR layout (UR3/5/10, e and non-e);
//! - offset_wrist:    a 6R chain of neither kind whose IK is the one-dimensional search of
//!                    seed 003 (Kinova Jaco2 j2n6s300);
//! - general:         no analytic method applies (the caller uses the numeric fallback).
#pragma once

#include <string>
#include <vector>

#include <Eigen/Core>

#include "dispkin/pose.hpp"
#include "dispkin/serial/revolute_chain.hpp"

namespace dispkin {
namespace serial {

enum class IkFamily { spherical_wrist, three_parallel, offset_wrist, general };

//! "spherical_wrist", "three_parallel", "offset_wrist", "general".
std::string to_string(IkFamily family);

//! The family of `chain`, from its axes (geometric tolerance `tolerance`, metres / radians).
IkFamily recognise(const RevoluteChain& chain, double tolerance = 1e-9);

//! Every joint vector q (each component in (−π, π]) with forward(chain, q) = pose to ≤ 1e-10,
//! by the closed form or search of `family`. No joint limits are applied here. Throws
//! std::invalid_argument if the family does not fit the chain or is `general`.
std::vector<Eigen::VectorXd> analytic_inverse(const RevoluteChain& chain, IkFamily family, const Posed& pose);

}  // namespace serial
}  // namespace dispkin
