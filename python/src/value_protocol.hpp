// What makes a binding's value type behave like a Python value: unpacking pickled states,
// math.isclose-style comparisons and hashing of floats.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <optional>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>

#include <pybind11/pybind11.h>

#include "conversions.hpp"
#include "dispkin/error.hpp"

namespace dispkin {
namespace python {

//! Where a value sits in a pickled state, for messages in the house format
//! "Trajectory.__setstate__: state[2] (time_law.pieces[4].start_s) = 0.5: <reason>": the type,
//! the item of the state's tuple, and the field's name inside that item.
class StateField {
 public:
  StateField(std::string type, std::size_t index, std::string name)
      : type_(std::move(type)), index_(index), name_(std::move(name)) {}
  //! A field inside this one: `sub` is appended to the name (".start", "[3]").
  StateField operator/(const std::string& sub) const { return StateField(type_, index_, name_ + sub); }
  StateField at(std::size_t k) const { return *this / ("[" + std::to_string(k) + "]"); }
  const std::string& type() const noexcept { return type_; }
  std::string argument() const {
    return type_ + ".__setstate__: state[" + std::to_string(index_) + "] (" + name_ + ")";
  }
  //! "<argument> = <repr of value>: <reason>".
  std::string message(const py::handle& value, const std::string& reason) const {
    return argument() + " = " + shown(value) + ": " + reason;
  }

  //! The repr of a value, or its type's name where repr fails (an instance made by __new__
  //! alone has no value to show).
  static std::string shown(const py::handle& value) {
    try {
      return echoed(std::string(py::repr(value)));
    } catch (const py::error_already_set&) {
      return "<" + std::string(py::str(py::type::handle_of(value).attr("__name__"))) + " without a value>";
    }
  }

