// The instants a joint-limit check looks at (retiming.hpp, checked_times).
#include "dispkin/error.hpp"
#include "dispkin/planning/retiming.hpp"

namespace dispkin {

std::vector<double> checked_times(const Trajectory& trajectory, const JointCheckOptions& options) {
  require(options.samples_between >= 0, "samples_between", static_cast<long>(options.samples_between), "must be ≥ 0");
  require_positive(options.difference_step, "difference_step");
  const std::vector<double> marks = trajectory.characteristic_times();
  std::vector<double> times;
  for (std::size_t k = 0; k + 1 < marks.size(); ++k) {
    for (int i = 0; i <= options.samples_between; ++i)
      times.push_back(marks[k] + (marks[k + 1] - marks[k]) * i / (options.samples_between + 1));
  }
  times.push_back(marks.back());
  return times;
}

}  // namespace dispkin
