//! One-dimensional time-optimal time laws s(t) over a distance S (doc/profiles.md).
//!
//! A `Profile` is piecewise-constant jerk: at most seven phases. The S-curve is the textbook
//! seven-phase law (jerk ∈ {+j, 0, −j}); the trapezoid is piecewise-constant acceleration
//! (its phases have jerk 0 and the acceleration jumps between them).
//!
//!   phase  1      2      3      4       5      6      7
//!   jerk   +j     0      −j     0       −j     0      +j
//!          ├─ accelerate v_start → v_peak ─┤ cruise ├─ decelerate v_peak → v_end ─┤
//!
//! Planning (`trapezoid`, `scurve`) validates its input, may throw and precomputes the state
//! (s, v, a) at both ends of every phase. Evaluation (`state_at`, `sample`) is noexcept and
//! allocation-free: a scan over at most seven phase start times and one cubic.
//!
//! Boundary accelerations are zero. Boundary velocities v_start, v_end ∈ [0, v_max] are
//! supported with the structure accelerate → cruise → decelerate (peak ≥ both boundary
//! velocities). For the trapezoid that structure is time-optimal for every feasible input.
//! For the S-curve it is time-optimal whenever it fits in S; when it does not fit, a shorter
//! law would have to dip below both boundary velocities (or none exists): that is refused with
//! std::invalid_argument, never approximated.
#pragma once

#include <array>
#include <cstddef>
#include <utility>

namespace dispkin {

//! Which law a Profile is.
enum class ProfileKind { trapezoid, scurve };

//! The state of a time law at one instant.
struct ProfileState {
  double s = 0.0;  //!< position along the path, in [0, S]
  double v = 0.0;  //!< velocity ṡ
  double a = 0.0;  //!< acceleration s̈
  double j = 0.0;  //!< jerk s⃛ (0 inside every trapezoid phase)
};

//! One phase of constant jerk: its duration, its jerk and the states at both of its ends.
//! Within a phase s, v, a are the cubic, quadratic and linear Taylor polynomials of either end
//! state. For the trapezoid `start.a` = `end.a` = ±a_max or 0 and the jerk is 0.
struct ProfilePhase {
  double duration = 0.0;  //!< how long the phase lasts (s)
  double jerk = 0.0;      //!< its constant jerk s⃛
  ProfileState start;     //!< state at the start of the phase (start.j = jerk)
  ProfileState end;       //!< state at the end of the phase (end.j = jerk)
};

//! A time law s(t), t ∈ [0, duration()], from (0, v_start, 0) to (S, v_end, 0).
//!
//! Invariants: 0 ≤ ṡ ≤ v_max, |s̈| ≤ a_max, |s⃛| ≤ j_max (S-curve) up to rounding; s is
//! non-decreasing; s, ṡ (and s̈ for the S-curve) are continuous.
class Profile {
 public:
  //! The most phases a law has (the seven of the S-curve).
  static constexpr int max_phases = 7;

  //! The time-optimal law under |ṡ| ≤ v_max, |s̈| ≤ a_max (no jerk limit) over `distance`,
  //! from velocity `v_start` to `v_end`. Peak velocity v_p = min(v_max, √(a S + (v_s² + v_e²)/2)):
  //! accelerate at +a to v_p, cruise, decelerate at −a to v_e. Throws std::invalid_argument on
  //! bad input, or if S < |v_e² − v_s²| / (2 a) (no law exists).
  static Profile trapezoid(double distance, double v_max, double a_max, double v_start = 0.0, double v_end = 0.0);

  //! The time-optimal seven-phase law under |ṡ| ≤ v_max, |s̈| ≤ a_max, |s⃛| ≤ j_max over
  //! `distance`, from velocity `v_start` to `v_end` (accelerations zero at both ends).
  //! Rest-to-rest is closed form in every case (v_max or a_max reached or not, S tiny or 0);
  //! with non-zero boundary velocities the peak velocity is the root of a monotone equation
  //! (safeguarded Newton). Throws std::invalid_argument on bad input, or if S is shorter than
  //! the accelerate → decelerate law between the boundary velocities needs.
  static Profile scurve(double distance, double v_max, double a_max, double j_max, double v_start = 0.0,
                        double v_end = 0.0);

