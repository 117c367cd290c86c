// Python binding of dispkin/shapes.hpp: the submodule dispkin._core.shapes.
#include <Eigen/Geometry>  // shapes.hpp uses cross() (Polyhedron::inradius) but includes only Eigen/Core
#include <pybind11/pybind11.h>

#include "bindings.hpp"
#include "conversions.hpp"
#include "dispkin/shapes.hpp"

namespace dispkin {
namespace python {

void bind_shapes(py::module_& m) {
  py::module_ s = m.def_submodule(
      "shapes", "Point-set builders for metric sets; each returns an (N, 3) array of points in metres.");
  const py::tuple origin = py::make_tuple(0.0, 0.0, 0.0);

  s.def(
      "box",
      [](const py::object& size, const py::object& center) {
        return to_array(shapes::box<double>(vector3(size, "size"), vector3(center, "center")));
      },
      py::arg("size"), py::arg_v("center", origin, "(0, 0, 0)"),
      "The 8 corners, as an (8, 3) array, of the axis-aligned box with edge lengths `size` (3,) "
      "around `center`, metres.");
  s.def(
      "icosahedron",
      [](double radius, const py::object& center, bool circumscribed) {
        return to_array(shapes::icosahedron<double>(radius, vector3(center, "center"), circumscribed));
      },
      py::arg("radius"), py::arg_v("center", origin, "(0, 0, 0)"), py::arg("circumscribed") = true,
      "The 12 vertices, as a (12, 3) array, of a regular icosahedron for the sphere of `radius` "
      "(metres) around `center`: circumscribed (default; its faces touch the sphere, vertex radius "
      "1.2584 radius, so it never under-estimates the sphere's speed) or inscribed (vertices on "
      "the sphere).");
  s.def(
      "icosphere",
      [](double radius, int subdivisions, const py::object& center) {
        return to_array(shapes::icosphere<double>(radius, subdivisions, vector3(center, "center")));
      },
      py::arg("radius"), py::arg("subdivisions"), py::arg_v("center", origin, "(0, 0, 0)"),
      "The vertices, as an (N, 3) array (N = 12, 42, 162, 642, ...), of the icosahedron subdivided "
      "`subdivisions` (0..7) times and scaled so that its faces circumscribe the sphere of `radius` "
      "(metres) around `center`.");
  s.def(
      "spherical_shell",
      [](double radius, int count, const py::object& center) {
        return to_array(shapes::spherical_shell<double>(radius, count, vector3(center, "center")));
      },
      py::arg("radius"), py::arg("count"), py::arg_v("center", origin, "(0, 0, 0)"),
      "`count` (>= 4) points, as a (count, 3) array, spread evenly on the sphere of `radius` "
      "(metres) around `center` (a Fibonacci lattice): the DISP patent's shell around a pivot point.");
}

}  // namespace python
}  // namespace dispkin
