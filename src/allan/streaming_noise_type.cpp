#include "imu_lab/allan/streaming_noise_type.h"

#include <algorithm>
#include <cmath>

#include "imu_lab/allan/noise_type.h"

namespace imu_lab {
namespace allan {
namespace {

bool is_hadamard_family(Statistic statistic) {
  return statistic == Statistic::kHadamard || statistic == Statistic::kOverlappingHadamard ||
         statistic == Statistic::kHadamardKrobka;
}

// Riley & Greenhall: difference until delta = r1 / (1 + r1) < 0.25, then alpha = -round(2 delta) - 2d.
int lag1_alpha(const BlockSeriesSummary& block_means, int max_differences) {
  for (int d = 0;; ++d) {
    const double denominator = block_means.centred_squares[d];
    const double r1 = denominator > 0.0 ? block_means.lag1_numerator[d] / denominator : 0.0;
    const double delta = r1 / (1.0 + r1);
    if (delta < 0.25 || d >= max_differences || block_means.count[d] < 3) {
      return -static_cast<int>(std::lround(2.0 * delta)) - 2 * d;
    }
  }
}

// B1 = sample variance / two-sample variance of the block means, classified against its
// expectation per phase exponent mu with boundaries at geometric means (as the batch rule).
int b1_alpha(const BlockSeriesSummary& block_means, int m, double modified_to_allan_ratio) {
  const long long n = block_means.count[0];
  const double successive = block_means.raw_squares[1];
  if (n < 2 || successive <= 0.0) return 0;
  const double ratio = block_means.centred_squares[0] / (successive / 2.0);
  int mu = -2;
  for (int candidate = 1; candidate > -2; --candidate) {
    const double boundary =
        std::sqrt(expected_b1_ratio(n, candidate) * expected_b1_ratio(n, candidate - 1));
    if (ratio > boundary) {
      mu = candidate;
      break;
    }
  }
  if (mu > -2) return -mu - 1;
  if (modified_to_allan_ratio < 0.0) return 1;
  const double boundary = std::sqrt(expected_modified_ratio(1, m) * expected_modified_ratio(2, m));
  return modified_to_allan_ratio > boundary ? 1 : 2;
}

}  // namespace

int streaming_noise_alpha(Statistic statistic, const BlockSeriesSummary& block_means, int m,
                          double modified_to_allan_ratio) {
  const bool hadamard = is_hadamard_family(statistic);
  const int alpha = block_means.count[0] >= kMinimumLag1Points
                        ? lag1_alpha(block_means, hadamard ? 3 : 2)
                        : b1_alpha(block_means, m, modified_to_allan_ratio);
  return std::clamp(alpha, hadamard ? -4 : -2, 2);
}

}  // namespace allan
}  // namespace imu_lab
