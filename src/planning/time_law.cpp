// A time law over a path (time_law.hpp).
#include "dispkin/planning/time_law.hpp"

#include <algorithm>

namespace dispkin {

TimeLaw TimeLaw::consecutive(const std::vector<Profile>& laws, std::size_t runs) {
  TimeLaw out;
  out.pieces_.reserve(laws.size());
  double s = 0.0;
  for (const Profile& law : laws) {
    out.append(law, s);
    s += law.distance();
  }
  out.runs_ = runs;
  return out;
}

void TimeLaw::append(const Profile& law, double start_s) {
  const double time = duration();
  pieces_.push_back(Piece{law, time, time + law.duration(), start_s});
}

std::vector<double> TimeLaw::characteristic_times() const {
  std::vector<double> times{0.0};
  for (const Piece& piece : pieces_) {
    const Profile& law = piece.profile;
    for (int i = 0; i < law.phase_count(); ++i) {
      const double begin = law.phase_start_time(i), end = law.phase_start_time(i + 1);
      times.push_back(piece.start_time + 0.5 * (begin + end));
      times.push_back(piece.start_time + end);
    }
  }
  std::sort(times.begin(), times.end());
  // Phases of vanishing length (a cruise over 10⁻⁹ of a law's distance, left by rounding) add
  // instants that coincide within 10⁻⁹ of the duration: one of each is kept.
  const double same = 1e-9 * duration();
  times.erase(std::unique(times.begin(), times.end(), [same](double a, double b) { return b - a <= same; }), times.end());
  return times;
}

}  // namespace dispkin
