// Bench calibration of an emulated tactical MEMS IMU (scale-factor errors 500-2000 ppm,
// misalignments ~3 arcmin, biases) on the shipped 24-position scheme plus 9 held-out positions,
// in both modes. Oracle: the emulator's realised error model.
#include <gtest/gtest.h>

#include <cstdio>

#include "calib_test_support.h"

namespace imu_lab {
namespace {

using calib_test::kDeg;

struct TacticalRuns {
  calib_test::EmulatedRun run;
  calib::CalibrationResult known, unknown;
  double noise_floor_spread_m_s2 = 0.0;  // |g| spread with the TRUE calibration: the emulated noise floor
};

// Dwells of 10 s and fast moves (200 deg/s, as a rate table turns): the gyro scale factors come
// from the moves, whose angle noise grows with their duration; the dwells set the accelerometers'.
const TacticalRuns& runs() {
  static const TacticalRuns runs = [] {
    TacticalRuns r;
    const auto positions = calib_test::concatenated(calib_test::shipped_positions("multiposition_24.yaml"),
                                                    calib_test::held_out_positions());
    calib_test::TableRun table;
    table.dwell_s = 10.0;
    table.move_rate_deg_s = 200.0;
    table.move_acceleration_deg_s2 = 1000.0;
    r.run = calib_test::emulate_table_run(calib_test::tactical_test_profile(), positions, table);
    calib::CalibrationOptions options;
    options.schedule = r.run.schedule;
    for (std::size_t k = 24; k < 33; ++k) options.held_out_positions.push_back(k);
    r.known = calib::calibrate(r.run.samples, options);
    options.site = options.schedule->site;
    options.schedule.reset();
    r.unknown = calib::calibrate(r.run.samples, options);
    std::vector<calib::RestMeans> held_out;
    for (const auto& rest : r.known.rests) {
      if (rest.held_out) held_out.push_back(rest.means);
    }
    r.noise_floor_spread_m_s2 =
        calib::held_out_check(held_out, r.run.truth, calib::ParameterCovariance::Zero(), options.site)
            .gravity_m_s2.corrected_spread;
    return r;
  }();
  return runs;
}

// Worst |estimate - truth| / sigma over the estimated parameters; prints the table.
double worst_normalised_error(const calib::CalibrationResult& result, const calib::ImuCalibration& truth,
                              const char* label) {
  const calib::ParameterVector expected = calib::to_parameter_vector(truth);
  double worst = 0.0;
  for (int k = 0; k < calib::kParameterCount; ++k) {
    if (!result.estimated[k]) continue;
    const double z = (result.values[k] - expected[k]) / result.sigmas[k];
    std::printf("[%s] %-20s estimate %+.8e truth %+.8e sigma %.3e  z %+5.2f\n", label, calib::parameter_name(k).c_str(),
                result.values[k], expected[k], result.sigmas[k], z);
    worst = std::max(worst, std::abs(z));
  }
  return worst;
}

// Largest reported sigma of the scale factors [ppm] and of the off-diagonal terms [arcsec],
// printed with the fit's conditioning under `label`.
std::pair<double, double> largest_sigmas(const calib::CalibrationResult& result, const char* label) {
  double scale_ppm = 0.0, misalignment_arcsec = 0.0;
  for (int offset : {calib::parameter_offset::kAccelerometerK, calib::parameter_offset::kGyroK}) {
    for (int element = 0; element < 9; ++element) {
      const double sigma = result.sigmas[offset + element];
      if (element % 4 == 0) {
        scale_ppm = std::max(scale_ppm, sigma * 1e6);
      } else {
        misalignment_arcsec = std::max(misalignment_arcsec, sigma * calib::kArcsecPerRad);
      }
    }
  }
  std::printf("[%s] largest sigma: scale factor %.2f ppm, misalignment %.2f arcsec; condition %.3g, chi2/dof %.2f\n",
              label, scale_ppm, misalignment_arcsec, result.condition_number, result.chi2_per_degree_of_freedom);
  return {scale_ppm, misalignment_arcsec};
}

TEST(CalibTactical, KnownOrientationsEstimatesWithinThreeSigmaAndSigmasOnTarget) {
  const auto& r = runs();
  EXPECT_TRUE(r.known.known_orientations);
  EXPECT_EQ(r.known.rests.size(), 33u);
  EXPECT_EQ(r.known.moves.size(), 23u);
  EXPECT_LT(worst_normalised_error(r.known, r.run.truth, "known"), 3.0);
  const auto [scale_ppm, misalignment_arcsec] = largest_sigmas(r.known, "known");
  EXPECT_LE(scale_ppm, 20.0);
  EXPECT_LE(misalignment_arcsec, 10.0);
}

TEST(CalibTactical, UnknownOrientationsEstimatesInTheAccelerometerFrameWithinThreeSigma) {
  const auto& r = runs();
  EXPECT_FALSE(r.unknown.known_orientations);
  for (int fixed : {1, 2, 5}) EXPECT_FALSE(r.unknown.estimated[calib::parameter_offset::kAccelerometerK + fixed]);
  EXPECT_LT(worst_normalised_error(r.unknown, calib_test::in_accelerometer_frame(r.run.truth), "unknown"), 3.0);
  const auto [scale_ppm, misalignment_arcsec] = largest_sigmas(r.unknown, "unknown");
  EXPECT_LE(scale_ppm, 60.0);
  EXPECT_LE(misalignment_arcsec, 30.0);
}

TEST(CalibTactical, HeldOutGravitySpreadShrinksTenfoldToTheNoiseFloor) {
  const auto& r = runs();
  for (const auto* result : {&r.known, &r.unknown}) {
    const auto& g = result->held_out.gravity_m_s2;
    std::printf(
        "[held-out |g|, %s] %zu rests: raw spread %.3e, corrected %.3e, expected %.3e, noise floor (true "
        "calibration) %.3e m/s^2, mean error %.2e\n",
        result->known_orientations ? "known" : "unknown", g.rests, g.raw_spread, g.corrected_spread, g.expected_spread,
        r.noise_floor_spread_m_s2, g.corrected_mean_error);
    EXPECT_EQ(g.rests, 9u);
    EXPECT_GE(g.raw_spread / g.corrected_spread, 10.0);
    EXPECT_LT(g.corrected_spread, 2.0 * r.noise_floor_spread_m_s2);
  }
}

}  // namespace
}  // namespace imu_lab
