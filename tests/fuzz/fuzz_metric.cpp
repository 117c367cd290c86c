// libFuzzer target: a MetricSet built from fuzzed points, spheres, groups and group speeds,
// then disp_distance (all three norms), section_length (both interpolations) and
// max_point_speed at fuzzed poses and twists.
#include <cstddef>
#include <cstdint>
#include <optional>

#include <dispkin/disp.hpp>
#include <dispkin/metric_set.hpp>

#include "fuzz_input.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using dispkin::fuzz::check_finite;
  dispkin::fuzz::Input in(data, size);
  dispkin::MetricSetd set;
  // Building: each add may throw on its own bad argument; the set keeps what was accepted.
  const int objects = in.below(10);
  for (int i = 0; i < objects; ++i) {
    dispkin::fuzz::expect_clean([&] {
      const int group = in.below(4) - (in.below(16) == 0 ? 1 : 0);  // now and then a negative id
      switch (in.below(5)) {
        case 0:
          set.add_relative(in.vector3(), group);
          break;
        case 1:
          set.add_absolute(in.vector3(), group);
          break;
        case 2: {
          const Eigen::Vector3d c = in.vector3();
          const double radius = in.number();
          set.add_sphere(c, radius, in.flag() ? dispkin::Frame::relative : dispkin::Frame::absolute, group);
          break;
        }
        case 3: {
          std::vector<Eigen::Vector3d> points(static_cast<std::size_t>(in.below(4)));
          for (auto& p : points) p = in.vector3();
          set.add_points(points, in.flag() ? dispkin::Frame::relative : dispkin::Frame::absolute, group);
          break;
        }
        default:
          set.set_group_speed(group, in.number());
          break;
      }
    });
  }
  std::optional<double> system_velocity;
  if (in.flag()) system_velocity = in.number();

  for (int k = 0; k < 3; ++k) {
    dispkin::fuzz::expect_clean([&] {
      const dispkin::Posed a = in.pose();
      const dispkin::Posed b = in.pose();
      switch (in.below(6)) {
        case 0:
          check_finite(dispkin::disp_distance(set, a, b, system_velocity), "disp_distance (Euclidean)");
          break;
        case 1:
          check_finite(dispkin::disp_distance<dispkin::MaxNorm>(set, a, b, system_velocity), "disp_distance (max)");
          break;
        case 2:
          check_finite(dispkin::disp_distance<dispkin::L1Norm>(set, a, b, system_velocity), "disp_distance (L1)");
          break;
        case 3:
          check_finite(dispkin::section_length(set, a, b, dispkin::Interpolation::screw, in.vector3(), system_velocity),
                       "section_length (screw)");
          break;
        case 4:
          check_finite(
              dispkin::section_length(set, a, b, dispkin::Interpolation::decoupled, in.vector3(), system_velocity),
              "section_length (decoupled)");
          break;
        default: {
          const Eigen::Vector3d v = in.vector3(), w = in.vector3();
          const dispkin::Twistd xi(v, w);
          check_finite(dispkin::max_point_speed(set, a, xi, system_velocity), "max_point_speed");
          break;
        }
      }
    });
  }
  return 0;
}
