#include "imu_lab/ros_io/node/calibration_corrector_node.h"

#include <Eigen/LU>
#include <boost/make_shared.hpp>
#include <cmath>

#include "imu_lab/calib/calibration_file.h"
#include "imu_lab/ros_io/msg/vector_message.h"
#include "imu_lab/ros_io/node/node_parameters.h"

namespace imu_lab {
namespace ros_io {
namespace {

constexpr double kLogThrottle_s = 5.0;

// K^-1 C K^-T for a known covariance; -1 in element 0 ("unknown", REP-145) stays as it is.
void carry_covariance(boost::array<double, 9>& covariance, const Eigen::Matrix3d& k_inverse) {
  if (covariance[0] < 0.0) return;
  Eigen::Matrix3d c;
  for (int k = 0; k < 9; ++k) c(k / 3, k % 3) = covariance[k];
  const Eigen::Matrix3d carried = k_inverse * c * k_inverse.transpose();
  for (int k = 0; k < 9; ++k) covariance[k] = carried(k / 3, k % 3);
}

}  // namespace

sensor_msgs::Imu corrected_message(const sensor_msgs::Imu& input, const calib::ImuCalibration& calibration) {
  sensor_msgs::Imu output = input;
  const calib::CorrectedSample corrected =
      calibration.correct(eigen_from_message(input.angular_velocity), eigen_from_message(input.linear_acceleration));
  set_vector_message(output.angular_velocity, corrected.angular_rate_rad_s);
  set_vector_message(output.linear_acceleration, corrected.specific_force_m_s2);
  carry_covariance(output.angular_velocity_covariance, calibration.gyro.scale_misalignment.inverse());
  carry_covariance(output.linear_acceleration_covariance, calibration.accelerometer.scale_misalignment.inverse());
  return output;
}

CalibrationCorrectorNode::CalibrationCorrectorNode(ros::NodeHandle& node, ros::NodeHandle& private_node) {
  calibration_file_ = parameter<std::string>(private_node, "calibration_file", "");
  if (calibration_file_.empty()) {
    throw parameter_error(private_node, "calibration_file", "required: the YAML written by fit_calibration");
  }
  calibration_ = calib::load_calibration(calibration_file_);
  const int queue_size = positive_parameter(private_node, "queue_size", 1000);

  // The input health is ready before the first subscription: in a nodelet manager the callbacks
  // run on worker threads as soon as it exists (one found health_ still empty and crashed it).
  health_.emplace(node.resolveName("imu/thermal"), load_input_health_settings(private_node, 3.0));
  publisher_ = node.advertise<sensor_msgs::Imu>("imu/corrected", queue_size);
  subscriber_ = node.subscribe("imu/thermal", queue_size, &CalibrationCorrectorNode::on_imu, this);
  diagnostics_.setHardwareID("calibration_corrector");
  diagnostics_.add("calibration correction", this, &CalibrationCorrectorNode::report);
  diagnostics_timer_ = node.createWallTimer(ros::WallDuration(1.0), [this](const ros::WallTimerEvent&) {
    std::lock_guard<std::mutex> lock(mutex_);
    diagnostics_.update();
  });
  ROS_INFO("calibration_corrector: %s -> %s with %s", subscriber_.getTopic().c_str(), publisher_.getTopic().c_str(),
           calibration_file_.c_str());
}

void CalibrationCorrectorNode::on_imu(const sensor_msgs::Imu::ConstPtr& message) {
  std::lock_guard<std::mutex> lock(mutex_);
  // Like every node of the chain: a duplicate or out-of-order stamp is dropped, not passed on.
  const StampVerdict verdict = health_->check_stamp(static_cast<std::int64_t>(message->header.stamp.toNSec()));
  if (verdict == StampVerdict::kDuplicate || verdict == StampVerdict::kOutOfOrder) {
    ROS_WARN_THROTTLE(kLogThrottle_s,
                      "calibration_corrector: dropped a sample at %.9f: its stamp is not after the "
                      "previous one (counted in diagnostics)",
                      message->header.stamp.toSec());
    return;
  }
  if (!health_->check_values(to_imu_record(*message))) {
    ROS_WARN_THROTTLE(kLogThrottle_s,
                      "calibration_corrector: dropped a sample with NaN/Inf, a value beyond +-1e100 or "
                      "a triad not provided at %.9f (counted in diagnostics)",
                      message->header.stamp.toSec());
    return;
  }
  // A shared message: nodelets downstream in the same manager receive this pointer, not a copy.
  publisher_.publish(boost::make_shared<sensor_msgs::Imu>(corrected_message(*message, calibration_)));
  ++corrected_;
}

void CalibrationCorrectorNode::report(diagnostic_updater::DiagnosticStatusWrapper& status) {
  health_->fill(status, "correcting");
  status.add("calibration file", calibration_file_);
  status.add("samples corrected", corrected_);
}

}  // namespace ros_io
}  // namespace imu_lab
