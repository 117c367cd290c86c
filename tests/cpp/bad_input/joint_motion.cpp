// The rows of the C++ bad-input table (tests/cpp/test_bad_input_table.cpp) of one area: joint motion of a UR5e:
// check_joint_limits, retime_by_scaling, retime_optimal, PTP moves.
#if defined(DISPKIN_HAS_SERIAL)
#include "rows.hpp"

namespace bad_input {

void joint_motion_rows(std::vector<Row>& table) {
  const RowAdder row{table};
  // --- check_joint_limits / retime_by_scaling ---
  const auto ur5e = [] { return SerialArm::from_urdf_file(urdf + "arm_ur5e_dh.urdf", "base_link", "tool0"); };
  const auto q_ur = [] { return (Eigen::VectorXd(6) << 0.3, -1.2, 1.5, -1.9, -1.57, 0.2).finished(); };
  const auto ur_path = [ur5e, q_ur] {
    const Posed a = ur5e().forward(q_ur());
    return Path::lin(a, Posed(a.quaternion(), a.translation() + Vector3d(0.05, 0, 0)));
  };
  row(
      "check_joint_limits", "negative samples_between",
      [=] {
        JointCheckOptions o;
        o.samples_between = -1;
        check_joint_limits(plan(ur_path(), good_set(), limits(0.1, 1, 10)), ur5e(), q_ur(), o);
      },
      IA, "samples_between = -1");
  row(
      "check_joint_limits", "zero difference_step",
      [=] {
        JointCheckOptions o;
        o.difference_step = 0.0;
        check_joint_limits(plan(ur_path(), good_set(), limits(0.1, 1, 10)), ur5e(), q_ur(), o);
      },
      IA, "difference_step = 0");
  row(
      "check_joint_limits", "q_start of the wrong size",
      [=] { check_joint_limits(plan(ur_path(), good_set(), limits(0.1, 1, 10)), ur5e(), Eigen::VectorXd::Zero(5)); },
      IA, "q_start size = 5");
  row(
      "check_joint_limits", "NaN q_start",
      [=] {
        check_joint_limits(plan(ur_path(), good_set(), limits(0.1, 1, 10)), ur5e(), Eigen::VectorXd::Constant(6, nan_));
      },
      IA, "q_start = (nan");
  row(
      "retime_by_scaling", "zero max_iterations",
      [=] { retime_by_scaling(ur_path(), good_set(), limits(0.1, 1, 10), ProfileKind::scurve, ur5e(), q_ur(), {}, 0); },
      IA, "max_iterations = 0");
  // --- retime_optimal ---
  const auto optimal = [=](const OptimalRetimeOptions& o) {
    retime_optimal(ur_path(), good_set(), limits(0.1, 1, std::nullopt), ur5e(), q_ur(), o);
  };
  row(
      "retime_optimal", "NaN jerk",
      [=] { retime_optimal(ur_path(), good_set(), limits(0.1, 1, nan_), ur5e(), q_ur()); }, IA, "jerk = nan");
  row(
      "retime_optimal", "zero jerk",
      [=] { retime_optimal(ur_path(), good_set(), limits(0.1, 1, 0.0), ur5e(), q_ur()); }, IA, "jerk = 0");
  row(
      "retime_optimal", "one grid interval",
      [=] {
        OptimalRetimeOptions o;
        o.grid_intervals = 1;
        optimal(o);
      },
      IA, "grid_intervals = 1");
  row(
      "retime_optimal", "NaN difference_step",
      [=] {
        OptimalRetimeOptions o;
        o.difference_step = nan_;
        optimal(o);
      },
      IA, "difference_step = nan");
  row(
      "retime_optimal", "negative check_samples_between",
      [=] {
        OptimalRetimeOptions o;
        o.check_samples_between = -1;
        optimal(o);
      },
      IA, "check_samples_between = -1");
  row(
      "retime_optimal", "negative max_refinements",
      [=] {
        OptimalRetimeOptions o;
        o.max_refinements = -1;
        optimal(o);
      },
      IA, "max_refinements = -1");
  row(
      "retime_optimal", "joint_acceleration of the wrong size",
      [=] {
        OptimalRetimeOptions o;
        o.joint_acceleration = Eigen::VectorXd::Ones(2);
        optimal(o);
      },
      IA, "joint_acceleration size = 2");
  row(
      "retime_optimal", "zero joint acceleration",
      [=] {
        OptimalRetimeOptions o;
        o.joint_acceleration = Eigen::VectorXd::Ones(6);
        o.joint_acceleration(4) = 0;
        optimal(o);
      },
      IA, "joint_acceleration[4] = 0");
  row(
      "retime_optimal", "hexapod, leg accelerations of the wrong size",
      [=] {
        OptimalRetimeOptions o;
        o.joint_acceleration = Eigen::VectorXd::Ones(3);
        const Hexapod h = hexapod();
        retime_optimal(Path::lin(h.home(), h.home() * Posed(Quaterniond::Identity(), Vector3d(0.01, 0, 0))), good_set(),
                       limits(0.1, 1, std::nullopt), h, o);
      },
      IA, "joint_acceleration size = 3");
  row(
      "check_joint_limits", "hexapod, zero difference_step",
      [=] {
        JointCheckOptions o;
        o.difference_step = 0.0;
        const Hexapod h = hexapod();
        check_joint_limits(plan(Path::lin(h.home(), h.home() * Posed(Quaterniond::Identity(), Vector3d(0.01, 0, 0))),
                                good_set(), limits(0.1, 1, 10)),
                           h, o);
      },
      IA, "difference_step = 0");
  row(
      "SerialArm::with_joint_limits", "effort of the wrong size",
      [=] {
        JointLimits l = ur5e().joint_limits();
        l.effort = Eigen::VectorXd::Ones(2);
        ur5e().with_joint_limits(l);
      },
      IA, "effort size = 2");
  row(
      "SerialArm::with_joint_limits", "negative velocity",
      [=] {
        JointLimits l = ur5e().joint_limits();
        l.velocity(1) = -1;
        ur5e().with_joint_limits(l);
      },
      IA, "joint \"shoulder_lift_joint\" velocity = -1");
  // --- plan(JointPath, ..., SerialArm): PTP moves (ptp.hpp) ---
  const auto q6 = [](double x) { return Eigen::VectorXd::Constant(6, x); };
  const auto ptp = [=](const JointPath& move, const MetricSetd& set, const Limits& l, const PtpOptions& o) {
    plan(move, set, l, l.jerk ? ProfileKind::scurve : ProfileKind::trapezoid, ur5e(), o);
  };
  row(
      "JointPath", "q_end of another size", [=] { JointPath(q6(0), Eigen::VectorXd::Zero(5)); }, IA,
      "q_end size = 5: must equal q_start size 6");
  row(
      "JointPath", "NaN q_end",
      [=] {
        Eigen::VectorXd q = q6(0);
        q(2) = nan_;
        JointPath(q6(0), q);
      },
      IA, "q_end = (0, 0, nan, 0, 0, 0): must be finite");
  row(
      "plan (PTP)", "q_a of the wrong size for the arm",
      [=] { ptp(JointPath(Eigen::VectorXd::Zero(5), Eigen::VectorXd::Ones(5)), good_set(), limits(0.1, 1, 10), {}); },
      IA, "q_a size = 5: must be the arm's dof 6");
  row(
      "plan (PTP)", "q_b outside the joint range",
      [=] {
        Eigen::VectorXd q = q6(0.1);
        q(1) = 7.0;
        ptp(JointPath(q6(0), q), good_set(), limits(0.1, 1, 10), {});
      },
      IA, "q_b[1] = 7: is outside the position limits [lower, upper] of joint \"shoulder_lift_joint\"");
  row(
      "plan (PTP)", "q_b equal to q_a", [=] { ptp(JointPath(q6(0.1), q6(0.1)), good_set(), limits(0.1, 1, 10), {}); },
      IA, "equals q_a: a PTP move must move");
  row(
      "plan (PTP)", "zero velocity", [=] { ptp(JointPath(q6(0), q6(0.1)), good_set(), limits(0.0, 1, 10), {}); }, IA,
      "velocity = 0");
  row(
      "plan (PTP)", "collinear set", [=] { ptp(JointPath(q6(0), q6(0.1)), collinear_set(), limits(0.1, 1, 10), {}); },
      IA, "metric_set = \"MetricSet\": is not well-formed");
  row(
      "plan (PTP)", "zero tolerance",
      [=] {
        PtpOptions o;
        o.tolerance = 0.0;
        ptp(JointPath(q6(0), q6(0.1)), good_set(), limits(0.1, 1, 10), o);
      },
      IA, "tolerance = 0: must be in (0, 0.5]");
  row(
      "plan (PTP)", "joint_acceleration of the wrong size",
      [=] {
        PtpOptions o;
        o.joint_acceleration = Eigen::VectorXd::Ones(3);
        ptp(JointPath(q6(0), q6(0.1)), good_set(), limits(0.1, 1, 10), o);
      },
      IA, "joint_acceleration size = 3");
  row(
      "plan (PTP)", "NaN joint acceleration",
      [=] {
        PtpOptions o;
        o.joint_acceleration = q6(1.0);
        o.joint_acceleration(4) = nan_;
        ptp(JointPath(q6(0), q6(0.1)), good_set(), limits(0.1, 1, 10), o);
      },
      IA, "joint_acceleration[4] = nan: must be > 0");
  row(
      "retime_optimal", "q_start of the wrong size",
      [=] { retime_optimal(ur_path(), good_set(), limits(0.1, 1, std::nullopt), ur5e(), Eigen::VectorXd::Zero(5)); },
      IA, "q_start size = 5");
}

}  // namespace bad_input
#endif
