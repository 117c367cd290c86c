// Python binding of dispkin/planning/retiming.hpp with serial/serial_retiming.hpp and
// hexapod/hexapod_retiming.hpp: check_joint_limits, retime.
#include <algorithm>
#include <optional>
#include <string>

#include <pybind11/eigen.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "bindings.hpp"
#include "conversions.hpp"
#include "interpreter_lock.hpp"
#include "path_state.hpp"
#include "value_protocol.hpp"
#include "dispkin/hexapod/hexapod_retiming.hpp"
#include "dispkin/serial/serial_retiming.hpp"

namespace dispkin {
namespace python {

namespace {

using hexapod::Hexapod;

// Per-sample arrays of a report: (N,) times and s, (N, dof) for the joint quantities.
py::dict report_arrays(const JointLimitReport& r) {
  const auto n = static_cast<Eigen::Index>(r.samples.size());
  const Eigen::Index dof = n > 0 ? r.samples.front().q.size() : 0;
  // A machine without a dynamics model (a hexapod) has no torques: (N, 0) arrays.
  const Eigen::Index torques = n > 0 ? r.samples.front().static_torque.size() : 0;
  Eigen::VectorXd time(n), s(n);
  Eigen::MatrixXd q(n, dof), qd(n, dof), qdd(n, dof), tau_static(n, torques), tau_dynamic(n, torques);
  for (Eigen::Index k = 0; k < n; ++k) {
    const JointSample& x = r.samples[static_cast<std::size_t>(k)];
    time(k) = x.time;
    s(k) = x.s;
    q.row(k) = x.q.transpose();
    qd.row(k) = x.qd.transpose();
    qdd.row(k) = x.qdd.transpose();
    if (torques > 0) {
      tau_static.row(k) = x.static_torque.transpose();
      tau_dynamic.row(k) = x.dynamic_torque.transpose();
    }
  }
  py::dict d;
  d["time"] = time;
  d["s"] = s;
  d["q"] = q;
  d["qd"] = qd;
  d["qdd"] = qdd;
  d["static_torque"] = tau_static;
  d["dynamic_torque"] = tau_dynamic;
  return d;
}

// Pickled states: every field, the samples as tuples of their vectors.
py::tuple report_state(const JointLimitReport& r) {
  py::list samples;
  for (const JointSample& x : r.samples)
    samples.append(py::make_tuple(x.time, x.s, x.q, x.qd, x.qdd, x.static_torque, x.dynamic_torque));
  return py::make_tuple(py::tuple(samples), r.velocity_factor, r.acceleration_factor, r.velocity_joint,
                        r.velocity_sample, r.torque_joint, r.torque_sample, r.position_excess, r.position_joint,
                        r.position_sample);
}

// A trajectory inside a result's state, at `where`; the Trajectory's own checks name their field.
Trajectory nested_trajectory(const py::handle& state, const StateField& where) {
  return inside(where, [&] { return trajectory_from_state(state, where); });
}

// A report from the 10 items of its state; `field(k, name)` says where item k sits.
template <typename Field>
JointLimitReport report_of_items(const py::tuple& s, Field field) {
  JointLimitReport r;
  const StateField samples_at = field(0, "samples");
  const py::sequence samples = state_sequence(s[0], samples_at);
  for (std::size_t k = 0; k < samples.size(); ++k) {
    const StateField at = samples_at.at(k);
    const py::tuple x = state_fields(samples[k], 7, at);
    const auto joints = [&](std::size_t i, const char* name) {
      return state_vector<Eigen::Dynamic>(x[i], at / ("." + std::string(name)));
    };
    r.samples.push_back(JointSample{state_number(x[0], at / ".time"), state_number(x[1], at / ".s"), joints(2, "q"),
                                    joints(3, "qd"), joints(4, "qdd"), joints(5, "static_torque"),
                                    joints(6, "dynamic_torque")});
  }
  const auto joint = [&](std::size_t k, const char* name) { return state_cast<int>(s[k], field(k, name)); };
  const auto sample = [&](std::size_t k, const char* name) {
    return state_count(s[k], field(k, name), r.samples.size());
  };
  r.velocity_factor = state_cast<double>(s[1], field(1, "velocity_factor"));
  r.acceleration_factor = state_cast<double>(s[2], field(2, "acceleration_factor"));
  r.velocity_joint = joint(3, "velocity_joint");
  r.velocity_sample = sample(4, "velocity_sample");
  r.torque_joint = joint(5, "torque_joint");
  r.torque_sample = sample(6, "torque_sample");
  r.position_excess = state_cast<double>(s[7], field(7, "position_excess"));
  r.position_joint = joint(8, "position_joint");
  r.position_sample = sample(9, "position_sample");
  require_consistent(r);  // the sizes agree before anything reads a sample's vectors
  return r;
}

JointLimitReport report_from_state(const py::object& state) {
  const py::tuple s = state_tuple(state, 10, "JointLimitReport");
  return report_of_items(s, [](std::size_t k, const char* name) { return StateField("JointLimitReport", k, name); });
}

// A report inside a re-timing result's state, at `where`; its own messages name the field.
JointLimitReport nested_report(const py::handle& state, const StateField& where) {
  const py::tuple s = state_fields(state, 10, where);
  const auto field = [&](std::size_t, const char* name) { return where / ("." + std::string(name)); };
  return inside(where, [&] { return report_of_items(s, field); });
}

py::tuple optimal_state(const OptimalRetimeResult& r) {
  return py::make_tuple(trajectory_state(r.trajectory), report_state(r.report), r.velocity_ratio, r.acceleration_ratio,
                        r.torque_ratio, r.margin, r.refinements, r.grid_s, r.grid_speed, r.jerk_window);
}

OptimalRetimeResult optimal_from_state(const py::object& state) {
  const py::tuple s = state_tuple(state, 10, "OptimalRetimeResult");
  const auto field = [](std::size_t k, const char* name) { return StateField("OptimalRetimeResult", k, name); };
  OptimalRetimeResult r;
  r.trajectory = nested_trajectory(s[0], field(0, "trajectory"));
  r.report = nested_report(s[1], field(1, "report"));
  r.velocity_ratio = state_cast<double>(s[2], field(2, "velocity_ratio"));
  r.acceleration_ratio = state_cast<double>(s[3], field(3, "acceleration_ratio"));
  r.torque_ratio = state_cast<double>(s[4], field(4, "torque_ratio"));
  r.margin = state_cast<double>(s[5], field(5, "margin"));
  r.refinements = state_cast<int>(s[6], field(6, "refinements"));
  const Eigen::VectorXd grid_s = state_vector<Eigen::Dynamic>(s[7], field(7, "grid_s"));
  const Eigen::VectorXd grid_speed = state_vector<Eigen::Dynamic>(s[8], field(8, "grid_speed"));
  r.grid_s.assign(grid_s.data(), grid_s.data() + grid_s.size());
  r.grid_speed.assign(grid_speed.data(), grid_speed.data() + grid_speed.size());
  r.jerk_window = state_cast<double>(s[9], field(9, "jerk_window"));
  require_consistent(r);
  return r;
}

RetimeResult retime_from_state(const py::object& state) {
  const py::tuple s = state_tuple(state, 4, "RetimeResult");
  const auto field = [](std::size_t k, const char* name) { return StateField("RetimeResult", k, name); };
  RetimeResult r{nested_trajectory(s[0], field(0, "trajectory")), state_cast<Limits>(s[1], field(1, "limits")),
                 state_cast<int>(s[2], field(2, "iterations")), nested_report(s[3], field(3, "report"))};
  require(r.iterations >= 1, "iterations", static_cast<long>(r.iterations), "must be at least 1 (plans made)");
  return r;
}

JointCheckOptions check_options(int samples_between, double difference_step) {
  JointCheckOptions o;
  o.samples_between = samples_between;
  o.difference_step = difference_step;
  return o;
}

// How the followers take a seven-joint arm's redundancy parameter.
void bind_redundancy_rule(py::module_& m) {
  py::class_<serial::RedundancyRule>(m, "RedundancyRule", R"doc(
How the followers of a Cartesian trajectory (FollowedTrajectory, check_joint_limits, retime by
either method) take a seven-joint arm's redundancy parameter: RedundancyRule() moves it from
q_start's value away from joint limits and singular poses, by the rule of SerialArm.follow per unit
of path (doc/inverse-kinematics.md eqs. 45, 49); RedundancyRule.held() (what they use without one)
keeps it at q_start's value.)doc")
      .def(py::init<>(),
           "The rule that moves the parameter, with follow()'s defaults (gain 0.05, max_rate 0.5, "
           "singularity_weight 0.1).")
      .def_static("held", &serial::RedundancyRule::held, "The rule that keeps the parameter at q_start's value.")
      .def_readwrite("move", &serial::RedundancyRule::move, "False: the parameter stays at q_start's value.")
      .def_readwrite("gain", &serial::RedundancyRule::gain,
                     "g of doc/inverse-kinematics.md eq. 45: rate per unit of the cost's slope, >= 0.")
      .def_readwrite("max_rate", &serial::RedundancyRule::max_rate,
                     "rho of doc/inverse-kinematics.md eq. 45: the largest change of the parameter (rad) per radian "
                     "the joints travel, >= 0.")
      .def_readwrite("singularity_weight", &serial::RedundancyRule::singularity_weight,
                     "mu of doc/inverse-kinematics.md eq. 44: the weight of the singularity term against the "
                     "joint-limit term, >= 0.")
      .def("__repr__", [](const serial::RedundancyRule& r) {
        return "RedundancyRule(move=" + std::string(r.move ? "True" : "False") + ", gain=" + float_repr(r.gain) +
               ", max_rate=" + float_repr(r.max_rate) + ", singularity_weight=" + float_repr(r.singularity_weight) +
               ")";
      });
}

void bind_joint_limit_report(py::module_& m) {
  py::class_<JointLimitReport> report(m, "JointLimitReport", R"doc(
What check_joint_limits found along a trajectory: the KUKA re-timing patent's factors FVEL = max |qd_i| / qd_max_i
and FACC = max |tau_dyn_i| / (tau_max_i - |tau_static_i|) (each <= 1 when the limits hold), where
they are reached, the largest excursion of q outside its position range, and the per-sample
arrays (`samples`: a dict of time, s, q, qd, qdd, static_torque, dynamic_torque; the torques are
(N, 0) arrays for a machine without a dynamics model, a hexapod).)doc");
  report.def_readonly("velocity_factor", &JointLimitReport::velocity_factor, "FVEL.")
      .def_readonly("acceleration_factor", &JointLimitReport::acceleration_factor, "FACC.")
      .def_readonly("velocity_joint", &JointLimitReport::velocity_joint,
                    "Joint index where FVEL is reached (-1: none).")
      .def_readonly("torque_joint", &JointLimitReport::torque_joint, "Joint index where FACC is reached (-1: none).")
      .def_readonly("position_excess", &JointLimitReport::position_excess,
                    "Largest excursion outside [lower, upper] (rad).")
      .def_readonly("position_joint", &JointLimitReport::position_joint, "Joint index of that excursion (-1: none).")
      .def_property_readonly(
          "velocity_time",
          [](const JointLimitReport& r) { return r.samples.empty() ? 0.0 : r.samples[r.velocity_sample].time; },
          "Time (s) where FVEL is reached.")
      .def_property_readonly(
          "torque_time",
          [](const JointLimitReport& r) { return r.samples.empty() ? 0.0 : r.samples[r.torque_sample].time; },
          "Time (s) where FACC is reached.")
      .def_property_readonly("within_limits", &JointLimitReport::within_limits,
                             "FVEL <= 1, FACC <= 1, no position excursion.")
      .def_property_readonly("samples", &report_arrays, "Per-sample arrays (dict).")
      .def("__repr__", [](const JointLimitReport& r) {
        return "JointLimitReport(velocity_factor=" + float_repr(r.velocity_factor) +
               ", acceleration_factor=" + float_repr(r.acceleration_factor) +
               ", samples=" + std::to_string(r.samples.size()) + ")";
      });
  def_pickle(report, "JointLimitReport", &report_state, &report_from_state);
}

void bind_check_joint_limits(py::module_& m) {
  m.def(
      "check_joint_limits",
      // The arm by value: its gravity as at the call, whatever another thread sets meanwhile.
      [](const Trajectory& trajectory, serial::SerialArm arm, const Eigen::VectorXd& q_start, int samples_between,
         double difference_step, const std::optional<serial::RedundancyRule>& redundancy_rule) {
        return check_joint_limits(trajectory, arm, q_start, check_options(samples_between, difference_step),
                                  redundancy_rule.value_or(serial::RedundancyRule::held()));
      },
      py::call_guard<py::gil_scoped_release>(), py::arg("trajectory"), py::arg("robot"), py::arg("q_start"),
      py::arg("samples_between") = 10, py::arg("difference_step") = 1e-4, py::kw_only(),
      py::arg("redundancy_rule") = py::none(),
      "Follow the planned trajectory (poses of the robot's tip link) through the robot's IK, on the branch "
      "continuous from q_start, at every characteristic point of its time laws and `samples_between` "
      "points between them: joint positions, velocities (Jacobian), accelerations and torques (static and "
      "dynamic). Returns a JointLimitReport. RuntimeError naming the time and path position where a pose has "
      "no IK solution, the arm is singular, or the static torque alone exceeds a joint's effort limit. A "
      "seven-joint arm's redundancy parameter as `redundancy_rule` (a RedundancyRule) moves it; None: held at "
      "q_start's value.");

  m.def(
      "check_joint_limits",
      [](const Trajectory& trajectory, const Hexapod& hexapod, int samples_between, double difference_step) {
        return check_joint_limits(trajectory, hexapod, check_options(samples_between, difference_step));
      },
      py::call_guard<py::gil_scoped_release>(), py::arg("trajectory"), py::arg("robot"),
      py::arg("samples_between") = 10, py::arg("difference_step") = 1e-4,
      "The same for a Hexapod, whose legs are its joints: q = leg lengths, qd = leg Jacobian times the body "
      "twist, qdd by central differences; velocity_factor against leg_speed, position_excess against the leg "
      "range. No dynamics model: torques stay empty and acceleration_factor 0.");
}

void bind_retime_result(py::module_& m) {
  py::class_<RetimeResult> retime_result(
      m, "RetimeResult", "The re-timed trajectory, the scaled limits, the plans made and the final report.");
  retime_result.def_readonly("trajectory", &RetimeResult::trajectory, "The trajectory planned with the scaled limits.")
      .def_readonly("limits", &RetimeResult::limits, "The scaled limits it was planned with.")
      .def_readonly("iterations", &RetimeResult::iterations, "Plans made (1: the original plan already fits).")
      .def_readonly("report", &RetimeResult::report,
                    "The joint-limit report of the final trajectory (within_limits is True).")
      .def("__repr__", [](const RetimeResult& r) {
        return "RetimeResult(duration=" + float_repr(r.trajectory.duration()) +
               ", iterations=" + std::to_string(r.iterations) +
               ", velocity_factor=" + float_repr(r.report.velocity_factor) +
               ", acceleration_factor=" + float_repr(r.report.acceleration_factor) + ")";
      });
  def_pickle(
      retime_result, "RetimeResult",
      [](const RetimeResult& r) {
        return py::make_tuple(trajectory_state(r.trajectory), r.limits, r.iterations, report_state(r.report));
      },
      &retime_from_state);
}

void bind_optimal_retime_result(py::module_& m) {
  py::class_<OptimalRetimeResult> optimal(m, "OptimalRetimeResult", R"doc(
What retime(method="optimal") produced: the re-timed trajectory (one constant-acceleration law per
grid interval; with a jerk limit constant-jerk laws), the dense check of it (`report`), the largest joint velocity, acceleration and
torque ratios found by that check (each <= 1; torque = static + dynamic against the effort limit),
the fraction by which the limits were tightened on the grid so that they also hold between grid
points (`margin`) and the re-solves that took, and the grid itself (`grid_s`, `grid_speed`).)doc");
  optimal
      .def_readonly(
          "trajectory", &OptimalRetimeResult::trajectory,
          "The re-timed trajectory: the same path, one constant-acceleration law per grid interval (with a jerk "
          "limit: constant-jerk laws).")
      .def_readonly("report", &OptimalRetimeResult::report, "The dense joint-limit check of `trajectory`.")
      .def_readonly("velocity_ratio", &OptimalRetimeResult::velocity_ratio,
                    "max |qd_i| / qd_max_i at the checked samples.")
      .def_readonly("acceleration_ratio", &OptimalRetimeResult::acceleration_ratio,
                    "max |qdd_i| / qdd_max_i at the checked samples (0 without acceleration limits).")
      .def_readonly("torque_ratio", &OptimalRetimeResult::torque_ratio,
                    "max |tau_i| / tau_max_i at the checked samples (0 without effort limits).")
      .def_readonly("margin", &OptimalRetimeResult::margin, "Fraction by which the grid limits were tightened.")
      .def_readonly("refinements", &OptimalRetimeResult::refinements, "Grid re-solves after a dense check overshoot.")
      .def_readonly("jerk_window", &OptimalRetimeResult::jerk_window,
                    "With a jerk limit (profile=\"scurve\"): the longest moving-average window (s) of the rest-to-rest "
                    "runs, the time each run grew by; 0 without.")
      .def_property_readonly(
          "grid_s",
          [](const OptimalRetimeResult& r) {
            return py::array_t<double>(static_cast<py::ssize_t>(r.grid_s.size()), r.grid_s.data());
          },
          "Grid positions s (m), (N+1,).")
      .def_property_readonly(
          "grid_speed",
          [](const OptimalRetimeResult& r) {
            return py::array_t<double>(static_cast<py::ssize_t>(r.grid_speed.size()), r.grid_speed.data());
          },
          "Path speed at the grid positions (m/s), (N+1,).")
      .def("__repr__", [](const OptimalRetimeResult& r) {
        return "OptimalRetimeResult(duration=" + float_repr(r.trajectory.duration()) +
               ", velocity_ratio=" + float_repr(r.velocity_ratio) +
               ", acceleration_ratio=" + float_repr(r.acceleration_ratio) +
               ", torque_ratio=" + float_repr(r.torque_ratio) + ", margin=" + float_repr(r.margin) +
               ", refinements=" + std::to_string(r.refinements) + ")";
      });
  def_pickle(optimal, "OptimalRetimeResult", &optimal_state, &optimal_from_state);
}

// retime(path, ..., robot=SerialArm).
void bind_retime_serial_arm(py::module_& m) {
  m.def(
      "retime",
      [](const Path& path, const MetricSetd& set, const Limits& limits, const serial::SerialArm& robot,
         const Eigen::VectorXd& q_start, const std::string& profile, const std::string& method, int samples_between,
         int max_iterations, int grid_intervals, const std::optional<Eigen::VectorXd>& joint_acceleration,
         bool torque_limits, double corner_tolerance,
         const std::optional<serial::RedundancyRule>& redundancy_rule) -> py::object {
        const ProfileKind kind = profile_kind(profile);
        const serial::RedundancyRule rule = redundancy_rule.value_or(serial::RedundancyRule::held());
        const serial::SerialArm arm = robot;  // its gravity as at the call, whatever another thread sets meanwhile
        if (method == "scaling") {
          // The scaling loop has no joint acceleration limit to scale against: refused, not ignored.
          if (joint_acceleration)
            throw std::invalid_argument(
                describe("joint_acceleration", *joint_acceleration,
                         "is not a limit of method=\"scaling\" (it scales the Cartesian limits "
                         "until the joint speed and effort limits hold); use method=\"optimal\""));
          RetimeResult result;
          {
            const UnlockedIf unlocked(true, path, set);
            result = retime_by_scaling(path, set, limits, kind, arm, q_start, check_options(samples_between, 1e-4),
                                       max_iterations, corner_tolerance, rule);
          }
          return py::cast(std::move(result));
        }
        if (method != "optimal")
          throw std::invalid_argument(describe("method", method, "must be \"scaling\" or \"optimal\""));
        limits.validate(kind);  // the S-curve needs a jerk limit, the trapezoid refuses one
        OptimalRetimeOptions options;
        options.grid_intervals = grid_intervals;
        if (joint_acceleration) options.joint_acceleration = *joint_acceleration;
        options.torque_limits = torque_limits;
        options.check_samples_between = samples_between;
        options.max_refinements = max_iterations;
        options.corner_tolerance = corner_tolerance;
        OptimalRetimeResult result;
        {
          const UnlockedIf unlocked(true, path, set);
          result = retime_optimal(path, set, limits, arm, q_start, options, rule);
        }
        return py::cast(std::move(result));
      },
      py::arg("path"), py::arg("metric_set"), py::arg("limits"), py::arg("robot"), py::arg("q_start"),
      py::arg("profile") = "scurve", py::arg("method") = "scaling", py::arg("samples_between") = 10,
      py::arg("max_iterations") = 20, py::arg("grid_intervals") = 100, py::arg("joint_acceleration") = py::none(),
      py::arg("torque_limits") = true, py::arg("corner_tolerance") = 0.0, py::kw_only(),
      py::arg("redundancy_rule") = py::none(),
      "Re-time `path` so that the robot keeps its joint limits. `corner_tolerance` (m): the path's corners blended "
      "first, as plan(..., corner_tolerance=) does (0: the path as given). `redundancy_rule` (a RedundancyRule; "
      "None: RedundancyRule.held()): a seven-joint arm's parameter along the path, for either method as "
      "check_joint_limits(..., redundancy_rule=) takes it: RedundancyRule() moves it away from joint limits and "
      "singular poses (doc/inverse-kinematics.md §14), the held rule keeps it at q_start's value.\n\n"
      "method=\"scaling\" (the KUKA re-timing patent's loop): plan, check_joint_limits, divide the velocity limit by "
      "FVEL and the acceleration limit by FACC, re-plan until both are <= 1 at every checked sample; returns a "
      "RetimeResult.\n"
      "method=\"optimal\": the fastest parameterisation under the DISP limits and the joint velocity limits, "
      "`joint_acceleration` ((dof,) array, optional) and the effort limits (if `torque_limits`) at once, over "
      "`grid_intervals` intervals of s, checked at `samples_between` points between characteristic points and "
      "re-solved with tightened limits up to `max_iterations` times if that check finds an overshoot; returns an "
      "OptimalRetimeResult, whose report is that check. With a moving redundancy_rule its grid solves the joints "
      "at the parameter's values along the planned path, their rates included (doc/inverse-kinematics.md eq. 51). "
      "With profile=\"trapezoid\" (limits without jerk) its laws are piecewise-constant "
      "acceleration; with profile=\"scurve\" (limits with jerk) each rest-to-rest run is then averaged over a "
      "window (jerk_window) so that |s'''| <= jerk within every section, the speed caps tightened beforehand so "
      "that the DISP limits still hold.\n"
      "RuntimeError if a position limit is violated, a static torque exceeds its limit, or it does not converge.");
}

// retime(path, ..., robot=Hexapod): its legs as joints.
void bind_retime_hexapod(py::module_& m) {
  m.def(
      "retime",
      [](const Path& path, const MetricSetd& set, const Limits& limits, const Hexapod& hexapod,
         const std::string& profile, const std::string& method, int samples_between, int max_iterations,
         int grid_intervals, const std::optional<Eigen::VectorXd>& joint_acceleration, double corner_tolerance) {
        if (method != "optimal") {
          throw std::invalid_argument(describe("method", method,
                                               "must be \"optimal\" for a Hexapod (its leg speeds enter "
                                               "plan() through Hexapod.joint_metric; no scaling loop)"));
        }
        limits.validate(profile_kind(profile));
        OptimalRetimeOptions options;
        options.grid_intervals = grid_intervals;
        if (joint_acceleration) options.joint_acceleration = *joint_acceleration;
        options.check_samples_between = samples_between;
        options.max_refinements = max_iterations;
        options.corner_tolerance = corner_tolerance;
        const UnlockedIf unlocked(true, path, set);
        return retime_optimal(path, set, limits, hexapod, options);
      },
      py::arg("path"), py::arg("metric_set"), py::arg("limits"), py::arg("robot"), py::kw_only(),
      py::arg("profile") = "trapezoid", py::arg("method") = "optimal", py::arg("samples_between") = 3,
      py::arg("max_iterations") = 6, py::arg("grid_intervals") = 100, py::arg("joint_acceleration") = py::none(),
      py::arg("corner_tolerance") = 0.0,
      "The optimal re-timing for a Hexapod: the fastest timing that keeps the DISP limits, every leg within its "
      "speed (leg_speed) and, if given, `joint_acceleration` ((6,) leg accelerations, m/s^2); returns an "
      "OptimalRetimeResult. profile=\"scurve\" (limits with jerk) limits the jerk as for an arm. `corner_tolerance` "
      "(m): the path's corners blended first, as plan(..., corner_tolerance=) does (0: the path as given). "
      "RuntimeError if a leg leaves its length range on the way.");
}

}  // namespace

void bind_retiming(py::module_& m) {
  bind_redundancy_rule(m);
  bind_joint_limit_report(m);
  bind_check_joint_limits(m);
  bind_retime_result(m);
  bind_optimal_retime_result(m);
  bind_retime_serial_arm(m);
  bind_retime_hexapod(m);
}

}  // namespace python
}  // namespace dispkin
