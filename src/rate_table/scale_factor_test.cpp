#include "imu_lab/rate_table/scale_factor_test.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <sstream>

#include "imu_lab/calib/rest_statistics.h"
#include "imu_lab/common/config_error.h"
#include "imu_lab/common/stamps.h"

namespace imu_lab {
namespace rate_table {
namespace {

constexpr double kDegPerRad = 180.0 / 3.14159265358979323846;

// Weighted least squares y = X beta, weights 1 / sigma^2.
struct WeightedFit {
  Eigen::VectorXd beta;
  Eigen::MatrixXd covariance;
  Eigen::VectorXd residuals;
  Eigen::VectorXd residual_variance;  // sigma_j^2 - x_j' Cov x_j
  double chi_squared = 0.0;
  bool full_rank = false;
};

WeightedFit weighted_fit(const Eigen::MatrixXd& design, const Eigen::VectorXd& y, const Eigen::VectorXd& sigma) {
  const Eigen::VectorXd weight = sigma.cwiseInverse();
  const Eigen::MatrixXd a = weight.asDiagonal() * design;
  WeightedFit fit;
  Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(a);
  qr.setThreshold(1e-10);
  fit.full_rank = qr.rank() == design.cols();
  if (!fit.full_rank) return fit;
  fit.beta = qr.solve(weight.asDiagonal() * y);
  fit.covariance = (a.transpose() * a).inverse();
  fit.residuals = y - design * fit.beta;
  fit.residual_variance.resize(y.size());
  for (Eigen::Index j = 0; j < y.size(); ++j) {
    fit.residual_variance[j] = sigma[j] * sigma[j] - design.row(j) * fit.covariance * design.row(j).transpose();
  }
  fit.chi_squared = fit.residuals.cwiseProduct(weight).squaredNorm();
  return fit;
}

// Columns 1, u, |u| (u = w / FS), then u^2, u^3 for the polynomial.
Eigen::MatrixXd design_matrix(const std::vector<double>& u, bool polynomial) {
  Eigen::MatrixXd design(u.size(), polynomial ? 5 : 3);
  for (std::size_t j = 0; j < u.size(); ++j) {
    design(j, 0) = 1.0;
    design(j, 1) = u[j];
    design(j, 2) = std::abs(u[j]);
    if (polynomial) {
      design(j, 3) = u[j] * u[j];
      design(j, 4) = u[j] * u[j] * u[j];
    }
  }
  return design;
}

// beta in output units per unit of u: K' = K FS, D' = D FS, c' = c FS^n.
ScaleFactorFit scale_factor_fit(const WeightedFit& fit, double full_scale_rad_s, int plateau_count) {
  ScaleFactorFit result;
  const Eigen::MatrixXd& cov = fit.covariance;
  const double k = fit.beta[1], d = fit.beta[2];
  result.bias_rad_s = {fit.beta[0], std::sqrt(cov(0, 0))};
  result.scale_factor_error_ppm = {1e6 * (k / full_scale_rad_s - 1.0), 1e6 * std::sqrt(cov(1, 1)) / full_scale_rad_s};
  // (K+ - K-) / K = 2 D' / K': delta method.
  const Eigen::Vector2d gradient(-2.0 * d / (k * k), 2.0 / k);
  result.asymmetry_ppm = {1e6 * 2.0 * d / k, 1e6 * std::sqrt(gradient.dot(cov.block<2, 2>(1, 1) * gradient))};
  if (fit.beta.size() == 5) {
    result.quadratic_ppm_fs = {1e6 * fit.beta[3] / full_scale_rad_s, 1e6 * std::sqrt(cov(3, 3)) / full_scale_rad_s};
    result.cubic_ppm_fs = {1e6 * fit.beta[4] / full_scale_rad_s, 1e6 * std::sqrt(cov(4, 4)) / full_scale_rad_s};
  }
  result.chi_squared = fit.chi_squared;
  result.degrees_of_freedom = plateau_count - static_cast<int>(fit.beta.size());
  return result;
}

std::string describe_levels(const std::vector<Plateau>& plateaus) {
  std::ostringstream text;
  for (std::size_t j = 0; j < plateaus.size(); ++j) {
    text << (j ? ", " : "") << plateaus[j].level_rad_s * kDegPerRad << " deg/s at " << plateaus[j].start_s << " s ("
         << plateaus[j].duration_s << " s)";
  }
  return plateaus.empty() ? std::string("none") : text.str();
}

std::string describe_rates(const std::vector<double>& rates_rad_s) {
  std::ostringstream text;
  for (std::size_t j = 0; j < rates_rad_s.size(); ++j) text << (j ? ", " : "") << rates_rad_s[j] * kDegPerRad;
  return text.str();
}

// Consecutive plateaus at one level (a glitch split a plateau) form one group: the group index of
// each plateau.
std::vector<std::size_t> level_groups(const std::vector<Plateau>& plateaus, double threshold_rad_s) {
  std::vector<std::size_t> group(plateaus.size(), 0);
  for (std::size_t j = 1; j < plateaus.size(); ++j) {
    const bool same = std::abs(plateaus[j].level_rad_s - plateaus[j - 1].level_rad_s) <= threshold_rad_s;
    group[j] = group[j - 1] + (same ? 0 : 1);
  }
  return group;
}

// Plateau levels against the nominal rates: a straight line must explain them within 5 % of the
// fastest rate (so a list in the wrong order, or a missed plateau, is refused).
void check_matching(const std::vector<PlateauMeasurement>& measured, const std::string& source,
                    const std::vector<Plateau>& found, const std::vector<double>& nominal) {
  Eigen::MatrixXd design(measured.size(), 2);
  Eigen::VectorXd levels(measured.size());
  double fastest = 0.0;
  for (std::size_t j = 0; j < measured.size(); ++j) {
    design(j, 0) = 1.0;
    design(j, 1) = measured[j].input_rad_s;
    levels[j] = measured[j].mean_output_rad_s;
    fastest = std::max(fastest, std::abs(measured[j].input_rad_s));
  }
  const Eigen::VectorXd line = design.colPivHouseholderQr().solve(levels);
  const double worst = (levels - design * line).cwiseAbs().maxCoeff();
  if (!(worst <= 0.05 * fastest) || !(line[1] > 0.5)) {
    throw InputError("rate-table recording: the plateaus found (" + describe_levels(found) +
                     ") do not follow the nominal rates of " + source + " (" + describe_rates(nominal) +
                     " deg/s): check the order of the rates and the mount");
  }
}

}  // namespace

ScaleFactorTestResult run_scale_factor_test(const std::vector<io::ImuRecord>& samples, const RateTableSetup& setup,
                                            const ScaleFactorTestOptions& options) {
  ScaleFactorTestResult result;
  result.setup = setup;
  result.axis = setup.tested_axis();
  result.axis_sign = setup.tested_axis_sign();
  result.earth_rate_on_axis_rad_s = setup.earth_rate_on_axis_rad_s();

  const Eigen::Vector3d axis_body = setup.axis_body();
  std::vector<double> stamps_s, table_rate_rad_s;
  for (const io::ImuRecord& sample : samples) {
    stamps_s.push_back(seconds_from_stamp_ns(sample.stamp_ns));
    table_rate_rad_s.push_back(sample.angular_rate_rad_s.dot(axis_body));
  }
  result.detection = detect_plateaus(stamps_s, table_rate_rad_s, options.plateaus);
  const std::vector<Plateau>& found = result.detection.plateaus;
  const std::vector<std::size_t> group = level_groups(found, result.detection.threshold_rad_s);
  const std::size_t group_count = found.empty() ? 0 : group.back() + 1;
  if (group_count != setup.nominal_rates_rad_s.size()) {
    throw InputError("rate-table recording: " + std::to_string(group_count) + " plateau levels found (" +
                     describe_levels(found) + ") for " + std::to_string(setup.nominal_rates_rad_s.size()) +
                     " nominal rates in " + setup.source + " (" + describe_rates(setup.nominal_rates_rad_s) +
                     " deg/s); list every plateau the table held (rates inside a dead zone read alike: two in a row "
                     "look like one), or adjust --min-plateau-s / --window-s");
  }

  std::vector<calib::StaticInterval> intervals;
  for (const Plateau& plateau : found) intervals.push_back({plateau.begin, plateau.end});
  const calib::RestStatistics statistics = calib::rest_statistics(samples, intervals, options.block_s);
  result.block_s = statistics.block_s;
  for (std::size_t j = 0; j < found.size(); ++j) {
    PlateauMeasurement measurement;
    measurement.plateau = found[j];
    measurement.nominal_rate_rad_s = setup.nominal_rates_rad_s[group[j]];
    // The tested axis lies along the table axis: it sees the table rate and the Earth rate's
    // component along that axis, both with the axis's sign.
    measurement.input_rad_s = result.axis_sign * (measurement.nominal_rate_rad_s + result.earth_rate_on_axis_rad_s);
    measurement.mean_output_rad_s = statistics.rests[j].mean_rate_rad_s[result.axis];
    measurement.sigma_of_mean_rad_s = statistics.rests[j].rate_sigma_of_mean_rad_s[result.axis];
    result.plateaus.push_back(measurement);
  }
  check_matching(result.plateaus, setup.source, found, setup.nominal_rates_rad_s);
  fit_plateau_measurements(result, options);
  return result;
}

void fit_plateau_measurements(ScaleFactorTestResult& result, const ScaleFactorTestOptions& options) {
  const std::vector<Plateau>& found = result.detection.plateaus;
  result.polynomial.reset();
  result.full_scale_rad_s = 0.0;
  result.dead_zone_found = false;
  result.dead_zone_above_rad_s = 0.0;
  result.dead_zone_below_rad_s.reset();
  for (auto& m : result.plateaus) {
    m.dead = false;
    m.line_residual_rad_s = m.polynomial_residual_rad_s = 0.0;
  }

  // Dead plateaus, judged against a straight line through the faster half of the rates (and the
  // rests), which a dead zone at the slow end cannot reach.
  std::vector<double> magnitudes;
  for (const auto& m : result.plateaus) {
    if (m.nominal_rate_rad_s != 0.0) magnitudes.push_back(std::abs(m.input_rad_s));
  }
  if (!magnitudes.empty()) {
    std::sort(magnitudes.begin(), magnitudes.end());
    const double median_magnitude = magnitudes[magnitudes.size() / 2];
    std::vector<std::size_t> reference;
    for (std::size_t j = 0; j < result.plateaus.size(); ++j) {
      const auto& m = result.plateaus[j];
      if (m.nominal_rate_rad_s == 0.0 || std::abs(m.input_rad_s) >= median_magnitude) reference.push_back(j);
    }
    Eigen::MatrixXd design(reference.size(), 2);
    Eigen::VectorXd y(reference.size());
    for (std::size_t r = 0; r < reference.size(); ++r) {
      design(r, 0) = 1.0;
      design(r, 1) = result.plateaus[reference[r]].input_rad_s;
      y[r] = result.plateaus[reference[r]].mean_output_rad_s;
    }
    const Eigen::VectorXd line = design.colPivHouseholderQr().solve(y);
    for (auto& m : result.plateaus) {
      if (m.nominal_rate_rad_s == 0.0) continue;
      const double expected = std::abs(line[1] * m.input_rad_s);
      m.dead = std::abs(m.mean_output_rad_s - line[0]) < options.dead_fraction * expected &&
               expected > options.dead_min_sigmas * m.sigma_of_mean_rad_s;
    }
  }

  double slowest = 0.0;
  for (const auto& m : result.plateaus) {
    const double magnitude = std::abs(m.input_rad_s);
    if (m.nominal_rate_rad_s != 0.0 && (slowest == 0.0 || magnitude < slowest)) slowest = magnitude;
    if (m.dead) {
      result.dead_zone_found = true;
      result.dead_zone_above_rad_s = std::max(result.dead_zone_above_rad_s, magnitude);
    }
  }
  result.slowest_nonzero_rate_rad_s = slowest;
  if (result.dead_zone_found) {
    // A rest inside the dead zone reads the bias alone, not bias + K * Earth rate.
    for (auto& m : result.plateaus) {
      if (m.nominal_rate_rad_s == 0.0 && std::abs(m.input_rad_s) <= result.dead_zone_above_rad_s) m.dead = true;
    }
    for (const auto& m : result.plateaus) {
      const double magnitude = std::abs(m.input_rad_s);
      if (!m.dead && magnitude > result.dead_zone_above_rad_s &&
          (!result.dead_zone_below_rad_s || magnitude < *result.dead_zone_below_rad_s)) {
        result.dead_zone_below_rad_s = magnitude;
      }
    }
  }

  std::vector<std::size_t> live;
  bool positive = false, negative = false;
  std::vector<double> live_magnitudes;
  for (std::size_t j = 0; j < result.plateaus.size(); ++j) {
    const auto& m = result.plateaus[j];
    if (m.dead) continue;
    live.push_back(j);
    positive = positive || m.input_rad_s > 0.0;
    negative = negative || m.input_rad_s < 0.0;
    result.full_scale_rad_s = std::max(result.full_scale_rad_s, std::abs(m.input_rad_s));
    const double magnitude = std::abs(m.nominal_rate_rad_s);
    if (magnitude > 0.0 && std::none_of(live_magnitudes.begin(), live_magnitudes.end(),
                                        [&](double seen) { return std::abs(seen - magnitude) <= 1e-12 * magnitude; })) {
      live_magnitudes.push_back(magnitude);
    }
  }
  if (live.size() < 4 || !positive || !negative) {
    throw InputError("rate-table recording: " + std::to_string(live.size()) +
                     " responding plateaus; the straight lines need at least four, in both directions (found " +
                     describe_levels(found) + ")");
  }
  std::vector<double> u;
  Eigen::VectorXd y(live.size()), sigma(live.size());
  for (std::size_t r = 0; r < live.size(); ++r) {
    const auto& m = result.plateaus[live[r]];
    u.push_back(m.input_rad_s / result.full_scale_rad_s);
    y[r] = m.mean_output_rad_s;
    sigma[r] = m.sigma_of_mean_rad_s;
  }
  if (!(sigma.minCoeff() > 0.0)) {
    throw InputError(
        "rate-table recording: a plateau mean has no measurable noise (constant output); "
        "its sigma, and the fit's, would be zero");
  }
  const WeightedFit line = weighted_fit(design_matrix(u, false), y, sigma);
  if (!line.full_rank) throw InputError("rate-table recording: the plateau rates do not determine the straight lines");
  result.line = scale_factor_fit(line, result.full_scale_rad_s, static_cast<int>(live.size()));
  Eigen::Index worst = 0;
  line.residuals.cwiseAbs().maxCoeff(&worst);
  const double full_scale_output = line.beta[1];  // K FS
  result.nonlinearity_ppm_fs = {1e6 * std::abs(line.residuals[worst]) / full_scale_output,
                                1e6 * std::sqrt(std::max(0.0, line.residual_variance[worst])) / full_scale_output};
  for (std::size_t r = 0; r < live.size(); ++r) result.plateaus[live[r]].line_residual_rad_s = line.residuals[r];

  if (live.size() >= 6 && live_magnitudes.size() >= 3) {
    const WeightedFit polynomial = weighted_fit(design_matrix(u, true), y, sigma);
    if (polynomial.full_rank) {
      result.polynomial = scale_factor_fit(polynomial, result.full_scale_rad_s, static_cast<int>(live.size()));
      for (std::size_t r = 0; r < live.size(); ++r) {
        result.plateaus[live[r]].polynomial_residual_rad_s = polynomial.residuals[r];
      }
    }
  }
}

}  // namespace rate_table
}  // namespace imu_lab
