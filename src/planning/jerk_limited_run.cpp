// Jerk limiting of a run and the run's laws back in s (jerk_limited_run.hpp).
#include "jerk_limited_run.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>

namespace dispkin::detail {
namespace {

// σ at time τ into a phase (its Taylor polynomial), and the state there.
JerkPhase advance(const JerkPhase& p, double tau) {
  JerkPhase out = p;
  out.duration = p.duration - tau;
  out.position = p.position + tau * (p.speed + tau * (0.5 * p.acceleration + p.jerk * tau / 6.0));
  out.speed = std::max(0.0, p.speed + tau * (p.acceleration + 0.5 * p.jerk * tau));
  out.acceleration = p.acceleration + p.jerk * tau;
  return out;
}

// Golden-section search for the shortest `duration` of `evaluate(x)` over [lo, hi] in `iterations`
// steps, starting from `best` (a scan's winner); returns the best candidate seen.
template <typename Candidate, typename Evaluate>
Candidate golden_section(double lo, double hi, int iterations, Candidate best, Evaluate&& evaluate) {
  constexpr double golden = 0.6180339887498949;
  double x1 = hi - golden * (hi - lo), x2 = lo + golden * (hi - lo);  // x1 ≤ x2
  Candidate c1 = evaluate(x1), c2 = evaluate(x2);
  for (int iteration = 0;; ++iteration) {
    if (c1.duration < best.duration) best = c1;
    if (c2.duration < best.duration) best = c2;
    if (iteration == iterations) return best;
    if (c1.duration <= c2.duration) {  // the minimum lies in [lo, x2]
      hi = x2;
      x2 = x1;
      c2 = std::move(c1);
      x1 = hi - golden * (hi - lo);
      c1 = evaluate(x1);
    } else {  // in [x1, hi]
      lo = x1;
      x1 = x2;
      c1 = std::move(c2);
      x2 = lo + golden * (hi - lo);
      c2 = evaluate(x2);
    }
  }
}

}  // namespace

AccelerationSteps acceleration_steps(const std::vector<GridPoint>& grid, std::size_t first, std::size_t count,
                                     const Parameterisation& fastest) {
  AccelerationSteps steps;
  steps.time.resize(count + 1);
  steps.position.resize(count + 1);
  steps.speed.resize(count + 1);
  steps.acceleration.resize(count);
  double time = 0.0;
  for (std::size_t i = 0; i <= count; ++i) {
    steps.time[i] = time;
    steps.position[i] = grid[first + i].sigma;
    steps.speed[i] = std::sqrt(fastest.x[i]);
    if (i == count) break;
    const double delta = grid[first + i + 1].sigma - grid[first + i].sigma;
    steps.acceleration[i] = fastest.u[i];
    time += 2.0 * delta / (std::sqrt(fastest.x[i]) + std::sqrt(fastest.x[i + 1]));
  }
  steps.speed.front() = steps.speed.back() = 0.0;
  return steps;
}

void append_jerk_laws(const SmoothParameter& smooth, std::vector<JerkPhase> phases, double run_end,
                      std::vector<Profile>& laws) {
  const double run_start = phases.front().position;
  // Cut at every section start inside the run; σ is non-decreasing, so by bisection on the
  // phase's cubic.
  std::vector<JerkPhase> cut;
  cut.reserve(phases.size() + smooth.sections());
  std::size_t k = smooth.section_at(run_start) + 1;
  for (std::size_t m = 0; m < phases.size(); ++m) {
    JerkPhase p = phases[m];
    const double next = m + 1 < phases.size() ? phases[m + 1].position : run_end;
    while (k < smooth.sections() && smooth.start(k) < run_end && smooth.start(k) <= p.position) ++k;
    while (k < smooth.sections() && smooth.start(k) < next && smooth.start(k) < run_end) {
      const double target = smooth.start(k);
      double lo = 0.0, hi = p.duration;
      for (int iteration = 0; iteration < 200 && hi - lo > 1e-15 * p.duration; ++iteration) {
        const double mid = 0.5 * (lo + hi);
        (advance(p, mid).position < target ? lo : hi) = mid;
      }
      if (hi > 1e-12 * p.duration && hi < p.duration * (1.0 - 1e-12)) {
        JerkPhase head = p;
        head.duration = hi;
        cut.push_back(head);
        p = advance(p, hi);
        p.position = target;  // exactly on the section start
      }
      ++k;
    }
    cut.push_back(p);
  }
  // Group by section, at most max_phases per law.
  std::size_t first = 0;
  while (first < cut.size()) {
    auto section_of = [&](const JerkPhase& p) { return smooth.section_at(advance(p, 0.5 * p.duration).position); };
    const std::size_t section = section_of(cut[first]);
    std::size_t last = first + 1;
    while (last < cut.size() && last - first < static_cast<std::size_t>(Profile::max_phases) &&
           section_of(cut[last]) == section)
      ++last;
    const double r = smooth.s_per_sigma(section);
    double durations[Profile::max_phases], jerks[Profile::max_phases];
    for (std::size_t m = first; m < last; ++m) {
      durations[m - first] = cut[m].duration;
      jerks[m - first] = r * cut[m].jerk;
    }
    const JerkPhase& a = cut[first];
    const double end_position = last < cut.size() ? cut[last].position : run_end;
    const double end_speed = last < cut.size() ? cut[last].speed : 0.0;
    const double end_acceleration = last < cut.size() ? cut[last].acceleration : 0.0;
    laws.push_back(Profile::from_phases(durations, jerks, static_cast<int>(last - first), r * a.speed,
                                        r * a.acceleration, r * std::max(0.0, end_position - a.position), r * end_speed,
                                        r * end_acceleration));
    first = last;
  }
}

JerkLimitedSolution jerk_limited_solution(const RunProblem& problem, double acceleration_limit, double jerk_limit) {
  const SmoothParameter& smooth = problem.smooth();
  const double run_start = problem.start(), run_end = problem.end();
  // The run's lowest σ per s: its acceleration and jerk caps in σ are a ρ and j ρ.
  double rho = std::numeric_limits<double>::infinity();
  for (std::size_t k = smooth.section_at(run_start); k < smooth.sections() && smooth.start(k) < run_end; ++k) {
    if (smooth.ell(k) > 0.0) rho = std::min(rho, 1.0 / smooth.s_per_sigma(k));
  }
  const double top_acceleration = acceleration_limit * rho, run_jerk = jerk_limit * rho;
  auto top_speed = [](const Parameterisation& p) { return std::sqrt(*std::max_element(p.x.begin(), p.x.end())); };
  // The jerk-limited law under the acceleration cap A ≤ a ρ and the speed cap V: its window
  // and its duration.
  struct Candidate {
    double cap, speed, window, duration;
    Parameterisation fastest;
    AccelerationSteps steps;
  };
  auto jerk_limited = [&](double cap, double speed) {
    Candidate c{cap, speed, 0.0, std::numeric_limits<double>::infinity(), {}, {}};
    const double longest = 2.0 * cap / run_jerk;  // 2A/j: a window that always suffices
    // First without the reach: its window and its top speed (tightening only lowers the
    // speeds) estimate the reach; widened and re-solved until the solve keeps to it.
    c.fastest = problem.solve(0.0, cap, speed);
    c.steps = acceleration_steps(problem.grid(), problem.run().first, problem.run().count, c.fastest);
    double assumed = smallest_window(c.steps, run_jerk, longest);
    double speed_bound = top_speed(c.fastest);
    for (int attempt = 0;; ++attempt) {
      const double reach = assumed * speed_bound;
      c.fastest = problem.solve(reach, cap, speed);
      c.steps = acceleration_steps(problem.grid(), problem.run().first, problem.run().count, c.fastest);
      c.window = smallest_window(c.steps, run_jerk, longest);
      const double top = top_speed(c.fastest);
      if (c.window <= assumed && c.window * top <= reach) break;
      if (attempt == 20) {
        throw std::runtime_error("jerk limiting: the moving-average window did not settle on the path interval " +
                                 interval_text(smooth.s_of(run_start), smooth.s_of(run_end)));
      }
      assumed = std::min(longest, std::max(c.window, 1.25 * assumed));
      speed_bound = std::max(speed_bound, top);
    }
    c.duration = c.steps.time.back() + c.window;
    return c;
  };
  // The window grows with the steps of σ̈: where the jerk limit is low against the
  // accelerations the joints allow, a lower acceleration cap A gives a shorter law (as the
  // S-curve's peak acceleration stays below a_max when a/j is long against the move), and a
  // speed cap V below what the joints allow gives a flat cruise instead of a speed that
  // follows a joint limit up and down (each change a step of σ̈). (A, V) are chosen to
  // minimise the duration: for each V of a scan, a scan of A over three decades and a
  // golden-section search between the best A's neighbours.
  auto best_for_speed = [&](double speed) {
    constexpr int scan = 8;
    constexpr double decades = 3.0;
    auto cap_at = [&](double e) { return top_acceleration * std::pow(10.0, -decades * e); };  // e ∈ [0, 1]
    std::vector<Candidate> scanned;
    scanned.reserve(scan + 1);
    std::size_t best = 0;
    for (int i = 0; i <= scan; ++i) {
      scanned.push_back(jerk_limited(cap_at(static_cast<double>(i) / scan), speed));
      if (scanned.back().duration < scanned[best].duration) best = scanned.size() - 1;
    }
    // Between the best A's neighbours.
    return golden_section(std::max(0.0, (static_cast<double>(best) - 1.0) / scan),
                          std::min(1.0, (static_cast<double>(best) + 1.0) / scan), 8, scanned[best],
                          [&](double e) { return jerk_limited(cap_at(e), speed); });
  };
  // V as a fraction f of the top speed without a jerk limit (f = 1: no cap): a scan, then
  // golden-section search between the best fraction's neighbours.
  const double free_speed = top_speed(problem.solve(0.0, top_acceleration));
  const std::vector<double> fractions{1.0, 0.95, 0.9, 0.8, 0.7, 0.6, 0.5, 0.4, 0.3};
  auto at_fraction = [&](double f) {
    return best_for_speed(f >= 1.0 ? std::numeric_limits<double>::infinity() : f * free_speed);
  };
  std::size_t best = 0;
  Candidate chosen = at_fraction(fractions[0]);
  for (std::size_t i = 1; i < fractions.size(); ++i) {
    Candidate c = at_fraction(fractions[i]);
    if (c.duration < chosen.duration) {
      chosen = std::move(c);
      best = i;
    }
  }
  // Between the best fraction's neighbours (fractions fall: the one after is the lower end).
  chosen = golden_section(fractions[std::min(best + 1, fractions.size() - 1)], fractions[best > 0 ? best - 1 : 0], 6,
                          std::move(chosen), at_fraction);
  return {std::move(chosen.fastest), std::move(chosen.steps), chosen.window};
}

void append_acceleration_laws(const RunProblem& problem, const Parameterisation& fastest, double acceleration_limit,
                              std::vector<Profile>& laws) {
  const SmoothParameter& smooth = problem.smooth();
  const std::vector<GridPoint>& grid = problem.grid();
  const Run& run = problem.run();
  for (std::size_t i = 0; i < run.count; ++i) {
    const double sigma0 = grid[run.first + i].sigma, sigma1 = grid[run.first + i + 1].sigma;
    const double x0 = fastest.x[i], u = fastest.u[i];
    for (double a = sigma0; a < sigma1;) {
      const std::size_t k = smooth.section_at(a);
      double b = k + 1 < smooth.sections() ? std::min(sigma1, smooth.start(k + 1)) : sigma1;
      if (!(b > a)) break;
      // A section boundary within rounding of the interval's end: one piece to the end (a
      // piece of 1e-15 m would only test the rounding of the trapezoid's feasibility check).
      if (sigma1 - b <= 1e-9 * (sigma1 - sigma0)) b = sigma1;
      if (b - a <= 1e-9 * (sigma1 - sigma0)) {  // the same at the interval's start
        a = b;
        continue;
      }
      const double r = smooth.s_per_sigma(k);
      const double v0 = r * std::sqrt(std::max(0.0, x0 + 2.0 * u * (a - sigma0)));
      const double v1 = r * std::sqrt(std::max(0.0, x0 + 2.0 * u * (b - sigma0)));
      const double distance = r * (b - a);
      // The trapezoid between v0 and v1 whose acceleration just covers the distance (a hair
      // above, so that rounding cannot make the law infeasible). |v1 − v0| (v1 + v0), the form
      // of the trapezoid's own check: v1² − v0² cancels when the speeds nearly agree.
      const double acc =
          std::max(std::abs(v1 - v0) * (v1 + v0) / (2.0 * distance) * (1.0 + 1e-9), 1e-12 * acceleration_limit);
      laws.push_back(Profile::trapezoid(distance, std::max(v0, v1), acc, v0, v1));
      a = b;
    }
  }
}

}  // namespace dispkin::detail
