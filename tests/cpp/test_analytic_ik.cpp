// Analytic IK tests.
#include <gtest/gtest.h>
