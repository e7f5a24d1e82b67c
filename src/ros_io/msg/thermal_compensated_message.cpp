#include "imu_lab/ros_io/msg/thermal_compensated_message.h"

#include "imu_lab/ros_io/msg/vector_message.h"

namespace imu_lab {
namespace ros_io {
sensor_msgs::Imu thermal_compensated_message(const sensor_msgs::Imu& input, const thermal::CompensatedSample& sample) {
  sensor_msgs::Imu output = input;
  set_vector_message(output.angular_velocity, sample.corrected.angular_rate_rad_s);
  set_vector_message(output.linear_acceleration, sample.corrected.specific_force_m_s2);
  return output;
}

}  // namespace ros_io
}  // namespace imu_lab
