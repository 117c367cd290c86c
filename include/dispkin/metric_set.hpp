//! The metric establishment set: the points and spheres the speed limit applies to.
//!
//! doc/disp-metric.md §4. Relative points and spheres are given in body (tool) coordinates and move
//! with the tool; absolute points and spheres are given in world coordinates and stay put, their
//! apparent speed seen from the tool is what is limited. Objects belong to groups; a group may
//! carry its own speed limit (the DISP patent JP7742490B2, Fig. 18), the others are held to the
//! system velocity.
#pragma once

#include <algorithm>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Eigenvalues>

#include "dispkin/error.hpp"

namespace dispkin {

//! Which coordinates an object of the set is given in.
enum class Frame {
  relative,  //!< body coordinates: the object moves with the tool
  absolute,  //!< world coordinates: the object stays put
};

//! The frame's name: "relative" or "absolute".
inline const char* to_string(Frame frame) { return frame == Frame::relative ? "relative" : "absolute"; }

//! A ball of the set: every point of it is held to the group's limit (doc/disp-metric.md §7).
template <typename Scalar>
struct Sphere {
  //! Its centre, in the coordinates of its Frame.
  Eigen::Matrix<Scalar, 3, 1> center;
  Scalar radius;  //!< ≥ 0; a sphere of radius 0 is a point
};

//! Points stored as three coordinate columns (x…, y…, z…): the speed kernels then stream through
//! contiguous arrays and vectorise (doc/disp-metric.md eqs. 20, 23 evaluate one affine map per
//! point).
template <typename Scalar>
class PointColumns {
 public:
  using Vector3 = Eigen::Matrix<Scalar, 3, 1>;                               //!< a point
  using Column = Eigen::Map<const Eigen::Array<Scalar, Eigen::Dynamic, 1>>;  //!< one coordinate of every point

  //! Appends point p.
  void push_back(const Vector3& p) {
    x_.push_back(p.x());
    y_.push_back(p.y());
    z_.push_back(p.z());
  }
  std::size_t size() const noexcept { return x_.size(); }  //!< the number of points
  bool empty() const noexcept { return x_.empty(); }       //!< whether there is no point
  //! Point i (by value: the coordinates are stored apart).
  Vector3 operator[](std::size_t i) const noexcept { return Vector3(x_[i], y_[i], z_[i]); }

  //! The x, y and z coordinates of every point, as contiguous columns.
  //!@{
  Column x() const noexcept { return Column(x_.data(), static_cast<Eigen::Index>(x_.size())); }
  Column y() const noexcept { return Column(y_.data(), static_cast<Eigen::Index>(y_.size())); }
  Column z() const noexcept { return Column(z_.data(), static_cast<Eigen::Index>(z_.size())); }
  //!@}

  //! The points as vectors, in order.
  std::vector<Vector3> to_vectors() const {
    std::vector<Vector3> out;
    out.reserve(size());
    for (std::size_t i = 0; i < size(); ++i) out.push_back((*this)[i]);
    return out;
  }

  //! Iteration yields the points by value.
  class const_iterator {
   public:
    //! At point i of owner.
    const_iterator(const PointColumns* owner, std::size_t i) : owner_(owner), i_(i) {}
    Vector3 operator*() const { return (*owner_)[i_]; }  //!< the point
    //! The next point.
    const_iterator& operator++() {
      ++i_;
      return *this;
    }
    //! Whether the two stand at different points.
    bool operator!=(const const_iterator& other) const { return i_ != other.i_; }

   private:
    const PointColumns* owner_;
    std::size_t i_;
  };
  const_iterator begin() const { return const_iterator(this, 0); }     //!< at the first point
  const_iterator end() const { return const_iterator(this, size()); }  //!< past the last point

 private:
  std::vector<Scalar> x_, y_, z_;
};

//! One group of the set: its objects and, optionally, its own speed limit.
template <typename Scalar>
struct MetricGroup {
  using Vector3 = Eigen::Matrix<Scalar, 3, 1>;  //!< a point

  int id = 0;                                    //!< the group's number, ≥ 0
  std::optional<Scalar> speed_limit;             //!< unset: the group is held to the system velocity
  PointColumns<Scalar> relative_points;          //!< points in body coordinates
  PointColumns<Scalar> absolute_points;          //!< points in world coordinates
  std::vector<Sphere<Scalar>> relative_spheres;  //!< balls in body coordinates
  std::vector<Sphere<Scalar>> absolute_spheres;  //!< balls in world coordinates

