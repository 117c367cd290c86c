// Hexapod leg speeds along a planned path: bounds of the leg rates over a section, the section
// lengths that keep every leg within its speed, and the joint metric of a whole path.
// Part of the umbrella library, not of dispkin::hexapod: it samples path sections (section
// poses, twists, lengths and motion bounds of curved sections), which the umbrella defines, so
// a program linking only the hexapod plugin statically needs nothing from the umbrella.
#include <algorithm>
#include <cmath>
#include <type_traits>
#include <variant>

#include "dispkin/hexapod/hexapod.hpp"
#include "dispkin/path/path.hpp"

namespace dispkin::hexapod {

namespace {

// A ≥ the acceleration per unit τ² of every platform joint along the section (see
// Hexapod::leg_rate_bounds), +∞ for a section kind without a closed form here.
double joint_acceleration_bound(const Section& section, const Hexapod::Joints& platform) {
  return std::visit(
      [&platform](const auto& s) -> double {
        using Kind = std::decay_t<decltype(s)>;
        // Distance of the joints from the pivot bounds their distance from any axis through it.
        auto reach = [&platform](const Eigen::Vector3d& pivot) {
          return (platform.colwise() - pivot).colwise().norm().maxCoeff();
        };
        if constexpr (std::is_same_v<Kind, LinSection>) {
          if (s.interpolation == Interpolation::screw) {
            // Constant body twist: p̈ = R ω × (v + ω × p).
            const Twistd xi = (s.start.inverse() * s.end).log();
            double a = 0.0;
            for (int j = 0; j < 6; ++j) {
              const Eigen::Vector3d p = platform.col(j);
              a = std::max(a, xi.angular.cross(xi.linear + xi.angular.cross(p)).norm());
            }
            return a;
          }
          // Pivot at constant velocity, rotation by θ about a fixed axis: ‖p̈‖ = θ² ρ.
          const double theta =
              quaternion_log(Eigen::Quaterniond(s.start.quaternion().conjugate() * s.end.quaternion())).norm();
          return theta * theta * reach(s.pivot);
        } else if constexpr (std::is_same_v<Kind, ArcSection>) {
          // Centripetal acceleration of the pivot plus that of the rotation about it.
          const double radius = (s.start * s.pivot - s.center).norm();
          return s.angle * s.angle * radius + s.rotation_angle * s.rotation_angle * reach(s.pivot);
        } else {
          // A curved section (SPLINE, blend): ‖p̈‖ ≤ |c̈| + (|ω̇| + |ω|²) ρ from its motion bounds.
          const MotionBounds b = s.motion_bounds();
          return b.pivot_acceleration + (b.omega_dot + b.omega * b.omega) * reach(s.pivot);
        }
      },
      section);
}

// Rates dℓ_i/dτ and lengths ℓ_i on the grid τ_k = k/n, k = 0…n (one column per τ_k).
struct LegSamples {
  Eigen::Matrix<double, 6, Eigen::Dynamic> rate, length;
};

LegSamples sample_legs(const Hexapod& hexapod, const Section& section, long n) {
  LegSamples out{Eigen::Matrix<double, 6, Eigen::Dynamic>(6, n + 1),
                 Eigen::Matrix<double, 6, Eigen::Dynamic>(6, n + 1)};
  for (long k = 0; k <= n; ++k) {
    const double tau = static_cast<double>(k) / static_cast<double>(n);
    const Posed pose = section_pose(section, tau);
    out.length.col(k) = hexapod.leg_lengths(pose);
    out.rate.col(k) = hexapod.leg_jacobian(pose) * section_twist(section, tau).vector();
  }
  return out;
}

}  // namespace

Hexapod::Legs Hexapod::leg_rate_bounds(const Section& section, double tolerance) const {
  require(std::isfinite(tolerance) && tolerance > 0.0 && tolerance <= 1.0, "tolerance", tolerance, "must be in (0, 1]");
  constexpr long min_samples = 64, max_samples = 65536;
  MetricSetd joints;
  for (int j = 0; j < 6; ++j) joints.add_relative(Eigen::Vector3d(platform_.col(j)));
  const double v = section_length(section, joints);
  const double a = joint_acceleration_bound(section, platform_);
  const Legs fallback = Legs::Constant(v);
  if (!std::isfinite(a) || v == 0.0) return fallback;  // no closed form, or no joint moves

  // M_i for a grid of n intervals; +∞ where the leg might reach zero length.
  auto curvature_bounds = [&](const LegSamples& samples, long n) {
    const double h = 1.0 / static_cast<double>(n);
    Legs m;
    for (int i = 0; i < 6; ++i) {
      const double shortest = samples.length.row(i).minCoeff() - v * h / 2;
      m(i) = shortest > 0.0 ? a + v * v / shortest : std::numeric_limits<double>::infinity();
    }
    return m;
  };
  // The grid size from a coarse pass: M_i (from the coarse grid's looser ℓ_low) and the demand.
  const LegSamples coarse = sample_legs(*this, section, min_samples);
  const Legs m_coarse = curvature_bounds(coarse, min_samples);
  const double demand = (coarse.rate.cwiseAbs().rowwise().maxCoeff().array() / leg_speed_.array()).maxCoeff();
  double wanted = 0.0;  // N ≥ max_i (M_i / speed_i) / (2 tolerance · demand)
  for (int i = 0; i < 6; ++i) {
    if (std::isfinite(m_coarse(i))) wanted = std::max(wanted, m_coarse(i) / leg_speed_(i) / (2.0 * tolerance * demand));
  }
  const long n = !(wanted < static_cast<double>(max_samples))
                     ? max_samples
                     : std::max(min_samples, static_cast<long>(std::ceil(wanted)));
  const LegSamples fine = n == min_samples ? coarse : sample_legs(*this, section, n);
  const Legs m = curvature_bounds(fine, n);
  const double h = 1.0 / static_cast<double>(n);
  Legs bound;
  for (int i = 0; i < 6; ++i) {
    if (!std::isfinite(m(i))) {
      bound(i) = v;
      continue;
    }
    const Eigen::ArrayXd g = fine.rate.row(i).transpose().array().abs();
    const double interval_max = (g.head(n) + g.tail(n)).maxCoeff();
    bound(i) = std::min(v, (interval_max + m(i) * h) / 2);
  }
  return bound;
}

std::vector<double> Hexapod::leg_section_lengths(const Path& path, double system_velocity, double tolerance) const {
  require_positive(system_velocity, "system_velocity");
  std::vector<double> out;
  out.reserve(path.size());
  for (const Section& section : path.sections()) {
    const Legs rates = leg_rate_bounds(section, tolerance);
    out.push_back(system_velocity * (rates.array() / leg_speed_.array()).maxCoeff());
  }
  return out;
}

namespace {

// Whether the path runs on smoothly from section k to k + 1: the twists per unit τ at the
// junction point the same way (to 1e-9, tighter than the planner's 1e-6 test, so that equal
// speeds there are accepted as tangent-continuous by the planner).
bool same_direction(const Twistd& out, const Twistd& in) {
  const Eigen::Matrix<double, 6, 1> a = out.vector(), b = in.vector();
  const double na = a.norm(), nb = b.norm();
  return na > 0.0 && nb > 0.0 && (a / na - b / nb).norm() <= 1e-9;
}

}  // namespace

PlanOptions Hexapod::joint_metric(const Path& path, const Limits& limits) const {
  const std::vector<double> needed = leg_section_lengths(path, limits.velocity);
  const std::vector<Section>& sections = path.sections();
  // Along a run of sections that continue one another, the planner passes the junctions at
  // speed only if the twist per unit of s, ξ_k/L_k, is continuous: L_{k+1}/L_k = ‖ξ_{k+1}(0)‖ /
  // ‖ξ_k(1)‖ =: c_{k+1}/c_k. So a run gets lengths λ c_k with λ = max_k needed_k / c_k: never
  // shorter than needed, and continuous wherever the DISP lengths are (if they dominate).
  PlanOptions options;
  options.min_section_lengths.resize(needed.size());
  std::size_t first = 0;
  std::vector<double> scale(needed.size(), 1.0);
  for (std::size_t k = 0; k < needed.size(); ++k) {
    const bool run_ends =
        k + 1 == needed.size() || !same_direction(section_twist(sections[k], 1.0), section_twist(sections[k + 1], 0.0));
    if (!run_ends) {
      scale[k + 1] = scale[k] * section_twist(sections[k + 1], 0.0).vector().norm() /
                     section_twist(sections[k], 1.0).vector().norm();
      continue;
    }
    double lambda = 0.0;
    for (std::size_t j = first; j <= k; ++j) lambda = std::max(lambda, needed[j] / scale[j]);
    for (std::size_t j = first; j <= k; ++j) options.min_section_lengths[j] = std::max(needed[j], lambda * scale[j]);
    first = k + 1;
  }
  return options;
}

JointMetric Hexapod::joint_metric() const {
  return [hexapod = *this](const Path& path, const Limits& limits) {
    return hexapod.joint_metric(path, limits).min_section_lengths;
  };
}

}  // namespace dispkin::hexapod
