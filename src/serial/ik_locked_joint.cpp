// Inverse kinematics of a 7R chain with its first or last joint locked (redundancy.hpp,
// doc/inverse-kinematics.md §11): the 6R chain left, read from the base or from the tip, solved by
// its closed form for each value of the locked joint.
#include "dispkin/serial/redundancy.hpp"

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "angles.hpp"
#include "dispkin/error.hpp"

namespace dispkin {
namespace serial {
namespace {

// The 6R chain of joints [first, first + 6) with the 7R chain's tip M (doc/inverse-kinematics.md eqs. 37, 38).
RevoluteChain rest_of(const RevoluteChain& chain, int first) {
  RevoluteChain rest;
  for (int i = first; i < first + 6; ++i) {
    rest.axes.push_back(chain.axes[static_cast<std::size_t>(i)]);
    rest.points.push_back(chain.points[static_cast<std::size_t>(i)]);
  }
  rest.tip_at_zero = chain.tip_at_zero;
  return rest;
}

// The 6R chain S read from the tip back (doc/inverse-kinematics.md eq. 39): S′(x′) = S(x)⁻¹ with x′ₖ = −x₇₋ₖ.
RevoluteChain reversed(const RevoluteChain& s) {
  RevoluteChain r;
  const Posed n_inv = s.tip_at_zero.inverse();
  for (int k = 5; k >= 0; --k) {
    const auto i = static_cast<std::size_t>(k);
    r.axes.push_back(n_inv.quaternion() * s.axes[i]);
    r.points.push_back(n_inv * s.points[i]);
  }
  r.tip_at_zero = n_inv;
  return r;
}

bool has_closed_form(IkFamily f) { return f == IkFamily::spherical_wrist || f == IkFamily::three_parallel; }

}  // namespace

LockedJoint find_locked_joint(const RevoluteChain& chain) {
  LockedJoint lock;
  if (chain.dof() != 7 || chain.points.size() != 7) return lock;
  // Locking an end joint moves the rest of the chain rigidly (doc/inverse-kinematics.md eqs. 37, 38): its family is one
  // for all values.
  for (const int joint : {6, 0}) {
    const RevoluteChain rest = rest_of(chain, joint == 6 ? 0 : 1);
    for (const bool from_tip : {false, true}) {
      RevoluteChain candidate = from_tip ? reversed(rest) : rest;
      const IkFamily family = recognise(candidate);
      if (!has_closed_form(family)) continue;
      lock.joint = joint;
      lock.reversed = from_tip;
      lock.rest = std::move(candidate);
      lock.family = family;
      return lock;
    }
  }
  return lock;
}

void locked_joint_inverse(const RevoluteChain& chain, const LockedJoint& lock, double value, const Posed& pose,
                          std::vector<Eigen::VectorXd>& out) {
  require_finite(value, "redundancy");
  require(lock.found(), "lock.joint", lock.joint, "no locked joint leaves a closed form");
  // The pose the 6R chain must reach (doc/inverse-kinematics.md eq. 37 / 38), inverted when it is read from the tip
  // (eq. 39).
  const auto j = static_cast<std::size_t>(lock.joint);
  const Posed unlock = rotation_about_line(chain.axes[j], chain.points[j], -value);
  Posed target = lock.joint == 6 ? pose * (chain.tip_at_zero.inverse() * unlock * chain.tip_at_zero) : unlock * pose;
  if (lock.reversed) target = target.inverse();
  IkSolutionSet set;
  analytic_inverse(lock.rest, lock.family, target, set);
  const int offset = lock.joint == 0 ? 1 : 0;
  for (int s = 0; s < set.count; ++s) {
    Eigen::VectorXd q(7);
    for (int k = 0; k < 6; ++k) q(offset + k) = lock.reversed ? -set[s](5 - k) : set[s](k);
    q(lock.joint) = value;
    out.push_back(std::move(q));
  }
}

double Redundancy::value(const Eigen::VectorXd& q) const {
  require(has_parameter(), "redundancy", kind, "the arm has no redundancy parameter");
  if (q.size() != dof)
    throw std::invalid_argument(
        describe("q", q, "expected " + std::to_string(dof) + " joint values, got " + std::to_string(q.size())));
  require_finite(q, "q");
  return q(joint);
}

std::vector<double> Redundancy::default_values() const {
  std::vector<double> values;
  if (!has_parameter()) return values;
  // Centres of equal parts (doc/inverse-kinematics.md eq. 40): never a range end, where a joint limit sits.
  const double width = (upper - lower) / default_value_count;
  for (int k = 0; k < default_value_count; ++k) values.push_back(lower + (k + 0.5) * width);
  return values;
}

}  // namespace serial
}  // namespace dispkin
