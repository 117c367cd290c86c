// Pickled states of paths and trajectories (path_state.hpp). Numbers travel as Python floats,
// which are the doubles themselves: nothing is rounded on the way.
#include "path_state.hpp"

#include <algorithm>
#include <limits>
#include <optional>
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

// The numbers are taken as stored; Path::from_sections and the Trajectory constructor check
// them (require_valid of each section), as they check sections made by the moves.
Posed pose_of_floats(const py::handle& obj, const StateField& where) {
  const Eigen::Matrix<double, 7, 1> x = state_vector<7>(obj, where);
  return Posed::unchecked(Eigen::Quaterniond(x(0), x(1), x(2), x(3)), x.tail<3>());
}

py::tuple cubic_floats(const Cubic3& c) {
  Eigen::Matrix<double, 12, 1> x;
  for (int k = 0; k < 4; ++k) x.segment<3>(3 * k) = c.a[static_cast<std::size_t>(k)];
  return floats(x);
}

Cubic3 cubic_of_floats(const py::handle& obj, const StateField& where) {
  const Eigen::Matrix<double, 12, 1> x = state_vector<12>(obj, where);
  Cubic3 c;
  for (int k = 0; k < 4; ++k) c.a[static_cast<std::size_t>(k)] = x.segment<3>(3 * k);
  return c;
}

ProfileState profile_state_of(const py::handle& obj, const StateField& where) {
  const Eigen::Vector4d x = state_vector<4>(obj, where);
  return ProfileState{x(0), x(1), x(2), x(3)};
}

// The items of a sequence field, each converted by `item(handle, field of item k)`.
template <typename T, typename Item>
std::vector<T> each(const py::handle& obj, const StateField& where, Item item) {
  std::vector<T> out;
  std::size_t k = 0;
  for (const py::handle x : state_sequence(obj, where)) {
    out.push_back(item(x, where.at(k)));
    ++k;
  }
  return out;
}

std::vector<double> numbers(const py::handle& obj, const StateField& where) {
  return each<double>(obj, where, [](const py::handle& x, const StateField& at) { return state_number(x, at); });
}

py::tuple sections_state(const std::vector<Section>& sections) {
  py::tuple out(sections.size());
  for (std::size_t k = 0; k < sections.size(); ++k) out[k] = section_state(sections[k]);
  return out;
}

std::vector<Section> sections_from_state(const py::handle& obj, const StateField& where) {
  return each<Section>(obj, where, [](const py::handle& x, const StateField& at) { return section_from_state(x, at); });
}

// A law's parts from the 7 items of its state; `field(k, name)` says where item k sits.
template <typename Field>
Profile profile_of_items(const py::tuple& s, Field field) {
  Profile::Parts p;
  const StateField kind_at = field(0, "kind");
  const std::string kind = state_cast<std::string>(s[0], kind_at);
  if (kind != "scurve" && kind != "trapezoid")
    throw py::value_error(kind_at.message(s[0], "must be 'scurve' or 'trapezoid'"));
  p.kind = profile_kind(kind);
  const StateField phases_at = field(1, "phases"), times_at = field(2, "times");
  const py::sequence phases = state_sequence(s[1], phases_at);
  const std::vector<double> times = numbers(s[2], times_at);
  if (phases.size() > static_cast<std::size_t>(Profile::max_phases))
    throw py::value_error(phases_at.message(s[1], "must hold at most 7 phases"));
  if (times.size() != phases.size() + 1)
    throw py::value_error(times_at.message(
        s[2], "must hold one time more than there are phases (" + std::to_string(phases.size()) + ")"));
  p.count = static_cast<int>(phases.size());
  for (std::size_t i = 0; i < phases.size(); ++i) {
    const StateField at = phases_at.at(i);
    const py::tuple ph = state_fields(phases[i], 4, at);
    p.phases[i] = ProfilePhase{state_number(ph[0], at / ".duration"), state_number(ph[1], at / ".jerk"),
                               profile_state_of(ph[2], at / ".start"), profile_state_of(ph[3], at / ".end")};
  }
  std::copy(times.begin(), times.end(), p.times.begin());
  p.distance = state_number(s[3], field(3, "distance"));
  p.peak_velocity = state_number(s[4], field(4, "peak_velocity"));
  p.start = profile_state_of(s[5], field(5, "start"));
  p.end = profile_state_of(s[6], field(6, "end"));
  return Profile::from_parts(p);
}

Profile profile_of(const py::handle& obj, const StateField& where) {
  const py::tuple s = state_fields(obj, 7, where);
  return inside(where, [&] {
    return profile_of_items(s, [&](std::size_t, const char* name) { return where / ("." + std::string(name)); });
  });
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
  return profile_of_items(s, [](std::size_t k, const char* name) { return StateField("Profile", k, name); });
}

