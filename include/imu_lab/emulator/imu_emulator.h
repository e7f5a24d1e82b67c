// The IMU emulator: sensor profile + motion source + settings -> one sample per step.
// Sample k covers [start_time_s + k dt, start_time_s + (k+1) dt]; its stamp is the END of the
// interval (so the first stamp is start_time_s + dt), in integer nanoseconds rounded as ROS rounds
// a time plus a duration (start_time_s and (k+1) dt each to the nanosecond, then added). Rates are exact interval
// averages and increments are average * dt. The motion source runs on scenario time (0 at start_time_s). Temperature
// terms of the profile see the interval's mean temperature and its rate. Same profile, scenario and settings (seed) ->
// bit-identical output.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cstdint>
#include <memory>
#include <optional>

#include "imu_lab/emulator/motion_source.h"
#include "imu_lab/emulator/scenario.h"
#include "imu_lab/emulator/sensor_profile.h"
#include "imu_lab/io/imu_records.h"

namespace imu_lab {
namespace emulator {

struct EmulatorSettings {
  double rate_hz = 100.0;
  double start_time_s = 0.0;  // from the config, never now()
  std::uint64_t seed = 1;
};

// What one step of the emulator gives: the sensor's output (rates, increments, temperatures, the
// noise variances a message's covariances carry) with the truth it was made from; the ROS layer
// turns it into messages (ros_io/msg/emulator_messages.h).
struct EmulatedSample {
  std::int64_t stamp_ns = 0;                                      // end of the interval (common/stamps.h)
  Eigen::Vector3d angular_rate_rad_s = Eigen::Vector3d::Zero();   // interval average
  Eigen::Vector3d specific_force_m_s2 = Eigen::Vector3d::Zero();  // interval average
  Eigen::Vector3d delta_angle_rad = Eigen::Vector3d::Zero();      // = average * dt
  Eigen::Vector3d delta_velocity_m_s = Eigen::Vector3d::Zero();   // = average * dt
  double temperature_c = 0.0;                                     // interval mean
  std::optional<double> second_temperature_c;                     // interval mean of the second thermosensor, if any
  // Per-axis variance of one sample's stationary noise (for sensor_msgs/Imu covariance
  // diagonals): white, white-angle, quantization, Markov, flicker bank, zero-DC family.
  // Excludes biases, random walk and deterministic terms. Constant over a run.
  Eigen::Vector3d angular_rate_variance_rad2_s2 = Eigen::Vector3d::Zero();
  Eigen::Vector3d specific_force_variance_m2_s4 = Eigen::Vector3d::Zero();
  // Truth at the same stamp: attitude, position, velocity and temperatures at the end of the
  // interval; angular rate and specific force averaged over the interval, exactly the averages the
  // sensor measured (the motion's integrals / dt), so an error-free sensor reads them bit for bit.
  io::TruthRecord truth;
};

// The sample's output as a recording of it would be read back.
inline io::ImuRecord to_imu_record(const EmulatedSample& sample) {
  return io::ImuRecord{sample.stamp_ns, sample.angular_rate_rad_s, sample.specific_force_m_s2};
}

class TriadChannel;  // sensor_channel.h

class ImuEmulator {
 public:
  ImuEmulator(const SensorProfile& profile, std::unique_ptr<MotionSource> motion, const EmulatorSettings& settings);
  ImuEmulator(const SensorProfile& profile, const ScenarioConfig& scenario, const EmulatorSettings& settings);
  ~ImuEmulator();
  ImuEmulator(ImuEmulator&&) noexcept;
  ImuEmulator& operator=(ImuEmulator&&) noexcept;

  EmulatedSample next();

  double sample_interval_s() const { return interval_s_; }
  std::uint64_t samples_emitted() const { return sample_index_; }
  const SensorProfile& profile() const { return profile_; }
  const EmulatorSettings& settings() const { return settings_; }
  // The triads' realised error models (turn-on bias drawn for this run, K, noise processes).
  const TriadChannel& gyro_channel() const { return *gyro_; }
  const TriadChannel& accelerometer_channel() const { return *accelerometer_; }

 private:
  SensorProfile profile_;
  EmulatorSettings settings_;
  double interval_s_ = 0.0;
  std::uint64_t sample_index_ = 0;
  std::unique_ptr<MotionSource> motion_;
  std::unique_ptr<TriadChannel> gyro_;
  std::unique_ptr<TriadChannel> accelerometer_;
  Eigen::Vector3d gyro_variance_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d accelerometer_variance_ = Eigen::Vector3d::Zero();
};

}  // namespace emulator
}  // namespace imu_lab
