#include "imu_lab/identify/record_length.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <limits>

#include "imu_lab/identify/avar_covariance.h"
#include "imu_lab/identify/fit_points.h"
#include "imu_lab/identify/fit_problem.h"

namespace imu_lab {
namespace identify {

namespace {

// The fit's spacing of averaging factors (fit_points.h) over what a record of sample_count
// samples can evaluate.
std::vector<FitPoint> hypothetical_points(const NoiseModel& model, double tau0_s, long long sample_count) {
  std::vector<FitPoint> points;
  // Averaging factors are ints (allan::StabilityPoint): a record longer than 2^31 samples is
  // evaluated up to that factor.
  constexpr double kLargestFactor = 1e9;
  for (double factor = 1.0; 2.0 * std::round(factor) <= sample_count - 1 && factor <= kLargestFactor;
       factor *= kFitPointRatio) {
    const int m = static_cast<int>(std::round(factor));
    if (!points.empty() && m == points.back().averaging_factor) continue;
    points.push_back({m * tau0_s, m, model_avar(model, m * tau0_s)});
  }
  return points;
}

}  // namespace

Eigen::MatrixXd predicted_log_covariance(const ModelStructure& structure, const std::vector<double>& log_parameters,
                                         double tau0_s, double record_length_s) {
  const NoiseModel model = model_from_log_parameters(structure, log_parameters);
  const long long sample_count = std::llround(record_length_s / tau0_s);
  const std::vector<FitPoint> points = hypothetical_points(model, tau0_s, sample_count);
  if (points.size() < 2) return Eigen::MatrixXd();
  OavarCovariance covariance(averaging_factors(points), tau0_s, sample_count);
  const MomentWeights weights = moment_weights(points, model, covariance, 0.0);
  const Eigen::MatrixXd result = log_parameter_covariance(points, structure, log_parameters, weights);
  return result.allFinite() ? result : Eigen::MatrixXd();
}

double predicted_relative_sigma(const ModelStructure& structure, const std::vector<double>& log_parameters,
                                int parameter_index, double tau0_s, double record_length_s) {
  const Eigen::MatrixXd covariance = predicted_log_covariance(structure, log_parameters, tau0_s, record_length_s);
  if (covariance.size() == 0 || !(covariance(parameter_index, parameter_index) >= 0.0)) {
    return std::numeric_limits<double>::infinity();
  }
  return std::sqrt(covariance(parameter_index, parameter_index));
}

double required_record_length_s(const ModelStructure& structure, const std::vector<double>& log_parameters,
                                int parameter_index, double tau0_s, double current_length_s,
                                double target_relative_sigma) {
  const auto sigma_at = [&](double length_s) {
    return predicted_relative_sigma(structure, log_parameters, parameter_index, tau0_s, length_s);
  };
  double low = std::log(100.0 * tau0_s);
  double high = std::log(1e4 * current_length_s);
  if (sigma_at(std::exp(high)) > target_relative_sigma) {
    return std::numeric_limits<double>::infinity();
  }
  if (sigma_at(std::exp(low)) <= target_relative_sigma) return std::exp(low);
  for (int iteration = 0; iteration < 20; ++iteration) {  // 2^-20 of a factor 1e6 range: 0.001 %
    const double middle = 0.5 * (low + high);
    if (sigma_at(std::exp(middle)) > target_relative_sigma) {
      low = middle;
    } else {
      high = middle;
    }
  }
  return std::exp(high);
}

double required_record_length_s(const FitResult& fit, const std::string& term_name, double target_relative_sigma) {
  const TermEstimate* term = fit.find(term_name);
  if (term == nullptr) {
    throw std::invalid_argument("required_record_length_s: no term '" + term_name + "'");
  }
  const auto position =
      std::find_if(fit.terms.begin(), fit.terms.end(), [&](const TermEstimate& t) { return t.name == term_name; });
  const int slot = static_cast<int>(position - fit.terms.begin());
  if (slot >= static_cast<int>(fit.structure.slots.size())) {
    return std::numeric_limits<double>::infinity();
  }
  const int index = parameter_offset(fit.structure, slot);
  const double predicted =
      predicted_relative_sigma(fit.structure, fit.log_parameters, index, fit.tau0_s, fit.record_length_s);
  const double reported = term->amplitude.log_sigma;
  const double inflation = (std::isfinite(reported) && predicted > 0.0) ? std::max(1.0, reported / predicted) : 1.0;
  return required_record_length_s(fit.structure, fit.log_parameters, index, fit.tau0_s, fit.record_length_s,
                                  target_relative_sigma / inflation);
}

}  // namespace identify
}  // namespace imu_lab
