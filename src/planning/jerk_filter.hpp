// Jerk limiting by a moving average (internal; used by retime_optimal with a jerk limit).
//
// A rest-to-rest law with piecewise-constant acceleration u(t) (the reachability result),
// t ∈ [0, t_N], is replaced by its moving average over a window of width T:
//   p_T(t) = (1/T) ∫_{t−T}^{t} p(τ) dτ,
// with p(τ) = p(0) before the start and p(t_N) after the end. Then
//   ṗ_T(t) = (p(t) − p(t−T)) / T,  p̈_T(t) = (ṗ(t) − ṗ(t−T)) / T,  p⃛_T(t) = (u(t) − u(t−T)) / T:
// the jerk is piecewise constant (it changes where t or t − T is a knot of u) and bounded by
// max |u(t) − u(t−T)| / T; |p̈_T| ≤ max |u|; ṗ_T is an average of the speeds over the window;
// and the law still runs from rest at p(0) to rest at exactly p(t_N), T later than before.
// The smallest window with max_t |u(t) − u(t−T)| ≤ j T is found by bisection (the condition
// is checked exactly on the step function): where u steps from +a through a cruise to −a it is
// a/j — the moving average of a trapezoid over a/j is the S-curve — and it is never above 2a/j.
#pragma once

#include <vector>

namespace dispkin::detail {

//! A law with constant acceleration between knots: time[i], position[i], speed[i] at the N + 1
//! knots (speed 0 at both ends), acceleration[i] on [time[i], time[i + 1]).
struct AccelerationSteps {
  std::vector<double> time, position, speed, acceleration;
};

//! One phase of constant jerk and the state at its start.
struct JerkPhase {
  double duration, jerk;
  double position, speed, acceleration;
};

//! The smallest window T ≤ upper with max_t |u(t) − u(t−T)| ≤ jerk · T, to a relative 10⁻⁹
//! (bisection; `upper` must satisfy it, 2 max|u| / jerk always does).
double smallest_window(const AccelerationSteps& law, double jerk, double upper);

//! The moving average of `law` over `window` > 0 as constant-jerk phases, from rest at
//! position[0] to rest at position[N] (the last phase ends there; `end_time` = t_N + window).
std::vector<JerkPhase> moving_average(const AccelerationSteps& law, double window, double& end_time);

}  // namespace dispkin::detail
