// Hexapod geometry, inverse and forward kinematics, workspace check, JSON description (leg
// speeds along a path: hexapod_along_path.cpp).
//
// JSON rather than YAML: nlohmann/json is a single header-only Debian package
// (nlohmann-json3-dev) linked only at build time, so the installed library gains no runtime
// dependency, and Python reads the same file with the standard library.
#include "dispkin/hexapod/hexapod.hpp"
#include "dispkin/input_budget.hpp"
#include "dispkin/numbers.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include <Eigen/LU>
#include <Eigen/Eigenvalues>
#include <nlohmann/json.hpp>

namespace dispkin::hexapod {

namespace {


// Points that span at least a plane: the second singular value of the centred points is not
// negligible against the first. Collinear (or coincident) joints make the platform turn
// freely about their line, a singular hexapod for every pose.
bool spans_plane(const Hexapod::Joints& joints) {
  const Eigen::Vector3d centroid = joints.rowwise().mean();
  const Hexapod::Joints centred = joints.colwise() - centroid;
  // Eigenvalues of the scatter matrix are the squared singular values, ascending.
  const Eigen::Vector3d s2 =
      Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(centred * centred.transpose()).eigenvalues();
  return s2(2) > 0.0 && s2(1) > 1e-18 * s2(2);
}

// A JSON value as it appears in a message: strings bare (describe() quotes them), the rest as
// JSON written only as far as a message shows it (describe() cuts at max_echoed_characters):
// a million-element array is not serialised to be cut afterwards. Arrays and objects cut short
// end with their size.
constexpr std::size_t json_preview = 120;
constexpr std::size_t json_preview_scalar = 40;

void append_json(const nlohmann::json& value, std::string& out) {
  if (value.is_array() || value.is_object()) {
    out += value.is_array() ? '[' : '{';
    std::size_t shown = 0;
    for (auto it = value.begin(); it != value.end() && out.size() <= json_preview; ++it, ++shown) {
      if (shown > 0) out += ',';
      if (value.is_object())
        out += nlohmann::json(it.key()).dump(-1, ' ', false, nlohmann::json::error_handler_t::replace) + ':';
      append_json(*it, out);
    }
    if (shown < value.size()) out += ", … " + std::to_string(value.size()) + (value.is_array() ? " items" : " keys");
    out += value.is_array() ? ']' : '}';
  } else {
    const std::string text = value.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
    out += text.size() <= json_preview_scalar ? text : text.substr(0, json_preview_scalar) + "…";
  }
}

std::string json_text(const nlohmann::json& value) {
  if (value.is_string()) return value.get<std::string>();
  std::string out;
  append_json(value, out);
  return out;
}

std::string leg_argument(const char* name, int i) { return std::string(name) + "[" + std::to_string(i) + "]"; }

}  // namespace

Hexapod::Hexapod(const Joints& base_joints, const Joints& platform_joints, const Legs& leg_min, const Legs& leg_max,
                 const Legs& leg_speed, const Posed& home)
    : base_(base_joints),
      platform_(platform_joints),
      leg_min_(leg_min),
      leg_max_(leg_max),
      leg_speed_(leg_speed),
      home_(home) {
  require_translation(base_joints, "base_joints");
  require_translation(platform_joints, "platform_joints");
  require(spans_plane(base_joints), "base_joints", base_joints, "must not be collinear (the joints must span a plane)");
  require(spans_plane(platform_joints), "platform_joints", platform_joints,
          "must not be collinear (the joints must span a plane)");
  for (int i = 0; i < 6; ++i) {
    require(std::isfinite(leg_min(i)) && leg_min(i) >= 0.0, leg_argument("leg_min", i), leg_min(i),
            "must be finite and not negative");
    require(std::isfinite(leg_max(i)) && leg_max(i) > leg_min(i), leg_argument("leg_max", i), leg_max(i),
            "must be finite and greater than leg_min[" + std::to_string(i) + "]");
    require(leg_max(i) <= numeric_range::max_translation, leg_argument("leg_max", i), leg_max(i),
            "must be at most 1e12 m (dispkin's numeric range)");
    require_limit(leg_speed(i), leg_argument("leg_speed", i));
  }
  const Eigen::Vector3d centroid = platform_joints.rowwise().mean();
  platform_scale_ = (platform_joints.colwise() - centroid).colwise().norm().maxCoeff();
}

Hexapod Hexapod::symmetric(double base_radius, double base_gap, double platform_radius, double platform_gap,
                           double height, double leg_min, double leg_max, double leg_speed) {
  require_positive(base_radius, "base_radius");
  require_positive(platform_radius, "platform_radius");
  require(std::isfinite(base_gap) && base_gap >= 0.0 && base_gap < 2 * pi / 3, "base_gap", base_gap,
          "must be in [0, 2π/3) rad");
  require(std::isfinite(platform_gap) && platform_gap >= 0.0 && platform_gap < 2 * pi / 3, "platform_gap", platform_gap,
          "must be in [0, 2π/3) rad");
  require_positive(height, "height");
  require(!(base_gap == 0.0 && platform_gap == 0.0), "base_gap", base_gap,
          "and platform_gap = 0 would make a 3-3 hexapod (legs meeting in pairs at both ends); one gap must be > 0");
  Joints base;
  Joints platform;
  for (int k = 0; k < 3; ++k) {
    const double centre = 2 * pi / 3 * k;
    const double angles_base[2] = {centre - base_gap / 2, centre + base_gap / 2};
    const double angles_platform[2] = {centre - pi / 3 + platform_gap / 2, centre + pi / 3 - platform_gap / 2};
    for (int j = 0; j < 2; ++j) {
      base.col(2 * k + j) << base_radius * std::cos(angles_base[j]), base_radius * std::sin(angles_base[j]), 0.0;
      platform.col(2 * k + j) << platform_radius * std::cos(angles_platform[j]),
          platform_radius * std::sin(angles_platform[j]), 0.0;
    }
  }
  return Hexapod(base, platform, Legs::Constant(leg_min), Legs::Constant(leg_max), Legs::Constant(leg_speed),
                 Posed(Eigen::Quaterniond::Identity(), Eigen::Vector3d(0.0, 0.0, height)));
}

Hexapod::Legs Hexapod::leg_lengths(const Posed& pose) const noexcept {
  const Eigen::Matrix3d r = pose.rotation();
  const Joints legs = ((r * platform_).colwise() + (pose.translation())) - base_;
  return legs.colwise().norm().transpose();
}

Hexapod::Legs Hexapod::leg_lengths(const Eigen::Matrix<double, 6, 1>& xyzuvw, const Eigen::Vector3d& pivot) const {
  return leg_lengths(Posed::from_xyzuvw(xyzuvw, pivot));
}

Hexapod::Jacobian Hexapod::leg_jacobian(const Posed& pose) const noexcept {
  // ℓ_i(T exp(ξ)) = ‖R (p_i + v + ω × p_i) + t − b_i‖ + O(ξ²), so
  // ∂ℓ_i/∂ξ = u_iᵀ R (v + ω × p_i) = ũ_iᵀ v + (p_i × ũ_i)ᵀ ω with ũ_i = Rᵀ u_i.
  const Eigen::Matrix3d r = pose.rotation();
  const Joints legs = ((r * platform_).colwise() + pose.translation()) - base_;
  Jacobian j;
  for (int i = 0; i < 6; ++i) {
    const Eigen::Vector3d u = r.transpose() * legs.col(i).normalized();
    j.row(i).head<3>() = u.transpose();
    j.row(i).tail<3>() = platform_.col(i).cross(u).transpose();
  }
  return j;
}

Posed Hexapod::forward(const Legs& legs, const Posed& guess, const ForwardOptions& options) const {
  for (int i = 0; i < 6; ++i) {
    require(std::isfinite(legs(i)) && legs(i) > 0.0, leg_argument("legs", i), legs(i),
            "must be finite and greater than zero");
  }
  for (int i = 0; i < 6; ++i) {
    if (legs(i) < leg_min_(i) || legs(i) > leg_max_(i)) {
      throw std::invalid_argument(describe("legs", legs,
                                           "legs[" + std::to_string(i) + "] is outside its length range [" +
                                               std::to_string(leg_min_(i)) + ", " + std::to_string(leg_max_(i)) +
                                               "]: no pose has these legs within the hexapod's limits"));
    }
  }
  require_positive(options.tolerance, "tolerance");
  require(options.max_iterations > 0, "max_iterations", options.max_iterations, "must be at least 1");
  // Rotation columns scaled by the platform size so the condition number compares metres
  // with metres, independent of the unit of length.
  Legs scale;
  scale << 1, 1, 1, platform_scale_, platform_scale_, platform_scale_;
  Posed pose = guess;
  Legs residual = leg_lengths(pose) - legs;
  double error = residual.cwiseAbs().maxCoeff();
  bool polishing = false;
  for (int iteration = 0; iteration < options.max_iterations; ++iteration) {
    // One more step after reaching the tolerance: Newton converges quadratically, so it takes
    // the pose error from about cond(J) × tolerance down to rounding (the "pose step tiny").
    if (error <= options.tolerance) {
      if (polishing) return pose;
      polishing = true;
    }
    const Jacobian scaled = leg_jacobian(pose) * scale.asDiagonal();
    const Eigen::PartialPivLU<Jacobian> lu(scaled);
    const double rcond = lu.rcond();
    if (!(rcond >= options.min_rcond)) {
      std::ostringstream out;
      out.precision(6);
      out << "Hexapod::forward: singular leg Jacobian (reciprocal condition number " << rcond << ") after " << iteration
          << " iterations, leg length residual " << error << " m";
      throw std::runtime_error(out.str());
    }
    const Legs step = scale.asDiagonal() * lu.solve(-residual);
    const Posed next = pose * Posed::exp(Twistd(step));
    const Legs next_residual = leg_lengths(next) - legs;
    const double next_error = next_residual.cwiseAbs().maxCoeff();
    if (polishing) return next_error <= error ? next : pose;
    pose = next;
    residual = next_residual;
    error = next_error;
    if (!std::isfinite(error)) break;
  }
  if (error <= options.tolerance) return pose;
  std::ostringstream out;
  out.precision(6);
  out << "Hexapod::forward: no convergence after " << options.max_iterations << " iterations, leg length residual "
      << error << " m (tolerance " << options.tolerance
      << " m); the leg lengths may be unreachable or the guess too far away";
  throw std::runtime_error(out.str());
}

WorkspaceCheck Hexapod::check(const Posed& pose) const noexcept {
  WorkspaceCheck result;
  result.lengths = leg_lengths(pose);
  for (int i = 0; i < 6; ++i) {
    const double l = result.lengths(i);
    if (l < leg_min_(i)) result.violations.push_back({i, l, leg_min_(i), leg_max_(i), leg_min_(i) - l});
    if (l > leg_max_(i)) result.violations.push_back({i, l, leg_min_(i), leg_max_(i), l - leg_max_(i)});
  }
  return result;
}

void Hexapod::require_reachable(const Posed& pose) const {
  const WorkspaceCheck c = check(pose);
  if (c.reachable()) return;
  const LegViolation& v = c.violations.front();
  std::ostringstream reason;
  reason.precision(12);
  reason << "outside the leg's range [" << v.lower << ", " << v.upper << "] by " << v.excess << " m";
  throw std::invalid_argument(describe("leg " + std::to_string(v.leg) + " length", v.length, reason.str()));
}

void Hexapod::add_leg_speed_group(MetricSetd& set, int group) const {
  for (int i = 0; i < 6; ++i) set.add_relative(Eigen::Vector3d(platform_.col(i)), group);
  set.set_group_speed(group, leg_speed_.minCoeff());
}


Posed Hexapod::forward(const Eigen::VectorXd& q) const {
  require(q.size() == 6, "q size", static_cast<long>(q.size()), "a hexapod has 6 legs");
  return forward(Legs(q));
}

std::vector<Eigen::VectorXd> Hexapod::inverse(const Posed& pose) const { return {Eigen::VectorXd(leg_lengths(pose))}; }

JointLimits Hexapod::joint_limits() const { return {leg_min_, leg_max_, leg_speed_, Eigen::VectorXd()}; }

std::vector<std::string> Hexapod::joint_names() const { return {"leg1", "leg2", "leg3", "leg4", "leg5", "leg6"}; }

Eigen::Matrix<double, 6, 1> xyzuvw_for_new_pivot(const Eigen::Matrix<double, 6, 1>& xyzuvw,
                                                 const Eigen::Vector3d& old_pivot, const Eigen::Vector3d& new_pivot) {
  // T = from_xyzuvw(v, p_old): t = XYZ_old + p_old − R p_old; about p_new the same t needs
  // XYZ_new = t − p_new + R p_new = XYZ_old + (R − I)(p_new − p_old).
  const Posed pose = Posed::from_xyzuvw(xyzuvw, old_pivot);
  require_translation(new_pivot, "new_pivot");
  Eigen::Matrix<double, 6, 1> out = xyzuvw;
  out.head<3>() += pose.rotation() * (new_pivot - old_pivot) - (new_pivot - old_pivot);
  return out;
}

// --- JSON description ----------------------------------------------------------------------

namespace {

using nlohmann::json;

// The keys a description's objects may have: any other (a misspelt "sped", a misplaced
// "leg_speed") is refused rather than silently ignored.
void require_known_keys(const json& object, std::initializer_list<const char*> known, const std::string& where) {
  if (!object.is_object()) return;  // member() says what is wrong with it
  for (auto it = object.begin(); it != object.end(); ++it) {
    bool is_known = false;
    for (const char* k : known) is_known = is_known || it.key() == k;
    if (is_known) continue;
    std::string allowed;
    for (const char* k : known) allowed += std::string(allowed.empty() ? "" : ", ") + k;
    const std::string name = where.empty() ? it.key() : where + "." + it.key();
    const std::string reason = "unknown key (allowed here: " + allowed + ")";
    if (it->is_number()) throw std::invalid_argument(describe(name, it->get<double>(), reason));
    throw std::invalid_argument(describe(name, json_text(*it), reason));
  }
}

// nlohmann's parser keeps its own stack, but dump() and the messages that show a value
// recurse once per level: nesting is refused while parsing, at max_nesting_depth.
struct TooDeep {
  std::size_t position;
};

json parse_bounded(const std::string& text) {
  require(text.size() <= input_budget::max_hexapod_json_bytes, "description size",
          static_cast<unsigned long>(text.size()),
          "more than " + std::to_string(input_budget::max_hexapod_json_bytes) +
              " bytes, the limit of a hexapod description (doc/input-budget.md)");
  const json::parser_callback_t depth_check = [](int depth, json::parse_event_t event, json&) {
    if (depth >= input_budget::max_nesting_depth &&
        (event == json::parse_event_t::object_start || event == json::parse_event_t::array_start))
      throw TooDeep{static_cast<std::size_t>(depth) + 1};
    return true;
  };
  try {
    return json::parse(text, depth_check);
  } catch (const TooDeep& deep) {
    throw std::invalid_argument(describe("description nesting depth", static_cast<long>(deep.position),
                                         "arrays and objects nest at most " +
                                             std::to_string(input_budget::max_nesting_depth) +
                                             " deep (doc/input-budget.md)"));
  } catch (const json::exception& e) {  // parse_error, and out_of_range for numbers like 1e999
    throw std::invalid_argument(
        describe("description", std::string("<text>"), std::string("is not JSON: ") + e.what()));
  }
}

const json& member(const json& object, const std::string& key, const std::string& where) {
  const std::string name = where.empty() ? key : where + "." + key;
  require(object.is_object(), where.empty() ? std::string("description") : where, json_text(object),
          "must be a JSON object");
  const auto it = object.find(key);
  require(it != object.end(), name, std::string("<missing>"), "required key is missing");
  return *it;
}

double number(const json& value, const std::string& name) {
  require(value.is_number(), name, json_text(value), "must be a number");
  return value.get<double>();
}

Eigen::Vector3d vector3(const json& value, const std::string& name) {
  require(value.is_array() && value.size() == 3, name, json_text(value), "must be an array of 3 numbers");
  Eigen::Vector3d out;
  for (int i = 0; i < 3; ++i) out(i) = number(value[static_cast<std::size_t>(i)], name + "[" + std::to_string(i) + "]");
  return out;
}

json to_json_array(const Eigen::Vector3d& v) { return json::array({v.x(), v.y(), v.z()}); }

}  // namespace

std::string Hexapod::to_json() const {
  json legs = json::array();
  for (int i = 0; i < 6; ++i) {
    legs.push_back({{"base", to_json_array(base_.col(i))},
                    {"platform", to_json_array(platform_.col(i))},
                    {"min", leg_min_(i)},
                    {"max", leg_max_(i)},
                    {"speed", leg_speed_(i)}});
  }
  const Eigen::Quaterniond& q = home_.quaternion();
  json description = {{"format", "dispkin.hexapod"},
                      {"version", 1},
                      {"units", "m, m/s"},
                      {"legs", legs},
                      {"home",
                       {{"translation", to_json_array(home_.translation())},
                        {"quaternion_wxyz", json::array({q.w(), q.x(), q.y(), q.z()})}}}};
  return description.dump(2);
}

Hexapod Hexapod::from_json(const std::string& text) {
  const json d = parse_bounded(text);
  require_known_keys(d, {"format", "version", "units", "legs", "home"}, "");
  const json& format = member(d, "format", "");
  require(format == "dispkin.hexapod", "format", json_text(format), "must be \"dispkin.hexapod\"");
  const json& version = member(d, "version", "");
  require(version == 1, "version", json_text(version), "must be 1 (the only version this build reads)");
  const json& legs = member(d, "legs", "");
  require(legs.is_array() && legs.size() == 6, "legs", json_text(legs), "must be an array of 6 leg objects");
  Joints base;
  Joints platform;
  Legs lo, hi, speed;
  for (int i = 0; i < 6; ++i) {
    const std::string where = "legs[" + std::to_string(i) + "]";
    const json& leg = legs[static_cast<std::size_t>(i)];
    require_known_keys(leg, {"base", "platform", "min", "max", "speed"}, where);
    base.col(i) = vector3(member(leg, "base", where), where + ".base");
    platform.col(i) = vector3(member(leg, "platform", where), where + ".platform");
    lo(i) = number(member(leg, "min", where), where + ".min");
    hi(i) = number(member(leg, "max", where), where + ".max");
    speed(i) = number(member(leg, "speed", where), where + ".speed");
  }
  const json& home = member(d, "home", "");
  require_known_keys(home, {"translation", "quaternion_wxyz"}, "home");
  const Eigen::Vector3d t = vector3(member(home, "translation", "home"), "home.translation");
  const json& q = member(home, "quaternion_wxyz", "home");
  require(q.is_array() && q.size() == 4, "home.quaternion_wxyz", json_text(q), "must be an array of 4 numbers");
  Eigen::Quaterniond quaternion(number(q[0], "home.quaternion_wxyz[0]"), number(q[1], "home.quaternion_wxyz[1]"),
                                number(q[2], "home.quaternion_wxyz[2]"), number(q[3], "home.quaternion_wxyz[3]"));
  return Hexapod(base, platform, lo, hi, speed, Posed(quaternion, t));
}

Hexapod Hexapod::load(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  require(static_cast<bool>(in), "path", path, "cannot be opened for reading");
  // Read in blocks up to the limit: a larger file is refused without being read to its end.
  std::string text;
  require(input_budget::read_at_most(in, input_budget::max_hexapod_json_bytes, text), "path", path,
          "is larger than " + std::to_string(input_budget::max_hexapod_json_bytes) +
              " bytes, the limit of a hexapod description (doc/input-budget.md)");
  try {
    return from_json(text);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(echoed(path) + ": " + e.what());
  }
}

void Hexapod::save(const std::string& path) const {
  std::ofstream out(path);
  require(static_cast<bool>(out), "path", path, "cannot be opened for writing");
  out << to_json() << '\n';
  require(static_cast<bool>(out), "path", path, "write failed");
}

}  // namespace dispkin::hexapod
