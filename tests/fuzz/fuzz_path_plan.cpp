// libFuzzer target: paths from fuzzed poses — Path::lin (both interpolations), circ, spline,
// joined by then() with and without blends — planned under a fuzzed metric set and fuzzed
// Limits with either profile, then sampled. Every sample of a planned trajectory must be
// finite, with 0 ≤ ṡ ≤ v_sys (to rounding).
#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include <dispkin/path.hpp>
#include <dispkin/planner.hpp>

#include "fuzz_input.hpp"

namespace {

using dispkin::Path;
using dispkin::Posed;

// The cutting tolerance of a CIRC / SPLINE / blend: fuzzed (bad values must be refused), but
// a valid one below 1e-4 is raised to 1e-4: finer ones cut a move into up to 10^5 sections per
// piece, and building those takes seconds per input, which would stall the fuzzer.
double tolerance(dispkin::fuzz::Input& in) {
  if (!in.flag()) return 1e-3;
  const double t = in.number();
  return t > 0.0 && t < 1e-4 ? 1e-4 : t;
}

// One move starting at `start` (or a fuzzed pose).
Path move(dispkin::fuzz::Input& in, const std::optional<Posed>& start) {
  const Posed a = start && in.below(8) != 0 ? *start : in.pose();
  switch (in.below(3)) {
    case 0: {
      const Posed b = in.pose();
      const auto kind = in.flag() ? dispkin::Interpolation::screw : dispkin::Interpolation::decoupled;
      return Path::lin(a, b, kind, in.flag() ? in.vector3() : Eigen::Vector3d::Zero());
    }
    case 1: {
      const Posed via = in.pose();
      const Posed b = in.pose();
      const Eigen::Vector3d pivot = in.flag() ? in.vector3() : Eigen::Vector3d::Zero();
      return Path::circ(a, via, b, pivot, tolerance(in));
    }
    default: {
      std::vector<Posed> keys{a};
      const int n = 2 + in.below(4);
      for (int i = 0; i < n; ++i) keys.push_back(in.pose());
      const Eigen::Vector3d pivot = in.flag() ? in.vector3() : Eigen::Vector3d::Zero();
      return Path::spline(keys, pivot, tolerance(in));
    }
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using dispkin::fuzz::check_finite;
  dispkin::fuzz::Input in(data, size);
  dispkin::fuzz::expect_clean([&] {
    Path path = move(in, std::nullopt);
    const int more = in.below(3);
    for (int i = 0; i < more; ++i) {
      const Path next = move(in, path.end());
      switch (in.below(3)) {
        case 0:
          path.then(next);
          break;
        case 1:
          path.then(next, in.number());
          break;
        default: {
          const double before = in.number(), after = in.number();
          path.then(next, before, after, tolerance(in));
          break;
        }
      }
    }
    for (const double u : {0.0, 0.5, 1.0, in.number()}) check_finite(path.sample(u), "Path::sample");
    // Long paths (many moves at tolerance 1e-4) are built and sampled, planned only when short:
    // planning thousands of sections takes too long per input.
    if (path.size() > 2000) return;

    // The set: a fixed well-formed tool, sometimes with fuzzed extra objects and group limits.
    dispkin::MetricSetd set;
    set.add_relative({Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(0.1, 0, 0), Eigen::Vector3d(0, 0.1, 0)});
    if (in.flag()) {
      const Eigen::Vector3d center = in.vector3();
      const double radius = in.number();
      set.add_sphere(center, radius, dispkin::Frame::absolute, 1);
    }
    if (in.flag()) set.set_group_speed(1, in.number());

    dispkin::Limits limits;
    limits.velocity = in.number();
    limits.acceleration = in.number();
    const auto kind = in.flag() ? dispkin::ProfileKind::scurve : dispkin::ProfileKind::trapezoid;
    if (kind == dispkin::ProfileKind::scurve || in.below(8) == 0) limits.jerk = in.number();
    dispkin::PlanOptions options;
    if (in.flag()) {
      options.min_section_lengths.resize(in.flag() ? path.size() : static_cast<std::size_t>(in.below(4)));
      for (double& l : options.min_section_lengths) l = in.number();
    }
    const dispkin::Trajectory trajectory = dispkin::plan(path, set, limits, kind, options);
    check_finite(trajectory.duration(), "Trajectory::duration");
    check_finite(trajectory.length(), "Trajectory::length");
    const double duration = trajectory.duration();
    for (const double t : {0.0, 0.25 * duration, 0.5 * duration, duration, in.number()}) {
      const dispkin::TrajectorySample s = trajectory.sample(t);
      check_finite(s.pose, "Trajectory::sample pose");
      check_finite(s.body_twist.vector(), "Trajectory::sample twist");
      check_finite(s.s, "Trajectory::sample s");
      check_finite(s.s_dot, "Trajectory::sample s_dot");
      check_finite(s.s_ddot, "Trajectory::sample s_ddot");
      if (std::isfinite(s.s_dot) && std::isfinite(limits.velocity) && (s.s_dot < -1e-9 * limits.velocity || s.s_dot > limits.velocity * (1.0 + 1e-9)))
        dispkin::fuzz::out_of_bound("Trajectory::sample s_dot outside [0, v_sys]");
    }
  });
  return 0;
}
