// Inputs the libFuzzer harnesses (test/fuzz/) found crashing a loader, or leaking an exception
// that named no key, kept as files in test/data/fuzz_regressions/ (or rebuilt, where the file's
// layout moves with the checkpoint version): each must now be refused with a clear error naming
// what is wrong.
#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "imu_lab/allan/checkpoint.h"
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

}  // namespace
}  // namespace imu_lab
