// The staircase law that carries acceleration across segment boundaries (carried_acceleration.hpp;
// doc/profiles.md §8, equation numbers (26)–(32) below refer to it).
//
// A state (s, ṡ, s̈) is viable when the fastest stop from it (26) stays under the staircase and
// comes to rest on the path (27)–(29): every law that respects the staircase and ends at rest
// is at least as fast as that stop at every position, so the test is exact. The law is built
// in time, phase by phase: the largest jerk among +j, 0 and the stop's own jerk whose phase keeps
// the state viable, each phase ended at the first of: the acceleration limit, the next segment
// boundary, the last viable instant (bisection), or the end of the stop's piece (31).
#include "carried_acceleration.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <tuple>
#include <utility>

#include "../jerk_kernels.hpp"

namespace dispkin::detail {
namespace {

constexpr double infinity = std::numeric_limits<double>::infinity();

// Range minima over the segments: a binary tree on a power-of-two number of leaves (the padding
// leaves are +∞). all() accepts a block of segments whole where its minimum fits and splits it
// where it does not, so a test against many segments costs a logarithm per segment near its limit.
class MinimumTree {
 public:
  explicit MinimumTree(const std::vector<double>& values) {
    while (leaves_ < values.size()) leaves_ *= 2;
    node_.assign(2 * leaves_, infinity);
    std::copy(values.begin(), values.end(), node_.begin() + static_cast<std::ptrdiff_t>(leaves_));
    for (std::size_t i = leaves_; i-- > 1;) node_[i] = std::min(node_[2 * i], node_[2 * i + 1]);
  }

  //! Whether fits(minimum, first, last) holds for the segments [l, r] (true if l > r).
  template <class Fits>
  bool all(std::size_t l, std::size_t r, const Fits& fits) const {
    return l > r || all(1, 0, leaves_ - 1, l, r, fits);
  }

 private:
  template <class Fits>
  bool all(std::size_t i, std::size_t lo, std::size_t hi, std::size_t l, std::size_t r, const Fits& fits) const {
    if (hi < l || lo > r) return true;
    if (l <= lo && hi <= r) {
      if (fits(node_[i], lo, hi)) return true;
      if (lo == hi) return false;
    }
    const std::size_t mid = lo + (hi - lo) / 2;
    return all(2 * i, lo, mid, l, r, fits) && all(2 * i + 1, mid + 1, hi, l, r, fits);
  }

