// The samples of a recording as the tools and nodes pass them around, whatever they were read
// from (a bag, a live topic, a CSV file): plain values, SI units, header stamps. The ROS layer
// converts messages into these (ros_io/bag/imu_bag_reader.h); everything after the conversion is ROS-free.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <cstdint>
#include <optional>

#include "imu_lab/common/stamps.h"

namespace imu_lab {
namespace io {

// sensor_msgs/Imu: one sample at its header stamp.
struct ImuRecord {
  std::int64_t stamp_ns = 0;  // header stamp, never the bag's receive time (common/stamps.h)
  Eigen::Vector3d angular_rate_rad_s = Eigen::Vector3d::Zero();
  Eigen::Vector3d specific_force_m_s2 = Eigen::Vector3d::Zero();
  // A triad whose covariance[0] is -1 carries no data (sensor_msgs/Imu's convention, e.g. a driver
  // of an IMU without gyros). Its values are then NaN, not the message's zeros, so that no consumer
  // can average, fit or integrate them unawares: each one refuses, skips or excludes them as it
  // does NaN, and can tell the user why from these flags.
  bool has_angular_rate = true;
  bool has_specific_force = true;
};

// A record with both triads at stamp_s rounded to the nanosecond, for a synthetic sample (records
// read from a recording, or emulated, carry their own integer stamp: ImuRecord{stamp_ns, ...}).
inline ImuRecord make_imu_record(double stamp_s, const Eigen::Vector3d& angular_rate_rad_s,
                                 const Eigen::Vector3d& specific_force_m_s2) {
  ImuRecord record;
  record.stamp_ns = stamp_ns_from_seconds(stamp_s);
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

// imu_lab/ImuTruth: the emulator's ground truth at the stamp (frames as in nav/nav_state.h); the
// emulator makes it, the ROS layer writes and reads it.
struct TruthRecord {
  std::int64_t stamp_ns = 0;
  Eigen::Quaterniond q_body_to_enu = Eigen::Quaterniond::Identity();
  Eigen::Vector3d angular_rate_rad_s = Eigen::Vector3d::Zero();   // body axes, interval average
  Eigen::Vector3d specific_force_m_s2 = Eigen::Vector3d::Zero();  // body axes, interval average
  double latitude_rad = 0.0;
  double longitude_rad = 0.0;
  double height_m = 0.0;
  Eigen::Vector3d velocity_enu_m_s = Eigen::Vector3d::Zero();
  double temperature_c = 0.0;
  std::optional<double> second_temperature_c;  // when the scenario has a second thermosensor (not in the message)
};

// sensor_msgs/Temperature: one thermosensor reading at its header stamp.
struct TemperatureRecord {
  std::int64_t stamp_ns = 0;
  double temperature_c = 0.0;
};

}  // namespace io
}  // namespace imu_lab
