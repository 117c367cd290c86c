// The bad-input table, C++ side: every public entry point × every kind of bad input (NaN, ±inf,
// empty, wrong size, zero or negative limits, degenerate sets, unreachable poses, out-of-range
// legs, malformed files, unknown names), one row each. A row asserts the exception type
// (std::invalid_argument / std::runtime_error) AND a fragment of the message
// "<argument> = <value>: <reason>" that names the argument and shows the value.
//
// Rows with `observed` set are the known gaps ("strict xfail"): the entry point does NOT
// reject the input. Such a row passes while the input is still accepted and fails once the
// library starts rejecting it, so that the row is promoted. The Python table and the list in
// tests/BAD_INPUT.md are in tests/python/test_bad_input_table.py. The rows live in
// tests/cpp/bad_input/, one source per API area (rows.hpp lists them in the order of the table).
#include <algorithm>
#include <cctype>
#include <ostream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "bad_input/rows.hpp"

namespace {

using bad_input::Expect;
using bad_input::Row;

std::vector<Row> rows() {
  std::vector<Row> r;
  using namespace bad_input;
  pose_rows(r);
  metric_set_rows(r);
  disp_functions_rows(r);
  paths_rows(r);
  profiles_rows(r);
  planning_rows(r);
  hexapod_rows(r);
  frames_rows(r);
#if defined(DISPKIN_HAS_SERIAL)
  serial_arm_rows(r);
  joint_motion_rows(r);
#endif
  return r;
}

std::string row_name(const Row& row) {
  std::string name = row.entry + "_" + row.bad;
  std::string out;
  for (std::size_t i = 0; i < name.size(); ++i) {
    const char c = name[i];
    if (c == '+' && name.compare(i, 4, "+inf") == 0)
      out += "Pos";
    else if (c == '-' && name.compare(i, 4, "-inf") == 0)
      out += "Neg";
    else if (std::isalnum(static_cast<unsigned char>(c)))
      out += c;
    else if (!out.empty() && out.back() != '_')
      out += '_';
  }
  while (!out.empty() && out.back() == '_') out.pop_back();
  return out;
}

class BadInputRows : public ::testing::TestWithParam<Row> {};

TEST_P(BadInputRows, RejectsWithNamedArgumentAndValue) {
  const Row& row = GetParam();
  std::string what;
  bool invalid_argument = false, runtime_error = false, other = false, threw = false;
  try {
    row.call();
  } catch (const std::invalid_argument& e) {
    threw = invalid_argument = true;
    what = e.what();
  } catch (const std::runtime_error& e) {
    threw = runtime_error = true;
    what = e.what();
  } catch (const std::exception& e) {
    threw = other = true;
    what = e.what();
  }
  if (threw) RecordProperty("message", what);
  const bool right_type = row.expect == Expect::invalid_argument ? invalid_argument : runtime_error;
  const bool matches = threw && right_type && what.find(row.fragment) != std::string::npos;
  if (!row.observed.empty()) {
    // Strict xfail: the gap must still be there, else promote the row.
    EXPECT_FALSE(matches) << row.entry << " now rejects " << row.bad << " (" << what
                          << "): remove `observed` from this row";
    RecordProperty("xfail", row.observed);
    return;
  }
  ASSERT_TRUE(threw) << row.entry << " accepted " << row.bad;
  EXPECT_FALSE(other) << "unexpected exception type: " << what;
  EXPECT_TRUE(right_type) << "wrong exception type: " << what;
  EXPECT_NE(what.find(row.fragment), std::string::npos)
      << "message \"" << what << "\" lacks \"" << row.fragment << "\"";
}

INSTANTIATE_TEST_SUITE_P(BadInputTable, BadInputRows, ::testing::ValuesIn(rows()),
                         [](const ::testing::TestParamInfo<Row>& param) { return row_name(param.param); });

TEST(BadInputTableMeta, NamesAreUniqueAndGapsAreCounted) {
  const std::vector<Row> all = rows();
  std::vector<std::string> names;
  int gaps = 0;
  for (const Row& r : all) {
    names.push_back(row_name(r));
    if (!r.observed.empty()) ++gaps;
  }
  std::sort(names.begin(), names.end());
  EXPECT_EQ(std::adjacent_find(names.begin(), names.end()), names.end());
  RecordProperty("rows", static_cast<int>(all.size()));
  RecordProperty("not_rejected", gaps);
}

}  // namespace