  std::size_t leaves_ = 1;
  std::vector<double> node_;
};

// (26) The fastest stop from (v, a) under the braking limit A and jerk j: if a > 0, a ramp at −j
// to the peak (v + a²/(2j), 0); then the pulse (17) down by the peak velocity — a ramp at −j to
// −p, a hold at −p, a ramp at +j to rest. It exists unless a < 0 with v + a|a|/(2j) < 0 (the
// velocity would turn negative whatever the law does).
struct Stop {
  bool exists = false;
  Motion start{};              // the state it stops from
  Motion peak{};               // where the acceleration reaches 0 (the start if a ≤ 0)
  int count = 0;               // pieces after the peak
  std::array<Motion, 4> at{};  // at[0] = peak, at[i] the start of piece i, at[count] = rest
  std::array<double, 3> duration{};
  std::array<double, 3> jerk{};
};

Stop fastest_stop(const Motion& x, double brake, double j) {
  Stop stop;
  stop.start = x;
  const JerkLimits lim{infinity, std::max(brake, -x.a), j, 1.0 / j};
  // v + a|a|/(2j) is a difference of nearly equal numbers on the stop's last ramp: rounding apart.
  if (x.a < 0.0 && x.v + natural_change(x.a, lim) < -1e-12 * x.v) return stop;
  stop.exists = true;
  stop.peak = x;
  if (x.a > 0.0) {
    stop.peak = advance(x, x.a * lim.jerk_time, -j);
    stop.peak.a = 0.0;
  }
  stop.at[0] = stop.peak;
  const Pulse p = pulse(stop.peak.a, -stop.peak.v, lim);
  // Upwards only when v + a|a|/(2j) = 0 to rounding: the ramp back to a = 0 is the whole stop.
  const double peak = p.sign > 0.0 ? -stop.peak.a : p.peak;
  const std::array<double, 3> durations{p.sign > 0.0 ? 0.0 : (p.peak + stop.peak.a) * lim.jerk_time,
                                        p.sign > 0.0 ? 0.0 : p.hold, peak * lim.jerk_time};
  const std::array<double, 3> jerks{-j, 0.0, j};
  const std::array<double, 3> a_after{-peak, -peak, 0.0};
  for (std::size_t i = 0; i < 3; ++i) {
    if (!(durations[i] > 0.0)) continue;
    const auto c = static_cast<std::size_t>(stop.count);
    stop.duration[c] = durations[i];
    stop.jerk[c] = jerks[i];
    stop.at[c + 1] = advance(stop.at[c], durations[i], jerks[i]);
    stop.at[c + 1].a = a_after[i];
    ++stop.count;
  }
  stop.at[static_cast<std::size_t>(stop.count)].v = 0.0;
  return stop;
}

// (28) Where the stop, on its way up to the peak, reaches the velocity w (v ≤ w ≤ peak):
// v + a t − j t²/2 = w, the smaller root in its cancellation-free form.
double rising_position(const Stop& stop, double w, double j) {
  const Motion& x = stop.start;
  if (w >= stop.peak.v) return stop.peak.s;
  const double dv = std::max(0.0, w - x.v);
  const double t = 2.0 * dv / (x.a + std::sqrt(std::max(0.0, x.a * x.a - 2.0 * j * dv)));
  return advance(x, t, -j).s;
}

// (29) Where the stop, after its peak, has slowed to w (0 ≤ w ≤ peak): in the piece where the
// velocity passes w, v₀ + a₀ t + j t²/2 = w has the root t = 2Δ / (−a₀ + √(a₀² − 2jΔ)),
// Δ = v₀ − w (a₀ ≤ 0 after the peak: no cancellation).
double falling_position(const Stop& stop, double w) {
  if (w >= stop.peak.v) return stop.peak.s;
  for (int i = 0; i < stop.count; ++i) {
    const auto k = static_cast<std::size_t>(i);
    if (w < stop.at[k + 1].v && i + 1 < stop.count) continue;
    const Motion& x = stop.at[k];
    const double dv = std::max(0.0, x.v - w);
    const double root = std::sqrt(std::max(0.0, x.a * x.a - 2.0 * stop.jerk[k] * dv));
    const double t = -x.a + root > 0.0 ? std::min(stop.duration[k], 2.0 * dv / (-x.a + root)) : stop.duration[k];
    return advance(x, t, stop.jerk[k]).s;
  }
  return stop.at[static_cast<std::size_t>(stop.count)].s;
}

class Staircase {
 public:
  Staircase(const std::vector<LimitedSegment>& segments, const std::vector<double>& accelerations, double j,
            bool settle_in_troughs, bool open_end)
      : open_end_(open_end),
        j_(j),
        accel_(accelerations),
        brake_(accelerations),
        limit_(segments.size()),
        start_(segments.size() + 1, 0.0),
        limits_(limit_values(segments)),
        accels_(accelerations),
        troughs_(trough_values(segments, settle_in_troughs)),
        settle_(settle_in_troughs) {
    for (std::size_t k = 0; k < segments.size(); ++k) {
      limit_[k] = segments[k].limit * (1.0 - margin);
      start_[k + 1] = start_[k] + segments[k].length;
    }
    for (std::size_t k = brake_.size() - 1; k-- > 0;) brake_[k] = std::min(brake_[k], brake_[k + 1]);
  }

  //! The internal limits lie this much (relative) below the given ones: room for the rounding of
  //! the law's phases, so that the checked result keeps the given limits exactly.
  static constexpr double margin = 1e-10;

