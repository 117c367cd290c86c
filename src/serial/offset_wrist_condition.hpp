// The offset wrist's condition (doc/inverse-kinematics.md §7): as q₆ = θ turns, the point w where
// axes 4 and 5 meet moves on a circle about axis 6; for each θ the positioning stage puts w with
// up to four branches of q₁, q₂, q₃, and the branch solves the pose iff the angle between axes 4
// and 5 is kept, f_b(θ) = ω₄ · R_rem ω₅ − ω₄ · ω₅ = 0 with R_rem = (R₁R₂R₃)ᵀ R_G'. What the search
// of ik_offset_wrist.cpp samples, brackets and refines: f_b and the positioning margins at θ,
// where the positioning stage gains or loses a branch, and the full q at a root. Internal to the
// analytic IK.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

#include <Eigen/Core>

#include "ik_internal.hpp"
#include "trig_polynomial.hpp"

namespace dispkin::serial::detail {

struct SolutionList {
  std::vector<Vector6d> q;
  int size() const { return static_cast<int>(q.size()); }
  const Vector6d& operator[](int i) const { return q[static_cast<std::size_t>(i)]; }
  void push(const Vector6d& x, double /*measured_error*/ = 0.0) { q.push_back(x); }
};

// f_b(θ) on the four branches.
struct Sample {
  std::array<bool, 4> exists{};
  std::array<double, 4> value{};
  std::array<double, 4> margin{};  // of the positioning stage (PositionSolutions::margin)
};

// A point or vector turning with q₆ = θ: a + cos θ b + sin θ c (R(k, ±θ) applied to a fixed
// vector has this form), so evaluating it costs six multiplications.
struct Turning {
  Eigen::Vector3d a, b, c;
  Eigen::Vector3d at(const CosSin& theta) const noexcept { return a + theta.c * b + theta.s * c; }
};

class OffsetWristSearch {
 public:
  OffsetWristSearch(const RevoluteChain& chain, const ChainGeometry& geometry, const Posed& pose)
      : chain_(chain),
        geometry_(geometry),
        pose_(pose),
        g_(pose * chain.tip_at_zero.inverse()),
        g_rotation_(g_.rotation()),
        cos_45_(chain.axes[3].dot(chain.axes[4])) {
    // The circle of w = axes 4 ∩ 5: G (R(ω₆, −θ)(w − p₆) + p₆), and R_G R(ω₆, −θ) ω₅, with
    // R(k, −θ) d = (k·d) k + cos θ d⊥ − sin θ k × d.
    const Eigen::Vector3d& k = chain.axes[5];
    const Eigen::Vector3d& p6 = chain.points[5];
    const Eigen::Vector3d d = geometry.point_45 - p6;
    const Eigen::Vector3d& w5 = chain.axes[4];
    wrist_point_ = {g_ * (k.dot(d) * k + p6), g_rotation_ * (d - k.dot(d) * k), -(g_rotation_ * k.cross(d))};
    axis_5_ = {g_rotation_ * (k.dot(w5) * k), g_rotation_ * (w5 - k.dot(w5) * k), -(g_rotation_ * k.cross(w5))};
    // R(ω₃, q₃) ω₄ in the same form (q₃ is a positioning angle).
    const Eigen::Vector3d& w3 = chain.axes[2];
    const Eigen::Vector3d& w4 = chain.axes[3];
    axis_4_in_3_ = {w3.dot(w4) * w3, w4 - w3.dot(w4) * w3, w3.cross(w4)};
  }

  Sample evaluate(double theta) const {
    Sample s;
    const CosSin turn{std::cos(theta), std::sin(theta)};
    const PositionSolutions arm = position(turn);
    s.margin = arm.margin;
    const Eigen::Vector3d v = axis_5_.at(turn);  // R_G R₆ᵀ ω₅
    // f_b = ω₄ · (R₁R₂R₃)ᵀ v = (R₂R₃ω₄) · (R₁ᵀ v); branches with the same q₁ share R₁ᵀ v.
    Eigen::Vector3d v1 = Eigen::Vector3d::Zero();
    CosSin q1_of_v1{2.0, 0.0};  // none yet
    for (std::size_t b = 0; b < 4; ++b) {
      if (!arm.exists[b]) continue;
      s.exists[b] = true;
      if (!(arm.q[b][0] == q1_of_v1)) {
        q1_of_v1 = arm.q[b][0];
        v1 = rotate(chain_.axes[0], q1_of_v1.inverse(), v);
      }
      s.value[b] = arm_axis_4(arm.q[b]).dot(v1) - cos_45_;
    }
    return s;
  }

