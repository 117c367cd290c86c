// numpy <-> Eigen conversions shared by the binding sources. They check shapes only; values
// (finiteness, unit norms, signs) are checked by the C++ library, whose std::invalid_argument
// pybind11 raises as ValueError.
#pragma once

#include <algorithm>
#include <cstddef>
#include <iterator>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <dispkin/error.hpp>
#include <dispkin/metric_set.hpp>
#include <dispkin/profile.hpp>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

namespace dispkin {
namespace python {

namespace py = pybind11;

//! A C-contiguous float64 view of whatever numpy can turn into numbers.
using Array = py::array_t<double, py::array::c_style | py::array::forcecast>;

//! Python's spelling of an array shape: "(4, 2)", "(3,)", "()".
inline std::string shape_string(const py::array& a) {
  std::string out = "(";
  for (py::ssize_t i = 0; i < a.ndim(); ++i) {
    if (i > 0) out += ", ";
    out += std::to_string(a.shape(i));
  }
  if (a.ndim() == 1) out += ",";
  return out + ")";
}

//! `obj` as a float64 array; ValueError "<name>: expected <expected>, got ..." if numpy cannot
//! read it as numbers.
inline Array as_array(const py::handle& obj, const std::string& name, const std::string& expected) {
  Array a = Array::ensure(obj);
  if (!a) {
    throw py::value_error(name + ": expected " + expected + " of numbers, got " +
                          std::string(py::str(py::type::handle_of(obj).attr("__name__"))));
  }
  return a;
}

[[noreturn]] inline void wrong_shape(const std::string& name, const std::string& expected, const py::array& a) {
  throw py::value_error(name + ": expected " + expected + ", got shape " + shape_string(a));
}

//! Python's spelling of a tuple of sizes (a shape, strides): "(4, 4)", "(6,)", "()".
template <typename Sizes>
std::string sizes_string(const Sizes& sizes) {
  std::string out = "(";
  for (auto it = std::begin(sizes); it != std::end(sizes); ++it)
    out += (it != std::begin(sizes) ? ", " : "") + std::to_string(*it);
  return out + (std::size(sizes) == 1 ? ",)" : ")");
}

//! Whether `a` has exactly the shape `shape`.
template <typename Shape>
bool has_shape(const py::array& a, const Shape& shape) {
  return static_cast<std::size_t>(a.ndim()) == std::size(shape) &&
         std::equal(std::begin(shape), std::end(shape), a.shape());
}

//! `obj` as a preallocated array that results are written into: a writeable C-contiguous float64
//! numpy array of one of the shapes `shapes` (the same array, not a copy). Otherwise ValueError
//! "<name>: expected a writeable C-contiguous float64 array of shape S, got ..." naming what `obj`
//! is: its type, dtype, shape, strides, or that it is read-only. Allocates nothing unless it
//! refuses, so a control loop can pass the same array at every cycle.
template <typename... Shapes>
py::array output_array(const py::handle& obj, const char* name, const Shapes&... shapes) {
  const auto refuse = [&](const std::string& got) {
    std::string expected;
    ((expected += (expected.empty() ? "" : " or ") + sizes_string(shapes)), ...);
    throw py::value_error(std::string(name) + ": expected a writeable C-contiguous float64 array of shape " + expected +
                          ", got " + got);
  };
  if (!py::isinstance<py::array>(obj)) refuse(std::string(py::str(py::type::handle_of(obj).attr("__name__"))));
  const auto a = py::reinterpret_borrow<py::array>(obj);
  if (!a.dtype().equal(py::dtype::of<double>())) refuse("dtype " + std::string(py::str(a.dtype())));
  if (!(has_shape(a, shapes) || ...)) refuse("shape " + shape_string(a));
  if (!(a.flags() & py::array::c_style)) {
    refuse("a non-contiguous array (strides " +
           sizes_string(std::vector<py::ssize_t>(a.strides(), a.strides() + a.ndim())) + ")");
  }
  if (!a.writeable()) refuse("a read-only array");
  return a;
}

//! A fixed-size vector (shape (n,)), e.g. a point (3,), a quaternion (4,) or a twist (6,).
template <int N>
Eigen::Matrix<double, N, 1> vector(const py::handle& obj, const std::string& name) {
  const std::string expected = "an array of shape (" + std::to_string(N) + ",)";
  const Array a = as_array(obj, name, expected);
  if (a.ndim() != 1 || a.shape(0) != N) wrong_shape(name, expected, a);
  return Eigen::Map<const Eigen::Matrix<double, N, 1>>(a.data());
}

inline Eigen::Vector3d vector3(const py::handle& obj, const std::string& name) { return vector<3>(obj, name); }

//! A 4×4 matrix.
inline Eigen::Matrix4d matrix4(const py::handle& obj, const std::string& name) {
  const std::string expected = "an array of shape (4, 4)";
  const Array a = as_array(obj, name, expected);
  if (a.ndim() != 2 || a.shape(0) != 4 || a.shape(1) != 4) wrong_shape(name, expected, a);
  return Eigen::Map<const Eigen::Matrix<double, 4, 4, Eigen::RowMajor>>(a.data());
}

//! Points as rows of an (N, 3) array; with `allow_single` a (3,) array is one point.
inline std::vector<Eigen::Vector3d> points(const py::handle& obj, const std::string& name, bool allow_single) {
  const std::string expected = allow_single ? "an array of shape (3,) or (N, 3)" : "an array of shape (N, 3)";
  const Array a = as_array(obj, name, expected);
  const bool single = allow_single && a.ndim() == 1 && a.shape(0) == 3;
  if (!single && (a.ndim() != 2 || a.shape(1) != 3)) wrong_shape(name, expected, a);
  const std::size_t n = single ? 1 : static_cast<std::size_t>(a.shape(0));
  std::vector<Eigen::Vector3d> out(n);
  for (std::size_t i = 0; i < n; ++i) out[i] = Eigen::Map<const Eigen::Vector3d>(a.data() + 3 * i);
  return out;
}

//! Points as an (N, 3) float64 array.
inline py::array_t<double> to_array(const std::vector<Eigen::Vector3d>& pts) {
  py::array_t<double> out({static_cast<py::ssize_t>(pts.size()), py::ssize_t{3}});
  double* data = out.mutable_data();
  for (std::size_t i = 0; i < pts.size(); ++i) Eigen::Map<Eigen::Vector3d>(data + 3 * i) = pts[i];
  return out;
}

//! A metric group's points as an (N, 3) float64 array.
inline py::array_t<double> to_array(const dispkin::PointColumns<double>& pts) {
  py::array_t<double> out({static_cast<py::ssize_t>(pts.size()), py::ssize_t{3}});
  double* data = out.mutable_data();
  for (std::size_t i = 0; i < pts.size(); ++i) Eigen::Map<Eigen::Vector3d>(data + 3 * i) = pts[i];
  return out;
}

//! A (3,) float64 array.
inline py::array_t<double> to_array(const Eigen::Vector3d& p) {
  py::array_t<double> out(py::ssize_t{3});
  Eigen::Map<Eigen::Vector3d>(out.mutable_data()) = p;
  return out;
}

//! The repr of a float as Python writes it (shortest round-trip form).
// The one spelling of a profile kind in Python: "scurve" or "trapezoid" (argument `profile`).
inline ProfileKind profile_kind(const std::string& name) {
  if (name == "scurve") return ProfileKind::scurve;
  if (name == "trapezoid") return ProfileKind::trapezoid;
  throw std::invalid_argument(describe("profile", name, "must be \"scurve\" or \"trapezoid\""));
}
inline const char* profile_name(ProfileKind kind) { return kind == ProfileKind::scurve ? "scurve" : "trapezoid"; }

inline std::string float_repr(double x) { return std::string(py::repr(py::float_(x))); }

//! "(a, b, c)" with each coefficient as Python writes it.
template <typename Derived>
std::string tuple_repr(const Eigen::DenseBase<Derived>& v) {
  std::string out = "(";
  for (Eigen::Index i = 0; i < v.size(); ++i) {
    if (i > 0) out += ", ";
    out += float_repr(v.derived().coeff(i));
  }
  return out + ")";
}

}  // namespace python
}  // namespace dispkin
