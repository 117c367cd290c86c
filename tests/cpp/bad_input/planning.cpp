// The rows of the C++ bad-input table (tests/cpp/test_bad_input_table.cpp) of one area: Limits, plan, Trajectory,
// overlaps and the motion stream.
#include "rows.hpp"

namespace bad_input {

void planning_rows(std::vector<Row>& table) {
  const RowAdder row{table};
  // --- Limits / plan ---
  row(
      "Limits::validate", "zero velocity", [] { limits(0, 1, 10).validate(ProfileKind::scurve); }, IA, "velocity = 0");
  row(
      "Limits::validate", "negative acceleration", [] { limits(1, -1, 10).validate(ProfileKind::scurve); }, IA,
      "acceleration = -1");
  row(
      "Limits::validate", "NaN velocity", [] { limits(nan_, 1, 10).validate(ProfileKind::scurve); }, IA,
      "velocity = nan");
  row(
      "Limits::validate", "+inf acceleration", [] { limits(1, inf_, 10).validate(ProfileKind::scurve); }, IA,
      "acceleration = inf");
  row(
      "Limits::validate", "velocity below the numeric range (1e-13)",
      [] { limits(1e-13, 1, 10).validate(ProfileKind::scurve); }, IA, "velocity = 1e-13: must be in [1e-12, 1e12]");
  row(
      "Limits::validate", "jerk above the numeric range (1e13)",
      [] { limits(1, 1, 1e13).validate(ProfileKind::scurve); }, IA, "jerk = 1e+13: must be in [1e-12, 1e12]");
  row(
      "Limits::validate", "zero jerk", [] { limits(1, 1, 0.0).validate(ProfileKind::scurve); }, IA, "jerk = 0");
  row(
      "Limits::validate", "negative jerk", [] { limits(1, 1, -5.0).validate(ProfileKind::scurve); }, IA, "jerk = -5");
  row(
      "Limits::validate", "scurve without jerk", [] { limits(1, 1, std::nullopt).validate(ProfileKind::scurve); }, IA,
      "jerk is missing: the S-curve profile needs a jerk limit");
  row(
      "Limits::validate", "jerk with trapezoid", [] { limits(1, 1, 10).validate(ProfileKind::trapezoid); }, IA,
      "jerk = 10");
  row(
      "plan", "empty set", [] { plan(Path::lin(A, B), MetricSetd(), limits(0.1, 1, 10)); }, IA,
      "metric_set = \"MetricSet\": is not well-formed");
  row(
      "plan", "collinear set", [] { plan(Path::lin(A, B), collinear_set(), limits(0.1, 1, 10)); }, IA,
      "metric_set = \"MetricSet\": is not well-formed");
  row(
      "plan", "zero velocity", [] { plan(Path::lin(A, B), good_set(), limits(0, 1, 10)); }, IA, "velocity = 0");
  row(
      "plan", "NaN jerk", [] { plan(Path::lin(A, B), good_set(), limits(0.1, 1, nan_)); }, IA, "jerk = nan");
  row(
      "plan(options)", "too many min lengths",
      [] {
        PlanOptions o;
        o.min_section_lengths = {0.1, 0.2};
        plan(Path::lin(A, B), good_set(), limits(0.1, 1, 10), ProfileKind::scurve, o);
      },
      IA, "min_section_lengths size = 2: must be 0 or the path's section count 1");
  row(
      "plan(options)", "negative min length",
      [] {
        PlanOptions o;
        o.min_section_lengths = {-0.5};
        plan(Path::lin(A, B), good_set(), limits(0.1, 1, 10), ProfileKind::scurve, o);
      },
      IA, "min_section_lengths[0] = -0.5");
  row(
      "plan(options)", "NaN min length",
      [] {
        PlanOptions o;
        o.min_section_lengths = {nan_};
        plan(Path::lin(A, B), good_set(), limits(0.1, 1, 10), ProfileKind::scurve, o);
      },
      IA, "min_section_lengths[0] = nan");
  row(
      "plan(options)", "+inf min length",
      [] {
        PlanOptions o;
        o.min_section_lengths = {inf_};
        plan(Path::lin(A, B), good_set(), limits(0.1, 1, 10), ProfileKind::scurve, o);
      },
      IA, "min_section_lengths[0] = inf");

  row(
      "OverlappedTrajectory", "negative overlap",
      [] {
        const Trajectory t = plan(Path::lin(A, B), good_set(), limits(0.1, 1, 10));
        OverlappedTrajectory(t, plan(Path::lin(B, C), good_set(), limits(0.1, 1, 10)), -0.5);
      },
      IA, "overlap = -0.5");
  row(
      "OverlappedTrajectory", "NaN overlap",
      [] {
        const Trajectory t = plan(Path::lin(A, B), good_set(), limits(0.1, 1, 10));
        OverlappedTrajectory(t, plan(Path::lin(B, C), good_set(), limits(0.1, 1, 10)), nan_);
      },
      IA, "overlap = nan");
  row(
      "OverlappedTrajectory", "overlap longer than a move",
      [] {
        const Trajectory t = plan(Path::lin(A, B), good_set(), limits(0.1, 1, 10));
        OverlappedTrajectory(t, plan(Path::lin(B, C), good_set(), limits(0.1, 1, 10)), 100.0);
      },
      IA, "overlap = 100: must be between 0 and the shorter move's duration");
  row(
      "OverlappedTrajectory", "moves not joining",
      [] {
        const Trajectory t = plan(Path::lin(A, B), good_set(), limits(0.1, 1, 10));
        OverlappedTrajectory(t, plan(Path::lin(C, B), good_set(), limits(0.1, 1, 10)), 0.1);
      },
      IA, "after = (0.1, 0.1, 0): must start where `before` ends");
  row(
      "Trajectory::stopped_at", "NaN time",
      [] { plan(Path::lin(A, B), good_set(), limits(0.1, 1, 10)).stopped_at(nan_); }, IA, "t = nan: must be finite");
  row(
      "Trajectory::with_override", "factor 0",
      [] { plan(Path::lin(A, B), good_set(), limits(0.1, 1, 10)).with_override(0.1, 0.0); }, IA,
      "factor = 0: must be in [0.001, 10]");
  row(
      "Trajectory::with_override", "NaN factor",
      [] { plan(Path::lin(A, B), good_set(), limits(0.1, 1, 10)).with_override(0.1, nan_); }, IA, "factor = nan");
  row(
      "Trajectory::resumed_at", "not stopped",
      [] { plan(Path::lin(A, B), good_set(), limits(0.1, 1, 10)).resumed_at(0.1); }, IA,
      "t = 0.1: resumes a stopped trajectory only");
  row(
      "Trajectory::stopped_at", "a re-timed law (limits unknown)",
      [] {
        const Trajectory t = plan(Path::lin(A, B), good_set(), limits(0.1, 1, 10));
        t.with_time_law(t.time_law()).stopped_at(0.1);
      },
      IA, "stopped_at: the trajectory holds no time-law limits");
}

}  // namespace bad_input
