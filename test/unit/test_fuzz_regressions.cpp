// Inputs the libFuzzer harnesses (test/fuzz/) found crashing a loader, or leaking an exception
// that named no key, kept as files in test/data/fuzz_regressions/ (or rebuilt, where the file's
// layout moves with the checkpoint version): each must now be refused with a clear error naming
// what is wrong.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>
#include <iterator>
#include <string>
#include <vector>

#include "imu_lab/allan/checkpoint.h"
#include "imu_lab/allan/checkpoint_codec.h"
#include "imu_lab/allan/confidence.h"
#include "imu_lab/allan/streaming_block_autocorrelation.h"
#include "imu_lab/allan/streaming_difference_accumulator.h"
#include "imu_lab/allan/streaming_level.h"
#include "imu_lab/allan/streaming_allan.h"
#include "imu_lab/allan/streaming_phase_history.h"
#include "imu_lab/calib/calibration_file.h"
#include "imu_lab/common/config_error.h"
#include "imu_lab/io/csv_import_config.h"
#include "imu_lab/thermal/thermal_model_yaml.h"

#ifndef IMU_LAB_TEST_DATA_DIR
#define IMU_LAB_TEST_DATA_DIR "test/data"
#endif

namespace imu_lab {
namespace {

std::string regression_file(const std::string& name) {
  return std::string(IMU_LAB_TEST_DATA_DIR) + "/fuzz_regressions/" + name;
}

// The message of the ConfigError that loading `name` throws, and its key.
template <class Load>
std::pair<std::string, std::string> config_error_of(Load load, const std::string& name) {
  try {
    load(regression_file(name));
  } catch (const ConfigError& error) {
    return {error.key(), error.what()};
  }
  ADD_FAILURE() << name << " was accepted";
  return {};
}

TEST(FuzzRegressions, CalibrationWithAScalarAtTheTopIsRefusedAsAFile) {
  // Was YAML::BadSubscript (operator[] on a scalar) escaping the loader.
  const auto [key, message] = config_error_of(calib::load_calibration, "calibration_scalar_root.yaml");
  EXPECT_EQ(key, "(file)") << message;
  EXPECT_NE(message.find("map of keys"), std::string::npos) << message;
}

TEST(FuzzRegressions, CalibrationWhoseFormatIsAMapNamesTheFormatKey) {
  // Was YAML::TypedBadConversion<std::string> escaping the loader.
  const auto [key, message] = config_error_of(calib::load_calibration, "calibration_format_map.yaml");
  EXPECT_EQ(key, "format") << message;
}

TEST(FuzzRegressions, CalibrationWithTextForANumberNamesTheElement) {
  // Was a ConfigError on key "(values)" that did not say which value.
  const auto [key, message] = config_error_of(calib::load_calibration, "calibration_text_in_bias.yaml");
  EXPECT_EQ(key, "gyro.bias_rad_s[1]") << message;
}

TEST(FuzzRegressions, ThermalModelWithAMapAsAKeyIsRefusedNamingWhere) {
  // Was YAML::TypedBadConversion<std::string> from YamlFields::allow_only (every YAML loader).
  const auto [key, message] = config_error_of(thermal::load_thermal_model, "thermal_model_map_as_key.yaml");
  EXPECT_EQ(key, "(key)") << message;  // at the top level of the file
  EXPECT_NE(message.find("plain name"), std::string::npos) << message;
}

TEST(FuzzRegressions, CsvColumnMappingWithAMapAsAKeyIsRefused) {
  // Was YAML::TypedBadConversion<std::string> from the mapping's key check.
  const auto load = [](const std::string& path) { io::load_csv_import_options(path); };
  const auto [key, message] = config_error_of(load, "csv_import_config_list_as_key.yaml");
  EXPECT_EQ(key, "(document)") << message;
  EXPECT_NE(message.find("plain name"), std::string::npos) << message;
}

// The checkpoint harness fuzzes the payload inside a valid envelope; so does this.
std::string checkpoint_with_payload(const std::string& payload_name) {
  std::ifstream in(regression_file(payload_name), std::ios::binary);
  const std::string payload((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_FALSE(payload.empty()) << payload_name;
  const std::string path = ::testing::TempDir() + "fuzz_regression_" + payload_name + ".ckpt";
  allan::write_checkpoint_file(path, payload);
  return path;
}

std::string input_error_loading_checkpoint(const std::string& payload_name) {
  try {
    allan::StreamingAllan::load_checkpoint(checkpoint_with_payload(payload_name));
  } catch (const InputError& error) {
    return error.what();
  }
  ADD_FAILURE() << payload_name << " was accepted";
  return "";
}

TEST(FuzzRegressions, CheckpointClaimingMoreChannelsThanItHoldsIsRefused) {
  // Was an allocation of 2^40 channel reports before a byte of their state was read.
  const std::string message = input_error_loading_checkpoint("allan_checkpoint_huge_channel_count.payload");
  EXPECT_NE(message.find("channel_count"), std::string::npos) << message;
  EXPECT_NE(message.find("start the run again"), std::string::npos) << message;
}

// The fuzzer's input was a whole payload whose layout changes with the checkpoint version; the
// part that mattered is rebuilt here: a phase history whose stored points disagree with its count.
TEST(FuzzRegressions, CheckpointWhosePhaseHistoryDisagreesWithItsCountIsRefused) {
  // Was accepted, then read past the history's end at the first snapshot (phase_at_level).
  allan::BinaryWriter out;
  for (int segment = 0; segment < 2; ++segment) {
    out.put_i64(0);                        // level
    out.put_i64(1000);                     // level-0 points pushed...
    out.put_f64s(std::vector<double>(3));  // ...but only three kept
  }
  allan::BinaryReader in(out.bytes(), "checkpoint x");
  allan::PhaseHistory history(4096);
  try {
    history.load(in);
    ADD_FAILURE() << "accepted";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("phase history length does not match its count"), std::string::npos)
        << error.what();
  }
}

// The checkpoint harness resumes what it loads (a snapshot, 4200 samples, a snapshot). The
// state it crafted is rebuilt here per component, from a real one with one field changed, so the
// tests outlive the checkpoint layout.

// `bytes` with the eight bytes at `offset` (an offset from the end when negative) replaced.
std::string with_int64_at(std::string bytes, std::ptrdiff_t offset, std::int64_t value) {
  const std::size_t at =
      offset < 0 ? bytes.size() - static_cast<std::size_t>(-offset) : static_cast<std::size_t>(offset);
  std::memcpy(&bytes[at], &value, sizeof value);
  return bytes;
}

template <class Load>
std::string input_error_of(Load load) {
  try {
    load();
  } catch (const InputError& error) {
    return error.what();
  }
  ADD_FAILURE() << "accepted";
  return "";
}

// Loading `tampered` into a fresh component is refused naming `problem`; `original` loads.
template <class Load>
void expect_only_the_tampered_state_refused(const Load& load, const std::string& original, const std::string& tampered,
                                            const std::string& problem) {
  const std::string message = input_error_of([&] {
    allan::BinaryReader in(tampered, "checkpoint x");
    load(in);
  });
  EXPECT_NE(message.find(problem), std::string::npos) << message;
  allan::BinaryReader untouched(original, "checkpoint x");
  EXPECT_NO_THROW(load(untouched));
}

allan::PhaseRing ramp_ring(std::int64_t points) {
  allan::PhaseRing ring(3 * 4 + 1, allan::kPhaseBlockPoints);
  for (std::int64_t n = 0; n < points; ++n) ring.push(1e-3 * static_cast<double>(n * n % 97));
  return ring;
}

TEST(FuzzRegressions, CheckpointWhoseNextNonOverlappingEndLagsTheProcessedPointsIsRefused) {
  // Was accepted; the next update then read the phase window before its stored history.
  const allan::PhaseRing ring = ramp_ring(200);
  allan::DifferenceAccumulator allan_sums(2, {1, 2, 4});
  allan_sums.update(ring, 0);
  allan::BinaryWriter out;
  allan_sums.save(out);
  // The next ends are the last vector of the state; m = 4's is the last of them, legitimately 200.
  expect_only_the_tampered_state_refused(
      [](allan::BinaryReader& in) {
        allan::DifferenceAccumulator(2, {1, 2, 4}).load(in, 200);
      },
      out.bytes(), with_int64_at(out.bytes(), -8, 12),
      "next non-overlapping difference out of step with the processed points");
}

TEST(FuzzRegressions, CheckpointWhoseNextBlockMeanLagsTheProcessedPointsIsRefused) {
  // The fuzzer's first resume crash: a heap read before the window in the block-mean update.
  const allan::PhaseRing ring = ramp_ring(200);
  allan::BlockMeanAutocorrelation block_means({1, 2, 4});
  block_means.update(ring);
  allan::BinaryWriter out;
  block_means.save(out);
  expect_only_the_tampered_state_refused(
      [](allan::BinaryReader& in) {
        allan::BlockMeanAutocorrelation({1, 2, 4}).load(in, 200);
      },
      out.bytes(), with_int64_at(out.bytes(), -8, 12), "next block mean out of step with the processed points");
}

// A level that has moved its window's history at least once (5000 points through a 4096 block).
void load_level(allan::BinaryReader& in) { allan::ResolutionLevel(0, {1, 2}).load(in); }

allan::BinaryWriter saved_level(bool close_a_segment) {
  allan::ResolutionLevel level(0, {1, 2});
  for (int n = 1; n < 5000; ++n) level.append_phase(1e-3 * (n % 13));
  level.process_appended();
  if (close_a_segment) {
    level.restart_segment();
    for (int n = 1; n < 10; ++n) level.append_phase(1e-3 * n);
  }
  allan::BinaryWriter out;
  level.save(out);
  return out;
}

TEST(FuzzRegressions, CheckpointWithUnprocessedPointsBeyondTheStoredHistoryIsRefused) {
  const allan::BinaryWriter out = saved_level(false);
  // level, factor count, the window's count, its stored points (length, values), then processed.
  allan::BinaryReader layout(out.bytes(), "checkpoint x");
  layout.get_u64();
  layout.get_u64();
  layout.get_i64();
  const std::size_t stored = layout.get_f64s().size();
  const std::ptrdiff_t processed_offset = 4 * 8 + static_cast<std::ptrdiff_t>(stored) * 8;
  expect_only_the_tampered_state_refused(load_level, out.bytes(), with_int64_at(out.bytes(), processed_offset, 0),
                                         "without the history before them");
}

TEST(FuzzRegressions, CheckpointWhoseClosedSegmentsOverflowTheTermCountIsRefused) {
  // Was accepted; the total deviation's normaliser (length times count) then overflowed int64.
  const allan::BinaryWriter out = saved_level(true);
  // The map of closed segments ends the state: its one entry is (5000 points, 1 segment).
  const std::string huge =
      with_int64_at(with_int64_at(out.bytes(), -16, std::int64_t{1} << 40), -8, std::int64_t{1} << 40);
  expect_only_the_tampered_state_refused(load_level, out.bytes(), huge, "closed segment length or count out of range");
}

TEST(FuzzRegressions, ChiSquaredBoundsHoldForATrillionDegreesOfFreedom) {
  // Boost's quantile series threw "exceeded 1000000 iterations" from a resumed snapshot.
  const allan::DeviationBounds bounds = allan::chi_squared_bounds(1.0, 1e12, 0.683);
  // Large-edf limit: 1 -+ z / sqrt(2 edf), z the standard normal's 84.15 % quantile.
  const double z = 1.000642;
  EXPECT_NEAR(bounds.lower, 1.0 - z / std::sqrt(2e12), 1e-11);
  EXPECT_NEAR(bounds.upper, 1.0 + z / std::sqrt(2e12), 1e-11);
  // No step where the approximation takes over: both sides of 1e8 agree to 1e-13.
  const allan::DeviationBounds below = allan::chi_squared_bounds(1.0, std::nextafter(1e8, 0.0), 0.683);
  const allan::DeviationBounds above = allan::chi_squared_bounds(1.0, 1e8, 0.683);
  EXPECT_NEAR(below.lower, above.lower, 1e-13);
  EXPECT_NEAR(below.upper, above.upper, 1e-13);
}

TEST(FuzzRegressions, SamplesThatOverflowTheSumsGiveNoPointsInsteadOfAnException) {
  // Finite samples near 1e300 make infinite squares; chi_squared_bounds used to throw on the
  // NaN deviation from inf - inf, out of snapshot().
  allan::StreamingOptions options;
  options.channel_count = 2;
  options.warm_up_sample_count = 10;
  allan::StreamingAllan engine(options);
  for (int k = 0; k < 3000; ++k) {
    const double huge = k % 2 == 0 ? 1e300 : -1e300;
    engine.push(std::int64_t{1000000} * k, {huge, 1e-3 * (k % 7)});
  }
  allan::StreamingSnapshot snapshot;
  ASSERT_NO_THROW(snapshot = engine.snapshot());
  for (const allan::Statistic statistic : allan::kStreamingStatistics) {
    for (const allan::StabilityPoint& point : snapshot.curve(statistic, 0)) {
      EXPECT_TRUE(std::isfinite(point.deviation))
          << allan::statistic_name(statistic) << " m " << point.averaging_factor;
    }
    EXPECT_FALSE(snapshot.curve(statistic, 1).empty()) << "the other channel keeps its curve";
  }
}

TEST(FuzzRegressions, StampsCenturiesApartAreGapsAndDisorderNotOverflow) {
  // Stamp differences overflowed int64 in the warm-up median and the stamp tracker (UB).
  allan::StreamingOptions options;
  options.channel_count = 1;
  options.warm_up_sample_count = 8;
  allan::StreamingAllan engine(options);
  const std::int64_t far_past = std::numeric_limits<std::int64_t>::min() + 1;
  const std::int64_t far_future = std::numeric_limits<std::int64_t>::max() - 1;
  const std::int64_t ms = 1000000;
  for (const std::int64_t stamp : {0 * ms, 1 * ms, 2 * ms, 3 * ms, far_future, far_past, 4 * ms, 5 * ms, 6 * ms}) {
    engine.push(stamp, {1.0});
  }
  const allan::StreamingSnapshot snapshot = engine.snapshot();
  EXPECT_EQ(snapshot.timing.tau0_s, 1e-3);
  EXPECT_GE(snapshot.timing.gap_count, 1);
  EXPECT_GE(snapshot.timing.out_of_order_count, 1);
}

}  // namespace
}  // namespace imu_lab
