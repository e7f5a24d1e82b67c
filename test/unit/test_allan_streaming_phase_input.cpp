// Increments (phase-type input, e.g. a ring-laser gyro's pulses) give the same result as the
// equivalent rates, and the deviations equal the batch statistics on the accumulated phase.
#include <gtest/gtest.h>

#include "allan_streaming_test_support.h"

namespace imu_lab {
namespace allan {
namespace {

using namespace testing_support;

TEST(AllanStreamingPhaseInput, IncrementsEqualTheEquivalentRates) {
  const double tau0_s = 2.5e-3;
  const std::int64_t tau0_ns = 2500000;
  const std::size_t count = 8000;
  const std::vector<double> rate = synthetic_rate(count, 31, 0.7);
  std::vector<double> increments(count);
  // Whole pulses of weight 1e-4 with carry: what a rate-integrating sensor delivers.
  const double pulse = 1e-4;
  double angle = 0.0;
  long long pulses_so_far = 0;
  for (std::size_t k = 0; k < count; ++k) {
    angle += rate[k] * tau0_s;
    const long long pulses = std::llround(angle / pulse);
    increments[k] = (pulses - pulses_so_far) * pulse;
    pulses_so_far = pulses;
  }
  std::vector<double> equivalent_rate(count);
  for (std::size_t k = 0; k < count; ++k) equivalent_rate[k] = increments[k] / tau0_s;

  const StreamingOptions options = test_options(1, 200, 10, 5.0);
  StreamingOptions phase_options = options;
  phase_options.input_kind = InputKind::kIncrement;
  StreamingAllan from_rates(options);
  StreamingAllan from_increments(phase_options);
  feed(from_rates, {equivalent_rate}, 0, count, tau0_ns);
  feed(from_increments, {increments}, 0, count, tau0_ns);
  const StreamingSnapshot rates_snapshot = from_rates.snapshot();
  const StreamingSnapshot increments_snapshot = from_increments.snapshot();

  std::vector<double> phase(count + 1, 0.0);
  for (std::size_t k = 0; k < count; ++k) phase[k + 1] = phase[k] + increments[k];
  for (const Statistic statistic : kStreamingStatistics) {
    const auto& streamed = increments_snapshot.curve(statistic, 0);
    ASSERT_GE(streamed.size(), 25u);
    compare_points(streamed, rates_snapshot.curve(statistic, 0), statistic_name(statistic) + " increments vs rates");
    // The batch phase path identifies noise from the phase itself, so compare deviations and '#'.
    const auto exact = points_up_to(streamed, options.exact_max_averaging_factor);
    const auto batch = evaluate(statistic, phase, tau0_s, factors_of(exact));
    ASSERT_EQ(exact.size(), batch.size());
    for (std::size_t i = 0; i < exact.size(); ++i) {
      EXPECT_EQ(exact[i].term_count, batch[i].term_count);
      EXPECT_LE(relative_difference(exact[i].deviation, batch[i].deviation), 1e-9)
          << statistic_name(statistic) << " m=" << exact[i].averaging_factor;
    }
  }
}

}  // namespace
}  // namespace allan
}  // namespace imu_lab