  // One branch only (refinement). `margin`: the positioning margin of the branch there.
  bool evaluate(double theta, std::size_t branch, double& value, double& margin) const {
    const CosSin turn{std::cos(theta), std::sin(theta)};
    const PositionSolutions arm = position(turn);
    margin = arm.margin[branch];
    if (!arm.exists[branch]) return false;
    const Eigen::Vector3d v1 = rotate(chain_.axes[0], arm.q[branch][0].inverse(), axis_5_.at(turn));
    value = arm_axis_4(arm.q[branch]).dot(v1) - cos_45_;
    return true;
  }

  bool evaluate(double theta, std::size_t branch, double& value) const {
    double margin;
    return evaluate(theta, branch, value, margin);
  }

  // Where the positioning stage's first subproblem (and, where it is an equation of θ alone, the
  // elbow's) stops or starts being solvable, sorted in [−π, π): between two of these the
  // branches that exist do not change. Each discriminant A² + B² − C² is a trigonometric
  // polynomial of degree 2 in θ (A, B, C are affine in the wrist point, or in its squared
  // distance from the shoulder, and the wrist point turns with θ), so these are exact however
  // narrow the gap or island between them. A sampling of the margins alone misses a gap or an
  // island narrower than its spacing where a margin moves steeply (the wrist circle grazing
  // axis 1): two of the 10⁶ round trips on the Jaco2 did at 180 samples, one of 10⁵ at 120.
  std::vector<double> positioning_ends() const {
    auto ends_of = [&](auto harmonic) {
      return sign_changes(TrigPolynomial::interpolate([&](double theta) {
                            return harmonic(wrist_point_.at({std::cos(theta), std::sin(theta)})).discriminant();
                          }),
                          1e-10);
    };
    std::vector<double> ends = ends_of(
        [&](const Eigen::Vector3d& y) { return first_positioning_harmonic(chain_, geometry_, geometry_.point_45, y); });
    if (elbow_independent_of_q1(geometry_)) {
      const std::vector<double> more =
          ends_of([&](const Eigen::Vector3d& y) { return elbow_harmonic(chain_, geometry_, geometry_.point_45, y); });
      ends.insert(ends.end(), more.begin(), more.end());
      std::sort(ends.begin(), ends.end());
    }
    return ends;
  }

  // The positioning margin of branch b (≥ 0 where it exists).
  double margin(double theta, std::size_t branch) const {
    return position({std::cos(theta), std::sin(theta)}).margin[branch];
  }

  // The full q at a root θ of branch b, offered to the solution list (polish, check, dedupe).
  void offer_root(double theta, std::size_t branch, SolutionList& out) const {
    const PositionSolutions arm = position({std::cos(theta), std::sin(theta)});
    if (!arm.exists[branch]) return;
    const Eigen::Vector3d t = arm.angles(branch);
    const Eigen::Matrix3d r_rem =
        (rotation(chain_.axes[0], t(0)) * rotation(chain_.axes[1], t(1)) * rotation(chain_.axes[2], t(2))).transpose() *
        g_rotation_ * rotation(chain_.axes[5], -theta);
    const Eigen::Vector3d& w4 = chain_.axes[3];
    const Eigen::Vector3d& w5 = chain_.axes[4];
    const double q4 = subproblem1(w4, w5, r_rem * w5);
    const Eigen::Vector3d x5 =
        w5.cross(std::abs(w5.x()) < 0.9 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY()).normalized();
    const double q5 = subproblem1(w5, x5, rotation(w4, -q4) * r_rem * x5);
    Vector6d q;
    q << t, q4, q5, theta;
    offer(chain_, pose_, q, out);
  }

 private:
  // The positioning stage for q₆ = θ.
  PositionSolutions position(const CosSin& turn) const {
    return solve_position(chain_, geometry_, geometry_.point_45, wrist_point_.at(turn));
  }

  // R₂R₃ ω₄ for the positioning angles t.
  Eigen::Vector3d arm_axis_4(const std::array<CosSin, 3>& t) const {
    return rotate(chain_.axes[1], t[1], axis_4_in_3_.at(t[2]));
  }

  const RevoluteChain& chain_;
  const ChainGeometry& geometry_;
  const Posed& pose_;
  Posed g_;
  Eigen::Matrix3d g_rotation_;
  double cos_45_;
  Turning wrist_point_;  // G (R(ω₆, −θ)(w − p₆) + p₆): where joints 1–3 must put w
  Turning axis_5_;       // R_G R(ω₆, −θ) ω₅
  Turning axis_4_in_3_;  // R(ω₃, q₃) ω₄
};

}  // namespace dispkin::serial::detail
