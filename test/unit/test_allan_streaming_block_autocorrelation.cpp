// The running-sum lag-1 autocorrelation of block means (and of their differences) equals the
// direct computation on the stored series, also when the series has a large mean.
#include <gtest/gtest.h>

#include "allan_streaming_test_support.h"
#include "imu_lab/allan/streaming_block_autocorrelation.h"

namespace imu_lab {
namespace allan {
namespace {

using namespace testing_support;

struct DirectLag1 {
  double numerator = 0.0;
  double denominator = 0.0;
};

DirectLag1 direct_lag1(const std::vector<double>& series) {
  double mean = 0.0;
  for (double value : series) mean += value;
  mean /= static_cast<double>(series.size());
  DirectLag1 result;
  for (std::size_t i = 0; i < series.size(); ++i) {
    result.denominator += (series[i] - mean) * (series[i] - mean);
    if (i + 1 < series.size()) result.numerator += (series[i] - mean) * (series[i + 1] - mean);
  }
  return result;
}

TEST(AllanStreamingBlockAutocorrelation, RunningSumsEqualTheDirectLag1OfEachDifference) {
  const int m = 3;
  const std::vector<double> rate = synthetic_rate(3000, 91, 5.0);  // mean 5 >> spread of block means
  PhaseRing ring(16);
  BlockMeanAutocorrelation accumulator({m});
  double phase = 0.0;
  ring.push(phase);
  accumulator.update(ring);
  std::vector<double> block_means;
  for (std::size_t k = 0; k < rate.size(); ++k) {
    phase += rate[k];
    ring.push(phase);
    accumulator.update(ring);
    if ((k + 1) % m == 0) block_means.push_back((rate[k - 2] + rate[k - 1] + rate[k]) / m);
  }
  const BlockSeriesSummary summary = accumulator.summary(0);
  std::vector<double> series = block_means;
  for (int d = 0; d <= kMaxBlockDifferences; ++d) {
    ASSERT_EQ(summary.count[d], static_cast<std::int64_t>(series.size())) << "d=" << d;
    const DirectLag1 direct = direct_lag1(series);
    EXPECT_NEAR(summary.lag1_numerator[d] / summary.centred_squares[d], direct.numerator / direct.denominator, 1e-9)
        << "d=" << d;
    EXPECT_LE(relative_difference(summary.centred_squares[d], direct.denominator), 1e-9) << "d=" << d;
    for (std::size_t i = 0; i + 1 < series.size(); ++i) series[i] = series[i + 1] - series[i];
    series.pop_back();
  }
}

}  // namespace
}  // namespace allan
}  // namespace imu_lab
