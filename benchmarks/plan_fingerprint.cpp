// Prints what plan() decides for seeded random paths and sets (the six path families and random
// sets of tests/cpp/random_paths.hpp, both profile kinds): section and law counts, the duration
// and the length, exactly (hexadecimal floating point). A performance change that must not
// change plans is checked by diffing this program's output before and after it
// (benchmarks/RESULTS.md).
//
//   dispkin_plan_fingerprint [count = 3000]
#include <cstdio>
#include <cstdlib>

#include <dispkin/planning/planner.hpp>

#include "../tests/cpp/random_paths.hpp"

int main(int argc, char** argv) {
  using namespace dispkin;
  const int count = argc > 1 ? std::atoi(argv[1]) : 3000;
  testing::Random rnd(901);
  for (int i = 0; i < count; ++i) {
    const double v = rnd.uniform(0.05, 1.0);
    const MetricSetd set = testing::random_set(rnd, v);
    const Path path = testing::random_path(rnd, i);
    const ProfileKind kind = i % 2 ? ProfileKind::scurve : ProfileKind::trapezoid;
    Limits limits{v, rnd.uniform(0.2, 5.0), std::nullopt};
    if (kind == ProfileKind::scurve) limits.jerk = rnd.uniform(1.0, 50.0);
    const Trajectory traj = plan(path, set, limits, kind);
    std::printf("%d family %d sections %zu pieces %zu laws %zu duration %a length %a\n", i, i % 6, traj.section_count(),
                traj.piece_count(), traj.law_count(), traj.duration(), traj.length());
  }
  return 0;
}