py::tuple section_state(const Section& section) {
  if (const auto* lin = std::get_if<LinSection>(&section))
    return py::make_tuple("lin", pose_floats(lin->start), pose_floats(lin->end), to_string(lin->interpolation),
                          floats(lin->pivot));
  if (const auto* arc = std::get_if<ArcSection>(&section))
    return py::make_tuple("arc", pose_floats(arc->start), floats(arc->center), floats(arc->normal), arc->angle,
                          floats(arc->rotation_axis), arc->rotation_angle, floats(arc->pivot));
  if (const auto* b = std::get_if<SlerpBlendSection>(&section))
    return py::make_tuple("slerp_blend", floats(b->q_start.coeffs()), floats(b->a), floats(b->b),
                          cubic_floats(b->position), b->v0, b->v1, floats(b->pivot));
  const CurveSection& c = std::get<CurveSection>(section);
  return py::make_tuple("curve", floats(c.q0.coeffs()), cubic_floats(c.position), cubic_floats(c.rotation), c.v0, c.v1,
                        floats(c.pivot));
}

Section section_from_state(const py::handle& state, const StateField& where) {
  if (!py::isinstance<py::tuple>(state) || py::len(state) == 0)
    throw py::type_error(where.message(state, "must be a tuple starting with 'lin', 'arc', 'curve' or 'slerp_blend'"));
  const StateField kind_at = where / ".kind";
  const std::string kind = state_cast<std::string>(py::reinterpret_borrow<py::tuple>(state)[0], kind_at);
  const auto fields = [&](std::size_t size) { return state_fields(state, size, where); };
  if (kind == "lin") {
    const py::tuple s = fields(5);
    const StateField interpolation_at = where / ".interpolation";
    const std::string interpolation = state_cast<std::string>(s[3], interpolation_at);
    if (interpolation != "decoupled" && interpolation != "screw")
      throw py::value_error(interpolation_at.message(s[3], "must be 'decoupled' or 'screw'"));
    return LinSection{pose_of_floats(s[1], where / ".start"), pose_of_floats(s[2], where / ".end"),
                      interpolation_from_string(interpolation), state_vector<3>(s[4], where / ".pivot")};
  }
  if (kind == "arc") {
    const py::tuple s = fields(8);
    ArcSection arc;
    arc.start = pose_of_floats(s[1], where / ".start");
    arc.center = state_vector<3>(s[2], where / ".center");
    arc.normal = state_vector<3>(s[3], where / ".normal");
    arc.angle = state_number(s[4], where / ".angle");
    arc.rotation_axis = state_vector<3>(s[5], where / ".rotation_axis");
    arc.rotation_angle = state_number(s[6], where / ".rotation_angle");
    arc.pivot = state_vector<3>(s[7], where / ".pivot");
    return arc;
  }
  if (kind == "curve") {
    const py::tuple s = fields(7);
    CurveSection c;
    c.q0.coeffs() = state_vector<4>(s[1], where / ".q0");  // Eigen's coeffs(): x, y, z, w
    c.position = cubic_of_floats(s[2], where / ".position");
    c.rotation = cubic_of_floats(s[3], where / ".rotation");
    c.v0 = state_number(s[4], where / ".v0");
    c.v1 = state_number(s[5], where / ".v1");
    c.pivot = state_vector<3>(s[6], where / ".pivot");
    return c;
  }
  if (kind == "slerp_blend") {
    const py::tuple s = fields(8);
    SlerpBlendSection b;
    b.q_start.coeffs() = state_vector<4>(s[1], where / ".q_start");  // Eigen's coeffs(): x, y, z, w
    b.a = state_vector<3>(s[2], where / ".a");
    b.b = state_vector<3>(s[3], where / ".b");
    b.position = cubic_of_floats(s[4], where / ".position");
    b.v0 = state_number(s[5], where / ".v0");
    b.v1 = state_number(s[6], where / ".v1");
    b.pivot = state_vector<3>(s[7], where / ".pivot");
    return b;
  }
  throw py::value_error(
      kind_at.message(py::reinterpret_borrow<py::tuple>(state)[0], "must be 'lin', 'arc', 'curve' or 'slerp_blend'"));
}

py::tuple path_state(const Path& path) {
  py::list limits;
  for (const MoveLimits& l : path.section_limits()) limits.append(py::make_tuple(l.velocity, l.acceleration));
  return py::make_tuple(sections_state(path.sections()), path.first_move_size(), path.last_move_size(),
                        py::tuple(limits), py::tuple(py::cast(path.move_starts())));
}

