// The deprecated header dispkin/input_limits.hpp forwards to dispkin/input_budget.hpp: code that
// names dispkin::input_limits still compiles and reads the same budget.
#include <gtest/gtest.h>

#include <dispkin/input_limits.hpp>

namespace dispkin {
namespace {

TEST(InputBudget, TheFormerNamespaceNamesTheSameBudget) {
  EXPECT_EQ(&input_limits::max_nesting_depth, &input_budget::max_nesting_depth);
  EXPECT_EQ(&input_limits::max_urdf_bytes, &input_budget::max_urdf_bytes);
  EXPECT_EQ(&input_limits::max_ik_solutions, &input_budget::max_ik_solutions);
}

}  // namespace
}  // namespace dispkin