 private:
  std::string type_;
  std::size_t index_;
  std::string name_;
};

namespace detail {

//! Whether `self` already holds its C++ value: made by a constructor or an earlier unpickling, or
//! a reference to a C++ value (an item of a result's list). pybind11's own test for a second
//! __init__: the instance is registered once it has a value.
template <typename T>
bool holds_value(const py::handle& self) {
  auto* instance = reinterpret_cast<py::detail::instance*>(self.ptr());
  return instance->get_value_and_holder(py::detail::get_type_info(typeid(T))).instance_registered();
}

//! What a state item of type T must be, as a Python user reads it.
template <typename T>
std::string expected_python_type() {
  if constexpr (std::is_same_v<T, bool>) {
    return "a bool";
  } else if constexpr (std::is_integral_v<T>) {
    return "an int";
  } else if constexpr (std::is_floating_point_v<T>) {
    return "a float";
  } else if constexpr (std::is_same_v<T, std::string>) {
    return "a str";
  } else if constexpr (std::is_same_v<T, std::optional<double>>) {
    return "a float or None";
  } else if constexpr (std::is_base_of_v<Eigen::EigenBase<T>, T>) {
    return "a sequence of floats";
  } else if constexpr (std::is_same_v<T, std::vector<bool>>) {
    return "a list of bools";
  } else {
    // A bound class: its Python name (pybind11's own message shows '?' for these).
    return "a " + std::string(py::str(py::type::of<T>().attr("__name__")));
  }
}

}  // namespace detail

//! The value at `where` as a T; TypeError naming the field and the value otherwise (pybind11's
//! own cast_error names neither).
template <typename T>
T state_cast(const py::handle& item, const StateField& where) {
  // bool is an int to Python: an index or a count given as True is a mistake, not a 1.
  if constexpr (std::is_integral_v<T> && !std::is_same_v<T, bool>) {
    if (!py::isinstance<py::int_>(item) || py::isinstance<py::bool_>(item))
      throw py::type_error(where.message(item, "must be " + detail::expected_python_type<T>()));
  }
  if constexpr (!std::is_arithmetic_v<T> && !std::is_same_v<T, std::string> &&
                !std::is_same_v<T, std::optional<double>> && !std::is_base_of_v<Eigen::EigenBase<T>, T> &&
                !std::is_same_v<T, std::vector<bool>>) {
    // A bound class: an instance made by __new__ alone has no value to copy.
    if (py::isinstance<T>(item) && !detail::holds_value<T>(item))
      throw py::type_error(where.message(item, "must be " + detail::expected_python_type<T>() + " that holds a value"));
  }
  try {
    return item.cast<T>();
  } catch (const py::cast_error&) {
    throw py::type_error(where.message(item, "must be " + detail::expected_python_type<T>()));
  } catch (const py::reference_cast_error&) {
    // None, or an instance without a value, for a bound class. pybind11's dispatcher would take
    // this exception for "try the next overload" and say only that the arguments do not fit.
    throw py::type_error(where.message(item, "must be " + detail::expected_python_type<T>()));
  }
}

//! Item `index` of a state tuple as a T (state_cast): `state_item<double>(s, 3, "Profile", "distance")`.
template <typename T>
T state_item(const py::tuple& state, std::size_t index, const std::string& type, const std::string& field) {
  return state_cast<T>(state[index], StateField(type, index, field));
}

//! `make()`, with what the C++ checks refuse (std::invalid_argument "<field> = <value>: <reason>")
//! raised as ValueError "<argument of where> <field> = …": for an object inside a state, whose
//! own checks name fields of its own.
template <typename Make>
auto inside(const StateField& where, Make make) {
  try {
    return make();
  } catch (const std::invalid_argument& e) {
    throw py::value_error(where.argument() + " " + e.what());
  }
}

//! A finite float at `where`: TypeError if it is no number, ValueError if NaN or infinite.
inline double state_number(const py::handle& item, const StateField& where) {
  const double x = state_cast<double>(item, where);
  if (!std::isfinite(x)) throw py::value_error(where.message(item, "must be finite"));
  return x;
}

//! An index or count at `where`: an int in [0, limit]; TypeError / ValueError naming it otherwise.
inline std::size_t state_count(const py::handle& item, const StateField& where, std::size_t limit) {
  const long long x = state_cast<long long>(item, where);
  if (x < 0 || static_cast<unsigned long long>(x) > limit)
    throw py::value_error(where.message(item, "must be in [0, " + std::to_string(limit) + "]"));
  return static_cast<std::size_t>(x);
}

//! A vector of N floats (N = Eigen::Dynamic: any number) at `where`, from a tuple, list or 1-d
//! array: TypeError if it is none of these or holds no numbers, ValueError if its size differs.
//! Its values are checked by the C++ type it goes into.
template <int N>
Eigen::Matrix<double, N, 1> state_vector(const py::handle& item, const StateField& where) {
  const std::string floats = N == Eigen::Dynamic ? "floats" : std::to_string(N) + " floats";
  const bool sequence =
      py::isinstance<py::tuple>(item) || py::isinstance<py::list>(item) || py::isinstance<py::array>(item);
  if (!sequence) throw py::type_error(where.message(item, "must be a tuple of " + floats));
  const Array a = Array::ensure(item);
  if (!a) throw py::type_error(where.message(item, "must be a tuple of " + floats));
  if (a.ndim() != 1 || (N != Eigen::Dynamic && a.shape(0) != N))
    throw py::value_error(where.message(item, "must be a tuple of " + floats + ", not of shape " + shape_string(a)));
  return Eigen::Map<const Eigen::Matrix<double, N, 1>>(a.data(), a.shape(0));
}

//! A tuple or list at `where` (the items of a field); TypeError otherwise.
inline py::sequence state_sequence(const py::handle& item, const StateField& where) {
  if (!py::isinstance<py::tuple>(item) && !py::isinstance<py::list>(item))
    throw py::type_error(where.message(item, "must be a tuple"));
  return py::reinterpret_borrow<py::sequence>(item);
}

//! A tuple of `size` items at `where`: TypeError if it is no tuple, ValueError if its length differs.
inline py::tuple state_fields(const py::handle& item, std::size_t size, const StateField& where) {
  if (!py::isinstance<py::tuple>(item))
    throw py::type_error(where.message(item, "must be a tuple of " + std::to_string(size) + " items"));
  if (py::len(item) != size)
    throw py::value_error(where.message(
        item, "must be a tuple of " + std::to_string(size) + " items, not " + std::to_string(py::len(item))));
  return py::reinterpret_borrow<py::tuple>(item);
}

//! `state` as a tuple of `size` items: TypeError naming the type if it is no tuple, ValueError if
//! its length differs (a pickle of another version of dispkin, or a hand-made state).
inline py::tuple state_tuple(const py::handle& state, std::size_t size, const std::string& type) {
  const std::string expected = "expected a tuple of " + std::to_string(size) + " items, got ";
  if (!py::isinstance<py::tuple>(state))
    throw py::type_error(type + ".__setstate__: state: " + expected + echoed(std::string(py::repr(state))));
  if (py::len(state) != size)
    throw py::value_error(type + ".__setstate__: state: " + expected + echoed(std::string(py::repr(state))));
  return py::reinterpret_borrow<py::tuple>(state);
}

namespace detail {


//! Runs `make` and names the type in what the library refuses: the C++ checks throw
//! std::invalid_argument "<field> = <value>: <reason>", which becomes the ValueError
//! "<Type>.__setstate__: <field> = <value>: <reason>". A loader's std::runtime_error (a URDF that
//! does not parse) is bad input too here: everything comes from the state.
template <typename Make>
auto named_unpickling(const std::string& type, Make make) {
  try {
    return make();
  } catch (const py::builtin_exception&) {
    throw;  // TypeError / ValueError of the state helpers: already named
  } catch (const std::invalid_argument& e) {
    throw py::value_error(type + ".__setstate__: " + e.what());
  } catch (const std::runtime_error& e) {
    throw py::value_error(type + ".__setstate__: " + e.what());
  }
}

}  // namespace detail

//! Pickling for a bound class: `get` gives the state, `set` makes the object from it.
//!
//! pybind11's __setstate__ is a constructor: called on an object that already holds a value it
//! returns None and changes nothing (its dispatcher ignores a second __init__). Such a call is a
//! mistake that would otherwise pass silently, so __setstate__ is replaced by a method that raises
//! TypeError for a live object and otherwise hands the state to pybind11's (which pickle, copy and
//! copyreg call on a fresh instance made by __new__).
template <typename T, typename... Options, typename Get, typename Set>
void def_pickle(py::class_<T, Options...>& cls, const std::string& type, Get get, Set set) {
  cls.def(py::pickle(get, [type, set](const py::object& state) {
    return detail::named_unpickling(type, [&] { return set(state); });
  }));
  const py::object construct = cls.attr("__setstate__");
  const py::cpp_function guarded(
      [construct, type](const py::handle& self, const py::object& state) {
        if (py::isinstance<T>(self) && detail::holds_value<T>(self)) {
          throw py::type_error(type + ".__setstate__: the object already holds a " + type +
                               " (a state makes a new object: pickle.loads, copy.copy, or " + type + ".__new__(" +
                               type + ") first)");
        }
        construct(self, state);
      },
      py::name("__setstate__"), py::is_method(cls), py::arg("state"));
  // Named __setstate__, pybind11 would treat this method as a constructor too and skip it for a
  // live object: it is a plain method, which calls the constructor itself.
  py::detail::function_record_ptr_from_PyObject(PyCFunction_GET_SELF(py::detail::get_function(guarded).ptr()))
      ->is_constructor = false;
  cls.attr("__setstate__") = guarded;
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
