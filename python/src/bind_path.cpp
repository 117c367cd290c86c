// Python binding of dispkin/path/path.hpp: Path (LIN, CIRC), its sections, and JointPath (PTP).
#include <optional>
#include <string>

#include <pybind11/eigen.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "bindings.hpp"
#include "conversions.hpp"
#include "interpreter_lock.hpp"
#include "path_state.hpp"
#include "value_protocol.hpp"
#include "dispkin/path/path.hpp"

namespace dispkin {
namespace python {

namespace {

// Section is a std::variant, which pybind11/stl.h would convert alternative by alternative;
// Python sees one class, so the variant travels in a holder.
struct SectionHolder {
  Section value;
};

const char* section_kind(const SectionHolder& s) {
  if (std::holds_alternative<LinSection>(s.value)) return "lin";
  if (std::holds_alternative<ArcSection>(s.value)) return "arc";
  if (std::holds_alternative<SlerpBlendSection>(s.value)) return "slerp_blend";
  return "curve";
}

// then(next), then(next, blend=...), then(next, before=..., after=...) or then(next, weight=...),
// each with the orientation blend by name.
Path& then_blended(Path& path, const Path& next, std::optional<double> blend, std::optional<double> before,
                   std::optional<double> after, double tolerance, const std::string& orientation_blend,
                   std::optional<double> weight) {
  require_not_read(&path, "Path.then");
  const OrientationBlend orientation = orientation_blend_from_string(orientation_blend);
  if (weight && (blend || before || after))
    throw std::invalid_argument(describe("weight", *weight, "give either weight or blend or before/after, not both"));
  if (weight) return path.then_weighted(next, *weight, orientation, tolerance);
  if (!blend && !before && !after) {
    if (orientation != OrientationBlend::rotation_vector)
      throw std::invalid_argument(
          describe("orientation_blend", orientation_blend, "needs a blend: give weight, blend or before and after"));
    return path.then(next);
  }
  if (blend && (before || after)) throw std::invalid_argument("blend: give either blend or before/after, not both");
  if (blend) return path.then(next, *blend, *blend, tolerance, orientation);
  if (!before || !after)
    throw std::invalid_argument(std::string(before ? "after" : "before") + " is missing: give both before and after");
  return path.then(next, *before, *after, tolerance, orientation);
}

// A scalar u gives one Pose; an array of u gives an (N, 4, 4) array of homogeneous matrices,
// sampled with the interpreter lock released when there are many.
py::object sample_path(const Path& path, const py::object& u) {
  const Array a = as_array(u, "u", "a number or an array of shape (N,)");
  if (a.ndim() == 0) {
    require_finite(*a.data(), "u");  // as for every element of an array below
    return py::cast(path.sample(*a.data()));
  }
  if (a.ndim() != 1) wrong_shape("u", "a number or an array of shape (N,)", a);
  py::array_t<double> out({a.shape(0), py::ssize_t{4}, py::ssize_t{4}});
  double* data = out.mutable_data();
  const double* u_data = a.data();
  const py::ssize_t n = a.shape(0);
  {
    const UnlockedIf unlocked(worth_releasing(static_cast<std::size_t>(n), trajectory_sample_ns), path);
    for (py::ssize_t i = 0; i < n; ++i) {
      const double ui = u_data[i];
      require_finite(ui, "u");
      Eigen::Map<Eigen::Matrix<double, 4, 4, Eigen::RowMajor>>(data + 16 * i) = path.sample(ui).matrix();
    }
  }
  return std::move(out);
}

void bind_section(py::module_& m) {
  py::class_<SectionHolder>(m, "Section", R"doc(
One section of a Path: the motion from `start` to `end` as the section parameter tau runs over
[0, 1]. `kind` is "lin" (straight: decoupled LIN or screw, exact length), "arc" (a piece of a
CIRC), "curve" (a piece of a SPLINE or of a blend) or "slerp_blend" (a piece of a blend with
orientation_blend="nested_slerp"); arcs and curves have lengths that are tight upper bounds.)doc")
      .def_property_readonly("kind", &section_kind, "\"lin\", \"arc\", \"curve\" or \"slerp_blend\".")
      .def_property_readonly(
          "start", [](const SectionHolder& s) { return section_start(s.value); }, "Pose at tau = 0.")
      .def_property_readonly(
          "end", [](const SectionHolder& s) { return section_end(s.value); }, "Pose at tau = 1.")
      .def(
          "pose",
          [](const SectionHolder& s, double tau) {
            require_finite(tau, "tau");
            return section_pose(s.value, tau);
          },
          py::arg("tau"), "The pose at section parameter tau (0 = start, 1 = end).")
      .def(
          "length",
          [](const SectionHolder& s, const MetricSetd& set, std::optional<double> v) {
            const UnlockedIf unlocked(worth_releasing(set), set);
            return section_length(s.value, set, v);
          },
          py::arg("metric_set"), py::arg("system_velocity") = py::none(),
          "L: no point or sphere of the set moves faster than L (metres) per unit of tau along this "
          "section.")
      .def("__repr__", [](const SectionHolder& s) { return std::string("Section(kind=\"") + section_kind(s) + "\")"; });

  // Before Path, so that the signature of Path.ptp names the Python type, not the C++ one.
}

void bind_joint_path(py::module_& m) {
  py::class_<JointPath> joint_path(m, "JointPath",
                                   "A PTP move: the straight line between two joint vectors (radians / metres).");
  joint_path.def_property_readonly("start", &JointPath::start, "q at u = 0.")
      .def_property_readonly("end", &JointPath::end, "q at u = 1.")
      .def(
          "sample",
          [](const JointPath& p, double u) {
            require_finite(u, "u");
            return p.sample(u);
          },
          py::arg("u"), "q(u) = q_a + u (q_b - q_a), u clamped to [0, 1].")
      .def("__repr__", [](const JointPath& p) { return "JointPath(" + std::to_string(p.start().size()) + " joints)"; });
  def_pickle(
      joint_path, "JointPath", [](const JointPath& p) { return py::make_tuple(p.start(), p.end()); },
      [](const py::object& state) {
        const py::tuple s = state_tuple(state, 2, "JointPath");
        return JointPath(state_vector<Eigen::Dynamic>(s[0], StateField("JointPath", 0, "start")),
                         state_vector<Eigen::Dynamic>(s[1], StateField("JointPath", 1, "end")));
      });
}

// The moves a path is built of: lin, circ, spline, and ptp (a JointPath).
void def_path_moves(py::class_<Path>& path) {
  const py::tuple origin = py::make_tuple(0.0, 0.0, 0.0);
  path.def_static(
          "lin",
          [](const Posed& a, const Posed& b, const std::string& interpolation, const py::object& pivot,
             std::optional<double> velocity, std::optional<double> acceleration) {
            return Path::lin(a, b, interpolation_from_string(interpolation), vector3(pivot, "pivot"))
                .with_limits({velocity, acceleration});
          },
          py::arg("a"), py::arg("b"), py::arg("interpolation") = "decoupled", py::arg_v("pivot", origin, "(0, 0, 0)"),
          py::kw_only(), py::arg("velocity") = py::none(), py::arg("acceleration") = py::none(),
          "A LIN move from pose a to pose b: the pivot (body coordinates, m) on a straight line, the "
          "orientation by SLERP (\"decoupled\"), or a constant-twist \"screw\". `velocity` (m/s) and "
          "`acceleration` (m/s^2), keywords: this move's own limits, capped by the plan's Limits.")
      .def_static(
          "circ",
          [](const Posed& a, const Posed& via, const Posed& b, const py::object& pivot, double tolerance,
             std::optional<double> velocity, std::optional<double> acceleration) {
            const Eigen::Vector3d p = vector3(pivot, "pivot");
            py::gil_scoped_release unlocked;
            return Path::circ(a, via, b, p, tolerance).with_limits({velocity, acceleration});
          },
          py::arg("a"), py::arg("via"), py::arg("b"), py::arg_v("pivot", origin, "(0, 0, 0)"),
          py::arg("tolerance") = 1e-3, py::kw_only(), py::arg("velocity") = py::none(),
          py::arg("acceleration") = py::none(),
          "A CIRC move: the pivot on the circular arc from a through via to b, the orientation turning "
          "from a's to b's proportionally to the arc angle (via's orientation is not used). Cut into "
          "sections whose length bound exceeds the exact speed by at most `tolerance` (relative). `velocity`, "
          "`acceleration` (keywords): this move's own limits, as for lin.")
      .def_static(
          "spline",
          [](const std::vector<Posed>& poses, const py::object& pivot, double tolerance, std::optional<double> velocity,
             std::optional<double> acceleration) {
            const Eigen::Vector3d p = vector3(pivot, "pivot");
            py::gil_scoped_release unlocked;
            return Path::spline(poses, p, tolerance).with_limits({velocity, acceleration});
          },
          py::arg("poses"), py::arg_v("pivot", origin, "(0, 0, 0)"), py::arg("tolerance") = 1e-3, py::kw_only(),
          py::arg("velocity") = py::none(), py::arg("acceleration") = py::none(),
          "A SPLINE move through the key poses (at least three): the pivot on the natural cubic spline "
          "(C2, knots spaced by pivot travel + 0.1 m per radian), the orientation a C1 curve (continuous "
          "angular velocity) through every key orientation. Passes through every key exactly. Cut into "
          "sections within each of which the speed varies by about `tolerance` (relative). `velocity`, "
          "`acceleration` (keywords): this move's own limits, as for lin.")
      .def_static(
          "ptp", [](const Eigen::VectorXd& q_a, const Eigen::VectorXd& q_b) { return JointPath(q_a, q_b); },
          py::arg("q_a"), py::arg("q_b"), "A PTP move: the straight line between two joint vectors (a JointPath).");
}

// Moves joined into one path, their corners blended.
void def_path_blending(py::class_<Path>& path) {
  path.def("then", &then_blended, py::arg("next"), py::kw_only(), py::arg("blend") = py::none(),
           py::arg("before") = py::none(), py::arg("after") = py::none(), py::arg("tolerance") = 1e-3,
           py::arg("orientation_blend") = "rotation_vector", py::arg("weight") = py::none(),
           py::return_value_policy::reference_internal,
           "Append `next`, which must start where this path ends; returns this path. With `blend` (or "
           "`before` and `after`, metres of pivot travel + 0.1 m per radian) the corner is replaced by a "
           "smooth pose curve from the point `before` ahead of the corner to the point `after` past it, "
           "joining both neighbours without a kink (the planner does not stop there). A blend may take "
           "at most half of each neighbouring move. `weight` w in (0, 0.5] instead gives the blend as a share "
           "of the moves (before = w x the last move's size, after = w x next's first move's). "
           "`orientation_blend`: \"rotation_vector\" (a cubic in the rotation vector, any neighbours) or "
           "\"nested_slerp\" (the Mamezou article's nested SLERP through the corner orientation, the pivot "
           "on the quadratic Bezier curve through the corner; both neighbours must be decoupled LINs).")
      .def(
          "blended",
          [](const Path& p, double corner_tolerance, double tolerance) {
            std::vector<CornerStop> stops;
            std::optional<Path> out;
            {
              const UnlockedIf unlocked(true, p);
              out = p.blended(corner_tolerance, &stops, tolerance);
            }
            py::list corners;
            for (const CornerStop& c : stops) corners.append(py::make_tuple(c.section, c.reason));
            return py::make_tuple(std::move(*out), corners);
          },
          py::arg("corner_tolerance"), py::arg("tolerance") = 1e-3,
          "The path with every corner between two moves blended (what plan(..., corner_tolerance=d) plans): the "
          "largest blend whose pivot stays within `corner_tolerance` (m) of the corner's two legs, at most half of "
          "each neighbouring move. Returns (path, corners left): each corner left as (index of the section it "
          "ends, reason).");
}

void bind_path_class(py::module_& m) {
  py::class_<Path> path(m, "Path", R"doc(
A pose path (geometry only, no time): a chain of sections. Build it with Path.lin / Path.circ
and chain with `then`. Path.ptp gives a JointPath (joint space).)doc");
  def_path_moves(path);
  def_path_blending(path);
  path.def_property_readonly(
          "move_starts", [](const Path& p) { return p.move_starts(); },
          "The index of the first section of every move (lin, circ, spline), in order.")
      .def(
          "sections",
          [](const Path& p) {
            py::list out;
            for (const Section& s : p.sections()) out.append(SectionHolder{s});
            return out;
          },
          "The sections, in order.")
      .def(
          "section_lengths",
          [](const Path& p, const MetricSetd& set, std::optional<double> v) {
            std::vector<double> lengths;
            {
              const UnlockedIf unlocked(true, p, set);
              lengths = p.section_lengths(set, v);
            }
            return py::array_t<double>(static_cast<py::ssize_t>(lengths.size()), lengths.data());
          },
          py::arg("metric_set"), py::arg("system_velocity") = py::none(),
          "L of every section (metres), as an (N,) array.")
      .def("sample", &sample_path, py::arg("u"),
           "Geometry only: the pose at u in [0, 1] (a Pose), or (N, 4, 4) matrices for an array of u. "
           "u is spread over the sections in proportion to pivot travel plus 0.1 m per radian.")
      .def_property_readonly("start", &Path::start, "The first pose.")
      .def_property_readonly("end", &Path::end, "The last pose.")
      .def("__len__", &Path::size, "Number of sections.")
      .def("__repr__", [](const Path& p) { return "Path(" + std::to_string(p.size()) + " sections)"; });
  def_pickle(path, "Path", &path_state, &path_from_state);
}

}  // namespace

void bind_path(py::module_& m) {
  bind_section(m);
  bind_joint_path(m);
  bind_path_class(m);
}

}  // namespace python
}  // namespace dispkin
