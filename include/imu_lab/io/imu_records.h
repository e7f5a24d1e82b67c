// The samples of a recording as the tools and nodes pass them around, whatever they were read
// from (a bag, a live topic, a CSV file): plain values, SI units, header stamps. The ROS layer
// converts messages into these (ros_io/bag/imu_bag_reader.h); everything after the conversion is ROS-free.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <cmath>
#include <cstdint>

namespace imu_lab {
namespace io {

// sensor_msgs/Imu: one sample at its header stamp.
struct ImuRecord {
  double stamp_s = 0.0;       // header stamp, never the bag's receive time
  std::int64_t stamp_ns = 0;  // the same, exact: differences of stamp_s near 1e9 s lose ~0.1 us
  Eigen::Vector3d angular_rate_rad_s = Eigen::Vector3d::Zero();
  Eigen::Vector3d specific_force_m_s2 = Eigen::Vector3d::Zero();
  // A triad whose covariance[0] is -1 carries no data (sensor_msgs/Imu's convention, e.g. a driver
  // of an IMU without gyros). Its values are then NaN, not the message's zeros, so that no consumer
  // can average, fit or integrate them unawares: each one refuses, skips or excludes them as it
  // does NaN, and can tell the user why from these flags.
  bool has_angular_rate = true;
  bool has_specific_force = true;
};

// A record with both triads at stamp_s, its exact stamp stamp_s rounded to the nanosecond (an
// emulated or synthetic sample; records read from a recording carry the message's own stamp).
inline ImuRecord make_imu_record(double stamp_s, const Eigen::Vector3d& angular_rate_rad_s,
                                 const Eigen::Vector3d& specific_force_m_s2) {
  ImuRecord record;
  record.stamp_s = stamp_s;
  record.stamp_ns = std::llround(stamp_s * 1e9);
  record.angular_rate_rad_s = angular_rate_rad_s;
  record.specific_force_m_s2 = specific_force_m_s2;
  return record;
}

// imu_lab/ImuIncrement: the sensor's own integrals over interval_s, ending at the stamp.
struct IncrementRecord {
  std::int64_t stamp_ns = 0;
  double interval_s = 0.0;
  Eigen::Vector3d delta_angle_rad = Eigen::Vector3d::Zero();
  Eigen::Vector3d delta_velocity_m_s = Eigen::Vector3d::Zero();
};

// imu_lab/ImuTruth: the emulator's ground truth at the stamp (frames as in nav/nav_state.h).
struct TruthRecord {
  std::int64_t stamp_ns = 0;
  Eigen::Quaterniond q_body_to_enu = Eigen::Quaterniond::Identity();
  Eigen::Vector3d angular_rate_rad_s = Eigen::Vector3d::Zero();   // body axes, interval average
  Eigen::Vector3d specific_force_m_s2 = Eigen::Vector3d::Zero();  // body axes, interval average
  double latitude_rad = 0.0;
  double longitude_rad = 0.0;
  double height_m = 0.0;
  Eigen::Vector3d velocity_enu_m_s = Eigen::Vector3d::Zero();
};

// sensor_msgs/Temperature: one thermosensor reading at its header stamp.
struct TemperatureRecord {
  double stamp_s = 0.0;
  double temperature_c = 0.0;
};

}  // namespace io
}  // namespace imu_lab
