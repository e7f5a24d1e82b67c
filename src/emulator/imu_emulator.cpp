#include "imu_lab/emulator/imu_emulator.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "imu_lab/common/config_error.h"
#include "imu_lab/common/stamps.h"

#include "imu_lab/emulator/sensor_channel.h"

namespace imu_lab {
namespace emulator {

ImuEmulator::ImuEmulator(const SensorProfile& profile, std::unique_ptr<MotionSource> motion,
                         const EmulatorSettings& settings)
    : profile_(profile),
      settings_(settings),
      interval_s_(1.0 / settings.rate_hz),
      motion_(std::move(motion)),
      gyro_(std::make_unique<TriadChannel>(profile.gyro, "gyro", settings.seed)),
      accelerometer_(std::make_unique<TriadChannel>(profile.accelerometer, "accelerometer", settings.seed)) {
  // Stamps are whole nanoseconds: a faster rate would repeat them.
  if (!(settings.rate_hz > 0.0 && settings.rate_hz <= 1e9)) {
    throw ConfigError("emulator settings", "rate_hz",
                      "must be in (0, 1e9] Hz, got " + std::to_string(settings.rate_hz));
  }
  if (!(settings.start_time_s >= 0.0 && std::isfinite(settings.start_time_s))) {
    throw ConfigError("emulator settings", "start_time_s",
                      "must be a finite time >= 0 s, got " + std::to_string(settings.start_time_s));
  }
  if (!motion_) throw std::invalid_argument("ImuEmulator: no motion source");
}

ImuEmulator::ImuEmulator(const SensorProfile& profile, const ScenarioConfig& scenario, const EmulatorSettings& settings)
    : ImuEmulator(profile, make_motion_source(scenario), settings) {
  // A thermal profile without the second sensor would silently put the main sensor's temperature
  // into the second-sensor terms, where the lag between the two is the point.
  const bool second_terms =
      profile.gyro.thermal.uses_second_sensor() || profile.accelerometer.thermal.uses_second_sensor();
  if (second_terms && scenario.thermal && !scenario.thermal->second_sensor_time_constant_s) {
    throw ConfigError(scenario.source, "thermal.second_sensor_time_constant_s",
                      "sensor profile " + profile.name +
                          " has second-thermosensor terms; give the scenario's second sensor (its time constant)");
  }
}

ImuEmulator::~ImuEmulator() = default;
ImuEmulator::ImuEmulator(ImuEmulator&&) noexcept = default;
ImuEmulator& ImuEmulator::operator=(ImuEmulator&&) noexcept = default;

EmulatedSample ImuEmulator::next() {
  // Times from the index (not accumulated) so long runs do not drift.
  const double elapsed_start_s = static_cast<double>(sample_index_) * interval_s_;
  ++sample_index_;
  // Scenario time from the run start: stamps near 1e9 s would round the motion's times to 1e-7 s.
  const TruthIncrement truth_increment = motion_->increment(elapsed_start_s, interval_s_);
  const Eigen::Vector3d true_rate = truth_increment.delta_angle_rad / interval_s_;
  const Eigen::Vector3d true_force = truth_increment.delta_velocity_m_s / interval_s_;

  EmulatedSample sample;
  sample.stamp_ns = stamp_ns_from_seconds(settings_.start_time_s) +
                    stamp_ns_from_seconds(static_cast<double>(sample_index_) * interval_s_);
  const SensorTemperature temperature{truth_increment.mean_temperature_c, truth_increment.mean_temperature_rate_c_s,
                                      truth_increment.mean_second_temperature_c};
  sample.angular_rate_rad_s = gyro_->measure(true_rate, true_force, elapsed_start_s, interval_s_, temperature);
  sample.specific_force_m_s2 =
      accelerometer_->measure(true_force, Eigen::Vector3d::Zero(), elapsed_start_s, interval_s_, temperature);
  sample.delta_angle_rad = sample.angular_rate_rad_s * interval_s_;
  sample.delta_velocity_m_s = sample.specific_force_m_s2 * interval_s_;
  sample.temperature_c = truth_increment.mean_temperature_c;
  sample.second_temperature_c = truth_increment.mean_second_temperature_c;
  if (sample_index_ == 1) {
    gyro_variance_ = gyro_->sample_variance(interval_s_);
    accelerometer_variance_ = accelerometer_->sample_variance(interval_s_);
  }
  sample.angular_rate_variance_rad2_s2 = gyro_variance_;
  sample.specific_force_variance_m2_s4 = accelerometer_variance_;

  const TruthState truth = motion_->truth_at(static_cast<double>(sample_index_) * interval_s_);
  sample.truth.stamp_ns = sample.stamp_ns;
  sample.truth.q_body_to_enu = truth.attitude_body_to_enu;
  // What the sample should read without errors: the interval averages the sensor measured.
  sample.truth.angular_rate_rad_s = true_rate;
  sample.truth.specific_force_m_s2 = true_force;
  sample.truth.latitude_rad = truth.latitude_rad;
  sample.truth.longitude_rad = truth.longitude_rad;
  sample.truth.height_m = truth.height_m;
  sample.truth.velocity_enu_m_s = truth.velocity_enu_m_s;
  sample.truth.temperature_c = truth.temperature_c;
  sample.truth.second_temperature_c = truth.second_temperature_c;
  return sample;
}

}  // namespace emulator
}  // namespace imu_lab
