// The offset-wrist search (doc/inverse-kinematics.md §7), made robust.
//
// Axes 4 and 5 meet in a point w off axis 6, so as q₆ turns, w moves on a circle about axis 6
// (the circle of the wrist-offset IK patent, Intrinsic, "Inverse kinematics solver for wrist-offset
// robots"; q₆ is its parameter). For each q₆ = θ:
//   G' = G e₆⁻¹(θ),  e₁e₂e₃ w = G' w           (positioning stage: up to 4 branches),
//   R₄R₅ = R_rem = (R₁R₂R₃)ᵀ R_G'              (two joints for a whole rotation),
// which is solvable iff the angle between axes 4 and 5 is kept (that patent's "fixed link
// angle"): f_b(θ) = ω₄ · R_rem ω₅ − ω₄ · ω₅ = 0 on branch b. Each branch is continuous where it
// exists (its subproblem labels are fixed), and two branches meet where a subproblem reaches
// its tangency, so:
//   - sign changes between samples of one branch bracket roots;
//   - a branch ending between samples is followed to its end (regula falsi on the positioning
//     margin, which is smooth there) and sampled from it uniformly in u = √(θ − θ_end), the
//     variable in which it and its partner branch are one smooth function; a sign change up
//     to the end, or a value there near zero, gives a root (the partner branch, which ends at
//     the same point with the same value, checks its own side), and a slope at the end that
//     heads for zero is followed to a root pair closer to the end than the first sub-sample;
//   - a branch may also end and restart between two samples where it exists (a gap the samples
//     straddle) or exist only between two where it does not (an island): a sampled extremum of
//     the margin that may cross zero is refined (golden section) and the run split or the
//     island followed;
//   - a sampled local extremum of |f_b| that may touch zero, or an interval across which the
//     neighbouring slope would carry f_b through zero, is refined (golden section); if it
//     crosses zero, it brackets two roots, if it touches, it is a candidate itself.
// Besides the equally spaced samples, every gap or island of the positioning stage gets one:
// the first subproblem's ends (and the elbow's where it does not depend on q₁) are the sign
// changes of trigonometric polynomials of degree 2 in θ, found exactly (positioning_ends), so a
// gap or island is not missed however steeply a margin moves next to it.
// Each refinement above was added for a miss a coarser sampling or a larger sweep showed
// (benchmarks/RESULTS.md).
// Every root becomes a full q (q₄, q₅ by subproblem 1), is polished by Newton on the full pose
// and kept only if forward kinematics reproduces the pose to 1e-10.
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "dispkin/error.hpp"
#include "ik_internal.hpp"
#include "offset_wrist_condition.hpp"