  std::size_t count() const { return limit_.size(); }
  double length() const { return start_.back(); }
  double start(std::size_t k) const { return start_[k]; }
  double limit(std::size_t k) const { return limit_[k]; }
  double acceleration(std::size_t k) const { return accel_[k]; }
  double jerk() const { return j_; }

  //! The segment holding position s (the last one for s ≥ the length).
  std::size_t segment_at(double s) const {
    const auto it = std::upper_bound(start_.begin() + 1, start_.end() - 1, s);
    return static_cast<std::size_t>(it - (start_.begin() + 1));
  }

  //! (27)–(30): whether x, reached by a phase within segment `law_segment`, keeps that segment's
  //! limits, and the fastest stop from x keeps under the staircase and rests on the path. (The
  //! phase's velocity is largest at one of its ends: the phases are cut where s̈ = 0.)
  //! When only a trough fails, its index goes to *binding_trough (if given).
  bool viable(const Motion& x, std::size_t law_segment, std::size_t* binding_trough = nullptr) const {
    if (!(x.v >= 0.0) || x.v > limit_[law_segment] || x.a > accel_[law_segment]) return false;
    const std::size_t m = segment_at(x.s);
    if (x.a > accel_[m]) return false;
    const Stop stop = fastest_stop(x, brake_[m], j_);
    if (!stop.exists) return false;
    const Motion& rest = stop.at[static_cast<std::size_t>(stop.count)];
    if (rest.s > length() && !open_end_) return false;
    const std::size_t kp = segment_at(stop.peak.s);
    if (stop.peak.v > limit_[kp]) return false;
    if (x.a > 0.0 && kp > m) {
      // (28) on the way up each segment is left before the velocity passes its limit, and
      // entered with an acceleration within its own.
      const bool below = limits_.all(m, kp - 1, [&](double v_min, std::size_t, std::size_t last) {
        return v_min >= stop.peak.v || rising_position(stop, v_min, j_) >= start_[last + 1];
      });
      if (!below) return false;
      if (!accels_.all(m + 1, kp, [&](double a_min, std::size_t, std::size_t) { return a_min >= x.a; })) return false;
    }
    // (29) after the peak each segment begins where the velocity has fallen to its limit.
    const bool under = limits_.all(kp + 1, segment_at(rest.s), [&](double v_min, std::size_t first, std::size_t) {
      return v_min >= stop.peak.v || falling_position(stop, v_min) <= start_[first];
    });
    if (!under || !settle_) return under;
    // (30) and, settling in troughs, each trough ahead is reached at its limit with zero acceleration: the pulse (17)
    // down to (V_k, 0) ends before it begins. The pulse to a lower velocity is longer, so a block
    // fits where the pulse to its lowest trough does; it ends within V·a/j past where the stop has
    // slowed to V, so no trough beyond that reach binds.
    const JerkLimits lim{infinity, std::max(brake_[m], -x.a), j_, 1.0 / j_};
    const double v_natural = x.v + natural_change(x.a, lim);
    const double reach = rest.s + stop.peak.v * lim.a_max * lim.jerk_time;
    return troughs_.all(m + 1, segment_at(reach), [&](double w, std::size_t first, std::size_t last) {
      const bool fits = w >= v_natural || pulse_end(x, w, lim) <= start_[first];
      if (!fits && first == last && binding_trough) *binding_trough = first;
      return fits;
    });
  }

  //! The limit of trough k (settled in at zero acceleration).
  double trough(std::size_t k) const { return limit_[k]; }

