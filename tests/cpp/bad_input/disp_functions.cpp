// The rows of the C++ bad-input table (tests/cpp/test_bad_input_table.cpp) of one area: the DISP functions: distances,
// speeds, section lengths, interpolation.
#include "rows.hpp"

namespace bad_input {

void disp_functions_rows(std::vector<Row>& table) {
  const RowAdder row{table};
  // --- DISP functions ---
  row(
      "disp_distance", "empty set", [] { disp_distance(MetricSetd(), A, B); }, IA,
      "metric_set = \"MetricSet\": is not well-formed: the set is empty");
  row(
      "disp_distance", "collinear set", [] { disp_distance(collinear_set(), A, B); }, IA,
      "metric_set = \"MetricSet\": is not well-formed");
  row(
      "disp_distance", "zero system_velocity", [] { disp_distance(good_set(), A, B, 0.0); }, IA, "system_velocity = 0");
  row(
      "disp_distance", "negative system_velocity", [] { disp_distance(good_set(), A, B, -1.0); }, IA,
      "system_velocity = -1");
  row(
      "disp_distance", "NaN system_velocity", [] { disp_distance(good_set(), A, B, nan_); }, IA,
      "system_velocity = nan");
  row(
      "interpolation_from_string", "unknown interpolation", [] { interpolation_from_string("slerp"); }, IA,
      "interpolation = \"slerp\"");
  row(
      "interpolation_from_string", "empty name", [] { interpolation_from_string(""); }, IA, "interpolation = \"\"");
  row(
      "interpolate", "NaN tau", [] { (void)interpolate(A, B, nan_, Interpolation::decoupled); }, IA, "tau = nan",
      "returns a pose whose quaternion and translation are all NaN (noexcept, unchecked; the Python binding rejects "
      "it)");
  row(
      "interpolate", "tau above 1", [] { (void)interpolate(A, B, 2.0, Interpolation::decoupled); }, IA, "tau = 2",
      "extrapolates: the pose at tau = 2 (x = 0.2); tau in [0, 1] is not checked");
  row(
      "section_length", "empty set", [] { section_length(MetricSetd(), A, B, Interpolation::decoupled); }, IA,
      "metric_set = \"MetricSet\": is not well-formed");
  row(
      "section_length", "collinear set", [] { section_length(collinear_set(), A, B, Interpolation::screw); }, IA,
      "metric_set = \"MetricSet\": is not well-formed");
  row(
      "section_length", "NaN pivot",
      [] { section_length(good_set(), A, B, Interpolation::decoupled, Vector3d(nan_, 0, 0)); }, IA,
      "pivot = (nan, 0, 0)");
  row(
      "section_length", "pivot beyond the numeric range (1e13 m)",
      [] { section_length(good_set(), A, B, Interpolation::screw, Vector3d(0, 1e13, 0)); }, IA,
      "pivot = (0, 1e+13, 0): must have coordinates within ±1e12 m");
  row(
      "section_length", "zero system_velocity",
      [] { section_length(good_set(), A, B, Interpolation::decoupled, Vector3d::Zero(), 0.0); }, IA,
      "system_velocity = 0");
  row(
      "section_length", "+inf system_velocity",
      [] { section_length(good_set(), A, B, Interpolation::decoupled, Vector3d::Zero(), inf_); }, IA,
      "system_velocity = inf");
  row(
      "max_point_speed", "negative system_velocity", [] { max_point_speed(good_set(), A, XI, -2.0); }, IA,
      "system_velocity = -2");
  row(
      "max_point_speed", "empty set", [] { (void)max_point_speed(MetricSetd(), A, XI); }, IA,
      "metric_set = \"MetricSet\": is empty");
  row(
      "max_point_speed", "NaN twist",
      [] { (void)max_point_speed(good_set(), A, Twistd(Vector3d(nan_, 0, 0), Vector3d::Zero())); }, IA, "twist");
}

}  // namespace bad_input
