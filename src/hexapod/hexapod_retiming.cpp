// Joint-limit prediction and re-timing for a hexapod (hexapod_retiming.hpp): the legs are the
// joints.
#include "dispkin/hexapod/hexapod_retiming.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>

namespace dispkin::hexapod {

JointLimitReport check_joint_limits(const Trajectory& trajectory, const Hexapod& hexapod,
                                    const JointCheckOptions& options) {
  const std::vector<double> times = checked_times(trajectory, options);
  const double duration = trajectory.duration(), h = options.difference_step;
  auto leg_speeds = [&](const TrajectorySample& at) -> Eigen::VectorXd {
    return hexapod.leg_jacobian(at.pose) * at.body_twist.vector();
  };
  JointLimitReport report;
  for (const double t : times) {
    const TrajectorySample here = trajectory.sample(t);
    JointSample sample;
    sample.time = t;
    sample.s = here.s;
    sample.q = hexapod.leg_lengths(here.pose);
    sample.qd = leg_speeds(here);
    const double t_before = std::max(0.0, t - h), t_after = std::min(duration, t + h);
    sample.qdd =
        t_after > t_before
            ? Eigen::VectorXd((leg_speeds(trajectory.sample(t_after)) - leg_speeds(trajectory.sample(t_before))) /
                              (t_after - t_before))
            : Eigen::VectorXd::Zero(6);
    const std::size_t index = report.samples.size();
    for (int k = 0; k < 6; ++k) {
      const double excess = std::max(hexapod.leg_min()(k) - sample.q(k), sample.q(k) - hexapod.leg_max()(k));
      if (excess > report.position_excess) {
        report.position_excess = excess;
        report.position_joint = k;
        report.position_sample = index;
      }
      const double f = std::abs(sample.qd(k)) / hexapod.leg_speed()(k);
      if (f > report.velocity_factor) {
        report.velocity_factor = f;
        report.velocity_joint = k;
        report.velocity_sample = index;
      }
    }
    report.samples.push_back(std::move(sample));
  }
  require_consistent(report);  // what a stored report is checked for, a made one holds too
  return report;
}

namespace {

// A hexapod: the legs are the joints (ℓ = IK, ℓ′ = J_leg ξ′), no dynamics model.
class HexapodModel final : public JointModel {
 public:
  explicit HexapodModel(const Hexapod& hexapod) : hexapod_(hexapod) {}
  int dof() const override { return 6; }
  std::string joint_name(int k) const override { return "leg " + std::to_string(k + 1); }
  const char* position_unit() const override { return "m"; }
  void joints(const Posed& pose, const Twistd& per_sigma, const Eigen::VectorXd&, const Eigen::VectorXd*,
              const PathPlace&, Eigen::VectorXd& q, Eigen::VectorXd& q1) const override {
    q = hexapod_.leg_lengths(pose);
    q1 = hexapod_.leg_jacobian(pose) * per_sigma.vector();
  }
  void torque_coefficients(const Eigen::VectorXd&, const Eigen::VectorXd&, const Eigen::VectorXd&, Eigen::VectorXd&,
                           Eigen::VectorXd&, Eigen::VectorXd&) const override {}
  JointLimitReport check(const Trajectory& trajectory, const Eigen::VectorXd&, int samples_between) const override {
    JointCheckOptions options;
    options.samples_between = samples_between;
    return check_joint_limits(trajectory, hexapod_, options);
  }
  JointBounds bounds(const OptimalRetimeOptions& options) const override {
    return {hexapod_.leg_speed(),
            options.joint_acceleration.size() ? options.joint_acceleration : JointBounds::unlimited(6),
            JointBounds::unlimited(6)};
  }

 private:
  const Hexapod& hexapod_;
};

}  // namespace

std::unique_ptr<JointModel> joint_model(const Hexapod& hexapod) { return std::make_unique<HexapodModel>(hexapod); }

OptimalRetimeResult retime_optimal(const Path& path, const MetricSetd& set, const Limits& limits,
                                   const Hexapod& hexapod, const OptimalRetimeOptions& options) {
  return retime_optimal(path, set, limits, HexapodModel(hexapod), hexapod.leg_lengths(hexapod.home()), options);
}

}  // namespace dispkin::hexapod
