// Python binding of dispkin/frames.hpp: WorkToolFrames (work and tool coordinate systems and
// the metric-set envelopes around their origins). Poses in as Pose or (4, 4) matrices.
#include <string>

#include <pybind11/eigen.h>
#include <pybind11/pybind11.h>

#include "bindings.hpp"
#include "conversions.hpp"
#include "value_protocol.hpp"
#include "dispkin/error.hpp"
#include "dispkin/frames.hpp"

namespace dispkin {
namespace python {

namespace {

using Vector6d = Eigen::Matrix<double, 6, 1>;

Posed pose_argument(const py::handle& obj, const std::string& name) {
  if (py::isinstance<Posed>(obj)) return obj.cast<Posed>();
  return Posed::from_matrix(matrix4(obj, name));
}

Envelope envelope_of(const std::string& name) {
  if (name == "icosahedron") return Envelope::icosahedron;
  if (name == "sphere") return Envelope::sphere;
  throw std::invalid_argument(describe("envelope", name, "must be \"icosahedron\" or \"sphere\""));
}

}  // namespace

void bind_frames(py::module_& m) {
  py::class_<WorkToolFrames> frames(m, "WorkToolFrames", R"doc(
A work frame W (world coordinates, stays put) and a tool frame F (platform coordinates, moves with
the platform), PI-style: a command is the pose X of the tool frame in the work frame, realised by
the platform pose T = W X F^-1 (and X = W^-1 T F). XYZUVW commands rotate about the tool origin,
`pivot` (platform coordinates). Envelopes around the origins generate metric sets: relative
points around the tool origin, absolute points around the work origin.)doc");
  frames
      .def(py::init([](const py::object& work, const py::object& tool) {
             return WorkToolFrames(work.is_none() ? Posed() : pose_argument(work, "work"),
                                   tool.is_none() ? Posed() : pose_argument(tool, "tool"));
           }),
           py::arg("work") = py::none(), py::arg("tool") = py::none(),
           "Work frame in world coordinates and tool frame in platform coordinates (Pose or (4, 4); default identity).")
      .def_property_readonly("work", &WorkToolFrames::work, "W: the work frame in world coordinates")
      .def_property_readonly("tool", &WorkToolFrames::tool, "F: the tool frame in platform coordinates")
      .def_property_readonly(
          "pivot", [](const WorkToolFrames& f) { return to_array(f.pivot()); },
          "(3,) the tool origin in platform coordinates: the pivot of commands in these frames")
      .def(
          "platform_pose",
          [](const WorkToolFrames& f, const py::object& command) {
            return f.platform_pose(pose_argument(command, "tool_in_work"));
          },
          py::arg("tool_in_work"),
          "The platform pose W X F^-1 that puts the tool frame at `tool_in_work` in the work frame.")
      .def(
          "tool_in_work",
          [](const WorkToolFrames& f, const py::object& platform) {
            return f.tool_in_work(pose_argument(platform, "platform"));
          },
          py::arg("platform"), "The tool frame's pose in the work frame, W^-1 T F, at platform pose `platform`.")
      .def(
          "platform_pose_xyzuvw",
          [](const WorkToolFrames& f, const py::object& xyzuvw) {
            return f.platform_pose_xyzuvw(vector<6>(xyzuvw, "xyzuvw"));
          },
          py::arg("xyzuvw"),
          "The platform pose for an XYZUVW command of the tool frame in the work frame (UVW about the tool origin).")
      .def(
          "xyzuvw",
          [](const WorkToolFrames& f, const py::object& platform) {
            return Vector6d(f.xyzuvw(pose_argument(platform, "platform")));
          },
          py::arg("platform"), "(6,) XYZUVW of the tool frame in the work frame at platform pose `platform`.")
      .def(
          "add_tool_envelope",
          [](const WorkToolFrames& f, MetricSetd& set, double radius, const std::string& envelope, int group) {
            f.add_tool_envelope(set, radius, envelope_of(envelope), group);
          },
          py::arg("metric_set"), py::arg("radius"), py::arg("envelope") = "icosahedron", py::arg("group") = 0,
          "Adds a circumscribed \"icosahedron\" (12 points) or the exact \"sphere\" of `radius` (m) around the tool "
          "origin to `metric_set` as relative objects of `group`.")
      .def(
          "add_work_envelope",
          [](const WorkToolFrames& f, MetricSetd& set, double radius, const std::string& envelope, int group) {
            f.add_work_envelope(set, radius, envelope_of(envelope), group);
          },
          py::arg("metric_set"), py::arg("radius"), py::arg("envelope") = "icosahedron", py::arg("group") = 0,
          "Adds a circumscribed \"icosahedron\" (12 points) or the exact \"sphere\" of `radius` (m) around the work "
          "origin to `metric_set` as absolute objects of `group`.")
      .def("__repr__", [](const WorkToolFrames& f) {
        return "WorkToolFrames(work_origin=" + tuple_repr(f.work().translation()) +
               ", tool_origin=" + tuple_repr(f.pivot()) + ")";
      });
  def_pickle(
      frames, "WorkToolFrames", [](const WorkToolFrames& f) { return py::make_tuple(f.work(), f.tool()); },
      [](const py::object& state) {
        const py::tuple s = state_tuple(state, 2, "WorkToolFrames");
        return WorkToolFrames(state_item<Posed>(s, 0, "WorkToolFrames", "work"),
                              state_item<Posed>(s, 1, "WorkToolFrames", "tool"));
      });
}

}  // namespace python
}  // namespace dispkin
