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
// Python holds, not copies. Of those, a MetricSet (add_*, set_group_speed) and a Path (then)
// can be changed from Python, so a released call marks the ones it reads, and their changing
// methods refuse with RuntimeError while one is marked (require_not_read): another thread
// changing a set that a plan is reading gets an error instead of the planner reading freed
// memory. Marks are set and cleared with the lock held, so the registry needs no lock of its
// own. A SerialArm is copied where its gravity matters (it can be set from Python); every other
// bound type is immutable once built.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <dispkin/metric_set.hpp>
#include <pybind11/pybind11.h>

namespace dispkin {
namespace python {

namespace detail {

//! The objects read by calls running with the lock released, once per reading call.
inline std::vector<const void*>& objects_being_read() {
  static std::vector<const void*> objects;
  return objects;
}

}  // namespace detail

//! RuntimeError when a call running with the lock released (in another thread) reads `object`:
//! called, with the lock held, by the methods that change a MetricSet or a Path.
inline void require_not_read(const void* object, const char* method) {
  const auto& read = detail::objects_being_read();
  if (std::find(read.begin(), read.end(), object) != read.end()) {
    throw std::runtime_error(std::string(method) +
                             ": the object is being read by a call running in another thread (a plan, a "
                             "length, a re-timing); change it once that call has returned, or change a copy "
                             "(copy.deepcopy)");
  }
}

//! Releases the interpreter lock for its lifetime if `release`, the objects given being marked
//! as read meanwhile (see require_not_read). Built and destroyed with the lock held.
class UnlockedIf {
 public:
  template <typename... Read>
  explicit UnlockedIf(bool release, const Read&... read) {
    static_assert(sizeof...(Read) <= 4, "UnlockedIf marks at most four objects");
    if (!release) return;
    ((marked_[count_++] = &read), ...);
    auto& objects = detail::objects_being_read();
    objects.insert(objects.end(), marked_.begin(), marked_.begin() + count_);
    unlocked_.emplace();
  }
  ~UnlockedIf() {
    unlocked_.reset();  // the lock first: the registry is touched with it held only
    auto& objects = detail::objects_being_read();
    for (std::size_t i = 0; i < count_; ++i) objects.erase(std::find(objects.begin(), objects.end(), marked_[i]));
  }
  UnlockedIf(const UnlockedIf&) = delete;
  UnlockedIf& operator=(const UnlockedIf&) = delete;

 private:
  std::array<const void*, 4> marked_{};
  std::size_t count_ = 0;
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
