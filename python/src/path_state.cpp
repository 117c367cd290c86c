// Pickled states of paths and trajectories (path_state.hpp). Numbers travel as Python floats,
// which are the doubles themselves: nothing is rounded on the way.
#include "path_state.hpp"

#include <string>
#include <utility>
#include <vector>

#include <pybind11/stl.h>

#include "conversions.hpp"
#include "value_protocol.hpp"

namespace dispkin {
namespace python {

namespace {

template <typename Derived>
py::tuple floats(const Eigen::DenseBase<Derived>& v) {
  py::tuple out(static_cast<std::size_t>(v.size()));
  for (Eigen::Index i = 0; i < v.size(); ++i) out[static_cast<std::size_t>(i)] = py::float_(v.derived().coeff(i));
  return out;
}

// A pose as (w, x, y, z, tx, ty, tz), the quaternion as stored.
py::tuple pose_floats(const Posed& p) {
  const Eigen::Quaterniond& q = p.quaternion();
  const Eigen::Vector3d& t = p.translation();
  return py::make_tuple(q.w(), q.x(), q.y(), q.z(), t.x(), t.y(), t.z());
}

Posed pose_of_floats(const py::handle& obj, const std::string& name) {
  const Eigen::Matrix<double, 7, 1> x = vector<7>(obj, name);
  require_finite(x, name);
  require(std::abs(x.head<4>().norm() - 1.0) <= 1e-12, name, x.head<4>().norm(), "quaternion norm must be 1");
  return Posed::unchecked(Eigen::Quaterniond(x(0), x(1), x(2), x(3)), x.tail<3>());
}

Eigen::Vector3d finite3(const py::handle& obj, const std::string& name) {
  const Eigen::Vector3d v = vector3(obj, name);
  require_finite(v, name);
  return v;
}

double finite(const py::handle& obj, const std::string& name) {
  const double x = obj.cast<double>();
  require_finite(x, name);
  return x;
}

py::tuple cubic_floats(const Cubic3& c) {
  Eigen::Matrix<double, 12, 1> x;
  for (int k = 0; k < 4; ++k) x.segment<3>(3 * k) = c.a[static_cast<std::size_t>(k)];
  return floats(x);
}

Cubic3 cubic_of_floats(const py::handle& obj, const std::string& name) {
  const Eigen::Matrix<double, 12, 1> x = vector<12>(obj, name);
  require_finite(x, name);
  Cubic3 c;
  for (int k = 0; k < 4; ++k) c.a[static_cast<std::size_t>(k)] = x.segment<3>(3 * k);
  return c;
}

ProfileState profile_state_of(const py::handle& obj, const std::string& name) {
  const Eigen::Vector4d x = vector<4>(obj, name);
  return ProfileState{x(0), x(1), x(2), x(3)};
}

std::vector<double> doubles(const py::handle& obj, const std::string& name) {
  std::vector<double> out;
  for (const py::handle x : obj.cast<py::sequence>()) out.push_back(finite(x, name));
  return out;
}

py::tuple sections_state(const std::vector<Section>& sections) {
  py::tuple out(sections.size());
  for (std::size_t k = 0; k < sections.size(); ++k) out[k] = section_state(sections[k]);
  return out;
}

std::vector<Section> sections_from_state(const py::handle& obj) {
  std::vector<Section> out;
  for (const py::handle s : obj.cast<py::sequence>()) out.push_back(section_from_state(s));
  return out;
}

}  // namespace

py::tuple profile_state(const Profile& law) {
  const Profile::Parts p = law.parts();
  const auto state = [](const ProfileState& x) { return py::make_tuple(x.s, x.v, x.a, x.j); };
  py::list phases;
  for (int i = 0; i < p.count; ++i) {
    const ProfilePhase& ph = p.phases[static_cast<std::size_t>(i)];
    phases.append(py::make_tuple(ph.duration, ph.jerk, state(ph.start), state(ph.end)));
  }
  py::list times;
  for (int i = 0; i <= p.count; ++i) times.append(p.times[static_cast<std::size_t>(i)]);
  return py::make_tuple(profile_name(p.kind), py::tuple(phases), py::tuple(times), p.distance, p.peak_velocity,
                        state(p.start), state(p.end));
}

Profile profile_from_state(const py::handle& state) {
  const py::tuple s = state_tuple(state, 7, "Profile");
  Profile::Parts p;
  p.kind = profile_kind(s[0].cast<std::string>());
  const py::tuple phases = s[1].cast<py::tuple>();
  const py::tuple times = s[2].cast<py::tuple>();
  require(phases.size() <= static_cast<std::size_t>(Profile::max_phases) && times.size() == phases.size() + 1,
          "Profile state phases", static_cast<long>(phases.size()), "must be at most 7, with one time more than phases");
  p.count = static_cast<int>(phases.size());
  for (std::size_t i = 0; i < phases.size(); ++i) {
    const py::tuple ph = state_tuple(phases[i], 4, "Profile phase");
    p.phases[i] = ProfilePhase{ph[0].cast<double>(), ph[1].cast<double>(), profile_state_of(ph[2], "Profile phase start"),
                               profile_state_of(ph[3], "Profile phase end")};
  }
  for (std::size_t i = 0; i < times.size(); ++i) p.times[i] = times[i].cast<double>();
  p.distance = s[3].cast<double>();
  p.peak_velocity = s[4].cast<double>();
  p.start = profile_state_of(s[5], "Profile start");
  p.end = profile_state_of(s[6], "Profile end");
  return Profile::from_parts(p);
}

py::tuple section_state(const Section& section) {
  if (const auto* lin = std::get_if<LinSection>(&section))
    return py::make_tuple("lin", pose_floats(lin->start), pose_floats(lin->end), to_string(lin->interpolation), floats(lin->pivot));
  if (const auto* arc = std::get_if<ArcSection>(&section))
    return py::make_tuple("arc", pose_floats(arc->start), floats(arc->center), floats(arc->normal), arc->angle,
                          floats(arc->rotation_axis), arc->rotation_angle, floats(arc->pivot));
  if (const auto* b = std::get_if<SlerpBlendSection>(&section))
    return py::make_tuple("slerp_blend", floats(b->q_start.coeffs()), floats(b->a), floats(b->b), cubic_floats(b->position),
                          b->v0, b->v1, floats(b->pivot));
  const CurveSection& c = std::get<CurveSection>(section);
  return py::make_tuple("curve", floats(c.q0.coeffs()), cubic_floats(c.position), cubic_floats(c.rotation), c.v0, c.v1,
                        floats(c.pivot));
}

Section section_from_state(const py::handle& state) {
  if (!py::isinstance<py::tuple>(state) || py::len(state) == 0) {
    throw py::value_error("Section state: expected a tuple starting with \"lin\", \"arc\", \"curve\" or \"slerp_blend\", got " +
                          std::string(py::repr(state)));
  }
  const std::string kind = state.cast<py::tuple>()[0].cast<std::string>();
  if (kind == "lin") {
    const py::tuple s = state_tuple(state, 5, "Section (lin)");
    return LinSection{pose_of_floats(s[1], "lin start"), pose_of_floats(s[2], "lin end"),
                      interpolation_from_string(s[3].cast<std::string>()), finite3(s[4], "lin pivot")};
  }
  if (kind == "arc") {
    const py::tuple s = state_tuple(state, 8, "Section (arc)");
    ArcSection arc;
    arc.start = pose_of_floats(s[1], "arc start");
    arc.center = finite3(s[2], "arc center");
    arc.normal = finite3(s[3], "arc normal");
    arc.angle = finite(s[4], "arc angle");
    arc.rotation_axis = finite3(s[5], "arc rotation_axis");
    arc.rotation_angle = finite(s[6], "arc rotation_angle");
    arc.pivot = finite3(s[7], "arc pivot");
    return arc;
  }
  if (kind == "curve") {
    const py::tuple s = state_tuple(state, 7, "Section (curve)");
    CurveSection c;
    const Eigen::Vector4d q = vector<4>(s[1], "curve q0");  // Eigen's coeffs(): x, y, z, w
    require(std::abs(q.norm() - 1.0) <= 1e-12, "curve q0", q.norm(), "quaternion norm must be 1");
    c.q0.coeffs() = q;
    c.position = cubic_of_floats(s[2], "curve position");
    c.rotation = cubic_of_floats(s[3], "curve rotation");
    c.v0 = finite(s[4], "curve v0");
    c.v1 = finite(s[5], "curve v1");
    c.pivot = finite3(s[6], "curve pivot");
    return c;
  }
  if (kind == "slerp_blend") {
    const py::tuple s = state_tuple(state, 8, "Section (slerp_blend)");
    SlerpBlendSection b;
    const Eigen::Vector4d q = vector<4>(s[1], "slerp_blend q_start");  // Eigen's coeffs(): x, y, z, w
    require_finite(q, "slerp_blend q_start");
    require(std::abs(q.norm() - 1.0) <= 1e-12, "slerp_blend q_start", q.norm(), "quaternion norm must be 1");
    b.q_start.coeffs() = q;
    b.a = finite3(s[2], "slerp_blend a");
    b.b = finite3(s[3], "slerp_blend b");
    // Each turn of the nested SLERP is below π (a blend takes at most half a LIN's turn ≤ π):
    // its logarithms, and so the motion, are smooth only there.
    require(b.a.norm() < pi, "slerp_blend a", b.a.norm(), "must be a turn below pi rad");
    require(b.b.norm() < pi, "slerp_blend b", b.b.norm(), "must be a turn below pi rad");
    b.position = cubic_of_floats(s[4], "slerp_blend position");
    b.v0 = finite(s[5], "slerp_blend v0");
    b.v1 = finite(s[6], "slerp_blend v1");
    require(0.0 <= b.v0 && b.v0 < b.v1 && b.v1 <= 1.0, "slerp_blend v0", b.v0, "must satisfy 0 <= v0 < v1 <= 1");
    b.pivot = finite3(s[7], "slerp_blend pivot");
    return b;
  }
  throw std::invalid_argument(
      describe("Section state kind", kind, "must be \"lin\", \"arc\", \"curve\" or \"slerp_blend\""));
}

py::tuple path_state(const Path& path) {
  py::list limits;
  for (const MoveLimits& l : path.section_limits()) limits.append(py::make_tuple(l.velocity, l.acceleration));
  return py::make_tuple(sections_state(path.sections()), path.first_move_size(), path.last_move_size(), py::tuple(limits),
                        py::tuple(py::cast(path.move_starts())));
}

Path path_from_state(const py::tuple& state) {
  const py::tuple s = state_tuple(state, 5, "Path");
  std::vector<MoveLimits> limits;
  for (const py::handle item : s[3].cast<py::sequence>()) {
    const py::tuple l = state_tuple(item, 2, "Path move limits");
    limits.push_back({l[0].cast<std::optional<double>>(), l[1].cast<std::optional<double>>()});
  }
  return Path::from_sections(sections_from_state(s[0]), s[1].cast<double>(), s[2].cast<double>(), limits,
                             s[4].cast<std::vector<std::size_t>>());
}

py::tuple time_law_state(const TimeLaw& law) {
  py::list pieces;
  for (const TimeLaw::Piece& p : law.pieces()) pieces.append(py::make_tuple(profile_state(p.profile), p.start_s));
  return py::make_tuple(law.run_count(), py::tuple(pieces));
}

TimeLaw time_law_from_state(const py::handle& state) {
  const py::tuple s = state_tuple(state, 2, "TimeLaw");
  TimeLaw law;
  // append places each law after the one before, as planning did: the same sums, the same times.
  for (const py::handle piece : s[1].cast<py::sequence>()) {
    const py::tuple p = state_tuple(piece, 2, "TimeLaw piece");
    law.append(profile_from_state(p[0]), finite(p[1], "TimeLaw piece start_s"));
  }
  const std::size_t runs = s[0].cast<std::size_t>();
  for (std::size_t k = 0; k < runs; ++k) law.end_run();
  return law;
}

py::tuple trajectory_state(const Trajectory& trajectory) {
  py::list limits;
  for (const SpeedLimit& l : trajectory.speed_limits()) limits.append(py::make_tuple(l.start_s, l.length, l.limit));
  const std::vector<double>& lengths = trajectory.section_lengths();
  const std::vector<double>& rests = trajectory.rest_positions();
  py::list stops, sources;
  for (const Stop& stop : trajectory.stops()) stops.append(py::make_tuple(stop.s, stop.reason));
  for (const SectionSource& source : trajectory.section_sources())
    sources.append(py::make_tuple(source.section, source.tau_start, source.tau_end));
  return py::make_tuple(sections_state(trajectory.path().sections()), py::tuple(py::cast(lengths)),
                        time_law_state(trajectory.time_law()), py::tuple(limits), py::tuple(py::cast(rests)), py::tuple(stops),
                        py::tuple(sources));
}

Trajectory trajectory_from_state(const py::tuple& state) {
  const py::tuple s = state_tuple(state, 7, "Trajectory");
  const std::vector<Section> sections = sections_from_state(s[0]);
  std::vector<double> lengths = doubles(s[1], "Trajectory state lengths");
  require(lengths.size() == sections.size(), "Trajectory state lengths", static_cast<long>(lengths.size()),
          "must hold one length per section");
  for (double l : lengths) require(l > 0.0, "Trajectory state lengths", l, "must be > 0");
  std::vector<SpeedLimit> limits;
  for (const py::handle item : s[3].cast<py::sequence>()) {
    const py::tuple l = state_tuple(item, 3, "Trajectory speed limit");
    limits.push_back(SpeedLimit{finite(l[0], "speed limit start_s"), finite(l[1], "speed limit length"), finite(l[2], "speed limit")});
  }
  std::vector<Stop> stops;
  for (const py::handle item : s[5].cast<py::sequence>()) {
    const py::tuple t = state_tuple(item, 2, "Trajectory stop");
    stops.push_back({finite(t[0], "stop s"), t[1].cast<std::string>()});
  }
  std::vector<SectionSource> sources;
  for (const py::handle item : s[6].cast<py::sequence>()) {
    const py::tuple t = state_tuple(item, 3, "Trajectory section source");
    sources.push_back({t[0].cast<std::size_t>(), finite(t[1], "section source tau_start"), finite(t[2], "section source tau_end")});
  }
  require(sources.empty() || sources.size() == sections.size(), "Trajectory state section sources",
          static_cast<long>(sources.size()), "must hold none or one per section");
  return Trajectory(SampledPath(sections, std::move(lengths)), time_law_from_state(s[2]), std::move(limits),
                    doubles(s[4], "Trajectory state rest positions"), std::move(stops), std::move(sources));
}

}  // namespace python
}  // namespace dispkin
