// Serial-arm plugin tests.
#include <gtest/gtest.h>
