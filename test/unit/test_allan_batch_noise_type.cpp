// The noise-type estimate and the confidence bounds on synthetic power-law noise whose type
// is known, including the B1 / R(n) fallback where the lag-1 method lacks data.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "imu_lab/allan/batch.h"
#include "imu_lab/allan/confidence.h"
#include "imu_lab/allan/noise_type.h"

namespace imu_lab {
namespace allan {
namespace {

std::vector<double> white(std::size_t count, unsigned seed) {
  std::mt19937_64 generator(seed);
  std::normal_distribution<double> normal(0.0, 1.0);
  std::vector<double> values(count);
  for (double& value : values) value = normal(generator);
  return values;
}

std::vector<double> cumulative(const std::vector<double>& values) {
  std::vector<double> sums(values.size());
  double sum = 0.0;
  for (std::size_t k = 0; k < values.size(); ++k) sums[k] = sum += values[k];
  return sums;
}

struct Case {
  const char* name;
  int alpha;
  std::vector<double> phase;
};

std::vector<Case> pure_noises() {
  const std::size_t n = 20000;
  return {
      {"WPM", 2, white(n, 1)}, {"WFM", 0, cumulative(white(n, 2))}, {"RWFM", -2, cumulative(cumulative(white(n, 3)))}};
}

TEST(AllanBatchNoiseType, Lag1MethodIdentifiesPureNoises) {
  for (const Case& noise : pure_noises()) {
    for (int m : {1, 4, 16, 64}) {  // >= 300 decimated points: the lag-1 method
      for (Statistic statistic :
           {Statistic::kOverlappingAllan, Statistic::kModifiedAllan, Statistic::kOverlappingHadamard}) {
        EXPECT_EQ(estimate_noise_alpha(statistic, noise.phase, 1.0, m, SampleKind::kPhase), noise.alpha)
            << noise.name << " " << statistic_name(statistic) << " m = " << m;
      }
    }
  }
}

// B1's expected value is taken at the statistic's term count, as Stable32 does; that count is
// the number of averages only for the non-overlapping estimators, so those are the ones whose
// fallback can tell the whole range apart (R(n) separating WPM from WFM).
TEST(AllanBatchNoiseType, B1AndRnFallbackIdentifiesPureNoises) {
  for (const Case& noise : pure_noises()) {
    for (int m : {700, 1000}) {  // 28 and 19 averages: too few for lag-1
      for (Statistic statistic : {Statistic::kAllan, Statistic::kHadamard}) {
        EXPECT_EQ(estimate_noise_alpha(statistic, noise.phase, 1.0, m, SampleKind::kPhase), noise.alpha)
            << noise.name << " " << statistic_name(statistic) << " m = " << m;
      }
    }
  }
}

TEST(AllanBatchNoiseType, ExpectedB1RatiosMatchTheirClosedForms) {
  EXPECT_DOUBLE_EQ(expected_b1_ratio(10, -1), 1.0);             // WFM: B1 = 1
  EXPECT_DOUBLE_EQ(expected_b1_ratio(10, 1), 5.0);              // RWFM: N / 2
  EXPECT_NEAR(expected_b1_ratio(10, -2), 99.0 / 135.0, 1e-15);  // PM: (N^2-1)/(1.5 N (N-1))
  EXPECT_NEAR(expected_b1_ratio(10, 0), 10 * std::log(10.0) / (18 * std::log(2.0)), 1e-15);
}

// Coverage: over many white-FM records the 68.3 % interval holds the true ADEV ~68 % of
// the time, which checks EDF and chi-squared together (a wrong EDF branch shifts it).
TEST(AllanBatchNoiseType, BoundsCoverTheTrueValueAtTheStatedRate) {
  const int records = 400;
  const int m = 8;
  int covered = 0;
  for (int r = 0; r < records; ++r) {
    const std::vector<double> phase = cumulative(white(2000, 1000 + r));
    const StabilityPoint point = evaluate(Statistic::kOverlappingAllan, phase, 1.0, {m})[0];
    const double true_deviation = std::sqrt(1.0 / m);  // WFM, unit variance per sample
    if (point.deviation_lower <= true_deviation && true_deviation <= point.deviation_upper) {
      ++covered;
    }
  }
  // Binomial(400, 0.683): standard deviation 2.3 %, so +-7 % is a 3-sigma band.
  EXPECT_NEAR(static_cast<double>(covered) / records, 0.683, 0.07);
}

}  // namespace
}  // namespace allan
}  // namespace imu_lab