  //! The first piece of the pulse (17) from x down to (w, 0) under the braking limit there, as
  //! (jerk, duration); a ramp through s̈ = 0 is cut there (the law chooses again at its peak).
  std::pair<double, double> pulse_piece(const Motion& x, double w) const {
    const JerkLimits lim{infinity, std::max(brake_[segment_at(x.s)], -x.a), j_, 1.0 / j_};
    const Pulse p = pulse(x.a, w - x.v, lim);
    const double target = p.sign * p.peak;
    const double ramp = std::abs(target - x.a) * lim.jerk_time;
    if (ramp > 1e-12 * lim.a_max * lim.jerk_time) {
      const double jerk = target >= x.a ? j_ : -j_;
      const bool through_zero = (x.a > 0.0 && target < 0.0) || (x.a < 0.0 && target > 0.0);
      return {jerk, through_zero ? std::abs(x.a) * lim.jerk_time : ramp};
    }
    if (p.hold > 0.0) return {0.0, p.hold};
    return {-p.sign * j_, p.peak * lim.jerk_time};
  }

  //! The fastest stop from x under this staircase's braking limit there.
  Stop stop_from(const Motion& x) const { return fastest_stop(x, brake_[segment_at(x.s)], j_); }

 private:
  // The limits of the troughs — segments below the one before and not above the one after — and
  // +∞ elsewhere (all +∞ unless troughs are settled in).
  static std::vector<double> trough_values(const std::vector<LimitedSegment>& segments, bool settle) {
    std::vector<double> v(segments.size(), infinity);
    for (std::size_t k = 1; settle && k < segments.size(); ++k) {
      const bool below_before = segments[k].limit < segments[k - 1].limit;
      const bool not_above_after = k + 1 == segments.size() || segments[k].limit <= segments[k + 1].limit;
      if (below_before && not_above_after) v[k] = segments[k].limit * (1.0 - margin);
    }
    return v;
  }

  // Where the pulse (17) from x down to (w, 0) ends.
  static double pulse_end(const Motion& x, double w, const JerkLimits& lim) {
    const Pulse p = pulse(x.a, w - x.v, lim);
    Motion y =
        advance(x, std::abs(p.sign * p.peak - x.a) * lim.jerk_time, p.sign * p.peak >= x.a ? lim.j_max : -lim.j_max);
    y.a = p.sign * p.peak;
    y = advance(y, p.hold, 0.0);
    return advance(y, p.peak * lim.jerk_time, -p.sign * lim.j_max).s;
  }

  static std::vector<double> limit_values(const std::vector<LimitedSegment>& segments) {
    std::vector<double> v(segments.size());
    for (std::size_t k = 0; k < segments.size(); ++k) v[k] = segments[k].limit * (1.0 - margin);
    return v;
  }

