// Recursive Newton–Euler on the product-of-exponentials chain (chain_dynamics.hpp). Everything
// is in base coordinates, so no frame changes between links are needed: a body's velocity is the
// spatial twist (v, ω) of its motion (v: the velocity of the body point at the base origin), and
// its wrench is (f, n) with the moment n about the base origin (doc/retiming.md (eq. 23)–(eq. 25)).
#include "chain_dynamics.hpp"

#include <array>
#include <cstddef>

#include "chain_pass.hpp"

namespace dispkin {
namespace serial {
namespace detail {
namespace {

// What the tip-to-base pass needs of joint i: its axis at q and the wrench its body needs
// (moving and holding), moments about the base origin.
struct JointState {
  Eigen::Vector3d axis, point;
  Eigen::Vector3d force, moment, holding_force, holding_moment;
};

// Pass: calls its argument visit(i, ωᵢ′, pᵢ′, T₍≤ᵢ₎) for every joint, base to tip (chain_pass, or a
// recorded pass at the same q).
template <typename Pass>
void newton_euler(int joint_count, const std::vector<ChainBody>& bodies, const Eigen::Vector3d& gravity, Pass&& pass,
                  const double* qd, const double* qdd, double* tau, double* holding, JointState* joints) {
  // Base to tip (doc/retiming.md eq. 23): the spatial twist V = (v, ω) and its rate A = (a, α), starting from
  // A₀ = (−g, 0) so that gravity acts as an upward acceleration of the base.
  Eigen::Vector3d v = Eigen::Vector3d::Zero(), w = Eigen::Vector3d::Zero();
  Eigen::Vector3d a = -gravity, alpha = Eigen::Vector3d::Zero();
  pass([&](int i, const Eigen::Vector3d& axis, const Eigen::Vector3d& point, const Posed& motion) {
    const auto k = static_cast<std::size_t>(i);
    const Eigen::Vector3d axis_v = point.cross(axis);  // the joint's twist ξᵢ′ = (pᵢ′ × ωᵢ′, ωᵢ′)
    v += qd[i] * axis_v;
    w += qd[i] * axis;
    // Ȧ adds ξᵢ′ q̈ᵢ and the bracket [V, ξᵢ′] q̇ᵢ (the rate of the moving axis).
    a += qdd[i] * axis_v + qd[i] * (w.cross(axis_v) + v.cross(axis));
    alpha += qdd[i] * axis + qd[i] * w.cross(axis);
    // The body at q (doc/retiming.md eq. 24): centre c, inertia I about c; its centre moves at v + ω × c.
    const ChainBody& body = bodies[k];
    // I x = R I⁰ Rᵀ x, turned by the motion's quaternion: cheaper than forming R I⁰ Rᵀ.
    const Eigen::Quaterniond& r = motion.quaternion();
    const auto inertia_times = [&](const Eigen::Vector3d& x) -> Eigen::Vector3d {
      return r * (body.inertia * (r.conjugate() * x));
    };
    const Eigen::Vector3d c = motion * body.centre_of_mass;
    const Eigen::Vector3d v_c = v + w.cross(c);
    const Eigen::Vector3d a_c = a + alpha.cross(c) + w.cross(v_c);
    JointState& j = joints[k];
    j.axis = axis;
    j.point = point;
    j.force = body.mass * a_c;
    j.moment = inertia_times(alpha) + w.cross(inertia_times(w)) + c.cross(j.force);
    if (holding) {
      j.holding_force = body.mass * -gravity;
      j.holding_moment = c.cross(j.holding_force);
    }
  });
  // Tip to base (doc/retiming.md eq. 25): joint i carries the wrench of every body from i on; its torque is
  // that moment about the axis, taken about a point of the axis.
  Eigen::Vector3d f = Eigen::Vector3d::Zero(), n = Eigen::Vector3d::Zero();
  Eigen::Vector3d f_hold = Eigen::Vector3d::Zero(), n_hold = Eigen::Vector3d::Zero();
  for (int i = joint_count - 1; i >= 0; --i) {
    const JointState& j = joints[static_cast<std::size_t>(i)];
    f += j.force;
    n += j.moment;
    tau[i] = j.axis.dot(n - j.point.cross(f));
    if (holding) {
      f_hold += j.holding_force;
      n_hold += j.holding_moment;
      holding[i] = j.axis.dot(n_hold - j.point.cross(f_hold));
    }
  }
}

}  // namespace

std::vector<ChainBody> chain_bodies(const std::vector<BodyInertia>& inertias, const std::vector<Posed>& frames) {
  std::vector<ChainBody> out;
  out.reserve(inertias.size());
  for (std::size_t i = 0; i < inertias.size(); ++i) {
    const Eigen::Matrix3d r = frames[i].rotation();
    out.push_back({inertias[i].mass, frames[i] * inertias[i].centre_of_mass, r * inertias[i].inertia * r.transpose()});
  }
  return out;
}

void chain_torques(const RevoluteChain& chain, const std::vector<ChainBody>& bodies, const Eigen::Vector3d& gravity,
                   const double* q, const double* qd, const double* qdd, double* tau, double* holding) {
  constexpr std::size_t small = 16;
  const int n = chain.dof();
  const auto pass = [&](auto&& visit) { chain_pass(chain, q, visit); };
  if (static_cast<std::size_t>(n) <= small) {
    std::array<JointState, small> joints;
    newton_euler(n, bodies, gravity, pass, qd, qdd, tau, holding, joints.data());
  } else {
    std::vector<JointState> joints(static_cast<std::size_t>(n));
    newton_euler(n, bodies, gravity, pass, qd, qdd, tau, holding, joints.data());
  }
}

void chain_torques(const ChainPassRecord& record, const std::vector<ChainBody>& bodies, const Eigen::Vector3d& gravity,
                   const double* qd, const double* qdd, double* tau, double* holding) noexcept {
  const auto pass = [&](auto&& visit) {
    for (int i = 0; i < record.joints; ++i) {
      const auto k = static_cast<std::size_t>(i);
      visit(i, record.axes[k], record.points[k], record.motions[k]);
    }
  };
  std::array<JointState, max_recorded_joints> joints;
  newton_euler(record.joints, bodies, gravity, pass, qd, qdd, tau, holding, joints.data());
}

}  // namespace detail
}  // namespace serial
}  // namespace dispkin
