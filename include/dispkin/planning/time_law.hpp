//! A time law s(t) over a path: consecutive one-dimensional profiles (doc/profiles.md), each over
//! its own span of s, grouped in rest-to-rest runs. plan() builds one per velocity-limit segment
//! of each run; re-timing builds others for the same path. Evaluation is noexcept and
//! allocation-free.
#pragma once

#include <algorithm>
#include <cstddef>
#include <vector>

#include "dispkin/profile.hpp"

namespace dispkin {

//! s(t) over a path: profiles one after another, each over its own span of s, in rest-to-rest
//! runs (doc/profiles.md).
class TimeLaw {
 public:
  //! One profile, placed in time and along the path.
  struct Piece {
    Profile profile;  //!< the law, from its own s = 0 and t = 0
    //! When it starts and ends, in trajectory time (s).
    //!@{
    double start_time, end_time;  //!< in trajectory time, s
    //!@}
    double start_s;  //!< path position at its start, m
    //! Whether the law was cut at end_time, before its own end, where another law takes over
    //! from its state there (a stop or a speed override, Trajectory::stopped_at); the law itself
    //! stays whole, so that the motion before the cut is the same, bit for bit.
    bool cut = false;

    //! The distance it covers: the law's own, or up to the cut.
    double distance() const noexcept { return cut ? profile.state_at(end_time - start_time).s : profile.distance(); }
  };

  //! Laws one after another from s = 0, each starting where the one before ended, in `runs`
  //! rest-to-rest runs (planning side; allocates).
  static TimeLaw consecutive(const std::vector<Profile>& laws, std::size_t runs);

  //! Appends `law` from path position `start_s`, starting when the last one ends.
  void append(const Profile& law, double start_s);
  //! Appends `law` from path position `start_s`, starting when the last one ends and cut at
  //! `end_time` (trajectory time, after its start and before its own end; Piece::cut).
  void append_cut(const Profile& law, double start_s, double end_time);
  //! The motion up to t, to which a new law from the state at t is appended: every law that
  //! ends at or before t as it is, the one running at t cut at t (planning side; allocates).
  //! Its runs are those that ended at rest before t.
  TimeLaw before(double t) const;
  //! Ends a rest-to-rest run (the motion is at rest after the last law appended).
  void end_run() noexcept { ++runs_; }

  //! When the last law ends (s); 0 without any.
  double duration() const noexcept { return pieces_.empty() ? 0.0 : pieces_.back().end_time; }
  //! Number of laws.
  std::size_t size() const noexcept { return pieces_.size(); }
  //! Number of rest-to-rest runs.
  std::size_t run_count() const noexcept { return runs_; }
  //! The laws in time order.
  const std::vector<Piece>& pieces() const noexcept { return pieces_; }

  //! The law running at t: the first that ends after t (the last one for t ≥ duration), found
  //! from the hint `piece` when that or the next one is it (size() means none: binary search).
  std::size_t piece_at(double t, std::size_t piece) const noexcept;
  //! s, ṡ, s̈, s⃛ at t (in [0, duration]) in the law piece_at(t, piece), which is stored in `piece`.
  ProfileState state_at(double t, std::size_t& piece) const noexcept {
    piece = piece_at(t, piece);
    const Piece& p = pieces_[piece];
    ProfileState state = p.profile.state_at(t - p.start_time);
    state.s = p.start_s + state.s;
    return state;
  }

  //! Every phase boundary and phase middle of every law, sorted, from 0 to duration(): the
  //! instants where velocity or acceleration peak or change their course. Allocates.
  std::vector<double> characteristic_times() const;

 private:
  std::vector<Piece> pieces_;
  std::size_t runs_ = 0;
};

// Inline: on the sampling path of every trajectory.
inline std::size_t TimeLaw::piece_at(double t, std::size_t piece) const noexcept {
  const std::size_t last = pieces_.size() - 1;
  // Piece p is it when the one before ends at or before t and p ends after t (or is the last).
  const auto is_it = [&](std::size_t p) {
    return (p == 0 || pieces_[p - 1].end_time <= t) && (p == last || t < pieces_[p].end_time);
  };
  if (piece <= last && is_it(piece)) return piece;
  if (piece < last && is_it(piece + 1)) return piece + 1;
  const auto it =
      std::upper_bound(pieces_.begin(), pieces_.end(), t, [](double x, const Piece& p) { return x < p.end_time; });
  return it == pieces_.end() ? last : static_cast<std::size_t>(it - pieces_.begin());
}

}  // namespace dispkin
