#include "imu_lab/identify/record_length.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <limits>

#include "imu_lab/allan/edf.h"
#include "imu_lab/identify/fit_points.h"

namespace imu_lab {
namespace identify {

namespace {
constexpr double kShapeStep = 1e-4;

int term_alpha(const Term& term, double tau_s) {
  switch (term.kind) {
    case TermKind::kWhiteAngle:
    case TermKind::kZeroDcFamily:
      return 2;
    case TermKind::kBiasInstability:
      return -1;
    case TermKind::kRandomWalk:
    case TermKind::kRateRamp:
      return -2;
    case TermKind::kMarkov:
      return tau_s < term.shape ? -2 : 0;
    default:  // white rate, sinusoid
      return 0;
  }
}
}  // namespace

int dominant_noise_alpha(const NoiseModel& model, double tau_s) {
  double largest = -1.0;
  int alpha = 0;
  for (const Term& term : model.terms) {
    const double contribution = term_avar(term, tau_s, model.white_rate_corner_hz);
    if (contribution > largest) {
      largest = contribution;
      alpha = term_alpha(term, tau_s);
    }
  }
  return alpha;
}

Eigen::MatrixXd predicted_log_covariance(const ModelStructure& structure,
                                         const std::vector<double>& log_parameters,
                                         double tau0_s, double record_length_s) {
  const NoiseModel model = model_from_log_parameters(structure, log_parameters);
  const int count = parameter_count(structure);
  const long long sample_count = static_cast<long long>(record_length_s / tau0_s);
  Eigen::MatrixXd information = Eigen::MatrixXd::Zero(count, count);
  const double corner = structure.white_rate_corner_hz;
  for (int m : octave_averaging_factors(sample_count)) {
    const double tau = m * tau0_s;
    const double total = model_avar(model, tau);
    const double edf = allan::equivalent_degrees_of_freedom(
        allan::Statistic::kOverlappingAllan, dominant_noise_alpha(model, tau), m, sample_count + 1);
    if (!(edf > 0.0) || !(total > 0.0)) continue;
    Eigen::VectorXd gradient(count);  // d ln(AVAR) / d ln(parameter)
    int index = 0;
    for (size_t i = 0; i < model.terms.size(); ++i) {
      gradient[index++] = 2.0 * term_avar(model.terms[i], tau, corner) / total;
      if (!structure.slots[i].shape_free) continue;
      Term up = model.terms[i], down = model.terms[i];
      up.shape *= std::exp(kShapeStep);
      down.shape *= std::exp(-kShapeStep);
      gradient[index++] =
          (term_avar(up, tau, corner) - term_avar(down, tau, corner)) / (2.0 * kShapeStep * total);
    }
    information += 0.5 * edf * gradient * gradient.transpose();  // chi2(edf)/edf scale family
  }
  Eigen::FullPivLU<Eigen::MatrixXd> lu(information);
  if (!lu.isInvertible()) return Eigen::MatrixXd();
  return lu.inverse();
}

double predicted_relative_sigma(const ModelStructure& structure,
                                const std::vector<double>& log_parameters, int parameter_index,
                                double tau0_s, double record_length_s) {
  const Eigen::MatrixXd covariance =
      predicted_log_covariance(structure, log_parameters, tau0_s, record_length_s);
  if (covariance.size() == 0 || !(covariance(parameter_index, parameter_index) >= 0.0)) {
    return std::numeric_limits<double>::infinity();
  }
  return std::sqrt(covariance(parameter_index, parameter_index));
}

double required_record_length_s(const ModelStructure& structure,
                                const std::vector<double>& log_parameters, int parameter_index,
                                double tau0_s, double current_length_s,
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
  for (int iteration = 0; iteration < 40; ++iteration) {
    const double middle = 0.5 * (low + high);
    if (sigma_at(std::exp(middle)) > target_relative_sigma) {
      low = middle;
    } else {
      high = middle;
    }
  }
  return std::exp(high);
}

double required_record_length_s(const FitResult& fit, const std::string& term_name,
                                double target_relative_sigma) {
  const TermEstimate* term = fit.find(term_name);
  if (term == nullptr) {
    throw std::invalid_argument("required_record_length_s: no term '" + term_name + "'");
  }
  const auto position = std::find_if(fit.terms.begin(), fit.terms.end(),
                                     [&](const TermEstimate& t) { return t.name == term_name; });
  const int slot = static_cast<int>(position - fit.terms.begin());
  if (slot >= static_cast<int>(fit.structure.slots.size())) {
    return std::numeric_limits<double>::infinity();
  }
  const int index = parameter_offset(fit.structure, slot);
  const double cramer_rao = predicted_relative_sigma(fit.structure, fit.log_parameters, index,
                                                     fit.tau0_s, fit.record_length_s);
  const double reported = term->amplitude.sigma / term->amplitude.value;
  const double inflation =
      (std::isfinite(reported) && cramer_rao > 0.0) ? std::max(1.0, reported / cramer_rao) : 1.0;
  return required_record_length_s(fit.structure, fit.log_parameters, index, fit.tau0_s,
                                  fit.record_length_s, target_relative_sigma / inflation);
}

}  // namespace identify
}  // namespace imu_lab
