//! What the section bounds need of each group of a metric set (doc/section-length.md): its weight
//! w_g = v_sys / v_g, how far its body objects reach from the pivot, and the bound of the
//! acceleration of every object of the group under motions whose pivot speed, pivot
//! acceleration, angular velocity and angular acceleration are bounded.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstring>
#include <optional>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "dispkin/disp.hpp"
#include "dispkin/metric_set.hpp"
#include "dispkin/pose.hpp"

namespace dispkin {

//! Bounds over a section, per unit τ: pivot speed |ċ| and acceleration |c̈|, angular velocity
//! |ω| and angular acceleration |ω̇|.
struct MotionBounds {
  //! |ċ| and |c̈| (m per unit τ and τ²), |ω| and |ω̇| (rad per unit τ and τ²)
  //!@{
  double pivot_speed, pivot_acceleration, omega, omega_dot;
  //!@}
};

//! Bounds over a section of the third derivatives of its motion, per unit τ³: the pivot's jerk
//! |c⃛| and the rate of the angular acceleration |ω̈| (body).
struct MotionJerkBounds {
  //! |c⃛| (m per unit τ³) and |ω̈| (rad per unit τ³)
  //!@{
  double pivot_jerk, omega_ddot;
  //!@}
};

//! Bounds of the acceleration ‖d²x/dτ²‖ and of the jerk ‖d³x/dτ³‖ of every object of a group over
//! a section (unweighted, per unit τ² and τ³).
struct GroupRates {
  double acceleration;  //!< the acceleration bound (m per unit τ²)
  double jerk;          //!< the jerk bound (m per unit τ³)
};

namespace detail {

//! Whether n doubles are equal bit for bit (+0 and −0 differ, so a remembered result is exactly
//! the one asked).
inline bool same_bits(const double* a, const double* b, std::size_t n) noexcept {
  return std::memcmp(a, b, n * sizeof(double)) == 0;
}

//! A bound of the acceleration (per unit τ²) of every object of the group under motions within
//! `bounds`: a body point at distance r from the pivot accelerates at most |c̈| + (|ω̇| + |ω|²) r;
//! an absolute point at distance r seen from the body at most |c̈| + |ω̇| r + |ω||ċ| (r from
//! `pivot_middle`, the pivot's world position at the middle of the section, plus |ċ|/2).
inline double group_acceleration_bound(const MetricGroup<double>& g, const Eigen::Vector3d& pivot,
                                       const Eigen::Vector3d& pivot_middle, const MotionBounds& bounds);

//! group_acceleration_bound and a bound of the jerk of every object of the group under motions
//! within `bounds` and `jerk` (doc/section-length.md eq. 25): a body point at distance r from the
//! pivot jerks at most |c⃛| + (|ω̈| + 3|ω||ω̇| + |ω|³) r, the velocity an absolute point at distance r
//! sees changes its rate at most at |c⃛| + (|ω̈| + |ω||ω̇|) r + 2|ω̇||ċ| + |ω||c̈|.
inline GroupRates group_rate_bounds(const MetricGroup<double>& g, double reach, const Eigen::Vector3d& pivot_middle,
                                    const MotionBounds& bounds, const MotionJerkBounds& jerk) noexcept;

//! How far the group's body objects reach from the pivot (body coordinates): the largest
//! |r − p| of its relative points and |c − p| + ρ of its relative spheres, 0 without any. It
//! depends on the pivot only, not on the section.
inline double relative_reach(const MetricGroup<double>& g, const Eigen::Vector3d& pivot) noexcept;

//! group_acceleration_bound with the group's relative_reach from the pivot already known.
inline double group_acceleration_bound(const MetricGroup<double>& g, double reach, const Eigen::Vector3d& pivot_middle,
                                       const MotionBounds& bounds) noexcept;

}  // namespace detail

//! What the section bounds need of each group of a set, once per path instead of once per
//! section: its weight v_sys / v_g and its relative_reach from the pivot (recomputed only
//! when a section has another pivot). Planning side; allocates.
class GroupFactors {
 public:
  //! Throws like MetricGroup::weight (a group limit without a system velocity).
  GroupFactors(const MetricSetd& set, std::optional<double> system_velocity)
      : set_(&set), system_velocity_(system_velocity) {
    groups_.reserve(set.groups().size());
    for (const auto& g : set.groups()) {
      groups_.push_back({g.weight(system_velocity), 0.0});
      max_weight_ = std::max(max_weight_, groups_.back().weight);
    }
  }