  //! Whether the group holds no point and no sphere.
  bool empty() const {
    return relative_points.empty() && absolute_points.empty() && relative_spheres.empty() && absolute_spheres.empty();
  }

  //! The factor this group's lengths are multiplied by so that path speed ≤ v_sys keeps the group
  //! under its own limit: v_sys / v_g (doc/disp-metric.md eq. 17; the DISP patent's M3/M4), 1
  //! without a group limit.
  Scalar weight(std::optional<Scalar> system_velocity) const {
    if (!speed_limit) return Scalar(1);
    if (!system_velocity) {
      std::ostringstream why;
      why << "system_velocity is missing: group " << id << " has its own speed limit " << *speed_limit
          << ", and its lengths are weighted by system_velocity / " << *speed_limit;
      throw std::invalid_argument(why.str());
    }
    require_limit(*system_velocity, "system_velocity");
    return *system_velocity / *speed_limit;
  }
};

namespace detail {

//! Running first and second moments of a point cloud, shifted by its first point so the
//! covariance keeps its digits far from the origin. Enough to tell, in O(1), whether the
//! points are coincident, collinear or span a plane.
template <typename Scalar>
struct AffineSpan {
  using Vector3 = Eigen::Matrix<Scalar, 3, 1>;
  using Matrix3 = Eigen::Matrix<Scalar, 3, 3>;

  long count = 0;
  Vector3 shift = Vector3::Zero();
  Vector3 sum = Vector3::Zero();
  Matrix3 outer = Matrix3::Zero();
  bool has_ball = false;  // a sphere of positive radius spans space on its own

  void add(const Vector3& p) {
    if (count == 0) shift = p;
    const Vector3 x = p - shift;
    sum += x;
    outer += x * x.transpose();
    ++count;
  }

  //! Points affinely span at least a plane: the spread across their main line is more than
  //! 1e-7 of the spread along it. (The moments carry rounding of about 1e-16 of the variance,
  //! i.e. 1e-8 in spread, so a finer test would call exactly collinear points a plane; a set
  //! within 1e-7 of a line is numerically degenerate anyway: rotations about the line would
  //! barely register.)
  bool spans_plane() const {
    if (has_ball) return true;
    if (count < 3) return false;
    const Vector3 mean = sum / Scalar(count);
    const Matrix3 covariance = outer / Scalar(count) - mean * mean.transpose();
    Eigen::SelfAdjointEigenSolver<Matrix3> eig;
    eig.compute(covariance, Eigen::EigenvaluesOnly);  // iterative: computeDirect loses half the digits
    const Vector3 lambda = eig.eigenvalues();         // ascending
    return lambda(2) > Scalar(0) && lambda(1) > Scalar(1e-14) * lambda(2);
  }
};

}  // namespace detail

//! The metric establishment set. Mutable while it is being built; every DISP function reads
//! it through a const reference and allocates nothing.
template <typename Scalar>
class MetricSet {
 public:
  using Vector3 = Eigen::Matrix<Scalar, 3, 1>;  //!< a point
  using Group = MetricGroup<Scalar>;            //!< a group of the set

  //! A point moving with the tool, in body coordinates.
  void add_relative(const Vector3& point, int group = 0) { add_points({point}, Frame::relative, group); }
  //! Points moving with the tool, in body coordinates.
  void add_relative(const std::vector<Vector3>& points, int group = 0) { add_points(points, Frame::relative, group); }

  //! A fixed point of the world (a protected zone), in world coordinates.
  void add_absolute(const Vector3& point, int group = 0) { add_points({point}, Frame::absolute, group); }
  //! Fixed points of the world, in world coordinates.
  void add_absolute(const std::vector<Vector3>& points, int group = 0) { add_points(points, Frame::absolute, group); }

  //! Points in the given frame. Every coordinate must be finite and within ±1e12 m.
  void add_points(const std::vector<Vector3>& points, Frame frame, int group = 0) {
    for (std::size_t i = 0; i < points.size(); ++i) {
      if (!within_translation_range(points[i])) require_translation(points[i], "points[" + std::to_string(i) + "]");
    }
    Group& g = group_for(group);
    auto& target = frame == Frame::relative ? g.relative_points : g.absolute_points;
    auto& span = frame == Frame::relative ? relative_span_ : absolute_span_;
    for (const Vector3& p : points) {
      target.push_back(p);
      span.add(p);
    }
    update_well_formed();
  }

