#include "imu_lab/ros_io/node/strapdown_navigator_node.h"

#include <cmath>

#include "imu_lab/common/format_number.h"
#include "imu_lab/common/site_limits.h"
#include "imu_lab/common/stamps.h"
#include "imu_lab/pipeline/navigation_csv.h"
#include "imu_lab/ros_io/msg/vector_message.h"
#include "imu_lab/ros_io/node/navigation_parameters.h"
#include "imu_lab/ros_io/node/node_parameters.h"

namespace imu_lab {
namespace ros_io {
namespace {

constexpr double kLogThrottle_s = 5.0;

}  // namespace

StrapdownNavigatorNode::StrapdownNavigatorNode(ros::NodeHandle& node, ros::NodeHandle& private_node) {
  const pipeline::NavigationSettings settings = load_navigation_settings(private_node);
  session_ = std::make_unique<pipeline::NavigationSession>(settings);
  world_ = std::make_unique<nav::LocalEnuFrame>(settings.navigator.earth, settings.latitude_rad, settings.longitude_rad,
                                                settings.height_m);
  frames_.world = parameter(private_node, "world_frame", frames_.world);
  frames_.body = parameter(private_node, "body_frame", frames_.body);
  publish_tf_ = parameter(private_node, "publish_tf", true);
  attitude_only_ = parameter(private_node, "attitude_only", false);
  path_interval_s_ = positive_parameter(private_node, "path_interval_s", 1.0);
  path_max_poses_ = static_cast<std::size_t>(positive_parameter(private_node, "path_max_poses", 3600));
  const int queue_size = positive_parameter(private_node, "queue_size", 2000);
  const InputType input_type = parse_input_type(private_node.resolveName("input_type"),
                                                parameter<std::string>(private_node, "input_type", "imu"));
  path_.header.frame_id = frames_.world;

  // The input health is ready before the first subscription: in a nodelet manager the callbacks
  // run on worker threads as soon as it exists (one found health_ still empty and crashed it).
  health_.emplace(node.resolveName(input_type == InputType::kImu ? "imu/corrected" : "imu/increment"),
                  load_input_health_settings(private_node, settings.gap_factor));
  bad_interval_condition_ =
      health_->define_condition("increments skipped: interval_s not positive", diagnostic_msgs::DiagnosticStatus::WARN);
  failed_alignment_condition_ =
      health_->define_condition("failed alignments (started again)", diagnostic_msgs::DiagnosticStatus::WARN);
  odometry_publisher_ = node.advertise<nav_msgs::Odometry>("nav/odometry", queue_size);
  path_publisher_ = node.advertise<nav_msgs::Path>("nav/path", 10);
  alignment_publisher_ = node.advertise<imu_lab::Alignment>("nav/alignment", 1, /*latch=*/true);
  if (input_type == InputType::kImu) {
    input_subscriber_ = node.subscribe("imu/corrected", queue_size, &StrapdownNavigatorNode::on_imu, this);
  } else {
    input_subscriber_ = node.subscribe("imu/increment", queue_size, &StrapdownNavigatorNode::on_increment, this);
  }
  reinitialise_service_ = private_node.advertiseService("reinitialise", &StrapdownNavigatorNode::on_reinitialise, this);
  if (parameter(private_node, "reference_height_topic", false)) {
    reference_height_subscriber_ =
        node.subscribe("reference_height", 10, &StrapdownNavigatorNode::on_reference_height, this);
  }

  diagnostics_.setHardwareID("strapdown_navigator");
  diagnostics_.add("strapdown navigation", this, &StrapdownNavigatorNode::report);
  diagnostics_timer_ = node.createWallTimer(ros::WallDuration(1.0), [this](const ros::WallTimerEvent&) {
    std::lock_guard<std::mutex> lock(mutex_);
    diagnostics_.update();
  });
  ROS_INFO("strapdown_navigator: %s input on %s; %s; world frame '%s' (ENU) at lat %.6f lon %.6f deg, h %.2f m",
           datatype_of(input_type), input_subscriber_.getTopic().c_str(),
           settings.align ? ("aligning for " + std::to_string(settings.alignment.duration_s) + " s").c_str()
                          : "given attitude",
           frames_.world.c_str(), settings.latitude_rad / pipeline::kDegToRad,
           settings.longitude_rad / pipeline::kDegToRad, settings.height_m);
}

void StrapdownNavigatorNode::on_imu(const sensor_msgs::Imu::ConstPtr& message) {
  std::lock_guard<std::mutex> lock(mutex_);
  // A triad not provided (covariance[0] = -1) reads as NaN: the session skips the sample.
  const ImuRecord record = to_imu_record(*message);
  health_->check_stamp(record.stamp_ns);
  health_->check_values(record);
  const auto outcome = session_->add_rates(record.stamp_ns, record.angular_rate_rad_s, record.specific_force_m_s2);
  after_sample(outcome, message->header.stamp);
}

void StrapdownNavigatorNode::on_increment(const imu_lab::ImuIncrement::ConstPtr& message) {
  std::lock_guard<std::mutex> lock(mutex_);
  nav::ImuIncrement increment;
  const auto& a = message->delta_angle_rad;
  const auto& v = message->delta_velocity_m_s;
  increment.delta_angle_rad = eigen_from_message(a);
  increment.delta_velocity_m_s = eigen_from_message(v);
  increment.dt_s = message->interval_s;
  health_->check_stamp(static_cast<std::int64_t>(message->header.stamp.toNSec()));
  const bool values_usable = health_->check_triads(increment.delta_angle_rad, increment.delta_velocity_m_s);
  if (values_usable && !(increment.dt_s > 0.0)) health_->count(bad_interval_condition_);
  after_sample(session_->add_increment(static_cast<std::int64_t>(message->header.stamp.toNSec()), increment),
               message->header.stamp);
}

void StrapdownNavigatorNode::on_reference_height(const std_msgs::Float64::ConstPtr& message) {
  std::lock_guard<std::mutex> lock(mutex_);
  if (message->data >= site_limits::kLowestHeightM && message->data <= site_limits::kHighestHeightM) {
    session_->set_reference_height(message->data);
  } else {  // NaN too
    ROS_WARN_THROTTLE(kLogThrottle_s, "strapdown_navigator: ignoring a reference height of %g m (outside [%g, %g] m)",
                      message->data, site_limits::kLowestHeightM, site_limits::kHighestHeightM);
  }
}

void StrapdownNavigatorNode::after_sample(pipeline::SampleOutcome outcome, const ros::Time& stamp) {
  if (outcome == pipeline::SampleOutcome::kDiverged) {
    ROS_ERROR("strapdown_navigator: navigation stopped: %s (sample at %.9f); call %s to start again",
              session_->last_problem().c_str(), stamp.toSec(), reinitialise_service_.getService().c_str());
    return;
  }
  if (outcome == pipeline::SampleOutcome::kHalted) return;  // counted, and on /diagnostics at ERROR level
  if (outcome == pipeline::SampleOutcome::kAlignmentFailed) health_->count(failed_alignment_condition_);
  if (pipeline::is_skipped(outcome) || outcome == pipeline::SampleOutcome::kAlignmentFailed) {
    ROS_WARN_THROTTLE(kLogThrottle_s, "strapdown_navigator: sample at %.9f skipped: %s (counted in diagnostics)",
                      stamp.toSec(), session_->last_problem().c_str());
    if (pipeline::is_skipped(outcome)) return;
  }
  if (session_->alignment() && !alignment_published_) {
    alignment_published_ = true;
    const pipeline::AlignmentResult& alignment = *session_->alignment();
    alignment_publisher_.publish(to_alignment_message(alignment, frames_));
    ROS_INFO("strapdown_navigator: %s alignment: roll %.4f pitch %.4f yaw %.4f deg", alignment.method.c_str(),
             alignment.roll_pitch_yaw_rad.x() / pipeline::kDegToRad,
             alignment.roll_pitch_yaw_rad.y() / pipeline::kDegToRad,
             alignment.roll_pitch_yaw_rad.z() / pipeline::kDegToRad);
  }
  if (session_->new_solution()) publish_solution();
}

void StrapdownNavigatorNode::publish_solution() {
  pipeline::NavigationSolution solution = pipeline::make_solution(*session_, *world_);
  if (attitude_only_) {
    solution.position_enu_m.setZero();
    solution.velocity_body_m_s.setZero();
  }
  odometry_publisher_.publish(to_odometry(solution, frames_));
  if (publish_tf_) transform_broadcaster_.sendTransform(to_transform(solution, frames_));
  const ros::Time stamp = to_ros_time(solution.stamp_ns);
  if (path_.poses.empty() || (stamp - path_.poses.back().header.stamp).toSec() >= path_interval_s_) {
    path_.poses.push_back(to_pose(solution, frames_));
    if (path_.poses.size() > path_max_poses_) path_.poses.erase(path_.poses.begin());
    path_.header.stamp = stamp;
    path_publisher_.publish(path_);
  }
}

void StrapdownNavigatorNode::report(diagnostic_updater::DiagnosticStatusWrapper& status) {
  const pipeline::InputCounters& counters = session_->counters();
  health_->fill(status, session_->halted() ? "stopped" : session_->navigating() ? "navigating" : "aligning");
  if (!session_->last_problem().empty()) status.add("last problem", session_->last_problem());
  status.add("samples used", counters.used);
  status.add("skipped: NaN/Inf or bad interval", counters.invalid);
  status.add("skipped: unordered stamps", counters.unordered);
  status.add("skipped: rate samples after a gap", counters.gaps);
  status.add("alignment", session_->alignment() ? "done (" + session_->alignment()->method + ")"
                                                : std::to_string(session_->alignment_progress_s()) + " of " +
                                                      std::to_string(session_->settings().alignment.duration_s) + " s");
  if (session_->navigating()) {
    const Eigen::Vector3d rpy =
        pipeline::roll_pitch_yaw_from_quaternion(session_->state().q_body_to_enu) / pipeline::kDegToRad;
    status.addf("roll, pitch, yaw [deg]", "%.4f, %.4f, %.4f", rpy.x(), rpy.y(), rpy.z());
  }
  status.add("divergences", counters.divergences);
  status.add("re-initialisations", counters.reinitialisations);
  if (const auto& divergence = session_->divergence()) {
    // Every report until told to start again: the condition persists, unlike the input problems.
    status.mergeSummary(diagnostic_msgs::DiagnosticStatus::ERROR,
                        "navigation stopped: state unusable at stamp " + format_stamp_s(divergence->stamp_ns) + " s (" +
                            divergence->problem + "); call " + reinitialise_service_.getService() + " to start again");
    status.add("navigation stopped at stamp [s]", format_stamp_s(divergence->stamp_ns));
    status.add("samples ignored since", counters.halted);
  }
}

bool StrapdownNavigatorNode::on_reinitialise(std_srvs::Trigger::Request&, std_srvs::Trigger::Response& response) {
  std::lock_guard<std::mutex> lock(mutex_);
  session_->reinitialise();
  alignment_published_ = false;
  path_.poses.clear();
  const pipeline::NavigationSettings& settings = session_->settings();
  response.success = true;
  response.message = settings.align ? "re-initialised: aligning for " +
                                          format_number(settings.alignment.duration_s, 6) + " s from the next sample"
                                    : "re-initialised: the given initial state at the next sample's stamp";
  ROS_INFO("strapdown_navigator: %s", response.message.c_str());
  return true;
}

}  // namespace ros_io
}  // namespace imu_lab
