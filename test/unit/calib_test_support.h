// Emulated calibration runs for the calib tests, in memory: a tactical MEMS IMU with the large
// scale-factor errors (500-2000 ppm) and ~3 arcmin misalignments the issue asks for, table
// schedules built from (roll, pitch, yaw) lists, and the emulator's own error model as the truth.
#pragma once

#include <Eigen/Core>
#include <array>
#include <string>
#include <variant>
#include <cmath>
#include <vector>

#include "imu_lab/calib/bench_calibration.h"
#include "imu_lab/calib/kalibr_intrinsics.h"
#include "imu_lab/emulator/imu_emulator.h"
#include "imu_lab/emulator/scenario.h"
#include "imu_lab/emulator/sensor_channel.h"
#include "imu_lab/emulator/static_motion.h"
#include "test_emulator_paths.h"

namespace imu_lab {
namespace calib_test {

constexpr double kDeg = 3.14159265358979323846 / 180.0;
constexpr double kArcmin = kDeg / 60.0;

using Attitudes = std::vector<Eigen::Quaterniond>;  // body -> ENU, one per rest

// The orientations of a shipped scheme (config/scenarios/multiposition_*.yaml).
inline Attitudes shipped_positions(const std::string& scenario_file) {
  Attitudes attitudes;
  const auto scenario = emulator::load_scenario(test::config_path("scenarios/" + scenario_file));
  for (const auto& position : scenario.multi_position->positions) attitudes.push_back(position.attitude_body_to_enu);
  return attitudes;
}

// Nine orientations no scheme uses, for the held-out check (the thesis's verification run has nine).
inline Attitudes held_out_positions() {
  const double roll_pitch_yaw_deg[9][3] = {{30, 20, 0},     {-60, 35, 45},  {120, -30, 10},
                                           {15, 70, -80},   {-150, 10, 30}, {75, -60, 120},
                                           {-20, -15, 200}, {160, 50, -45}, {45, 45, 45}};
  Attitudes attitudes;
  for (const auto& rpy : roll_pitch_yaw_deg) {
    attitudes.push_back(emulator::attitude_from_roll_pitch_yaw(rpy[0] * kDeg, rpy[1] * kDeg, rpy[2] * kDeg));
  }
  return attitudes;
}

inline Attitudes concatenated(Attitudes first, const Attitudes& second) {
  first.insert(first.end(), second.begin(), second.end());
  return first;
}

// Keeps the noise that averages down within a rest (white rate, white angle); drops bias
// instability and random walk: over one run they are indistinguishable from a constant bias, so
// no calibration can tell them from it (they set the bias's run-to-run scatter instead).
inline void keep_fast_noise_only(emulator::TriadErrorModel& triad) {
  for (auto& processes : triad.noise_per_axis) {
    std::vector<noise::ProcessParameters> fast;
    for (const auto& process : processes) {
      if (std::holds_alternative<noise::WhiteRateParameters>(process) ||
          std::holds_alternative<noise::WhiteAngleParameters>(process)) {
        fast.push_back(process);
      }
    }
    processes = fast;
  }
}

// Tactical MEMS noise (config/sensors/tactical_mems.yaml: white rate, 100 Hz anti-alias filter,
// white-angle quantization) with large deterministic errors; no thermal terms (the chain removes
// them before calibration) and no g-sensitivity unless asked.
inline emulator::SensorProfile tactical_test_profile(bool with_g_sensitivity = false) {
  auto profile = emulator::load_sensor_profile(test::config_path("sensors/tactical_mems.yaml"));
  keep_fast_noise_only(profile.gyro);
  keep_fast_noise_only(profile.accelerometer);
  profile.gyro.thermal = emulator::ThermalSensitivity{};
  profile.accelerometer.thermal = emulator::ThermalSensitivity{};
  if (!with_g_sensitivity) profile.gyro.g_sensitivity.setZero();
  profile.gyro.scale_factor_error_ppm = Eigen::Vector3d(500.0, -1200.0, 2000.0);
  profile.accelerometer.scale_factor_error_ppm = Eigen::Vector3d(-800.0, 1500.0, 1900.0);
  profile.gyro.misalignment_rad << 0.0, 3.0 * kArcmin, -2.5 * kArcmin,  //
      -3.2 * kArcmin, 0.0, 2.8 * kArcmin,                               //
      3.5 * kArcmin, -2.0 * kArcmin, 0.0;
  profile.accelerometer.misalignment_rad << 0.0, -2.8 * kArcmin, 3.1 * kArcmin,  //
      2.6 * kArcmin, 0.0, -3.4 * kArcmin,                                        //
      -3.0 * kArcmin, 2.2 * kArcmin, 0.0;
  return profile;
}

struct TableRun {
  double dwell_s = 10.0;
  double move_rate_deg_s = 90.0;
  double move_acceleration_deg_s2 = 180.0;
  double rate_hz = 200.0;
  std::uint64_t seed = 1;
  double latitude_deg = 50.45;
};

inline emulator::ScenarioConfig table_scenario(const Attitudes& positions, const TableRun& run) {
  emulator::ScenarioConfig scenario;
  scenario.type = "multi_position";
  scenario.source = "calib test schedule";
  scenario.latitude_rad = run.latitude_deg * kDeg;
  scenario.height_m = 180.0;
  scenario.temperature_c = 25.0;
  emulator::MultiPositionConfig table;
  table.move_rate_rad_s = run.move_rate_deg_s * kDeg;
  table.move_acceleration_rad_s2 = run.move_acceleration_deg_s2 * kDeg;
  double duration_s = 0.0;
  for (const auto& attitude : positions) {
    table.positions.push_back({attitude, run.dwell_s});
    duration_s += run.dwell_s + 180.0 / run.move_rate_deg_s + run.move_rate_deg_s / run.move_acceleration_deg_s2;
  }
  scenario.duration_s = duration_s;
  scenario.multi_position = table;
  return scenario;
}

struct EmulatedRun {
  std::vector<io::ImuRecord> samples;
  calib::ImuCalibration truth;  // the emulator's realised error model
  calib::TableSchedule schedule;
};

inline calib::ImuCalibration truth_of(const emulator::ImuEmulator& imu) {
  calib::ImuCalibration truth;
  truth.gyro.bias = imu.gyro_channel().total_bias();
  truth.gyro.scale_misalignment = imu.gyro_channel().scale_misalignment_matrix();
  truth.gyro.g_sensitivity = imu.profile().gyro.g_sensitivity;
  truth.accelerometer.bias = imu.accelerometer_channel().total_bias();
  truth.accelerometer.scale_misalignment = imu.accelerometer_channel().scale_misalignment_matrix();
  return truth;
}

// Runs until the scheduled time is covered (the last rest is cut to its dwell).
inline EmulatedRun emulate_table_run(const emulator::SensorProfile& profile, const Attitudes& positions,
                                     const TableRun& run) {
  const emulator::ScenarioConfig scenario = table_scenario(positions, run);
  emulator::EmulatorSettings settings;
  settings.rate_hz = run.rate_hz;
  settings.seed = run.seed;
  settings.start_time_s = 1000.0;
  emulator::ImuEmulator imu(profile, scenario, settings);
  EmulatedRun result;
  result.truth = truth_of(imu);
  result.schedule = calib::schedule_from_scenario(scenario);
  const auto count = static_cast<std::size_t>(scenario.duration_s * run.rate_hz);
  result.samples.reserve(count);
  for (std::size_t k = 0; k < count; ++k) {
    const emulator::EmulatedSample sample = imu.next();
    result.samples.push_back(emulator::to_imu_record(sample));
  }
  return result;
}

// Truth re-expressed in the mode-2 frame convention: K_accelerometer = L Q (L lower triangular,
// Q the rotation body -> accelerometer frame); the gyro's K and G see body vectors through Q^T.
inline calib::ImuCalibration in_accelerometer_frame(const calib::ImuCalibration& truth) {
  Eigen::Matrix3d lower, body_to_accelerometer;
  calib::lower_triangular_times_rotation(truth.accelerometer.scale_misalignment, lower, body_to_accelerometer);
  calib::ImuCalibration converted = truth;
  converted.accelerometer.scale_misalignment = lower;
  converted.gyro.scale_misalignment = truth.gyro.scale_misalignment * body_to_accelerometer.transpose();
  converted.gyro.g_sensitivity = truth.gyro.g_sensitivity * body_to_accelerometer.transpose();
  return converted;
}

}  // namespace calib_test
}  // namespace imu_lab
