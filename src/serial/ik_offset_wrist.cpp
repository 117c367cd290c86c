// The offset-wrist search (seed 003, MATH.md §8), made robust.
//
// Axes 4 and 5 meet in a point w off axis 6, so as q₆ turns, w moves on a circle about axis 6
// (the patent's circle; q₆ is its parameter). For each q₆ = θ:
//   G' = G e₆⁻¹(θ),  e₁e₂e₃ w = G' w           (positioning stage: up to 4 branches),
//   R₄R₅ = R_rem = (R₁R₂R₃)ᵀ R_G'              (two joints for a whole rotation),
// which is solvable iff the angle between axes 4 and 5 is kept (the patent's "fixed link
// angle"): f_b(θ) = ω₄ · R_rem ω₅ − ω₄ · ω₅ = 0 on branch b. Each branch is continuous where it
// exists (its subproblem labels are fixed), and two branches meet where a subproblem reaches
// its tangency, so:
//   - sign changes between samples of one branch bracket roots;
//   - a branch ending between samples is followed to its end by bisection; a sign change up to
//     the end, or a value there near zero, gives a root (the partner branch, which ends at the
//     same point with the same value, checks its own side);
//   - a sampled local extremum of |f_b| that may touch zero is refined (golden section); if it
//     crosses zero, it brackets two roots, if it touches, it is a candidate itself.
// Every root becomes a full q (q₄, q₅ by subproblem 1), is polished by Newton on the full pose
// and kept only if forward kinematics reproduces the pose to 1e-10.
#include <stdexcept>

#include "dispkin/error.hpp"
#include "ik_internal.hpp"

namespace dispkin {
namespace serial {
namespace detail {
namespace {

struct SolutionList {
  std::vector<Vector6d> q;
  int size() const { return static_cast<int>(q.size()); }
  const Vector6d& operator[](int i) const { return q[static_cast<std::size_t>(i)]; }
  void push(const Vector6d& x) { q.push_back(x); }
};

// f_b(θ) on the four branches.
struct Sample {
  std::array<bool, 4> exists{};
  std::array<double, 4> value{};
};

class OffsetWristSearch {
 public:
  OffsetWristSearch(const RevoluteChain& chain, const ChainGeometry& geometry, const Posed& pose)
      : chain_(chain), geometry_(geometry), pose_(pose), g_(pose * chain.tip_at_zero.inverse()),
        g_rotation_(g_.rotation()), cos_45_(chain.axes[3].dot(chain.axes[4])) {}

  Sample evaluate(double theta) const {
    Sample s;
    const PositionSolutions arm = position(theta);
    const Eigen::Vector3d v = g_rotation_ * rotate(chain_.axes[5], -theta, chain_.axes[4]);  // R_G R₆ᵀ ω₅
    for (std::size_t b = 0; b < 4; ++b) {
      if (!arm.exists[b]) continue;
      s.exists[b] = true;
      s.value[b] = chain_.axes[3].dot(back_through_arm(arm.q[b], v)) - cos_45_;
    }
    return s;
  }

  // One branch only (refinement).
  bool evaluate(double theta, std::size_t branch, double& value) const {
    const PositionSolutions arm = position(theta);
    if (!arm.exists[branch]) return false;
    const Eigen::Vector3d v = g_rotation_ * rotate(chain_.axes[5], -theta, chain_.axes[4]);
    value = chain_.axes[3].dot(back_through_arm(arm.q[branch], v)) - cos_45_;
    return true;
  }

  // The full q at a root θ of branch b, offered to the solution list (polish, check, dedupe).
  void offer_root(double theta, std::size_t branch, SolutionList& out) const {
    const PositionSolutions arm = position(theta);
    if (!arm.exists[branch]) return;
    const Eigen::Vector3d& t = arm.q[branch];
    const Eigen::Matrix3d r_rem = (rotation(chain_.axes[0], t(0)) * rotation(chain_.axes[1], t(1)) *
                                   rotation(chain_.axes[2], t(2)))
                                      .transpose() *
                                  g_rotation_ * rotation(chain_.axes[5], -theta);
    const Eigen::Vector3d& w4 = chain_.axes[3];
    const Eigen::Vector3d& w5 = chain_.axes[4];
    const double q4 = subproblem1(w4, w5, r_rem * w5);
    const Eigen::Vector3d x5 = w5.cross(std::abs(w5.x()) < 0.9 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY()).normalized();
    const double q5 = subproblem1(w5, x5, rotation(w4, -q4) * r_rem * x5);
    Vector6d q;
    q << t, q4, q5, theta;
    offer(chain_, pose_, q, out);
  }

 private:
  PositionSolutions position(double theta) const {
    const Eigen::Vector3d& p6 = chain_.points[5];
    const Eigen::Vector3d w_target = g_ * (rotate(chain_.axes[5], -theta, geometry_.point_45 - p6) + p6);
    return solve_position(chain_, geometry_, geometry_.point_45, w_target);
  }

  // (R₁R₂R₃)ᵀ v.
  Eigen::Vector3d back_through_arm(const Eigen::Vector3d& t, const Eigen::Vector3d& v) const {
    return rotate(chain_.axes[2], -t(2), rotate(chain_.axes[1], -t(1), rotate(chain_.axes[0], -t(0), v)));
  }

