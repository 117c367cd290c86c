// One function per C++ module, each defined in its own binding source and called by module.cpp.
#pragma once

#include <pybind11/pybind11.h>

namespace dispkin {
namespace python {

void bind_pose(pybind11::module_& m);        // bind_pose.cpp: Pose
void bind_metric_set(pybind11::module_& m);  // bind_metric_set.cpp: MetricSet
void bind_shapes(pybind11::module_& m);      // bind_shapes.cpp: the submodule `shapes`
void bind_disp(pybind11::module_& m);        // bind_disp.cpp: distances, speeds, section lengths
void bind_profile(pybind11::module_& m);     // bind_profile.cpp: Profile (trapezoid, S-curve)
void bind_path(pybind11::module_& m);        // bind_path.cpp: Path, Section, JointPath
void bind_planner(pybind11::module_& m);     // bind_planner.cpp: Limits, plan, Trajectory, TrajectoryCursor
void bind_hexapod(pybind11::module_& m);     // bind_hexapod.cpp: Hexapod, WorkspaceCheck, LegViolation
void bind_frames(pybind11::module_& m);      // bind_frames.cpp: WorkToolFrames
void bind_serial(pybind11::module_& m);      // bind_serial*.cpp: SerialArm, JointLimits, InverseResult (if built)
void bind_retiming(pybind11::module_& m);    // bind_retiming.cpp: check_joint_limits, retime (if built)
void bind_ptp(pybind11::module_& m);         // bind_ptp.cpp: JointTrajectory, plan(JointPath, ..., robot=) (if built)

}  // namespace python
}  // namespace dispkin
