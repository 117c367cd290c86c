// libFuzzer target: the time laws — Profile::trapezoid / scurve from fuzzed distance, limits
// and boundary velocities, and velocity_limited_law over fuzzed segments — and their states.
// An accepted law must be finite everywhere and keep 0 ≤ ṡ ≤ v_max, |s̈| ≤ a_max (to rounding).
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include <dispkin/profile.hpp>
#include <dispkin/planning/velocity_limit.hpp>

#include "fuzz_input.hpp"

namespace {

void check_law(const dispkin::Profile& p, double v_max, double a_max, dispkin::fuzz::Input& in) {
  if (!std::isfinite(p.duration()) || !std::isfinite(p.peak_velocity())) {
    dispkin::fuzz::non_finite("Profile::duration / peak_velocity");
    return;
  }
  const double t_end = p.duration();
  for (const double t : {0.0, 0.1 * t_end, 0.5 * t_end, 0.9 * t_end, t_end, in.number()}) {
    const dispkin::ProfileState x = p.state_at(t);
    if (!std::isfinite(x.s) || !std::isfinite(x.v) || !std::isfinite(x.a)) {
      dispkin::fuzz::non_finite("Profile state (s, v, a)");
      return;
    }
    const double slack = 1e-9;
    if (x.v < -slack * v_max || x.v > v_max * (1 + slack))
      dispkin::fuzz::out_of_bound("Profile velocity outside [0, v_max]");
    if (std::abs(x.a) > a_max * (1 + slack)) dispkin::fuzz::out_of_bound("Profile acceleration above a_max");
    if (x.s < -slack * p.distance() || x.s > p.distance() * (1 + slack))
      dispkin::fuzz::out_of_bound("Profile position outside [0, S]");
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  dispkin::fuzz::Input in(data, size);
  dispkin::fuzz::expect_clean([&] {
    switch (in.below(3)) {
      case 0: {
        const double s = in.number(), v = in.number(), a = in.number(), v0 = in.number(), v1 = in.number();
        check_law(dispkin::Profile::trapezoid(s, v, a, v0, v1), v, a, in);
        break;
      }
      case 1: {
        const double s = in.number(), v = in.number(), a = in.number(), j = in.number();
        const double v0 = in.flag() ? in.number() : 0.0, v1 = in.flag() ? in.number() : 0.0;
        check_law(dispkin::Profile::scurve(s, v, a, j, v0, v1), v, a, in);
        break;
      }
      default: {
        std::vector<dispkin::LimitedSegment> segments(static_cast<std::size_t>(in.below(6)));
        for (auto& seg : segments) {
          seg.length = in.number();
          seg.limit = in.number();
        }
        const double a = in.number();
        std::optional<double> j;
        if (in.flag()) j = in.number();
        const double v0 = in.flag() ? in.number() : 0.0, v1 = in.flag() ? in.number() : 0.0;
        const std::vector<dispkin::Profile> laws = dispkin::velocity_limited_law(segments, a, j, v0, v1);
        // Laws in order, each within one segment (a segment may hold several).
        if (laws.size() < segments.size()) dispkin::fuzz::finding("velocity_limited_law: a segment without a law");
        std::size_t k = 0;
        double s = 0.0, segment_end = segments[0].length;
        for (const dispkin::Profile& law : laws) {
          while (k + 1 < segments.size() && s >= segment_end * (1 - 1e-12)) segment_end += segments[++k].length;
          check_law(law, segments[k].limit, a, in);
          s += law.distance();
        }
        break;
      }
    }
  });
  return 0;
}
