// Checks on a URDF's joint graph made before urdfdom parses the document (urdf_joint_graph.cpp).
#pragma once

#include <string>

namespace dispkin {
namespace serial {

// Throws std::invalid_argument naming a link on the cycle (and the cycle, joint by joint) when
// the joints of the URDF text form one. Malformed XML passes: urdfdom reports it.
void require_acyclic_joints(const std::string& xml);

}  // namespace serial
}  // namespace dispkin
