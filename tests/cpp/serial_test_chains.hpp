// RevoluteChains of named robots, written from their published Denavit–Hartenberg tables, for
// the analytic-IK and serial-arm tests. The joint values q are the DH angles θᵢ minus the
// listed offsets (so q = 0 is the pose drawn in each table); the controllers' own zero and
// sign conventions may differ, which changes nothing for inverse kinematics.
#pragma once

#include <array>
#include <cmath>
#include <string>
#include <vector>

#include <dispkin/serial/revolute_chain.hpp>

namespace dispkin::testing {

//! One row of a classic (distal) DH table: T = Rz(θ + offset) Tz(d) Tx(a) Rx(α); lengths in m.
struct DhRow {
  double a;
  double alpha;
  double d;
  double offset;
};

//! The chain of a classic DH table: joint i turns about z_{i−1}, through the origin of frame
//! i−1, both taken at q = 0; the tip is frame n.
inline serial::RevoluteChain chain_from_dh(const std::vector<DhRow>& rows) {
  serial::RevoluteChain chain;
  Posed frame;
  for (const DhRow& r : rows) {
    chain.axes.push_back(frame.rotation().col(2));
    chain.points.push_back(frame.translation());
    const Posed link = Posed::unchecked(Eigen::Quaterniond(Eigen::AngleAxisd(r.offset, Eigen::Vector3d::UnitZ())),
                                        Eigen::Vector3d::Zero()) *
                       Posed::unchecked(Eigen::Quaterniond::Identity(), Eigen::Vector3d(0.0, 0.0, r.d)) *
                       Posed::unchecked(Eigen::Quaterniond::Identity(), Eigen::Vector3d(r.a, 0.0, 0.0)) *
                       Posed::unchecked(Eigen::Quaterniond(Eigen::AngleAxisd(r.alpha, Eigen::Vector3d::UnitX())),
                                        Eigen::Vector3d::Zero());
    frame = frame * link;
  }
  chain.tip_at_zero = frame;
  return chain;
}

constexpr double half_pi = 1.57079632679489661923;
constexpr double pi = 3.14159265358979323846;

//! KUKA KR6 R900 sixx (KR AGILUS): the dimensions of KUKA's specification drawing, 400 mm base
//! height, 25 mm shoulder offset, 455 mm upper arm, 35 mm elbow offset, 420 mm forearm, 80 mm
//! flange. Spherical wrist.
inline serial::RevoluteChain kuka_kr6_r900() {
  return chain_from_dh({{0.025, -half_pi, 0.400, 0.0},
                        {0.455, 0.0, 0.0, -half_pi},
                        {0.035, -half_pi, 0.0, 0.0},
                        {0.0, half_pi, 0.420, 0.0},
                        {0.0, -half_pi, 0.0, 0.0},
                        {0.0, 0.0, 0.080, 0.0}});
}

//! ABB IRB 120 (product specification, 3HAC035960): 290 mm base height, 270 mm upper arm,
//! 70 mm elbow offset, 302 mm forearm, 72 mm flange; no shoulder offset. Spherical wrist.
inline serial::RevoluteChain abb_irb120() {
  return chain_from_dh({{0.0, -half_pi, 0.290, 0.0},
                        {0.270, 0.0, 0.0, -half_pi},
                        {0.070, -half_pi, 0.0, 0.0},
                        {0.0, half_pi, 0.302, 0.0},
                        {0.0, -half_pi, 0.0, 0.0},
                        {0.0, 0.0, 0.072, 0.0}});
}

//! ABB IRB 6640-235/2.55 (product specification): 780 mm base height, 320 mm shoulder offset,
//! 1075 mm upper arm, 200 mm elbow offset, 1142.5 mm forearm, 200 mm flange (the values IK-Geo
//! uses for its IRB 6640 example). Spherical wrist.
inline serial::RevoluteChain abb_irb6640() {
  return chain_from_dh({{0.320, -half_pi, 0.780, 0.0},
                        {1.075, 0.0, 0.0, -half_pi},
                        {0.200, -half_pi, 0.0, 0.0},
                        {0.0, half_pi, 1.1425, 0.0},
                        {0.0, -half_pi, 0.0, 0.0},
                        {0.0, 0.0, 0.200, 0.0}});
}

//! Universal Robots UR5 (UR's published DH parameters): d₁ = 0.089159, a₂ = −0.425,
//! a₃ = −0.39225, d₄ = 0.10915, d₅ = 0.09465, d₆ = 0.0823; α = (π/2, 0, 0, π/2, −π/2, 0).
//! Axes 2, 3, 4 parallel.
inline serial::RevoluteChain ur5() {
  return chain_from_dh({{0.0, half_pi, 0.089159, 0.0},
                        {-0.425, 0.0, 0.0, 0.0},
                        {-0.39225, 0.0, 0.0, 0.0},
                        {0.0, half_pi, 0.10915, 0.0},
                        {0.0, -half_pi, 0.09465, 0.0},
                        {0.0, 0.0, 0.0823, 0.0}});
}

//! Universal Robots UR10e (UR's published DH parameters): d₁ = 0.1807, a₂ = −0.6127,
//! a₃ = −0.57155, d₄ = 0.17415, d₅ = 0.11985, d₆ = 0.11655; α as the UR5.
inline serial::RevoluteChain ur10e() {
  return chain_from_dh({{0.0, half_pi, 0.1807, 0.0},
                        {-0.6127, 0.0, 0.0, 0.0},
                        {-0.57155, 0.0, 0.0, 0.0},
                        {0.0, half_pi, 0.17415, 0.0},
                        {0.0, -half_pi, 0.11985, 0.0},
                        {0.0, 0.0, 0.11655, 0.0}});
}

//! Kinova Jaco2 6-DOF curved wrist (j2n6s300), classic DH from Kinova's "DH parameters" note
//! for the Jaco2 arms: D1 = 0.2755, D2 = 0.4100, D3 = 0.2073, D4 = D5 = 0.0741, D6 = 0.1600,
//! e2 = 0.0098, wrist angle aa = 30° (consecutive wrist axes 60° apart), and
//!   d4b = D3 + sin(aa)/sin(2aa)·D4,  d5b = sin(aa)/sin(2aa)·(D4 + D5),  d6b = sin(aa)/sin(2aa)·D5 + D6,
//!   α = (π/2, π, π/2, 2aa, 2aa, π), a = (0, D2, 0, 0, 0, 0), d = (D1, 0, −e2, −d4b, −d5b, −d6b).
//! Axes 4 ∩ 5 and 5 ∩ 6 at different points: an offset wrist.
inline serial::RevoluteChain kinova_jaco2_j2n6s300() {
  const double aa = pi / 6.0;
  const double k = std::sin(aa) / std::sin(2.0 * aa);
  const double d1 = 0.2755, d2 = 0.4100, d3 = 0.2073, d4 = 0.0741, d5 = 0.0741, d6 = 0.1600, e2 = 0.0098;
  const double d4b = d3 + k * d4;
  const double d5b = k * d4 + k * d5;
  const double d6b = k * d5 + d6;
  return chain_from_dh({{0.0, half_pi, d1, 0.0},
                        {d2, pi, 0.0, 0.0},
                        {0.0, half_pi, -e2, 0.0},
                        {0.0, 2.0 * aa, -d4b, 0.0},
                        {0.0, 2.0 * aa, -d5b, 0.0},
                        {0.0, pi, -d6b, 0.0}});
}

struct NamedChain {
  std::string name;
  serial::RevoluteChain chain;
};

//! The chain of a modified (proximal, Craig) DH table: row i is (a_{i−1}, α_{i−1}, d_i, offset_i),
//! T = Rx(α) Tx(a) Rz(θ + offset) Tz(d), joint i about the z axis after Rx Tx; `flange` (its
//! offset ignored) places the tip after the last joint.
inline serial::RevoluteChain chain_from_modified_dh(const std::vector<DhRow>& rows, const DhRow& flange) {
  serial::RevoluteChain chain;
  Posed frame;
  const auto rx_tx = [](const DhRow& r) {
    return Posed::unchecked(Eigen::Quaterniond(Eigen::AngleAxisd(r.alpha, Eigen::Vector3d::UnitX())),
                            Eigen::Vector3d::Zero()) *
           Posed::unchecked(Eigen::Quaterniond::Identity(), Eigen::Vector3d(r.a, 0.0, 0.0));
  };
  for (const DhRow& r : rows) {
    frame = frame * rx_tx(r);
    chain.axes.push_back(frame.rotation().col(2));
    chain.points.push_back(frame.translation());
    frame = frame *
            Posed::unchecked(Eigen::Quaterniond(Eigen::AngleAxisd(r.offset, Eigen::Vector3d::UnitZ())),
                             Eigen::Vector3d::Zero()) *
            Posed::unchecked(Eigen::Quaterniond::Identity(), Eigen::Vector3d(0.0, 0.0, r.d));
  }
  chain.tip_at_zero =
      frame * rx_tx(flange) * Posed::unchecked(Eigen::Quaterniond::Identity(), Eigen::Vector3d(0.0, 0.0, flange.d));
  return chain;
}

//! Franka Emika Panda: Franka's published modified DH table (d₁ 0.333, d₃ 0.316, a₃ 0.0825,
//! a₄ −0.0825, d₅ 0.384, a₆ 0.088, flange 0.107). Seven joints; axes 1, 2, 3 meet, 5 and 6 meet.
inline serial::RevoluteChain franka_panda() {
  return chain_from_modified_dh({{0.0, 0.0, 0.333, 0.0},
                                 {0.0, -half_pi, 0.0, 0.0},
                                 {0.0, half_pi, 0.316, 0.0},
                                 {0.0825, half_pi, 0.0, 0.0},
                                 {-0.0825, -half_pi, 0.384, 0.0},
                                 {0.0, half_pi, 0.0, 0.0},
                                 {0.088, half_pi, 0.0, 0.0}},
                                {0.0, 0.0, 0.107, 0.0});
}

//! KUKA LBR iiwa 14 R820: the published classic DH table (d₁ 0.36, d₃ 0.42, d₅ 0.4, d₇ 0.126,
//! every a = 0). Seven joints, an SRS arm: axes 1, 2, 3 meet, and 5, 6, 7.
inline serial::RevoluteChain kuka_iiwa14() {
  return chain_from_dh({{0.0, -half_pi, 0.36, 0.0},
                        {0.0, half_pi, 0.0, 0.0},
                        {0.0, half_pi, 0.42, 0.0},
                        {0.0, -half_pi, 0.0, 0.0},
                        {0.0, -half_pi, 0.4, 0.0},
                        {0.0, half_pi, 0.0, 0.0},
                        {0.0, 0.0, 0.126, 0.0}});
}

//! Every test robot, by name.
inline std::vector<NamedChain> named_test_chains() {
  return {{"kuka_kr6_r900", kuka_kr6_r900()},
          {"abb_irb120", abb_irb120()},
          {"abb_irb6640", abb_irb6640()},
          {"ur5", ur5()},
          {"ur10e", ur10e()},
          {"jaco2_j2n6s300", kinova_jaco2_j2n6s300()}};
}

}  // namespace dispkin::testing
