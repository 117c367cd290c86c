// The rows of the C++ bad-input table (tests/cpp/test_bad_input_table.cpp) of one area: WorkToolFrames.
#include "rows.hpp"

namespace bad_input {

void frames_rows(std::vector<Row>& table) {
  const RowAdder row{table};
  // --- WorkToolFrames ---
  row(
      "WorkToolFrames::add_tool_envelope", "zero radius",
      [] {
        MetricSetd s;
        WorkToolFrames().add_tool_envelope(s, 0.0);
      },
      IA, "radius = 0");
  row(
      "WorkToolFrames::add_tool_envelope", "NaN radius",
      [] {
        MetricSetd s;
        WorkToolFrames().add_tool_envelope(s, nan_, Envelope::sphere);
      },
      IA, "radius = nan");
  row(
      "WorkToolFrames::add_tool_envelope", "negative group",
      [] {
        MetricSetd s;
        WorkToolFrames().add_tool_envelope(s, 0.1, Envelope::icosahedron, -2);
      },
      IA, "group = -2");
  row(
      "WorkToolFrames::add_work_envelope", "negative radius",
      [] {
        MetricSetd s;
        WorkToolFrames().add_work_envelope(s, -0.1);
      },
      IA, "radius = -0.1");
  row(
      "WorkToolFrames::add_work_envelope", "+inf radius",
      [] {
        MetricSetd s;
        WorkToolFrames().add_work_envelope(s, inf_, Envelope::sphere);
      },
      IA, "radius = inf");
  row(
      "WorkToolFrames::platform_pose_xyzuvw", "NaN U",
      [] { WorkToolFrames().platform_pose_xyzuvw(v6(0, 0, 0, nan_, 0, 0)); }, IA, "xyzuvw = (0, 0, 0, nan, 0, 0)");
}

}  // namespace bad_input
