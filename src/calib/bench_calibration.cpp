#include "imu_lab/calib/bench_calibration.h"

#include <ceres/ceres.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <sstream>

#include "calibration_residuals.h"
#include "imu_lab/calib/observability.h"
#include "imu_lab/common/ceres_solver_options.h"
#include "imu_lab/common/config_error.h"
#include "imu_lab/common/fit_quality.h"
#include "imu_lab/common/stamps.h"

namespace imu_lab {
namespace calib {
namespace {

constexpr const char* kKnownFrame = "the schedule's body frame (the table's)";
constexpr const char* kAccelerometerFrame =
    "accelerometer frame: body x along the accelerometer x axis, accelerometer y axis in the body xy plane "
    "(K_accelerometer lower triangular)";
// K_accelerometer elements fixed at zero by the mode-2 frame convention (row-major indices).
const std::vector<int> kUpperTriangle = {1, 2, 5};

Eigen::Quaterniond exp_rotation(const Eigen::Vector3d& rotation_vector) {
  const double angle = rotation_vector.norm();
  if (angle == 0.0) return Eigen::Quaterniond::Identity();
  return Eigen::Quaterniond(Eigen::AngleAxisd(angle, rotation_vector / angle));
}

// The parameters Ceres moves, with the starting point K = I, everything else zero.
struct ParameterBlocks {
  double accelerometer_bias[3] = {0, 0, 0};
  double accelerometer_k[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
  double gyro_bias[3] = {0, 0, 0};
  double gyro_k[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
  double gyro_g_sensitivity[9] = {0, 0, 0, 0, 0, 0, 0, 0, 0};
  std::vector<std::array<double, 3>> rest_deltas;

  ParameterVector values() const {
    ParameterVector v;
    std::copy(accelerometer_bias, accelerometer_bias + 3, v.data() + parameter_offset::kAccelerometerBias);
    std::copy(accelerometer_k, accelerometer_k + 9, v.data() + parameter_offset::kAccelerometerK);
    std::copy(gyro_bias, gyro_bias + 3, v.data() + parameter_offset::kGyroBias);
    std::copy(gyro_k, gyro_k + 9, v.data() + parameter_offset::kGyroK);
    std::copy(gyro_g_sensitivity, gyro_g_sensitivity + 9, v.data() + parameter_offset::kGyroGSensitivity);
    return v;
  }
};

// One column block of the Jacobian: where it lives and which calibration parameters it holds
// (-1 for a rest's attitude, a nuisance parameter).
struct FreeBlock {
  double* data;
  std::vector<int> parameter_index;
  std::vector<std::string> names;
};

void require_enough_rests(std::size_t fitted, std::size_t held_out, bool known_orientations,
                          const StaticDetection& detection, const StaticDetectionOptions& detection_options) {
  const std::size_t minimum = known_orientations ? kMinimumKnownRests : kMinimumUnknownRests;
  if (fitted == 0 && held_out == 0) {
    std::ostringstream message;
    message
        << "no static intervals found (window " << detection.window_s << " s, threshold " << detection.threshold_rad_s
        << " rad/s = " << detection.threshold_rad_s * kDegPerRad
        << " deg/s over the resting level, from a window noise of " << detection.window_noise_rad_s
        << " rad/s; resting level " << detection.resting_level_rad_s.norm() << " rad/s, at most "
        << detection_options.max_resting_rate_rad_s
        << " rad/s for a rest): the IMU must rest still in each orientation for at least the minimum rest duration; "
           "raise the threshold or lower the minimum duration if it did";
    throw InputError(message.str());
  }
  if (fitted < minimum) {
    std::ostringstream message;
    message << "too few rests to fit: " << fitted << " static positions used for fitting (" << held_out
            << " held out); calibrating with " << (known_orientations ? "known" : "unknown")
            << " orientations needs at least " << minimum << ": record " << (minimum - fitted) << " more position"
            << (minimum - fitted == 1 ? "" : "s");
    throw InputError(message.str());
  }
}

// Mode 2 start: the first rest levelled with heading 0, each next one carried over by the raw
// gyro integrated across the move, then levelled again by its own gravity direction.
std::vector<Eigen::Quaterniond> starting_attitudes(const std::vector<io::ImuRecord>& samples,
                                                   const std::vector<RestMeans>& rests) {
  const Eigen::Vector3d up = Eigen::Vector3d::UnitZ();
  const auto level = [&](const Eigen::Quaterniond& guess, const Eigen::Vector3d& force_body) {
    return (Eigen::Quaterniond::FromTwoVectors(guess * force_body, up) * guess).normalized();
  };
  std::vector<Eigen::Quaterniond> attitudes;
  attitudes.push_back(level(Eigen::Quaterniond::Identity(), rests[0].mean_force_m_s2));
  for (std::size_t r = 1; r < rests.size(); ++r) {
    Eigen::Quaterniond turned = attitudes.back();
    for (std::size_t k = rests[r - 1].interval.end; k < rests[r].interval.begin; ++k) {
      turned = turned * exp_rotation(samples[k].angular_rate_rad_s *
                                     seconds_between(samples[k - 1].stamp_ns, samples[k].stamp_ns));
    }
    attitudes.push_back(level(turned, rests[r].mean_force_m_s2));
  }
  return attitudes;
}

Eigen::MatrixXd weighted_jacobian(ceres::Problem& problem, const std::vector<FreeBlock>& blocks) {
  ceres::Problem::EvaluateOptions options;
  for (const FreeBlock& block : blocks) options.parameter_blocks.push_back(block.data);
  double cost = 0.0;
  ceres::CRSMatrix sparse;
  problem.Evaluate(options, &cost, nullptr, nullptr, &sparse);
  Eigen::MatrixXd dense = Eigen::MatrixXd::Zero(sparse.num_rows, sparse.num_cols);
  for (int row = 0; row < sparse.num_rows; ++row) {
    for (int k = sparse.rows[row]; k < sparse.rows[row + 1]; ++k) dense(row, sparse.cols[k]) = sparse.values[k];
  }
  return dense;
}

std::string describe_unobservable(const std::vector<std::vector<std::string>>& directions) {
  std::ostringstream message;
  message << "the rests and moves cannot observe " << directions.size() << " parameter combination"
          << (directions.size() == 1 ? "" : "s") << ":";
  for (const auto& names : directions) {
    message << " [";
    for (std::size_t k = 0; k < names.size(); ++k) message << (k ? ", " : "") << names[k];
    message << "]";
  }
  message << "; add orientations that tilt the named axes against gravity (accelerometers) or turns about "
             "them (gyros), or fit fewer parameters";
  return message.str();
}

}  // namespace

CalibrationResult calibrate(const std::vector<io::ImuRecord>& samples, const CalibrationOptions& options) {
  CalibrationResult result;
  result.known_orientations = options.schedule.has_value();
  const bool known = result.known_orientations;
  const CalibrationSite site = known ? options.schedule->site : options.site;
  result.frame_convention = known ? kKnownFrame : kAccelerometerFrame;

  result.detection = detect_static_intervals(samples, options.static_detection);
  const std::size_t rest_count = result.detection.intervals.size();
  std::vector<bool> held_out(rest_count, false);
  for (std::size_t index : options.held_out_positions) {
    if (index >= rest_count) {
      throw InputError("held-out position " + std::to_string(index + 1) +
                       " does not exist: " + std::to_string(rest_count) + " static intervals were found");
    }
    held_out[index] = true;
  }
  const std::size_t held_out_count = std::count(held_out.begin(), held_out.end(), true);
  require_enough_rests(rest_count - held_out_count, held_out_count, known, result.detection, options.static_detection);
  if (known && options.schedule->attitudes_body_to_enu.size() != rest_count) {
    std::ostringstream message;
    message << "found " << rest_count << " static intervals but the schedule " << options.schedule->source << " has "
            << options.schedule->attitudes_body_to_enu.size() << " positions (window " << result.detection.window_s
            << " s, threshold " << result.detection.threshold_rad_s
            << " rad/s): check that the bag and the schedule belong together, or adjust the static threshold "
               "or the minimum rest duration";
    throw InputError(message.str());
  }
  result.noise = rest_statistics(samples, result.detection.intervals, options.noise_block_s);
  const std::vector<RestMeans>& rests = result.noise.rests;
  const std::vector<Eigen::Quaterniond> nominal =
      known ? options.schedule->attitudes_body_to_enu : starting_attitudes(samples, rests);

  ParameterBlocks blocks;
  blocks.rest_deltas.assign(rest_count, {0.0, 0.0, 0.0});
  ceres::Problem problem;
  problem.AddParameterBlock(blocks.accelerometer_bias, 3);
  problem.AddParameterBlock(blocks.accelerometer_k, 9);
  problem.AddParameterBlock(blocks.gyro_bias, 3);
  problem.AddParameterBlock(blocks.gyro_k, 9);
  problem.AddParameterBlock(blocks.gyro_g_sensitivity, 9);
  if (!known) problem.SetManifold(blocks.accelerometer_k, new ceres::SubsetManifold(9, kUpperTriangle));
  if (!options.estimate_g_sensitivity) problem.SetParameterBlockConstant(blocks.gyro_g_sensitivity);

  const double gravity = site.gravity_m_s2();
  const Eigen::Vector3d earth_rate = site.earth_rate_enu_rad_s();
  std::vector<std::size_t> fitted;
  for (std::size_t r = 0; r < rest_count; ++r) {
    if (held_out[r]) continue;
    fitted.push_back(r);
    auto* residual = new residuals::RestResidual{nominal[r],
                                                 rests[r].mean_force_m_s2,
                                                 rests[r].mean_rate_rad_s,
                                                 rests[r].force_sigma_of_mean_m_s2,
                                                 rests[r].rate_sigma_of_mean_rad_s,
                                                 gravity,
                                                 earth_rate};
    problem.AddResidualBlock(new ceres::AutoDiffCostFunction<residuals::RestResidual, 6, 3, 9, 3, 9, 9, 3>(residual),
                             nullptr, blocks.accelerometer_bias, blocks.accelerometer_k, blocks.gyro_bias,
                             blocks.gyro_k, blocks.gyro_g_sensitivity, blocks.rest_deltas[r].data());
    if (known) problem.SetParameterBlockConstant(blocks.rest_deltas[r].data());
  }
  std::vector<residuals::MoveResidual> move_residuals;
  for (std::size_t m = 1; m < fitted.size(); ++m) {
    const RestMeans& from = rests[fitted[m - 1]];
    const RestMeans& to = rests[fitted[m]];
    residuals::MoveResidual move;
    move.samples = &samples;
    move.first = from.interval.end;
    move.last = to.interval.begin;
    move.nominal_from = nominal[fitted[m - 1]];
    move.nominal_to = nominal[fitted[m]];
    const double duration_s = seconds_between(samples[move.first - 1].stamp_ns, samples[move.last - 1].stamp_ns);
    move.earth_turn = exp_rotation(earth_rate * duration_s);
    // Rate noise integrated over the move: white density^2 * duration (per axis).
    move.angle_sigma_rad = result.noise.rate_density_rad_s_per_sqrt_hz * std::sqrt(duration_s);
    move.g_sensitivity = options.estimate_g_sensitivity;
    move_residuals.push_back(move);
    problem.AddResidualBlock(new ceres::AutoDiffCostFunction<residuals::MoveResidual, 3, 3, 9, 3, 9, 9, 3, 3>(
                                 new residuals::MoveResidual(move)),
                             nullptr, blocks.accelerometer_bias, blocks.accelerometer_k, blocks.gyro_bias,
                             blocks.gyro_k, blocks.gyro_g_sensitivity, blocks.rest_deltas[fitted[m - 1]].data(),
                             blocks.rest_deltas[fitted[m]].data());
  }
  if (!known) {
    auto* prior = new residuals::HeadingPrior{nominal[fitted[0]].conjugate() * Eigen::Vector3d::UnitZ(),
                                              options.heading_prior_sigma_rad};
    problem.AddResidualBlock(new ceres::AutoDiffCostFunction<residuals::HeadingPrior, 1, 3>(prior), nullptr,
                             blocks.rest_deltas[fitted[0]].data());
  }

  // The Jacobian's columns: the calibration parameters that move, then (mode 2) the rests' attitudes.
  std::vector<FreeBlock> free_blocks;
  const auto add_block = [&](double* data, int offset, int size, const std::vector<int>& fixed) {
    FreeBlock block{data, {}, {}};
    for (int k = 0; k < size; ++k) {
      if (std::find(fixed.begin(), fixed.end(), k) != fixed.end()) continue;
      block.parameter_index.push_back(offset + k);
      block.names.push_back(parameter_name(offset + k));
    }
    free_blocks.push_back(block);
  };
  add_block(blocks.accelerometer_bias, parameter_offset::kAccelerometerBias, 3, {});
  add_block(blocks.accelerometer_k, parameter_offset::kAccelerometerK, 9, known ? std::vector<int>{} : kUpperTriangle);
  add_block(blocks.gyro_bias, parameter_offset::kGyroBias, 3, {});
  add_block(blocks.gyro_k, parameter_offset::kGyroK, 9, {});
  if (options.estimate_g_sensitivity) add_block(blocks.gyro_g_sensitivity, parameter_offset::kGyroGSensitivity, 9, {});
  if (!known) {
    for (std::size_t r : fitted) {
      FreeBlock block{blocks.rest_deltas[r].data(), {-1, -1, -1}, {}};
      for (const char* axis : {"x", "y", "z"}) {
        block.names.push_back("attitude of rest " + std::to_string(r + 1) + " about " + axis);
      }
      free_blocks.push_back(block);
    }
  }
  std::vector<std::string> column_names;
  std::vector<int> column_parameter;
  for (const FreeBlock& block : free_blocks) {
    column_names.insert(column_names.end(), block.names.begin(), block.names.end());
    column_parameter.insert(column_parameter.end(), block.parameter_index.begin(), block.parameter_index.end());
  }

  const Observability before = analyse_observability(weighted_jacobian(problem, free_blocks), column_names);
  if (!before.unobservable.empty()) throw InputError(describe_unobservable(before.unobservable));

  const ceres::Solver::Options solver_options = small_fit_solver_options({100, 1e-14, 1e-14, 1e-12});
  ceres::Solver::Summary summary;
  ceres::Solve(solver_options, &problem, &summary);
  result.solver_report = summary.BriefReport();
  if (!summary.IsSolutionUsable()) throw InputError("calibration: the solver failed: " + summary.message);

  const Eigen::MatrixXd jacobian = weighted_jacobian(problem, free_blocks);
  const Observability after = analyse_observability(jacobian, column_names);
  if (!after.unobservable.empty()) throw InputError(describe_unobservable(after.unobservable));
  result.residual_count = jacobian.rows();
  result.free_parameter_count = jacobian.cols();
  const double degrees_of_freedom = std::max<double>(1.0, result.residual_count - result.free_parameter_count);
  result.chi2_per_degree_of_freedom = 2.0 * summary.final_cost / degrees_of_freedom;
  result.condition_number = after.condition_number;
  for (std::size_t a = 0; a < column_parameter.size(); ++a) {
    if (column_parameter[a] < 0) continue;
    result.estimated[column_parameter[a]] = true;
    for (std::size_t b = 0; b < column_parameter.size(); ++b) {
      if (column_parameter[b] < 0) continue;
      result.covariance(column_parameter[a], column_parameter[b]) =
          after.covariance(a, b) * result.chi2_per_degree_of_freedom;
    }
  }
  result.values = blocks.values();
  result.sigmas = result.covariance.diagonal().cwiseMax(0.0).cwiseSqrt();
  result.calibration = from_parameter_vector(result.values);

  // Per-rest and per-move residuals in physical units (the residual functors, unweighted).
  std::vector<RestMeans> held_out_rests;
  for (std::size_t r = 0; r < rest_count; ++r) {
    RestReport report;
    report.means = rests[r];
    report.held_out = held_out[r];
    report.attitude_body_to_enu = nominal[r] * exp_rotation(Eigen::Vector3d(blocks.rest_deltas[r].data()));
    if (held_out[r]) {
      held_out_rests.push_back(rests[r]);
    } else {
      const residuals::RestResidual unweighted{nominal[r],
                                               rests[r].mean_force_m_s2,
                                               rests[r].mean_rate_rad_s,
                                               Eigen::Vector3d::Ones(),
                                               Eigen::Vector3d::Ones(),
                                               gravity,
                                               earth_rate};
      double residual[6];
      unweighted(blocks.accelerometer_bias, blocks.accelerometer_k, blocks.gyro_bias, blocks.gyro_k,
                 blocks.gyro_g_sensitivity, blocks.rest_deltas[r].data(), residual);
      report.force_residual_m_s2 = Eigen::Vector3d(residual[0], residual[1], residual[2]);
      report.rate_residual_rad_s = Eigen::Vector3d(residual[3], residual[4], residual[5]);
    }
    result.rests.push_back(report);
  }
  for (std::size_t m = 0; m < move_residuals.size(); ++m) {
    residuals::MoveResidual unweighted = move_residuals[m];
    unweighted.angle_sigma_rad = Eigen::Vector3d::Ones();
    MoveReport report;
    report.from = fitted[m];
    report.to = fitted[m + 1];
    report.duration_s = seconds_between(samples[unweighted.first - 1].stamp_ns, samples[unweighted.last - 1].stamp_ns);
    report.angle_rad =
        result.rests[report.from].attitude_body_to_enu.angularDistance(result.rests[report.to].attitude_body_to_enu);
    unweighted(blocks.accelerometer_bias, blocks.accelerometer_k, blocks.gyro_bias, blocks.gyro_k,
               blocks.gyro_g_sensitivity, blocks.rest_deltas[report.from].data(), blocks.rest_deltas[report.to].data(),
               report.angle_residual_rad.data());
    result.moves.push_back(report);
  }
  result.held_out = held_out_check(held_out_rests, result.calibration, result.covariance, site);
  const std::string warning = chi2_warning(
      "the calibration fit", result.chi2_per_degree_of_freedom,
      result.known_orientations
          ? "is the schedule the one the IMU followed (its orientations and site), and was it still in the rests?"
          : "are the latitude and height the site's (gravity and the Earth rate are the reference), and was the IMU "
            "still in the rests?");
  if (!warning.empty()) result.warnings.push_back(warning);
  return result;
}

}  // namespace calib
}  // namespace imu_lab
