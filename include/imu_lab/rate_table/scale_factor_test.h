// Rate-table scale-factor test of the gyro axis along the table axis (IEEE Std 952 / 528 terms;
// Krobka 2015 eq. 1.1: error = bias + scale-factor error * rate + nonlinear part):
//   1. plateaus found automatically (plateaus.h) on the rate about the table axis, matched in
//      order to the nominal rates (consecutive plateaus at one level, split by a glitch, share one);
//   2. per plateau the mean output and its sigma (calib::rest_statistics: scatter of block means,
//      pooled over the plateaus), and the input w = s (nominal + Earth rate along the table axis),
//      s = +-1 the tested axis's direction on the table axis;
//   3. plateaus whose output stays within half the expected response of the bias although the
//      response would stand far above the noise are dead (dead zone), kept out of the fits, and
//      bracket the dead zone: above the fastest dead |w|, below the slowest live one beyond it;
//   4. weighted least squares, sigmas from the plateau sigmas (not rescaled by chi-squared; the
//      chi-squared is reported as the check of the model):
//      straight lines  y = b + K w + D |w|   (K+ = K + D, K- = K - D): scale-factor error K - 1,
//        asymmetry (K+ - K-) / K, and nonlinearity = the largest residual of these lines in ppm
//        of the full-scale output K FS (FS = the largest |w| tested), its sigma that residual's;
//      polynomial      y = b + K w + D |w| + c2 w^2 + c3 w^3: the same with the quadratic and cubic
//        terms apart, in ppm of full scale at full scale (1e6 c2 FS, 1e6 c3 FS^2), when at least
//        three rate magnitudes and six live plateaus allow it.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "imu_lab/io/imu_records.h"
#include "imu_lab/rate_table/plateaus.h"
#include "imu_lab/rate_table/rate_table_setup.h"

namespace imu_lab {
namespace rate_table {

struct ScaleFactorTestOptions {
  PlateauOptions plateaus;
  double block_s = 1.0;           // block means for the noise of a plateau mean
  double dead_fraction = 0.5;     // dead: |output - bias| < this fraction of the expected response
  double dead_min_sigmas = 10.0;  // ... and the expected response exceeds this many sigmas
};

struct Estimate {
  double value = 0.0;
  double sigma = 0.0;
};

struct PlateauMeasurement {
  Plateau plateau;
  double nominal_rate_rad_s = 0.0;
  double input_rad_s = 0.0;  // on the tested axis, Earth rate included
  double mean_output_rad_s = 0.0;
  double sigma_of_mean_rad_s = 0.0;
  bool dead = false;
  double line_residual_rad_s = 0.0;        // of the straight-line fit (0 for dead plateaus)
  double polynomial_residual_rad_s = 0.0;  // of the polynomial fit, when there is one
};

struct ScaleFactorFit {
  Estimate bias_rad_s;
  Estimate scale_factor_error_ppm;  // (K - 1) 1e6
  Estimate asymmetry_ppm;           // (K+ - K-) / K 1e6
  Estimate quadratic_ppm_fs;        // polynomial fit only
  Estimate cubic_ppm_fs;            // polynomial fit only
  double chi_squared = 0.0;
  int degrees_of_freedom = 0;
};

struct ScaleFactorTestResult {
  RateTableSetup setup;
  PlateauDetection detection;
  double block_s = 0.0;
  int axis = 0;  // 0 x, 1 y, 2 z
  double axis_sign = 1.0;
  double earth_rate_on_axis_rad_s = 0.0;
  double full_scale_rad_s = 0.0;  // largest |input| tested
  std::vector<PlateauMeasurement> plateaus;
  ScaleFactorFit line;
  Estimate nonlinearity_ppm_fs;  // largest |line residual| / (K FS)
  std::optional<ScaleFactorFit> polynomial;
  // Dead zone bracket in |input|: none found (then it is below the slowest nonzero rate, if any).
  bool dead_zone_found = false;
  double dead_zone_above_rad_s = 0.0;           // fastest dead |w|
  std::optional<double> dead_zone_below_rad_s;  // slowest live |w| beyond it
  double slowest_nonzero_rate_rad_s = 0.0;
};

// Throws InputError (the plateaus found do not match the nominal rates, too few live plateaus,
// no plateau in one direction) with the levels found, so the user can fix the rates or options.
ScaleFactorTestResult run_scale_factor_test(const std::vector<io::ImuRecord>& samples, const RateTableSetup& setup,
                                            const ScaleFactorTestOptions& options);

// Steps 3 and 4 on result.plateaus as they stand (inputs, mean outputs, sigmas): what
// run_scale_factor_test ends with. Exposed so the same estimator can be applied to other plateau
// means, e.g. an error-free sensor's, which gives the exact value of every statistic.
void fit_plateau_measurements(ScaleFactorTestResult& result, const ScaleFactorTestOptions& options);

}  // namespace rate_table
}  // namespace imu_lab
