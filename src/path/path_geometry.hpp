// Geometry shared by the path builders (path.cpp, spline.cpp, blend.cpp); internal.
#pragma once

#include <algorithm>
#include <cmath>
#include <type_traits>
#include <variant>

#include "dispkin/path/path.hpp"

namespace dispkin {
namespace detail {

// The geometric size of a section, the weight of its share of the path parameter u: pivot
// travel plus 0.1 m per radian of rotation (so that pure rotations get a share too).
constexpr double metres_per_radian = 0.1;

inline double rotation_angle(const Posed& a, const Posed& b) {
  return quaternion_log(Eigen::Quaterniond(a.quaternion().conjugate() * b.quaternion())).norm();
}

inline double geometric_size(const Section& section) {
  return std::visit(
      [](const auto& s) -> double {
        using T = std::decay_t<decltype(s)>;
        if constexpr (std::is_same_v<T, LinSection>) {
          return ((s.end * s.pivot) - (s.start * s.pivot)).norm() + metres_per_radian * rotation_angle(s.start, s.end);
        } else if constexpr (std::is_same_v<T, CurveSection> || std::is_same_v<T, SlerpBlendSection>) {
          // The chord: sections of a curve are short, cut to a small velocity deviation.
          const Posed a = s.pose(0.0), b = s.pose(1.0);
          return ((b * s.pivot) - (a * s.pivot)).norm() + metres_per_radian * rotation_angle(a, b);
        } else {
          const double radius = ((s.start * s.pivot) - s.center).norm();
          return std::abs(s.angle) * radius + metres_per_radian * std::abs(s.rotation_angle);
        }
      },
      section);
}

// How many equal-v sections a curve is cut into where its speed ranges over [low, high]
// (doc/section-length.md eq. 29): one per `tolerance` of relative variation, so that each
// section's fastest object cruises within about `tolerance` of its bound; at most 10⁵.
inline int sections_for_speed_range(double low, double high, double tolerance) {
  const double wanted = high > 0.0 ? std::ceil((high - low) / (tolerance * high)) : 1.0;
  return static_cast<int>(std::clamp(std::isfinite(wanted) ? wanted : 1.0, 1.0, 100000.0));
}

//! The part τ ∈ [t0, t1] of a section, as a section of the same kind run over its own τ.
inline Section section_part(const Section& section, double t0, double t1) {
  return std::visit(
      [&](const auto& s) -> Section {
        using T = std::decay_t<decltype(s)>;
        if constexpr (std::is_same_v<T, LinSection>) {
          // A sub-piece of a line with SLERP (or of a screw) is the same motion between its ends.
          return LinSection{s.pose(t0), s.pose(t1), s.interpolation, s.pivot};
        } else if constexpr (std::is_same_v<T, ArcSection>) {
          ArcSection part = s;
          part.start = s.pose(t0);
          part.angle = s.angle * (t1 - t0);
          part.rotation_angle = s.rotation_angle * (t1 - t0);
          return part;
        } else {
          // A part of a curve (cubic or nested SLERP): the same curve over a part of its v.
          T part = s;
          part.v0 = s.v0 + t0 * s.span();
          part.v1 = s.v0 + t1 * s.span();
          return part;
        }
      },
      section);
}

//! The curve parameter at τ of a curve or nested-SLERP section as the planner cuts it:
//! v₀ + τ h, and the section's own v₁ at τ = 1 (so that the last part ends where the section does).
template <class Curve>
double cut_parameter(const Curve& curve, double tau) {
  return tau >= 1.0 ? curve.v1 : curve.v0 + tau * curve.span();
}

//! The part τ ∈ [t0, t1] of a section as the planner cuts it (doc/planning.md §9): the section
//! itself when whole; else as section_part, but with the section's own ends at τ = 0 and 1 (a
//! LIN's poses, a curve's v₁), so that the part that ends a section ends where the section does,
//! bit for bit.
inline Section planned_part(const Section& section, double t0, double t1) {
  if (t0 == 0.0 && t1 == 1.0) return section;
  return std::visit(
      [&](const auto& s) -> Section {
        using T = std::decay_t<decltype(s)>;
        if constexpr (std::is_same_v<T, LinSection>) {
          return LinSection{t0 == 0.0 ? s.start : s.pose(t0), t1 >= 1.0 ? s.end : s.pose(t1), s.interpolation, s.pivot};
        } else if constexpr (std::is_same_v<T, ArcSection>) {
          return detail::section_part(section, t0, t1);
        } else {
          T part = s;
          part.v0 = cut_parameter(s, t0);
          part.v1 = cut_parameter(s, t1);
          return part;
        }
      },
      section);
}

}  // namespace detail
}  // namespace dispkin
