//! PTP (joint-space) moves of a serial arm planned under the DISP point-set limit.
//!
//! A PTP move is the joint line q(u) = q_a + u Δq, Δq = q_b − q_a, u ∈ [0, 1] (JointPath). The
//! tool follows T(q(u)); its body twist per unit u is J_b(q(u)) Δq. The planner cuts [0, 1]
//! into joint sections [u_k, u_k+1] and bounds, per section, the fastest point or sphere of
//! the metric set per unit of the section parameter τ = (u − u_k)/h_k (h_k = u_k+1 − u_k):
//!
//!   L_k = max over groups g of  w_g · ( V_g(½) + ½ A_g ),   w_g = v_sys / v_g,
//!
//! with V_g(½) the exact fastest speed of the group at the section's middle (doc/disp-metric.md §6: points,
//! absolute points seen from the tool, spheres by the exact sphere formula) and A_g a bound of
//! the acceleration per τ² of every object of the group over the section (a Lipschitz bound of
//! its velocity, derived from the chain geometry — see doc/ptp.md). Along the section ‖x′(τ) − x′(½)‖ ≤ |τ − ½| A_g ≤ ½
//! A_g, so no object moves faster than L_k per unit τ: the planner's section guarantee (doc/planning.md §2), the same
//! construction as CurveSection (speed at the middle + half the acceleration bound).
//!
//! Cutting rule: a section is halved until L_k − V(½) ≤ tolerance · max(V(½), V_floor), V(½) =
//! maxg w_g V_g(½) (the bound is then within `tolerance` of the speed sampled at its middle, hence
//! of the section's sampled maximum), with V_floor = 1 % of the move's fastest pace (the largest
//! V(½) per unit u of the initial eight sections) times the section's span h_k: sections that crawl are not
//! resolved finer than 1 % of the move's pace. Sections where (almost) no point moves are
//! lengthened to that 1 % pace (lengthening only slows down). Then neighbouring sections are
//! halved until their h_k / L_k differ by at most 1 % (the planner's junction rule; here it keeps
//! the rate below from dropping by more than 1 % at a junction). No section is shorter than 2⁻¹⁶.
//!
//! Time law and velocity-limit curve: s is the DISP arc length. The rate du/ds is continuous: at
//! each section junction it is the smaller of the two sections' h_k / L_k (at the ends their own),
//! linear in u inside a section (du/ds = r₀ + m (u − u_k)), so never above h_k / L_k there: every
//! object of the set moves at most at ṡ · (its weight)⁻¹, and the joint velocities
//! q̇ = Δq (du/ds) ṡ are continuous; q̈ = Δq ((du/ds) s̈ + m (du/ds) ṡ²). Per section the speed
//! limit is the smallest of v_sys; q̇maxᵢ / (|Δqᵢ| r_max) (the joint velocity limits, r_max the
//! section's larger end rate); √(a / (A_k / L_k² + |m|)) (the planner's curvature rule: a point
//! accelerates at most at ṡ² (A_k / L_k² + |m|) from the path's bending and the changing rate,
//! A_k the largest unweighted A_g); with joint acceleration limits √(0.1 q̈maxᵢ / (|Δqᵢ| |m| r_max))
//! (a tenth of q̈max for the rate's change). It is rounded down to a staircase of 5 % steps
//! (v_sys, 0.95 v_sys, …; the planner's rule with a finer step because a joint limit, not a
//! curvature, usually binds), and the time law is velocity_limited_law over those segments, rest to
//! rest: the speed drops only where a section is slower. Joint acceleration limits (optional) also
//! lower the law's acceleration limit to min(a, min_k minᵢ 0.9 q̈maxᵢ / (|Δqᵢ| r_max)). Every joint
//! moves on the line, so all of them start and end together (a synchronized PTP).
#pragma once

#include <cstddef>
#include <optional>
#include <vector>

#include <Eigen/Core>

#include "dispkin/path/curve_section.hpp"
#include "dispkin/metric_set.hpp"
#include "dispkin/path/path.hpp"
#include "dispkin/planning/planner.hpp"
#include "dispkin/planning/time_law.hpp"
#include "dispkin/planning/trajectory.hpp"
#include "dispkin/pose.hpp"
#include "dispkin/profile.hpp"
#include "dispkin/serial/revolute_chain.hpp"
#include "dispkin/serial/serial_arm.hpp"

