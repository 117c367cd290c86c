// Python binding of a SerialArm's joints along poses and trajectories (dispkin/serial/serial_arm.hpp,
// serial_retiming.hpp): the methods follow, joint_velocities, follow_trajectory and
// check_joint_limits. Sampled joints are the rows of (N, n) arrays.
#include <string>
#include <vector>

#include <pybind11/eigen.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "serial_arm_binding.hpp"
#include "dispkin/serial/ptp.hpp"
#include "dispkin/serial/serial_retiming.hpp"

namespace dispkin {
namespace python {

using serial::FollowedJoints;
using serial::JointTrajectory;
using serial::SerialArm;

void def_following(py::class_<SerialArm>& cls) {
  cls.def(
         "follow",
         [](const SerialArm& a, const std::vector<Posed>& poses, const py::object& q_start, bool move_redundancy,
            double gain, double max_rate, double singularity_weight) {
           const Eigen::VectorXd start = joint_vector(q_start, "q_start");
           serial::RedundancyRule rule;
           rule.move = move_redundancy;
           rule.gain = gain;
           rule.max_rate = max_rate;
           rule.singularity_weight = singularity_weight;
           std::vector<Eigen::VectorXd> path;
           {
             py::gil_scoped_release unlocked;
             path = serial::follow(a, poses, start, {}, rule);
           }
           py::array_t<double> out({static_cast<py::ssize_t>(path.size()), static_cast<py::ssize_t>(a.dof())});
           for (std::size_t k = 0; k < path.size(); ++k)
             Eigen::Map<Eigen::VectorXd>(out.mutable_data() + k * static_cast<std::size_t>(a.dof()), a.dof()) = path[k];
           return out;
         },
         py::arg("poses"), py::arg("q_start"), py::kw_only(),
         py::arg("move_redundancy") = serial::RedundancyRule{}.move, py::arg("gain") = serial::RedundancyRule{}.gain,
         py::arg("max_rate") = serial::RedundancyRule{}.max_rate,
         py::arg("singularity_weight") = serial::RedundancyRule{}.singularity_weight,
         "(N, n) joint path: for each pose the solution nearest to the previous one, from q_start. "
         "RuntimeError naming the first pose without a solution. A seven-joint arm with a redundancy parameter "
         "starts at q_start's value and, with move_redundancy, moves it away from joint limits and singular poses "
         "by at most max_rate rad per radian the other joints travel (doc/inverse-kinematics.md eq. 45); no joint "
         "steps more than 0.3 rad from one pose to the next (RuntimeError naming the pose instead).")
      .def(
          "joint_velocities",
          [](const SerialArm& a, const py::object& q, const py::object& body_twists) {
            const Array qs = rows_of(q, "q", a.dof());
            const Array twists = rows_of(body_twists, "body_twists", 6);
            if (twists.shape(0) != qs.shape(0))
              throw py::value_error("body_twists: expected " + std::to_string(qs.shape(0)) + " rows like q, got " +
                                    std::to_string(twists.shape(0)));
            using Rows = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
            const Rows q_rows = Eigen::Map<const Rows>(qs.data(), qs.shape(0), a.dof());
            const Rows twist_rows = Eigen::Map<const Rows>(twists.data(), twists.shape(0), 6);
            Eigen::MatrixXd out(qs.shape(0), a.dof());
            {
              py::gil_scoped_release unlocked;
              for (Eigen::Index k = 0; k < q_rows.rows(); ++k) {
                const Twistd xi(Eigen::Matrix<double, 6, 1>(twist_rows.row(k).transpose()));
                out.row(k) = serial::joint_velocity(a, q_rows.row(k).transpose(), xi).transpose();
              }
            }
            return to_rows(out);
          },
          py::arg("q"), py::arg("body_twists"),
          "(N, n) joint velocities: row k solves body_jacobian(q[k]) qd = body_twists[k] ((N, n) and (N, 6) "
          "arrays) in the least-squares sense, minimum norm (exact for a 6-joint arm away from singularities).")
      .def(
          "follow_trajectory",
          [](const SerialArm& a, const Trajectory& trajectory, const py::object& times, const py::object& q_start,
             double difference_step) {
            const Eigen::VectorXd start = joint_vector(q_start, "q_start");
            const std::vector<double> at = times_of(times, "times");
            FollowedJoints j;
            {
              py::gil_scoped_release unlocked;
              j = follow_joints(trajectory, a, start, at, difference_step);
            }
            return py::make_tuple(to_rows(j.q), to_rows(j.qd), to_rows(j.qdd));
          },
          py::arg("trajectory"), py::arg("times"), py::arg("q_start"), py::arg("difference_step") = 1e-4,
          "(q, qd, qdd), each (N, n), of the arm following a Cartesian trajectory at `times` (s): q by follow() "
          "from q_start, qd by joint_velocities() of the trajectory's body twist, qdd by central differences of "
          "qd over +-difference_step (one-sided at the ends), each neighbour followed from the sample's q.")
      .def(
          "check_joint_limits",
          [](const SerialArm& a, const py::object& trajectory, const py::object& times) {
            const JointTrajectory& move = trajectory.cast<const JointTrajectory&>();
            const std::vector<double> at = times_of(times, "times");
            const SerialArm arm = a;  // its gravity as now, whatever another thread sets meanwhile
            JointLimitReport report;
            {
              py::gil_scoped_release unlocked;
              report = check_joint_limits(move, arm, at);
            }
            return py::cast(std::move(report));  // py::object: JointLimitReport is bound after SerialArm
          },
          py::arg("trajectory"), py::arg("times"),
          "JointLimitReport of a PTP move (JointTrajectory) at `times` (s): the factors FVEL and FACC of its "
          "joint line's own q, qd, qdd. RuntimeError where the static torque alone reaches an effort limit.");
}

}  // namespace python
}  // namespace dispkin
