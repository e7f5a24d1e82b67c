#include "imu_lab/ros_io/msg/navigation_messages.h"

#include "imu_lab/ros_io/msg/vector_message.h"

namespace imu_lab {
namespace ros_io {
namespace {

geometry_msgs::Quaternion to_message(const Eigen::Quaterniond& q) {
  geometry_msgs::Quaternion out;
  out.w = q.w();
  out.x = q.x();
  out.y = q.y();
  out.z = q.z();
  return out;
}

}  // namespace

ros::Time to_ros_time(std::int64_t stamp_ns) {
  ros::Time stamp;
  stamp.fromNSec(static_cast<std::uint64_t>(stamp_ns));
  return stamp;
}

geometry_msgs::PoseStamped to_pose(const pipeline::NavigationSolution& solution, const NavigationFrames& frames) {
  geometry_msgs::PoseStamped pose;
  pose.header.stamp = to_ros_time(solution.stamp_ns);
  pose.header.frame_id = frames.world;
  set_vector_message(pose.pose.position, solution.position_enu_m);
  pose.pose.orientation = to_message(solution.q_body_to_enu);
  return pose;
}

// Odometry and the tf are the pose with the body frame named (and, for odometry, the twist).
nav_msgs::Odometry to_odometry(const pipeline::NavigationSolution& solution, const NavigationFrames& frames) {
  const geometry_msgs::PoseStamped pose = to_pose(solution, frames);
  nav_msgs::Odometry odometry;
  odometry.header = pose.header;
  odometry.child_frame_id = frames.body;
  odometry.pose.pose = pose.pose;
  set_vector_message(odometry.twist.twist.linear, solution.velocity_body_m_s);
  set_vector_message(odometry.twist.twist.angular, solution.angular_rate_body_rad_s);
  return odometry;
}

geometry_msgs::TransformStamped to_transform(const pipeline::NavigationSolution& solution,
                                             const NavigationFrames& frames) {
  const geometry_msgs::PoseStamped pose = to_pose(solution, frames);
  geometry_msgs::TransformStamped transform;
  transform.header = pose.header;
  transform.child_frame_id = frames.body;
  set_vector_message(transform.transform.translation, solution.position_enu_m);
  transform.transform.rotation = pose.pose.orientation;
  return transform;
}

imu_lab::Alignment to_alignment_message(const pipeline::AlignmentResult& alignment, const NavigationFrames& frames) {
  imu_lab::Alignment message;
  message.header.stamp = to_ros_time(alignment.stamp_ns);
  message.header.frame_id = frames.world;
  message.method = alignment.method;
  message.duration_s = alignment.duration_s;
  message.orientation = to_message(alignment.q_body_to_enu);
  message.roll_rad = alignment.roll_pitch_yaw_rad.x();
  message.pitch_rad = alignment.roll_pitch_yaw_rad.y();
  message.yaw_rad = alignment.roll_pitch_yaw_rad.z();
  set_vector_message(message.mean_angular_rate_rad_s, alignment.mean_angular_rate_rad_s);
  set_vector_message(message.mean_specific_force_m_s2, alignment.mean_specific_force_m_s2);
  set_vector_message(message.predicted_error_sigma_rad, alignment.predicted_error_sigma_rad);
  return message;
}

}  // namespace ros_io
}  // namespace imu_lab