  //! A sphere (handled exactly, doc/disp-metric.md eq. 25), relative (body) or absolute (world)
  //! centre.
  void add_sphere(const Vector3& center, Scalar radius, Frame frame = Frame::relative, int group = 0) {
    require_translation(center, "center");
    using std::isfinite;
    require(isfinite(radius) && radius >= Scalar(0) && radius <= Scalar(numeric_range::max_translation), "radius",
            radius, "must be finite and not negative, at most 1e12 m (dispkin's numeric range)");
    Group& g = group_for(group);
    (frame == Frame::relative ? g.relative_spheres : g.absolute_spheres).push_back({center, radius});
    auto& span = frame == Frame::relative ? relative_span_ : absolute_span_;
    span.add(center);
    if (radius > Scalar(0)) span.has_ball = true;
    update_well_formed();
  }

  //! Give group `group` its own speed limit (it is created if it does not exist yet).
  void set_group_speed(int group, Scalar speed) {
    require_limit(speed, "speed");
    group_for(group).speed_limit = speed;
  }

  //! The groups, in increasing id.
  const std::vector<Group>& groups() const noexcept { return groups_; }

  //! The group with this id, or nullptr.
  const Group* find_group(int id) const noexcept {
    for (const Group& g : groups_)
      if (g.id == id) return &g;
    return nullptr;
  }

  //! The number of points, relative and absolute, of every group.
  std::size_t point_count() const noexcept {
    std::size_t n = 0;
    for (const Group& g : groups_) n += g.relative_points.size() + g.absolute_points.size();
    return n;
  }
  //! The number of spheres, relative and absolute, of every group.
  std::size_t sphere_count() const noexcept {
    std::size_t n = 0;
    for (const Group& g : groups_) n += g.relative_spheres.size() + g.absolute_spheres.size();
    return n;
  }
  //! Whether the set holds no point and no sphere.
  bool empty() const noexcept { return point_count() == 0 && sphere_count() == 0; }

  //! Whether the DISP distance over this set is a metric for every pair of poses
  //! (doc/disp-metric.md §4, "Well-formedness"): the relative part or the absolute part must on its
  //! own span at least a plane (or contain a sphere of positive radius). If both parts are
  //! collinear, some pose lines them up and a rotation about that line goes unseen.
  //! Cached when the set changes, so the DISP functions can check it at no cost.
  bool is_well_formed() const noexcept { return well_formed_; }

  //! Throws std::invalid_argument explaining why the set is not well-formed.
  void require_well_formed() const {
    if (is_well_formed()) return;
    std::string why;
    if (empty()) {
      why = "the set is empty";
    } else {
      why = "its relative part (" + part_summary(relative_span_) + ") and its absolute part (" +
            part_summary(absolute_span_) +
            ") are each at most collinear, so a rotation about their common line would have zero "
            "length; add a point off that line or a sphere of positive radius";
    }
    throw std::invalid_argument(describe("metric_set", std::string("MetricSet"), "is not well-formed: " + why));
  }

 private:
  static std::string part_summary(const detail::AffineSpan<Scalar>& span) {
    return std::to_string(span.count) + (span.count == 1 ? " object" : " objects");
  }

  Group& group_for(int id) {
    require(id >= 0, "group", id, "must be a non-negative integer");
    for (Group& g : groups_)
      if (g.id == id) return g;
    Group g;
    g.id = id;
    groups_.push_back(std::move(g));
    std::sort(groups_.begin(), groups_.end(), [](const Group& a, const Group& b) { return a.id < b.id; });
    for (Group& h : groups_)
      if (h.id == id) return h;
    return groups_.back();  // unreachable
  }

  void update_well_formed() { well_formed_ = relative_span_.spans_plane() || absolute_span_.spans_plane(); }

  std::vector<Group> groups_;
  bool well_formed_ = false;
  detail::AffineSpan<Scalar> relative_span_;
  detail::AffineSpan<Scalar> absolute_span_;
};

//! The metric set in double precision.
using MetricSetd = MetricSet<double>;

}  // namespace dispkin
