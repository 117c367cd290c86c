// Seeded random cases for the sweeps: seed and count come from DISPKIN_TEST_SEED and
// DISPKIN_TEST_COUNT so a failure can be replayed and a long sweep run on demand.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include <dispkin/metric_set.hpp>
#include <dispkin/pose.hpp>

namespace dispkin::testing {

inline unsigned long env_or(const char* name, unsigned long fallback) {
  const char* text = std::getenv(name);
  return text ? std::stoul(text) : fallback;
}

//! Cases per sweep: DISPKIN_TEST_COUNT, else `fallback` (the CI size), at most
//! DISPKIN_TEST_COUNT_CAP (the sanitizer builds cap the large suites without raising the small).
inline int case_count(int fallback) {
  const unsigned long count = env_or("DISPKIN_TEST_COUNT", static_cast<unsigned long>(fallback));
  return static_cast<int>(std::min(count, env_or("DISPKIN_TEST_COUNT_CAP", count)));
}

//! The message of the std::invalid_argument that `f` throws, or "<no exception>".
template <typename F>
std::string message_of(F&& f) {
  try {
    f();
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "<no exception>";
}

//! The message of the std::runtime_error that `f` throws, or "<no exception>".
template <typename F>
std::string runtime_message_of(F&& f) {
  try {
    f();
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "<no exception>";
}

class Random {
 public:
  explicit Random(unsigned long salt) : engine_(env_or("DISPKIN_TEST_SEED", 20261122UL) * 7919UL + salt) {}

  double uniform(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(engine_); }
  int integer(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(engine_); }
  Eigen::Vector3d vector(double scale) {
    return Eigen::Vector3d(uniform(-scale, scale), uniform(-scale, scale), uniform(-scale, scale));
  }
  Eigen::Vector3d unit_vector() {
    std::normal_distribution<double> n(0.0, 1.0);
    Eigen::Vector3d v(n(engine_), n(engine_), n(engine_));
    return v.normalized();
  }
  Eigen::Quaterniond rotation() {
    std::normal_distribution<double> n(0.0, 1.0);
    Eigen::Quaterniond q(n(engine_), n(engine_), n(engine_), n(engine_));
    return q.normalized();
  }
  Posed pose(double scale = 1.0) { return Posed(rotation(), vector(scale)); }
  //! b = a moved by a random amount: translation up to `step`, rotation up to `max_angle`.
  Posed nearby(const Posed& a, double step, double max_angle) {
    const Eigen::Vector3d w = unit_vector() * uniform(0.0, max_angle);
    return a * Posed::exp(Twistd(vector(step), w));
  }
  //! A random well-formed set: relative points (≥ 3, not collinear), maybe absolute points,
  //! spheres and a second group with its own limit.
  MetricSetd metric_set(bool with_groups = true) {
    MetricSetd set;
    const int relative = integer(3, 8);
    for (int i = 0; i < relative; ++i) set.add_relative(vector(0.5));
    if (integer(0, 1)) {
      for (int i = integer(1, 4); i > 0; --i) set.add_absolute(vector(1.0), with_groups ? integer(0, 1) : 0);
    }
    if (integer(0, 1))
      set.add_sphere(vector(0.3), uniform(0.0, 0.2), integer(0, 1) ? Frame::relative : Frame::absolute);
    if (with_groups && integer(0, 1)) {
      set.add_relative(vector(0.5), 1);
      set.set_group_speed(1, uniform(0.2, 2.0));
    }
    return set;
  }
  std::mt19937_64& engine() { return engine_; }

 private:
  std::mt19937_64 engine_;
};

}  // namespace dispkin::testing
