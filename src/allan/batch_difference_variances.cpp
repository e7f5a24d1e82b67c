// The statistics built from d-th differences of phase at lag m: Allan (d = 2) and Hadamard
// (d = 3), non-overlapping or overlapping, and Krobka's mean-removed forms of the overlapping ones.
#include <cmath>

#include "imu_lab/allan/batch.h"

#include "batch_input_checks.h"

namespace imu_lab {
namespace allan {
namespace {

struct DifferenceEstimator {
  Statistic statistic;
  int order;               // d
  bool overlapping;        // stride tau0 instead of tau
  bool remove_mean;        // Krobka: subtract <D>^2
};

// Moments of D_k = sum_j (-1)^(d-j) C(d,j) x[k + j m] over k = 0, stride, ..., k + d m <= N-1.
// Two passes (mean, then spread about it) keep <D^2> - <D>^2 free of cancellation.
struct DifferenceMoments {
  double mean = 0.0;
  double central_mean_square = 0.0;  // <(D - <D>)^2>
  double mean_square() const { return central_mean_square + mean * mean; }
};

DifferenceMoments difference_moments(const std::vector<double>& x, std::size_t m, int order,
                                     std::size_t stride, long long terms) {
  static const double kWeights[2][4] = {{1.0, -2.0, 1.0, 0.0}, {-1.0, 3.0, -3.0, 1.0}};
  const double* weights = kWeights[order - 2];
  auto difference_at = [&](std::size_t k) {
    double value = 0.0;
    for (int j = 0; j <= order; ++j) value += weights[j] * x[k + j * m];
    return value;
  };
  long double sum = 0.0L;
  for (long long i = 0; i < terms; ++i) sum += difference_at(i * stride);
  DifferenceMoments moments;
  moments.mean = static_cast<double>(sum / terms);
  long double spread = 0.0L;
  for (long long i = 0; i < terms; ++i) {
    const double deviation = difference_at(i * stride) - moments.mean;
    spread += static_cast<long double>(deviation) * deviation;
  }
  moments.central_mean_square = static_cast<double>(spread / terms);
  return moments;
}

double difference_variance(const DifferenceEstimator& estimator, const std::vector<double>& phase,
                           double tau0_s, int m) {
  const long long terms = detail::require_computable(estimator.statistic, phase, tau0_s, m);
  const std::size_t stride = estimator.overlapping ? 1 : static_cast<std::size_t>(m);
  const DifferenceMoments moments =
      difference_moments(phase, static_cast<std::size_t>(m), estimator.order, stride, terms);
  // Normalised so that white FM gives the same level for Allan (1/2) and Hadamard (1/6).
  const double normalisation = estimator.order == 2 ? 2.0 : 6.0;
  const double tau_s = m * tau0_s;
  const double mean_square =
      estimator.remove_mean ? moments.central_mean_square : moments.mean_square();
  return mean_square / (normalisation * tau_s * tau_s);
}

}  // namespace

double allan_variance(const std::vector<double>& phase, double tau0_s, int m) {
  return difference_variance({Statistic::kAllan, 2, false, false}, phase, tau0_s, m);
}

double overlapping_allan_variance(const std::vector<double>& phase, double tau0_s, int m) {
  return difference_variance({Statistic::kOverlappingAllan, 2, true, false}, phase, tau0_s, m);
}

double hadamard_variance(const std::vector<double>& phase, double tau0_s, int m) {
  return difference_variance({Statistic::kHadamard, 3, false, false}, phase, tau0_s, m);
}

double overlapping_hadamard_variance(const std::vector<double>& phase, double tau0_s, int m) {
  return difference_variance({Statistic::kOverlappingHadamard, 3, true, false}, phase, tau0_s,
                             m);
}

double allan_krobka_variance(const std::vector<double>& phase, double tau0_s, int m) {
  return difference_variance({Statistic::kAllanKrobka, 2, true, true}, phase, tau0_s, m);
}

double hadamard_krobka_variance(const std::vector<double>& phase, double tau0_s, int m) {
  return difference_variance({Statistic::kHadamardKrobka, 3, true, true}, phase, tau0_s, m);
}

}  // namespace allan
}  // namespace imu_lab
