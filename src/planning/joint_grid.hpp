// The joint path on a grid of the smooth parameter σ and the limits it imposes on each run's
// parameterisation (internal to the re-timing; doc/retiming.md §4–5).
#pragma once

#include <cstddef>
#include <limits>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "dispkin/planning/retiming.hpp"
#include "reachability.hpp"
#include "smooth_parameter.hpp"

namespace dispkin::detail {

//! What the limits need of the joint path at one grid position σ.
struct GridPoint {
  double sigma;
  Eigen::VectorXd q, q1, q2;                    // q, dq/dσ, d²q/dσ²
  Eigen::VectorXd torque_u, torque_x, gravity;  // τ = torque_u·σ̈ + torque_x·σ̇² + gravity (empty: no dynamics)
  // The other values of q″ (and torque_x with each, where torques are kept) on the grid intervals
  // next to σ, where the machine's q″ steps between grid points (JointModel::rate_steps).
  std::vector<Eigen::VectorXd> q2_other, torque_x_other;
};

//! The joint path at σ: q and q′ from the machine (on the branch of q_ref, Newton from `guess` if
//! not null), q″ in closed form (JointModel::joints_with_rate, doc/retiming.md (eq. 28)) where
//! [σ − h, σ + h] lies inside [lo, hi] and one section, else (or where the machine has no closed
//! form) by central differences of q′ with step h inside [lo, hi] (one-sided at its ends: a run's
//! ends are rests, where the path may turn a corner), and with `torques` the torque coefficients
//! (doc/retiming.md eq. 12; left empty without: no effort limit to keep). Where the machine's q″
//! steps within ±`spacing` (the grid interval) inside [lo, hi], the other values it takes there
//! (q2_other, with their torque_x_other).
GridPoint grid_point(const SmoothParameter& path, const JointModel& model, double sigma, double h, double spacing,
                     double lo, double hi, const Eigen::VectorXd& q_ref, const Eigen::VectorXd* guess = nullptr,
                     bool torques = true);

//! The joint limits at one grid point as half-planes in (u, x) = (σ̈, σ̇²), each limit multiplied by
//! `scale` (doc/retiming.md (eq. 13)); the acceleration and torque limits for q″ and each of its
//! other values.
void append_limits(const GridPoint& p, const JointBounds& bounds, double scale, std::vector<HalfPlane>& out);

//! The cap on σ̇² from the joint velocity limits at one grid point (+∞ where none binds).
double joint_speed_cap(const GridPoint& p, const JointBounds& bounds, double scale);

//! "[s0, s1] m" for messages.
std::string interval_text(double s0, double s1);

//! A rest-to-rest run: grid points [first, first + count].
struct Run {
  std::size_t first, count;
};

//! The fastest parameterisation of one run on the grid under the DISP limits in σ and the joint
//! limits at `scale` (reachability.hpp; doc/retiming.md (eq. 14–16)). The admissible polygon of
//! every interval under the DISP limits and the joint limits at both its ends, and the joint speeds'
//! cap on σ̇² at every grid point, are built once: a solve copies the polygons and clips them only
//! by its own caps (the jerk-limited search solves the same run hundreds of times).
class RunProblem {
 public:
  RunProblem(const SmoothParameter& smooth, const std::vector<GridPoint>& grid, const JointBounds& bounds, double scale,
             Run run);

  const SmoothParameter& smooth() const noexcept { return smooth_; }
  const std::vector<GridPoint>& grid() const noexcept { return grid_; }
  const Run& run() const noexcept { return run_; }
  //! σ at the run's start and end.
  double start() const noexcept { return grid_[run_.first].sigma; }
  double end() const noexcept { return grid_[run_.first + run_.count].sigma; }

  //! Solves the run. With a jerk limit, `reach` > 0 lowers every speed cap (the DISP velocity-limit
  //! curve and the joint speeds) to its minimum over ±reach around the interval, and a
  //! `run_acceleration` > 0 lowers the acceleration cap to it: the moving average then keeps them
  //! (doc/retiming.md (eq. 22)). `run_speed` caps σ̇ throughout. Throws std::runtime_error naming
  //! the path interval where no speed keeps the limits.
  Parameterisation solve(double reach, double run_acceleration,
                         double run_speed = std::numeric_limits<double>::infinity()) const;

 private:
  const SmoothParameter& smooth_;
  const std::vector<GridPoint>& grid_;
  Run run_;
  std::vector<GridInterval> admissible_;       // per interval: the DISP and joint limits, no run caps
  std::vector<double> speed_cap_;              // per grid point of the run: joint_speed_cap
  mutable std::vector<GridInterval> clipped_;  // solve()'s copy of admissible_, clipped
};

}  // namespace dispkin::detail
