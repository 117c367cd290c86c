// Sampling a trajectory: the time law gives s, ṡ, s̈ at t, the sampled path the pose and the
// body twist per unit τ at s (trajectory.hpp).
#include "dispkin/planning/trajectory.hpp"

namespace dispkin {

TrajectorySample Trajectory::sample(double t) const noexcept {
  Cursor search{law_.size(), path_.section_count()};  // no hint: binary search
  return sample(t, search);
}

TrajectorySample Trajectory::sample(double t, Cursor& cursor) const noexcept {
  TrajectorySample out;
  if (law_.size() == 0) return out;
  if (!(t > 0.0)) t = 0.0;
  const ProfileState law = law_.state_at(t, cursor.piece);
  out.s = law.s;
  out.s_dot = law.v;
  out.s_ddot = law.a;
  const std::size_t k = cursor.section = path_.section_state(out.s, cursor.section, out.pose, out.body_twist);
  out.body_twist = out.body_twist * (out.s_dot * path_.inverse_length(k));  // per τ → per second
  return out;
}

void Trajectory::sample(const double* times, TrajectorySample* out, std::size_t count) const noexcept {
  Cursor cursor;
  for (std::size_t i = 0; i < count; ++i) out[i] = sample(times[i], cursor);
}

}  // namespace dispkin
