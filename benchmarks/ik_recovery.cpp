// Recovery sweep of the offset-wrist search (target: ≥ 99.99 % of round trips recovered).
// Round trips on the Kinova Jaco2 j2n6s300: q uniform in (−π, π]⁶, forward, offset-wrist
// inverse with the given number of samples; "found" exactly as in the RoundTripJaco2 test (the
// original q within recovery_bound, max(1e-8, 8 u L / σ_min(J)), modulo 2π), every returned
// solution checked by forward kinematics to ik_pose_tolerance, and every `dense_every`-th case
// compared with a 3600-sample search (solution count). Seed and count from DISPKIN_TEST_SEED / DISPKIN_TEST_COUNT.
//
//   DISPKIN_TEST_SEED=1 DISPKIN_TEST_COUNT=20000 build/ik/benchmarks/dispkin_ik_recovery 180 100
//
// Prints every miss (q, nearest solution) and a summary line; exits with 1 if anything missed.
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include <Eigen/SVD>

#include <dispkin/serial/analytic_ik.hpp>

#include "../tests/cpp/ik_recovery_bound.hpp"
#include "../tests/cpp/random_cases.hpp"
#include "../tests/cpp/serial_test_chains.hpp"

namespace {

namespace serial = dispkin::serial;
using dispkin::Posed;

double joint_gap(const Eigen::VectorXd& q, const Eigen::VectorXd& r) {
  double gap = 0.0;
  for (int i = 0; i < q.size(); ++i) gap = std::max(gap, std::abs(std::remainder(q(i) - r(i), 2.0 * M_PI)));
  return gap;
}

double pose_error(const serial::RevoluteChain& chain, const Eigen::VectorXd& q, const Posed& pose) {
  const Posed t = serial::forward(chain, q);
  const Eigen::Quaterniond d = pose.quaternion().conjugate() * t.quaternion();
  return std::max((t.translation() - pose.translation()).norm(), 2.0 * std::atan2(d.vec().norm(), std::abs(d.w())));
}

}  // namespace

int main(int argc, char** argv) {
  serial::OffsetWristOptions options;
  if (argc > 1) options.samples = std::atoi(argv[1]);
  const int dense_every = argc > 2 ? std::atoi(argv[2]) : 0;
  const int count = dispkin::testing::case_count(20000);
  const serial::RevoluteChain chain = dispkin::testing::kinova_jaco2_j2n6s300();
  dispkin::testing::Random random(616);  // the salt of the RoundTripJaco2 test
  serial::OffsetWristOptions dense;
  dense.samples = 3600;
  long missed = 0, inexact = 0, compared = 0, count_differs = 0;
  for (int n = 0; n < count; ++n) {
    Eigen::VectorXd q(6);
    for (int i = 0; i < 6; ++i) q(i) = random.uniform(-M_PI, M_PI);
    const Posed pose = serial::forward(chain, q);
    const auto solutions = serial::offset_wrist_inverse(chain, pose, options);
    double nearest = 1e300;
    for (const auto& s : solutions) {
      nearest = std::min(nearest, joint_gap(s, q));
      if (!(pose_error(chain, s, pose) <= serial::ik_pose_tolerance)) ++inexact;
    }
    const double bound = dispkin::testing::recovery_bound(chain, q);
    if (!(nearest <= bound)) {
      ++missed;
      std::printf("missed case %d: nearest %.3g, bound %.3g, q =", n, nearest, bound);
      for (int i = 0; i < 6; ++i) std::printf(" %.17g", q(i));
      std::printf("\n");
    }
    if (dense_every > 0 && n % dense_every == 0) {
      ++compared;
      if (serial::offset_wrist_inverse(chain, pose, dense).size() != solutions.size()) ++count_differs;
    }
  }
  std::printf(
      "samples %d, %d cases: found %ld (recovery %.4f %%), solutions above 1e-10: %ld, "
      "count differs from 3600 samples: %ld of %ld\n",
      options.samples, count, count - missed, 100.0 * static_cast<double>(count - missed) / count, inexact,
      count_differs, compared);
  return missed == 0 && inexact == 0 && count_differs == 0 ? 0 : 1;
}
