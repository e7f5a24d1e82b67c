// An Eigen vector into any geometry_msgs type with x, y, z fields (Vector3, Point): the one
// conversion every node and tool that publishes or writes them shares.
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

}  // namespace ros_io
}  // namespace imu_lab
