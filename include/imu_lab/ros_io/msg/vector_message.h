// An Eigen vector into any geometry_msgs type with x, y, z fields (Vector3, Point) and back: the
// one conversion every node and tool that publishes, writes or reads them shares.
#pragma once

#include <Eigen/Core>

namespace imu_lab {
namespace ros_io {

template <class Vector3Like>
void set_vector_message(Vector3Like& message, const Eigen::Vector3d& v) {
  message.x = v.x();
  message.y = v.y();
  message.z = v.z();
}

template <class Vector3Like>
Eigen::Vector3d eigen_from_message(const Vector3Like& message) {
  return Eigen::Vector3d(message.x, message.y, message.z);
}

}  // namespace ros_io
}  // namespace imu_lab