  //! The time-optimal jerk-limited law from a moving, accelerating state (doc/profiles.md §7):
  //! from (0, v_start, a_start) to (distance, v_end, 0) under 0 ≤ ṡ ≤ v_max, |s̈| ≤ a_max,
  //! |s⃛| ≤ j_max, never running backwards. The start may lie beyond the limits (v_start > v_max,
  //! |a_start| > a_max, or an a_start that carries ṡ above v_max even when cut at once): the law
  //! then first eases onto the limits at full jerk (and at −a_max), the velocity falling to v_max
  //! as fast as the limits allow, and is time-optimal from there. At most seven phases.
  //! Where S is too short for a law whose velocity stays between its start and end, the law dips
  //! (slows down and speeds up again). Throws std::invalid_argument on bad input (v_end ∉
  //! [0, v_max]; an a_start < 0 that makes ṡ negative before the acceleration can return to zero),
  //! or if no law fits in `distance` (the message names the distance needed and the shortfall).
  static Profile from_state(double distance, double v_max, double a_max, double j_max, double v_start = 0.0,
                            double a_start = 0.0, double v_end = 0.0);

  //! The time-optimal law without a jerk limit from velocity `v_start` ≥ 0, which may exceed
  //! v_max (doc/profiles.md §7.8): as trapezoid() for v_start ≤ v_max; above it, brake at −a_max
  //! to v_max, cruise, decelerate to v_end. The acceleration is not a state of this law (it
  //! jumps). Throws std::invalid_argument on bad input, or if S < |v_end² − v_start²| / (2 a).
  static Profile trapezoid_from_state(double distance, double v_max, double a_max, double v_start = 0.0,
                                      double v_end = 0.0);

  //! A law from explicit constant-jerk phases, for laws the two factories above do not make
  //! (the jerk-limited optimal re-timing cuts its motion into such pieces): `count` phases
  //! (1 … max_phases) of `durations[i]` > 0 and jerk `jerks[i]`, from (0, v_start, a_start) to
  //! (distance, v_end, a_end). The states between phases are integrated forward from the start
  //! and backward from the end (both ends are reproduced to rounding); the two halves must meet
  //! within 10⁻⁸ of the law's scale, and ṡ must stay ≥ 0 (to the same tolerance) — otherwise
  //! std::invalid_argument (the phases do not lead from the start state to the end state). The
  //! kind is scurve; outside the law the boundary states hold with their acceleration.
  static Profile from_phases(const double* durations, const double* jerks, int count, double v_start, double a_start,
                             double distance, double v_end, double a_end);

  //! Everything a law is made of: what storing a law (a pickle) keeps, and from_parts makes the
  //! same law from again, bit for bit.
  struct Parts {
    ProfileKind kind = ProfileKind::trapezoid;      //!< which family the law is of
    int count = 0;                                  //!< phases used, 0 … max_phases
    std::array<ProfilePhase, max_phases> phases{};  //!< the first `count` are used
    std::array<double, max_phases + 1> times{};     //!< start times of the phases, then T
    double distance = 0.0;                          //!< S, the length the law covers
    double peak_velocity = 0.0;                     //!< the highest ṡ of the law
    ProfileState start{};                           //!< the state before the start
    ProfileState end{};                             //!< the state from the end on
  };
  //! The law's parts (from_parts(parts()) is this law).
  Parts parts() const noexcept { return {kind_, count_, phases_, time_, distance_, peak_velocity_, start_, end_}; }
  //! The law of `parts`, taken as they are (nothing integrated again). Throws
  //! std::invalid_argument unless count is within [0, max_phases], the used times start at 0
  //! and do not decrease, every used number is finite, and the parts make a law as the
  //! factories do (require_consistent).
  static Profile from_parts(const Parts& parts);

  //! Trapezoid (acceleration-limited) or S-curve (jerk-limited).
  ProfileKind kind() const noexcept { return kind_; }
  //! T, the time the law takes (0 for S = 0 with v_start = v_end).
  double duration() const noexcept { return time_[static_cast<std::size_t>(count_)]; }
  //! S, the distance covered.
  double distance() const noexcept { return distance_; }
  //! The peak velocity v_p reached between the acceleration and the deceleration (for
  //! from_state and trapezoid_from_state: the highest velocity the law reaches).
  double peak_velocity() const noexcept { return peak_velocity_; }
  //! The number of phases of non-zero duration (0 … 7).
  int phase_count() const noexcept { return count_; }
  //! Phase i, 0 ≤ i < phase_count() (not checked).
  const ProfilePhase& phase(int i) const noexcept { return phases_[static_cast<std::size_t>(i)]; }
  //! The start time of phase i, 0 ≤ i ≤ phase_count() (i = phase_count(): the duration).
  double phase_start_time(int i) const noexcept { return time_[static_cast<std::size_t>(i)]; }

