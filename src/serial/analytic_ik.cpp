// Analytic inverse kinematics of 6R chains (see include/dispkin/serial/analytic_ik.hpp): the
// entry points, which check the chain, recognise or check its family and run its solver.
#include "dispkin/serial/analytic_ik.hpp"

#include <array>
#include <cstring>
#include <stdexcept>

#include "dispkin/error.hpp"
#include "dispkin/serial/redundancy.hpp"
#include "ik_internal.hpp"

namespace dispkin {
namespace serial {
namespace detail {
std::vector<Eigen::VectorXd> offset_wrist_search(const RevoluteChain& chain, const ChainGeometry& geometry,
                                                 const Posed& pose, int samples);
}  // namespace detail

namespace {

// The geometric tolerance of the solvers' family checks (metres, radians): chains written
// from DH tables or URDFs are exact to rounding; a family that fits only to 1e-9 still gives
// exact solutions because every candidate is polished on the true chain.
constexpr double family_tolerance = 1e-9;

// The chain last analysed on this thread (its axes, points and tip, bit for bit) and its
// geometry. The real-time path solves pose after pose of one chain, and checking and analysing it
// again cost as much as a tenth of a closed-form call. The geometry holds constants of the tip
// (M⁻¹ and those of the arm frame), so the tip is part of the key. Only a validated chain is
// stored, and it has no NaN, so bitwise equality with it is equality.
struct ChainKey {
  std::array<double, 18> axes{}, points{};
  std::array<double, 7> tip{};
};

struct AnalysedChain {
  ChainKey key;
  bool valid = false;
  detail::ChainGeometry geometry;
};

std::array<double, 7> tip_of(const RevoluteChain& chain) {
  const Eigen::Quaterniond& r = chain.tip_at_zero.quaternion();
  const Eigen::Vector3d& t = chain.tip_at_zero.translation();
  return {{r.w(), r.x(), r.y(), r.z(), t.x(), t.y(), t.z()}};
}

// The vectors of axes and points hold their doubles contiguously, three per joint.
static_assert(sizeof(Eigen::Vector3d) == 3 * sizeof(double), "Vector3d is three packed doubles");

ChainKey key_of(const RevoluteChain& chain) {
  ChainKey key;
  std::memcpy(key.axes.data(), chain.axes.data(), sizeof key.axes);
  std::memcpy(key.points.data(), chain.points.data(), sizeof key.points);
  key.tip = tip_of(chain);
  return key;
}

bool same_chain(const RevoluteChain& chain, const ChainKey& key) {
  if (chain.axes.size() != 6 || chain.points.size() != 6) return false;
  const std::array<double, 7> tip = tip_of(chain);
  return std::memcmp(chain.axes.data(), key.axes.data(), sizeof key.axes) == 0 &&
         std::memcmp(chain.points.data(), key.points.data(), sizeof key.points) == 0 &&
         std::memcmp(tip.data(), key.tip.data(), sizeof tip) == 0;
}

// validate_chain + analyse with family_tolerance, from the thread's cache when the chain is the
// one analysed last.
const detail::ChainGeometry& checked_geometry(const RevoluteChain& chain) {
  thread_local AnalysedChain last;
  if (last.valid && same_chain(chain, last.key)) return last.geometry;
  last.valid = false;
  detail::validate_chain(chain);
  last.geometry = detail::analyse(chain, family_tolerance);
  last.key = key_of(chain);
  last.valid = true;
  return last.geometry;
}

// Throws unless `family` fits the chain (and is not general).
void require_family(const detail::ChainGeometry& g, IkFamily family) {
  const char* why = "";
  switch (family) {
    case IkFamily::spherical_wrist:
      why = g.why_not_spherical;
      break;
    case IkFamily::three_parallel:
      why = g.why_not_three_parallel;
      break;
    case IkFamily::offset_wrist:
      why = g.why_not_offset;
      break;
    case IkFamily::general:
      why = "no analytic solver for the general family (use a numeric solver)";
      break;
    case IkFamily::locked_joint:
      why = "a 7R chain needs a value of its locked joint (locked_joint_inverse)";
      break;
  }
  if (*why != '\0')
    throw std::invalid_argument(describe("family", to_string(family), std::string("does not fit the chain: ") + why));
}

}  // namespace

std::string to_string(IkFamily family) {
  switch (family) {
    case IkFamily::spherical_wrist:
      return "spherical_wrist";
    case IkFamily::three_parallel:
      return "three_parallel";
    case IkFamily::offset_wrist:
      return "offset_wrist";
    case IkFamily::general:
      return "general";
    case IkFamily::locked_joint:
      return "locked_joint";
  }
  return "unknown";
}

IkFamily recognise(const RevoluteChain& chain, double tolerance) {
  require(std::isfinite(tolerance) && tolerance > 0.0, "tolerance", tolerance, "must be finite and positive");
  if (chain.dof() != 6) {
    // A 6R chain has a closed form or search; a 7R one may have a locked joint that leaves one
    // (redundancy.hpp); other lengths are still checked for sanity.
    if (chain.axes.size() != chain.points.size())
      throw std::invalid_argument(describe("chain.points", static_cast<long>(chain.points.size()),
                                           "expected one point per axis (" + std::to_string(chain.axes.size()) + ")"));
    return find_locked_joint(chain).found() ? IkFamily::locked_joint : IkFamily::general;
  }
  detail::validate_chain(chain);
  return detail::analyse(chain, tolerance).family;
}

void analytic_inverse(const RevoluteChain& chain, IkFamily family, const Posed& pose, IkSolutionSet& out) {
  out.count = 0;
  const detail::ChainGeometry& g = checked_geometry(chain);
  require_family(g, family);
  if (family == IkFamily::spherical_wrist) {
    detail::spherical_wrist_inverse(chain, g, pose, out);
  } else if (family == IkFamily::three_parallel) {
    const bool near_singular = detail::three_parallel_inverse(chain, g, pose, out);
    // Within ~1e-8 rad of the wrist singularity the closed form's q₅ (a tangency of
    // subproblem 4, so known only to √ε) can leave Newton short of 1e-10 when the elbow is also
    // near stretched. The UR layout also fits the offset-wrist search, which parametrises by
    // q₆ directly: it is the fallback there (and the only case that allocates).
    if (out.count == 0 && near_singular && *g.why_not_offset == '\0') {
      for (const Eigen::VectorXd& q : detail::offset_wrist_search(chain, g, pose, OffsetWristOptions{}.samples))
        out.push(q, ik_pose_tolerance);  // measured inside the search, kept below the tolerance
    }
  } else {
    throw std::invalid_argument(describe("family", to_string(family),
                                         "has no closed form; the allocation-free overload takes spherical_wrist "
                                         "or three_parallel"));
  }
}

std::vector<Eigen::VectorXd> offset_wrist_inverse(const RevoluteChain& chain, const Posed& pose,
                                                  const OffsetWristOptions& options) {
  require(options.samples >= 16, "options.samples", options.samples, "must be at least 16");
  const detail::ChainGeometry& g = checked_geometry(chain);
  require_family(g, IkFamily::offset_wrist);
  return detail::offset_wrist_search(chain, g, pose, options.samples);
}

std::vector<Eigen::VectorXd> analytic_inverse(const RevoluteChain& chain, IkFamily family, const Posed& pose) {
  if (family == IkFamily::offset_wrist) return offset_wrist_inverse(chain, pose, OffsetWristOptions{});
  IkSolutionSet set;
  analytic_inverse(chain, family, pose, set);
  std::vector<Eigen::VectorXd> out;
  out.reserve(static_cast<std::size_t>(set.count));
  for (int i = 0; i < set.count; ++i) out.emplace_back(set.q[static_cast<std::size_t>(i)]);
  return out;
}

}  // namespace serial
}  // namespace dispkin
