#include "imu_lab/ros_io/msg/emulator_messages.h"

#include "imu_lab/ros_io/msg/vector_message.h"

namespace imu_lab {
namespace ros_io {
namespace {

void set_diagonal(boost::array<double, 9>& covariance, const Eigen::Vector3d& variance) {
  covariance.fill(0.0);
  for (int i = 0; i < 3; ++i) covariance[4 * i] = variance[i];
}

}  // namespace

imu_lab::ImuTruth to_truth_message(const io::TruthRecord& truth, const std_msgs::Header& header) {
  imu_lab::ImuTruth message;
  message.header = header;
  message.orientation.w = truth.q_body_to_enu.w();
  message.orientation.x = truth.q_body_to_enu.x();
  message.orientation.y = truth.q_body_to_enu.y();
  message.orientation.z = truth.q_body_to_enu.z();
  set_vector_message(message.angular_velocity_rad_s, truth.angular_rate_rad_s);
  set_vector_message(message.specific_force_m_s2, truth.specific_force_m_s2);
  message.latitude_rad = truth.latitude_rad;
  message.longitude_rad = truth.longitude_rad;
  message.height_m = truth.height_m;
  set_vector_message(message.velocity_enu_m_s, truth.velocity_enu_m_s);
  message.temperature_c = truth.temperature_c;
  return message;
}

io::TruthRecord to_truth_record(const imu_lab::ImuTruth& message) {
  io::TruthRecord record;
  record.stamp_ns = static_cast<std::int64_t>(message.header.stamp.toNSec());
  record.q_body_to_enu =
      Eigen::Quaterniond(message.orientation.w, message.orientation.x, message.orientation.y, message.orientation.z);
  record.angular_rate_rad_s = eigen_from_message(message.angular_velocity_rad_s);
  record.specific_force_m_s2 = eigen_from_message(message.specific_force_m_s2);
  record.latitude_rad = message.latitude_rad;
  record.longitude_rad = message.longitude_rad;
  record.height_m = message.height_m;
  record.velocity_enu_m_s = eigen_from_message(message.velocity_enu_m_s);
  record.temperature_c = message.temperature_c;
  return record;
}

EmulatorMessages to_messages(const emulator::EmulatedSample& sample, double interval_s, const std::string& frame_id) {
  EmulatorMessages out;
  std_msgs::Header header;
  header.stamp.fromNSec(static_cast<std::uint64_t>(sample.stamp_ns));
  header.frame_id = frame_id;

  out.raw.header = header;
  out.raw.orientation.w = 1.0;
  out.raw.orientation_covariance.fill(0.0);
  out.raw.orientation_covariance[0] = -1.0;
  set_vector_message(out.raw.angular_velocity, sample.angular_rate_rad_s);
  set_vector_message(out.raw.linear_acceleration, sample.specific_force_m_s2);
  set_diagonal(out.raw.angular_velocity_covariance, sample.angular_rate_variance_rad2_s2);
  set_diagonal(out.raw.linear_acceleration_covariance, sample.specific_force_variance_m2_s4);

  out.temperature.header = header;
  out.temperature.temperature = sample.temperature_c;
  out.temperature.variance = 0.0;
  if (sample.second_temperature_c) {
    out.second_temperature = out.temperature;
    out.second_temperature->temperature = *sample.second_temperature_c;
  }

  out.truth = to_truth_message(sample.truth, header);

  out.increment.header = header;
  out.increment.interval_s = interval_s;
  set_vector_message(out.increment.delta_angle_rad, sample.delta_angle_rad);
  set_vector_message(out.increment.delta_velocity_m_s, sample.delta_velocity_m_s);
  return out;
}

}  // namespace ros_io
}  // namespace imu_lab
