// The statistics built from d-th differences of phase at lag m: Allan (d = 2) and Hadamard
// (d = 3), non-overlapping or overlapping, and Krobka's mean-removed forms of the overlapping ones.
#include <algorithm>
#include <cmath>

#include "imu_lab/allan/batch.h"

#include "batch_input_checks.h"

namespace imu_lab {
namespace allan {
namespace {

struct DifferenceEstimator {
  Statistic statistic;
  int order;         // d
  bool overlapping;  // stride tau0 instead of tau
  bool remove_mean;  // Krobka: subtract <D>^2
};

// Moments of D_k = sum_j (-1)^(d-j) C(d,j) x[k + j m] over k = 0, stride, ..., k + d m <= N-1.
// Two passes (mean, then spread about it) keep <D^2> - <D>^2 free of cancellation.
struct DifferenceMoments {
  double mean = 0.0;
  double central_mean_square = 0.0;  // <(D - <D>)^2>
  double mean_square() const { return central_mean_square + mean * mean; }
};

// Sums term(i), i < count: in double within short blocks (fast, and D is small and zero-mean),
// in extended precision across blocks, so ten million terms lose nothing.
template <typename Term>
long double block_sum(long long count, Term term) {
  constexpr long long kBlock = 1024;
  long double total = 0.0L;
  for (long long start = 0; start < count; start += kBlock) {
    const long long end = std::min(count, start + kBlock);
    double partial = 0.0;
    for (long long i = start; i < end; ++i) partial += term(i);
    total += partial;
  }
  return total;
}

template <int kOrder>
DifferenceMoments difference_moments(const std::vector<double>& x, std::size_t m, std::size_t stride, long long terms) {
  const double* p = x.data();
  auto difference_at = [p, m, stride](long long i) {
    const double* q = p + i * stride;
    if constexpr (kOrder == 2) return q[2 * m] - 2.0 * q[m] + q[0];
    return q[3 * m] - 3.0 * q[2 * m] + 3.0 * q[m] - q[0];
  };
  DifferenceMoments moments;
  moments.mean = static_cast<double>(block_sum(terms, difference_at) / terms);
  const double mean = moments.mean;
  const long double spread = block_sum(terms, [&](long long i) {
    const double deviation = difference_at(i) - mean;
    return deviation * deviation;
  });
  moments.central_mean_square = static_cast<double>(spread / terms);
  return moments;
}

double difference_variance(const DifferenceEstimator& estimator, const std::vector<double>& phase, double tau0_s,
                           int m) {
  const long long terms = detail::require_computable(estimator.statistic, phase, tau0_s, m);
  const std::size_t stride = estimator.overlapping ? 1 : static_cast<std::size_t>(m);
  const std::size_t lag = static_cast<std::size_t>(m);
  const DifferenceMoments moments = estimator.order == 2 ? difference_moments<2>(phase, lag, stride, terms)
                                                         : difference_moments<3>(phase, lag, stride, terms);
  // Normalised so that white FM gives the same level for Allan (1/2) and Hadamard (1/6).
  const double normalisation = estimator.order == 2 ? 2.0 : 6.0;
  const double tau_s = m * tau0_s;
  const double mean_square = estimator.remove_mean ? moments.central_mean_square : moments.mean_square();
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
  return difference_variance({Statistic::kOverlappingHadamard, 3, true, false}, phase, tau0_s, m);
}

double allan_krobka_variance(const std::vector<double>& phase, double tau0_s, int m) {
  return difference_variance({Statistic::kAllanKrobka, 2, true, true}, phase, tau0_s, m);
}

double hadamard_krobka_variance(const std::vector<double>& phase, double tau0_s, int m) {
  return difference_variance({Statistic::kHadamardKrobka, 3, true, true}, phase, tau0_s, m);
}

}  // namespace allan
}  // namespace imu_lab
