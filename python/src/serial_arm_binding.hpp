// The pieces of the SerialArm binding, one source per subject: bind_serial.cpp (the arm model:
// joints, limits, forward kinematics, Jacobians, dynamics), bind_serial_inverse.cpp (inverse
// kinematics and the redundancy parameter), bind_serial_following.cpp (joints along poses and
// trajectories); and the argument conversions they share (serial_arguments.cpp).
#pragma once

#include <string>
#include <vector>

#include <Eigen/Core>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include "conversions.hpp"
#include "dispkin/pose.hpp"
#include "dispkin/serial/serial_arm.hpp"

namespace dispkin {
namespace python {

//! A Pose or a (4, 4) matrix; `name` names it in the error.
Posed pose_of(const py::handle& obj, const std::string& name);
//! A joint vector: shape (n,); its length is checked by the C++ call, which knows n.
Eigen::VectorXd joint_vector(const py::handle& obj, const std::string& name);
//! Joint vectors: an (N, n) array or a list of (n,) arrays.
std::vector<Eigen::VectorXd> joint_vectors(const py::handle& obj, const std::string& name);
//! A (N, columns) array, its shape checked.
Array rows_of(const py::handle& obj, const std::string& name, py::ssize_t columns);
//! Sample times: an (N,) array.
std::vector<double> times_of(const py::handle& obj, const std::string& name);

py::array_t<double> to_vector_array(const Eigen::VectorXd& v);
//! Joint vectors as a list of (n,) arrays.
py::list to_list(const std::vector<Eigen::VectorXd>& solutions);
//! Solutions as the rows of a (k, n) array ((0, n) when there are none).
py::array_t<double> solution_rows(const std::vector<Eigen::VectorXd>& solutions, int n);
//! A matrix as a row-major (rows, cols) array.
py::array_t<double> to_rows(const Eigen::MatrixXd& m);

//! InverseResult and Redundancy (bind_serial_inverse.cpp).
void bind_inverse_result(py::module_& m);
//! SerialArm's inverse kinematics: inverse, inverse_many, inverse_solutions, nearest.
void def_inverse_kinematics(py::class_<serial::SerialArm>& arm);
//! SerialArm's joints along poses and trajectories: follow, joint_velocities,
//! follow_trajectory, check_joint_limits (bind_serial_following.cpp).
void def_following(py::class_<serial::SerialArm>& arm);

}  // namespace python
}  // namespace dispkin
