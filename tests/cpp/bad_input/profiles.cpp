// The rows of the C++ bad-input table (tests/cpp/test_bad_input_table.cpp) of one area: Profile.
#include "rows.hpp"

namespace bad_input {

void profiles_rows(std::vector<Row>& table) {
  const RowAdder row{table};
  // --- Profile ---
  row(
      "Profile::trapezoid", "v_max whose duration overflows (10 m at 1e-308 m/s)",
      [] { Profile::trapezoid(10, 1e-308, 1); }, IA,
      "v_max = 1e-308: with a_max = 1 over distance = 10: the law's duration overflows");
  row(
      "Profile::scurve", "v_max whose duration overflows (10 m at 1e-308 m/s)",
      [] { Profile::scurve(10, 1e-308, 1, 1); }, IA,
      "v_max = 1e-308: with a_max = 1, j_max = 1 over distance = 10: the law's duration overflows");
  row(
      "Profile::trapezoid", "NaN distance", [] { Profile::trapezoid(nan_, 1, 1); }, IA, "distance = nan");
  row(
      "Profile::trapezoid", "negative distance", [] { Profile::trapezoid(-1, 1, 1); }, IA, "distance = -1");
  row(
      "Profile::trapezoid", "+inf distance", [] { Profile::trapezoid(inf_, 1, 1); }, IA, "distance = inf");
  row(
      "Profile::trapezoid", "zero v_max", [] { Profile::trapezoid(1, 0, 1); }, IA, "v_max = 0");
  row(
      "Profile::trapezoid", "negative a_max", [] { Profile::trapezoid(1, 1, -1); }, IA, "a_max = -1");
  row(
      "Profile::trapezoid", "+inf v_max", [] { Profile::trapezoid(1, inf_, 1); }, IA, "v_max = inf");
  row(
      "Profile::trapezoid", "negative v_start", [] { Profile::trapezoid(1, 1, 1, -0.5); }, IA, "v_start = -0.5");
  row(
      "Profile::trapezoid", "v_end above v_max", [] { Profile::trapezoid(1, 1, 1, 0, 2.0); }, IA, "v_end = 2");
  row(
      "Profile::scurve", "zero j_max", [] { Profile::scurve(1, 1, 1, 0); }, IA, "j_max = 0");
  row(
      "Profile::scurve", "NaN j_max", [] { Profile::scurve(1, 1, 1, nan_); }, IA, "j_max = nan");
  row(
      "Profile::scurve", "negative v_max", [] { Profile::scurve(1, -1, 1, 1); }, IA, "v_max = -1");
  row(
      "Profile::scurve", "NaN distance", [] { Profile::scurve(nan_, 1, 1, 1); }, IA, "distance = nan");
  row(
      "Profile::from_phases", "zero phases",
      [] {
        const double d[] = {1.0};
        Profile::from_phases(d, d, 0, 0, 0, 1, 1, 0);
      },
      IA, "count = 0");
  row(
      "Profile::from_phases", "NaN duration",
      [] {
        const double d[] = {nan_}, j[] = {0.0};
        Profile::from_phases(d, j, 1, 1, 0, 1, 1, 0);
      },
      IA, "durations[0] = nan");
  row(
      "Profile::from_phases", "inf jerk",
      [] {
        const double d[] = {1.0}, j[] = {inf_};
        Profile::from_phases(d, j, 1, 1, 0, 1, 1, 0);
      },
      IA, "jerks[0] = inf");
  row(
      "Profile::from_phases", "negative v_start",
      [] {
        const double d[] = {1.0}, j[] = {0.0};
        Profile::from_phases(d, j, 1, -1, 0, 1, 1, 0);
      },
      IA, "v_start = -1");
  row(
      "Profile::from_phases", "end state not reached",
      [] {
        const double d[] = {1.0}, j[] = {0.0};
        Profile::from_phases(d, j, 1, 1, 0, 2, 1, 0);
      },
      IA, "distance = 2");
}

}  // namespace bad_input
