// Streaming equals the batch reference on the reference data sets: Stable32's PHASE.DAT (phase
// data, fed as increments), the OCXO frequency record and the NBS14 1000-point set.
#include <gtest/gtest.h>

#include "allan_streaming_test_support.h"

#ifndef IMU_LAB_TEST_DATA_DIR
#error "IMU_LAB_TEST_DATA_DIR must name test/data"
#endif

namespace imu_lab {
namespace allan {
namespace {

using namespace testing_support;

StreamingSnapshot stream(const std::vector<double>& values, InputKind kind, const StreamingOptions& base,
                         std::int64_t tau0_ns) {
  StreamingOptions options = base;
  options.channel_count = 1;
  options.input_kind = kind;
  StreamingAllan engine(options);
  feed(engine, {values}, 0, values.size(), tau0_ns);
  return engine.snapshot();
}

double compare_all_statistics(const StreamingSnapshot& snapshot, const std::vector<double>& rate, double tau0_s,
                              std::size_t min_points, const std::string& data_set) {
  double worst = 0.0;
  for (const Statistic statistic : kStreamingStatistics) {
    const auto& streamed = snapshot.curve(statistic, 0);
    EXPECT_GE(streamed.size(), min_points) << data_set << " " << statistic_name(statistic);
    const auto reference = evaluate_frequency(statistic, rate, tau0_s, factors_of(streamed));
    worst = std::max(worst, compare_points(streamed, reference, data_set + " " + statistic_name(statistic)));
  }
  return worst;
}

TEST(AllanStreamingReferenceData, PhaseDatIncrementsEqualBatchAtEveryM) {
  const std::vector<double> phase = read_column(std::string(IMU_LAB_TEST_DATA_DIR) + "/stable32/phase_dat/PHASE.DAT");
  ASSERT_EQ(phase.size(), 1001u);
  std::vector<double> increments(phase.size() - 1);
  for (std::size_t k = 0; k + 1 < phase.size(); ++k) increments[k] = phase[k + 1] - phase[k];
  StreamingOptions options;
  options.tau_spacing = TauSpacing::kEveryM;
  options.exact_max_averaging_factor = 500;
  options.max_tau_s = 500.0;
  const StreamingSnapshot snapshot = stream(increments, InputKind::kIncrement, options, 1000000000);
  // Increments are rates times tau0 = 1 s: every field equals the batch frequency path.
  const double worst = compare_all_statistics(snapshot, increments, 1.0, 300, "PHASE.DAT");
  // And the deviations equal the batch statistics on the phase itself.
  for (const Statistic statistic : kStreamingStatistics) {
    const auto& streamed = snapshot.curve(statistic, 0);
    const auto on_phase = evaluate(statistic, phase, 1.0, factors_of(streamed));
    ASSERT_EQ(streamed.size(), on_phase.size());
    for (std::size_t i = 0; i < streamed.size(); ++i) {
      EXPECT_LE(relative_difference(streamed[i].deviation, on_phase[i].deviation), 1e-9);
    }
  }
  std::printf("PHASE.DAT: max relative difference to batch %.3g\n", worst);
}

TEST(AllanStreamingReferenceData, OcxoFrequencyEqualsBatch) {
  const std::vector<double> hertz =
      read_column(std::string(IMU_LAB_TEST_DATA_DIR) + "/stable32/ocxo/ocxo_frequency.txt");
  ASSERT_EQ(hertz.size(), 19982u);
  std::vector<double> fractional(hertz.size());
  for (std::size_t k = 0; k < hertz.size(); ++k) fractional[k] = (hertz[k] - 1e7) / 1e7;
  StreamingOptions options;
  options.points_per_decade = 20;
  options.exact_max_averaging_factor = 10000;  // every tau of the record is exact
  options.max_tau_s = 1e4;
  const StreamingSnapshot snapshot = stream(fractional, InputKind::kFrequency, options, 1000000000);
  const double worst = compare_all_statistics(snapshot, fractional, 1.0, 60, "OCXO");
  std::printf("OCXO: max relative difference to batch %.3g\n", worst);
}

TEST(AllanStreamingReferenceData, Nbs14EqualsBatchAtEveryM) {
  std::vector<double> nbs14;
  long long n = 1234567890;
  for (int i = 0; i < 1000; ++i) {
    nbs14.push_back(static_cast<double>(n) / 2147483647.0);
    n = (16807 * n) % 2147483647;
  }
  StreamingOptions options;
  options.tau_spacing = TauSpacing::kEveryM;
  options.exact_max_averaging_factor = 500;
  options.max_tau_s = 500.0;
  const StreamingSnapshot snapshot = stream(nbs14, InputKind::kFrequency, options, 1000000000);
  const double worst = compare_all_statistics(snapshot, nbs14, 1.0, 300, "NBS14");
  std::printf("NBS14: max relative difference to batch %.3g\n", worst);
}

}  // namespace
}  // namespace allan
}  // namespace imu_lab
