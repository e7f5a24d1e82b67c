// pipeline::NavigationSolution / pipeline::AlignmentResult -> the messages the strapdown navigator publishes.
// Odometry (nav_msgs convention): pose in the world frame (local ENU at the initial position,
// REP-103), twist in the child (body, REP-145) frame. Covariances are left zero: the navigator
// does not propagate them.
#pragma once

#include <geometry_msgs/PoseStamped.h>
#include <geometry_msgs/TransformStamped.h>
#include <imu_lab/Alignment.h>
#include <nav_msgs/Odometry.h>

#include <string>

#include "imu_lab/pipeline/navigation_session.h"
#include "imu_lab/pipeline/navigation_solution.h"

namespace imu_lab {
namespace ros_io {

struct NavigationFrames {
  std::string world = "world";
  std::string body = "imu_link";
};

ros::Time to_ros_time(std::int64_t stamp_ns);
nav_msgs::Odometry to_odometry(const pipeline::NavigationSolution& solution, const NavigationFrames& frames);
geometry_msgs::TransformStamped to_transform(const pipeline::NavigationSolution& solution,
                                             const NavigationFrames& frames);
geometry_msgs::PoseStamped to_pose(const pipeline::NavigationSolution& solution, const NavigationFrames& frames);
imu_lab::Alignment to_alignment_message(const pipeline::AlignmentResult& alignment, const NavigationFrames& frames);

}  // namespace ros_io
}  // namespace imu_lab
