// The thesis's check of a calibration (Golovach 2017 section 5.4-5.5), on rests the fit did not use:
// the magnitudes |g| and |Earth rate| do not depend on the orientation, so their spread over the
// rests, after correction, shows what the calibration left (the thesis: 3e-4 m/s^2 and
// 0.001 deg/h measured, 0.015 deg/h allowed, for its ring-laser system).
#pragma once

#include <cstddef>
#include <vector>

#include "imu_lab/calib/calibration_parameters.h"
#include "imu_lab/calib/calibration_schedule.h"
#include "imu_lab/calib/imu_calibration.h"
#include "imu_lab/calib/rest_statistics.h"

namespace imu_lab {
namespace calib {

// Spread = sample standard deviation over the rests of a vector invariant's magnitude.
struct InvariantSpread {
  std::size_t rests = 0;
  double reference = 0.0;             // g or Earth rate at the site
  double raw_spread = 0.0;            // of |mean output|
  double corrected_spread = 0.0;      // of |corrected mean|
  double corrected_mean_error = 0.0;  // mean |corrected| - reference
  // What the spread should be after a correct calibration: the rests' own noise along the
  // invariant's direction and the parameters' covariance, in quadrature.
  double expected_spread = 0.0;
};

struct HeldOutCheck {
  InvariantSpread gravity_m_s2;
  InvariantSpread earth_rate_rad_s;
};

HeldOutCheck held_out_check(const std::vector<RestMeans>& rests, const ImuCalibration& calibration,
                            const ParameterCovariance& covariance, const CalibrationSite& site);

}  // namespace calib
}  // namespace imu_lab
