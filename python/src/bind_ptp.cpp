// Python binding of dispkin/serial/ptp.hpp: JointTrajectory and plan(JointPath, ..., robot=SerialArm).
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <pybind11/eigen.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "bindings.hpp"
#include "conversions.hpp"
#include "interpreter_lock.hpp"
#include "dispkin/error.hpp"
#include "dispkin/serial/followed_trajectory.hpp"
#include "dispkin/serial/joint_overlap.hpp"
#include "dispkin/serial/mixed_overlap.hpp"
#include "dispkin/serial/ptp.hpp"

namespace dispkin {
namespace python {

namespace {

using serial::FollowedTrajectory;
using serial::JointSection;
using serial::JointTrajectory;
using serial::JointTrajectorySample;
using serial::OverlappedJointTrajectory;
using serial::OverlappedMixedTrajectory;
using serial::PtpOptions;


// Samples at `times` (a number or (N,)), `columns` numbers per sample, shaped (N, *tail); for a
// number one sample shaped `tail` (a float when that is empty), as numpy does for a scalar. An
// array of many times is sampled with the interpreter lock released (`write` is C++ only).
template <typename Traj, typename Write>
py::object sampled(const Traj& traj, const py::object& times, std::vector<py::ssize_t> tail, py::ssize_t columns,
                   Write write) {
  const Array a = as_array(times, "times", "a number or an array of shape (N,)");
  if (a.ndim() > 1) wrong_shape("times", "a number or an array of shape (N,)", a);
  std::vector<double> t(a.data(), a.data() + a.size());
  for (double x : t) require_finite(x, "times");
  std::vector<py::ssize_t> shape;
  if (a.ndim() == 1) shape.push_back(static_cast<py::ssize_t>(t.size()));
  shape.insert(shape.end(), tail.begin(), tail.end());
  py::array_t<double> out(shape);
  double* data = out.mutable_data();
  {
    const UnlockedIf unlocked(worth_releasing(t.size(), trajectory_sample_ns));
    for (std::size_t i = 0; i < t.size(); ++i) write(traj.sample(t[i]), data + static_cast<py::ssize_t>(i) * columns);
  }
  if (shape.empty()) return py::float_(*data);
  return std::move(out);
}

// The sampling methods of a joint motion (JointTrajectorySample per time): tool poses, body
// twists, joint positions, velocities, accelerations.
template <typename Traj>
void def_joint_sampling(py::class_<Traj>& cls) {
  cls.def(
         "sample",
         [](const Traj& t, const py::object& times) {
           return sampled(t, times, {4, 4}, 16, [](const JointTrajectorySample& s, double* out) {
             Eigen::Map<Eigen::Matrix<double, 4, 4, Eigen::RowMajor>>{out} = s.pose.matrix();
           });
         },
         py::arg("times"), "Tool poses at `times` (the arm's forward kinematics of the joints) as (N, 4, 4) matrices.")
      .def(
          "body_twist",
          [](const Traj& t, const py::object& times) {
            return sampled(t, times, {6}, 6, [](const JointTrajectorySample& s, double* out) {
              Eigen::Map<Eigen::Matrix<double, 6, 1>>{out} = s.body_twist.vector();
            });
          },
          py::arg("times"), "Body twists (v, omega) of the tool at `times`, (N, 6), m/s and rad/s.")
      .def(
          "joint_positions",
          [](const Traj& t, const py::object& times) {
            const int n = static_cast<int>(t.sample(0.0).q.size());
            return sampled(t, times, {n}, n, [n](const JointTrajectorySample& s, double* out) {
              Eigen::Map<Eigen::VectorXd>{out, n} = s.q;
            });
          },
          py::arg("times"), "Joint positions at `times`, (N, dof), rad.")
      .def(
          "joint_velocities",
          [](const Traj& t, const py::object& times) {
            const int n = static_cast<int>(t.sample(0.0).q.size());
            return sampled(t, times, {n}, n, [n](const JointTrajectorySample& s, double* out) {
              Eigen::Map<Eigen::VectorXd>{out, n} = s.qd;
            });
          },
          py::arg("times"), "Joint velocities at `times`, (N, dof), rad/s.")
      .def(
          "joint_accelerations",
          [](const Traj& t, const py::object& times) {
            const int n = static_cast<int>(t.sample(0.0).q.size());
            return sampled(t, times, {n}, n, [n](const JointTrajectorySample& s, double* out) {
              Eigen::Map<Eigen::VectorXd>{out, n} = s.qdd;
            });
          },
          py::arg("times"), "Joint accelerations at `times`, (N, dof), rad/s^2.");
}

// FollowedTrajectory::from_start or ::to_end with the redundancy rule optional (None: held).
template <FollowedTrajectory (*make)(Trajectory, const serial::SerialArm&, const Eigen::VectorXd&, double,
                                     const serial::RedundancyRule&)>
FollowedTrajectory followed_from(Trajectory trajectory, const serial::SerialArm& arm, const Eigen::VectorXd& q,
                                 double spacing, const std::optional<serial::RedundancyRule>& redundancy_rule) {
  return make(std::move(trajectory), arm, q, spacing, redundancy_rule.value_or(serial::RedundancyRule::held()));
}

// What a PTP move was planned as: its ends, joint sections and velocity-limit curve.
void def_joint_trajectory_plan(py::class_<JointTrajectory>& cls) {
  cls.def_property_readonly("duration", &JointTrajectory::duration, "Seconds.")
      .def_property_readonly("length", &JointTrajectory::length,
                             "The DISP arc length (sum of the section bounds), metres.")
      .def_property_readonly("dof", &JointTrajectory::dof, "Number of joints.")
      .def_property_readonly("start", &JointTrajectory::start, "q_a (rad).")
      .def_property_readonly("end", &JointTrajectory::end, "q_b (rad).")
      .def_property_readonly("law_count", &JointTrajectory::law_count,
                             "Time laws: one per segment of the velocity-limit curve.")
      .def_property_readonly(
          "law_acceleration", &JointTrajectory::law_acceleration,
          "The acceleration limit of the time law (m/s^2): the DISP one, lowered by joint acceleration limits.")
      .def(
          "sections",
          [](const JointTrajectory& t) {
            Eigen::MatrixXd out(static_cast<Eigen::Index>(t.sections().size()), 5);
            for (std::size_t k = 0; k < t.sections().size(); ++k) {
              const JointSection& s = t.sections()[k];
              out.row(static_cast<Eigen::Index>(k)) << s.u0, s.u1, s.length, s.acceleration, s.middle_speed;
            }
            return out;
          },
          "The joint sections as (K, 5) rows (u0, u1, length, acceleration bound, speed at the middle): the "
          "section bound L (m per unit of the section parameter) is never below the fastest weighted speed of the "
          "set over the section.")
      .def(
          "speed_limits",
          [](const JointTrajectory& t) {
            Eigen::MatrixXd out(static_cast<Eigen::Index>(t.speed_limits().size()), 3);
            for (std::size_t k = 0; k < t.speed_limits().size(); ++k) {
              const SpeedLimit& span = t.speed_limits()[k];
              out.row(static_cast<Eigen::Index>(k)) << span.start_s, span.length, span.limit;
            }
            return out;
          },
          "The velocity-limit curve as (K, 3) rows (start s, length, limit): the system velocity, lowered where a "
          "joint velocity limit or the curvature rule binds.");
}

// A PTP move sampled at given times: tool poses and twists, joints, the path parameter.
void def_joint_trajectory_samples(py::class_<JointTrajectory>& cls) {
  cls.def(
         "sample",
         [](const JointTrajectory& t, const py::object& times) {
           return sampled(t, times, {4, 4}, 16, [](const JointTrajectorySample& s, double* out) {
             Eigen::Map<Eigen::Matrix<double, 4, 4, Eigen::RowMajor>>{out} = s.pose.matrix();
           });
         },
         py::arg("times"), "Tool poses at `times` as (N, 4, 4) homogeneous matrices.")
      .def(
          "sample_xyzuvw",
          [](const JointTrajectory& t, const py::object& times) {
            return sampled(t, times, {6}, 6, [](const JointTrajectorySample& s, double* out) {
              Eigen::Map<Eigen::Matrix<double, 6, 1>>{out} = s.pose.to_xyzuvw();
            });
          },
          py::arg("times"), "Tool poses at `times` as (N, 6) XYZUVW (metres, radians).")
      .def(
          "body_twist",
          [](const JointTrajectory& t, const py::object& times) {
            return sampled(t, times, {6}, 6, [](const JointTrajectorySample& s, double* out) {
              Eigen::Map<Eigen::Matrix<double, 6, 1>>{out} = s.body_twist.vector();
            });
          },
          py::arg("times"), "Body twists (v, omega) of the tool at `times`, (N, 6), m/s and rad/s.")
      .def(
          "joint_positions",
          [](const JointTrajectory& t, const py::object& times) {
            const int n = t.dof();
            return sampled(t, times, {n}, n, [n](const JointTrajectorySample& s, double* out) {
              Eigen::Map<Eigen::VectorXd>{out, n} = s.q;
            });
          },
          py::arg("times"), "q at `times`, (N, dof), rad.")
      .def(
          "joint_velocities",
          [](const JointTrajectory& t, const py::object& times) {
            const int n = t.dof();
            return sampled(t, times, {n}, n, [n](const JointTrajectorySample& s, double* out) {
              Eigen::Map<Eigen::VectorXd>{out, n} = s.qd;
            });
          },
          py::arg("times"), "q-dot at `times`, (N, dof), rad/s.")
      .def(
          "joint_accelerations",
          [](const JointTrajectory& t, const py::object& times) {
            const int n = t.dof();
            return sampled(t, times, {n}, n, [n](const JointTrajectorySample& s, double* out) {
              Eigen::Map<Eigen::VectorXd>{out, n} = s.qdd;
            });
          },
          py::arg("times"), "q-double-dot at `times`, (N, dof), rad/s^2.")
      .def(
          "parameter",
          [](const JointTrajectory& t, const py::object& times) {
            return sampled(t, times, {}, 1, [](const JointTrajectorySample& s, double* out) { *out = s.u; });
          },
          py::arg("times"), "u at `times`, (N,): q = q_a + u (q_b - q_a).")
      .def(
          "path_position",
          [](const JointTrajectory& t, const py::object& times) {
            return sampled(t, times, {}, 1, [](const JointTrajectorySample& s, double* out) { *out = s.s; });
          },
          py::arg("times"), "s at `times`, (N,), metres of DISP arc length.")
      .def(
          "path_velocity",
          [](const JointTrajectory& t, const py::object& times) {
            return sampled(t, times, {}, 1, [](const JointTrajectorySample& s, double* out) { *out = s.s_dot; });
          },
          py::arg("times"), "s-dot at `times`, (N,), m/s: the speed bound of every point of the set.");
}

void bind_joint_trajectory(py::module_& m) {
  // dynamic_attr: a JointTrajectory keeps the arguments of the plan() that made it, from which
  // pickling makes it again (planning is deterministic: the same samples, bit for bit).
  py::class_<JointTrajectory> cls(m, "JointTrajectory", py::dynamic_attr(), R"doc(
A planned PTP move of a serial arm: every joint on the line from q_a to q_b, all arriving
together, timed so that no point or sphere of the metric set moves faster than its limit at any
time and no joint faster than its velocity limit. Sample it at any times (seconds, clamped to
[0, duration]); the ends are exactly q_a and q_b, at rest.)doc");
  def_joint_trajectory_plan(cls);
  def_joint_trajectory_samples(cls);
  cls.def(
         "__reduce__",
         [](const py::object& self) -> py::tuple {
           if (!py::hasattr(self, "_plan_arguments")) {
             throw py::type_error("cannot pickle a JointTrajectory that dispkin.plan did not make");
           }
           const py::tuple a = self.attr("_plan_arguments");
           py::dict keywords;
           keywords["robot"] = a[4];
           keywords["joint_acceleration"] = a[5];
           keywords["tolerance"] = a[6];
           const py::object replan =
               py::module_::import("functools")
                   .attr("partial")(py::module_::import("dispkin._core").attr("plan"), **keywords);
           return py::make_tuple(replan, py::make_tuple(a[0], a[1], a[2], a[3]));
         },
         "Pickling: plan() again with the arguments that made this trajectory.")
      .def("__repr__", [](const JointTrajectory& t) {
        return "JointTrajectory(duration=" + float_repr(t.duration()) + ", joints=" + std::to_string(t.dof()) +
               ", sections=" + std::to_string(t.sections().size()) + ")";
      });
}

void bind_overlapped_joint_trajectory(py::module_& m) {
  py::class_<OverlappedJointTrajectory>(m, "OverlappedJointTrajectory", R"doc(
The Mamezou article's overlapped velocity method for PTP moves: `after` starts `overlap` seconds
before `before` ends, and meanwhile the joint displacements add,
theta(t) = theta_b(t) + theta_f(t') - theta_2 (t' the next move's own time, theta_2 the via
joints), so the joint velocities and accelerations add too; the tool pose is the arm's forward
kinematics. No speed guarantee of its own: check the peak point speed before using large
overlaps.)doc")
      .def(py::init([](const JointTrajectory& before, const JointTrajectory& after, double overlap) {
             return OverlappedJointTrajectory(before, after, overlap);
           }),
           py::arg("before"), py::arg("after"), py::arg("overlap"),
           "`before` must end where `after` starts (to 1e-9 rad), on the same arm; 0 <= overlap <= the shorter "
           "duration (seconds).")
      .def_property_readonly("duration", &OverlappedJointTrajectory::duration, "Seconds.")
      .def_property_readonly("overlap", &OverlappedJointTrajectory::overlap, "Seconds during which both moves run.")
      .def_property_readonly("overlap_start", &OverlappedJointTrajectory::overlap_start,
                             "When the second move starts, seconds.")
      .def(
          "sample",
          [](const OverlappedJointTrajectory& t, const py::object& times) {
            return sampled(t, times, {4, 4}, 16, [](const JointTrajectorySample& s, double* out) {
              Eigen::Map<Eigen::Matrix<double, 4, 4, Eigen::RowMajor>>{out} = s.pose.matrix();
            });
          },
          py::arg("times"), "Tool poses at `times` as (N, 4, 4) homogeneous matrices.")
      .def(
          "body_twist",
          [](const OverlappedJointTrajectory& t, const py::object& times) {
            return sampled(t, times, {6}, 6, [](const JointTrajectorySample& s, double* out) {
              Eigen::Map<Eigen::Matrix<double, 6, 1>>{out} = s.body_twist.vector();
            });
          },
          py::arg("times"), "Body twists (v, omega) of the tool at `times`, (N, 6), m/s and rad/s.")
      .def(
          "joint_positions",
          [](const OverlappedJointTrajectory& t, const py::object& times) {
            const int n = t.before().dof();
            return sampled(t, times, {n}, n, [n](const JointTrajectorySample& s, double* out) {
              Eigen::Map<Eigen::VectorXd>{out, n} = s.q;
            });
          },
          py::arg("times"), "theta at `times`, (N, dof), rad.")
      .def(
          "joint_velocities",
          [](const OverlappedJointTrajectory& t, const py::object& times) {
            const int n = t.before().dof();
            return sampled(t, times, {n}, n, [n](const JointTrajectorySample& s, double* out) {
              Eigen::Map<Eigen::VectorXd>{out, n} = s.qd;
            });
          },
          py::arg("times"), "theta-dot at `times`, (N, dof), rad/s: the sum of both moves' during the overlap.")
      .def(
          "joint_accelerations",
          [](const OverlappedJointTrajectory& t, const py::object& times) {
            const int n = t.before().dof();
            return sampled(t, times, {n}, n, [n](const JointTrajectorySample& s, double* out) {
              Eigen::Map<Eigen::VectorXd>{out, n} = s.qdd;
            });
          },
          py::arg("times"), "theta-double-dot at `times`, (N, dof), rad/s^2.")
      .def("__repr__", [](const OverlappedJointTrajectory& o) {
        return "OverlappedJointTrajectory(duration=" + float_repr(o.duration()) +
               ", overlap=" + float_repr(o.overlap()) + ")";
      });
}

void bind_followed_trajectory(py::module_& m) {
  py::class_<FollowedTrajectory> followed(m, "FollowedTrajectory", R"doc(
A Cartesian trajectory (a LIN, CIRC, ... plan) as the joint motion of a serial arm whose tip
follows it on one inverse-kinematics branch: the Mamezou article's "unifying to one type of
control trajectory" done in joint space, where a PTP move is native. The joints are computed at
construction on nodes along the path (DISP arc length at most `spacing` apart, refined until
every interval's middle agrees with the branch's IK solution to 1e-10 rad) and interpolated by
cubic Hermite polynomials; the trajectory's own time law gives s(t). The sampled pose is the
arm's forward kinematics of the joints.)doc");
  followed
      .def_static("from_start", &followed_from<&FollowedTrajectory::from_start>, py::arg("trajectory"),
                  py::arg("robot"), py::arg("q_start"), py::arg("spacing") = FollowedTrajectory::default_spacing,
                  py::kw_only(), py::arg("redundancy_rule") = py::none(),
                  "The branch that starts at q_start (whose forward kinematics must be the trajectory's start "
                  "pose to 1e-9). ValueError naming the argument for a wrong q_start or spacing, an arm that is "
                  "neither 6R nor 7R with a redundancy parameter (kept at q_start's value), or a trajectory the arm "
                  "cannot follow (out of reach, singular, a joint limit). A seven-joint arm's parameter moves by "
                  "`redundancy_rule` (a RedundancyRule; doc/inverse-kinematics.md eqs. 47-50), else it is held.")
      .def_static("to_end", &followed_from<&FollowedTrajectory::to_end>, py::arg("trajectory"), py::arg("robot"),
                  py::arg("q_end"), py::arg("spacing") = FollowedTrajectory::default_spacing, py::kw_only(),
                  py::arg("redundancy_rule") = py::none(),
                  "The branch that ends at q_end (followed backwards from the trajectory's end pose, which "
                  "forward kinematics of q_end must be): for a Cartesian move a PTP move from q_end follows.")
      .def_property_readonly("duration", &FollowedTrajectory::duration, "Seconds.")
      .def_property_readonly("length", &FollowedTrajectory::length,
                             "The Cartesian trajectory's DISP arc length, metres.")
      .def_property_readonly("dof", &FollowedTrajectory::dof, "Number of joints.")
      .def_property_readonly("start", &FollowedTrajectory::start, "The joints at t = 0 (rad).")
      .def_property_readonly("end", &FollowedTrajectory::end, "The joints at the end (rad).")
      .def_property_readonly("trajectory", &FollowedTrajectory::trajectory, "The Cartesian trajectory followed.")
      .def_property_readonly("node_count", &FollowedTrajectory::node_count, "Number of grid nodes.")
      .def_property_readonly("midpoint_error", &FollowedTrajectory::midpoint_error,
                             "The largest joint error found at an interval's middle (rad, at most 1e-10).");
  def_joint_sampling(followed);
  followed.def("__repr__", [](const FollowedTrajectory& f) {
    return "FollowedTrajectory(duration=" + float_repr(f.duration()) + ", nodes=" + std::to_string(f.node_count()) +
           ")";
  });
}

void bind_overlapped_mixed_trajectory(py::module_& m) {
  py::class_<OverlappedMixedTrajectory> mixed(m, "OverlappedMixedTrajectory", R"doc(
The Mamezou article's overlapped velocity method for a PTP move and a Cartesian move, in either
order, after unifying both to joint space: the Cartesian move as a FollowedTrajectory (from the
PTP move's end, or to its start), then, as for two PTP moves, `after` starts `overlap` seconds
before `before` ends and meanwhile the joint displacements add,
theta(t) = theta_b(t) + theta_f(t') - theta_2. Outside the overlap each move runs alone; the tool
pose is the arm's forward kinematics. No speed guarantee of its own: check the peak point speed
before using large overlaps.)doc");
  mixed
      .def(py::init([](const JointTrajectory& before, const FollowedTrajectory& after, double overlap) {
             return OverlappedMixedTrajectory(before, after, overlap);
           }),
           py::arg("before"), py::arg("after"), py::arg("overlap"),
           "A PTP move, then a Cartesian move followed from its end (FollowedTrajectory.from_start with "
           "before.end); 0 <= overlap <= the shorter duration (seconds).")
      .def(py::init([](const FollowedTrajectory& before, const JointTrajectory& after, double overlap) {
             return OverlappedMixedTrajectory(before, after, overlap);
           }),
           py::arg("before"), py::arg("after"), py::arg("overlap"),
           "A Cartesian move followed to the start of the PTP move after it (FollowedTrajectory.to_end with "
           "after.start); 0 <= overlap <= the shorter duration (seconds).")
      .def_property_readonly("duration", &OverlappedMixedTrajectory::duration, "Seconds.")
      .def_property_readonly("overlap", &OverlappedMixedTrajectory::overlap, "Seconds during which both moves run.")
      .def_property_readonly("overlap_start", &OverlappedMixedTrajectory::overlap_start,
                             "When the second move starts, seconds.")
      .def_property_readonly("ptp_first", &OverlappedMixedTrajectory::ptp_first,
                             "True for a PTP move then a Cartesian one, False for the reverse.");
  def_joint_sampling(mixed);
  mixed.def("__repr__", [](const OverlappedMixedTrajectory& o) {
    return "OverlappedMixedTrajectory(duration=" + float_repr(o.duration()) + ", overlap=" + float_repr(o.overlap()) +
           ", ptp_first=" + (o.ptp_first() ? "True" : "False") + ")";
  });

  m.def(
      "plan",
      [](const JointPath& path, const MetricSetd& set, const Limits& limits, const std::string& profile,
         const py::object& robot, const std::optional<Eigen::VectorXd>& joint_acceleration, double tolerance) {
        const ProfileKind kind = profile_kind(profile);
        if (robot.is_none() || !py::isinstance<serial::SerialArm>(robot)) {
          throw std::invalid_argument(describe("robot", std::string(py::repr(robot)),
                                               "must be a SerialArm: a PTP move (JointPath) is planned on an arm"));
        }
        PtpOptions options;
        if (joint_acceleration) options.joint_acceleration = *joint_acceleration;
        options.tolerance = tolerance;
        const serial::SerialArm& arm = robot.cast<const serial::SerialArm&>();
        std::optional<JointTrajectory> planned;
        {
          const UnlockedIf unlocked(true, set);
          planned = plan(path, set, limits, kind, arm, options);
        }
        py::object trajectory = py::cast(std::move(*planned));
        trajectory.attr("_plan_arguments") =
            py::make_tuple(path, set, limits, profile, robot, joint_acceleration, tolerance);
        return trajectory;
      },
      py::arg("path"), py::arg("metric_set"), py::arg("limits"), py::arg("profile") = "scurve", py::kw_only(),
      py::arg("robot") = py::none(), py::arg("joint_acceleration") = py::none(), py::arg("tolerance") = 1e-2,
      "Plan the PTP move `path` (Path.ptp(q_a, q_b)) on `robot` (a SerialArm, required) under the metric set and "
      "limits: the tool's points and spheres never faster than their limits, the joints never faster than the "
      "arm's velocity limits (and `joint_acceleration`, rad/s^2 per joint, if given), all joints arriving together. "
      "`tolerance`: the section bounds' slack over the sampled speed. Returns a JointTrajectory.");
}

}  // namespace

void bind_ptp(py::module_& m) {
  bind_joint_trajectory(m);
  bind_overlapped_joint_trajectory(m);
  bind_followed_trajectory(m);
  bind_overlapped_mixed_trajectory(m);
}

}  // namespace python
}  // namespace dispkin
