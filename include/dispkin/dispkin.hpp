//! dispkin: trajectory planning under a point-set speed limit. The whole public API.
#pragma once

#include "dispkin/version.hpp"
#include "dispkin/error.hpp"
#include "dispkin/input_budget.hpp"
#include "dispkin/pose.hpp"
#include "dispkin/metric_set.hpp"
#include "dispkin/shapes.hpp"
#include "dispkin/disp.hpp"
#include "dispkin/convex_hull.hpp"
#include "dispkin/path/curve_section.hpp"
#include "dispkin/path/path.hpp"
#include "dispkin/profile.hpp"
#include "dispkin/planning/motion_stream.hpp"
#include "dispkin/planning/planner.hpp"
#include "dispkin/planning/overlap.hpp"
#include "dispkin/planning/retiming.hpp"
#include "dispkin/kinematics.hpp"
#include "dispkin/frames.hpp"
#include "dispkin/hexapod/hexapod.hpp"
#include "dispkin/hexapod/hexapod_retiming.hpp"
#if defined(DISPKIN_HAS_SERIAL)  // set by dispkin::dispkin when the serial-arm plugin is built
#include "dispkin/serial/serial_arm.hpp"
#include "dispkin/serial/ptp.hpp"
#include "dispkin/serial/serial_retiming.hpp"
#endif
