// Analytic inverse kinematics of 6R chains (see include/dispkin/serial/analytic_ik.hpp).
#include "dispkin/serial/analytic_ik.hpp"
