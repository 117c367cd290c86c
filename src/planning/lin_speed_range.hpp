// The range of the fastest object's speed along a part of a decoupled LIN, exactly: the largest
// and a lower bound of the smallest weighted speed per unit τ over τ ∈ [t₀, t₁]
// (doc/planning.md §9, eqs. 27–31). The planner cuts a LIN where this range is wider than its
// cruise allows (append_cut, planner.cpp); the largest is the piece's length.
#pragma once

#include <Eigen/Core>

#include "dispkin/path/group_factors.hpp"
#include "dispkin/path/path.hpp"
#include "dispkin/path/section_motion.hpp"

namespace dispkin {
namespace detail {

//! Speeds per unit τ of the whole LIN, each group's multiplied by its weight.
struct SpeedRange {
  double low = 0.0;   //!< ≤ the fastest object's speed at every τ of the part
  double high = 0.0;  //!< the fastest object's largest speed over the part (exact to rounding)
};

//! A decoupled LIN prepared once for the speed ranges of its parts. In the body frame of the
//! start the pivot's velocity Δc is seen turning backwards about the rotation axis k while
//! every body object's own term Ω × (r − p) stands still (doc/planning.md eq. 27); absolute objects see an
//! apparent velocity affine in τ (doc/planning.md eq. 30).
class DecoupledSpeeds {
 public:
  DecoupledSpeeds(const LinSection& lin, const GroupFactors& factors) noexcept;

  //! The range over τ ∈ [t0, t1] ⊂ [0, 1].
  SpeedRange range(double t0, double t1) const noexcept;

 private:
  // Δc⊥ seen from the body at τ (doc/planning.md eq. 27), remembered for the last two τ asked.
  Eigen::Vector3d across_at(double t) const noexcept;

  const GroupFactors* factors_;
  Eigen::Vector3d omega_;   // Ω = θ k, body frame of the start
  Eigen::Vector3d k_;       // unit rotation axis (body); any unit vector without rotation
  Eigen::Vector3d across_;  // Δc⊥ at τ = 0 (body), and k × Δc⊥
  Eigen::Vector3d across_side_;
  Eigen::Vector3d pivot_;  // p (body)
  double theta_ = 0.0, along_ = 0.0, across_size_ = 0.0;
  // World view of absolute objects: g(τ) = Δc + Ω_w × (x − c₀) − τ Ω_w × Δc (doc/planning.md eq. 30).
  Eigen::Vector3d delta_c_, omega_world_, w_hat_, pivot_start_, drift_;
  double along_world_ = 0.0;
  struct TurnMemo {
    double t;
    Eigen::Vector3d across;
  };
  mutable TurnMemo turns_[2] = {{-1.0, Eigen::Vector3d::Zero()}, {-1.0, Eigen::Vector3d::Zero()}};
  mutable int next_turn_ = 0;
};

}  // namespace detail
}  // namespace dispkin