namespace dispkin::serial {

//! The largest number of joints a JointTrajectory samples without allocating.
constexpr int max_ptp_joints = 12;

//! A joint vector of at most max_ptp_joints entries, stored inline (no heap).
using JointVector = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, max_ptp_joints, 1>;

//! Options of a PTP plan beyond the DISP limits and the arm's joint velocity limits.
struct PtpOptions {
  //! Empty: none. Otherwise one joint acceleration limit per joint (rad/s², each > 0; +∞: none).
  Eigen::VectorXd joint_acceleration;
  //! Relative slack of the section bounds over the speed sampled at each section's middle, in
  //! (0, 0.5]. The bound's slack falls linearly with the section span, so the section count grows
  //! as 1/tolerance: 10⁻² gives about 10³ sections for a long 6-joint move (10⁻³ about 10⁴,
  //! tests/cpp/test_ptp.cpp, doc/ptp.md §5).
  double tolerance = 1e-2;
};

//! One joint section: u ∈ [u0, u1] of the joint line, and its bounds.
struct JointSection {
  //! The part of the joint line it covers, u ∈ [u0, u1].
  //!@{
  double u0 = 0.0, u1 = 0.0;
  //!@}
  double length = 0.0;        //!< L_k: the weighted speed bound per unit τ (m)
  double acceleration = 0.0;  //!< A_k: unweighted acceleration bound of every object per unit τ² (m)
  double middle_speed = 0.0;  //!< the weighted fastest speed per unit τ at the middle, exact (m)
};

//! What a joint trajectory is at one instant: the tool's state (pose: the tip pose in the base
//! frame; s, ṡ, s̈ of the time law) and the joints'.
struct JointTrajectorySample : TrajectorySample {
  //! Joint positions, velocities, accelerations (rad, rad/s, rad/s²).
  //!@{
  JointVector q, qd, qdd;
  //!@}
  double u = 0.0;  //!< the joint-line parameter
};

//! A planned PTP move. Sampling is noexcept, allocation-free and lock-free.
class JointTrajectory {
 public:
  double duration() const noexcept { return law_.duration(); }  //!< how long the move takes (s)
  //! s at the end: Σ over sections of ∫ du / (du/ds), at least Σ L_k.
  double length() const noexcept { return length_; }
  int dof() const noexcept { return static_cast<int>(q_start_.size()); }  //!< the number of joints
  const Eigen::VectorXd& start() const noexcept { return q_start_; }      //!< the joints at t = 0
  const Eigen::VectorXd& end() const noexcept { return q_end_; }          //!< the joints at the end
  //! The joint sections (in order of u) and their bounds.
  const std::vector<JointSection>& sections() const noexcept { return sections_; }
  //! Number of time laws (one per segment of the velocity-limit curve).
  std::size_t law_count() const noexcept { return law_.size(); }
  //! The time law s(t).
  const TimeLaw& time_law() const noexcept { return law_; }
  //! The velocity-limit curve: ṡ ≤ limit over [start_s, start_s + length).
  const std::vector<SpeedLimit>& speed_limits() const noexcept { return speed_limits_; }
  //! The acceleration limit the time law kept to (the DISP one, lowered by joint acceleration limits).
  double law_acceleration() const noexcept { return law_acceleration_; }
  //! The arm's chain the move was planned on (its forward kinematics gives sample().pose).
  const RevoluteChain& chain() const noexcept { return chain_; }

  //! The state at time t (clamped to [0, duration]); exactly q_a at t ≤ 0 and q_b at t ≥ duration.
  JointTrajectorySample sample(double t) const noexcept;
  //! out[i] = sample(times[i]).
  void sample(const double* times, JointTrajectorySample* out, std::size_t count) const noexcept;

 private:
  friend JointTrajectory plan(const JointPath&, const MetricSetd&, const Limits&, ProfileKind, const SerialArm&,
                              const PtpOptions&);
  // q at u without rounding at the ends: q_a at u = 0 and q_b at u = 1 exactly.
  template <typename Out>
  void joints_at(double u, Out& q) const noexcept;

  // The rate du/ds in section k: r₀ + m (u − u_k), from s = `s` over `span` of s.
  struct SectionRate {
    double s, span, rate, slope;
  };

  RevoluteChain chain_;
  Eigen::VectorXd q_start_, q_end_, delta_;
  std::vector<JointSection> sections_;
  std::vector<SectionRate> rates_;
  double length_ = 0.0;
  TimeLaw law_;
  std::vector<SpeedLimit> speed_limits_;
  double law_acceleration_ = 0.0;
};

//! Plans the PTP move `path` on `arm` under `set` and `limits` (see the file comment). Throws
//! std::invalid_argument naming the argument for: a joint vector of the wrong size or not
//! finite, q_a = q_b, an end outside the arm's position limits, bad limits or options, a set
//! that is not well-formed, more than max_ptp_joints joints, or a move that moves no point of the
//! set while the arm states no joint velocity limit (nothing would bound its speed).
JointTrajectory plan(const JointPath& path, const MetricSetd& set, const Limits& limits, ProfileKind profile,
                     const SerialArm& arm, const PtpOptions& options = {});

}  // namespace dispkin::serial
