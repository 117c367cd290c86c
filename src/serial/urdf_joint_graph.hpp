// Checks on a URDF's joint graph made before urdfdom parses the document (urdf_joint_graph.cpp).
#pragma once

class TiXmlElement;

namespace dispkin {
namespace serial {

// Throws std::invalid_argument naming the link when the joints under <robot> do not form a
// forest: a cycle (spelled out joint by joint), or a link that is the child of two joints.
// Joints without a name or links are urdfdom's to report.
void require_joint_tree(const TiXmlElement& robot);

}  // namespace serial
}  // namespace dispkin
