// S-curve cycle times under many changes of the speed limit (not a timing of the planner alone: a
// program that prints durations, ratios and planning CPU times; doc/profiles.md §8): for each
// workload the trapezoid plan, the S-curve plan, and the S-curve as the chain of laws at rest
// acceleration at every boundary (velocity_limited_chain over the same staircase, what the S-curve
// planned before the law carried acceleration), with the thread CPU time of both laws, and the
// duration no jerk-limited law under the staircase can beat (doc/profiles.md §8.5).
//
//   build/cmake/benchmarks/dispkin_scurve_staircase [DIR]
//
// With DIR, each workload's staircase is also written to DIR/<name>.txt (rows "length limit", then
// a line "# a j"), for benchmarks/scurve_grid_optimum.py.
#include <time.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <string>
#include <random>
#include <vector>

#include "dispkin/planning/planner.hpp"
#include "dispkin/planning/velocity_limit.hpp"
#include "dispkin/shapes.hpp"

namespace {

using dispkin::Path;
using dispkin::Posed;
using V = Eigen::Vector3d;

double thread_cpu() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

Path lins_through(const std::vector<Posed>& poses) {
  Path path = Path::lin(poses[0], poses[1]);
  for (std::size_t i = 2; i < poses.size(); ++i) path.then(Path::lin(poses[i - 1], poses[i]));
  return path;
}

// The staircases of a plan, one per run between rests.
std::vector<std::vector<dispkin::LimitedSegment>> staircases(const dispkin::Trajectory& traj) {
  std::vector<std::vector<dispkin::LimitedSegment>> runs;
  const std::vector<double>& rests = traj.rest_positions();
  std::size_t r = 1;
  runs.emplace_back();
  for (const dispkin::SpeedLimit& g : traj.speed_limits()) {
    if (r + 1 < rests.size() && g.start_s >= rests[r] - 1e-12 * traj.length()) {
      runs.emplace_back();
      ++r;
    }
    runs.back().push_back({g.length, g.limit});
  }
  return runs;
}

const char* staircase_dir = nullptr;

void write_staircases(const char* name, const std::vector<std::vector<dispkin::LimitedSegment>>& runs, double a,
                      double j) {
  std::string file = std::string(staircase_dir) + "/";
  for (const char* c = name; *c; ++c) file += std::isalnum(static_cast<unsigned char>(*c)) ? *c : '_';
  FILE* out = std::fopen((file + ".txt").c_str(), "w");
  if (!out) return;
  for (const auto& run : runs) {
    for (const dispkin::LimitedSegment& g : run) std::fprintf(out, "%.17g %.17g\n", g.length, g.limit);
    std::fprintf(out, "# %.17g %.17g\n", a, j);
  }
  std::fclose(out);
}

void report(const char* name, const Path& path, const dispkin::MetricSetd& set, double v, double a, double j,
            double tolerance) {
  dispkin::PlanOptions options;
  options.corner_tolerance = tolerance;
  const double trapezoid =
      dispkin::plan(path, set, dispkin::Limits{v, a, {}}, dispkin::ProfileKind::trapezoid, options).duration();
  const double plan_start = thread_cpu();
  const dispkin::Trajectory scurve =
      dispkin::plan(path, set, dispkin::Limits{v, a, j}, dispkin::ProfileKind::scurve, options);
  const double plan_cpu = thread_cpu() - plan_start;
  // The chain and the law over the same staircases, timed in alternating rounds (best of 5).
  const auto runs = staircases(scurve);
  double chain = 0.0, law = 0.0, chain_cpu = 1e300, law_cpu = 1e300;
  std::size_t segments = 0;
  for (const auto& run : runs) segments += run.size();
  for (int round = 0; round < 5; ++round) {
    double c = 0.0, l = 0.0;
    const double t0 = thread_cpu();
    for (const auto& run : runs)
      for (const dispkin::Profile& p : dispkin::velocity_limited_chain(run, a, j)) c += p.duration();
    const double t1 = thread_cpu();
    for (const auto& run : runs)
      for (const dispkin::Profile& p : dispkin::velocity_limited_law(run, a, j)) l += p.duration();
    const double t2 = thread_cpu();
    chain = c;
    law = l;
    chain_cpu = std::min(chain_cpu, t1 - t0);
    law_cpu = std::min(law_cpu, t2 - t1);
  }
  if (staircase_dir) write_staircases(name, runs, a, j);
  double bound = 0.0;
  for (const auto& run : runs) bound += dispkin::jerk_limited_duration_bound(run, a, j);
  std::printf(
      "%s: %zu segments in %zu runs; trapezoid %.3f s, S-curve %.3f s (its laws %.3f s; chain at rest "
      "boundaries %.3f s; no S-curve law below %.3f s); S-curve / trapezoid %.3f (chain %.3f, bound %.3f); law %.2f "
      "ms, chain %.2f ms CPU (%.1f x) of a %.0f ms plan\n",
      name, segments, runs.size(), trapezoid, scurve.duration(), law, chain, bound, scurve.duration() / trapezoid,
      chain / trapezoid, bound / trapezoid, 1e3 * law_cpu, 1e3 * chain_cpu, law_cpu / chain_cpu, 1e3 * plan_cpu);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc > 1) staircase_dir = argv[1];
  std::mt19937_64 engine(32);
  std::uniform_real_distribution<double> u(0.0, 1.0);

