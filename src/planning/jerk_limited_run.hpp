// Jerk limiting of a run (internal to the re-timing; doc/retiming.md §6): the grid solution as a
// law of constant σ̈ steps, the search for the acceleration and speed caps whose moving-average
// law is shortest, and that law back in s as laws of constant jerk.
#pragma once

#include <vector>

#include "dispkin/profile.hpp"
#include "jerk_filter.hpp"
#include "joint_grid.hpp"
#include "reachability.hpp"
#include "smooth_parameter.hpp"

namespace dispkin::detail {

//! The grid solution of a run as a law in time: σ at the grid points, σ̇ = √x, σ̈ = u, and the time
//! of each interval from its mean speed (exact for constant σ̈; doc/retiming.md (eq. 17)).
AccelerationSteps acceleration_steps(const std::vector<GridPoint>& grid, std::size_t first, std::size_t count,
                                     const Parameterisation& fastest);

//! The grid solution chosen for jerk limiting, its steps in time and its moving-average window T.
struct JerkLimitedSolution {
  Parameterisation fastest;
  AccelerationSteps steps;
  double window;
};

//! The run's solution whose moving average over the smallest window that keeps the jerk limit is
//! shortest: the acceleration cap A ≤ a ρ and a uniform speed cap V by scans and golden-section
//! searches, the speed caps tightened over the window's reach (doc/retiming.md (eq. 21–22)).
//! acceleration_limit and jerk_limit are the DISP ones (in s). Throws std::runtime_error when the
//! window does not settle.
JerkLimitedSolution jerk_limited_solution(const RunProblem& problem, double acceleration_limit, double jerk_limit);

//! A run's jerk-limited law in σ (constant-jerk phases ending at rest at `run_end`) as laws in s:
//! cut where sections begin (ds/dσ changes there: ṡ, s̈, s⃛ are σ̇, σ̈, σ⃛ times the section's ds/dσ),
//! at most Profile::max_phases phases per law.
void append_jerk_laws(const SmoothParameter& smooth, std::vector<JerkPhase> phases, double run_end,
                      std::vector<Profile>& laws);

//! A run's grid solution (constant σ̈ over each grid interval) as trapezoid laws in s, cut where
//! sections begin (ṡ = σ̇ ds/dσ).
void append_acceleration_laws(const RunProblem& problem, const Parameterisation& fastest, double acceleration_limit,
                              std::vector<Profile>& laws);

}  // namespace dispkin::detail
