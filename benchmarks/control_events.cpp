// The cost of the control-loop requests (doc/events.md) and of sampling after them. Not a Google
// Benchmark program: the figures wanted are per request (median, 99th percentile and largest over
// requests at seeded random instants), per append, and the worst of 10^6 consecutive samples.
// Results: benchmarks/history/2026-12-04-control-loop-requests-stop-speed-override-append.md.
//
//   requests  Trajectory::stopped_at(t) and with_override(t, factor) on a single LIN and a
//             50-move blended chain, S-curve and trapezoid (control_events.hpp): thread CPU time
//             per request, the result freed inside the timing; and where the time of a request
//             goes: the copies of the path and of the other vectors the new trajectory holds,
//             the motion up to t (TimeLaw::before), the constructor's consistency check, and the
//             rest (the state at t and the new law).
//   append    MotionStream::append at a random instant of a leg of n zig-zag LINs of 5–15 cm,
//             corner tolerance 1 mm, n = 2, 5, 10, 20, 50 (the move joined to the running leg),
//             with plan() of the longer path alone beside it.
//   stream    a program of 1000 LINs streamed as a controller feeds it (each move appended when
//             under 1.5 s is planned ahead, 1 kHz cycles): the cost of each append by how many
//             moves were appended before it — flat, since a join plans only the path ahead.
//   sample    10^6 consecutive 1 kHz cycles (t = k ms) of Trajectory::sample(t, cursor) and
//             MotionStream::sample(t, cursor) on the chain overridden to 2 % at 1 s, stopped at
//             600 s and resumed at 620 s (1434 s of motion), in a tight loop, three rounds
//             alternating with the clock alone; each call timed by std::chrono::steady_clock
//             (wall time: what a control loop sees, preemption included). Then 10^4 cycles paced
//             by sleeping until each next 1 ms deadline, as a real loop runs.
//
// Usage: dispkin_control_events [all|requests|append|stream|sample] [scale=1] [name]
//   scale multiplies the numbers of requests, appends and paced cycles (the tight sampling runs
//   are always 10^6 cycles); name keeps only the trajectories whose name holds it, e.g.
//   "chain, S-curve" (for a profiler: valgrind --tool=callgrind --toggle-collect=...).
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include "control_events.hpp"