  bool open_end_;  // the last segment goes on past the end (the law ends cruising at its limit)
  double j_;
  std::vector<double> accel_;  // A_k, each segment's acceleration limit
  std::vector<double> brake_;  // min over k' ≥ k of A_k': the braking limit of the stops
  std::vector<double> limit_;  // V_k (1 − margin)
  std::vector<double> start_;  // s_k, k = 0 … n (s_n the length)
  MinimumTree limits_, accels_, troughs_;
  bool settle_;
};

// One phase of constant jerk of the law being built.
struct Phase {
  double duration, jerk;
  Motion start;
};

// The time at which a constant-jerk phase from x reaches position `target` (≤ its position after
// `cap`): Newton on the non-decreasing s(t) (ṡ its derivative), kept inside a shrinking bracket
// and bisecting where a step would leave it; the result is the bracket's upper end (s ≥ target).
double time_to_position(const Motion& x, double jerk, double cap, double target) {
  constexpr double eps = std::numeric_limits<double>::epsilon();
  double lo = 0.0, hi = cap, t = cap;
  for (int i = 0; i < 100 && hi - lo > 4.0 * eps * hi; ++i) {
    const Motion y = advance(x, t, jerk);
    (y.s < target ? lo : hi) = t;
    if (y.s >= target && y.s - target <= 4.0 * eps * std::abs(target)) return t;
    const double step = y.v > 0.0 ? (target - y.s) / y.v : 0.0;
    // Converged from below: the next representable times reach the target.
    t = std::abs(step) <= 4.0 * eps * t ? t * (1.0 + 8.0 * eps) : t + step;
    if (!(t > lo && t < hi)) t = 0.5 * (lo + hi);
  }
  return hi;
}

// (32) A law is kept only if every phase keeps 0 ≤ ṡ ≤ V, |s̈| ≤ A, |s⃛| ≤ j of its segment,
// the velocity's maximum over a phase taken at its ends or where s̈ = 0 inside it.
bool within_limits(const Profile& law, double v_max, double a_max, double j) {
  const double slack = 1e-12;
  for (int i = 0; i < law.phase_count(); ++i) {
    const ProfilePhase& p = law.phase(i);
    double v_top = std::max(p.start.v, p.end.v);
    if (p.jerk != 0.0 && (p.start.a > 0.0) != (p.end.a > 0.0)) {
      const double t = -p.start.a / p.jerk;
      v_top = std::max(v_top, p.start.v + t * (p.start.a + 0.5 * p.jerk * t));
    }
    const double v_low = std::min(p.start.v, p.end.v);
    if (!(v_top <= v_max * (1.0 + slack)) || !(v_low >= -slack * v_max)) return false;
    if (!(std::max(std::abs(p.start.a), std::abs(p.end.a)) <= a_max * (1.0 + 1e-9))) return false;
    if (!(std::abs(p.jerk) <= j * (1.0 + slack))) return false;
  }
  return true;
}

// The laws of one segment from its phases (consecutive phases of the same jerk merged), at most
// Profile::max_phases each, the last ending at the segment's end `s_end` in state `end`; false if
// a law does not keep the segment's limits (32).
bool append_segment_laws(std::vector<Phase>& phases, double s_end, const Motion& end, const LimitedSegment& segment,
                         double a_max, double j, std::vector<Profile>& laws) {
  std::vector<Phase> merged;
  for (const Phase& p : phases) {
    if (!(p.duration > 0.0)) continue;
    if (!merged.empty() && merged.back().jerk == p.jerk) {
      merged.back().duration += p.duration;
    } else {
      merged.push_back(p);
    }
  }
  phases.clear();
  if (merged.empty()) return false;
  std::array<double, Profile::max_phases> durations{}, jerks{};
  for (std::size_t first = 0; first < merged.size(); first += Profile::max_phases) {
    const std::size_t count = std::min<std::size_t>(Profile::max_phases, merged.size() - first);
    for (std::size_t i = 0; i < count; ++i) {
      durations[i] = merged[first + i].duration;
      jerks[i] = merged[first + i].jerk;
    }
    const Motion& from = merged[first].start;
    const bool last = first + count == merged.size();
    const Motion to = last ? end : merged[first + count].start;
    const double to_s = last ? s_end : to.s;
    laws.push_back(Profile::from_phases(durations.data(), jerks.data(), static_cast<int>(count), from.v, from.a,
                                        to_s - from.s, to.v, to.a));
    if (!within_limits(laws.back(), segment.limit, a_max, j)) return false;
  }
  return true;
}

// The largest τ ∈ [0, cap] for which the phase of jerk `jerk` from x ends in a viable state,
// assuming that once it leaves the viable states it does not come back (bisection to 1e-12 of
// the jerk's time scale a/j).
// (the first non-viable instant found goes to *edge).
// A rise (jerk > 0) ends at most at the acceleration limit `a_cap`, as the law then runs it
// (advance_by): a rise to the limit must not look non-viable for the last bit of rounding in
// s̈ + j τ.
double viable_duration(const Staircase& stairs, const Motion& x, std::size_t m, double jerk, double cap, double a_cap,
                       double resolution, double* edge) {
  const auto at = [&](double t) {
    Motion y = advance(x, t, jerk);
    if (jerk > 0.0) y.a = std::min(y.a, a_cap);
    return y;
  };
  *edge = cap;
  if (stairs.viable(at(cap), m)) return cap;
  double lo = 0.0, hi = cap;
  while (hi - lo > resolution) {
    const double mid = 0.5 * (lo + hi);
    (stairs.viable(at(mid), m) ? lo : hi) = mid;
  }
  *edge = hi;
  return lo;
}

}  // namespace

namespace {

// The law of §8.2 being built, phase by phase (31): the state, its segment, the segment's phases.
class GreedyLaw {
 public:
  GreedyLaw(const Staircase& stairs, const std::vector<LimitedSegment>& segments,
            const std::vector<double>& accelerations, double v_start, double v_end)
      : stairs_(stairs),
        segments_(segments),
        accelerations_(accelerations),
        j_(stairs.jerk()),
        v_start_(v_start),
        v_end_(v_end),
        open_end_(v_end > 0.0),
        x_{0.0, v_start, 0.0} {
    for (double a : accelerations) a_top_ = std::max(a_top_, a);
    resolution_ = 1e-9 * a_top_ / j_;
    shortest_ = 1e-6 * a_top_ / j_;
    laws_.reserve(segments.size());
  }

