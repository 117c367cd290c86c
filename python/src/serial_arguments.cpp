// Argument conversions of the SerialArm binding (serial_arm_binding.hpp): joint vectors are (n,)
// arrays, poses are Pose or (4, 4) arrays, sampled joints are the rows of (N, n) arrays.
#include <string>
#include <vector>

#include "serial_arm_binding.hpp"

namespace dispkin {
namespace python {

// A Pose or a (4, 4) matrix. A Pose is read as it is, and so is a contiguous float64 array, C
// or Fortran order (Pose.matrix() gives the latter), without a converted copy; anything else
// goes through numpy's conversion.
Posed pose_of(const py::handle& obj, const std::string& name) {
  if (py::isinstance<Posed>(obj)) return obj.cast<const Posed&>();
  if (py::array_t<double>::check_(obj)) {
    const auto a = py::reinterpret_borrow<py::array>(obj);
    if (a.ndim() == 2 && a.shape(0) == 4 && a.shape(1) == 4) {
      const auto* data = static_cast<const double*>(a.data());
      if (a.flags() & py::array::c_style)
        return Posed::from_matrix(Eigen::Map<const Eigen::Matrix<double, 4, 4, Eigen::RowMajor>>(data));
      if (a.flags() & py::array::f_style) return Posed::from_matrix(Eigen::Map<const Eigen::Matrix4d>(data));
    }
  }
  return Posed::from_matrix(matrix4(obj, name));
}

// Solutions as the rows of a (k, n) array ((0, n) when there are none).
py::array_t<double> solution_rows(const std::vector<Eigen::VectorXd>& solutions, int n) {
  py::array_t<double> out({static_cast<py::ssize_t>(solutions.size()), static_cast<py::ssize_t>(n)});
  double* data = out.mutable_data();
  for (const Eigen::VectorXd& q : solutions) {
    Eigen::Map<Eigen::VectorXd>(data, n) = q;
    data += n;
  }
  return out;
}

// A joint vector: shape (n,); its length is checked by the C++ call, which knows n.
Eigen::VectorXd joint_vector(const py::handle& obj, const std::string& name) {
  const std::string expected = "an array of shape (n,)";
  const Array a = as_array(obj, name, expected);
  if (a.ndim() != 1) wrong_shape(name, expected, a);
  return Eigen::Map<const Eigen::VectorXd>(a.data(), a.shape(0));
}

py::array_t<double> to_vector_array(const Eigen::VectorXd& v) {
  py::array_t<double> out(py::ssize_t{v.size()});
  Eigen::Map<Eigen::VectorXd>(out.mutable_data(), v.size()) = v;
  return out;
}

py::list to_list(const std::vector<Eigen::VectorXd>& solutions) {
  py::list out;
  for (const Eigen::VectorXd& q : solutions) out.append(to_vector_array(q));
  return out;
}

std::vector<Eigen::VectorXd> joint_vectors(const py::handle& obj, const std::string& name) {
  std::vector<Eigen::VectorXd> out;
  if (py::isinstance<py::array>(obj)) {
    const Array a = as_array(obj, name, "an array of shape (N, n)");
    if (a.ndim() != 2) wrong_shape(name, "an array of shape (N, n) or a list of (n,) arrays", a);
    for (py::ssize_t i = 0; i < a.shape(0); ++i)
      out.push_back(Eigen::Map<const Eigen::VectorXd>(a.data() + i * a.shape(1), a.shape(1)));
    return out;
  }
  if (!py::isinstance<py::sequence>(obj)) throw py::value_error(name + ": expected a list of (n,) arrays");
  std::size_t k = 0;
  for (const py::handle item : obj.cast<py::sequence>())
    out.push_back(joint_vector(item, name + "[" + std::to_string(k++) + "]"));
  return out;
}

// A (N, columns) array as its rows.
Array rows_of(const py::handle& obj, const std::string& name, py::ssize_t columns) {
  const std::string expected = "an array of shape (N, " + std::to_string(columns) + ")";
  Array a = as_array(obj, name, expected);
  if (a.ndim() != 2 || a.shape(1) != columns) wrong_shape(name, expected, a);
  return a;
}

std::vector<double> times_of(const py::handle& obj, const std::string& name) {
  const Array a = as_array(obj, name, "an array of shape (N,)");
  if (a.ndim() != 1) wrong_shape(name, "an array of shape (N,)", a);
  return std::vector<double>(a.data(), a.data() + a.shape(0));
}

py::array_t<double> to_rows(const Eigen::MatrixXd& m) {
  py::array_t<double> out({static_cast<py::ssize_t>(m.rows()), static_cast<py::ssize_t>(m.cols())});
  Eigen::Map<Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>(out.mutable_data(), m.rows(),
                                                                                     m.cols()) = m;
  return out;
}

}  // namespace python
}  // namespace dispkin
