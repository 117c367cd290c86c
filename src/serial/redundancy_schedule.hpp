// The redundancy parameter θ(s) of a seven-joint arm along a planned path, moved by the rule of
// doc/inverse-kinematics.md §12 (internal to the serial plugin; doc/inverse-kinematics.md §14,
// eqs. 49–50): what FollowedTrajectory, the joint-limit check and re-timing by scaling solve at.
#pragma once

#include <cstddef>
#include <vector>

#include <Eigen/Core>

#include "dispkin/path/sampled_path.hpp"
#include "dispkin/serial/serial_arm.hpp"

namespace dispkin::serial::detail {

//! θ(s) on nodes along a path: per section k, n_k = ⌈L_k / spacing⌉ equal intervals in τ (the
//! grid FollowedTrajectory starts from, so its refined nodes keep every interval of this one
//! whole), θ and θ′ = dθ/ds at each node, a cubic Hermite polynomial between them
//! (doc/inverse-kinematics.md eq. 50). Empty (moves() false) where the parameter is held.
class RedundancySchedule {
 public:
  //! θ, dθ/ds (rad/m) and d²θ/ds² (rad/m²) at one path position.
  struct State {
    double value = 0.0, rate = 0.0, curvature = 0.0;
  };

  //! None: the parameter held at one value.
  RedundancySchedule() = default;
  //! The parameter of `arm` along `path` from q_given at its start (backwards: at its end), moved
  //! by `rule` (doc/inverse-kinematics.md eq. 49); none when the arm has no parameter or rule.move
  //! is false. Throws std::runtime_error naming the path position where the pose has no solution
  //! at the parameter value reached, or the arm is singular.
  RedundancySchedule(const SampledPath& path, const SerialArm& arm, const Eigen::VectorXd& q_given, bool backwards,
                     double spacing, const RedundancyRule& rule);

  //! Whether the parameter moves along the path.
  bool moves() const noexcept { return !value_.empty(); }
  //! The state at τ ∈ [0, 1] of section k (clamped).
  State at(std::size_t k, double tau) const noexcept;
  //! The state at path position s (clamped to the path).
  State at(double s) const noexcept;
  //! The lowest and highest d²θ/ds² (rad/m²) on the pieces of doc/inverse-kinematics.md eq. 50
  //! that [s0, s1] touches (clamped to the path; s0 ≤ s1): θ″ steps at the nodes.
  void curvature_range(double s0, double s1, double& low, double& high) const noexcept;
  //! q with its parameter joint set to θ: the reference whose value branch_solution solves at
  //! (branch_following.cpp) and whose other joints pick the branch.
  Eigen::VectorXd reference(const Eigen::VectorXd& q, double theta) const;

 private:
  struct SectionNodes {
    double start, length;  // s_k and L_k
    std::size_t first;     // its nodes first … first + intervals
    int intervals;
  };
  int joint_ = -1;
  // The section holding s and its piece there (both clamped).
  void piece_at(double s, std::size_t& k, int& i) const noexcept;

  std::vector<SectionNodes> sections_;
  std::vector<double> value_, rate_;  // θ_i and dθ/ds at node i
};

}  // namespace dispkin::serial::detail