  bool done() const { return m_ == stairs_.count(); }

  //! One phase: false where the law does not settle (no candidate fits, a check fails).
  bool step() {
    const Stop stop = stairs_.stop_from(x_);
    const std::size_t n = stairs_.count();
    // In the last segment, once the stop ends at the end of the path (to 1e-9 of its length), the
    // law is that stop: what is left is rounding, not room to speed up.
    const double length = stairs_.length();
    if (!open_end_ && m_ + 1 == n && stop.exists &&
        length - stop.at[static_cast<std::size_t>(stop.count)].s <= 1e-9 * length) {
      on_edge_ = true;
      edge_trough_.reset();
    }
    std::optional<Choice> choice;
    for (int c = 0; c < 3 && !choice; ++c) {
      const std::optional<Piece> piece = candidate(c, stop);
      if (failed_) return false;
      if (piece) choice = take(c, *piece, stop);
    }
    return choice && advance_by(*choice, stop);
  }

  //! The laws, once done(), if the law ends in the state asked for.
  std::optional<std::vector<Profile>> result() {
    const double v_scale = std::max({1e-300, v_start_, v_end_});
    if (!(std::abs(x_.v - v_end_) <= 1e-9 * v_scale) || !(std::abs(x_.a) <= 1e-9 * a_top_)) return std::nullopt;
    return std::move(laws_);
  }

 private:
  struct Piece {
    double jerk, cap;  // a constant jerk and the longest it may last
  };
  struct Choice {
    double jerk, duration;
    bool stopping;         // the fastest stop's own piece
    bool settles = false;  // a rise that ends at zero acceleration
  };

  // Candidate c (31): 0 — +j up to the acceleration limit, 1 — 0, 2 — the piece of the manoeuvre
  // that bounds the state (the pulse into the binding trough, or the fastest stop). Nothing where
  // it does not apply; failed_ where nothing can.
  std::optional<Piece> candidate(int c, const Stop& stop) {
    if (c < 2 && on_edge_) return std::nullopt;
    if (c == 0) {
      const double a_cap = stairs_.acceleration(m_);
      if (!(x_.a < a_cap)) return std::nullopt;
      return Piece{j_, (a_cap - x_.a) / j_};
    }
    if (c == 1) {
      if (x_.v <= 0.0 && x_.a <= 0.0) return std::nullopt;
      return Piece{0.0, x_.a < 0.0 ? x_.v / -x_.a : infinity};  // braking: until ṡ would reach 0
    }
    if (edge_trough_) {
      const auto [jerk, cap] = stairs_.pulse_piece(x_, stairs_.trough(*edge_trough_));
      failed_ = !(cap > 0.0);
      return Piece{jerk, cap};
    }
    failed_ = !stop.exists || (x_.a <= 0.0 && stop.count == 0);  // at rest and nothing else fits
    if (failed_) return std::nullopt;
    if (x_.a > 0.0) return Piece{-j_, x_.a / j_};  // to the peak, then choose again
    return Piece{stop.jerk[0], stop.duration[0]};
  }

