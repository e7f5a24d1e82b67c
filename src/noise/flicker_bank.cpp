#include "imu_lab/noise/flicker_bank.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include <Eigen/Dense>

#include "imu_lab/noise/analytic_avar.h"

namespace imu_lab {
namespace noise {

namespace {
constexpr double kTwoPi = 6.28318530717958647692;
// Candidate poles: 3 per decade from 0.1 / (2 pi tau_max) to 2 f0. With least-squares weights
// the bank follows eq. 5.3 to ~0.3 % for tau in [1 / f0, tau_max] (measured over 1 to 8
// decades); below ~1 / f0 the sharp cutoff of eq. 5.3 cannot be followed by first-order poles.
constexpr double kPolesPerDecade = 3.0;
constexpr double kTopPoleOverCutoff = 2.0;
constexpr double kBottomPoleTimesTauMax = 0.1;
}  // namespace

namespace {
std::vector<double> log_grid(double low, double high, double points_per_decade) {
  const int count = std::max(2, static_cast<int>(std::ceil(std::log10(high / low) * points_per_decade)) + 1);
  std::vector<double> grid;
  for (int i = 0; i < count; ++i) grid.push_back(low * std::pow(high / low, double(i) / (count - 1)));
  return grid;
}

// Least-squares weights q_j^2 minimising the relative AVAR error on the claimed range; poles
// whose weight comes out negative are dropped and the rest refitted (a minimal NNLS).
std::vector<double> fit_weights(const std::vector<double>& corners, const std::vector<double>& taus,
                                const BiasInstabilityParameters& p, std::vector<bool>& active) {
  for (;;) {
    std::vector<int> columns;
    for (size_t j = 0; j < corners.size(); ++j)
      if (active[j]) columns.push_back(static_cast<int>(j));
    Eigen::MatrixXd design(taus.size(), columns.size());
    for (size_t i = 0; i < taus.size(); ++i) {
      const double target = bias_instability_avar(p.coefficient, p.cutoff_frequency_hz, taus[i]);
      for (size_t c = 0; c < columns.size(); ++c)
        design(i, c) = taus[i] * integrated_markov_factor(kTwoPi * corners[columns[c]] * taus[i]) / target;
    }
    const Eigen::VectorXd solution =
        design.colPivHouseholderQr().solve(Eigen::VectorXd::Ones(static_cast<Eigen::Index>(taus.size())));
    Eigen::Index most_negative = 0;
    if (solution.minCoeff(&most_negative) >= 0.0) {
      std::vector<double> weights(corners.size(), 0.0);
      for (size_t c = 0; c < columns.size(); ++c) weights[columns[c]] = solution[c];
      return weights;
    }
    active[columns[most_negative]] = false;
  }
}
}  // namespace

FlickerBankDesign design_flicker_bank(const BiasInstabilityParameters& p) {
  if (!(p.coefficient > 0.0) || !(p.cutoff_frequency_hz > 0.0) || !(p.tau_min_s > 0.0) ||
      !(p.tau_max_s > p.tau_min_s)) {
    throw std::invalid_argument("bias instability: need B > 0, f0 > 0, 0 < tau_min < tau_max");
  }
  const double top = kTopPoleOverCutoff * p.cutoff_frequency_hz;
  const double bottom = kBottomPoleTimesTauMax / (kTwoPi * p.tau_max_s);
  const std::vector<double> corners = log_grid(bottom, top, kPolesPerDecade);
  const std::vector<double> taus = log_grid(p.tau_min_s, p.tau_max_s, 50.0);
  std::vector<bool> active(corners.size(), true);
  const std::vector<double> weights = fit_weights(corners, taus, p, active);

  FlickerBankDesign design;
  design.valid_tau_min_s = p.tau_min_s;
  design.valid_tau_max_s = p.tau_max_s;
  for (size_t j = 0; j < corners.size(); ++j) {
    if (weights[j] <= 0.0) continue;
    design.corner_frequencies_hz.push_back(corners[j]);
    design.drive_densities.push_back(std::sqrt(weights[j]));
  }
  for (double tau : taus) {
    const double target = bias_instability_avar(p.coefficient, p.cutoff_frequency_hz, tau);
    const double error = std::abs(flicker_bank_avar(design, tau) / target - 1.0);
    design.max_relative_error = std::max(design.max_relative_error, error);
  }
  if (design.max_relative_error > kFlickerBankTolerance) {
    throw std::invalid_argument("bias instability: the Markov bank misses eq. 5.3 by " +
                                std::to_string(design.max_relative_error) + " over the range");
  }
  return design;
}

double flicker_bank_avar(const FlickerBankDesign& design, double tau_s) {
  double sum = 0.0;
  for (size_t j = 0; j < design.corner_frequencies_hz.size(); ++j) {
    const double q = design.drive_densities[j];
    sum += q * q * tau_s * integrated_markov_factor(kTwoPi * design.corner_frequencies_hz[j] * tau_s);
  }
  return sum;
}

FlickerBankNoise::FlickerBankNoise(const BiasInstabilityParameters& parameters, NormalStream normals)
    : design_(design_flicker_bank(parameters)), normals_(normals) {
  for (size_t j = 0; j < design_.corner_frequencies_hz.size(); ++j) {
    poles_.emplace_back(kTwoPi * design_.corner_frequencies_hz[j], design_.drive_densities[j]);
    states_.push_back(std::sqrt(poles_.back().stationary_variance()) * normals_.next());
  }
}

double FlickerBankNoise::next_interval_average(double, double interval_s) {
  double integral = 0.0;
  for (size_t j = 0; j < poles_.size(); ++j) {
    const double n1 = normals_.next();
    const double n2 = normals_.next();
    integral += poles_[j].advance(states_[j], interval_s, n1, n2);
  }
  return integral / interval_s;
}

double FlickerBankNoise::allan_variance(double tau_s, double) const { return flicker_bank_avar(design_, tau_s); }

double FlickerBankNoise::sample_variance(double interval_s) const {
  double sum = 0.0;
  for (const auto& pole : poles_) sum += pole.stationary_average_variance(interval_s);
  return sum;
}

}  // namespace noise
}  // namespace imu_lab
