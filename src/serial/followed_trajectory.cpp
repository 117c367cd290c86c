// A Cartesian trajectory as joint motion along the arm's IK branch (followed_trajectory.hpp,
// doc/ptp.md eqs. 17–20).
#include "dispkin/serial/followed_trajectory.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

#include "dispkin/error.hpp"
#include "dispkin/serial/chain_kinematics.hpp"
#include "cubic_hermite.hpp"
#include "joint_following.hpp"
#include "redundancy_rule.hpp"
#include "redundancy_schedule.hpp"

namespace dispkin::serial {

namespace {

using detail::Hermite;

// A section's grid is halved at most this many times (64 × finer than `spacing`): the cubic
// Hermite error falls as h⁴, so a motion that still misses the midpoint check then is not smooth
// on this branch (a branch change, a near-singular spike).
constexpr int max_refinements = 6;

[[noreturn]] void not_followed(double s, const std::string& why) {
  throw std::invalid_argument(
      describe("trajectory", s, "the arm cannot follow it on its branch at this path position (m): " + why));
}

// The joints of one section on nodes τ_i = i/n, entered at τ = 0 (forward) or τ = 1 (backwards)
// with q_in, and the largest midpoint error; throws through not_followed.
struct SectionNodes {
  std::vector<Eigen::VectorXd> q, rate;
  double midpoint_error = 0.0;
};

class SectionFollower {
 public:
  SectionFollower(const Trajectory& trajectory, const SerialArm& arm, const detail::RedundancySchedule& parameter)
      : path_(trajectory.path()), arm_(arm), limits_(arm.joint_limits()), parameter_(parameter) {}

  SectionNodes follow(std::size_t k, int n, const Eigen::VectorXd& q_in, bool backwards) const {
    SectionNodes out;
    out.q.resize(static_cast<std::size_t>(n) + 1);
    out.rate.resize(static_cast<std::size_t>(n) + 1);
    const int entry = backwards ? n : 0, step = backwards ? -1 : 1;
    for (int i = entry, done = 0; done <= n; i += step, ++done) {
      const double tau = static_cast<double>(i) / n;
      Posed pose;
      Twistd per_tau;
      path_.section_state_at(k, tau, pose, per_tau);
      const auto idx = static_cast<std::size_t>(i);
      if (done == 0) {
        out.q[idx] = q_in;
      } else {
        const auto prev = static_cast<std::size_t>(i - step);
        // Predicted by the previous node's rate: Newton's tracking starts on the branch.
        const Eigen::VectorXd guess = out.q[prev] + (tau - static_cast<double>(i - step) / n) * out.rate[prev];
        out.q[idx] = solve(k, tau, pose, out.q[prev], guess);
      }
      out.rate[idx] = rate_of(k, tau, out.q[idx], per_tau);
    }
    // The check of doc/ptp.md eq. 20 at every interval's middle.
    const Hermite middle{0.5, 1.0 / n};
    for (int i = 0; i < n; ++i) {
      const auto a = static_cast<std::size_t>(i), b = a + 1;
      const Eigen::VectorXd h = middle.value(out.q[a], out.rate[a], out.q[b], out.rate[b]);
      const double tau = (i + 0.5) / n;
      Posed pose;
      Twistd per_tau;
      path_.section_state_at(k, tau, pose, per_tau);
      const Eigen::VectorXd q = solve(k, tau, pose, h, h);
      out.midpoint_error = std::max(out.midpoint_error, (q - h).lpNorm<Eigen::Infinity>());
    }
    return out;
  }

 private:
  double s_at(std::size_t k, double tau) const { return path_.section_start(k) + tau * path_.section_lengths()[k]; }

  Eigen::VectorXd solve(std::size_t k, double tau, const Posed& pose, const Eigen::VectorXd& q_ref,
                        const Eigen::VectorXd& guess) const {
    Eigen::VectorXd q;
    try {
      // A moving parameter: the solution at θ(s) (doc/inverse-kinematics.md eq. 50) on q_ref's branch.
      const Eigen::VectorXd reference =
          parameter_.moves() ? parameter_.reference(q_ref, parameter_.at(k, tau).value) : q_ref;
      q = detail::branch_solution(arm_, pose, reference, std::numeric_limits<double>::quiet_NaN(), s_at(k, tau),
                                  &guess);
    } catch (const std::runtime_error& e) {
      not_followed(s_at(k, tau), e.what());
    }
    for (Eigen::Index j = 0; j < q.size(); ++j) {
      if (!(q(j) >= limits_.lower(j) - 1e-9 && q(j) <= limits_.upper(j) + 1e-9)) {
        not_followed(s_at(k, tau), "joint " + std::to_string(j + 1) + " would be at " + std::to_string(q(j)) +
                                       " rad, outside its range [" + std::to_string(limits_.lower(j)) + ", " +
                                       std::to_string(limits_.upper(j)) + "]");
      }
    }
    return q;
  }

