// URDF (urdfdom) → KDL chain between two links, with limits and inertias (serial_arm.hpp
// states the rules). The conversion is written here rather than taken from ROS' kdl_parser so
// that it reads only the path we need and reports every problem by link or joint name.
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <mutex>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <Eigen/Geometry>
#include <console_bridge/console.h>
#include <tinyxml.h>
#include <kdl/chain.hpp>
#include <kdl/joint.hpp>
#include <kdl/rigidbodyinertia.hpp>
#include <kdl/rotationalinertia.hpp>
#include <kdl/segment.hpp>
#include <urdf_model/model.h>
#include <urdf_parser/urdf_parser.h>

#include "dispkin/error.hpp"
#include "dispkin/input_budget.hpp"
#include "serial_arm_model.hpp"
#include "urdf_format_text.hpp"
#include "urdf_joint_graph.hpp"
#include "urdf_numbers.hpp"
#include "xml_bounds.hpp"

namespace dispkin {
namespace serial {
namespace {

constexpr double infinity = std::numeric_limits<double>::infinity();

// urdfdom reports why a document is rejected through console_bridge, not through its return
// value; this handler keeps the messages so that the exception can carry them. The handler is
// process-global, hence the lock.
class CapturingOutput : public console_bridge::OutputHandler {
 public:
  void log(const std::string& text, console_bridge::LogLevel level, const char*, int) override {
    if (level >= console_bridge::CONSOLE_BRIDGE_LOG_WARN) {
      if (!messages.empty()) messages += "; ";
      messages += text;
    }
  }
  std::string messages;
};

std::mutex parse_mutex;

// Everything refused before urdfdom reads the text: its size, nesting and attribute counts
// (xml_bounds.cpp), then, read by TinyXML as urdfdom will, a '%' urdfdom could use as a printf
// format (urdf_format_text.cpp), a joint graph that is not a tree (urdf_joint_graph.cpp) and
// any number that is not one (urdf_numbers.cpp).
void require_sound_urdf(const std::string& padded) {
  TiXmlDocument document;
  document.Parse(padded.c_str());
  // Before the parse error test: what TinyXML read up to an error is checked too.
  require_no_printf_directive(document);
  // Malformed XML and missing names are urdfdom's to report, with its own messages.
  if (document.Error()) return;
  const TiXmlElement* robot = document.FirstChildElement("robot");
  if (robot == nullptr) return;
  require_joint_tree(*robot);
  require_valid_numbers(*robot);
}

urdf::ModelInterfaceSharedPtr parse(const std::string& xml, std::string& messages) {
  require_bounded_xml(xml);
  // TinyXML 2.6.2 (urdfdom's XML parser, and ours in require_sound_urdf) steps over a UTF-8
  // lead byte by the length it announces, so a text ending inside such a sequence ("…\xe6") was
  // read up to 3 bytes past its terminating NUL (an ASan heap-buffer-overflow).
  // Both parsers read the text as a C string: NULs appended keep those reads inside the buffer.
  const std::string padded = xml + std::string(4, '\0');
  require_sound_urdf(padded);
  const std::lock_guard<std::mutex> lock(parse_mutex);
  CapturingOutput capture;
  console_bridge::useOutputHandler(&capture);
  urdf::ModelInterfaceSharedPtr model;
  try {
    model = urdf::parseURDF(padded);
  } catch (...) {
    console_bridge::restorePreviousOutputHandler();
    throw;
  }
  console_bridge::restorePreviousOutputHandler();
  messages = capture.messages;
  // No cycle reaches urdfdom (require_joint_tree reads the same text with the same
  // parser), so its links, which own their children, are freed with the model.
  return model;
}

std::string joint_label(const urdf::Joint& joint) { return "joint \"" + joint.name + "\""; }

Eigen::Vector3d checked_vector(const urdf::Vector3& v, const std::string& what) {
  const Eigen::Vector3d e(v.x, v.y, v.z);
  require_finite(e, what);
  return e;
}

KDL::Frame checked_frame(const urdf::Pose& pose, const std::string& what) {
  const Eigen::Vector3d p = checked_vector(pose.position, what + " xyz");
  const Eigen::Vector4d xyzw(pose.rotation.x, pose.rotation.y, pose.rotation.z, pose.rotation.w);
  require_finite(xyzw, what + " rotation (x, y, z, w)");
  const double norm = xyzw.norm();
  require(norm > 0.5, what + " rotation (x, y, z, w)", xyzw, "is not a rotation");
  return KDL::Frame(KDL::Rotation::Quaternion(xyzw(0) / norm, xyzw(1) / norm, xyzw(2) / norm, xyzw(3) / norm),
                    KDL::Vector(p.x(), p.y(), p.z()));
}

// The link's own inertia about the link frame's origin, in link axes (KDL's convention). The
// first physically impossible inertia met is described in `impossible` (kept empty otherwise).
KDL::RigidBodyInertia link_inertia(const urdf::Link& link, std::string& impossible) {
  if (!link.inertial) return KDL::RigidBodyInertia::Zero();
  const urdf::Inertial& in = *link.inertial;
  const std::string what = "link \"" + link.name + "\" inertial";
  require(std::isfinite(in.mass) && in.mass >= 0.0, what + " mass", in.mass, "must be finite and not negative");
  Eigen::Matrix3d inertia;
  inertia << in.ixx, in.ixy, in.ixz, in.ixy, in.iyy, in.iyz, in.ixz, in.iyz, in.izz;
  require_finite(inertia, what + " inertia");
  const std::string why = impossible_inertia(inertia);
  if (impossible.empty() && !why.empty()) {
    impossible =
        describe(what + " inertia (ixx, ixy, ixz, iyy, iyz, izz)",
                 (Eigen::Matrix<double, 6, 1>() << in.ixx, in.ixy, in.ixz, in.iyy, in.iyz, in.izz).finished(), why);
  }
  const KDL::Frame origin = checked_frame(in.origin, what + " origin");
  // URDF gives the inertia about the centre of mass in the <inertial><origin> axes; turn it
  // into link axes (R I Rᵀ) before handing it to KDL, which wants it about the centre of mass.
  Eigen::Matrix3d r;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) r(i, j) = origin.M(i, j);
  const Eigen::Matrix3d i_link = r * inertia * r.transpose();
  return KDL::RigidBodyInertia(
      in.mass, origin.p,
      KDL::RotationalInertia(i_link(0, 0), i_link(1, 1), i_link(2, 2), i_link(0, 1), i_link(0, 2), i_link(1, 2)));
}

// `link` plus every link hanging off it through fixed joints, except `skip` (the next link on
// the path, which is a segment of its own), in `link`'s frame.
KDL::RigidBodyInertia rigid_body_inertia(const urdf::Link& link, const std::string& skip, std::string& impossible) {
  KDL::RigidBodyInertia total = link_inertia(link, impossible);
  for (const urdf::JointSharedPtr& joint : link.child_joints) {
    if (!joint || joint->type != urdf::Joint::FIXED || joint->child_link_name == skip) continue;
    for (const urdf::LinkSharedPtr& child : link.child_links) {
      if (child && child->name == joint->child_link_name) {
        const KDL::Frame offset =
            checked_frame(joint->parent_to_joint_origin_transform, joint_label(*joint) + " origin");
        total = total + offset * rigid_body_inertia(*child, "", impossible);
      }
    }
  }
  return total;
}

BodyInertia to_body_inertia(const KDL::RigidBodyInertia& rbi) {
  BodyInertia out;
  out.mass = rbi.getMass();
  out.centre_of_mass = to_eigen(rbi.getCOG());
  // KDL stores the inertia about the frame origin; move it back to the centre of mass
  // (parallel-axis theorem, I_c = I_o − m (|c|² 1 − c cᵀ)).
  const KDL::RotationalInertia io = rbi.getRotationalInertia();
  Eigen::Matrix3d i_origin;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) i_origin(i, j) = io.data[3 * i + j];
  const Eigen::Vector3d& c = out.centre_of_mass;
  out.inertia = i_origin - out.mass * (c.squaredNorm() * Eigen::Matrix3d::Identity() - c * c.transpose());
  return out;
}

// Joint limits of one revolute / continuous joint into slot i of `limits`.
void read_limits(const urdf::Joint& joint, int i, JointLimits& limits) {
  const std::string name = joint_label(joint);
  const urdf::JointLimitsSharedPtr& l = joint.limits;
  if (joint.type == urdf::Joint::REVOLUTE) {
    if (!l) throw std::invalid_argument(name + ": a revolute joint needs <limit lower=\"…\" upper=\"…\">");
    require(std::isfinite(l->lower), name + " limit lower", l->lower, "must be finite");
    require(std::isfinite(l->upper), name + " limit upper", l->upper, "must be finite");
    require(l->lower < l->upper, name + " limit (lower, upper)", Eigen::Vector2d(l->lower, l->upper),
            "needs lower < upper");
    limits.lower(i) = l->lower;
    limits.upper(i) = l->upper;
  } else {
    limits.lower(i) = -infinity;
    limits.upper(i) = infinity;
  }
  const auto stated = [&](double value, const char* what) {
    if (!l) return infinity;
    require(std::isfinite(value) && value >= 0.0, name + " limit " + what, value, "must be finite and not negative");
    return value > 0.0 ? value : infinity;  // 0 is urdfdom's "not given"
  };
  limits.velocity(i) = stated(l ? l->velocity : 0.0, "velocity");
  limits.effort(i) = stated(l ? l->effort : 0.0, "effort");
}

// The point of line b (through pb along ub) nearest to line a (through pa along ua); pb when
// the lines are parallel (every point is as near).
Eigen::Vector3d nearest_point_on_line(const Eigen::Vector3d& pa, const Eigen::Vector3d& ua, const Eigen::Vector3d& pb,
                                      const Eigen::Vector3d& ub) {
  const Eigen::Vector3d n = ua.cross(ub);
  const double n2 = n.squaredNorm();
  if (n2 < 1e-18) return pb;
  // pb + s ub with (pb + s ub − pa) ⟂ ua × (ua × ub): the common perpendicular's foot on b.
  const double s = (pb - pa).cross(ua).dot(n) / n2;
  return pb + s * ub;
}

// The links from base_link to tip_link: the path tip → base through the parent joints, then
// reversed. Cycles were refused before urdfdom parsed the text (which accepts some); the walk
// still stops at a repeated link, so it cannot run forever whatever urdfdom builds.
std::vector<urdf::LinkConstSharedPtr> link_path(const urdf::LinkConstSharedPtr& tip, const std::string& base_link,
                                                const std::string& tip_link) {
  std::vector<urdf::LinkConstSharedPtr> path{tip};
  std::set<std::string> visited{tip_link};
  while (path.back()->name != base_link) {
    const urdf::LinkConstSharedPtr parent = path.back()->getParent();
    require(parent != nullptr, "base_link", base_link, "is not an ancestor of tip_link \"" + tip_link + "\"");
    require(visited.insert(parent->name).second, "link", parent->name,
            "is its own ancestor: the URDF's joints form a cycle on the way from tip_link \"" + tip_link + "\"");
    path.push_back(parent);
  }
  std::reverse(path.begin(), path.end());
  return path;
}

// The joints along the path of links, each revolute, continuous or fixed.
std::vector<const urdf::Joint*> path_joints(const std::vector<urdf::LinkConstSharedPtr>& path) {
  std::vector<const urdf::Joint*> joints;
  for (std::size_t k = 1; k < path.size(); ++k) {
    const urdf::Joint& joint = *path[k]->parent_joint;
    switch (joint.type) {
      case urdf::Joint::REVOLUTE:
      case urdf::Joint::CONTINUOUS:
      case urdf::Joint::FIXED:
        break;
      case urdf::Joint::PRISMATIC:
      case urdf::Joint::PLANAR:
      case urdf::Joint::FLOATING:
      default:
        throw std::invalid_argument(joint_label(joint) + " between \"" + joint.parent_link_name + "\" and \"" +
                                    joint.child_link_name +
                                    "\": only revolute, continuous and fixed joints are supported on a serial arm");
    }
    joints.push_back(&joint);
  }
  return joints;
}

// The inertia of every joint's moving body: its segment plus the fixed segments after it.
std::vector<BodyInertia> moving_body_inertias(const KDL::Chain& chain) {
  std::vector<BodyInertia> inertias;
  for (unsigned s = 0; s < chain.getNrOfSegments(); ++s) {
    const KDL::Segment& seg = chain.getSegment(s);
    if (seg.getJoint().getType() == KDL::Joint::Fixed) continue;
    KDL::RigidBodyInertia body = seg.getInertia();
    KDL::Frame to_body = KDL::Frame::Identity();
    for (unsigned f = s + 1; f < chain.getNrOfSegments(); ++f) {
      const KDL::Segment& fixed = chain.getSegment(f);
      if (fixed.getJoint().getType() != KDL::Joint::Fixed) break;
      to_body = to_body * fixed.getFrameToTip();
      body = body + to_body * fixed.getInertia();
    }
    inertias.push_back(to_body_inertia(body));
  }
  return inertias;
}

}  // namespace

