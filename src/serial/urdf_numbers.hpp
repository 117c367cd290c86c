// One check of every number of a URDF's links and joints, made before urdfdom reads them
// (urdf_numbers.cpp).
#pragma once

#include <string>

#include <Eigen/Core>

class TiXmlElement;

namespace dispkin {
namespace serial {

// Throws std::invalid_argument naming the link or joint, the element, the attribute, its text
// and line when a number of a <link> or <joint> under <robot> is not a finite number of
// dispkin's numeric range or has the wrong count of components. urdfdom drops an <inertial> it
// cannot read with a warning, and reads "1e300" as a metre like any other: neither reaches the
// model.
void require_valid_numbers(const TiXmlElement& robot);

// Why a symmetric 3 × 3 matrix is no rigid body's inertia about its centre of mass ("" when it
// is one): a negative principal moment, or principal moments λ₁ ≤ λ₂ ≤ λ₃ with λ₁ + λ₂ < λ₃
// (each is a sum of two second moments of the mass), both to 1e-6 of the largest. Many real
// URDFs have such inertias on links no chain uses (18 of example-robot-data's files), so the
// loader records this for the links of the loaded chain only and the dynamics refuse it.
std::string impossible_inertia(const Eigen::Matrix3d& inertia);

}  // namespace serial
}  // namespace dispkin
