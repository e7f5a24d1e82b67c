// What the attitude panel shows, without ROS or Qt: roll, pitch and yaw of the navigator's
// solution (nav/odometry) in degrees beside the 1-sigma error its alignment predicted
// (nav/alignment), and the nodes' input health (/diagnostics), each marked stale when its source
// has gone quiet. The widget only lays out these strings.
#pragma once

#include <array>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace imu_lab {
namespace panel {

// The solution's attitude: REP-103 angles of the body relative to ENU, yaw from east to north.
struct AttitudeSample {
  double roll_rad = 0.0;
  double pitch_rad = 0.0;
  double yaw_rad = 0.0;
};

// The alignment's result (imu_lab/Alignment): predicted 1-sigma of the small rotation error in
// ENU axes (east tilt, north tilt, heading); NaN where the method does not estimate that angle.
struct AlignmentSummary {
  std::string method;
  double duration_s = 0.0;
  std::array<double, 3> error_sigma_enu_rad{};
};

// One diagnostic status (diagnostic_msgs/DiagnosticStatus); level as there: 0 OK, 1 WARN,
// 2 ERROR, 3 STALE.
struct HealthStatus {
  std::string name;
  int level = 0;
  std::string message;
};

struct AttitudeRow {
  std::string angle;  // roll, pitch or yaw
  std::string value;  // "12.345 deg", or "-" before the first solution
  std::string sigma;  // "+-0.0012 deg (4.3 arcsec)", or why there is none
};

struct HealthLine {
  int level = 0;     // as HealthStatus::level; 3 (STALE) for a status not repeated in time
  std::string text;  // "WARN  allan_monitor: allan: 2 gaps (0.3 s)"
};

struct AttitudeView {
  bool have_attitude = false;
  bool have_alignment = false;
  std::vector<AttitudeRow> rows;
  std::string solution_line;             // where the numbers come from, or what is missing
  std::string health_summary;            // "input health: OK (2 statuses)"
  std::vector<HealthLine> health_lines;  // one per status, worst first
  int worst_health_level = -1;           // -1: no status received
};

// 1-sigma of roll, pitch and yaw at heading yaw_rad from the ENU-axis sigmas of the small rotation
// error. For a near-level body the roll error is the tilt about the body's forward axis
// (cos yaw, sin yaw) and the pitch error the tilt about its left axis (-sin yaw, cos yaw); the
// message carries no east-north correlation (msg/Alignment.msg), so the two tilts are taken as
// independent. Yaw's is the heading's.
std::array<double, 3> roll_pitch_yaw_sigma_rad(const std::array<double, 3>& error_sigma_enu_rad, double yaw_rad);

// "12.345 deg" (three decimals: a milli-degree is 3.6 arcsec).
std::string format_angle_deg(double angle_rad);
// "+-0.0012 deg (4.3 arcsec)": two significant digits, whole arcseconds from 100 ("+-0.13 deg
// (470 arcsec)"); "not estimated" for NaN.
std::string format_sigma(double sigma_rad);

class AttitudePanelModel {
 public:
  // A source silent for longer than stale_after_s is shown stale (the navigator publishes odometry
  // at its output rate and diagnostics once a second).
  explicit AttitudePanelModel(double stale_after_s = 3.0) : stale_after_s_(stale_after_s) {}

  // received_s: the viewer's clock when the message arrived (any monotonic clock, as view()'s).
  void set_attitude(const AttitudeSample& attitude, double received_s);
  void set_alignment(const AlignmentSummary& alignment);
  // Keeps the latest status per name.
  void set_health(const HealthStatus& status, double received_s);

  AttitudeView view(double now_s) const;

 private:
  struct ReceivedHealth {
    HealthStatus status;
    double received_s;
  };
  double stale_after_s_;
  std::optional<AttitudeSample> attitude_;
  double attitude_received_s_ = 0.0;
  std::optional<AlignmentSummary> alignment_;
  std::map<std::string, ReceivedHealth> health_;
};

}  // namespace panel
}  // namespace imu_lab