SerialArm SerialArm::from_urdf_file(const std::string& path, const std::string& base_link,
                                    const std::string& tip_link) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::invalid_argument(describe("path", path, "cannot be opened"));
  // Read in blocks up to the limit: a larger file is refused without being read to its end.
  std::string text;
  require(input_budget::read_at_most(in, input_budget::max_urdf_bytes, text), "path", path,
          "is larger than " + std::to_string(input_budget::max_urdf_bytes) +
              " bytes, the limit of a URDF (doc/input-budget.md)");
  try {
    return from_urdf_string(text, base_link, tip_link);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(echoed(path) + ": " + e.what());
  }
}

SerialArm SerialArm::from_urdf_string(const std::string& xml, const std::string& base_link,
                                      const std::string& tip_link) {
  require(!base_link.empty(), "base_link", base_link, "must name a link");
  require(!tip_link.empty(), "tip_link", tip_link, "must name a link");
  require(base_link != tip_link, "tip_link", tip_link, "must differ from base_link");
  std::string messages;
  const urdf::ModelInterfaceSharedPtr urdf = parse(xml, messages);
  if (!urdf)
    throw std::invalid_argument("URDF: not a valid robot description" + (messages.empty() ? "" : ": " + messages));

  const urdf::LinkConstSharedPtr base = urdf->getLink(base_link);
  require(base != nullptr, "base_link", base_link, "is not a link of robot \"" + urdf->getName() + "\"");
  const urdf::LinkConstSharedPtr tip = urdf->getLink(tip_link);
  require(tip != nullptr, "tip_link", tip_link, "is not a link of robot \"" + urdf->getName() + "\"");

  const std::vector<urdf::LinkConstSharedPtr> path = link_path(tip, base_link, tip_link);

  auto model = std::make_shared<Model>();
  model->robot_name = urdf->getName();
  model->base_link = base_link;
  model->tip_link = tip_link;
  model->urdf = xml;
  const std::vector<const urdf::Joint*> joints = path_joints(path);

  int n = 0;
  for (const urdf::Joint* joint : joints) n += joint->type == urdf::Joint::FIXED ? 0 : 1;
  require(n > 0, "tip_link", tip_link,
          "has no revolute or continuous joint between it and base_link \"" + base_link + "\"");
  JointLimits& limits = model->limits;
  limits.lower.resize(n);
  limits.upper.resize(n);
  limits.velocity.resize(n);
  limits.effort.resize(n);

  int i = 0;
  for (std::size_t k = 0; k < joints.size(); ++k) {
    const urdf::Joint& joint = *joints[k];
    const urdf::Link& child = *path[k + 1];
    const std::string next = k + 2 < path.size() ? path[k + 2]->name : "";
    const KDL::Frame origin = checked_frame(joint.parent_to_joint_origin_transform, joint_label(joint) + " origin");
    const KDL::RigidBodyInertia inertia = rigid_body_inertia(child, next, model->impossible_inertia);
    if (joint.type == urdf::Joint::FIXED) {
      model->chain.addSegment(KDL::Segment(child.name, KDL::Joint(joint.name, KDL::Joint::Fixed), origin, inertia));
      continue;
    }
    const Eigen::Vector3d axis = checked_vector(joint.axis, joint_label(joint) + " axis");
    require(axis.norm() > 1e-9, joint_label(joint) + " axis", axis, "must not be zero");
    const Eigen::Vector3d unit = axis.normalized();
    // KDL wants the joint's origin and axis in the parent segment's tip frame: the URDF axis
    // is given in the joint frame, which is the URDF origin transform away.
    const KDL::Vector axis_in_parent = origin.M * KDL::Vector(unit.x(), unit.y(), unit.z());
    model->chain.addSegment(KDL::Segment(
        child.name, KDL::Joint(joint.name, origin.p, axis_in_parent, KDL::Joint::RotAxis), origin, inertia));
    model->joint_names.push_back(joint.name);
    read_limits(joint, i, limits);
    ++i;
  }
  // inertias(): the moving body of joint i is its segment plus the fixed segments after it.
  model->inertias = moving_body_inertias(model->chain);
  model->bodies = detail::chain_bodies(model->inertias, link_frames_at_zero(model->chain));

  model->revolute = revolute_chain_of(model->chain);
  model->family = recognise(model->revolute);
  describe_redundancy(model->revolute, model->family, model->joint_names, model->limits, model->lock,
                      model->redundancy);
  // The reference points of configuration() (6R arms).
  if (n == 6) {
    const RevoluteChain& c = model->revolute;
    model->elbow_point = nearest_point_on_line(c.points[4], c.axes[4], c.points[3], c.axes[3]);
    model->shoulder_point = nearest_point_on_line(c.points[5], c.axes[5], c.points[4], c.axes[4]);
  }
  return SerialArm(std::move(model));
}

}  // namespace serial
}  // namespace dispkin