Path path_from_state(const py::object& state) {
  const py::tuple s = state_tuple(state, 5, "Path");
  const StateField limits_at("Path", 3, "section_limits");
  const std::vector<MoveLimits> limits =
      each<MoveLimits>(s[3], limits_at, [](const py::handle& item, const StateField& at) {
        const py::tuple l = state_fields(item, 2, at);
        return MoveLimits{state_cast<std::optional<double>>(l[0], at / ".velocity"),
                          state_cast<std::optional<double>>(l[1], at / ".acceleration")};
      });
  const std::vector<Section> sections = sections_from_state(s[0], StateField("Path", 0, "sections"));
  const std::vector<std::size_t> move_starts =
      each<std::size_t>(s[4], StateField("Path", 4, "move_starts"),
                        [&](const py::handle& x, const StateField& at) { return state_count(x, at, sections.size()); });
  return Path::from_sections(sections, state_item<double>(s, 1, "Path", "first_move_size"),
                             state_item<double>(s, 2, "Path", "last_move_size"), limits, move_starts);
}

py::tuple time_law_state(const TimeLaw& law) {
  py::list pieces;
  // A law cut where another took over keeps its cut time as a third item.
  for (const TimeLaw::Piece& p : law.pieces())
    pieces.append(p.cut ? py::tuple(py::make_tuple(profile_state(p.profile), p.start_s, p.end_time))
                        : py::tuple(py::make_tuple(profile_state(p.profile), p.start_s)));
  return py::make_tuple(law.run_count(), py::tuple(pieces));
}

TimeLaw time_law_from_state(const py::handle& state, const StateField& where) {
  const py::tuple s = state_fields(state, 2, where);
  TimeLaw law;
  // append places each law after the one before, as planning did: the same sums, the same times.
  const StateField pieces_at = where / ".pieces";
  const py::sequence pieces = state_sequence(s[1], pieces_at);
  for (std::size_t k = 0; k < pieces.size(); ++k) {
    const StateField at = pieces_at.at(k);
    const bool cut = py::isinstance<py::tuple>(pieces[k]) && py::len(pieces[k]) == 3;
    const py::tuple p = state_fields(pieces[k], cut ? 3 : 2, at);
    if (cut)
      law.append_cut(profile_of(p[0], at / ".profile"), state_number(p[1], at / ".start_s"),
                     state_number(p[2], at / ".end_time"));
    else
      law.append(profile_of(p[0], at / ".profile"), state_number(p[1], at / ".start_s"));
  }
  // Runs: at least one, at most one per law (the Trajectory constructor checks it).
  const std::size_t runs = state_count(s[0], where / ".runs", pieces.size());
  for (std::size_t k = 0; k < runs; ++k) law.end_run();
  return law;
}

namespace {

py::tuple sources_state(const std::vector<SectionSource>& sources) {
  py::tuple out(sources.size());
  for (std::size_t k = 0; k < sources.size(); ++k)
    out[k] = py::make_tuple(sources[k].section, sources[k].tau_start, sources[k].tau_end);
  return out;
}

// (section, tau_start, tau_end) items; `bound`: the largest index accepted.
std::vector<SectionSource> sources_of(const py::handle& obj, const StateField& where, std::size_t bound) {
  return each<SectionSource>(obj, where, [bound](const py::handle& item, const StateField& at) {
    const py::tuple t = state_fields(item, 3, at);
    return SectionSource{state_count(t[0], at / ".section", bound), state_number(t[1], at / ".tau_start"),
                         state_number(t[2], at / ".tau_end")};
  });
}

}  // namespace

py::tuple trajectory_state(const Trajectory& trajectory) {
  py::list limits;
  for (const SpeedLimit& l : trajectory.speed_limits())
    limits.append(py::make_tuple(l.start_s, l.length, l.limit, l.acceleration, l.ceiling));
  const std::optional<TimeLawLimits>& law_limits = trajectory.limits();
  const py::object limits_of_law =
      law_limits ? py::object(py::make_tuple(law_limits->acceleration, py::cast(law_limits->jerk))) : py::none();
  const std::vector<double>& lengths = trajectory.section_lengths();
  const std::vector<double>& rests = trajectory.rest_positions();
  const SampledPath& path = trajectory.path();
  py::list stops;
  for (const Stop& stop : trajectory.stops()) stops.append(py::make_tuple(stop.s, stop.reason));
  // The sources when they are other than the parts (a trajectory continued on another plan).
  const bool own_sources = &trajectory.section_sources() != &path.parts();
  return py::make_tuple(sections_state(path.whole_sections()), py::tuple(py::cast(lengths)),
                        time_law_state(trajectory.time_law()), py::tuple(limits), py::tuple(py::cast(rests)),
                        py::tuple(stops), own_sources ? sources_state(trajectory.section_sources()) : py::tuple(),
                        limits_of_law, trajectory.override_factor(), sources_state(path.parts()));
}

