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

void TimeLaw::append_cut(const Profile& law, double start_s, double end_time) {
  const double time = duration();
  pieces_.push_back(Piece{law, time, end_time, start_s, true});
}

TimeLaw TimeLaw::before(double t) const {
  TimeLaw out;
  for (const Piece& piece : pieces_) {
    if (piece.end_time <= t) {
      out.pieces_.push_back(piece);
      if (!piece.cut && piece.profile.state_at(piece.profile.duration()).v == 0.0) ++out.runs_;
    } else {
      if (piece.start_time < t) {
        out.pieces_.push_back(piece);
        out.pieces_.back().end_time = t;
        out.pieces_.back().cut = true;
      }
      break;
    }
  }
  return out;
}

std::vector<double> TimeLaw::characteristic_times() const {
  std::vector<double> times{0.0};
  for (const Piece& piece : pieces_) {
    const Profile& law = piece.profile;
    // A cut law runs up to its cut only.
    const double run = piece.end_time - piece.start_time;
    for (int i = 0; i < law.phase_count() && law.phase_start_time(i) < run; ++i) {
      const double begin = law.phase_start_time(i), end = std::min(law.phase_start_time(i + 1), run);
      times.push_back(piece.start_time + 0.5 * (begin + end));
      times.push_back(piece.start_time + end);
    }
  }
  std::sort(times.begin(), times.end());
  // Phases of vanishing length (a cruise over 10⁻⁹ of a law's distance, left by rounding) add
  // instants that coincide within 10⁻⁹ of the duration: one of each is kept.
  const double same = 1e-9 * duration();
  times.erase(std::unique(times.begin(), times.end(), [same](double a, double b) { return b - a <= same; }),
              times.end());
  return times;
}

}  // namespace dispkin
