// Profiles from their parts and from explicit phases (dispkin/profile.hpp; doc/profiles.md §4).
#include <cmath>
#include <limits>
#include <string>

#include <gtest/gtest.h>

#include "dispkin/profile.hpp"
#include "random_cases.hpp"

namespace dispkin {
namespace {

using testing::message_of;

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// A law made again from its parts gives the same states, bit for bit, at any time.
TEST(Profile, FromPartsMakesTheSameLaw) {
  const Profile laws[] = {Profile::trapezoid(0.3, 0.25, 1.0, 0.1, 0.05), Profile::scurve(0.3, 0.25, 1.0, 10.0),
                          Profile::scurve(0.01, 0.25, 1.0, 10.0, 0.02, 0.0)};
  for (const Profile& law : laws) {
    const Profile copy = Profile::from_parts(law.parts());
    EXPECT_EQ(copy.kind(), law.kind());
    EXPECT_EQ(copy.phase_count(), law.phase_count());
    for (int i = -10; i <= 1010; ++i) {
      const double t = law.duration() * i / 1000.0;
      const ProfileState x = copy.state_at(t), y = law.state_at(t);
      ASSERT_EQ(x.s, y.s);
      ASSERT_EQ(x.v, y.v);
      ASSERT_EQ(x.a, y.a);
      ASSERT_EQ(x.j, y.j);
    }
  }
  Profile::Parts bad = laws[1].parts();
  bad.count = 8;
  EXPECT_NE(message_of([&] { Profile::from_parts(bad); }).find("count = 8"), std::string::npos);
  bad = laws[1].parts();
  bad.times[2] = bad.times[1] - 1.0;
  EXPECT_NE(message_of([&] { Profile::from_parts(bad); }).find("times[2]"), std::string::npos);
}

// Parts that are no law are refused as the factories' laws would be (require_consistent): a
// phase whose end is not its start carried over its duration, a law faster than its peak, a
// law that does not end at its distance. Scaled consistently (v × f, a × f², j × f³, t / f) it is
// a law again.
TEST(Profile, FromPartsRefusesPartsThatAreNoLaw) {
  const Profile law = Profile::scurve(0.3, 0.25, 1.0, 10.0);
  Profile::Parts bad = law.parts();
  bad.phases[2].end.v = 1e308;
  EXPECT_NE(message_of([&] { Profile::from_parts(bad); }).find("phases[2].end (s, v, a) = ("), std::string::npos);
  bad = law.parts();
  bad.peak_velocity = 0.5 * law.peak_velocity();
  EXPECT_NE(message_of([&] { Profile::from_parts(bad); }).find("must be within [0, peak_velocity = 0.125]"),
            std::string::npos);
  bad = law.parts();
  bad.distance *= 2.0;
  EXPECT_NE(message_of([&] { Profile::from_parts(bad); }).find("end.s = 0.3: must be the distance 0.6"),
            std::string::npos);
  Profile::Parts faster = law.parts();
  const double f = 1000.0;
  const auto scale = [f](ProfileState& x) {
    x.v *= f;
    x.a *= f * f;
    x.j *= f * f * f;
  };
  for (int i = 0; i < faster.count; ++i) {
    ProfilePhase& p = faster.phases[static_cast<std::size_t>(i)];
    p.duration /= f;
    p.jerk *= f * f * f;
    scale(p.start);
    scale(p.end);
  }
  for (double& t : faster.times) t /= f;
  faster.peak_velocity *= f;
  EXPECT_NEAR(Profile::from_parts(faster).duration(), law.duration() / f, 1e-12 * law.duration());
}

// from_phases: the phases of an S-curve with boundary velocities give back the same law; phases
// that do not lead to the stated end state, or that run backwards, are refused.
TEST(Profile, FromPhasesRebuildsALaw) {
  const Profile law = Profile::scurve(0.3, 0.5, 2.0, 20.0, 0.1, 0.05);
  double durations[Profile::max_phases], jerks[Profile::max_phases];
  const int n = law.phase_count();
  for (int i = 0; i < n; ++i) {
    durations[i] = law.phase(i).duration;
    jerks[i] = law.phase(i).jerk;
  }
  const Profile copy = Profile::from_phases(durations, jerks, n, 0.1, 0.0, 0.3, 0.05, 0.0);
  EXPECT_NEAR(copy.duration(), law.duration(), 1e-15);
  for (int k = 0; k <= 200; ++k) {
    const double t = law.duration() * k / 200.0;
    const ProfileState a = law.state_at(t), b = copy.state_at(t);
    ASSERT_NEAR(a.s, b.s, 1e-13);
    ASSERT_NEAR(a.v, b.v, 1e-13);
    ASSERT_NEAR(a.a, b.a, 1e-12);
  }
  // A piece of it that starts and ends mid-phase, with non-zero accelerations.
  const double t0 = 0.3 * law.phase_start_time(1), t1 = law.duration() - 0.5 * law.phase(n - 1).duration;
  const ProfileState a = law.state_at(t0), b = law.state_at(t1);
  int m = 0;
  double cut_durations[Profile::max_phases], cut_jerks[Profile::max_phases];
  for (int i = 0; i < n; ++i) {
    const double lo = std::max(t0, law.phase_start_time(i)), hi = std::min(t1, law.phase_start_time(i + 1));
    if (hi > lo) {
      cut_durations[m] = hi - lo;
      cut_jerks[m++] = law.phase(i).jerk;
    }
  }
  const Profile piece = Profile::from_phases(cut_durations, cut_jerks, m, a.v, a.a, b.s - a.s, b.v, b.a);
  EXPECT_NEAR(piece.duration(), t1 - t0, 1e-15);
  const ProfileState middle = piece.state_at(0.5 * (t1 - t0)), expected = law.state_at(0.5 * (t0 + t1));
  EXPECT_NEAR(middle.s, expected.s - a.s, 1e-13);
  EXPECT_NEAR(middle.v, expected.v, 1e-13);
  EXPECT_EQ(piece.state_at(t1 - t0 + 1.0).a, b.a);  // the end state holds, with its acceleration

  // Every law starts exactly where it is placed (s = 0), its phases' rounding left at their meeting
  // point inside or at the end, also when it has one phase whose end the caller rounded (1e-9 of
  // its distance off here, within the tolerance).
  const double one_d[] = {0.7}, one_j[] = {3.0};
  const double one_s = 3.0 * 0.7 * 0.7 * 0.7 / 6.0;
  const Profile one = Profile::from_phases(one_d, one_j, 1, 0.0, 0.0, one_s * (1.0 + 1e-9), 1.5 * 0.49, 2.1);
  EXPECT_EQ(one.state_at(0.0).s, 0.0);
  EXPECT_EQ(one.state_at(0.0).v, 0.0);
  EXPECT_EQ(one.state_at(one.duration()).s, one.distance());

  EXPECT_NE(
      message_of([&] { Profile::from_phases(durations, jerks, n, 0.1, 0.0, 0.31, 0.05, 0.0); }).find("do not lead"),
      std::string::npos);
  const double dip_d[] = {2.0}, dip_j[] = {2.0};  // ṡ = (t − 1)² − 0.01: below 0 around t = 1
  EXPECT_NE(message_of([&] {
              Profile::from_phases(dip_d, dip_j, 1, 0.99, -2.0, 2.0 / 3.0 - 0.02, 0.99, 2.0);
            }).find("negative"),
            std::string::npos);
  EXPECT_NE(message_of([&] { Profile::from_phases(durations, jerks, 0, 0.1, 0.0, 0.3, 0.05, 0.0); }).find("count = 0"),
            std::string::npos);
  durations[1] = kNaN;
  EXPECT_NE(
      message_of([&] { Profile::from_phases(durations, jerks, n, 0.1, 0.0, 0.3, 0.05, 0.0); }).find("durations[1]"),
      std::string::npos);
}

}  // namespace
}  // namespace dispkin
