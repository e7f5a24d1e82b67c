// The thesis's own case: a navigation-grade ring-laser IMU (config/sensors/rlg_navigation.yaml,
// full noise model with 1-arcsec pulses) on the 12-position scheme with the thesis's 60 s dwells
// and 10 deg/s table moves, then nine held-out positions. After correction the spread of |g| and
// |Earth rate| over the held-out rests must be at the emulated noise floor, i.e. the spread the
// TRUE calibration gives on the same rests (thesis: 3e-4 m/s^2 and 0.001 deg/h measured,
// 0.015 deg/h allowed).
#include <gtest/gtest.h>

#include <cstdio>

#include "calib_test_support.h"

namespace imu_lab {
namespace {

TEST(CalibNavigationGrade, HeldOutGravityAndEarthRateSpreadsAtTheNoiseFloor) {
  const auto profile = emulator::load_sensor_profile(test::config_path("sensors/rlg_navigation.yaml"));
  calib_test::TableRun table;
  table.dwell_s = 60.0;
  table.move_rate_deg_s = 10.0;
  table.move_acceleration_deg_s2 = 20.0;
  table.rate_hz = 100.0;
  table.seed = 3;
  const auto run = calib_test::emulate_table_run(
      profile,
      calib_test::concatenated(calib_test::shipped_positions("multiposition_12_thesis.yaml"),
                               calib_test::held_out_positions()),
      table);
  calib::CalibrationOptions options;
  options.schedule = run.schedule;
  for (std::size_t k = 12; k < 21; ++k) options.held_out_positions.push_back(k);
  const auto result = calib::calibrate(run.samples, options);

  std::vector<calib::RestMeans> held_out;
  for (const auto& rest : result.rests) {
    if (rest.held_out) held_out.push_back(rest.means);
  }
  const auto floor = calib::held_out_check(held_out, run.truth, calib::ParameterCovariance::Zero(), run.schedule.site);
  const auto& g = result.held_out.gravity_m_s2;
  const auto& w = result.held_out.earth_rate_rad_s;
  constexpr double kDegPerHour = calib::kDegPerRad * 3600.0;
  std::printf(
      "[rlg] |g| spread over %zu held-out rests: raw %.3e, corrected %.3e, floor %.3e, expected %.3e m/s^2 "
      "(thesis 3e-4)\n",
      g.rests, g.raw_spread, g.corrected_spread, floor.gravity_m_s2.corrected_spread, g.expected_spread);
  std::printf(
      "[rlg] |Earth rate| spread: raw %.5f, corrected %.5f, floor %.5f, expected %.5f deg/h (thesis 0.001 "
      "measured, 0.015 allowed)\n",
      w.raw_spread * kDegPerHour, w.corrected_spread * kDegPerHour,
      floor.earth_rate_rad_s.corrected_spread * kDegPerHour, w.expected_spread * kDegPerHour);
  std::printf("[rlg] gyro scale factor sigma %.2f %.2f %.2f ppm; condition %.3g, chi2/dof %.2f\n",
              result.sigmas[calib::parameter_offset::kGyroK] * 1e6,
              result.sigmas[calib::parameter_offset::kGyroK + 4] * 1e6,
              result.sigmas[calib::parameter_offset::kGyroK + 8] * 1e6, result.condition_number,
              result.chi2_per_degree_of_freedom);
  // The accelerometers' bias instability moves each rest's mean by several times the white noise
  // over 60 s; the rest sigmas count it (rest_statistics.h), so a correct fit is not called
  // untrustworthy (chi2/dof was 10.96 with white-only sigmas).
  EXPECT_LT(result.chi2_per_degree_of_freedom, 3.0);
  EXPECT_TRUE(result.warnings.empty()) << result.warnings.front();
  EXPECT_LT(g.corrected_spread, 2.0 * floor.gravity_m_s2.corrected_spread);
  EXPECT_LT(w.corrected_spread, 2.0 * floor.earth_rate_rad_s.corrected_spread);
  EXPECT_LT(g.corrected_spread, 3e-4);
  EXPECT_LT(w.corrected_spread * kDegPerHour, 0.015);
}

}  // namespace
}  // namespace imu_lab