  //! Makes reach() refer to `pivot` (body coordinates).
  void use_pivot(const Eigen::Vector3d& pivot) noexcept {
    if (has_pivot_ && pivot == pivot_) return;
    for (std::size_t i = 0; i < groups_.size(); ++i)
      groups_[i].reach = detail::relative_reach(set_->groups()[i], pivot);
    pivot_ = pivot;
    has_pivot_ = true;
  }

  const MetricSetd& set() const noexcept { return *set_; }  //!< the set, which must outlive this
  //! The system velocity the weights are taken for.
  std::optional<double> system_velocity() const noexcept { return system_velocity_; }

  //! axis_turn(axis, angle), the same quaternion bit for bit, remembered for the last two pairs
  //! asked: the sections of one CIRC repeat their turns (the pivot's half turn about the normal,
  //! the orientation's turn), so a path evaluates them once per CIRC, not once per section.
  Eigen::Quaterniond turn(const Eigen::Vector3d& axis, double angle) const noexcept {
    for (const TurnMemo& m : turns_) {
      if (m.known && detail::same_bits(m.axis.data(), axis.data(), 3) && detail::same_bits(&m.angle, &angle, 1))
        return m.turn;
    }
    TurnMemo& m = turns_[next_turn_];
    next_turn_ = 1 - next_turn_;
    m = {axis, angle, detail::axis_turn(axis, angle), true};
    return m.turn;
  }
  //! std::sin(x), remembered for the last x asked (an arc's deviation bound, the same for all
  //! the sections of one CIRC).
  double sine(double x) const noexcept {
    if (!sine_known_ || !detail::same_bits(&sine_of_, &x, 1)) {
      sine_of_ = x;
      sine_ = std::sin(x);
      sine_known_ = true;
    }
    return sine_;
  }
  double weight(std::size_t group) const noexcept { return groups_[group].weight; }  //!< w_g = v_sys / v_g
  double max_weight() const noexcept { return max_weight_; }                         //!< the largest w_g
  //! The group's relative_reach from the pivot of the last use_pivot (m).
  double reach(std::size_t group) const noexcept { return groups_[group].reach; }