  const RevoluteChain& chain_;
  const ChainGeometry& geometry_;
  const Posed& pose_;
  Posed g_;
  Eigen::Matrix3d g_rotation_;
  double cos_45_;
};

// Illinois regula falsi on [a, b] with f(a) f(b) < 0.
double refine_root(const OffsetWristSearch& search, std::size_t branch, double a, double fa, double b, double fb) {
  int side = 0;
  for (int iteration = 0; iteration < 100 && std::abs(b - a) > 1e-14; ++iteration) {
    double c = (a * fb - b * fa) / (fb - fa);
    if (!(c > std::min(a, b) && c < std::max(a, b))) c = 0.5 * (a + b);
    double fc;
    if (!search.evaluate(c, branch, fc)) return c;  // left the branch (rounding at its end)
    if (fc == 0.0) return c;
    if ((fc < 0.0) == (fb < 0.0)) {
      b = c;
      fb = fc;
      if (side == -1) fa *= 0.5;
      side = -1;
    } else {
      a = c;
      fa = fc;
      if (side == 1) fb *= 0.5;
      side = 1;
    }
  }
  return std::abs(fa) < std::abs(fb) ? a : b;
}

// The value of a near-touching candidate below which Newton on the full pose decides.
constexpr double touch_tolerance = 1e-5;

}  // namespace

std::vector<Eigen::VectorXd> offset_wrist_search(const RevoluteChain& chain, const ChainGeometry& geometry,
                                                 const Posed& pose, int samples) {
  const OffsetWristSearch search(chain, geometry, pose);
  const int n = samples;
  const double step = 2.0 * pi / n;
  std::vector<Sample> table(static_cast<std::size_t>(n));
  for (int j = 0; j < n; ++j) table[static_cast<std::size_t>(j)] = search.evaluate(-pi + j * step);
  auto theta_of = [&](int j) { return -pi + j * step; };  // j may reach n: one turn later

  SolutionList out;
  for (std::size_t b = 0; b < 4; ++b) {
    for (int j = 0; j < n; ++j) {
      const Sample& s0 = table[static_cast<std::size_t>(j)];
      const Sample& s1 = table[static_cast<std::size_t>((j + 1) % n)];
      const double t0 = theta_of(j);
      const double t1 = theta_of(j + 1);
      if (s0.exists[b] && s0.value[b] == 0.0) search.offer_root(t0, b, out);
      if (s0.exists[b] && s1.exists[b]) {
        if ((s0.value[b] < 0.0) != (s1.value[b] < 0.0) && s1.value[b] != 0.0)
          search.offer_root(refine_root(search, b, t0, s0.value[b], t1, s1.value[b]), b, out);
      } else if (s0.exists[b] != s1.exists[b]) {
        // The branch ends inside (t0, t1): bisect to its end, keeping the existing side.
        double in = s0.exists[b] ? t0 : t1;
        double outside = s0.exists[b] ? t1 : t0;
        double f_in = s0.exists[b] ? s0.value[b] : s1.value[b];
        const double f_start = f_in;
        const double start = in;
        while (std::abs(outside - in) > 1e-14) {
          const double mid = 0.5 * (in + outside);
          double f;
          if (search.evaluate(mid, b, f)) {
            in = mid;
            f_in = f;
          } else {
            outside = mid;
          }
        }
        if ((f_start < 0.0) != (f_in < 0.0)) {
          search.offer_root(refine_root(search, b, start, f_start, in, f_in), b, out);
        }
        if (std::abs(f_in) <= touch_tolerance) search.offer_root(in, b, out);
      }
      // A sampled extremum of |f| that may touch or cross zero between t₋₁ and t₁.
      const Sample& sm = table[static_cast<std::size_t>((j + n - 1) % n)];
      if (sm.exists[b] && s0.exists[b] && s1.exists[b]) {
        const double f0 = s0.value[b];
        const double sign = f0 < 0.0 ? -1.0 : 1.0;
        const double fm = sign * sm.value[b];
        const double fp = sign * s1.value[b];
        const double fc = sign * f0;
        if (fm > 0.0 && fp > 0.0 && fc <= fm && fc <= fp && fc < 4.0 * ((fm - fc) + (fp - fc))) {
          // Golden-section minimum of sign · f on [t₋₁, t₁].
          double lo = t0 - step;
          double hi = t1;
          const double ratio = 0.5 * (std::sqrt(5.0) - 1.0);
          double x1 = hi - ratio * (hi - lo);
          double x2 = lo + ratio * (hi - lo);
          double f1 = 0.0, f2 = 0.0;
          bool ok = search.evaluate(x1, b, f1) && search.evaluate(x2, b, f2);
          for (int k = 0; ok && k < 60 && hi - lo > 1e-12; ++k) {
            if (sign * f1 < sign * f2) {
              hi = x2;
              x2 = x1;
              f2 = f1;
              x1 = hi - ratio * (hi - lo);
              ok = search.evaluate(x1, b, f1);
            } else {
              lo = x1;
              x1 = x2;
              f1 = f2;
              x2 = lo + ratio * (hi - lo);
              ok = search.evaluate(x2, b, f2);
            }
            if (ok && (sign * f1 <= 0.0 || sign * f2 <= 0.0)) break;  // crossed: two roots
          }
          if (ok) {
            const double xm = sign * f1 < sign * f2 ? x1 : x2;
            const double fmin = std::min(sign * f1, sign * f2);
            if (fmin <= 0.0) {
              const double f_xm = sign * fmin;
              if (fmin == 0.0) {
                search.offer_root(xm, b, out);
              } else {
                search.offer_root(refine_root(search, b, t0 - step, sm.value[b], xm, f_xm), b, out);
                search.offer_root(refine_root(search, b, xm, f_xm, t1, s1.value[b]), b, out);
              }
            } else if (fmin <= touch_tolerance) {
              search.offer_root(xm, b, out);
            }
          }
        }
      }
    }
  }
  std::vector<Eigen::VectorXd> result;
  result.reserve(out.q.size());
  for (const Vector6d& q : out.q) result.emplace_back(q);
  return result;
}

}  // namespace detail
}  // namespace serial
}  // namespace dispkin