  // The candidate's phase: cut at the next segment boundary, and for +j and 0 at the last viable
  // instant; nothing if that leaves less than a useful phase.
  std::optional<Choice> take(int c, Piece piece, const Stop& stop) {
    const std::size_t n = stairs_.count();
    const double s_next = stairs_.start(m_ + 1);
    const Motion far = std::isfinite(piece.cap) ? advance(x_, piece.cap, piece.jerk) : Motion{infinity, 0.0, 0.0};
    // The stop that ends the path rests at its end to rounding: it is not cut there.
    const bool final_stop = c == 2 && !edge_trough_ && m_ + 1 == n && stop.count == 1 && piece.jerk > 0.0 &&
                            far.s <= stairs_.length() * (1.0 + 1e-9);
    const bool to_boundary = !final_stop && (!std::isfinite(piece.cap) || far.s >= s_next - 1e-15 * s_next);
    if (to_boundary) {
      // Without a cap (jerk 0, s̈ ≥ 0) the boundary is reached by Δ/ṡ and by √(2Δ/s̈).
      double horizon = piece.cap;
      if (!std::isfinite(horizon)) {
        if (x_.v > 0.0) horizon = (s_next - x_.s) / x_.v;
        if (x_.a > 0.0) horizon = std::min(horizon, std::sqrt(2.0 * (s_next - x_.s) / x_.a));
      }
      piece.cap = time_to_position(x_, piece.jerk, horizon, s_next);
    }
    if (c == 1 && !open_end_ && m_ + 1 == n && stop.exists && x_.v > 0.0 && std::abs(x_.a) <= 1e-12 * a_top_) {
      // Cruising in the last segment with the stop resting a hair before the end: the cruise
      // that shifts the stop onto the end, however short, then the stop. (The bisection cannot
      // find a hold of δ/ṡ below its resolution, and creeping the last δ after the stop costs
      // time ∝ ∛(δ/j).)
      const double short_by = stairs_.length() - stop.at[static_cast<std::size_t>(stop.count)].s;
      if (short_by > 0.0 && short_by <= 1e-6 * stairs_.length() && short_by / x_.v < piece.cap) {
        on_edge_ = true;
        edge_trough_.reset();
        return Choice{0.0, short_by / x_.v, false};
      }
    }
    if (c == 2) {
      const bool stopping = !edge_trough_;
      on_edge_ = false;
      edge_trough_.reset();
      return Choice{piece.jerk, piece.cap, stopping};
    }
    double edge = piece.cap;
    double duration =
        viable_duration(stairs_, x_, m_, piece.jerk, piece.cap, stairs_.acceleration(m_), resolution_, &edge);
    // A phase that reaches the segment boundary ends at an event however short it is; so does a
    // rise that brings a small braking acceleration — a rounding remainder of a pulse or a stop —
    // back to zero where rising further would pass the limit (doc/profiles.md eq. 31).
    bool useful = duration > shortest_ || (to_boundary && duration == piece.cap);
    bool settles = false;
    if (!useful && c == 0 && x_.a < 0.0 && -x_.a / j_ < piece.cap) {
      const double to_zero = -x_.a / j_;
      double zero_edge = to_zero;
      settles = viable_duration(stairs_, x_, m_, piece.jerk, to_zero, 0.0, resolution_, &zero_edge) == to_zero;
      if (settles) {
        duration = piece.cap = to_zero;
        useful = true;
      }
    }
    on_edge_ = useful && duration < piece.cap;
    if (duration < piece.cap) {
      // Which rule the phase breaks first: a trough's, or the stop's (followed next).
      std::size_t k = n;
      stairs_.viable(advance(x_, edge, piece.jerk), m_, &k);
      edge_trough_.reset();
      if (k < n) edge_trough_ = k;
    }
    if (!useful) return std::nullopt;
    return Choice{piece.jerk, duration, false, settles};
  }

