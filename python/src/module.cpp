// The extension module dispkin._core. The pure-Python package `dispkin` re-exports it.
#include <pybind11/pybind11.h>

#include "bindings.hpp"
#include "dispkin/version.hpp"

PYBIND11_MODULE(_core, m) {
  m.doc() =
      "dispkin._core: the compiled core of dispkin (poses, metric sets, shapes, DISP distances and "
      "section lengths). Use it through the package `dispkin`. Units: metres, radians, seconds.";
  m.attr("__version__") = dispkin::version;
  dispkin::python::bind_pose(m);
  dispkin::python::bind_metric_set(m);
  dispkin::python::bind_shapes(m);
  dispkin::python::bind_disp(m);
  dispkin::python::bind_profile(m);
  dispkin::python::bind_path(m);
  dispkin::python::bind_planner(m);
  dispkin::python::bind_hexapod(m);
  dispkin::python::bind_frames(m);
#if defined(DISPKIN_HAS_SERIAL)
  dispkin::python::bind_serial(m);
  dispkin::python::bind_retiming(m);
  dispkin::python::bind_ptp(m);
#endif
}
