// The joint graph of a URDF, read before urdfdom builds its model: a URDF whose joints form a
// cycle, or give a link two parents, is refused here. urdfdom keeps the last parent joint of a
// link and drops the others without a word (a three-joint arm became a two-joint one). urdfdom's links own their
// children (shared_ptr) and point to their parent weakly, so a cycle of joints is a ring of links that own each other.
// When urdfdom refuses such a document (no root link left) it drops its model with the ring inside, and the links are
// never freed; the leak is in urdfdom's error path, out of our reach once it has started. Reading the graph first with
// the XML parser urdfdom itself uses (TinyXML) keeps such documents away from it.
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include <tinyxml.h>

#include "dispkin/error.hpp"
#include "urdf_joint_graph.hpp"

namespace dispkin {
namespace serial {
namespace {

struct Edge {
  std::string joint, child;
};

std::string link_attribute(const TiXmlElement& joint, const char* element) {
  const TiXmlElement* e = joint.FirstChildElement(element);
  const char* link = e != nullptr ? e->Attribute("link") : nullptr;
  return link != nullptr ? link : "";
}

}  // namespace

void require_joint_tree(const TiXmlElement& robot) {
  std::map<std::string, std::vector<Edge>> children;  // parent link → joints to its children
  std::map<std::string, std::string> parent_joint;    // child link → the joint to its parent
  std::string second_parent;                          // the first link met with two parent joints, said after any cycle
  for (const TiXmlElement* joint = robot.FirstChildElement("joint"); joint != nullptr;
       joint = joint->NextSiblingElement("joint")) {
    const char* name = joint->Attribute("name");
    const std::string parent = link_attribute(*joint, "parent"), child = link_attribute(*joint, "child");
    if (name == nullptr || parent.empty() || child.empty()) continue;
    const auto [known, first] = parent_joint.emplace(child, name);
    if (!first && second_parent.empty()) {
      second_parent = describe("link", child,
                               "is the child of two joints, \"" + known->second + "\" and \"" + name + "\" (line " +
                                   std::to_string(joint->Row()) + "): a link has one parent joint");
    }
    children[parent].push_back({name, child});
  }

  // Depth-first search from every link; a link met again while it is still on the stack
  // closes a cycle, which the message spells out link by link with the joints between.
  enum class Mark { unseen, on_stack, done };
  std::map<std::string, Mark> mark;
  struct Frame {
    std::string link;
    std::size_t next = 0;
    std::string via;  // the joint that led here
  };
  for (const auto& start : children) {
    if (mark[start.first] != Mark::unseen) continue;
    std::vector<Frame> stack{{start.first, 0, ""}};
    mark[start.first] = Mark::on_stack;
    while (!stack.empty()) {
      Frame& top = stack.back();
      const auto out = children.find(top.link);
      if (out == children.end() || top.next == out->second.size()) {
        mark[top.link] = Mark::done;
        stack.pop_back();
        continue;
      }
      const Edge edge = out->second[top.next++];
      const Mark seen = mark[edge.child];
      if (seen == Mark::on_stack) {
        std::string cycle;
        std::size_t k = stack.size();
        while (stack[k - 1].link != edge.child) --k;
        cycle = "\"" + stack[k - 1].link + "\"";
        for (std::size_t i = k; i < stack.size(); ++i) cycle += " -(" + stack[i].via + ")-> \"" + stack[i].link + "\"";
        cycle += " -(" + edge.joint + ")-> \"" + edge.child + "\"";
        throw std::invalid_argument(
            describe("link", edge.child, "is its own ancestor: the URDF's joints form a cycle " + cycle));
      }
      if (seen == Mark::unseen) {
        mark[edge.child] = Mark::on_stack;
        stack.push_back({edge.child, 0, edge.joint});
      }
    }
  }
  // A cycle hanging off a tree gives one of its links a second parent too: the cycle, said
  // above, is the clearer message.
  if (!second_parent.empty()) throw std::invalid_argument(second_parent);
}

}  // namespace serial
}  // namespace dispkin
