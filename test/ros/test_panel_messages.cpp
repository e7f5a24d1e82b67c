// The rviz panel's inputs through their messages: a fit published as imu_lab/NoiseAxis (as
// allan_monitor publishes it) gives the panel the fit's own total and partial curves and each
// term's record length; short parallel arrays read as missing points.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "../unit/identify_test_records.h"
#include "imu_lab/emulator/static_motion.h"
#include "imu_lab/identify/fit.h"
#include "imu_lab/identify/partial_curves.h"
#include "imu_lab/identify/record_length.h"
#include "imu_lab/ros_io/msg/noise_messages.h"
#include "imu_lab/ros_io/msg/panel_messages.h"

namespace imu_lab {
namespace {

constexpr double kTau0_s = 0.01;
constexpr double kLength_s = 7200.0;

// N, B and K as a tactical MEMS gyro has them, and an output step of 1e-4 rad/s.
identify::FitResult tactical_fit(std::vector<allan::StabilityPoint>* points) {
  identify::NoiseModel model;
  model.terms = {{identify::TermKind::kWhiteRate, 3e-5, 0.0},
                 {identify::TermKind::kBiasInstability, 1e-5, 0.5 / kTau0_s},
                 {identify::TermKind::kRandomWalk, 2e-7, 0.0}};
  identify::FitOptions options;
  options.output_quantization_step = 1e-4;
  model.output_quantization_density = identify::quantization_density(options.output_quantization_step, kTau0_s);
  *points = identify_test::exact_octave_curve(model, kTau0_s, kLength_s);
  return identify::fit_noise_model(*points, kTau0_s, kLength_s, options);
}

TEST(PanelMessages, TheFitsCurvesSurviveThePublishedMessage) {
  std::vector<allan::StabilityPoint> points;
  const identify::FitResult fit = tactical_fit(&points);
  ASSERT_GT(fit.model.output_quantization_density, 0.0);
  // Model order (partial_curves) and report order (the message) agree for any of N, B, K.
  ASSERT_GE(fit.model.terms.size(), 2u);
  for (const identify::Term& term : fit.model.terms) {
    ASSERT_TRUE(term.kind == identify::TermKind::kWhiteRate || term.kind == identify::TermKind::kBiasInstability ||
                term.kind == identify::TermKind::kRandomWalk)
        << identify::term_kind_name(term.kind);
  }
  const imu_lab::NoiseAxis message =
      ros_io::to_noise_axis(identify::SensorKind::kGyroscope, 0, fit, ros_io::kResolvedRelativeSigma);
  const panel::NoiseAxisModel axis = ros_io::to_noise_axis_model(message);
  EXPECT_EQ(axis.axis, "gyro_x");

  const identify::PartialCurves expected = identify::partial_curves(fit, points);
  const auto series = panel::model_series(axis, expected.tau_s);
  ASSERT_EQ(series.size(), expected.term_names.size() + 1) << "the total, every model term and the rounding";
  for (std::size_t k = 0; k < expected.tau_s.size(); ++k) {
    ASSERT_EQ(series[0].points.size(), expected.tau_s.size());
    EXPECT_NEAR(series[0].points[k].log10_deviation, std::log10(expected.total_deviation[k]), 1e-9)
        << "tau " << expected.tau_s[k];
    for (std::size_t term = 0; term < expected.term_names.size(); ++term) {
      EXPECT_NEAR(series[term + 1].points[k].log10_deviation, std::log10(expected.term_deviations[term][k]), 1e-9)
          << expected.term_names[term] << " at tau " << expected.tau_s[k];
    }
  }
}

TEST(PanelMessages, EachModelTermCarriesTheRecordItNeeds) {
  std::vector<allan::StabilityPoint> points;
  const identify::FitResult fit = tactical_fit(&points);
  const imu_lab::NoiseAxis message =
      ros_io::to_noise_axis(identify::SensorKind::kGyroscope, 0, fit, ros_io::kResolvedRelativeSigma);
  ASSERT_EQ(message.required_record_length_s.size(), message.term.size());
  bool saw_bias_instability = false;
  for (std::size_t i = 0; i < message.term.size(); ++i) {
    const double required_s = message.required_record_length_s[i];
    if (message.status[i] == "absent") {
      EXPECT_TRUE(std::isnan(required_s)) << message.term[i];
      continue;
    }
    // The record that gives the term's amplitude a 10 % sigma: sigma ~ 1 / sqrt(T) puts it near
    // T (sigma / 0.1)^2 (not exactly: a longer record also reaches longer taus).
    const identify::TermEstimate* term = fit.find(message.term[i]);
    ASSERT_NE(term, nullptr) << message.term[i];
    // The search starts at 100 samples.
    const double scaling_guess_s =
        std::max(100.0 * kTau0_s, kLength_s * std::pow(term->amplitude.log_sigma / 0.1, 2.0));
    EXPECT_GT(required_s, scaling_guess_s / 2.0) << message.term[i];
    EXPECT_LT(required_s, scaling_guess_s * 2.0) << message.term[i];
    saw_bias_instability |= message.term[i] == "bias_instability";
  }
  EXPECT_TRUE(saw_bias_instability);

  imu_lab::NoiseParameters report_message;
  report_message.record_length_s = kLength_s;
  report_message.target_relative_sigma = ros_io::kResolvedRelativeSigma;
  imu_lab::NoiseTriad triad;
  triad.sensor = "gyro";
  triad.axes = {message};
  report_message.triads = {triad};
  const panel::NoiseReport report = ros_io::to_noise_report(report_message);
  ASSERT_EQ(report.axes.size(), 1u);
  EXPECT_DOUBLE_EQ(report.target_relative_sigma, 0.1);
  const auto lines = panel::record_length_lines(report.axes[0], kLength_s);
  EXPECT_FALSE(lines.empty());
}

TEST(PanelMessages, ShortParallelArraysReadAsMissingPoints) {
  imu_lab::AllanDeviation message;
  message.statistic = "oadev";
  message.sensor = "accel";
  message.unit = "m/s^2";
  message.tau_s = {0.1, 1.0, 10.0};
  imu_lab::AllanAxis axis;
  axis.axis = "x";
  axis.deviation = {1e-3, 5e-4};
  axis.lower = {9e-4};
  axis.upper = {1.1e-3};
  message.axes = {axis};
  const panel::StabilityCurves curves = ros_io::to_stability_curves(message);
  ASSERT_EQ(curves.axes.size(), 1u);
  ASSERT_EQ(curves.axes[0].deviation.size(), 3u);
  EXPECT_TRUE(std::isnan(curves.axes[0].deviation[2]));
  EXPECT_TRUE(std::isnan(curves.axes[0].lower[1]));
  panel::AllanPanelModel model;
  model.add_curves(curves);
  const panel::AllanPlot plot = model.plot("accel", "oadev", 0);
  EXPECT_EQ(plot.measured.points.size(), 2u);
  EXPECT_EQ(plot.band.size(), 1u);
}

// The attitude panel: the odometry's quaternion back to the angles that made it, the alignment's
// ENU sigmas and the diagnostic status as they were published.
TEST(PanelMessages, AttitudeAlignmentAndHealthReachTheAttitudePanel) {
  constexpr double kDeg = M_PI / 180.0;
  const Eigen::Quaterniond q = emulator::attitude_from_roll_pitch_yaw(2.0 * kDeg, -3.0 * kDeg, 120.0 * kDeg);
  nav_msgs::Odometry odometry;
  odometry.pose.pose.orientation.w = q.w();
  odometry.pose.pose.orientation.x = q.x();
  odometry.pose.pose.orientation.y = q.y();
  odometry.pose.pose.orientation.z = q.z();
  const panel::AttitudeSample attitude = ros_io::to_attitude_sample(odometry);
  EXPECT_NEAR(attitude.roll_rad, 2.0 * kDeg, 1e-12);
  EXPECT_NEAR(attitude.pitch_rad, -3.0 * kDeg, 1e-12);
  EXPECT_NEAR(attitude.yaw_rad, 120.0 * kDeg, 1e-12);

  imu_lab::Alignment alignment;
  alignment.method = "given_heading";
  alignment.duration_s = 60.0;
  alignment.predicted_error_sigma_rad.x = 1e-4;
  alignment.predicted_error_sigma_rad.y = 2e-4;
  alignment.predicted_error_sigma_rad.z = std::nan("");
  const panel::AlignmentSummary summary = ros_io::to_alignment_summary(alignment);
  EXPECT_EQ(summary.method, "given_heading");
  EXPECT_EQ(summary.duration_s, 60.0);
  EXPECT_EQ(summary.error_sigma_enu_rad[0], 1e-4);
  EXPECT_EQ(summary.error_sigma_enu_rad[1], 2e-4);
  EXPECT_TRUE(std::isnan(summary.error_sigma_enu_rad[2]));

  diagnostic_msgs::DiagnosticStatus status;
  status.name = "strapdown_navigator: strapdown navigation";
  status.level = diagnostic_msgs::DiagnosticStatus::WARN;
  status.message = "2 gaps";
  const panel::HealthStatus health = ros_io::to_health_status(status);
  EXPECT_EQ(health.name, status.name);
  EXPECT_EQ(health.level, 1);
  EXPECT_EQ(health.message, "2 gaps");
}

}  // namespace
}  // namespace imu_lab
