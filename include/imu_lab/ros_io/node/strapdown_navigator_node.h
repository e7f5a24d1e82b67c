// The strapdown_navigator node (also the nodelet imu_lab/StrapdownNavigatorNodelet): IMU samples
// in, static alignment, then strapdown navigation out. Header stamps only, never arrival time.
//
// Subscribes (relative names; remap them):
//   imu/corrected (sensor_msgs/Imu; rates averaged over the interval since the previous stamp)
//     with input_type: imu (default), or imu/increment (imu_lab/ImuIncrement) with input_type:
//     increment; reference_height (std_msgs/Float64 [m]) when reference_height_topic: true.
// Publishes:
//   nav/odometry (nav_msgs/Odometry, every solution): pose in world_frame, twist in body_frame;
//   nav/path (nav_msgs/Path, one pose per path_interval_s, at most path_max_poses);
//   nav/alignment (imu_lab/Alignment, latched); tf world_frame -> body_frame; /diagnostics.
// Parameters: those of navigation_parameters.h, and
//   input_type (imu | increment), world_frame (world), body_frame (imu_link), publish_tf (true),
//   path_interval_s (1.0), path_max_poses (3600), queue_size (2000), reference_height_topic (false),
//   attitude_only (false: publish the position at the origin and zero velocity, for IMUs whose
//   free-inertial position is meaningless within seconds; the attitude is unchanged).
// World frame: local ENU (REP-103) with its origin at the initial position (latitude_deg,
// longitude_deg, height_m); position in metres, exact on the chosen Earth model (local_enu.h).
//   expected_rate_hz (input_health.h; gap_factor is the navigation's own).
// Bad input (NaN, gaps, unordered stamps) is skipped, logged (throttled) and counted in the
// diagnostics (input_health.h); the node keeps running.
// When the navigation state becomes unusable (NaN/Inf, |height| > 1000 km: nav::state_problem) the
// node stops publishing solutions, logs the stamp and reason once and reports them on
// /diagnostics at ERROR level at every update; it starts again (alignment, or the given initial
// state at the next sample) only when told to: service ~reinitialise (std_srvs/Trigger), which
// also works at any other time.
#pragma once

#include <diagnostic_updater/diagnostic_updater.h>
#include <imu_lab/ImuIncrement.h>
#include <nav_msgs/Path.h>
#include <ros/ros.h>
#include <sensor_msgs/Imu.h>
#include <std_msgs/Float64.h>
#include <std_srvs/Trigger.h>
#include <tf2_ros/transform_broadcaster.h>

#include <memory>
#include <mutex>
#include <optional>

#include "imu_lab/ros_io/bag/bag_navigation.h"
#include "imu_lab/ros_io/node/input_health.h"
#include "imu_lab/nav/local_enu.h"
#include "imu_lab/ros_io/msg/navigation_messages.h"
#include "imu_lab/pipeline/navigation_session.h"

namespace imu_lab {
namespace ros_io {

class StrapdownNavigatorNode {
 public:
  // Throws ConfigError naming the parameter that is wrong.
  StrapdownNavigatorNode(ros::NodeHandle& node, ros::NodeHandle& private_node);

 private:
  void on_imu(const sensor_msgs::Imu::ConstPtr& message);
  void on_increment(const imu_lab::ImuIncrement::ConstPtr& message);
  void on_reference_height(const std_msgs::Float64::ConstPtr& message);
  void after_sample(pipeline::SampleOutcome outcome, const ros::Time& stamp);
  void publish_solution();
  void report(diagnostic_updater::DiagnosticStatusWrapper& status);
  bool on_reinitialise(std_srvs::Trigger::Request& request, std_srvs::Trigger::Response& response);

  std::mutex mutex_;  // a nodelet may run the callbacks on several threads
  std::unique_ptr<pipeline::NavigationSession> session_;
  std::unique_ptr<nav::LocalEnuFrame> world_;
  NavigationFrames frames_;
  bool publish_tf_ = true;
  bool attitude_only_ = false;
  double path_interval_s_ = 1.0;
  std::size_t path_max_poses_ = 3600;
  nav_msgs::Path path_;
  bool alignment_published_ = false;

  ros::Subscriber input_subscriber_;
  ros::Subscriber reference_height_subscriber_;
  ros::Publisher odometry_publisher_;
  ros::Publisher path_publisher_;
  ros::Publisher alignment_publisher_;
  ros::ServiceServer reinitialise_service_;
  tf2_ros::TransformBroadcaster transform_broadcaster_;
  diagnostic_updater::Updater diagnostics_;
  ros::WallTimer diagnostics_timer_;

  std::optional<InputHealth> health_;
  std::size_t bad_interval_condition_ = 0, failed_alignment_condition_ = 0;
};

}  // namespace ros_io
}  // namespace imu_lab
