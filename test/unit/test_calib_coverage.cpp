// The reported sigmas mean what they say: over repeated emulated runs (different seeds) of the
// 6-position scheme in mode 1, the errors divided by their sigmas have unit RMS and about 95 %
// of them lie within 2 sigma.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "calib_test_support.h"

namespace imu_lab {
namespace {

TEST(CalibCoverage, NormalisedErrorsHaveUnitSpreadOverSeeds) {
  calib_test::TableRun table;
  table.dwell_s = 4.0;
  table.rate_hz = 100.0;
  table.move_rate_deg_s = 200.0;
  table.move_acceleration_deg_s2 = 1000.0;
  const auto profile = calib_test::tactical_test_profile();
  const auto positions = calib_test::shipped_positions("multiposition_12_thesis.yaml");
  std::vector<double> normalised;
  for (std::uint64_t seed = 1; seed <= 16; ++seed) {
    table.seed = seed;
    const auto run = calib_test::emulate_table_run(profile, positions, table);
    calib::CalibrationOptions options;
    options.schedule = run.schedule;
    const auto result = calib::calibrate(run.samples, options);
    const calib::ParameterVector truth = calib::to_parameter_vector(run.truth);
    for (int k = 0; k < calib::kParameterCount; ++k) {
      if (result.estimated[k]) normalised.push_back((result.values[k] - truth[k]) / result.sigmas[k]);
    }
  }
  double sum_squares = 0.0;
  std::size_t inside_two_sigma = 0;
  for (double z : normalised) {
    sum_squares += z * z;
    if (std::abs(z) < 2.0) ++inside_two_sigma;
  }
  const double rms = std::sqrt(sum_squares / normalised.size());
  const double fraction = static_cast<double>(inside_two_sigma) / normalised.size();
  std::printf("[coverage] %zu normalised errors: RMS %.3f, within 2 sigma %.3f\n", normalised.size(), rms, fraction);
  EXPECT_GT(rms, 0.8);
  EXPECT_LT(rms, 1.25);
  EXPECT_GT(fraction, 0.90);
}

}  // namespace
}  // namespace imu_lab
