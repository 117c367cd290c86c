// Trajectory::stopped_at and with_override against Ruckig's 1-DoF update from the same state,
// one process, the same seeded requests (control_events.hpp: a single LIN and a 50-move blended
// chain, S-curve and trapezoid). Built only when DISPKIN_RUCKIG_DIR names a Ruckig source tree
// (benchmarks/CMakeLists.txt); Ruckig is measured, nothing of it is part of dispkin.
// Results: benchmarks/history/2026-12-04-control-loop-requests-stop-speed-override-append.md.
//
// The state of each request is (ṡ, s̈) = sample(t) of the trajectory (s̈ = 0 for the trapezoid,
// where it is no state). Ruckig is given it as input; dispkin finds it in the trajectory itself.
//   stop:     Ruckig<1>::calculate, velocity control interface, from (ṡ, s̈) to v = 0, a = 0
//             under the trajectory's a_max and j_max (j_max = ∞ for the trapezoid)
//             vs Trajectory::stopped_at(t): the motion up to t kept, the fastest stop after it.
//   override: Ruckig<1>::calculate, position interface, from (ṡ, s̈) over the remaining distance
//             (length − s) to rest at max_velocity = factor × v_max, min_velocity = 0
//             vs Trajectory::with_override(t, factor): the motion up to t kept, then the law over
//             factor × the velocity-limit curve to the end of the path.
// dispkin's request returns a new trajectory (copies of the path and its vectors, freed inside
// the timing); Ruckig's fills the same output object each time. Timing: passes over all requests
// in alternating rounds by the thread CPU time (the ratio dispkin / Ruckig of each round; its
// median and range), and per request for the median and the largest: each dispkin call alone,
// Ruckig's as the mean of 64 calls on the same state (one call is well below the cost of reading
// the thread CPU clock, about 0.5 µs in the KVM guest of RESULTS.md).
// Agreement: the largest relative difference of the stop durations over the moving states.
//
// Usage: dispkin_control_events_vs_ruckig [requests=1000] [rounds=21]
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

#include <ruckig/ruckig.hpp>

#include "control_events.hpp"

namespace {

using namespace control_events;

constexpr double nan = std::numeric_limits<double>::quiet_NaN();
constexpr int kRepeat = 64;  // Ruckig calls per timed request

struct RuckigOne {
  ruckig::Ruckig<1> otg;
  ruckig::InputParameter<1> stop, move;
  ruckig::Trajectory<1> out;

  explicit RuckigOne(const Workload& w) {
    const double j = w.limits.jerk ? *w.limits.jerk : std::numeric_limits<double>::infinity();
    for (auto* in : {&stop, &move}) {
      in->current_position = {0.0};
      in->target_velocity = {0.0};
      in->target_acceleration = {0.0};
      in->max_velocity = {w.limits.velocity};
      in->max_acceleration = {w.limits.acceleration};
      in->max_jerk = {j};
    }
    stop.control_interface = ruckig::ControlInterface::Velocity;
    move.min_velocity = {0.0};
  }
  ruckig::Result last = ruckig::Result::Working;
  double calculate(const ruckig::InputParameter<1>& in) {
    last = otg.calculate(in, out);
    return last == ruckig::Result::Working || last == ruckig::Result::Finished ? out.get_duration() : nan;
  }
  // The duration, NaN where Ruckig reports no law.
  double stop_from(double v, double a) {
    stop.current_velocity = {v};
    stop.current_acceleration = {a};
    return calculate(stop);
  }
  double move_from(double distance, double v, double a, double v_max) {
    move.current_velocity = {v};
    move.current_acceleration = {a};
    move.target_position = {distance};
    move.max_velocity = {v_max};
    return calculate(move);
  }
};

struct State {
  double t, factor, remaining, v, a;
};

std::string load_average() {
  std::ifstream in("/proc/loadavg");
  std::string a, b, c;
  in >> a >> b >> c;
  return a + " " + b + " " + c;
}

}  // namespace

