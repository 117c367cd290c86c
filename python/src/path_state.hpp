// The pickled states of paths and trajectories: every number they are made of, so that the
// object made again from its state samples the same bit for bit (path_state.cpp). Reading a
// state names the field of anything of the wrong type (TypeError) or shape (ValueError); the
// C++ types check the values as they check what planning makes.
#pragma once

#include <pybind11/pybind11.h>

#include "dispkin/path/path.hpp"
#include "dispkin/planning/time_law.hpp"
#include "dispkin/planning/trajectory.hpp"
#include "value_protocol.hpp"

namespace dispkin {
namespace python {

//! (kind, phases, phase start times, distance, peak velocity, start and end states): Profile::from_parts.
pybind11::tuple profile_state(const Profile& law);
Profile profile_from_state(const pybind11::handle& state);

//! ("lin" | "arc" | "curve", the section's fields as tuples of floats).
pybind11::tuple section_state(const Section& section);
Section section_from_state(const pybind11::handle& state, const StateField& where);

//! (sections, first_move_size, last_move_size, move limits per section, move starts):
//! Path::from_sections makes it again.
pybind11::tuple path_state(const Path& path);
Path path_from_state(const pybind11::object& state);

//! (rest-to-rest runs, (profile parts, start_s) per law): TimeLaw::append makes it again.
pybind11::tuple time_law_state(const TimeLaw& law);
TimeLaw time_law_from_state(const pybind11::handle& state, const StateField& where);

//! (sections, lengths, time law, velocity-limit curve, rest positions, stops, section sources).
pybind11::tuple trajectory_state(const Trajectory& trajectory);
Trajectory trajectory_from_state(const pybind11::object& state);
//! The same for a trajectory inside another state (a re-timing result's) at `where`.
Trajectory trajectory_from_state(const pybind11::handle& state, const StateField& where);

}  // namespace python
}  // namespace dispkin
