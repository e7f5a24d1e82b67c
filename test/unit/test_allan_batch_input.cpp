// Bad input to the batch statistics: a tau the record cannot support is skipped by evaluate()
// and refused by the single-tau functions; non-positive tau0, NaN, m < 1 and an impossible
// confidence are refused with a message naming the problem.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "imu_lab/allan/batch.h"
#include "imu_lab/allan/confidence.h"
#include "imu_lab/allan/edf.h"

namespace imu_lab {
namespace allan {
namespace {

const Statistic kAllStatistics[] = {Statistic::kAllan,    Statistic::kOverlappingAllan,    Statistic::kModifiedAllan,
                                    Statistic::kHadamard, Statistic::kOverlappingHadamard, Statistic::kTime,
                                    Statistic::kTotal,    Statistic::kAllanKrobka,         Statistic::kHadamardKrobka};

std::vector<double> ramp_phase(std::size_t count) {
  std::vector<double> phase(count);
  for (std::size_t k = 0; k < count; ++k) phase[k] = std::sin(0.37 * k) + 0.01 * k * k;
  return phase;
}

// Expects std::invalid_argument whose message contains `fragment`.
template <typename Call>
void expect_refused(Call call, const std::string& fragment) {
  try {
    call();
    ADD_FAILURE() << "expected std::invalid_argument mentioning \"" << fragment << "\"";
  } catch (const std::invalid_argument& error) {
    EXPECT_NE(std::string(error.what()).find(fragment), std::string::npos) << error.what();
  }
}

TEST(AllanBatchInput, TermCountsFollowStable32AndReachZeroWhenTooShort) {
  // N = 1001 phase samples, the PHASE.DAT layout, at m = 128.
  EXPECT_EQ(term_count(Statistic::kAllan, 1001, 128), 6);
  EXPECT_EQ(term_count(Statistic::kHadamard, 1001, 128), 5);
  EXPECT_EQ(term_count(Statistic::kOverlappingAllan, 1001, 128), 745);
  EXPECT_EQ(term_count(Statistic::kAllanKrobka, 1001, 128), 745);
  EXPECT_EQ(term_count(Statistic::kOverlappingHadamard, 1001, 128), 617);
  EXPECT_EQ(term_count(Statistic::kModifiedAllan, 1001, 128), 618);
  EXPECT_EQ(term_count(Statistic::kTotal, 1001, 128), 999);
  // The shortest records each statistic accepts at m = 4, and one sample fewer.
  EXPECT_EQ(term_count(Statistic::kAllan, 9, 4), 1);
  EXPECT_EQ(term_count(Statistic::kAllan, 8, 4), 0);
  EXPECT_EQ(term_count(Statistic::kHadamard, 13, 4), 1);
  EXPECT_EQ(term_count(Statistic::kHadamard, 12, 4), 0);
  EXPECT_EQ(term_count(Statistic::kOverlappingAllan, 9, 4), 1);
  EXPECT_EQ(term_count(Statistic::kOverlappingAllan, 8, 4), 0);
  EXPECT_EQ(term_count(Statistic::kModifiedAllan, 12, 4), 1);
  EXPECT_EQ(term_count(Statistic::kModifiedAllan, 11, 4), 0);
  EXPECT_EQ(term_count(Statistic::kTotal, 9, 4), 7);
  EXPECT_EQ(term_count(Statistic::kTotal, 8, 4), 0);
  EXPECT_EQ(term_count(Statistic::kOverlappingAllan, 0, 1), 0);
}

TEST(AllanBatchInput, EvaluateSkipsTausTheRecordCannotSupport) {
  const std::vector<double> phase = ramp_phase(100);
  for (Statistic statistic : kAllStatistics) {
    const std::vector<StabilityPoint> points = evaluate(statistic, phase, 0.5, {1, 2, 40, 1000});
    ASSERT_FALSE(points.empty()) << statistic_name(statistic);
    for (const StabilityPoint& point : points) {
      EXPECT_GT(point.term_count, 0) << statistic_name(statistic);
      EXPECT_NE(point.averaging_factor, 1000) << statistic_name(statistic);
      EXPECT_DOUBLE_EQ(point.tau_s, 0.5 * point.averaging_factor);
    }
    EXPECT_TRUE(evaluate(statistic, ramp_phase(3), 1.0, {2, 5}).empty()) << statistic_name(statistic);
  }
}

TEST(AllanBatchInput, SingleTauFunctionsRefuseTooShortRecords) {
  for (Statistic statistic : kAllStatistics) {
    expect_refused([&] { variance(statistic, ramp_phase(10), 1.0, 50); }, "too few");
  }
}

TEST(AllanBatchInput, NonPositiveTau0IsRefused) {
  const std::vector<double> phase = ramp_phase(100);
  for (double tau0_s : {0.0, -1.0, std::numeric_limits<double>::quiet_NaN()}) {
    for (Statistic statistic : kAllStatistics) {
      expect_refused([&] { variance(statistic, phase, tau0_s, 1); }, "tau0_s");
      expect_refused([&] { evaluate(statistic, phase, tau0_s, {1}); }, "tau0_s");
    }
    expect_refused([&] { phase_from_frequency({1.0, 2.0}, tau0_s); }, "tau0_s");
  }
}

TEST(AllanBatchInput, NonFiniteSamplesAreRefused) {
  std::vector<double> phase = ramp_phase(100);
  phase[37] = std::numeric_limits<double>::quiet_NaN();
  for (Statistic statistic : kAllStatistics) {
    expect_refused([&] { variance(statistic, phase, 1.0, 2); }, "sample 37");
    expect_refused([&] { evaluate(statistic, phase, 1.0, {1, 2}); }, "not finite");
    // Refused even when every requested tau would have been skipped as too long.
    expect_refused([&] { evaluate(statistic, phase, 1.0, {1000}); }, "not finite");
  }
  std::vector<double> frequency(50, 1.0);
  frequency[3] = std::numeric_limits<double>::infinity();
  expect_refused([&] { phase_from_frequency(frequency, 1.0); }, "sample 3");
  expect_refused([&] { evaluate_frequency(Statistic::kAllan, frequency, 1.0, {1}); }, "not finite");
}

TEST(AllanBatchInput, AveragingFactorBelowOneAndBadConfidenceAreRefused) {
  const std::vector<double> phase = ramp_phase(100);
  expect_refused([&] { overlapping_allan_variance(phase, 1.0, 0); }, "m = 0");
  expect_refused([&] { evaluate(Statistic::kAllan, phase, 1.0, {1, -3}); }, "m = -3");
  expect_refused([&] { evaluate(Statistic::kAllan, phase, 1.0, {1}, 1.0); }, "confidence");
  expect_refused([&] { evaluate(Statistic::kAllan, phase, 1.0, {1}, 0.0); }, "confidence");
  expect_refused([&] { chi_squared_bounds(1.0, 0.0, 0.683); }, "edf");
  expect_refused([&] { greenhall_edf(-3, 2, 4, 1000, true, false); }, "alpha");
  expect_refused([&] { greenhall_edf(0, 2, 500, 1000, true, false); }, "fewer");
}

TEST(AllanBatchInput, PhaseFromFrequencyIntegratesFromZero) {
  const std::vector<double> phase = phase_from_frequency({1.0, -2.0, 4.0}, 0.5);
  ASSERT_EQ(phase.size(), 4u);
  EXPECT_DOUBLE_EQ(phase[0], 0.0);
  EXPECT_DOUBLE_EQ(phase[1], 0.5);
  EXPECT_DOUBLE_EQ(phase[2], -0.5);
  EXPECT_DOUBLE_EQ(phase[3], 1.5);
}

}  // namespace
}  // namespace allan
}  // namespace imu_lab
