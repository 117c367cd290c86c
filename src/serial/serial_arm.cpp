// The serial-arm plugin: the product-of-exponentials view of the KDL chain, on which forward
// kinematics, the Jacobians and the analytic IK work, and the dynamics through Orocos KDL.
#include "dispkin/serial/serial_arm.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>

#include <Eigen/Geometry>
#include <Eigen/SVD>
#include <kdl/chainidsolver_recursive_newton_euler.hpp>
#include <kdl/jntarray.hpp>

#include "dispkin/error.hpp"
#include "dispkin/serial/chain_kinematics.hpp"
#include "angles.hpp"
#include "chain_dynamics.hpp"
#include "serial_arm_model.hpp"

namespace dispkin {
namespace serial {
namespace {

KDL::JntArray to_jnt_array(const Eigen::VectorXd& q) {
  KDL::JntArray out(static_cast<unsigned>(q.size()));
  out.data = q;
  return out;
}

int sign_of(double x) { return x > 1e-9 ? 1 : (x < -1e-9 ? -1 : 0); }

}  // namespace

RevoluteChain revolute_chain_of(const KDL::Chain& chain) {
  RevoluteChain out;
  KDL::Frame t = KDL::Frame::Identity();  // base → the current segment's root, at q = 0
  for (unsigned s = 0; s < chain.getNrOfSegments(); ++s) {
    const KDL::Segment& seg = chain.getSegment(s);
    const KDL::Joint& joint = seg.getJoint();
    if (joint.getType() != KDL::Joint::Fixed) {
      if (joint.getType() != KDL::Joint::RotAxis)
        throw std::logic_error("revolute_chain_of: joint \"" + joint.getName() + "\" is not a rotation about an axis");
      out.axes.push_back(to_eigen(t.M * joint.JointAxis()).normalized());
      out.points.push_back(to_eigen(t * joint.JointOrigin()));
    }
    t = t * seg.pose(0.0);
  }
  out.tip_at_zero = to_pose(t);
  return out;
}

std::vector<Posed> link_frames_at_zero(const KDL::Chain& chain) {
  std::vector<Posed> frames;
  KDL::Frame t = KDL::Frame::Identity();
  for (unsigned s = 0; s < chain.getNrOfSegments(); ++s) {
    const KDL::Segment& seg = chain.getSegment(s);
    t = t * seg.pose(0.0);
    if (seg.getJoint().getType() != KDL::Joint::Fixed) frames.push_back(to_pose(t));
  }
  return frames;
}

SerialArm::SerialArm(std::shared_ptr<const Model> model) : model_(std::move(model)) {}

const std::string& SerialArm::robot_name() const noexcept { return model_->robot_name; }
const std::string& SerialArm::urdf() const noexcept { return model_->urdf; }
const std::string& SerialArm::base_link() const noexcept { return model_->base_link; }
const std::string& SerialArm::tip_link() const noexcept { return model_->tip_link; }
int SerialArm::dof() const { return static_cast<int>(model_->joint_names.size()); }
JointLimits SerialArm::joint_limits() const { return model_->limits; }
std::vector<std::string> SerialArm::joint_names() const { return model_->joint_names; }

SerialArm SerialArm::with_joint_limits(const JointLimits& limits) const {
  require_joint_limits(limits, static_cast<Eigen::Index>(dof()), [this](Eigen::Index i) {
    return "joint \"" + model_->joint_names[static_cast<std::size_t>(i)] + "\"";
  });
  auto model = std::make_shared<Model>(*model_);
  model->limits = limits;
  describe_redundancy(model->revolute, model->family, model->joint_names, model->limits, model->lock,
                      model->redundancy);
  return SerialArm(std::move(model));
}

void describe_redundancy(const RevoluteChain& chain, IkFamily family, const std::vector<std::string>& joint_names,
                         const JointLimits& limits, LockedJoint& lock, Redundancy& r) {
  lock = LockedJoint{};
  r = Redundancy{};
  if (family != IkFamily::locked_joint) return;
  lock = find_locked_joint(chain);
  r.kind = "locked_joint";
  r.joint = lock.joint;
  r.joint_name = joint_names[static_cast<std::size_t>(r.joint)];
  r.dof = chain.dof();
  // A joint whose limits span more than a turn (or none) takes every value in one turn.
  const double lo = limits.lower(r.joint), hi = limits.upper(r.joint);
  const bool within_a_turn = std::isfinite(lo) && std::isfinite(hi) && hi - lo <= detail::two_pi;
  r.lower = within_a_turn ? lo : -detail::pi;
  r.upper = within_a_turn ? hi : detail::pi;
}

const Redundancy& SerialArm::redundancy() const noexcept { return model_->redundancy; }
std::vector<BodyInertia> SerialArm::inertias() const { return model_->inertias; }
const RevoluteChain& SerialArm::chain() const noexcept { return model_->revolute; }
IkFamily SerialArm::family() const noexcept { return model_->family; }

void SerialArm::require_joint_vector(const Eigen::VectorXd& q, const char* name) const {
  if (q.size() != dof())
    throw std::invalid_argument(
        describe(name, q, "expected " + std::to_string(dof()) + " joint values, got " + std::to_string(q.size())));
  require_finite(q, name);
}

// Forward kinematics and the Jacobians on the product-of-exponentials chain (chain_kinematics.hpp):
// revolute_chain_of holds every moving joint of the KDL chain with its fixed segments folded in.
Posed SerialArm::forward(const Eigen::VectorXd& q) const {
  require_joint_vector(q, "q");
  return chain_pose(model_->revolute, q.data());
}

Eigen::MatrixXd SerialArm::jacobian(const Eigen::VectorXd& q) const {
  require_joint_vector(q, "q");
  Eigen::Matrix<double, 6, Eigen::Dynamic> j(6, dof());
  chain_jacobian(model_->revolute, q.data(), j);
  return j;
}

Eigen::MatrixXd SerialArm::body_jacobian(const Eigen::VectorXd& q) const {
  require_joint_vector(q, "q");
  Eigen::Matrix<double, 6, Eigen::Dynamic> j(6, dof());
  chain_body_jacobian(model_->revolute, q.data(), j);
  return j;
}

Eigen::VectorXd joint_velocity(const SerialArm& arm, const Eigen::VectorXd& q, const Twistd& body_twist) {
  Eigen::MatrixXd j = arm.body_jacobian(q);
  const int locked = arm.redundancy().joint;
  if (locked >= 0) {
    // A redundant arm at one parameter value: the locked joint does not move (doc/inverse-kinematics.md (eq. 42)).
    const Eigen::Index n = j.cols();
    j.block(0, locked, 6, n - 1 - locked) = j.block(0, locked + 1, 6, n - 1 - locked).eval();
    j.conservativeResize(6, n - 1);
    Eigen::JacobiSVD<Eigen::MatrixXd> svd(j, Eigen::ComputeThinU | Eigen::ComputeThinV);
    svd.setThreshold(std::numeric_limits<double>::epsilon() *
                     static_cast<double>(std::max<Eigen::Index>(j.rows(), j.cols())));
    const Eigen::VectorXd moving = svd.solve(body_twist.vector());
    Eigen::VectorXd qd(n);
    qd << moving.head(locked), 0.0, moving.tail(n - 1 - locked);
    return qd;
  }
  // The cut-off of a least-squares solver (LAPACK's gelsd): ε · max(rows, cols) of the largest singular value.
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(j, Eigen::ComputeThinU | Eigen::ComputeThinV);
  svd.setThreshold(std::numeric_limits<double>::epsilon() *
                   static_cast<double>(std::max<Eigen::Index>(j.rows(), j.cols())));
  return svd.solve(body_twist.vector());
}

void SerialArm::set_gravity(const Eigen::Vector3d& gravity) {
  // Within the numeric range of lengths and masses (1e12), products of the three stay far from
  // overflow in the torques; 1e308 m/s² gave infinite terms and NaN torques.
  require_finite(gravity, "gravity");
  require(gravity.cwiseAbs().maxCoeff() <= numeric_range::max_limit, "gravity", gravity,
          "must have coordinates within ±1e12 m/s² (dispkin's numeric range)");
  gravity_ = gravity;
}

void SerialArm::require_dynamics() const {
  if (!model_->impossible_inertia.empty())
    throw std::invalid_argument(model_->impossible_inertia + ": the torques of robot \"" + model_->robot_name +
                                "\" need a rigid body's inertia on every link from base_link to tip_link");
}

// Recursive Newton–Euler on the product-of-exponentials chain (chain_dynamics.hpp): the pass of
// forward() and jacobian(), no per-call solver or KDL chain (it matches KDL's ChainIdSolver_RNE to
// rounding: test_serial_dynamics.cpp).
Eigen::VectorXd SerialArm::torques(const Eigen::VectorXd& q, const Eigen::VectorXd& qd,
                                   const Eigen::VectorXd& qdd) const {
  require_joint_vector(q, "q");
  require_joint_vector(qd, "qd");
  require_joint_vector(qdd, "qdd");
  require_dynamics();
  Eigen::VectorXd tau(dof());
  detail::chain_torques(model_->revolute, model_->bodies, gravity_, q.data(), qd.data(), qdd.data(), tau.data(),
                        nullptr);
  return tau;
}

void SerialArm::torques(const Eigen::VectorXd& q, const Eigen::VectorXd& qd, const Eigen::VectorXd& qdd,
                        Eigen::VectorXd& tau, Eigen::VectorXd& holding) const {
  require_joint_vector(q, "q");
  require_joint_vector(qd, "qd");
  require_joint_vector(qdd, "qdd");
  require_dynamics();
  tau.resize(dof());
  holding.resize(dof());
  detail::chain_torques(model_->revolute, model_->bodies, gravity_, q.data(), qd.data(), qdd.data(), tau.data(),
                        holding.data());
}

Eigen::VectorXd SerialArm::static_torques(const Eigen::VectorXd& q) const {
  require_joint_vector(q, "q");
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(dof());
  return torques(q, zero, zero);
}

namespace detail {

void recorded_torques(const SerialArm& arm, const ChainPassRecord& record, const Eigen::VectorXd& qd,
                      const Eigen::VectorXd& qdd, Eigen::VectorXd& tau, Eigen::VectorXd& holding) {
  ArmAccess::require_joint_vector(arm, qd, "qd");
  ArmAccess::require_joint_vector(arm, qdd, "qdd");
  ArmAccess::require_dynamics(arm);
  tau.resize(arm.dof());
  holding.resize(arm.dof());
  chain_torques(record, ArmAccess::model(arm).bodies, arm.gravity(), qd.data(), qdd.data(), tau.data(), holding.data());
}

Eigen::VectorXd torques_by_kdl(const SerialArm& arm, const Eigen::VectorXd& q, const Eigen::VectorXd& qd,
                               const Eigen::VectorXd& qdd) {
  // KDL's joints keep their last pose in mutable members (KDL::Joint::pose): a copy of the chain
  // per call keeps this thread-safe (it is a reference for tests, not on any hot path).
  KDL::Chain chain = ArmAccess::model(arm).chain;
  const Eigen::Vector3d& g = arm.gravity();
  KDL::ChainIdSolver_RNE solver(chain, KDL::Vector(g.x(), g.y(), g.z()));
  const KDL::Wrenches no_external(chain.getNrOfSegments(), KDL::Wrench::Zero());
  KDL::JntArray tau(static_cast<unsigned>(arm.dof()));
  if (solver.CartToJnt(to_jnt_array(q), to_jnt_array(qd), to_jnt_array(qdd), no_external, tau) < 0)
    throw std::runtime_error("torques: KDL ChainIdSolver_RNE failed");
  return tau.data;
}

}  // namespace detail

Configuration SerialArm::configuration(const Eigen::VectorXd& q) const {
  require(dof() == 6, "dof", dof(), "configuration flags are defined for 6R arms");
  require_joint_vector(q, "q");
  const RevoluteChain& c = model_->revolute;
  // Axis i at q is axis i at 0 moved by joints 1 … i−1.
  Eigen::Vector3d w[6], p[6];
  Posed t;
  Posed t4;  // joints 1 … 4: moves both reference points (joint 5 turns about the line of one)
  for (int i = 0; i < 6; ++i) {
    w[i] = t.quaternion() * c.axes[static_cast<std::size_t>(i)];
    p[i] = t * c.points[static_cast<std::size_t>(i)];
    t = t * rotation_about_line(c.axes[static_cast<std::size_t>(i)], c.points[static_cast<std::size_t>(i)], q(i));
    if (i == 3) t4 = t;
  }
  const Eigen::Vector3d s = t4 * model_->shoulder_point;
  const Eigen::Vector3d e = t4 * model_->elbow_point;
  Configuration out;
  out.shoulder = sign_of((s - p[0]).dot(w[1].cross(w[0])));
  out.elbow = sign_of(w[2].dot((p[2] - p[1]).cross(e - p[2])));
  out.wrist = sign_of(w[4].dot(w[3].cross(w[5])));
  return out;
}

}  // namespace serial
}  // namespace dispkin
