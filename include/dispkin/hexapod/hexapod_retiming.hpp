//! Joint-limit prediction and re-timing of Cartesian trajectories for a hexapod, whose legs are
//! its joints: q = the leg lengths (its inverse kinematics, unique), q̇ = J_leg ξ_b, limits
//! leg_speed() and [leg_min, leg_max]; no dynamics model (doc/retiming.md). The generic parts are
//! in planning/retiming.hpp.
#pragma once

#include <memory>

#include "dispkin/hexapod/hexapod.hpp"
#include "dispkin/metric_set.hpp"
#include "dispkin/path/path.hpp"
#include "dispkin/planning/planner.hpp"
#include "dispkin/planning/retiming.hpp"

namespace dispkin::hexapod {

//! Follows `trajectory` with the hexapod's legs as its joints: q = the leg lengths (its inverse kinematics,
//! unique), q̇ = J_leg ξ_b, q̈ by central differences; velocity_factor against leg_speed(),
//! position_excess against [leg_min, leg_max]. No dynamics model: the torques stay empty and
//! acceleration_factor 0. Throws std::invalid_argument for bad options.
JointLimitReport check_joint_limits(const Trajectory& trajectory, const Hexapod& hexapod,
                                    const JointCheckOptions& options = {});

//! retime_optimal (planning/retiming.hpp) for a hexapod: the legs are the joints (leg_speed() and
//! options.joint_acceleration as their limits; no torques), followed from the home pose's leg
//! lengths, and a leg that leaves its length range is an error naming it.
OptimalRetimeResult retime_optimal(const Path& path, const MetricSetd& set, const Limits& limits,
                                   const Hexapod& hexapod, const OptimalRetimeOptions& options = {});

//! The hexapod as a JointModel (legs as joints, no torques). Holds a reference to `hexapod`,
//! which must outlive it.
std::unique_ptr<JointModel> joint_model(const Hexapod& hexapod);

}  // namespace dispkin::hexapod
