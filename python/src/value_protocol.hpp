// What makes a binding's value type behave like a Python value: unpacking pickled states,
// math.isclose-style comparisons and hashing of floats.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <string>

#include <pybind11/pybind11.h>

#include "conversions.hpp"
#include "dispkin/error.hpp"

namespace dispkin {
namespace python {

//! `state` as a tuple of `size` items; ValueError naming the type otherwise (a pickle of another
//! version of dispkin, or a hand-made state).
inline py::tuple state_tuple(const py::handle& state, std::size_t size, const std::string& type) {
  if (!py::isinstance<py::tuple>(state) || py::len(state) != size) {
    throw py::value_error(type + ".__setstate__: state: expected a tuple of " + std::to_string(size) + " items, got " +
                          std::string(py::repr(state)));
  }
  return state.cast<py::tuple>();
}

//! The tolerances of an isclose method: finite and not negative, as math.isclose requires.
inline void require_tolerances(double rel_tol, double abs_tol) {
  require(std::isfinite(rel_tol) && rel_tol >= 0.0, "rel_tol", rel_tol, "must be finite and not negative");
  require(std::isfinite(abs_tol) && abs_tol >= 0.0, "abs_tol", abs_tol, "must be finite and not negative");
}

//! math.isclose(a, b, rel_tol, abs_tol): |a − b| ≤ max(rel_tol · max(|a|, |b|), abs_tol).
inline bool isclose(double a, double b, double rel_tol, double abs_tol) {
  if (a == b) return true;  // infinities of the same sign too
  return std::abs(a - b) <= std::max(rel_tol * std::max(std::abs(a), std::abs(b)), abs_tol);
}

//! isclose for every coefficient of two arrays of the same size.
template <typename A, typename B>
bool all_close(const A& a, const B& b, double rel_tol, double abs_tol) {
  if (a.size() != b.size()) return false;
  for (Eigen::Index i = 0; i < a.size(); ++i)
    if (!isclose(a.coeff(i), b.coeff(i), rel_tol, abs_tol)) return false;
  return true;
}

//! Python's hash of a tuple of the given floats (equal values hash equally, 0.0 and −0.0 too).
template <typename... Floats>
py::ssize_t hash_floats(Floats... values) {
  return py::hash(py::make_tuple(values...));
}

}  // namespace python
}  // namespace dispkin
