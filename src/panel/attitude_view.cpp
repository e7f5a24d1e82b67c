#include "imu_lab/panel/attitude_view.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace imu_lab {
namespace panel {
namespace {

constexpr double kRadToDeg = 180.0 / 3.14159265358979323846;
constexpr double kDegToArcsec = 3600.0;
constexpr int kStaleLevel = 3;  // diagnostic_msgs/DiagnosticStatus::STALE

std::string printed(const char* format, double first, double second = 0.0) {
  char text[96];
  std::snprintf(text, sizeof text, format, first, second);
  return text;
}

const char* level_name(int level) {
  switch (level) {
    case 0: return "OK";
    case 1: return "WARN";
    case 2: return "ERROR";
    default: return "STALE";
  }
}

}  // namespace

std::array<double, 3> roll_pitch_yaw_sigma_rad(const std::array<double, 3>& error_sigma_enu_rad, double yaw_rad) {
  const double cosine = std::cos(yaw_rad), sine = std::sin(yaw_rad);
  const double east2 = error_sigma_enu_rad[0] * error_sigma_enu_rad[0];
  const double north2 = error_sigma_enu_rad[1] * error_sigma_enu_rad[1];
  return {std::sqrt(cosine * cosine * east2 + sine * sine * north2),
          std::sqrt(sine * sine * east2 + cosine * cosine * north2), error_sigma_enu_rad[2]};
}

std::string format_angle_deg(double angle_rad) {
  return std::isfinite(angle_rad) ? printed("%.3f deg", angle_rad * kRadToDeg) : "not finite";
}

std::string format_sigma(double sigma_rad) {
  if (std::isnan(sigma_rad)) return "not estimated";
  const double sigma_deg = sigma_rad * kRadToDeg;
  const double sigma_arcsec = sigma_deg * kDegToArcsec;
  // Two significant digits, without an exponent for hundreds of arcseconds and more.
  return printed(sigma_arcsec < 99.5 ? "+-%.2g deg (%.2g arcsec)" : "+-%.2g deg (%.0f arcsec)", sigma_deg,
                 sigma_arcsec);
}

void AttitudePanelModel::set_attitude(const AttitudeSample& attitude, double received_s) {
  attitude_ = attitude;
  attitude_received_s_ = received_s;
}

void AttitudePanelModel::set_alignment(const AlignmentSummary& alignment) { alignment_ = alignment; }

void AttitudePanelModel::set_health(const HealthStatus& status, double received_s) {
  health_[status.name] = {status, received_s};
}

AttitudeView AttitudePanelModel::view(double now_s) const {
  AttitudeView view;
  view.have_attitude = attitude_.has_value();
  view.have_alignment = alignment_.has_value();
  const std::array<const char*, 3> names{"roll", "pitch", "yaw"};
  std::array<double, 3> sigma_rad{NAN, NAN, NAN};
  if (alignment_ && attitude_)
    sigma_rad = roll_pitch_yaw_sigma_rad(alignment_->error_sigma_enu_rad, attitude_->yaw_rad);
  for (std::size_t i = 0; i < names.size(); ++i) {
    AttitudeRow row;
    row.angle = names[i];
    if (attitude_) {
      const std::array<double, 3> angles{attitude_->roll_rad, attitude_->pitch_rad, attitude_->yaw_rad};
      row.value = format_angle_deg(angles[i]);
    } else {
      row.value = "-";
    }
    row.sigma = alignment_ ? format_sigma(sigma_rad[i]) : "no alignment yet";
    view.rows.push_back(row);
  }

  if (!attitude_) {
    view.solution_line = "waiting for nav/odometry (the navigator publishes after its alignment)";
  } else if (now_s - attitude_received_s_ > stale_after_s_) {
    view.solution_line =
        printed("STALE: no nav/odometry for %.0f s; the angles are the last received", now_s - attitude_received_s_);
  } else {
    view.solution_line = "navigating";
  }
  if (alignment_) {
    view.solution_line += "; 1-sigma predicted by the " + alignment_->method + " alignment" +
                          (alignment_->duration_s > 0.0 ? printed(" (%.0f s)", alignment_->duration_s) : "");
  }

  for (const auto& [name, received] : health_) {
    const bool stale = now_s - received.received_s > stale_after_s_;
    const int level = stale ? kStaleLevel : received.status.level;
    std::string line = std::string(level_name(level)) + "  " + name + ": " + received.status.message;
    if (stale) line += printed(" (last report %.0f s ago)", now_s - received.received_s);
    view.health_lines.push_back({level, line});
    view.worst_health_level = std::max(view.worst_health_level, level);
  }
  std::stable_sort(view.health_lines.begin(), view.health_lines.end(),
                   [](const HealthLine& a, const HealthLine& b) { return a.level > b.level; });
  view.health_summary = health_.empty()
                            ? "input health: no /diagnostics received yet"
                            : std::string("input health: ") + level_name(view.worst_health_level) + " (" +
                                  std::to_string(health_.size()) + (health_.size() == 1 ? " status)" : " statuses)");
  return view;
}

}  // namespace panel
}  // namespace imu_lab
