// libFuzzer target: paths from fuzzed poses — Path::lin (both interpolations), circ, spline,
// joined by then() with and without blends — planned under a fuzzed metric set and fuzzed
// Limits with either profile, then sampled. Every sample of a planned trajectory must be
// finite, with 0 ≤ ṡ ≤ v_sys (to rounding).
//
// Each execution is bounded: a curved move or blend is cut into at most `max_sections`
// sections. The library cuts a CIRC into about angle/tolerance sections and a SPLINE piece or a
// blend into about rate/(2·tolerance·speed) — both proportional to 1/tolerance — so the fuzzer
// first builds the move at the coarsest tolerance (0.1), counts its sections n₀, and raises a
// fuzzed tolerance below 0.1·n₀/max_sections to that floor (a finer one would ask for more than
// max_sections sections). Invalid tolerances (NaN, ±inf, ≤ 0, > 0.1) pass unchanged, so the
// library's own checks stay fuzzed; the library's limits (10^6 sections per CIRC, 10^5 per
// SPLINE piece) are tested by GoogleTest cases, not here.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <utility>
#include <vector>

#include <dispkin/path/path.hpp>
#include <dispkin/planning/planner.hpp>

#include "fuzz_input.hpp"

namespace {

using dispkin::Path;
using dispkin::Posed;

// Sections per curved move or blend (see the file comment); a path of three moves and two
// blends plans in a few milliseconds under ASan.
constexpr double max_sections = 100.0;
// The coarsest tolerance the library takes: the trial cut.
constexpr double coarsest = 0.1;

// A tolerance from the bytes (1e-3 when the flag says so).
double fuzzed_tolerance(dispkin::fuzz::Input& in) { return in.flag() ? in.number() : 1e-3; }

// `build(tolerance)` at the fuzzed tolerance, raised when needed so that the curve it cuts has
// at most max_sections sections. A valid tolerance only: the trial at 0.1 decides the floor; an
// invalid one goes straight to the library, which must refuse it. `extends` (a blend, whose
// result also holds the path before and after it): the curve's n₀ is the growth from 0.1 to
// 0.05, since the count is proportional to 1/tolerance and the rest does not change.
Path bounded(const std::function<Path(double)>& build, double tolerance, bool extends = false) {
  if (!(std::isfinite(tolerance) && tolerance > 0.0 && tolerance < coarsest)) return build(tolerance);
  Path trial = build(coarsest);
  double n0 = static_cast<double>(trial.size());
  if (extends) n0 = std::max(1.0, static_cast<double>(build(0.5 * coarsest).size()) - n0);
  if (n0 * coarsest / tolerance <= max_sections) return build(tolerance);
  const double floor = coarsest * n0 / max_sections;
  return floor >= coarsest ? trial : build(floor);
}

// Curved moves whose geometry lies far outside the stated range (README, "Numeric range") are
// skipped: a blend of 1e-300 m in a 100 m move, or SPLINE keys 1e-299 m and 1e2 m apart, make
// curves whose speed varies by the same ratio, and the library then cuts each piece into its cap
// of 10^5 sections even at the coarsest tolerance (half a second under ASan). Skipped are finite,
// non-zero translation / pivot coordinates and blend distances outside [1e-3, 1e3] m (every
// moderate number of fuzz_input.hpp lies inside); NaN, ±inf, zero and negative values reach the
// library, which must refuse them, and LIN moves take every number.
struct Skip {};
void require_moderate(double x) {
  const double m = std::abs(x);
  if (std::isfinite(m) && m != 0.0 && (m < 1e-3 || m > 1e3)) throw Skip{};
}
void require_moderate(const Eigen::Vector3d& v) {
  for (int i = 0; i < 3; ++i) require_moderate(v(i));
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
      for (const Posed* p : {&a, &via, &b}) require_moderate(p->translation());
      require_moderate(pivot);
      return bounded([&](double t) { return Path::circ(a, via, b, pivot, t); }, fuzzed_tolerance(in));
    }
    default: {
      std::vector<Posed> keys{a};
      const int n = 2 + in.below(4);
      for (int i = 0; i < n; ++i) keys.push_back(in.pose());
      const Eigen::Vector3d pivot = in.flag() ? in.vector3() : Eigen::Vector3d::Zero();
      for (const Posed& p : keys) require_moderate(p.translation());
      require_moderate(pivot);
      return bounded([&](double t) { return Path::spline(keys, pivot, t); }, fuzzed_tolerance(in));
    }
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using dispkin::fuzz::check_finite;
  dispkin::fuzz::Input in(data, size);
  dispkin::fuzz::expect_clean([&] {
    std::optional<Path> built;
    try {
      Path path = move(in, std::nullopt);
      const int more = in.below(3);
      for (int i = 0; i < more; ++i) {
        const Path next = move(in, path.end());
        const int kind = in.below(3);
        if (kind == 0) {
          path.then(next);
          continue;
        }
        // A blend (kind 1: then(next, blend) at its default tolerance 1e-3).
        const double before = in.number(), after = kind == 1 ? before : in.number();
        const double tolerance = kind == 1 ? 1e-3 : fuzzed_tolerance(in);
        require_moderate(before);
        require_moderate(after);
        path = bounded(
            [&](double t) {
              Path blended = path;
              blended.then(next, before, after, t);
              return blended;
            },
            tolerance, true);
      }
      built = std::move(path);
    } catch (const Skip&) {
      return;
    }
    const Path path = std::move(*built);
    for (const double u : {0.0, 0.5, 1.0, in.number()}) check_finite(path.sample(u), "Path::sample");
    // Only when a move needs more than max_sections even at the coarsest tolerance: built and
    // sampled, not planned.
    if (path.size() > 6 * max_sections) return;

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
      if (std::isfinite(s.s_dot) && std::isfinite(limits.velocity) &&
          (s.s_dot < -1e-9 * limits.velocity || s.s_dot > limits.velocity * (1.0 + 1e-9)))
        dispkin::fuzz::out_of_bound("Trajectory::sample s_dot outside [0, v_sys]");
    }
  });
  return 0;
}