  //! s, ṡ, s̈, s⃛ at time t. Outside the law the boundary states hold: for t < 0 (and NaN)
  //! (0, v_start, a_start, 0) — a_start is 0 except for laws from a state (from_state,
  //! from_phases) — and for t ≥ T (S, v_end, 0, 0). At a phase boundary the later phase is
  //! used (its jerk, and for the trapezoid its acceleration, is reported), so t = 0 gives the
  //! first phase and t = T the state after the end. Inside a phase the state is evaluated from
  //! the nearer end of the phase, so it is exact to rounding near both ends of the law.
  ProfileState state_at(double t) const noexcept;

  //! state_at for each of `count` times: out[i] = state_at(times[i]).
  void sample(const double* times, ProfileState* out, std::size_t count) const noexcept;

 private:
  Profile() = default;
  //! What every law satisfies, the factories' and a stored one's alike; std::invalid_argument
  //! naming the part otherwise. The law starts at s = 0 and ends at the distance; each phase's
  //! duration is the time between its start and end times; each phase's end state is its start
  //! state carried over its duration with its jerk; each phase starts where (s) and as fast (ṡ)
  //! as the one before ends; and 0 ≤ ṡ ≤ peak_velocity throughout — each to 1e-8 of
  //! the law's scale (the tolerance within which from_phases' halves meet).
  void require_consistent() const;
  //! Appends a phase of `duration` > 0 and jerk `jerk` whose acceleration runs from `a_start`
  //! to `a_end` (s and v are filled in by integrate()). Zero durations are skipped.
  void add_phase(double duration, double jerk, double a_start, double a_end) noexcept;
  //! Fills s and v at both ends of every phase: forward from (0, v_start) up to the start of
  //! phase `cruise` and backward from (S, v_end) from its end, so that both ends of the law
  //! are reproduced to rounding.
  void integrate(double v_start, double v_end, int cruise) noexcept;
  // from_phases: the phases' states integrated forward from the start over the first half and
  // backward from the end over the second; the two states where the halves meet.
  std::pair<ProfileState, ProfileState> integrate_from_both_ends(double v_start, double a_start, double v_end,
                                                                 double a_end) noexcept;

  std::array<ProfilePhase, max_phases> phases_{};
  std::array<double, max_phases + 1> time_{};  //!< start times of the phases, then T
  int count_ = 0;
  ProfileKind kind_ = ProfileKind::trapezoid;
  double distance_ = 0.0;
  double peak_velocity_ = 0.0;
  ProfileState start_{};  //!< (0, v_start, a_start, 0), the state before the start
  ProfileState end_{};    //!< (S, v_end, 0, 0), the state from the end on
};

inline ProfileState Profile::state_at(double t) const noexcept {
  if (!(t >= 0.0)) return start_;
  if (t >= time_[static_cast<std::size_t>(count_)]) return end_;
  // The last phase whose start time is ≤ t (a boundary time belongs to the later phase).
  int i = 0;
  while (i + 1 < count_ && time_[static_cast<std::size_t>(i + 1)] <= t) ++i;
  const ProfilePhase& p = phases_[static_cast<std::size_t>(i)];
  const double dt = t - time_[static_cast<std::size_t>(i)];
  const double tau = time_[static_cast<std::size_t>(i + 1)] - t;
  const double j = p.jerk;
  ProfileState x;
  x.j = j;
  if (dt <= tau) {
    // Taylor polynomial of the start state: s = s₀ + v₀ dt + a₀ dt²/2 + j dt³/6.
    const ProfileState& a = p.start;
    x.a = a.a + j * dt;
    x.v = a.v + dt * (a.a + 0.5 * j * dt);
    x.s = a.s + dt * (a.v + dt * (0.5 * a.a + j * dt / 6.0));
  } else {
    // Taylor polynomial of the end state, τ = t_end − t: s = s₁ − v₁ τ + a₁ τ²/2 − j τ³/6.
    const ProfileState& b = p.end;
    x.a = b.a - j * tau;
    x.v = b.v - tau * (b.a - 0.5 * j * tau);
    x.s = b.s - tau * (b.v - tau * (0.5 * b.a - j * tau / 6.0));
  }
  return x;
}

inline void Profile::sample(const double* times, ProfileState* out, std::size_t count) const noexcept {
  for (std::size_t i = 0; i < count; ++i) out[i] = state_at(times[i]);
}

}  // namespace dispkin