namespace {

using namespace control_events;
using dispkin::MotionStream;
using dispkin::SampledPath;
using dispkin::TimeLaw;

std::string load_average() {
  std::ifstream in("/proc/loadavg");
  std::string a, b, c;
  in >> a >> b >> c;
  return a + " " + b + " " + c;
}

std::size_t scaled(std::size_t n, double scale) {
  return std::max<std::size_t>(1, static_cast<std::size_t>(static_cast<double>(n) * scale));
}

void run_requests(double scale, const std::string& only) {
  const double overhead = thread_clock_overhead();
  std::printf("== requests: thread CPU time per call (us), clock pair %.0f ns subtracted; load average %s\n", overhead,
              load_average().c_str());
  std::printf("%-26s %5s %8s %6s %9s | %-26s | %-26s\n", "trajectory", "laws", "sections", "spans", "duration",
              "stopped_at median/p99/max", "with_override median/p99/max");
  struct Parts {
    std::vector<double> request, path, vectors, before, check, rest;
  };
  std::vector<std::pair<std::string, std::pair<Parts, Parts>>> breakdowns;
  std::vector<double> whole_copy_medians;
  for (const Workload& w : workloads()) {
    if (w.name.find(only) == std::string::npos) continue;
    const Trajectory& traj = w.trajectory;
    const std::vector<Request> reqs = requests(traj, scaled(10000, scale), 7001);
    for (std::size_t i = 0; i < 50; ++i) keep(traj.stopped_at(reqs[i].t));  // warm-up
    Parts stop, over;
    std::vector<double> whole_copy;
    for (const Request& r : reqs) {
      const double ts = time_call(
          [&] {
            const Trajectory x = traj.stopped_at(r.t);
            keep(x);
          },
          overhead);
      const double to = time_call(
          [&] {
            const Trajectory x = traj.with_override(r.t, r.factor);
            keep(x);
          },
          overhead);
      const double tp = time_call(
          [&] {
            const SampledPath p(traj.path());
            keep(p);
          },
          overhead);
      const double tv = time_call(
          [&] {
            const auto a = traj.speed_limits();
            const auto b = traj.rest_positions();
            const auto c = traj.stops();
            const auto d = traj.section_sources();
            keep(a), keep(b), keep(c), keep(d);
          },
          overhead);
      const double tb = time_call(
          [&] {
            const TimeLaw l = traj.time_law().before(r.t);
            keep(l);
          },
          overhead);
      const double tc = time_call([&] { traj.require_consistent(); }, overhead);
      whole_copy.push_back(time_call(
          [&] {
            const Trajectory x(traj);
            keep(x);
          },
          overhead));
      for (auto* p : {&stop, &over}) {
        p->path.push_back(tp);
        p->vectors.push_back(tv);
        p->before.push_back(tb);
        p->check.push_back(tc);
      }
      stop.request.push_back(ts);
      stop.rest.push_back(ts - tp - tv - tb - tc);
      over.request.push_back(to);
      over.rest.push_back(to - tp - tv - tb - tc);
    }
    const Spread s = spread(stop.request), o = spread(over.request);
    std::printf("%-26s %5zu %8zu %6zu %8.2fs | %8.2f %8.2f %8.2f | %8.2f %8.2f %8.2f\n", w.name.c_str(),
                traj.law_count(), traj.section_count(), traj.speed_limits().size(), traj.duration(), s.median * 1e-3,
                s.p99 * 1e-3, s.max * 1e-3, o.median * 1e-3, o.p99 * 1e-3, o.max * 1e-3);
    std::fflush(stdout);
    breakdowns.push_back({w.name, {stop, over}});
    whole_copy_medians.push_back(median(whole_copy));
  }
  std::printf(
      "\nwhere the time of a request goes (medians over the same requests, us; rest = request less the parts, "
      "per request)\n");
  std::printf("%-26s %-13s %9s %9s %9s %9s %9s %9s %11s\n", "trajectory", "request", "request", "path copy", "vectors",
              "before(t)", "check", "rest", "whole copy");
  for (std::size_t i = 0; i < breakdowns.size(); ++i) {
    for (int k = 0; k < 2; ++k) {
      const Parts& p = k == 0 ? breakdowns[i].second.first : breakdowns[i].second.second;
      std::printf("%-26s %-13s %9.2f %9.2f %9.2f %9.2f %9.2f %9.2f %11.2f\n", breakdowns[i].first.c_str(),
                  k == 0 ? "stopped_at" : "with_override", median(p.request) * 1e-3, median(p.path) * 1e-3,
                  median(p.vectors) * 1e-3, median(p.before) * 1e-3, median(p.check) * 1e-3, median(p.rest) * 1e-3,
                  whole_copy_medians[i] * 1e-3);
    }
  }
  std::printf("load average after: %s\n\n", load_average().c_str());
}

void run_append(double scale) {
  const double overhead = thread_clock_overhead();
  std::printf(
      "== MotionStream::append to a running leg of n LINs (S-curve, v 0.2, a 1, j 10, corner tolerance 1 mm), "
      "thread CPU us; load average %s\n",
      load_average().c_str());
  std::printf("%4s %7s %8s %9s %9s %9s %9s | %11s\n", "n", "joined", "new leg", "median", "p99", "max", "per move",
              "plan median");
  const dispkin::MetricSetd set = tool_set();
  const dispkin::Limits limits = limits_for(ProfileKind::scurve);
  dispkin::PlanOptions options;
  options.corner_tolerance = kCornerTolerance;
  const std::size_t legs = scaled(20, scale), instants = 10;
  for (const int n : {2, 5, 10, 20, 50}) {
    std::vector<double> append_ns, plan_ns;
    std::size_t joined = 0, new_leg = 0;
    for (std::size_t rep = 0; rep < legs; ++rep) {
      std::mt19937_64 rng(9000 + 100 * static_cast<std::uint64_t>(n) + rep);
      const std::vector<Path> moves = zigzag(rng, n + 1);
      MotionStream base(set, limits, ProfileKind::scurve, kCornerTolerance);
      for (int k = 0; k < n; ++k) base.append(moves[static_cast<std::size_t>(k)], 0.0);
      const Path longer = joined_path(moves, static_cast<std::size_t>(n) + 1);
      std::uniform_real_distribution<double> instant(0.0, 0.9 * base.duration());
      for (std::size_t i = 0; i < instants; ++i) {
        const double t = instant(rng);
        MotionStream stream = base;  // copied and freed outside the timing
        const double ns = time_call([&] { stream.append(moves.back(), t); }, overhead);
        if (stream.leg_count() == 1) {
          ++joined;
          append_ns.push_back(ns);
        } else {
          ++new_leg;
        }
        plan_ns.push_back(time_call(
            [&] {
              const Trajectory x = dispkin::plan(longer, set, limits, ProfileKind::scurve, options);
              keep(x);
            },
            overhead));
      }
    }
    const Spread a = spread(append_ns);
    std::printf("%4d %7zu %8zu %9.1f %9.1f %9.1f %9.1f | %11.1f\n", n, joined, new_leg, a.median * 1e-3, a.p99 * 1e-3,
                a.max * 1e-3, a.median * 1e-3 / (n + 1), median(plan_ns) * 1e-3);
    std::fflush(stdout);
  }
  std::printf("load average after: %s\n\n", load_average().c_str());
}

// A program streamed as a controller feeds it: 1000 zig-zag LINs, each appended when less than
// 1.5 s of motion is planned beyond the current cycle (1 kHz), so the look-ahead stays the same
// while the moves run grow. The cost of each append, by how many moves were appended before it.
void run_stream(double scale) {
  const double overhead = thread_clock_overhead();
  const std::size_t count = scaled(1000, scale);
  std::printf(
      "== MotionStream fed just in time: %zu LINs (S-curve, v 0.2, a 1, j 10, corner tolerance 1 mm), each appended "
      "when under 1.5 s is planned ahead; thread CPU us per append by moves appended before; load average %s\n",
      count, load_average().c_str());
  std::mt19937_64 rng(9500);
  const std::vector<Path> moves = zigzag(rng, count);
  MotionStream stream(tool_set(), limits_for(ProfileKind::scurve), ProfileKind::scurve, kCornerTolerance);
  stream.append(moves[0], 0.0);
  const std::size_t buckets = 5, per_bucket = (count + buckets - 1) / buckets;
  std::vector<std::vector<double>> ns(buckets);
  std::size_t next = 1;
  double t = 0.0;
  while (next < moves.size()) {
    if (stream.duration() - t < 1.5) {
      MotionStream copy = stream;  // the worker's copy, made and freed outside the timing
      ns[next / per_bucket].push_back(time_call([&] { copy.append(moves[next], t); }, overhead));
      stream = std::move(copy);
      ++next;
    }
    t += 1e-3;
  }
  std::printf("%-22s %8s %9s %9s %9s\n", "moves appended before", "appends", "median", "p99", "max");
  for (std::size_t b = 0; b < buckets; ++b) {
    const Spread a = spread(ns[b]);
    std::printf("%8zu – %-11zu %8zu %9.1f %9.1f %9.1f\n", b * per_bucket, std::min(count, (b + 1) * per_bucket) - 1,
                ns[b].size(), a.median * 1e-3, a.p99 * 1e-3, a.max * 1e-3);
  }
  std::printf("legs from rest: %zu (1: it never stopped); duration %.1f s\n", stream.leg_count(), stream.duration());
  std::printf("load average after: %s\n\n", load_average().c_str());
}

struct Tail {
  double median, p99, p9999, max;
  std::size_t over_10us;
};

Tail tail(const std::vector<double>& ns) {
  std::size_t over = 0;
  for (double x : ns) over += x > 10000.0;
  return {median(ns), quantile(ns, 0.99), quantile(ns, 0.9999), largest(ns), over};
}

void print_tail(const char* what, const Tail& t) {
  std::printf("%-44s %9.0f %9.0f %9.0f %10.0f %8zu\n", what, t.median, t.p99, t.p9999, t.max, t.over_10us);
  std::fflush(stdout);
}

void run_sample(std::size_t paced_cycles) {
  using Clock = std::chrono::steady_clock;
  constexpr std::size_t cycles = 1000000;
  const std::vector<Workload> all = workloads();
  const Workload& chain = all[1];  // the 50-move chain, S-curve
  const Trajectory events = chain.trajectory.with_override(1.0, 0.02).stopped_at(600.0).resumed_at(620.0);
  MotionStream stream(tool_set(), chain.limits, ProfileKind::scurve, kCornerTolerance);
  {
    std::mt19937_64 rng(20261206);  // the moves of the chain
    const std::vector<Path> moves = zigzag(rng, 50);
    for (std::size_t k = 0; k < 10; ++k) stream.append(moves[k], 0.0);
    stream.set_override(1.0, 0.02);
    for (std::size_t k = 10; k < moves.size(); ++k) stream.append(moves[k], 2.0 * static_cast<double>(k - 9));
    stream.stop(600.0);
    stream.resume(620.0);
  }
  std::printf(
      "== sampling: %zu consecutive 1 kHz cycles (t = k ms) in a tight loop, steady_clock ns per call (wall time); "
      "load average %s\n",
      cycles, load_average().c_str());
  std::printf("trajectory: %.1f s, %zu laws, %zu sections; stream: %.1f s, %zu leg(s)\n", events.duration(),
              events.law_count(), events.section_count(), stream.duration(), stream.leg_count());
  std::printf("%-44s %9s %9s %9s %10s %8s\n", "", "median", "p99", "p99.99", "max", ">10us");
  std::vector<double> ns(cycles);
  const auto run = [&](std::size_t n, bool paced, auto&& sample_at) {
    ns.assign(n, 0.0);
    auto deadline = Clock::now();
    for (std::size_t k = 0; k < n; ++k) {
      if (paced) {
        deadline += std::chrono::milliseconds(1);
        std::this_thread::sleep_until(deadline);
      }
      const double t = 1e-3 * static_cast<double>(k);
      const auto a = Clock::now();
      const dispkin::TrajectorySample x = sample_at(t);
      const auto b = Clock::now();
      keep(x);
      ns[k] = static_cast<double>(std::chrono::duration_cast<std::chrono::nanoseconds>(b - a).count());
    }
    return tail(ns);
  };
  const auto nothing = [](double) { return dispkin::TrajectorySample{}; };
  for (int round = 1; round <= 3; ++round) {
    const std::string r = " (" + std::to_string(round) + ")";
    print_tail(("steady_clock pair alone, the floor" + r).c_str(), run(cycles, false, nothing));
    Trajectory::Cursor tc;
    print_tail(("Trajectory::sample(t, cursor)" + r).c_str(),
               run(cycles, false, [&](double t) { return events.sample(t, tc); }));
    MotionStream::Cursor sc;
    print_tail(("MotionStream::sample(t, cursor)" + r).c_str(),
               run(cycles, false, [&](double t) { return stream.sample(t, sc); }));
  }
  if (paced_cycles > 0) {
    std::printf("paced: %zu cycles each, sleeping until every next 1 ms deadline (caches as a real loop leaves them)\n",
                paced_cycles);
    print_tail("steady_clock pair alone, paced", run(paced_cycles, true, nothing));
    Trajectory::Cursor tc;
    print_tail("Trajectory::sample(t, cursor), paced",
               run(paced_cycles, true, [&](double t) { return events.sample(t, tc); }));
    MotionStream::Cursor sc;
    print_tail("MotionStream::sample(t, cursor), paced",
               run(paced_cycles, true, [&](double t) { return stream.sample(t, sc); }));
  }
  std::printf("load average after: %s\n\n", load_average().c_str());
}

}  // namespace

int main(int argc, char** argv) {
  const std::string part = argc > 1 ? argv[1] : "all";
  const double scale = argc > 2 ? std::atof(argv[2]) : 1.0;
  const std::string only = argc > 3 ? argv[3] : "";
  if (part != "all" && part != "requests" && part != "append" && part != "stream" && part != "sample") {
    std::fprintf(stderr, "usage: %s [all|requests|append|stream|sample] [scale=1] [trajectories named with this]\n",
                 argv[0]);
    return 2;
  }
  if (part == "all" || part == "requests") run_requests(scale, only);
  if (part == "all" || part == "append") run_append(scale);
  if (part == "all" || part == "stream") run_stream(scale);
  if (part == "all" || part == "sample") run_sample(scaled(10000, scale));
  return 0;
}