namespace dispkin {
namespace serial {
namespace detail {
namespace {

// A bracket [a, b] of a root of f_b with the values there (of opposite signs, or a == b where the
// root was hit exactly or the branch was left).
struct Bracket {
  double a, fa, b, fb;
  double root() const noexcept { return std::abs(fa) < std::abs(fb) ? a : b; }
};

// Illinois regula falsi on [a, b] with f(a) f(b) < 0, to 1e-10 rad: Newton on the full pose
// (offer) takes the root from there to rounding. The weights the Illinois rule halves are kept
// apart from the values, which the bracket returns. Every fourth step bisects: where f is far
// from linear across the bracket (an end value 10³ times closer to zero than the other, next
// to a near-touching root: one of the 10⁷ round trips on the Jaco2) the secant steps crawl,
// and 100 of them left the bracket wide.
Bracket refine_bracket(const OffsetWristSearch& search, std::size_t branch, double a, double fa, double b, double fb) {
  double wa = fa, wb = fb;  // weighted values
  int side = 0;
  for (int iteration = 0; iteration < 200 && std::abs(b - a) > 1e-10; ++iteration) {
    double c = iteration % 4 == 3 ? 0.5 * (a + b) : (a * wb - b * wa) / (wb - wa);
    if (!(c > std::min(a, b) && c < std::max(a, b))) c = 0.5 * (a + b);
    double fc;
    if (!search.evaluate(c, branch, fc) || fc == 0.0)
      return {c, 0.0, c, 0.0};  // (left the branch: rounding at its end)
    if ((fc < 0.0) == (fb < 0.0)) {
      b = c;
      fb = wb = fc;
      if (side == -1) wa *= 0.5;
      side = -1;
    } else {
      a = c;
      fa = wa = fc;
      if (side == 1) wb *= 0.5;
      side = 1;
    }
  }
  return {a, fa, b, fb};
}

double refine_root(const OffsetWristSearch& search, std::size_t branch, double a, double fa, double b, double fb) {
  return refine_bracket(search, branch, a, fa, b, fb).root();
}

// The value of a near-touching candidate below which Newton on the full pose decides.
constexpr double touch_tolerance = 1e-5;

// Sub-samples between a branch's end and its first regular sample: near its end a branch
// behaves like a square root, so roots and extrema crowd there; the spacing is graded
// (quadratic in the index) to follow that.
constexpr int end_samples = 12;

struct Point {
  double theta;
  double value;
};

// Golden-section minimum of sign · f_b on [lo, hi]; false if the branch was left.
// `slope`: where given, stop as soon as even this slope could not carry f from the best point
// to zero within the bracket (the bound that made the caller look, see zero_reaching_slope).
bool minimise(const OffsetWristSearch& search, std::size_t branch, double sign, double lo, double hi, Point& best,
              double slope = std::numeric_limits<double>::infinity()) {
  const double ratio = 0.5 * (std::sqrt(5.0) - 1.0);
  double x1 = hi - ratio * (hi - lo);
  double x2 = lo + ratio * (hi - lo);
  double f1 = 0.0, f2 = 0.0;
  if (!search.evaluate(x1, branch, f1) || !search.evaluate(x2, branch, f2)) return false;
  for (int k = 0; k < 60 && hi - lo > 1e-10; ++k) {
    if (sign * f1 <= 0.0 || sign * f2 <= 0.0) break;                                  // crossed zero: two roots
    if (std::min(sign * f1, sign * f2) > touch_tolerance + slope * (hi - lo)) break;  // cannot reach zero
    if (sign * f1 < sign * f2) {
      hi = x2;
      x2 = x1;
      f2 = f1;
      x1 = hi - ratio * (hi - lo);
      if (!search.evaluate(x1, branch, f1)) return false;
    } else {
      lo = x1;
      x1 = x2;
      f1 = f2;
      x2 = lo + ratio * (hi - lo);
      if (!search.evaluate(x2, branch, f2)) return false;
    }
  }
  best = sign * f1 < sign * f2 ? Point{x1, f1} : Point{x2, f2};
  return true;
}

// Whether f, of one sign at run[i] and run[i + 1], would reach zero between them if it kept the
// slope it has on the neighbouring interval on either side (f turning back inside the interval):
// that slope's magnitude if so, else 0.
double zero_reaching_slope(const std::vector<Point>& run, std::size_t i) {
  const Point& p0 = run[i];
  const Point& p1 = run[i + 1];
  const double sign = p0.value < 0.0 ? -1.0 : 1.0;
  const double width = p1.theta - p0.theta;
  if (i >= 1) {
    const Point& pm = run[i - 1];
    const double slope = sign * (p0.value - pm.value) / (p0.theta - pm.theta);
    if (sign * p0.value + slope * width < 0.0) return -slope;
  }
  if (i + 2 < run.size()) {
    const Point& pp = run[i + 2];
    const double slope = sign * (pp.value - p1.value) / (pp.theta - p1.theta);
    if (sign * p1.value - slope * width < 0.0) return slope;
  }
  return 0.0;
}

// The roots between p0 and p1 (θ increasing) where f_b changes sign: the one regula falsi finds,
// and more where f turns back on either side of it. Three roots in one sample interval (f
// S-shaped through zero near an inflection: two of the 10⁷ round trips on the Jaco2) show on a
// side of the found root as a sign change between the bracket's end and the sample, or between
// the side's midpoint and the sample (another root in each half), or as a midpoint or sample far
// closer to zero than a straight line from the root would be (f bends back: a golden section
// finds whether it crosses zero before the sample).
void roots_in_sign_change(const OffsetWristSearch& search, std::size_t b, const Point& p0, const Point& p1,
                          SolutionList& out, int depth = 0) {
  Bracket k = refine_bracket(search, b, p0.theta, p0.value, p1.theta, p1.value);
  search.offer_root(k.root(), b, out);
  if (depth >= 3) return;
  if (k.a == k.b) {
    // Hit exactly (or the branch was left): the sides start 1e-10 rad away.
    const double c = k.a;
    if (!search.evaluate(c - 1e-10, b, k.fa) || !search.evaluate(c + 1e-10, b, k.fb)) return;
    k.a = c - 1e-10;
    k.b = c + 1e-10;
  }
  if (k.fa == 0.0 || k.fb == 0.0 || !(k.b > k.a)) return;
  const double slope = std::abs((k.fb - k.fa) / (k.b - k.a));
  auto ordered = [](const Point& x, const Point& y, Point& lo, Point& hi) {
    lo = x.theta < y.theta ? x : y;
    hi = x.theta < y.theta ? y : x;
  };
  auto side = [&](const Point& near, const Point& sample) {  // near: the bracket's end on this side
    if (sample.value == 0.0 || near.theta == sample.theta) return;
    Point lo, hi;
    ordered(near, sample, lo, hi);
    if ((near.value < 0.0) != (sample.value < 0.0)) {
      roots_in_sign_change(search, b, lo, hi, out, depth + 1);
      return;
    }
    Point mid{0.5 * (near.theta + sample.theta), 0.0};
    if (!search.evaluate(mid.theta, b, mid.value)) return;
    if ((mid.value < 0.0) != (sample.value < 0.0)) {
      Point a, c;
      ordered(near, mid, a, c);
      roots_in_sign_change(search, b, a, c, out, depth + 1);
      ordered(mid, sample, a, c);
      roots_in_sign_change(search, b, a, c, out, depth + 1);
      return;
    }
    const bool bends_back = std::abs(mid.value) < 0.25 * std::abs(sample.value) ||
                            std::abs(sample.value) < 0.5 * slope * (hi.theta - lo.theta);
    if (!bends_back) return;
    const double sign = sample.value < 0.0 ? -1.0 : 1.0;
    Point low;
    if (!minimise(search, b, sign, lo.theta, hi.theta, low, slope)) return;
    if (sign * low.value < 0.0) {
      roots_in_sign_change(search, b, lo, low, out, depth + 1);
      roots_in_sign_change(search, b, low, hi, out, depth + 1);
    } else if (sign * low.value <= touch_tolerance) {
      search.offer_root(low.theta, b, out);
    }
  };
  side({k.a, k.fa}, p0);
  side({k.b, k.fb}, p1);
}

// Roots of branch b along a run of points where it exists (θ increasing, the branch defined
// between consecutive points): sign changes, exact zeros, and sampled extrema of |f| that may
// touch or cross zero. `ends`: the first / last point is where the branch ends.
void scan(const OffsetWristSearch& search, std::size_t b, const std::vector<Point>& run, bool first_is_end,
          bool last_is_end, SolutionList& out) {
  const std::size_t n = run.size();
  if (first_is_end && std::abs(run.front().value) <= touch_tolerance) search.offer_root(run.front().theta, b, out);
  if (last_is_end && std::abs(run.back().value) <= touch_tolerance) search.offer_root(run.back().theta, b, out);
  for (std::size_t i = 0; i + 1 < n; ++i) {
    const Point& p0 = run[i];
    const Point& p1 = run[i + 1];
    if (p0.value == 0.0) search.offer_root(p0.theta, b, out);
    if ((p0.value < 0.0) != (p1.value < 0.0) && p1.value != 0.0) {
      roots_in_sign_change(search, b, p0, p1, out);
    } else if (const double slope = p0.value != 0.0 && p1.value != 0.0 ? zero_reaching_slope(run, i) : 0.0) {
      // No sign change, but the slope f has next to the interval carries it through zero
      // inside: a narrow pair of roots (or a touching one) the spacing does not resolve.
      const double sign = p0.value < 0.0 ? -1.0 : 1.0;
      Point low;
      if (minimise(search, b, sign, p0.theta, p1.theta, low, slope)) {
        if (sign * low.value < 0.0) {
          search.offer_root(refine_root(search, b, p0.theta, p0.value, low.theta, low.value), b, out);
          search.offer_root(refine_root(search, b, low.theta, low.value, p1.theta, p1.value), b, out);
        } else if (sign * low.value <= touch_tolerance) {
          search.offer_root(low.theta, b, out);
        }
      }
    }
    if (i == 0) continue;
    // A sampled extremum of |f| at p0 that a parabola through its neighbours brings near zero.
    const Point& pm = run[i - 1];
    const double sign = p0.value < 0.0 ? -1.0 : 1.0;
    const double fm = sign * pm.value, fc = sign * p0.value, fp = sign * p1.value;
    if (!(fm > 0.0 && fp > 0.0 && fc <= fm && fc <= fp && fc < 4.0 * ((fm - fc) + (fp - fc)))) continue;
    Point low;
    if (!minimise(search, b, sign, pm.theta, p1.theta, low)) continue;
    if (sign * low.value < 0.0) {
      search.offer_root(refine_root(search, b, pm.theta, pm.value, low.theta, low.value), b, out);
      search.offer_root(refine_root(search, b, low.theta, low.value, p1.theta, p1.value), b, out);
    } else if (sign * low.value <= touch_tolerance) {
      search.offer_root(low.theta, b, out);
    }
  }
}

// The end of branch b between `in` (where it exists) and `outside` (where it does not);
// returns the graded sub-samples from the end towards `in` (excluding `in`), end first.
// The end is where the positioning margin of the branch reaches −tangency_slack. The margin is
// smooth through the end (f_b is not: it behaves like a square root there), so regula falsi on
// it (Illinois-weighted) needs a handful of evaluations where bisection needs ~40; every
// fourth step bisects, so that a margin with a kink (a minimum of two subproblems' margins)
// still brackets the end at least as fast as bisection.
// `m_in`, `m_out`: the margins at `in` and `outside` (from the sample table).
std::vector<Point> branch_end(const OffsetWristSearch& search, std::size_t b, double in, double m_in, double outside,
                              double m_out) {
  const double start = in;
  double f_in = 0.0, f = 0.0;
  m_in += tangency_slack;  // ≥ 0 inside, < 0 outside (unless the branch ends by degeneracy)
  m_out += tangency_slack;
  int side = 0;
  for (int step = 0; step < 200 && std::abs(outside - in) > 1e-14; ++step) {
    double mid = 0.5 * (in + outside);
    if (step % 4 != 3 && m_in >= 0.0 && m_out < 0.0) {
      const double t = in + (outside - in) * (m_in / (m_in - m_out));
      if (t > std::min(in, outside) && t < std::max(in, outside)) mid = t;
    }
    double m;
    if (search.evaluate(mid, b, f, m)) {
      in = mid;
      f_in = f;
      m_in = m + tangency_slack;
      if (side == 1) m_out *= 0.5;
      side = 1;
    } else {
      outside = mid;
      m_out = m + tangency_slack;
      if (side == -1) m_in *= 0.5;
      side = -1;
    }
  }
  std::vector<Point> points;
  if (in == start) return points;  // the sample itself is the end (to rounding)
  points.push_back({in, f_in});
  // Sub-samples uniform in u = √((θ − θ_end) / (θ_start − θ_end)): the branch and its partner
  // (the other label of the subproblem that reaches its tangency) are one smooth function
  // g(±u), f_b ≈ f_end + g₁ u + g₂ u².
  auto theta_at = [&](double u) { return in + (start - in) * u * u; };
  for (int k = 1; k < end_samples; ++k) {
    const double theta = theta_at(static_cast<double>(k) / end_samples);
    double value;
    if (search.evaluate(theta, b, value)) points.push_back({theta, value});
  }
  // A pair of roots closer to the end than the first sub-sample (a touching pair next to the
  // tangency): f leaves the end towards zero and comes back. The slope g₁ at u = 0 (probed at
  // u = 1e-3) and the first sub-sample give the model's extremum; where it may reach zero, a
  // golden-section search finds it and the run gets that point, so that the scan brackets both
  // roots.
  const double u1 = 1.0 / end_samples;
  const double u_probe = 1e-3;
  double f_probe = 0.0;
  if (points.size() >= 2 && points[1].theta == theta_at(u1) && f_in != 0.0 &&
      search.evaluate(theta_at(u_probe), b, f_probe)) {
    const double sign = f_in < 0.0 ? -1.0 : 1.0;
    const double h0 = sign * f_in;                        // > 0
    const double h1 = sign * (f_probe - f_in) / u_probe;  // slope of |f| in u
    const double h2 = (sign * points[1].value - h0 - h1 * u1) / (u1 * u1);
    const bool heads_to_zero = h1 < 0.0;
    const double u_min = h2 > 0.0 ? -h1 / (2.0 * h2) : u1;
    const double h_min = h2 > 0.0 ? h0 - h1 * h1 / (4.0 * h2) : h0 + h1 * u1 + h2 * u1 * u1;
    if (heads_to_zero && u_min <= u1 && h_min < 0.5 * h0) {
      Point low;
      if (minimise(search, b, sign, std::min(in, points[1].theta), std::max(in, points[1].theta), low) &&
          low.theta != in && low.theta != points[1].theta)
        points.insert(points.begin() + 1, low);
    }
  }
  return points;
}

// branch_end() measuring the margins at both points first.
std::vector<Point> branch_end(const OffsetWristSearch& search, std::size_t b, double in, double outside) {
  return branch_end(search, b, in, search.margin(in, b), outside, search.margin(outside, b));
}

// A gap the samples straddle: branch b exists at the samples t₋₁, t₀, t₁ but its margin has a
// sampled minimum at t₀ that a parabola brings near zero. Golden-section minimisation of the
// margin looks for a θ in (t₋₁, t₁) where the branch does not exist; true with that θ and its
// margin if there is one (the run is then split there).
bool straddled_gap(const OffsetWristSearch& search, std::size_t b, double lo, double hi, double& theta,
                   double& margin) {
  const double ratio = 0.5 * (std::sqrt(5.0) - 1.0);
  double x1 = hi - ratio * (hi - lo);
  double x2 = lo + ratio * (hi - lo);
  double f = 0.0, m1 = 0.0, m2 = 0.0;
  if (!search.evaluate(x1, b, f, m1)) {
    theta = x1, margin = m1;
    return true;
  }
  if (!search.evaluate(x2, b, f, m2)) {
    theta = x2, margin = m2;
    return true;
  }
  for (int k = 0; k < 80 && hi - lo > 1e-13; ++k) {
    if (m1 < m2) {
      hi = x2;
      x2 = x1;
      m2 = m1;
      x1 = hi - ratio * (hi - lo);
      if (!search.evaluate(x1, b, f, m1)) {
        theta = x1, margin = m1;
        return true;
      }
    } else {
      lo = x1;
      x1 = x2;
      m1 = m2;
      x2 = lo + ratio * (hi - lo);
      if (!search.evaluate(x2, b, f, m2)) {
        theta = x2, margin = m2;
        return true;
      }
    }
  }
  return false;
}

// An island: branch b absent at the samples t₋₁, t₀, t₁ but with a sampled maximum of its
// margin at t₀ that a parabola brings near zero. Golden-section maximisation of the margin
// finds a point of the island if there is one; the island is then sampled from both its ends.
void island(const OffsetWristSearch& search, std::size_t b, double lo, double hi, SolutionList& out) {
  const double ratio = 0.5 * (std::sqrt(5.0) - 1.0);
  double x1 = hi - ratio * (hi - lo);
  double x2 = lo + ratio * (hi - lo);
  double m1 = search.margin(x1, b), m2 = search.margin(x2, b);
  const double left = lo, right = hi;
  double inside = 0.0;
  bool found = false;
  for (int k = 0; k < 80 && hi - lo > 1e-13; ++k) {
    double f;
    if (m1 >= 0.0 && search.evaluate(x1, b, f)) {
      inside = x1;
      found = true;
      break;
    }
    if (m2 >= 0.0 && search.evaluate(x2, b, f)) {
      inside = x2;
      found = true;
      break;
    }
    if (m1 > m2) {
      hi = x2;
      x2 = x1;
      m2 = m1;
      x1 = hi - ratio * (hi - lo);
      m1 = search.margin(x1, b);
    } else {
      lo = x1;
      x1 = x2;
      m1 = m2;
      x2 = lo + ratio * (hi - lo);
      m2 = search.margin(x2, b);
    }
  }
  if (!found) return;
  double f_inside = 0.0;
  search.evaluate(inside, b, f_inside);
  std::vector<Point> run = branch_end(search, b, inside, left);
  run.push_back({inside, f_inside});
  const std::vector<Point> back = branch_end(search, b, inside, right);
  run.insert(run.end(), back.rbegin(), back.rend());
  scan(search, b, run, true, true, out);
}

// The angles sampled: `samples` equally spaced, and one inside every interval between two
// positioning ends that none of them falls in (a gap the equal spacing would straddle, an
// island it would miss), so that the runs, gaps and islands of the search see it; in order.
std::vector<double> sample_angles(const OffsetWristSearch& search, int samples) {
  const double step = 2.0 * pi / samples;
  std::vector<double> thetas(static_cast<std::size_t>(samples));
  for (int j = 0; j < samples; ++j) thetas[static_cast<std::size_t>(j)] = -pi + j * step;
  const std::vector<double> ends = search.positioning_ends();
  for (std::size_t i = 0; i < ends.size(); ++i) {
    const double lo = ends[i];
    const double hi = i + 1 < ends.size() ? ends[i + 1] : ends.front() + 2.0 * pi;
    const double first_sample_after = -pi + (std::floor((lo + pi) / step) + 1.0) * step;
    const double mid = 0.5 * (lo + hi);  // in [−π, 2π): into the samples' [−π, π)
    if (first_sample_after >= hi) thetas.push_back(mid < pi ? mid : mid - 2.0 * pi);
  }
  std::sort(thetas.begin(), thetas.end());
  return thetas;
}

}  // namespace

std::vector<Eigen::VectorXd> offset_wrist_search(const RevoluteChain& chain, const ChainGeometry& geometry,
                                                 const Posed& pose, int samples) {
  const OffsetWristSearch search(chain, geometry, pose);
  const std::vector<double> thetas = sample_angles(search, samples);
  const int n = static_cast<int>(thetas.size());
  std::vector<Sample> table(static_cast<std::size_t>(n));
  for (int j = 0; j < n; ++j) table[static_cast<std::size_t>(j)] = search.evaluate(thetas[static_cast<std::size_t>(j)]);
  auto wrapped = [&](int j) { return static_cast<std::size_t>(((j % n) + n) % n); };
  auto at = [&](int j) -> const Sample& { return table[wrapped(j)]; };
  // j beyond [0, n): the same sample a turn later / earlier.
  auto theta_of = [&](int j) {
    const int turns = j >= 0 ? j / n : -((n - 1 - j) / n);
    return thetas[wrapped(j)] + 2.0 * pi * turns;
  };

  SolutionList out;
  std::vector<Point> run;
  // A sampled minimum of the margin of branch b at sample k (existing, as its neighbours) that a
  // parabola brings near zero: a gap between the samples may hide there.
  auto dip_at = [&](std::size_t b, int k) {
    const double mm = at(k - 1).margin[b], m0 = at(k).margin[b], mp = at(k + 1).margin[b];
    return m0 <= mm && m0 <= mp && m0 < 4.0 * ((mm - m0) + (mp - m0));
  };
  // The existing samples first … last of branch b, with the branch absent at `before` (margin
  // m_before) and at `after` (margin m_after): split at the gaps the samples straddle, each
  // piece followed to its ends and scanned.
  auto process_run = [&](std::size_t b, int first, int last, double before, double m_before, double after,
                         double m_after) {
    int piece = first;
    for (int k = first; k <= last; ++k) {
      double gap_theta = 0.0, gap_margin = 0.0;
      const bool gap_found = k > piece && k < last && dip_at(b, k) &&
                             straddled_gap(search, b, theta_of(k - 1), theta_of(k + 1), gap_theta, gap_margin);
      if (!gap_found && k < last) continue;
      const int right = !gap_found ? last : (gap_theta < theta_of(k) ? k - 1 : k);
      run.clear();
      const std::vector<Point> front = branch_end(search, b, theta_of(piece), at(piece).margin[b], before, m_before);
      run.insert(run.end(), front.begin(), front.end());
      for (int i = piece; i <= right; ++i) run.push_back({theta_of(i), at(i).value[b]});
      const std::vector<Point> back = branch_end(search, b, theta_of(right), at(right).margin[b],
                                                 gap_found ? gap_theta : after, gap_found ? gap_margin : m_after);
      run.insert(run.end(), back.rbegin(), back.rend());
      scan(search, b, run, !front.empty(), !back.empty(), out);
      if (!gap_found) break;
      piece = right + 1;
      before = gap_theta;
      m_before = gap_margin;
      k = piece;  // the loop's ++k then looks at piece + 1 first
    }
  };
  for (std::size_t b = 0; b < 4; ++b) {
    int gap = -1;  // a sample where the branch does not exist
    for (int j = 0; j < n && gap < 0; ++j)
      if (!at(j).exists[b]) gap = j;
    if (gap < 0) {
      // The branch exists at every sample: one periodic run, unless it has a gap the samples
      // straddle, from which it is then followed once round.
      double gap_theta = 0.0, gap_margin = 0.0;
      int k = 0;
      while (k < n &&
             !(dip_at(b, k) && straddled_gap(search, b, theta_of(k - 1), theta_of(k + 1), gap_theta, gap_margin)))
        ++k;
      if (k == n) {
        // Two samples repeated past the turn so that the wrap-around interval and extremum are
        // scanned too.
        run.clear();
        for (int j = 0; j < n + 2; ++j) run.push_back({theta_of(j), at(j).value[b]});
        scan(search, b, run, false, false, out);
      } else {
        const int first = gap_theta < theta_of(k) ? k : k + 1;  // the first sample after the gap
        process_run(b, first, first + n - 1, gap_theta, gap_margin, gap_theta + 2.0 * pi, gap_margin);
      }
      continue;
    }
    // Runs of consecutive existing samples, starting after the gap, once round; islands
    // between absent samples.
    for (int j = gap + 1; j <= gap + n;) {
      if (!at(j).exists[b]) {
        const Sample& sm = at(j - 1);
        const Sample& sp = at(j + 1);
        const double mm = sm.margin[b], m0 = at(j).margin[b], mp = sp.margin[b];
        if (!sm.exists[b] && !sp.exists[b] && m0 >= mm && m0 >= mp && -m0 < 4.0 * ((m0 - mm) + (m0 - mp)))
          island(search, b, theta_of(j - 1), theta_of(j + 1), out);
        ++j;
        continue;
      }
      int last = j;
      while (last + 1 <= gap + n && at(last + 1).exists[b]) ++last;
      process_run(b, j, last, theta_of(j - 1), at(j - 1).margin[b], theta_of(last + 1), at(last + 1).margin[b]);
      j = last + 1;
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
