// Laws checked against a velocity-limit curve at every position (law_under_curve.hpp).
#include "law_under_curve.hpp"

#include <algorithm>
#include <limits>

namespace dispkin::detail {

namespace {

// When `law` (ṡ ≥ 0) reaches s, within [0, t_end].
double time_at(const Profile& law, double s, double t_end) {
  if (s <= 0.0) return 0.0;
  double lo = 0.0, hi = t_end;
  if (law.state_at(hi).s <= s) return hi;
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    if (mid <= lo || mid >= hi) break;
    (law.state_at(mid).s < s ? lo : hi) = mid;
  }
  return hi;
}

}  // namespace

double peak_between(const Profile& law, double t_end, double s0, double s1) {
  const double ta = time_at(law, s0, t_end), tb = time_at(law, s1, t_end);
  double peak = std::max(law.state_at(ta).v, law.state_at(tb).v);
  for (int i = 0; i < law.phase_count() && law.phase_start_time(i) < tb; ++i) {
    const ProfilePhase& p = law.phase(i);
    if (law.phase_start_time(i) > ta) peak = std::max(peak, p.start.v);  // a trapezoid peaks where phases meet
    if (p.jerk == 0.0) continue;
    const double at = law.phase_start_time(i) - p.start.a / p.jerk;  // where s̈ = 0 in the phase
    if (at > ta && at < tb && at < law.phase_start_time(i) + p.duration) peak = std::max(peak, law.state_at(at).v);
  }
  return peak;
}

bool keeps_under_tops(const Profile& law, double t_end, double start_s, double peak,
                      const std::vector<SpeedLimit>& spans, std::size_t first, double tol_s) {
  const double s1 = start_s + law.state_at(t_end).s;
  double lowest = std::numeric_limits<double>::infinity();
  for (std::size_t k = first; k < spans.size() && spans[k].start_s <= s1 - tol_s; ++k)
    if (spans[k].start_s + spans[k].length >= start_s + tol_s) lowest = std::min(lowest, spans[k].top());
  if (peak <= lowest * (1.0 + 1e-8)) return true;
  for (std::size_t k = first; k < spans.size() && spans[k].start_s <= s1 - tol_s; ++k) {
    const SpeedLimit& l = spans[k];
    if (l.start_s + l.length < start_s + tol_s) continue;
    const double a = std::max(l.start_s, start_s) - start_s, b = std::min(l.start_s + l.length, s1) - start_s;
    if (peak_between(law, t_end, a, b) > l.top() * (1.0 + 1e-8)) return false;
  }
  return true;
}

}  // namespace dispkin::detail
