// PTP moves of a serial arm under the DISP limit: cutting, velocity-limit curve, sampling (ptp.hpp).
#include "dispkin/serial/ptp.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "dispkin/error.hpp"
#include "dispkin/planning/velocity_limit.hpp"
#include "dispkin/serial/chain_kinematics.hpp"
#include "ptp_section.hpp"

namespace dispkin::serial {
namespace {

constexpr int initial_sections = 8;
constexpr int max_depth = 16;            // sections never shorter than 2⁻¹⁶ of the move
constexpr double floor_fraction = 1e-2;  // V_floor and the least pace: 1 % of the move's fastest
constexpr double junction_step = 1e-2;   // the planner's junction rule: h/L steps ≤ 1 %
constexpr double staircase_step = 0.95;  // velocity-limit levels v_sys · 0.95ᵏ
constexpr double rate_share = 0.9;       // of a joint acceleration limit for Δq r s̈; the rest for Δq m r ṡ²

struct Cutter {
  const RevoluteChain& chain;
  const Eigen::VectorXd& q_a;
  const Eigen::VectorXd& delta;
  const GroupFactors& factors;
  double tolerance;
  double floor_pace = 0.0;  // V_floor per unit u: a section of span h compares with floor_pace · h

  JointSection bounds(double u0, double u1) const {
    return detail::joint_section_bounds(chain, q_a, delta, u0, u1, factors);
  }
  // Appends [u0, u1] cut until its bound is within the tolerance of its middle speed.
  void cut(const JointSection& section, int depth, std::vector<JointSection>& out) const {
    const double slack = section.length - section.middle_speed;
    if (depth >= max_depth ||
        slack <= tolerance * std::max(section.middle_speed, floor_pace * (section.u1 - section.u0))) {
      out.push_back(section);
      return;
    }
    const double um = 0.5 * (section.u0 + section.u1);
    cut(bounds(section.u0, um), depth + 1, out);
    cut(bounds(um, section.u1), depth + 1, out);
  }
};

int depth_of(const JointSection& s) { return static_cast<int>(std::lround(-std::log2(s.u1 - s.u0))); }

// The move's checks (ptp.hpp): joint vectors of the arm's size, finite, distinct and inside its
// position limits; the options' tolerance and joint acceleration limits.
void require_move(const JointPath& path, const SerialArm& arm, const PtpOptions& options) {
  const int n = arm.dof();
  require(n <= max_ptp_joints, "arm dof", n, "exceeds max_ptp_joints = " + std::to_string(max_ptp_joints));
  const Eigen::VectorXd& q_a = path.start();
  const Eigen::VectorXd& q_b = path.end();
  require(q_a.size() == n, "q_a size", static_cast<long>(q_a.size()), "must be the arm's dof " + std::to_string(n));
  require(q_b.size() == n, "q_b size", static_cast<long>(q_b.size()), "must be the arm's dof " + std::to_string(n));
  require_finite(q_a, "q_a");
  require_finite(q_b, "q_b");
  require(q_a != q_b, "q_b", q_b, "equals q_a: a PTP move must move");
  const JointLimits joint = arm.joint_limits();
  const std::vector<std::string> names = arm.joint_names();
  for (int i = 0; i < n; ++i) {
    const std::string name = "joint \"" + names[static_cast<std::size_t>(i)] + "\"";
    require(q_a(i) >= joint.lower(i) && q_a(i) <= joint.upper(i), "q_a[" + std::to_string(i) + "]", q_a(i),
            "is outside the position limits [lower, upper] of " + name);
    require(q_b(i) >= joint.lower(i) && q_b(i) <= joint.upper(i), "q_b[" + std::to_string(i) + "]", q_b(i),
            "is outside the position limits [lower, upper] of " + name);
  }
  require(std::isfinite(options.tolerance) && options.tolerance > 0.0 && options.tolerance <= 0.5, "tolerance",
          options.tolerance, "must be in (0, 0.5]");
  const Eigen::VectorXd& qdd_max = options.joint_acceleration;
  require(qdd_max.size() == 0 || qdd_max.size() == n, "joint_acceleration size", static_cast<long>(qdd_max.size()),
          "must be 0 (none) or the arm's dof " + std::to_string(n));
  for (Eigen::Index i = 0; i < qdd_max.size(); ++i)
    require(qdd_max(i) > 0.0, "joint_acceleration[" + std::to_string(i) + "]", qdd_max(i), "must be > 0 (+inf: none)");
}

// Sections: a uniform start, then halving by the cutting rule (ptp.hpp); sets the cutter's floor.
std::vector<JointSection> cut_sections(Cutter& cutter) {
  std::vector<JointSection> initial;
  double fastest = 0.0, fastest_bound = 0.0;  // the largest exact middle pace, and bound pace
  for (int k = 0; k < initial_sections; ++k) {
    initial.push_back(cutter.bounds(double(k) / initial_sections, double(k + 1) / initial_sections));
    fastest = std::max(fastest, initial.back().middle_speed * initial_sections);
    fastest_bound = std::max(fastest_bound, initial.back().length * initial_sections);
  }
  cutter.floor_pace = floor_fraction * (fastest > 0.0 ? fastest : fastest_bound);
  std::vector<JointSection> sections;
  for (const JointSection& s : initial) cutter.cut(s, 3, sections);
  return sections;
}

// The least pace L/h: a section where (almost) no point moves is lengthened to 1 % of the
// fastest pace, so u never runs more than 100 times faster there (lengthening only slows).
double least_pace_of(const std::vector<JointSection>& sections, const Eigen::VectorXd& q_b) {
  double pace = 0.0;
  for (const JointSection& s : sections) pace = std::max(pace, s.length / (s.u1 - s.u0));
  require(pace > 0.0, "path", q_b, "moves no point of the metric set: nothing bounds the DISP speed of this move");
  return floor_fraction * pace;
}

void lengthen(JointSection& s, double least_pace) { s.length = std::max(s.length, least_pace * (s.u1 - s.u0)); }

// The junction rule: neighbours' h/L within 1 %; halve both where not (a few passes).
void keep_junctions(std::vector<JointSection>& sections, const Cutter& cutter, double least_pace) {
  for (int pass = 0; pass < 2 * max_depth; ++pass) {
    std::vector<bool> split(sections.size(), false);
    bool any = false;
    for (std::size_t k = 0; k + 1 < sections.size(); ++k) {
      const double r0 = (sections[k].u1 - sections[k].u0) / sections[k].length;
      const double r1 = (sections[k + 1].u1 - sections[k + 1].u0) / sections[k + 1].length;
      if (std::abs(r0 - r1) > junction_step * std::max(r0, r1)) {
        if (depth_of(sections[k]) < max_depth) split[k] = any = true;
        if (depth_of(sections[k + 1]) < max_depth) split[k + 1] = any = true;
      }
    }
    if (!any) break;
    std::vector<JointSection> next;
    next.reserve(2 * sections.size());
    for (std::size_t k = 0; k < sections.size(); ++k) {
      if (!split[k]) {
        next.push_back(sections[k]);
        continue;
      }
      const double um = 0.5 * (sections[k].u0 + sections[k].u1);
      next.push_back(cutter.bounds(sections[k].u0, um));
      next.push_back(cutter.bounds(um, sections[k].u1));
      lengthen(next[next.size() - 2], least_pace);
      lengthen(next.back(), least_pace);
    }
    sections.swap(next);
  }
}

// The rate du/ds at each junction (ptp.hpp): the smaller of the two sections' h/L, at the ends
// their own; count + 1 of them.
std::vector<double> junction_rates(const std::vector<JointSection>& sections) {
  const std::size_t count = sections.size();
  std::vector<double> ratio(count), rate(count + 1);
  for (std::size_t k = 0; k < count; ++k) ratio[k] = (sections[k].u1 - sections[k].u0) / sections[k].length;
  rate[0] = ratio[0];
  rate[count] = ratio[count - 1];
  for (std::size_t k = 1; k < count; ++k) rate[k] = std::min(ratio[k - 1], ratio[k]);
  return rate;
}

// A section with the slope m of its rate du/ds and the larger of its end rates.
struct SectionPace {
  const JointSection& section;
  double slope, r_max;
};

// The speed limit of a section on the staircase (ptp.hpp): system velocity, joint velocities,
// curvature rule, and with joint acceleration limits the share of q̈ that the changing rate
// takes; lowers `a_law` to what the joint acceleration limits leave the time law.
double speed_level(const SectionPace& pace, const std::vector<double>& dq, const JointLimits& joint,
                   const Eigen::VectorXd& qdd_max, const Limits& limits, double& a_law) {
  const JointSection& section = pace.section;
  const double r_max = pace.r_max;
  // A point accelerates at most at ṡ² (A/L² + |m|) (ptp.hpp).
  const double bend = (section.acceleration > 0.0 ? section.acceleration / (section.length * section.length) : 0.0) +
                      std::abs(pace.slope);
  double v = limits.velocity;
  if (bend > 0.0) v = std::min(v, std::sqrt(limits.acceleration / bend));
  for (std::size_t i = 0; i < dq.size(); ++i) {
    const double d = dq[i];
    if (d == 0.0) continue;
    const auto e = static_cast<Eigen::Index>(i);
    v = std::min(v, joint.velocity(e) / (d * r_max));
    if (qdd_max.size()) {
      a_law = std::min(a_law, rate_share * qdd_max(e) / (d * r_max));
      if (pace.slope != 0.0)
        v = std::min(v, std::sqrt((1.0 - rate_share) * qdd_max(e) / (d * std::abs(pace.slope) * r_max)));
    }
  }
  double level = limits.velocity;
  if (v < limits.velocity) {
    level =
        limits.velocity * std::pow(staircase_step, std::ceil(std::log(v / limits.velocity) / std::log(staircase_step)));
    if (level > v) level = v;  // rounding of pow / log: never above the limit
  }
  return level;
}

// The time law over the staircase, rest to rest (velocity_limited_law), and the staircase as
// speed limits along s.
void law_over(const std::vector<LimitedSegment>& segments, double acceleration, std::optional<double> jerk,
              std::vector<SpeedLimit>& speed_limits, TimeLaw& law) {
  double start_s = 0.0, span_s = 0.0;
  for (const LimitedSegment& segment : segments) {
    speed_limits.push_back({span_s, segment.length, segment.limit});
    span_s += segment.length;
  }
  for (const Profile& piece : velocity_limited_law(segments, acceleration, jerk)) {
    law.append(piece, start_s);
    start_s += piece.distance();
  }
  law.end_run();
}

}  // namespace

JointTrajectory plan(const JointPath& path, const MetricSetd& set, const Limits& limits, ProfileKind profile,
                     const SerialArm& arm, const PtpOptions& options) {
  limits.validate(profile);
  set.require_well_formed();
  require_move(path, arm, options);
  const int n = arm.dof();
  const Eigen::VectorXd& q_a = path.start();
  const Eigen::VectorXd& q_b = path.end();
  const JointLimits joint = arm.joint_limits();
  const Eigen::VectorXd& qdd_max = options.joint_acceleration;

  JointTrajectory out;
  out.chain_ = arm.chain();
  out.q_start_ = q_a;
  out.q_end_ = q_b;
  out.delta_ = q_b - q_a;

  GroupFactors factors(set, limits.velocity);
  factors.use_pivot(Eigen::Vector3d::Zero());
  Cutter cutter{out.chain_, q_a, out.delta_, factors, options.tolerance};
  std::vector<JointSection> sections = cut_sections(cutter);
  const double least_pace = least_pace_of(sections, q_b);
  for (JointSection& s : sections) lengthen(s, least_pace);
  keep_junctions(sections, cutter, least_pace);
  out.sections_ = sections;

  // The rate u per unit s (ptp.hpp): at each junction the smaller of the two sections' h/L, linear
  // in u inside a section, so never above its own h/L. Inside section k, with r₀, r₁ its end rates
  // and m = (r₁ − r₀)/h: du/ds = r₀ + m (u − u_k), hence s-length ∫ du / r = h ln(r₁/r₀) / (r₁ − r₀).
  const std::size_t count = sections.size();
  const std::vector<double> rate = junction_rates(sections);
  out.rates_.resize(count);
  double s = 0.0;
  for (std::size_t k = 0; k < count; ++k) {
    const double h = sections[k].u1 - sections[k].u0;
    const double r0 = rate[k], r1 = rate[k + 1];
    const double slope = (r1 - r0) / h;
    const double span = r1 == r0 ? h / r0 : h * std::log1p((r1 - r0) / r0) / (r1 - r0);
    out.rates_[k] = {s, span, r0, slope};
    s += span;
  }
  out.length_ = s;

  // The velocity-limit curve (ptp.hpp), a level per section, one segment per run of a level.
  std::vector<double> dq(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) dq[static_cast<std::size_t>(i)] = std::abs(out.delta_(i));
  double a_law = limits.acceleration;
  std::vector<LimitedSegment> segments;
  for (std::size_t k = 0; k < count; ++k) {
    const JointTrajectory::SectionRate& r = out.rates_[k];
    const SectionPace pace{sections[k], r.slope, std::max(rate[k], rate[k + 1])};
    const double level = speed_level(pace, dq, joint, qdd_max, limits, a_law);
    if (!segments.empty() && segments.back().limit == level) {
      segments.back().length += r.span;
    } else {
      segments.push_back({r.span, level});
    }
  }
  out.law_acceleration_ = a_law;
  const std::optional<double> jerk = profile == ProfileKind::scurve ? limits.jerk : std::nullopt;
  law_over(segments, a_law, jerk, out.speed_limits_, out.law_);
  return out;
}

template <typename Out>
void JointTrajectory::joints_at(double u, Out& q) const noexcept {
  // q_a + u Δq near the start, q_b − (1 − u) Δq near the end: both ends exact.
  if (u <= 0.5) {
    q = q_start_ + u * delta_;
  } else {
    q = q_end_ - (1.0 - u) * delta_;
  }
}

JointTrajectorySample JointTrajectory::sample(double t) const noexcept {
  JointTrajectorySample out;
  if (law_.size() == 0) return out;
  const auto n = static_cast<Eigen::Index>(q_start_.size());
  out.q.resize(n);
  out.qd.resize(n);
  out.qdd.resize(n);
  if (!(t > 0.0)) t = 0.0;
  std::size_t k = 0;
  if (t >= duration()) {
    out.s = length();
    k = sections_.size() - 1;
  } else {
    std::size_t piece = law_.size();  // no hint: binary search
    const ProfileState law = law_.state_at(t, piece);
    out.s = law.s;
    out.s_dot = law.v;
    out.s_ddot = law.a;
    const auto next =
        std::upper_bound(rates_.begin(), rates_.end(), out.s, [](double x, const SectionRate& r) { return x < r.s; });
    k = next == rates_.begin() ? 0 : static_cast<std::size_t>(next - rates_.begin()) - 1;
  }
  const JointSection& section = sections_[k];
  const SectionRate& r = rates_[k];
  // Inside section k: u − u_k = r₀ (e^{m s′} − 1)/m and du/ds = r₀ e^{m s′}, s′ = s − s_k.
  double rate = r.rate, u = section.u1;
  if (t < duration()) {
    const double ds = std::clamp(out.s - r.s, 0.0, r.span);
    const double ms = r.slope * ds;
    const double advance = r.slope == 0.0 ? r.rate * ds : r.rate * std::expm1(ms) / r.slope;
    u = std::min(section.u0 + advance, section.u1);
    rate = r.rate * std::exp(ms);
  }
  out.u = u;
  joints_at(out.u, out.q);
  // q̇ = Δq (du/ds) ṡ, q̈ = Δq ((du/ds) s̈ + m (du/ds) ṡ²).
  out.qd = delta_ * (rate * out.s_dot);
  out.qdd = delta_ * (rate * (out.s_ddot + r.slope * out.s_dot * out.s_dot));
  chain_pose_and_twist(chain_, out.q.data(), out.qd.data(), out.pose, out.body_twist);
  return out;
}

void JointTrajectory::sample(const double* times, JointTrajectorySample* out, std::size_t count) const noexcept {
  for (std::size_t i = 0; i < count; ++i) out[i] = sample(times[i]);
}

}  // namespace dispkin::serial
