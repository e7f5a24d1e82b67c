// Streaming equals the batch reference on the reference data sets: Stable32's PHASE.DAT (phase
// data, fed as increments), the OCXO frequency record and the NBS14 1000-point set.
#include <gtest/gtest.h>

#include "allan_streaming_test_support.h"
#include "test_allan_batch_reference.h"

namespace imu_lab {
namespace allan {
namespace {

using namespace testing_support;

// Every m up to 500, all exact: the small sets' whole curve.
StreamingOptions every_m_options() {
  StreamingOptions options = test_options(1, 500, 10, 500.0);
  options.tau_spacing = TauSpacing::kEveryM;
  return options;
}

StreamingSnapshot stream(const std::vector<double>& values, InputKind kind, StreamingOptions options) {
  options.input_kind = kind;
  StreamingAllan engine(options);
  feed(engine, {values}, 0, values.size(), 1000000000);  // tau0 = 1 s
  return engine.snapshot();
}

double compare_all_statistics(const StreamingSnapshot& snapshot, const std::vector<double>& rate,
                              std::size_t min_points, const std::string& data_set) {
  double worst = 0.0;
  for (const Statistic statistic : kStreamingStatistics) {
    const auto& streamed = snapshot.curve(statistic, 0);
    EXPECT_GE(streamed.size(), min_points) << data_set << " " << statistic_name(statistic);
    const auto reference = evaluate_frequency(statistic, rate, 1.0, factors_of(streamed));
    worst = std::max(worst, compare_points(streamed, reference, data_set + " " + statistic_name(statistic)));
  }
  std::printf("%s: max relative difference to batch %.3g\n", data_set.c_str(), worst);
  return worst;
}

TEST(AllanStreamingReferenceData, PhaseDatIncrementsEqualBatchAtEveryM) {
  const std::vector<double> phase = testing::read_column(testing::stable32_path("phase_dat/PHASE.DAT"));
  ASSERT_EQ(phase.size(), 1001u);
  std::vector<double> increments(phase.size() - 1);
  for (std::size_t k = 0; k + 1 < phase.size(); ++k) increments[k] = phase[k + 1] - phase[k];
  const StreamingSnapshot snapshot = stream(increments, InputKind::kIncrement, every_m_options());
  // Increments are rates times tau0 = 1 s: every field equals the batch frequency path.
  compare_all_statistics(snapshot, increments, 300, "PHASE.DAT");
  // And the deviations equal the batch statistics on the phase itself.
  for (const Statistic statistic : kStreamingStatistics) {
    const auto& streamed = snapshot.curve(statistic, 0);
    const auto on_phase = evaluate(statistic, phase, 1.0, factors_of(streamed));
    ASSERT_EQ(streamed.size(), on_phase.size());
    for (std::size_t i = 0; i < streamed.size(); ++i) {
      EXPECT_LE(relative_difference(streamed[i].deviation, on_phase[i].deviation), 1e-9);
    }
  }
}

TEST(AllanStreamingReferenceData, OcxoFrequencyEqualsBatch) {
  const std::vector<double> fractional = testing::read_ocxo_fractional_frequency();
  ASSERT_EQ(fractional.size(), 19982u);
  // Every tau of the record is exact.
  const StreamingSnapshot snapshot = stream(fractional, InputKind::kFrequency, test_options(1, 10000, 20, 1e4));
  compare_all_statistics(snapshot, fractional, 60, "OCXO");
}

TEST(AllanStreamingReferenceData, Nbs14EqualsBatchAtEveryM) {
  const std::vector<double> nbs14 = testing::nbs14_frequency();
  compare_all_statistics(stream(nbs14, InputKind::kFrequency, every_m_options()), nbs14, 300, "NBS14");
}

}  // namespace
}  // namespace allan
}  // namespace imu_lab