 private:
  struct Factors {
    double weight, reach;
  };
  const MetricSetd* set_;
  std::optional<double> system_velocity_;
  std::vector<Factors> groups_;
  double max_weight_ = 0.0;
  Eigen::Vector3d pivot_ = Eigen::Vector3d::Zero();
  bool has_pivot_ = false;
  struct TurnMemo {
    Eigen::Vector3d axis;
    double angle;
    Eigen::Quaterniond turn;
    bool known;
  };
  // Memos of pure functions: filling them does not change what the object answers.
  mutable TurnMemo turns_[2] = {{Eigen::Vector3d::Zero(), 0.0, Eigen::Quaterniond::Identity(), false},
                                {Eigen::Vector3d::Zero(), 0.0, Eigen::Quaterniond::Identity(), false}};
  mutable int next_turn_ = 0;
  mutable double sine_of_ = 0.0, sine_ = 0.0;
  mutable bool sine_known_ = false;
};

//! A section's length (weighted, see CurveSection::length) and acceleration bound
//! (unweighted, see CurveSection::acceleration_bound), from one evaluation, with bounds of the
//! tool's angular velocity |ω| and its rate |ω̇| per unit τ (the rotational limit's terms,
//! doc/planning.md §11).
struct SectionBounds {
  double length;        //!< the weighted speed bound per unit τ (m)
  double acceleration;  //!< the unweighted acceleration bound per unit τ² (m)
  //! |ω| and |ω̇| per unit τ and τ² (rad)
  //!@{
  double omega = 0.0, omega_dot = 0.0;
  //!@}
};

namespace detail {

inline double relative_reach(const MetricGroup<double>& g, const Eigen::Vector3d& pivot) noexcept {
  double r = 0.0;
  for (const auto& p : g.relative_points) r = std::max(r, (p - pivot).norm());
  for (const auto& s : g.relative_spheres) r = std::max(r, (s.center - pivot).norm() + s.radius);
  return r;
}

inline double group_acceleration_bound(const MetricGroup<double>& g, const Eigen::Vector3d& pivot,
                                       const Eigen::Vector3d& pivot_middle, const MotionBounds& b) {
  return group_acceleration_bound(g, relative_reach(g, pivot), pivot_middle, b);
}

// The largest distance of the group's absolute objects from the pivot anywhere on the section
// (at most |ċ|/2 from the middle); negative without any.
inline double absolute_reach(const MetricGroup<double>& g, const Eigen::Vector3d& pivot_middle,
                             const MotionBounds& b) noexcept {
  if (g.absolute_points.empty() && g.absolute_spheres.empty()) return -1.0;
  double r_absolute = 0.0;
  for (const auto& p : g.absolute_points) r_absolute = std::max(r_absolute, (p - pivot_middle).norm());
  for (const auto& s : g.absolute_spheres)
    r_absolute = std::max(r_absolute, (s.center - pivot_middle).norm() + s.radius);
  return r_absolute + 0.5 * b.pivot_speed;
}

inline double group_acceleration_bound(const MetricGroup<double>& g, double r_relative,
                                       const Eigen::Vector3d& pivot_middle, const MotionBounds& b) noexcept {
  // The body objects' reach is given.
  const double r_absolute = absolute_reach(g, pivot_middle, b);
  double rate = b.pivot_acceleration + (b.omega_dot + b.omega * b.omega) * r_relative;
  if (r_absolute >= 0.0)
    rate = std::max(rate, b.pivot_acceleration + b.omega_dot * r_absolute + b.omega * b.pivot_speed);
  return rate;
}

inline GroupRates group_rate_bounds(const MetricGroup<double>& g, double r_relative,
                                    const Eigen::Vector3d& pivot_middle, const MotionBounds& b,
                                    const MotionJerkBounds& j) noexcept {
  const double r_absolute = absolute_reach(g, pivot_middle, b);
  // Body points: x = c + R(r − p), R‴ = R([ω]ₓ³ + 2[ω]ₓ[ω̇]ₓ + [ω̇]ₓ[ω]ₓ + [ω̈]ₓ).
  GroupRates rates{b.pivot_acceleration + (b.omega_dot + b.omega * b.omega) * r_relative,
                   j.pivot_jerk + (j.omega_ddot + b.omega * (3.0 * b.omega_dot + b.omega * b.omega)) * r_relative};
  if (r_absolute >= 0.0) {
    // Absolute points: g = ċ + ω_w × (x − c), g″ = c⃛ + ω̈_w × (x − c) − 2 ω̇_w × ċ − ω_w × c̈, with
    // ω_w = R ω, ω̇_w = R ω̇ and ω̈_w = R (ω̈ + ω × ω̇).
    rates.acceleration =
        std::max(rates.acceleration, b.pivot_acceleration + b.omega_dot * r_absolute + b.omega * b.pivot_speed);
    rates.jerk = std::max(rates.jerk, j.pivot_jerk + (j.omega_ddot + b.omega * b.omega_dot) * r_absolute +
                                          2.0 * b.omega_dot * b.pivot_speed + b.omega * b.pivot_acceleration);
  }
  return rates;
}

//! A section's bounds from its middle (doc/section-length.md eqs. 23–24): every object's speed changes at
//! most at the rate of its acceleration bound, so within half a section of the middle it exceeds
//! its middle speed by at most half that bound. Each group's exact speed at the middle pose and
//! twist plus half its rate, weighted; the largest rate; the motion's |ω| and |ω̇|.
//! `middle_speed` receives max_g w_g V_g(½), the weighted fastest speed at the middle: a lower
//! bound of the section's exact peak, so that length − middle_speed bounds the slack
//! (doc/section-length.md eq. 26).
inline SectionBounds bounds_from_middle(const GroupFactors& factors, const Posed& middle, const Twistd& twist_middle,
                                        const Eigen::Vector3d& pivot_middle, const MotionBounds& motion,
                                        double& middle_speed) {
  const MetricSetd& set = factors.set();
  double length = 0.0, acceleration = 0.0;
  middle_speed = 0.0;
  for (std::size_t i = 0; i < set.groups().size(); ++i) {
    const auto& g = set.groups()[i];
    const double rate = group_acceleration_bound(g, factors.reach(i), pivot_middle, motion);
    const double speed = group_max_speed(g, middle, twist_middle);
    length = std::max(length, factors.weight(i) * (speed + 0.5 * rate));
    middle_speed = std::max(middle_speed, factors.weight(i) * speed);
    acceleration = std::max(acceleration, rate);
  }
  return {length, acceleration, motion.omega, motion.omega_dot};
}
inline SectionBounds bounds_from_middle(const GroupFactors& factors, const Posed& middle, const Twistd& twist_middle,
                                        const Eigen::Vector3d& pivot_middle, const MotionBounds& motion) {
  double middle_speed = 0.0;
  return bounds_from_middle(factors, middle, twist_middle, pivot_middle, motion, middle_speed);
}

}  // namespace detail
}  // namespace dispkin
