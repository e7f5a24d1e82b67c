// sensor_msgs/Imu read from its serialised form keeping only what an ImuRecord holds: the header
// stamp, the angular velocity and the linear acceleration, and the first element of their
// covariances (-1 marks a triad without data). The bag readers deserialise every
// message of a long bag; skipping the frame_id string, the orientation and the three covariance
// matrices instead of building a whole sensor_msgs::Imu saves an allocation and ~300 bytes of
// copying per message. Same md5sum and type as sensor_msgs/Imu, so rosbag hands it exactly the
// messages it would hand sensor_msgs::Imu, and the values read are the same bits.
#pragma once

#include <geometry_msgs/Vector3.h>
#include <ros/serialization.h>
#include <ros/time.h>
#include <sensor_msgs/Imu.h>

#include <boost/shared_ptr.hpp>
#include <cstdint>

namespace imu_lab {
namespace ros_io {

struct ImuWireFields {
  using ConstPtr = boost::shared_ptr<const ImuWireFields>;
  ros::Time stamp;
  geometry_msgs::Vector3 angular_velocity;
  double angular_velocity_covariance_0 = 0.0;  // -1: no angular rate in the message
  geometry_msgs::Vector3 linear_acceleration;
  double linear_acceleration_covariance_0 = 0.0;  // -1: no specific force in the message
};

}  // namespace ros_io
}  // namespace imu_lab

namespace ros {
namespace message_traits {

template <>
struct MD5Sum<imu_lab::ros_io::ImuWireFields> {
  static const char* value() { return MD5Sum<sensor_msgs::Imu>::value(); }
  static const char* value(const imu_lab::ros_io::ImuWireFields&) { return value(); }
};

template <>
struct DataType<imu_lab::ros_io::ImuWireFields> {
  static const char* value() { return DataType<sensor_msgs::Imu>::value(); }
  static const char* value(const imu_lab::ros_io::ImuWireFields&) { return value(); }
};

}  // namespace message_traits

namespace serialization {

// Read only: the layout of sensor_msgs/Imu (std_msgs/Header seq, stamp, frame_id; orientation;
// float64[9] covariance after each of the three vectors). A short message throws
// StreamOverrunException (a ros::Exception), as deserialising sensor_msgs::Imu would.
template <>
struct Serializer<imu_lab::ros_io::ImuWireFields> {
  static constexpr std::uint32_t kQuaternionBytes = 4 * sizeof(double);
  static constexpr std::uint32_t kCovarianceBytes = 9 * sizeof(double);

  template <typename Stream>
  static void read(Stream& stream, imu_lab::ros_io::ImuWireFields& fields) {
    std::uint32_t sequence = 0;
    stream.next(sequence);
    stream.next(fields.stamp);
    std::uint32_t frame_id_bytes = 0;
    stream.next(frame_id_bytes);
    stream.advance(frame_id_bytes);
    stream.advance(kQuaternionBytes + kCovarianceBytes);
    stream.next(fields.angular_velocity);
    stream.next(fields.angular_velocity_covariance_0);
    stream.advance(kCovarianceBytes - sizeof(double));
    stream.next(fields.linear_acceleration);
    stream.next(fields.linear_acceleration_covariance_0);
    stream.advance(kCovarianceBytes - sizeof(double));
  }
};

}  // namespace serialization
}  // namespace ros