  // 400 LINs of 2–20 mm along x zig-zagging ±4 mm, a sphere and a tip on the tool; 0.5 mm blends.
  {
    std::vector<Posed> poses{Posed()};
    double x = 0.0;
    for (int k = 1; k <= 400; ++k) {
      x += 0.002 + 0.018 * u(engine);
      poses.emplace_back(Eigen::Quaterniond::Identity(), V(x, k % 2 ? 0.004 : -0.004, 0.0));
    }
    dispkin::MetricSetd set;
    set.add_sphere(V(0, 0, 0.1), 0.02);
    set.add_relative(V(0, 0, 0.15));
    report("zig-zag, 400 LINs, j 20", lins_through(poses), set, 0.2, 2.0, 20.0, 0.0005);
    report("zig-zag, 400 LINs, j 2000", lins_through(poses), set, 0.2, 2.0, 2000.0, 0.0005);
  }

  // A contour of 2000 moves of 0.08–0.24 mm on a 50 mm circle, the tool turning 0.005–0.015 rad
  // about its axis per move, a 0.1 m icosahedron around a 0.15 m long tool; blends of 0.01 mm.
  {
    std::vector<Posed> poses;
    double phi = 0.0, angle = 0.0;
    for (int k = 0; k <= 2000; ++k) {
      poses.emplace_back(Eigen::Quaterniond(Eigen::AngleAxisd(angle, V::UnitZ())),
                         V(0.05 * std::cos(phi), 0.05 * std::sin(phi), 0.0));
      phi += (0.00008 + 0.00016 * u(engine)) / 0.05;
      angle += 0.005 + 0.01 * u(engine);
    }
    dispkin::MetricSetd set;
    set.add_relative(dispkin::shapes::icosahedron(0.05));
    set.add_relative(V(0.0, 0.0, 0.15));
    report("turning contour, 2000 moves of 0.08-0.24 mm, j 10", lins_through(poses), set, 0.1, 1.0, 10.0, 0.00001);
  }

  // A 3-axis pocket of 5000 short G1 moves (0.2–1 mm, directions changing by up to 20°), G64-like
  // blends of 0.05 mm.
  {
    std::vector<Posed> poses{Posed()};
    V p = V::Zero();
    double heading = 0.0;
    for (int k = 1; k <= 5000; ++k) {
      heading += (u(engine) - 0.5) * 0.7;
      const double step = 0.0002 + 0.0008 * u(engine);
      p += step * V(std::cos(heading), std::sin(heading), 0.0);
      poses.emplace_back(Eigen::Quaterniond::Identity(), p);
    }
    dispkin::MetricSetd set;
    set.add_sphere(V(0.0, 0.0, 0.05), 0.01);  // a 20 mm cutter 50 mm below the spindle
    set.add_relative(V(0.0, 0.0, 0.0));
    report("pocket, 5000 G1 moves, j 50", lins_through(poses), set, 0.05, 1.0, 50.0, 0.00005);
  }
  return 0;
}
