// When the bindings let other Python threads run: every call that can take more than about
// 10 µs releases the interpreter lock (GIL) while its C++ work runs, after its arguments have
// been converted to C++ values and before its result is converted back (no Python object is
// touched meanwhile). Shorter calls keep it: releasing and taking it back costs a fraction of a
// µs when no other thread wants it, a visible share of a call that takes one, and when another
// thread runs Python code meanwhile, taking it back waits until that thread lets go of it (up
// to the switch interval, 5 ms by default), so a loop of short calls that released the lock
// would crawl beside a busy thread.
//
// What a released call reads must not change meanwhile: its C++ arguments are the objects
// Python holds (a MetricSet, a Path, a Trajectory), not copies, so another thread must not
// modify one (MetricSet.add_*, set_group_speed, Path.then) while a call that uses it runs.
// A SerialArm is copied where its gravity matters (it can be set from Python).
#pragma once

#include <cstddef>
#include <optional>

#include <dispkin/metric_set.hpp>
#include <pybind11/pybind11.h>

namespace dispkin {
namespace python {

//! Releases the interpreter lock for its lifetime if `release`.
class UnlockedIf {
 public:
  explicit UnlockedIf(bool release) {
    if (release) unlocked_.emplace();
  }

 private:
  std::optional<pybind11::gil_scoped_release> unlocked_;
};

//! Whether `count` steps of about `ns_each` nanoseconds each add up to the ≈ 10 µs worth
//! releasing the lock for.
inline bool worth_releasing(std::size_t count, double ns_each) noexcept {
  return static_cast<double>(count) * ns_each >= 1e4;
}

//! Whether a pass over `set` (a distance, a section length, a speed) is: the slowest kernel, a
//! decoupled section length, takes ≈ 20 ns per object (benchmarks/RESULTS.md), so from 500.
inline bool worth_releasing(const MetricSetd& set) noexcept {
  return worth_releasing(set.point_count() + set.sphere_count(), 20.0);
}

// The cost of one step of the batched calls (ns), rounded down from the benchmarks.
constexpr double trajectory_sample_ns = 200.0;  //!< Trajectory / JointTrajectory.sample, Path.sample
constexpr double leg_lengths_ns = 50.0;         //!< Hexapod.inverse of one pose
constexpr double point_speed_ns = 5.0;          //!< point_speed of one point
constexpr double hull_point_ns = 100.0;         //!< Qhull, per input point
constexpr double profile_state_ns = 20.0;       //!< Profile.sample of one time
constexpr double point_transform_ns = 20.0;     //!< Pose.transform of one point

}  // namespace python
}  // namespace dispkin
