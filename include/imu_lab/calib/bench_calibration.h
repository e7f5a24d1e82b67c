// Bench calibration of both triads (Golovach 2017 section 3.3 and chapter 5) from one recording in
// which the IMU rests in several orientations and turns between them.
//
// Mode 1, known orientations (a table schedule): accelerometers from gravity (WGS-84 normal gravity
// at the site), gyros from the rotations between rests (the corrected rates integrated over each
// move must equal the schedule's rotation plus the Earth's turn meanwhile) and from Earth rate in
// the rests. Earth rate alone pins a gyro scale factor only to about (rate noise of a rest mean) /
// (Earth rate), ~1e-4 for a navigation-grade gyro in a minute: the moves do the rest.
// Mode 2, unknown orientations (a hand-turned IMU): every rest's attitude is a further unknown.
// |g| is invariant, so the accelerometers are fitted in their own frame: body x along the
// accelerometer x axis, the accelerometer y axis in the body xy plane, i.e. K_accelerometer is
// lower triangular (K(0,1) = K(0,2) = K(1,2) = 0). The gyros' K (full) and the rests' attitudes
// follow from integrating between rests; the heading of the rests only from Earth rate.
// Both modes are one Ceres problem: static residuals (6 per rest) and move residuals (3 per move).
// Rests listed in held_out_positions are left out of the fit and used for the thesis's check:
// the spread of |g| and |Earth rate| over them, before and after correction.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "imu_lab/calib/calibration_parameters.h"
#include "imu_lab/calib/calibration_schedule.h"
#include "imu_lab/calib/held_out_check.h"
#include "imu_lab/calib/imu_calibration.h"
#include "imu_lab/calib/rest_statistics.h"
#include "imu_lab/calib/static_intervals.h"

namespace imu_lab {
namespace calib {

struct CalibrationOptions {
  std::optional<TableSchedule> schedule;        // mode 1 when given
  CalibrationSite site;                         // mode 2 (mode 1 takes the schedule's)
  std::vector<std::size_t> held_out_positions;  // rest indices (0-based, time order)
  bool estimate_g_sensitivity = false;
  StaticDetectionOptions static_detection;
  double noise_block_s = 0.5;
  double heading_prior_sigma_rad = 1.0;  // mode 2 only, see HeadingPrior
};

// Minimum rests used for fitting: mode 1 (3 equations per rest for 12 accelerometer parameters)
// and mode 2 (one |g| equation per rest for 9).
constexpr std::size_t kMinimumKnownRests = 4;
constexpr std::size_t kMinimumUnknownRests = 9;

struct RestReport {
  RestMeans means;
  bool held_out = false;
  Eigen::Vector3d force_residual_m_s2 = Eigen::Vector3d::Zero();  // measured - model (fitted rests)
  Eigen::Vector3d rate_residual_rad_s = Eigen::Vector3d::Zero();
  Eigen::Quaterniond attitude_body_to_enu = Eigen::Quaterniond::Identity();  // given or estimated
};

struct MoveReport {
  std::size_t from = 0, to = 0;  // rest indices
  double duration_s = 0.0;
  double angle_rad = 0.0;
  Eigen::Vector3d angle_residual_rad = Eigen::Vector3d::Zero();
};

struct CalibrationResult {
  ImuCalibration calibration;
  ParameterVector values = ParameterVector::Zero();
  ParameterVector sigmas = ParameterVector::Zero();
  ParameterCovariance covariance = ParameterCovariance::Zero();
  std::array<bool, kParameterCount> estimated{};  // false: fixed (frame convention, G not fitted)
  bool known_orientations = true;
  std::string frame_convention;
  double condition_number = 0.0;
  double chi2_per_degree_of_freedom = 0.0;
  std::size_t residual_count = 0;
  std::size_t free_parameter_count = 0;
  StaticDetection detection;
  RestStatistics noise;
  std::vector<RestReport> rests;
  std::vector<MoveReport> moves;
  HeldOutCheck held_out;
  std::string solver_report;
  std::vector<std::string> warnings;  // chi2/dof far above 1 (common/fit_quality.h)
};

// Throws InputError with what is wrong and what to do: no or too few rests (with the number still
// needed), rests not matching the schedule, a schedule or motion that leaves parameters
// unobservable (named), a solver failure.
CalibrationResult calibrate(const std::vector<io::ImuRecord>& samples, const CalibrationOptions& options);

}  // namespace calib
}  // namespace imu_lab
