//! dispkin: trajectory planning under a point-set speed limit. The whole public API.
#pragma once

#include "dispkin/version.hpp"
#include "dispkin/error.hpp"
#include "dispkin/pose.hpp"
#include "dispkin/metric_set.hpp"
#include "dispkin/shapes.hpp"
#include "dispkin/disp.hpp"
#include "dispkin/convex_hull.hpp"
#include "dispkin/curve_section.hpp"
#include "dispkin/path.hpp"
#include "dispkin/profile.hpp"
#include "dispkin/planner.hpp"
#include "dispkin/overlap.hpp"
#include "dispkin/kinematics.hpp"
#include "dispkin/hexapod.hpp"
#include "dispkin/frames.hpp"
#if defined(DISPKIN_HAS_SERIAL)  // set by dispkin::dispkin when the serial-arm plugin is built
#include "dispkin/serial/serial_arm.hpp"
#include "dispkin/retiming.hpp"
#include "dispkin/ptp.hpp"
#endif
