// The batch statistics against published reference values: NIST SP 1065's NBS14 table and
// Stable32 1.60's output for PHASE.DAT (octave taus, with bounds) and an OCXO (all taus).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <map>
#include <string>
#include <vector>

#include "imu_lab/allan/batch.h"
#include "test_allan_batch_reference.h"

namespace imu_lab {
namespace allan {
namespace {

using testing::half_last_digit;
using testing::read_stable32_table;
using testing::stable32_path;

const Statistic kStable32Statistics[] = {
    Statistic::kAllan,    Statistic::kOverlappingAllan,    Statistic::kModifiedAllan,
    Statistic::kHadamard, Statistic::kOverlappingHadamard, Statistic::kTime,
    Statistic::kTotal};

std::vector<int> averaging_factors_of(const std::vector<testing::Stable32Row>& rows) {
  std::vector<int> factors;
  for (const auto& row : rows) factors.push_back(row.averaging_factor);
  return factors;
}

// Agreement "to the printed digits": 1e-4 relative plus half a unit in the last digit.
double printed_tolerance(const testing::Stable32Row& row) {
  return 1e-4 * std::fabs(row.sigma) + half_last_digit(row.sigma_text);
}

TEST(AllanBatchNbs14, ReproducesTheSp1065TableToSevenDigits) {
  // NIST SP 1065, NBS14 1000-point test, tau0 = 1 s, tau = 1, 10, 100 s.
  const std::map<Statistic, std::vector<double>> expected = {
      {Statistic::kAllan, {2.922319e-01, 9.965736e-02, 3.897804e-02}},
      {Statistic::kOverlappingAllan, {2.922319e-01, 9.159953e-02, 3.241343e-02}},
      {Statistic::kModifiedAllan, {2.922319e-01, 6.172376e-02, 2.170921e-02}},
      {Statistic::kTotal, {2.922319e-01, 9.134743e-02, 3.406530e-02}},
      {Statistic::kHadamard, {2.943883e-01, 1.052754e-01, 3.910860e-02}},
      {Statistic::kOverlappingHadamard, {2.943883e-01, 9.581083e-02, 3.237638e-02}},
      {Statistic::kTime, {1.687202e-01, 3.563623e-01, 1.253382e+00}}};
  const std::vector<double> frequency = testing::nbs14_frequency();
  ASSERT_EQ(frequency.size(), 1000u);
  const std::vector<double> phase = phase_from_frequency(frequency, 1.0);
  for (const auto& [statistic, deviations] : expected) {
    const std::vector<int> factors = {1, 10, 100};
    for (std::size_t i = 0; i < factors.size(); ++i) {
      const double deviation = std::sqrt(variance(statistic, phase, 1.0, factors[i]));
      EXPECT_NEAR(deviation / deviations[i], 1.0, 1e-6)
          << statistic_name(statistic) << " at tau = " << factors[i] << " s";
    }
  }
}

TEST(AllanBatchNbs14, GeneratorMatchesTheReadmeCheckValues) {
  const std::vector<double> frequency = testing::nbs14_frequency();
  EXPECT_DOUBLE_EQ(frequency[1], 395529916.0 / 2147483647.0);
  EXPECT_DOUBLE_EQ(frequency[2], 1209410747.0 / 2147483647.0);
  EXPECT_DOUBLE_EQ(frequency[3], 633705974.0 / 2147483647.0);
}

TEST(AllanBatchPhaseDat, ReproducesStable32SigmaCountAlphaAndBounds) {
  const std::vector<double> phase = testing::read_column(stable32_path("phase_dat/PHASE.DAT"));
  ASSERT_EQ(phase.size(), 1001u);
  for (Statistic statistic : kStable32Statistics) {
    const std::string name = statistic_name(statistic);
    const auto rows = read_stable32_table(stable32_path("phase_dat/phase_dat_" + name + "_octave.txt"));
    ASSERT_GE(rows.size(), 8u) << name;
    const std::vector<StabilityPoint> points = evaluate(statistic, phase, 1.0, averaging_factors_of(rows), 0.683);
    ASSERT_EQ(points.size(), rows.size()) << name;
    double worst_value = 0.0, worst_bound = 0.0;
    for (std::size_t i = 0; i < rows.size(); ++i) {
      const auto& row = rows[i];
      const auto& point = points[i];
      const std::string where = name + " m = " + std::to_string(row.averaging_factor);
      EXPECT_EQ(point.averaging_factor, row.averaging_factor) << where;
      EXPECT_DOUBLE_EQ(point.tau_s, row.tau_s) << where;
      EXPECT_NEAR(point.deviation, row.sigma, printed_tolerance(row)) << where;
      EXPECT_EQ(point.term_count, row.term_count) << where;
      EXPECT_EQ(point.alpha, row.alpha) << where;
      EXPECT_NEAR(point.deviation_lower / row.lower, 1.0, 5e-4) << where << " lower bound";
      EXPECT_NEAR(point.deviation_upper / row.upper, 1.0, 5e-4) << where << " upper bound";
      worst_value = std::max(worst_value, std::fabs(point.deviation / row.sigma - 1.0));
      worst_bound = std::max({worst_bound, std::fabs(point.deviation_lower / row.lower - 1.0),
                              std::fabs(point.deviation_upper / row.upper - 1.0)});
    }
    std::printf("PHASE.DAT %-6s worst relative error: sigma %.1e, bounds %.1e\n", name.c_str(), worst_value,
                worst_bound);
  }
}

TEST(AllanBatchOcxo, ReproducesStable32SigmaCountAndNoiseTypeAtAllTaus) {
  const std::vector<double> frequency = testing::read_ocxo_fractional_frequency();
  ASSERT_EQ(frequency.size(), 19982u);
  for (Statistic statistic : kStable32Statistics) {
    const std::string name = statistic_name(statistic);
    const auto rows = read_stable32_table(stable32_path("ocxo/stable32_" + name + "_alltau.txt"));
    ASSERT_GT(rows.size(), 200u) << name;
    const std::vector<StabilityPoint> points =
        evaluate_frequency(statistic, frequency, 1.0, averaging_factors_of(rows));
    ASSERT_EQ(points.size(), rows.size()) << name;
    std::size_t alpha_agreements = 0;
    bool stable32_alpha_all_zero = true;
    double worst_value = 0.0;
    for (std::size_t i = 0; i < rows.size(); ++i) {
      const auto& row = rows[i];
      const auto& point = points[i];
      const std::string where = name + " m = " + std::to_string(row.averaging_factor);
      EXPECT_NEAR(point.deviation, row.sigma, printed_tolerance(row)) << where;
      EXPECT_EQ(point.term_count, row.term_count) << where;
      if (point.alpha == row.alpha) ++alpha_agreements;
      if (row.alpha != 0) stable32_alpha_all_zero = false;
      worst_value = std::max(worst_value, std::fabs(point.deviation / row.sigma - 1.0));
    }
    const double share = static_cast<double>(alpha_agreements) / rows.size();
    std::printf("OCXO %-6s %zu taus, worst sigma error %.1e, alpha agrees on %.1f %%\n", name.c_str(), rows.size(),
                worst_value, 100.0 * share);
    if (statistic == Statistic::kTotal) {
      // Stable32 1.60 leaves TOTDEV's Alpha column at 0 in this run (it is 0 even at m = 1, 2,
      // where every other statistic reads FPM): it did not identify a noise type, so there is
      // nothing to compare our estimate with. Pin that, so a changed reference is noticed.
      EXPECT_TRUE(stable32_alpha_all_zero);
    } else {
      EXPECT_GE(share, 0.95) << name;
    }
  }
}

}  // namespace
}  // namespace allan
}  // namespace imu_lab