int main(int argc, char** argv) {
  const std::size_t count = argc > 1 ? static_cast<std::size_t>(std::atol(argv[1])) : 1000;
  const int rounds = argc > 2 ? std::atoi(argv[2]) : 21;
  const double overhead = thread_clock_overhead();
  std::printf(
      "%zu requests per trajectory, %d alternating rounds; thread CPU clock pair %.0f ns (subtracted per call); "
      "load average %s\n",
      count, rounds, overhead, load_average().c_str());
  std::printf("%-26s %-9s | %-19s | %-19s | %9s %9s | %-22s | %8s %6s\n", "trajectory", "request",
              "dispkin median/max us", "Ruckig median/max us", "dk pass", "Rk pass", "dispkin/Ruckig [range]",
              "max diff", "failed");
  std::vector<std::string> failures;
  for (const Workload& w : workloads()) {
    const Trajectory& traj = w.trajectory;
    std::vector<State> states;
    for (const Request& r : requests(traj, count, 7002)) {
      const dispkin::TrajectorySample x = traj.sample(r.t);
      states.push_back({r.t, r.factor, traj.length() - x.s, x.s_dot, w.kind == ProfileKind::scurve ? x.s_ddot : 0.0});
    }
    RuckigOne ruckig(w);
    for (int request = 0; request < 2; ++request) {
      const bool stop = request == 0;
      // Agreement of the stop durations, and Ruckig's failures.
      double worst = 0.0;
      std::size_t failed = 0;
      for (const State& x : states) {
        const double theirs =
            stop ? ruckig.stop_from(x.v, x.a) : ruckig.move_from(x.remaining, x.v, x.a, x.factor * w.limits.velocity);
        if (!std::isfinite(theirs)) {
          if (failed++ == 0)
            failures.push_back(w.name + (stop ? " stop" : " override") + ": Ruckig result " +
                               std::to_string(static_cast<int>(ruckig.last)) + " at t = " + std::to_string(x.t) +
                               " s: v = " + std::to_string(x.v) + ", a = " + std::to_string(x.a) + ", remaining " +
                               std::to_string(x.remaining) + " m, factor " + std::to_string(x.factor));
          continue;
        }
        if (stop && x.v > 1e-9) {
          const double ours = traj.stopped_at(x.t).duration() - x.t;
          worst = std::max(worst, std::abs(ours - theirs) / theirs);
        }
      }
      const auto dispkin_call = [&](const State& x) {
        const Trajectory out = stop ? traj.stopped_at(x.t) : traj.with_override(x.t, x.factor);
        keep(out);
      };
      const auto ruckig_call = [&](const State& x) {
        keep(stop ? ruckig.stop_from(x.v, x.a) : ruckig.move_from(x.remaining, x.v, x.a, x.factor * w.limits.velocity));
      };
      const Rounds r = alternate(
          [&] {
            for (const State& x : states) ruckig_call(x);
          },
          [&] {
            for (const State& x : states) dispkin_call(x);
          },
          states.size(), rounds);
      // Per request: one dispkin call; Ruckig's, far below the thread clock's own cost, as the
      // mean of kRepeat calls on the same state.
      std::vector<double> ours, theirs;
      const auto ruckig_repeated = [&](const State& x) {
        for (int k = 0; k < kRepeat; ++k) ruckig_call(x);
      };
      for (int sweep = 0; sweep < 3; ++sweep) {
        for (const State& x : states) {
          if (sweep % 2 == 0) {
            ours.push_back(time_call([&] { dispkin_call(x); }, overhead));
            theirs.push_back(time_call([&] { ruckig_repeated(x); }, overhead) / kRepeat);
          } else {
            theirs.push_back(time_call([&] { ruckig_repeated(x); }, overhead) / kRepeat);
            ours.push_back(time_call([&] { dispkin_call(x); }, overhead));
          }
        }
      }
      char ratio[64];
      std::snprintf(ratio, sizeof ratio, "%7.1f [%5.1f, %5.1f]", r.ratio_median, r.ratio_min, r.ratio_max);
      char diff[32];
      if (stop)
        std::snprintf(diff, sizeof diff, "%8.1e", worst);
      else
        std::snprintf(diff, sizeof diff, "%8s", "-");
      std::printf("%-26s %-9s | %8.2f %10.2f | %8.3f %10.3f | %9.2f %9.3f | %-22s | %s %6zu\n", w.name.c_str(),
                  stop ? "stop" : "override", median(ours) * 1e-3, largest(ours) * 1e-3, median(theirs) * 1e-3,
                  largest(theirs) * 1e-3, r.b_median * 1e-3, r.a_median * 1e-3, ratio, diff, failed);
      std::fflush(stdout);
    }
  }
  for (const std::string& f : failures) std::printf("first failure of %s\n", f.c_str());
  std::printf("load average after: %s\n", load_average().c_str());
  return 0;
}
