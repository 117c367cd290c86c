// The rows of the C++ bad-input table (tests/cpp/test_bad_input_table.cpp) of one area: Pose.
#include "rows.hpp"

namespace bad_input {

void pose_rows(std::vector<Row>& table) {
  const RowAdder row{table};
  // --- Pose ---
  row(
      "Pose(quaternion, translation)", "NaN quaternion", [] { Posed(Quaterniond(nan_, 0, 0, 0), Vector3d::Zero()); },
      IA, "quaternion (w, x, y, z) = (nan, 0, 0, 0)");
  row(
      "Pose(quaternion, translation)", "+inf translation", [] { Posed(Quaterniond::Identity(), Vector3d(inf_, 0, 0)); },
      IA, "translation = (inf, 0, 0)");
  row(
      "Pose(quaternion, translation)", "-inf translation",
      [] { Posed(Quaterniond::Identity(), Vector3d(0, -inf_, 0)); }, IA, "translation = (0, -inf, 0)");
  row(
      "Pose(quaternion, translation)", "translation beyond the numeric range (1e13 m)",
      [] { Posed(Quaterniond::Identity(), Vector3d(0, 0, 1e13)); }, IA,
      "translation = (0, 0, 1e+13): must have coordinates within ±1e12 m");
  row(
      "Pose::from_xyzuvw", "X beyond the numeric range (1e300 m)",
      [] { Posed::from_xyzuvw((Eigen::Matrix<double, 6, 1>() << 1e300, 0, 0, 0, 0, 0).finished()); }, IA,
      "xyzuvw (X, Y, Z) = (1e+300, 0, 0): must have coordinates within ±1e12 m");
  row(
      "Pose(quaternion, translation)", "zero quaternion", [] { Posed(Quaterniond(0, 0, 0, 0), Vector3d::Zero()); }, IA,
      "quaternion (w, x, y, z) = (0, 0, 0, 0): must be a unit quaternion");
  row(
      "Pose(quaternion, translation)", "non-unit quaternion", [] { Posed(Quaterniond(2, 0, 0, 0), Vector3d::Zero()); },
      IA, "quaternion (w, x, y, z) = (2, 0, 0, 0): must be a unit quaternion");
  row(
      "Pose(rotation, translation)", "scaled rotation",
      [] { Posed(Eigen::Matrix3d(2 * Eigen::Matrix3d::Identity()), Vector3d::Zero()); }, IA,
      "rotation = (2, 0, 0, 0, 2, 0, 0, 0, 2): must be orthonormal with determinant +1");
  row(
      "Pose(rotation, translation)", "reflection (det -1)",
      [] { Posed(Eigen::Matrix3d(Vector3d(1, 1, -1).asDiagonal()), Vector3d::Zero()); }, IA,
      "rotation = (1, 0, 0, 0, 1, 0, 0, 0, -1): must be orthonormal with determinant +1");
  row(
      "Pose(rotation, translation)", "NaN rotation", [] { Posed(Eigen::Matrix3d::Constant(nan_), Vector3d::Zero()); },
      IA, "rotation = (nan, nan, nan");
  row(
      "Pose::from_matrix", "NaN entry",
      [] {
        Matrix4d m = Matrix4d::Identity();
        m(0, 3) = nan_;
        Posed::from_matrix(m);
      },
      IA, "matrix = (1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, nan, 0, 0, 1)");
  row(
      "Pose::from_matrix", "+inf entry",
      [] {
        Matrix4d m = Matrix4d::Identity();
        m(1, 1) = inf_;
        Posed::from_matrix(m);
      },
      IA, "matrix = (1, 0, 0, 0, 0, inf");
  row(
      "Pose::from_matrix", "bad last row",
      [] {
        Matrix4d m = Matrix4d::Identity();
        m(3, 3) = 2;
        Posed::from_matrix(m);
      },
      IA, "matrix last row = (0, 0, 0, 2)");
  row(
      "Pose::from_matrix", "scaled rotation",
      [] {
        Matrix4d m = 2 * Matrix4d::Identity();
        m(3, 3) = 1;
        Posed::from_matrix(m);
      },
      IA, "rotation = (2, 0, 0, 0, 2, 0, 0, 0, 2): must be orthonormal");
  row(
      "Pose::from_xyzuvw", "NaN", [] { Posed::from_xyzuvw(v6(0, 0, 0, nan_, 0, 0)); }, IA,
      "xyzuvw = (0, 0, 0, nan, 0, 0)");
  row(
      "Pose::from_xyzuvw", "+inf", [] { Posed::from_xyzuvw(v6(inf_, 0, 0, 0, 0, 0)); }, IA,
      "xyzuvw = (inf, 0, 0, 0, 0, 0)");
  row(
      "Pose::from_xyzuvw", "NaN pivot", [] { Posed::from_xyzuvw(Vector6d::Zero(), Vector3d(nan_, 0, 0)); }, IA,
      "pivot = (nan, 0, 0)");
  row(
      "Pose::to_xyzuvw", "NaN pivot", [] { B.to_xyzuvw(Vector3d(nan_, 0, 0)); }, IA, "pivot = (nan, 0, 0)");
  row(
      "Pose::to_xyzuvw", "-inf pivot", [] { B.to_xyzuvw(Vector3d(0, 0, -inf_)); }, IA, "pivot = (0, 0, -inf)");
  row(
      "Pose::rotated_about_pivot", "NaN pivot", [] { A.rotated_about_pivot(B, Vector3d(nan_, 0, 0)); }, IA,
      "pivot = (nan, 0, 0)");
  row(
      "Pose::rotated_about_pivot", "+inf pivot", [] { A.rotated_about_pivot(B, Vector3d(0, inf_, 0)); }, IA,
      "pivot = (0, inf, 0)");
}

}  // namespace bad_input