namespace {

// A trajectory from the 7 items of its state; `field(k, name)` says where item k sits.
template <typename Field>
Trajectory trajectory_of_items(const py::tuple& s, Field field) {
  std::vector<Section> sections = sections_from_state(s[0], field(0, "sections"));
  std::vector<double> lengths = numbers(s[1], field(1, "section_lengths"));
  // Item 9 (since sections are kept once, however finely cut): where each section of the
  // trajectory lies in the sections of item 0; before, item 0 held them one by one.
  std::vector<SectionSource> parts;
  if (s.size() == 10) parts = sources_of(s[9], field(9, "section_parts"), sections.empty() ? 0 : sections.size() - 1);
  const std::size_t count = parts.empty() ? sections.size() : parts.size();
  // The constructor checks everything else; the lengths must pair with the sections before
  // SampledPath divides by them.
  if (lengths.size() != count)
    throw py::value_error(
        field(1, "section_lengths").message(s[1], "must hold one length per section (" + std::to_string(count) + ")"));
  for (std::size_t k = 0; k < lengths.size(); ++k)
    if (!(lengths[k] > 0.0))
      throw py::value_error(field(1, "section_lengths").at(k).message(py::float_(lengths[k]), "must be > 0"));
  const std::vector<SpeedLimit> limits =
      each<SpeedLimit>(s[3], field(3, "speed_limits"), [](const py::handle& item, const StateField& at) {
        // (start_s, length, limit), and since the events (acceleration, ceiling).
        const bool own = py::isinstance<py::tuple>(item) && py::len(item) == 5;
        const py::tuple l = state_fields(item, own ? 5 : 3, at);
        return SpeedLimit{state_number(l[0], at / ".start_s"), state_number(l[1], at / ".length"),
                          state_number(l[2], at / ".limit"), own ? state_number(l[3], at / ".acceleration") : 0.0,
                          own ? state_number(l[4], at / ".ceiling") : 0.0};
      });
  std::vector<Stop> stops = each<Stop>(s[5], field(5, "stops"), [](const py::handle& item, const StateField& at) {
    const py::tuple t = state_fields(item, 2, at);
    return Stop{state_number(t[0], at / ".s"), state_cast<std::string>(t[1], at / ".reason")};
  });
  // Any index: it names a section of the path as planned, which the state does not hold.
  std::vector<SectionSource> sources =
      sources_of(s[6], field(6, "section_sources"), std::numeric_limits<std::size_t>::max() >> 1);
  // Items 7 and 8 (what the law keeps to, the override in force) since the events; a state of 7
  // items holds neither.
  std::optional<TimeLawLimits> law_limits;
  double override_factor = 1.0;
  if (s.size() >= 9) {
    if (!s[7].is_none()) {
      const py::tuple l = state_fields(s[7], 2, field(7, "limits"));
      law_limits = TimeLawLimits{
          state_number(l[0], field(7, "limits") / ".acceleration"),
          l[1].is_none() ? std::nullopt : std::optional<double>(state_number(l[1], field(7, "limits") / ".jerk"))};
    }
    override_factor = state_number(s[8], field(8, "override_factor"));
  }
  SampledPath path = inside(field(9, "section_parts"),
                            [&] { return SampledPath(std::move(sections), std::move(parts), std::move(lengths)); });
  return Trajectory(std::move(path), time_law_from_state(s[2], field(2, "time_law")), limits,
                    numbers(s[4], field(4, "rest_positions")), std::move(stops), std::move(sources), law_limits,
                    override_factor);
}

// The items of a Trajectory state: 10, or 9 from before sections were kept once, or 7 from
// before the events.
std::size_t trajectory_items(const py::handle& state) {
  if (!py::isinstance<py::tuple>(state)) return 10;
  const std::size_t n = py::len(state);
  return n == 7 || n == 9 ? n : 10;
}

}  // namespace

Trajectory trajectory_from_state(const py::object& state) {
  const py::tuple s = state_tuple(state, trajectory_items(state), "Trajectory");
  return trajectory_of_items(s, [](std::size_t k, const char* name) { return StateField("Trajectory", k, name); });
}

Trajectory trajectory_from_state(const py::handle& state, const StateField& where) {
  const py::tuple s = state_fields(state, trajectory_items(state), where);
  return trajectory_of_items(s, [&](std::size_t, const char* name) { return where / ("." + std::string(name)); });
}

}  // namespace python
}  // namespace dispkin
