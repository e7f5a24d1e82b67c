// Beyond the exact limit the streaming engine equals the decimated batch estimator (rate
// averaged over 2^L samples, batch statistic at m / 2^L), term counts and EDF included.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <set>

#include "allan_streaming_test_support.h"
#include "imu_lab/allan/decimated_batch.h"
#include "imu_lab/allan/streaming_tau_plan.h"

namespace imu_lab {
namespace allan {
namespace {

using namespace testing_support;

TEST(AllanStreamingDecimated, BeyondTheExactLimitEqualsTheDecimatedBatchEstimator) {
  const StreamingOptions options = test_options(2, 24, 10, 10.0);
  const std::size_t count = 30001;  // not a multiple of any block: incomplete blocks are dropped
  const std::vector<std::vector<double>> rates = {synthetic_rate(count, 21, 0.5), synthetic_rate(count, 22)};
  StreamingAllan engine(options);
  feed(engine, rates, 0, count);
  const StreamingSnapshot snapshot = engine.snapshot();
  const TauPlan plan = plan_taus(options, 1e-3);
  ASSERT_GE(plan.levels.size(), 6u);

  double worst = 0.0;
  std::size_t compared = 0;
  for (const Statistic statistic : kStreamingStatistics) {
    for (std::size_t c = 0; c < rates.size(); ++c) {
      const std::vector<StabilityPoint>& curve = snapshot.curve(statistic, c);
      for (const PlannedLevel& level : plan.levels) {
        if (level.level == 0) continue;
        const auto reference =
            evaluate_decimated_frequency(statistic, rates[c], 1e-3, level.level, level.level_averaging_factors);
        std::vector<StabilityPoint> streamed;
        for (const StabilityPoint& point : curve) {
          for (const StabilityPoint& expected : reference) {
            if (point.averaging_factor == expected.averaging_factor) streamed.push_back(point);
          }
        }
        worst = std::max(worst, compare_points(streamed, reference,
                                               statistic_name(statistic) + " level " + std::to_string(level.level)));
        compared += reference.size();
      }
    }
  }
  EXPECT_GE(compared, 200u);
  std::printf("max relative difference to the decimated batch beyond m_exact: %.3g over %zu points\n", worst, compared);
}

TEST(AllanStreamingDecimated, LevelsCoverOneOctaveEachAndReportMultiplesOfTheirBlock) {
  StreamingOptions options = test_options(1, 100, 10, 100.0);
  options.tau_spacing = TauSpacing::kEveryM;  // every m probes each octave's lower edge
  const TauPlan plan = plan_taus(options, 1e-3);
  int previous_largest = 0;
  for (const PlannedLevel& level : plan.levels) {
    for (const int factor : level.level_averaging_factors) {
      EXPECT_LE(factor, 100);
      if (level.level > 0) {
        EXPECT_GT(factor, 50) << "level " << level.level;
      }
      EXPECT_GT(factor << level.level, previous_largest);
      previous_largest = factor << level.level;
    }
  }
  EXPECT_EQ(plan.levels.size(), 11u);                             // 100 * 2^10 >= 1e5
  EXPECT_EQ(plan.levels[1].level_averaging_factors.front(), 51);  // m = 101 rounds up to 102
  EXPECT_EQ(previous_largest, 98 * 1024);  // 1e5 rounded up to a whole block: within one block of max_tau
}

// Every m up to max_tau / tau0, each rounded up to a multiple of its level's block, as the plan
// was built before it stepped from one multiple to the next.
std::map<int, std::set<int>> every_m_plan_by_brute_force(std::int64_t max_factor, std::int64_t exact_limit) {
  std::map<int, std::set<int>> factors_by_level;
  for (std::int64_t m = 1; m <= max_factor; ++m) {
    int level = 0;
    while (m > (exact_limit << level)) ++level;
    const std::int64_t block = std::int64_t{1} << level;
    factors_by_level[level].insert(static_cast<int>((m + block - 1) / block));
  }
  return factors_by_level;
}

TEST(AllanStreamingDecimated, EveryMPlanHoldsEveryFactorEachLevelTellsApart) {
  for (const int exact_limit : {2, 3, 7, 16, 100}) {
    for (const double max_tau_s : {0.001, 0.017, 0.5, 3.3, 60.0}) {
      StreamingOptions options = test_options(1, exact_limit, 10, max_tau_s);
      options.tau_spacing = TauSpacing::kEveryM;
      const TauPlan plan = plan_taus(options, 1e-3);
      std::map<int, std::set<int>> planned;
      for (const PlannedLevel& level : plan.levels) {
        planned[level.level].insert(level.level_averaging_factors.begin(), level.level_averaging_factors.end());
      }
      EXPECT_EQ(planned,
                every_m_plan_by_brute_force(static_cast<std::int64_t>(std::floor(max_tau_s / 1e-3)), exact_limit))
          << "exact limit " << exact_limit << ", max tau " << max_tau_s << " s";
    }
  }
}

TEST(AllanStreamingDecimated, EveryMPlanForNanosecondStampsIsQuick) {
  // A corrupt tau0 of 1 ns asks for every m up to 2^30 (the cap): the plan keeps 16 per octave
  // beyond the exact limit, and finds them without trying each m (the checkpoint fuzzer found a
  // 13 s stall there).
  StreamingOptions options = test_options(1, 32, 10, 1e4);
  options.tau_spacing = TauSpacing::kEveryM;
  const TauPlan plan = plan_taus(options, 1e-9);
  std::size_t factors = 0;
  for (const PlannedLevel& level : plan.levels) factors += level.level_averaging_factors.size();
  EXPECT_EQ(plan.levels.size(), 26u);   // 32 * 2^25 >= 2^30 - 1
  EXPECT_EQ(factors, 32u + 25u * 16u);  // 1..32 on level 0, 17..32 on each level above
}

}  // namespace
}  // namespace allan
}  // namespace imu_lab
