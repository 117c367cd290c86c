// Python binding of dispkin/pose.hpp: Pose (twists are (6,) arrays (v, ω)).
#include <cmath>
#include <string>
#include <vector>

#include <pybind11/eigen.h>
#include <pybind11/pybind11.h>

#include "bindings.hpp"
#include "conversions.hpp"
#include "interpreter_lock.hpp"
#include "value_protocol.hpp"
#include "dispkin/error.hpp"
#include "dispkin/pose.hpp"

namespace dispkin {
namespace python {

namespace {

using Vector6d = Eigen::Matrix<double, 6, 1>;

Posed make_pose(const py::object& quaternion, const py::object& translation) {
  const Eigen::Vector4d q = vector<4>(quaternion, "quaternion");
  require_finite(q, "quaternion");  // here, so the message shows (w, x, y, z) as the user wrote it
  return Posed(Eigen::Quaterniond(q(0), q(1), q(2), q(3)), vector3(translation, "translation"));
}

Eigen::Vector4d wxyz(const Posed& pose) {
  const Eigen::Quaterniond& q = pose.quaternion();
  return Eigen::Vector4d(q.w(), q.x(), q.y(), q.z());
}

// The same transform: q and −q are the same rotation (their matrices agree bit for bit).
bool same_pose(const Posed& a, const Posed& b) {
  const Eigen::Vector4d qa = wxyz(a), qb = wxyz(b);
  return a.translation() == b.translation() && (qa == qb || qa == -qb);
}

// The quaternion with the sign that makes its first non-zero coefficient positive, so that q and
// −q hash alike.
Eigen::Vector4d canonical_wxyz(const Posed& pose) {
  const Eigen::Vector4d q = wxyz(pose);
  for (int i = 0; i < 4; ++i)
    if (q(i) != 0.0) return q(i) < 0.0 ? Eigen::Vector4d(-q) : q;
  return q;
}

// The state of a pickled Pose: the quaternion (w, x, y, z) and the translation as stored, so
// that the copy is the same bit for bit (no normalisation on the way back).
py::tuple pose_state(const Posed& pose) {
  const Eigen::Vector4d q = wxyz(pose);
  const Eigen::Vector3d& t = pose.translation();
  return py::make_tuple(py::make_tuple(q(0), q(1), q(2), q(3)), py::make_tuple(t(0), t(1), t(2)));
}

Posed pose_from_state(const py::object& state) {
  const py::tuple s = state_tuple(state, 2, "Pose");
  const Eigen::Vector4d q = state_vector<4>(s[0], StateField("Pose", 0, "quaternion (w, x, y, z)"));
  const Eigen::Vector3d t = state_vector<3>(s[1], StateField("Pose", 1, "translation"));
  return Posed::from_stored(Eigen::Quaterniond(q(0), q(1), q(2), q(3)), t);
}

}  // namespace

// Poses from a quaternion and translation, a matrix, XYZUVW about a pivot, a twist.
void def_pose_construction(py::class_<Posed>& pose) {
  const py::tuple origin = py::make_tuple(0.0, 0.0, 0.0);
  pose.def(py::init(&make_pose), py::arg_v("quaternion", py::make_tuple(1.0, 0.0, 0.0, 0.0), "(1, 0, 0, 0)"),
           py::arg_v("translation", origin, "(0, 0, 0)"),
           "Pose from a unit quaternion (w, x, y, z) (normalised if within 1e-6 of unit norm) and a "
           "translation (x, y, z) in metres. The defaults give the identity.")
      .def_static(
          "from_matrix", [](const py::object& matrix) { return Posed::from_matrix(matrix4(matrix, "matrix")); },
          py::arg("matrix"),
          "Pose from a homogeneous (4, 4) matrix [R t; 0 0 0 1] (R orthonormal to 1e-6, t in metres).")
      .def_static(
          "from_xyzuvw",
          [](const py::object& xyzuvw, const py::object& pivot) {
            return Posed::from_xyzuvw(vector<6>(xyzuvw, "xyzuvw"), vector3(pivot, "pivot"));
          },
          py::arg("xyzuvw"), py::arg_v("pivot", origin, "(0, 0, 0)"),
          "Pose from (X, Y, Z, U, V, W): metres and radians, R = Rx(U) Ry(V) Rz(W) (moving axes), the "
          "rotation acting about `pivot` (body coordinates, metres): x_w = R (x_b - p) + p + (X, Y, Z).")
      .def_static(
          "exp",
          [](const py::object& twist) {
            const Vector6d xi = vector<6>(twist, "twist");
            require_finite(xi, "twist");
            return Posed::exp(Twistd(xi));
          },
          py::arg("twist"),
          "SE(3) exponential of a body twist (v, ω) (metres, radians): the pose reached after unit "
          "time at that constant twist.")
      .def(
          "log", [](const Posed& self) { return self.log().vector(); },
          "SE(3) logarithm: the (6,) body twist (v, ω) with Pose.exp(twist) == self, rotation angle "
          "in [0, π].");
}

// A pose in the coordinates users give: matrix, rotation, quaternion, translation, XYZUVW.
void def_pose_coordinates(py::class_<Posed>& pose) {
  const py::tuple origin = py::make_tuple(0.0, 0.0, 0.0);
  pose.def("matrix", &Posed::matrix, "The homogeneous (4, 4) matrix [R t; 0 0 0 1] (metres).")
      .def("rotation", &Posed::rotation, "The (3, 3) rotation matrix R (body to world).")
      .def_property_readonly("quaternion", &wxyz, "The unit quaternion (w, x, y, z) of R, as a (4,) array.")
      .def_property_readonly(
          "translation", [](const Posed& self) { return to_array(self.translation()); },
          "The translation t in metres (world position of the body origin), as a (3,) array.")
      .def(
          "to_xyzuvw",
          [](const Posed& self, const py::object& pivot) {
            const Eigen::Vector3d p = vector3(pivot, "pivot");
            require_finite(p, "pivot");  // to_xyzuvw itself does not check (it is noexcept-style)
            return self.to_xyzuvw(p);
          },
          py::arg_v("pivot", origin, "(0, 0, 0)"),
          "(X, Y, Z, U, V, W) as a (6,) array, the inverse of from_xyzuvw for the same pivot: U, W in "
          "(-π, π], V in [-π/2, π/2]; at gimbal lock (V = ±π/2) W = 0 and U carries the rotation.");
}

// Composition, the inverse, points transformed, a rotation about a pivot.
void def_pose_algebra(py::class_<Posed>& pose) {
  pose.def("inverse", &Posed::inverse, "The inverse transform (world to body).")
      .def(
          "__mul__", [](const Posed& self, const Posed& other) { return self * other; }, py::is_operator(),
          "Composition: (a * b) maps x to a(b(x)).")
      .def(
          "transform",
          [](const Posed& self, const py::object& points_in) -> py::object {
            const Array a = as_array(points_in, "points", "an array of shape (3,) or (N, 3)");
            std::vector<Eigen::Vector3d> pts = points(a, "points", true);
            {
              const UnlockedIf unlocked(worth_releasing(pts.size(), point_transform_ns));
              for (std::size_t i = 0; i < pts.size(); ++i) {
                require_finite(pts[i], "points[" + std::to_string(i) + "]");
                pts[i] = self * pts[i];
              }
            }
            if (a.ndim() == 1) return to_array(pts.front());
            return to_array(pts);
          },
          py::arg("points"),
          "Map points from body to world coordinates (metres): a (3,) array or the rows of an (N, 3) "
          "array; returns the same shape.")
      .def(
          "rotated_about_pivot",
          [](const Posed& self, const Posed& orientation, const py::object& pivot) {
            return self.rotated_about_pivot(orientation, vector3(pivot, "pivot"));
          },
          py::arg("orientation"), py::arg("pivot"),
          "The pose with the orientation of `orientation` whose body point `pivot` (body coordinates, "
          "metres) stays where it is in world: a rotation commanded about a pivot.");
}

// Comparison: within a tolerance, exactly (== and hash), isclose.
void def_pose_comparison(py::class_<Posed>& pose) {
  pose.def(
          "is_approx",
          [](const Posed& self, const Posed& other, double tol) {
            require(std::isfinite(tol) && tol >= 0.0, "tol", tol, "must be finite and not negative");
            return self.is_approx(other, tol);
          },
          py::arg("other"), py::arg("tol") = 1e-9,
          "Whether `other` is the same transform to within `tol` (rotation-matrix entries, and "
          "translation in metres per coordinate).")
      .def(
          "__eq__", [](const Posed& self, const Posed& other) { return same_pose(self, other); }, py::is_operator(),
          "The same transform, exactly: equal translations and equal quaternions up to sign (q and -q are one "
          "rotation). Use isclose for poses computed in different ways.")
      .def("__hash__",
           [](const Posed& self) {
             const Eigen::Vector4d q = canonical_wxyz(self);
             const Eigen::Vector3d& t = self.translation();
             return hash_floats(q(0), q(1), q(2), q(3), t(0), t(1), t(2));
           })
      .def(
          "isclose",
          [](const Posed& self, const Posed& other, double rel_tol, double abs_tol) {
            require_tolerances(rel_tol, abs_tol);
            return all_close(self.translation(), other.translation(), rel_tol, abs_tol) &&
                   all_close(Eigen::Matrix3d(self.rotation()), Eigen::Matrix3d(other.rotation()), rel_tol, abs_tol);
          },
          py::arg("other"), py::kw_only(), py::arg("rel_tol") = 1e-9, py::arg("abs_tol") = 0.0,
          "math.isclose for every coordinate: each translation coordinate (m) and each rotation-matrix "
          "entry agree within max(rel_tol * larger magnitude, abs_tol). Entries near 0 need abs_tol.");
}

void bind_pose(py::module_& m) {
  py::class_<Posed> pose(m, "Pose", R"doc(
A rigid transform T = (R, t) in SE(3), mapping body (tool) coordinates to world coordinates:
x_world = R x_body + t. Stored as a unit quaternion and a translation in metres; immutable.
Twists are (6,) arrays (v, ω): body velocity in m/s (or m per unit parameter) and angular
velocity in rad/s, both in body coordinates.)doc");
  def_pose_construction(pose);
  def_pose_coordinates(pose);
  def_pose_algebra(pose);
  def_pose_comparison(pose);
  pose.def("__repr__", [](const Posed& self) {
    return "Pose(quaternion=" + tuple_repr(wxyz(self)) + ", translation=" + tuple_repr(self.translation()) + ")";
  });
  def_pickle(pose, "Pose", &pose_state, &pose_from_state);
}

}  // namespace python
}  // namespace dispkin
