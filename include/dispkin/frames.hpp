//! Work and tool coordinate systems, and the metric sets generated around their origins (the
//! "special coordinate systems" of the DISP patent JP7742490B2).
//!
//! Conventions (as PI hexapod controllers use them): the work frame W is given in world (base)
//! coordinates and stays put, e.g. attached to the workpiece; the tool frame F is given in body
//! (platform) coordinates and moves with the platform, e.g. at a fibre end or a cutter tip. A
//! command is the pose X of the tool frame expressed in the work frame; the platform pose T
//! that realises it satisfies W X = T F, so
//!   T = W · X · F⁻¹   and   X = W⁻¹ · T · F.
//! XYZUVW commands in these frames rotate about the tool origin: the pivot of the platform is
//! F's origin, pivot() (platform coordinates), for Pose::from_xyzuvw and for paths.
//!
//! Generated metric sets (the DISP patent): points around the tool origin are relative points (they
//! move with the tool and set its speed; a sphere there ties the angular speed to the system
//! velocity through its radius), points around the work origin are absolute points (they stay put
//! and hold anything near their convex hull to the speed limit).
#pragma once

#include <vector>

#include <Eigen/Core>

#include "dispkin/error.hpp"
#include "dispkin/metric_set.hpp"
#include "dispkin/pose.hpp"
#include "dispkin/shapes.hpp"

namespace dispkin {

//! What is put around a frame's origin: a circumscribed regular icosahedron (12 points that
//! contain the sphere, doc/disp-metric.md eq. 26) or the exact sphere.
enum class Envelope { icosahedron, sphere };

//! The envelope's name: "icosahedron" or "sphere".
inline const char* to_string(Envelope envelope) { return envelope == Envelope::icosahedron ? "icosahedron" : "sphere"; }

//! A work frame (world coordinates) and a tool frame (platform coordinates). Both are any rigid
//! poses; identity for both makes the platform pose the command.
class WorkToolFrames {
 public:
  using Vector6 = Eigen::Matrix<double, 6, 1>;  //!< XYZUVW (m, rad)

  //! Identity work and tool frames.
  WorkToolFrames() = default;
  //! The work frame W (world coordinates) and the tool frame F (platform coordinates).
  WorkToolFrames(const Posed& work, const Posed& tool) : work_(work), tool_(tool) {}

  const Posed& work() const noexcept { return work_; }  //!< W: work frame → world
  const Posed& tool() const noexcept { return tool_; }  //!< F: tool frame → platform

  //! The platform pose T = W X F⁻¹ that puts the tool frame at `tool_in_work` in the work frame.
  Posed platform_pose(const Posed& tool_in_work) const noexcept { return work_ * tool_in_work * tool_.inverse(); }
  //! The tool frame's pose in the work frame, X = W⁻¹ T F, at platform pose `platform`.
  Posed tool_in_work(const Posed& platform) const noexcept { return work_.inverse() * platform * tool_; }

  //! The platform pose for an XYZUVW command of the tool frame in the work frame (U, V, W
  //! about the tool origin, Pose::from_xyzuvw's convention). Throws for non-finite input.
  Posed platform_pose_xyzuvw(const Vector6& xyzuvw) const { return platform_pose(Posed::from_xyzuvw(xyzuvw)); }
  //! The XYZUVW of the tool frame in the work frame at platform pose `platform`.
  Vector6 xyzuvw(const Posed& platform) const { return tool_in_work(platform).to_xyzuvw(); }

  //! The tool origin in platform coordinates: the pivot for paths commanded in these frames.
  Eigen::Vector3d pivot() const { return tool_.translation(); }

  //! Adds an envelope of `radius` (m) around the tool origin as relative objects of `group`
  //! (the icosahedron turned with the tool frame). Throws std::invalid_argument for a radius
  //! that is not finite and positive or a negative group.
  void add_tool_envelope(MetricSetd& set, double radius, Envelope envelope = Envelope::icosahedron,
                         int group = 0) const {
    add_envelope(set, tool_, radius, envelope, Frame::relative, group);
  }
  //! Adds an envelope of `radius` (m) around the work origin as absolute objects of `group`.
  void add_work_envelope(MetricSetd& set, double radius, Envelope envelope = Envelope::icosahedron,
                         int group = 0) const {
    add_envelope(set, work_, radius, envelope, Frame::absolute, group);
  }

 private:
  static void add_envelope(MetricSetd& set, const Posed& frame, double radius, Envelope envelope, Frame where,
                           int group) {
    require_positive(radius, "radius");
    if (envelope == Envelope::sphere) {
      set.add_sphere(frame.translation(), radius, where, group);
      return;
    }
    std::vector<Eigen::Vector3d> points = shapes::icosahedron(radius);
    for (Eigen::Vector3d& p : points) p = frame * p;
    set.add_points(points, where, group);
  }

  Posed work_;
  Posed tool_;
};

}  // namespace dispkin