  // q′ = J_b(q)⁻¹ ξ_τ (doc/ptp.md eq. 17); a moving parameter turns at θ′ = dθ/ds · L_k per τ
  // (doc/inverse-kinematics.md eq. 47).
  Eigen::VectorXd rate_of(std::size_t k, double tau, const Eigen::VectorXd& q, const Twistd& per_tau) const {
    const double parameter_rate = parameter_.moves() ? parameter_.at(k, tau).rate * path_.section_lengths()[k] : 0.0;
    try {
      return detail::joint_velocity(arm_, q, per_tau, std::numeric_limits<double>::quiet_NaN(), s_at(k, tau),
                                    parameter_rate);
    } catch (const std::runtime_error& e) {
      not_followed(s_at(k, tau), e.what());
    }
  }

  const SampledPath& path_;
  const SerialArm& arm_;
  JointLimits limits_;
  const detail::RedundancySchedule& parameter_;
};

}  // namespace

FollowedTrajectory FollowedTrajectory::from_start(Trajectory trajectory, const SerialArm& arm,
                                                  const Eigen::VectorXd& q_start, double spacing,
                                                  const RedundancyRule& redundancy_rule) {
  return FollowedTrajectory(std::move(trajectory), arm, q_start, false, spacing, redundancy_rule);
}

FollowedTrajectory FollowedTrajectory::to_end(Trajectory trajectory, const SerialArm& arm, const Eigen::VectorXd& q_end,
                                              double spacing, const RedundancyRule& redundancy_rule) {
  return FollowedTrajectory(std::move(trajectory), arm, q_end, true, spacing, redundancy_rule);
}

FollowedTrajectory::FollowedTrajectory(Trajectory trajectory, const SerialArm& arm, const Eigen::VectorXd& q_given,
                                       bool backwards, double spacing, const RedundancyRule& redundancy_rule)
    : trajectory_(std::move(trajectory)), chain_(arm.chain()) {
  const char* given = backwards ? "q_end" : "q_start";
  require(arm.dof() == 6 || arm.redundancy().has_parameter(), "arm", static_cast<long>(arm.dof()),
          "joints: following a Cartesian trajectory inverts the Jacobian, so the arm must have 6, or 7 with a "
          "redundancy parameter (SerialArm::redundancy())");
  require(q_given.size() == arm.dof(), given, static_cast<long>(q_given.size()),
          "entries: must have one per joint of the arm (" + std::to_string(arm.dof()) + ")");
  require_finite(q_given, given);
  // Below 10 µm a grid only costs memory (doc/ptp.md eq. 20 refines where a motion needs it).
  require(std::isfinite(spacing) && spacing >= 1e-5 && spacing <= 1.0, "spacing", spacing, "must be in [1e-5, 1] m");
  require(trajectory_.section_count() > 0, "trajectory", static_cast<long>(trajectory_.section_count()),
          "sections: must have at least one");
  const Posed wanted = trajectory_.sample(backwards ? trajectory_.duration() : 0.0).pose;
  const Posed reached = chain_pose(chain_, q_given.data());
  require(reached.is_approx(wanted, 1e-9), given, q_given,
          std::string("its forward kinematics must be the trajectory's ") + (backwards ? "end" : "start") +
              " pose to 1e-9 (translation off by " +
              std::to_string((reached.translation() - wanted.translation()).norm()) + " m)");

  const SampledPath& path = trajectory_.path();
  const std::size_t sections = path.section_count();
  std::vector<SectionNodes> nodes(sections);
  detail::require_valid(redundancy_rule);
  // The parameter's schedule on the unrefined grid, so that every refined interval lies in one of
  // its Hermite pieces and the joints stay smooth inside it (doc/inverse-kinematics.md eq. 50).
  detail::RedundancySchedule parameter;
  try {
    parameter = detail::RedundancySchedule(path, arm, q_given, backwards, spacing, redundancy_rule);
  } catch (const std::runtime_error& e) {
    throw std::invalid_argument(
        describe("trajectory", trajectory_.length(),
                 std::string("the arm cannot follow it with its redundancy parameter moved: ") + e.what()));
  }
  const SectionFollower follower(trajectory_, arm, parameter);
  Eigen::VectorXd q_in = q_given;
  for (std::size_t done = 0; done < sections; ++done) {
    const std::size_t k = backwards ? sections - 1 - done : done;
    const double length = path.section_lengths()[k];
    int n = static_cast<int>(std::min(std::ceil(length / spacing), 1e6));
    n = std::max(n, 1);
    for (int refinement = 0;; ++refinement, n *= 2) {
      nodes[k] = follower.follow(k, n, q_in, backwards);
      if (nodes[k].midpoint_error <= midpoint_tolerance) break;
      if (refinement == max_refinements) {
        not_followed(path.section_start(k),
                     "the joints between nodes " + std::to_string(length / n) + " m apart still miss the branch by " +
                         std::to_string(nodes[k].midpoint_error) + " rad (a branch change or a near-singular pose)");
      }
    }
    midpoint_error_ = std::max(midpoint_error_, nodes[k].midpoint_error);
    q_in = backwards ? nodes[k].q.front() : nodes[k].q.back();
  }

  Eigen::Index total = 0;
  for (const SectionNodes& s : nodes) total += static_cast<Eigen::Index>(s.q.size());
  nodes_q_.resize(arm.dof(), total);
  nodes_rate_.resize(arm.dof(), total);
  grids_.reserve(sections);
  Eigen::Index column = 0;
  for (const SectionNodes& s : nodes) {
    grids_.push_back({column, static_cast<int>(s.q.size()) - 1});
    for (std::size_t i = 0; i < s.q.size(); ++i, ++column) {
      nodes_q_.col(column) = s.q[i];
      nodes_rate_.col(column) = s.rate[i];
    }
  }
  start_ = nodes_q_.col(0);
  end_ = nodes_q_.col(total - 1);
}

JointTrajectorySample FollowedTrajectory::sample(double t) const noexcept {
  const SampledPath& path = trajectory_.path();
  const double duration = trajectory_.duration();
  const double time = t >= duration ? duration : (t > 0.0 ? t : 0.0);  // NaN: the start
  std::size_t piece = trajectory_.time_law().size();                   // no hint: the law Trajectory::sample finds
  const ProfileState state = trajectory_.time_law().state_at(time, piece);
  // The ends are the end nodes exactly (s at the end may round off the last section's length).
  std::size_t k = 0;
  double tau = 0.0;
  if (time >= duration) {
    k = grids_.size() - 1;
    tau = 1.0;
  } else if (time > 0.0) {
    k = path.section_at(state.s, grids_.size());
    tau = std::clamp((state.s - path.section_start(k)) * path.inverse_length(k), 0.0, 1.0);
  }
  const SectionGrid& grid = grids_[k];
  const int i = std::min(static_cast<int>(tau * grid.intervals), grid.intervals - 1);
  const Hermite at{tau * grid.intervals - i, 1.0 / grid.intervals};
  const Eigen::Index a = grid.first + i, b = a + 1;
  const auto q0 = nodes_q_.col(a), q1 = nodes_q_.col(b), m0 = nodes_rate_.col(a), m1 = nodes_rate_.col(b);
  // Per unit s: the section's τ runs at 1/L_k (doc/ptp.md eq. 19).
  const double per_s = path.inverse_length(k);
  JointTrajectorySample out;
  out.q = at.value(q0, m0, q1, m1);
  const JointVector dq_ds = per_s * at.rate(q0, m0, q1, m1);
  const JointVector d2q_ds2 = (per_s * per_s) * at.curvature(q0, m0, q1, m1);
  out.qd = dq_ds * state.v;
  out.qdd = d2q_ds2 * (state.v * state.v) + dq_ds * state.a;
  out.s = state.s;
  out.s_dot = state.v;
  out.s_ddot = state.a;
  out.u = trajectory_.length() > 0.0 ? state.s / trajectory_.length() : 0.0;
  chain_pose_and_twist(chain_, out.q.data(), out.qd.data(), out.pose, out.body_twist);
  return out;
}

}  // namespace dispkin::serial
