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

ros::Time sample_stamp(double start_time_s, double interval_s, std::uint64_t n) {
  ros::Time start;
  start.fromSec(start_time_s);
  return start + ros::Duration(static_cast<double>(n) * interval_s);
}

EmulatorMessages to_messages(const emulator::EmulatedSample& sample, const ros::Time& stamp, double interval_s,
                             const std::string& frame_id) {
  EmulatorMessages out;
  std_msgs::Header header;
  header.stamp = stamp;
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

  const emulator::TruthSample& truth = sample.truth;
  out.truth.header = header;
  out.truth.orientation.w = truth.attitude_body_to_enu.w();
  out.truth.orientation.x = truth.attitude_body_to_enu.x();
  out.truth.orientation.y = truth.attitude_body_to_enu.y();
  out.truth.orientation.z = truth.attitude_body_to_enu.z();
  set_vector_message(out.truth.angular_velocity_rad_s, truth.angular_rate_rad_s);
  set_vector_message(out.truth.specific_force_m_s2, truth.specific_force_m_s2);
  out.truth.latitude_rad = truth.latitude_rad;
  out.truth.longitude_rad = truth.longitude_rad;
  out.truth.height_m = truth.height_m;
  set_vector_message(out.truth.velocity_enu_m_s, truth.velocity_enu_m_s);
  out.truth.temperature_c = truth.temperature_c;

  out.increment.header = header;
  out.increment.interval_s = interval_s;
  set_vector_message(out.increment.delta_angle_rad, sample.delta_angle_rad);
  set_vector_message(out.increment.delta_velocity_m_s, sample.delta_velocity_m_s);
  return out;
}

}  // namespace ros_io
}  // namespace imu_lab
