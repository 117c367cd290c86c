// Prints the closed-form solution sets of seeded poses for the robots of the two closed-form
// families (tests/cpp/serial_test_chains.hpp): random joint vectors and ones at or next to the
// wrist singularity (q₅ = 0, 1e-9, 1e-6) and the stretched elbow (q₃ = 0). Each line: robot,
// the pose (w x y z of its quaternion, then its translation) and every solution, exactly
// (hexadecimal floating point). tests/data/ik_solution_sets.txt holds its output from before the
// closed forms were restructured for speed; AnalyticIk.SolutionSetsAsRecorded compares with it.
//
//   dispkin_ik_solution_sets > tests/data/ik_solution_sets.txt
#include <cstdio>
#include <string>

#include <dispkin/serial/analytic_ik.hpp>
#include <dispkin/serial/chain_kinematics.hpp>

#include "../tests/cpp/random_cases.hpp"
#include "../tests/cpp/serial_test_chains.hpp"

int main() {
  using namespace dispkin;
  std::printf("# robot qw qx qy qz tx ty tz count q1..q6 per solution (benchmarks/ik_solution_sets.cpp)\n");
  testing::Random random(20261202);
  for (const testing::NamedChain& named : testing::named_test_chains()) {
    const serial::IkFamily family = serial::recognise(named.chain);
    if (family != serial::IkFamily::spherical_wrist && family != serial::IkFamily::three_parallel) continue;
    for (int n = 0; n < 200; ++n) {
      Eigen::VectorXd q(6);
      for (int i = 0; i < 6; ++i) q(i) = random.uniform(-3.14159, 3.14159);
      if (n >= 150 && n < 180) q(4) = (n % 3 == 0) ? 0.0 : (n % 3 == 1 ? 1e-9 : 1e-6);
      if (n >= 180) q(2) = 0.0;
      const Posed pose = serial::forward(named.chain, q);
      serial::IkSolutionSet set;
      serial::analytic_inverse(named.chain, family, pose, set);
      const Eigen::Quaterniond& r = pose.quaternion();
      std::printf("%s %a %a %a %a %a %a %a %d", named.name.c_str(), r.w(), r.x(), r.y(), r.z(), pose.translation().x(),
                  pose.translation().y(), pose.translation().z(), set.count);
      for (int s = 0; s < set.count; ++s)
        for (int i = 0; i < 6; ++i) std::printf(" %a", set[s](i));
      std::printf("\n");
    }
  }
  return 0;
}
