// The rows of the C++ bad-input table (tests/cpp/test_bad_input_table.cpp) of one area: Path, JointPath and their
// sections.
#include "rows.hpp"

namespace bad_input {

void paths_rows(std::vector<Row>& table) {
  const RowAdder row{table};
  // --- Path / JointPath ---
  row(
      "Path::lin", "NaN pivot", [] { Path::lin(A, B, Interpolation::decoupled, Vector3d(nan_, 0, 0)); }, IA,
      "pivot = (nan, 0, 0)");
  // A LIN pivot of 6.3e257 m, beyond the numeric range, was once accepted and Path::sample
  // returned infinities.
  row(
      "Path::lin", "pivot beyond the numeric range (6.3e257 m)",
      [] { Path::lin(A, B, Interpolation::decoupled, Vector3d(117, 6.3e257, 117)); }, IA,
      "pivot = (117, 6.3e+257, 117): must have coordinates within ±1e12 m");
  row(
      "Path::lin", "coinciding poses", [] { Path::lin(A, A); }, IA, "b = (0, 0, 0): start and end poses coincide");
  row(
      "Path::circ", "collinear via",
      [] { Path::circ(A, Posed::from_xyzuvw(v6(0.05, 0, 0, 0, 0, 0)), Posed::from_xyzuvw(v6(0.1, 0, 0, 0, 0, 0))); },
      IA, "via = (0.05, 0, 0): is collinear with the start and end points");
  row(
      "Path::circ", "via 1e-9 m off the line, beyond the end",
      [] { Path::circ(A, Posed::from_xyzuvw(v6(0.2, 1e-9, 0, 0, 0, 0)), Posed::from_xyzuvw(v6(0.1, 0, 0, 0, 0, 0))); },
      IA,
      "via = (0.2, 1e-09, 0): is almost collinear with the start and end points and outside the segment between them");
  row(
      "Path::circ", "via equals start", [] { Path::circ(A, A, C); }, IA,
      "via = (0, 0, 0): coincides with the start point");
  row(
      "Path::circ", "zero tolerance", [] { Path::circ(A, B, C, Vector3d::Zero(), 0.0); }, IA, "tolerance = 0");
  row(
      "Path::circ", "negative tolerance", [] { Path::circ(A, B, C, Vector3d::Zero(), -1e-3); }, IA,
      "tolerance = -0.001");
  row(
      "Path::circ", "NaN tolerance", [] { Path::circ(A, B, C, Vector3d::Zero(), nan_); }, IA, "tolerance = nan");
  row(
      "Path::circ", "NaN pivot", [] { Path::circ(A, B, C, Vector3d(nan_, 0, 0)); }, IA, "pivot = (nan, 0, 0)");
  row(
      "Path::circ", "pivot beyond the numeric range (1e13 m)", [] { Path::circ(A, B, C, Vector3d(1e13, 0, 0)); }, IA,
      "pivot = (1e+13, 0, 0): must have coordinates within ±1e12 m");
  row(
      "Path::spline", "two poses",
      [] {
        Path::spline({A, B});
      },
      IA, "poses = 2: key poses given: a SPLINE needs at least three");
  row(
      "Path::spline", "repeated key pose",
      [] {
        Path::spline({A, B, B, C});
      },
      IA, "poses[2] = (0.1, 0, 0): coincides with the key pose before it");
  row(
      "Path::spline", "zero tolerance",
      [] {
        Path::spline({A, B, C}, Vector3d::Zero(), 0.0);
      },
      IA, "tolerance = 0");
  row(
      "Path::spline", "NaN pivot",
      [] {
        Path::spline({A, B, C}, Vector3d(nan_, 0, 0));
      },
      IA, "pivot = (nan, 0, 0)");
  row(
      "Path::spline", "pivot beyond the numeric range (1e13 m)",
      [] {
        Path::spline({A, B, C}, Vector3d(0, 0, -1e13));
      },
      IA, "pivot = (0, 0, -1e+13): must have coordinates within ±1e12 m");
  row(
      "Path::then (blend)", "negative blend", [] { Path::lin(A, B).then(Path::lin(B, C), -0.01); }, IA,
      "before = -0.01: must be a positive distance");
  row(
      "Path::then (blend)", "NaN after", [] { Path::lin(A, B).then(Path::lin(B, C), 0.01, nan_); }, IA,
      "after = nan: must be a positive distance");
  row(
      "Path::then (blend)", "blend over half the next move", [] { Path::lin(A, B).then(Path::lin(B, C), 0.01, 0.08); },
      IA, "after = 0.08: exceeds half of the move after the via point");
  row(
      "Path::then (blend)", "not joining", [] { Path::lin(A, B).then(Path::lin(C, B), 0.01); }, IA,
      "next = (0.1, 0.1, 0): must start where the path ends");
  row(
      "Path::then", "discontinuous join",
      [] {
        Path p = Path::lin(A, B);
        p.then(Path::lin(C, A));
      },
      IA, "next = (0.1, 0.1, 0): must start where the path ends");
  row(
      "Path::section_lengths", "empty set", [] { Path::lin(A, B).section_lengths(MetricSetd()); }, IA,
      "metric_set = \"MetricSet\": is not well-formed");
  row(
      "Path::sample", "NaN u", [] { (void)Path::lin(A, B).sample(nan_); }, IA, "u = nan",
      "returns the start pose (noexcept; NaN treated as u <= 0)");
  row(
      "Path::sample", "u above 1", [] { (void)Path::lin(A, B).sample(1.5); }, IA, "u = 1.5",
      "clamped to the end pose (documented: \"Clamped outside\")");
  row(
      "Path::sample", "-inf u", [] { (void)Path::lin(A, B).sample(-inf_); }, IA, "u = -inf",
      "clamped to the start pose (documented: \"Clamped outside\")");
  row(
      "JointPath", "NaN joint", [] { JointPath(Eigen::Vector2d(0, nan_), Eigen::Vector2d(0, 1)); }, IA,
      "q_start = (0, nan): must be finite");
  row(
      "JointPath", "size mismatch", [] { JointPath(Eigen::VectorXd::Zero(2), Eigen::VectorXd::Zero(3)); }, IA,
      "q_end size = 3");
  row(
      "JointPath", "empty", [] { JointPath(Eigen::VectorXd(), Eigen::VectorXd()); }, IA,
      "q_start = 0: must have at least one joint");
  row(
      "JointPath::sample", "NaN u", [] { JointPath(Eigen::Vector2d(0, 0), Eigen::Vector2d(1, 1)).sample(nan_); }, IA,
      "u = nan", "returns (nan, nan) (the Python binding rejects it: u = nan: must be finite)");
  row(
      "max_point_speed", "+inf twist",
      [] { (void)max_point_speed(good_set(), A, Twistd(Vector3d(inf_, 0, 0), Vector3d::Zero())); }, IA, "twist");
  row(
      "JointPath::sample", "u above 1", [] { JointPath(Eigen::Vector2d(0, 0), Eigen::Vector2d(1, 1)).sample(2.0); }, IA,
      "u = 2", "clamped, returns (1, 1) (documented: \"u clamped to [0, 1]\")");
}

}  // namespace bad_input