  // Runs the chosen phase; at the segment boundary (or at rest at the end) the segment's laws.
  bool advance_by(const Choice& choice, const Stop& stop) {
    const std::size_t n = stairs_.count();
    const double s_next = stairs_.start(m_ + 1), length = stairs_.length();
    if (++steps_ > 64 * n + 1024) return false;  // a segment rarely needs more than a handful
    phases_.push_back({choice.duration, choice.jerk, x_});
    Motion next = advance(x_, choice.duration, choice.jerk);
    if (choice.jerk > 0.0) next.a = std::min(next.a, stairs_.acceleration(m_));
    if (choice.settles) next.a = 0.0;
    // The stop's last ramp ends at rest exactly.
    const bool rests = choice.stopping && stop.count == 1 && choice.jerk > 0.0 && choice.duration == stop.duration[0];
    if (rests) next.v = next.a = 0.0;
    const bool at_rest_at_end = m_ + 1 == n && rests && length - next.s <= 1e-9 * length;
    if (next.s >= s_next - 1e-15 * s_next || at_rest_at_end) {
      next.s = s_next;
      if (at_rest_at_end) next = Motion{length, 0.0, 0.0};
      if (!append_segment_laws(phases_, s_next, next, segments_[m_], accelerations_[m_], j_, laws_)) return false;
      ++m_;
    }
    x_ = next;
    return true;
  }

  const Staircase& stairs_;
  const std::vector<LimitedSegment>& segments_;
  const std::vector<double>& accelerations_;
  double j_, v_start_, v_end_;
  bool open_end_;
  double a_top_ = 0.0;
  double resolution_ = 0.0;  // time resolution of the edges (a braking start 1e-9 a/j early)
  // A phase of +j or 0 shorter than this is not taken (its velocity change is below 1e-12 a²/j):
  // near the edge of the viable states rounding leaves room for vanishing phases only.
  double shortest_ = 0.0;
  // Whether the last phase ended on the edge of the viable states: the manoeuvre is followed from
  // there to its next event, not alternated with other jerks in vanishing steps (31).
  bool on_edge_ = false;
  std::optional<std::size_t> edge_trough_;  // the trough whose rule made the edge, if one did
  bool failed_ = false;
  Motion x_;
  std::size_t m_ = 0, steps_ = 0;
  std::vector<Phase> phases_;
  std::vector<Profile> laws_;
};

}  // namespace

std::optional<std::vector<Profile>> carried_acceleration_law(const std::vector<LimitedSegment>& segments,
                                                             const std::vector<double>& accelerations, double j_max,
                                                             double v_start, double v_end, bool settle_in_troughs) {
  // v_end > 0: the law ends cruising at the last segment's limit, which goes on past the end.
  const Staircase stairs(segments, accelerations, j_max, settle_in_troughs, v_end > 0.0);
  GreedyLaw law(stairs, segments, accelerations, v_start, v_end);
  try {
    while (!law.done())
      if (!law.step()) return std::nullopt;
  } catch (const std::invalid_argument&) {
    return std::nullopt;  // from_phases: the phases do not lead to the end state to rounding
  }
  return law.result();
}

std::vector<Profile> reversed_in_time(const std::vector<Profile>& laws) {
  std::vector<Profile> out;
  out.reserve(laws.size());
  std::array<double, Profile::max_phases> durations{}, jerks{};
  for (auto law = laws.rbegin(); law != laws.rend(); ++law) {
    const int count = law->phase_count();
    // Run backwards, s̈ changes sign and s⃛ keeps it (d/dτ = −d/dt applied three times, once to s).
    for (int i = 0; i < count; ++i) {
      durations[static_cast<std::size_t>(i)] = law->phase(count - 1 - i).duration;
      jerks[static_cast<std::size_t>(i)] = law->phase(count - 1 - i).jerk;
    }
    const ProfileState first = law->state_at(0.0), last = law->state_at(law->duration());
    const double a_first = count > 0 ? law->phase(0).start.a : first.a;
    const double a_last = count > 0 ? law->phase(count - 1).end.a : last.a;
    out.push_back(Profile::from_phases(durations.data(), jerks.data(), count, last.v, -a_last, law->distance(), first.v,
                                       -a_first));
  }
  return out;
}

}  // namespace dispkin::detail
