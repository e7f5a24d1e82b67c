// The fit_thermal tool as a user runs it: emulated thermal-test bags in, model / CSV / plot out,
// and the refusals (one orientation for scale factor, too small a span, no or stale
// temperature topic), each with exit code 1 and a message that says what to do.
#include <gtest/gtest.h>
#include <rosbag/bag.h>
#include <sensor_msgs/Imu.h>
#include <sensor_msgs/Temperature.h>

#include "imu_lab/thermal/thermal_model_yaml.h"
#include "ros_test_support.h"

namespace imu_lab {
namespace {

using test_support::run_tool;

const std::string kData = IMU_LAB_TEST_DATA_DIR;

std::string emulated_bag(const std::string& name, const std::string& arguments) {
  const std::string bag = test_support::scratch_directory() + "/" + name + ".bag";
  const auto result = run_tool("emulate", arguments + " --no-truth --no-increments --out " + bag);
  EXPECT_EQ(result.exit_code, 0) << result.output;
  return bag;
}

TEST(FitThermalTool, FitsAMultiPositionTestAndWritesModelCsvAndPlot) {
  const std::string bag =
      emulated_bag("fit", "--profile " + kData + "/thermal/uncompensated_mems_gyro.yaml --scenario " + kData +
                              "/thermal/fit_multiposition.yaml --rate-hz 2 --seed 11");
  const std::string directory = test_support::scratch_directory();
  const auto result = run_tool("fit_thermal", bag + " --out " + directory +
                                                  "/model.yaml --rate-term --latitude-deg 50.45 "
                                                  "--plot " +
                                                  directory + "/thermal.png");
  ASSERT_EQ(result.exit_code, 0) << result.output;
  EXPECT_NE(result.output.find("in 6 orientations"), std::string::npos) << result.output;
  const auto model = thermal::load_thermal_model(directory + "/model.yaml");
  EXPECT_TRUE(model.uses_temperature_rate);
  EXPECT_LT(model.validity.temperature_min_c, -20.0);
  EXPECT_GT(model.validity.temperature_max_c, 60.0);
  EXPECT_FALSE(model.accelerometer[2].scale_factor_polynomial_ppm.empty());
  EXPECT_NE(test_support::read_file(directory + "/model.yaml").find("sigma"), std::string::npos);
  const std::string csv = test_support::read_file(directory + "/model_residuals.csv");
  EXPECT_EQ(csv.rfind("triad,axis,unit,stamp_s,temperature_c,rate_c_s,orientation,observed_delta_bias", 0), 0u);
  EXPECT_TRUE(test_support::file_exists(directory + "/thermal.png"));
}

// The regime switch (Golovach 2017 eqs. 3.18, 3.19) from the command line: the threshold derived
// from the bag's thermosensor and printed, the model written with both regimes; then applied by
// `correct`, which feeds the same indicator; and the refusals.
TEST(FitThermalTool, FitsTheRegimeSwitchAndCorrectAppliesIt) {
  const std::string bag =
      emulated_bag("regime", "--profile " + kData + "/thermal/uncompensated_mems_gyro.yaml --scenario " + kData +
                                 "/thermal/fit_multiposition.yaml --rate-hz 2 --seed 11");
  const std::string directory = test_support::scratch_directory();
  const std::string out = directory + "/regime.yaml";
  const auto result = run_tool("fit_thermal", bag + " --out " + out +
                                                  " --regime-switch --regime-hold-s 60 --latitude-deg 50.45 "
                                                  "--second-temperature-topic /imu/temperature2 --order 2");
  ASSERT_EQ(result.exit_code, 0) << result.output;
  EXPECT_NE(result.output.find("regime switch: |d2T/dt2| over 300 s, from the data: threshold"), std::string::npos)
      << result.output;
  const auto model = thermal::load_thermal_model(out);
  ASSERT_TRUE(model.regime_switch.enabled);
  EXPECT_GT(model.regime_switch.threshold_c_s2, 0.0);
  EXPECT_EQ(model.regime_switch.hold_s, 60.0);
  EXPECT_EQ(model.dynamic_accelerometer[0].bias_polynomial.size(), 2u);
  EXPECT_EQ(model.dynamic_accelerometer[0].bias_second_sensor_polynomial.size(), 1u);
  const std::string text = test_support::read_file(out);
  EXPECT_NE(text.find("dynamic.bias_polynomial[0]"), std::string::npos);
  const auto applied = run_tool("correct", bag + " --thermal-model " + out +
                                               " --second-temperature-topic /imu/temperature2 "
                                               "--out " +
                                               directory + "/regime_corrected.bag");
  EXPECT_EQ(applied.exit_code, 0) << applied.output;
  // The refusals: arguments, exit code, what the message must say.
  struct Refusal {
    std::string arguments;
    int exit_code;
    std::string says;
  };
  const Refusal refusals[] = {
      // A threshold no temperature change reaches: the dynamic regime is empty.
      {"--regime-switch --regime-threshold-c-s2 1 --no-scale-factor", 1,
       "the dynamic regime (|d2T/dt2| above 1 degC/s^2, hold 0 s) holds 0 static windows"},
      {"--regime-switch --regime-threshold-c-s2 0 --no-scale-factor", 2, "--regime-threshold-c-s2"},
      {"--regime-hold-s 10 --no-scale-factor", 2, "need --regime-switch"},
      {"--second-sensor-scale-factor --latitude-deg 50.45", 2, "give --second-temperature-topic"},
      // Positions at the soaks only: the two sensors agree there, the second-sensor scale factor
      // is not separable, and the refusal says what it needs.
      {"--latitude-deg 50.45 --second-temperature-topic /imu/temperature2 --second-sensor-scale-factor --order 2", 1,
       "while the two sensors disagree"},
  };
  for (const Refusal& refusal : refusals) {
    const std::string refused_out = directory + "/refused.yaml";
    const auto refused = run_tool("fit_thermal", bag + " --out " + refused_out + " " + refusal.arguments);
    EXPECT_EQ(refused.exit_code, refusal.exit_code) << refusal.arguments << "\n" << refused.output;
    EXPECT_NE(refused.output.find(refusal.says), std::string::npos) << refusal.arguments << "\n" << refused.output;
    EXPECT_FALSE(test_support::file_exists(refused_out)) << refusal.arguments;
  }
}

// The scale factor in the second thermosensor on a test that turns the IMU through the ramps.
TEST(FitThermalTool, FitsTheSecondSensorScaleFactorOnATumblingTest) {
  const std::string bag =
      emulated_bag("tumbling", "--profile " + kData + "/thermal/uncompensated_mems_gyro.yaml --scenario " + kData +
                                   "/thermal/tumbling_second_sensor.yaml --rate-hz 2 --seed 12");
  const std::string out = test_support::scratch_directory() + "/tumbling.yaml";
  const auto result = run_tool("fit_thermal", bag + " --out " + out +
                                                  " --latitude-deg 50.45 --precise-revisits --order 2 "
                                                  "--second-temperature-topic /imu/temperature2 "
                                                  "--second-sensor-scale-factor");
  ASSERT_EQ(result.exit_code, 0) << result.output;
  const auto model = thermal::load_thermal_model(out);
  for (int axis = 0; axis < 3; ++axis)
    EXPECT_EQ(model.accelerometer[axis].scale_factor_second_sensor_polynomial_ppm.size(), 1u);
  EXPECT_NE(test_support::read_file(out).find("scale_factor_second_sensor_polynomial_ppm[0]"), std::string::npos);
}

TEST(FitThermalTool, RefusesScaleFactorFromOneOrientationButFitsTheBias) {
  const std::string bag = emulated_bag("chamber", "--scenario thermal_chamber --rate-hz 1 --seed 12");
  const std::string out = test_support::scratch_directory() + "/model.yaml";
  const auto refused = run_tool("fit_thermal", bag + " --out " + out + " --latitude-deg 45");
  EXPECT_EQ(refused.exit_code, 1) << refused.output;
  EXPECT_NE(refused.output.find("two opposite orientations"), std::string::npos) << refused.output;
  EXPECT_NE(refused.output.find("thermal_multiposition.yaml"), std::string::npos) << refused.output;
  EXPECT_FALSE(test_support::file_exists(out));
  const auto bias_only = run_tool("fit_thermal", bag + " --out " + out + " --no-scale-factor");
  EXPECT_EQ(bias_only.exit_code, 0) << bias_only.output;
  EXPECT_TRUE(test_support::file_exists(out));
}

TEST(FitThermalTool, RefusesTooSmallASpanAndAMissingTopic) {
  const std::string bag = emulated_bag("static", "--scenario static --duration-s 600 --rate-hz 10 --seed 13");
  const std::string out = test_support::scratch_directory() + "/model.yaml";
  const auto span = run_tool("fit_thermal", bag + " --out " + out + " --no-scale-factor --order 2");
  EXPECT_EQ(span.exit_code, 1) << span.output;
  EXPECT_NE(span.output.find("span only 0.0 degC"), std::string::npos) << span.output;
  EXPECT_NE(span.output.find("wider range"), std::string::npos) << span.output;
  const auto missing =
      run_tool("fit_thermal", bag + " --out " + out + " --no-scale-factor --temperature-topic /imu/board_temperature");
  EXPECT_EQ(missing.exit_code, 1) << missing.output;
  EXPECT_NE(missing.output.find("has no topic /imu/board_temperature"), std::string::npos) << missing.output;
  EXPECT_NE(missing.output.find("/imu/temperature (sensor_msgs/Temperature"), std::string::npos) << missing.output;
  EXPECT_NE(missing.output.find("A thermal fit needs the thermosensor"), std::string::npos) << missing.output;
  EXPECT_FALSE(test_support::file_exists(out));
}

TEST(FitThermalTool, RefusesATemperatureTopicThatStops) {
  // IMU for 300 s, thermosensor only for the first 100 s: stale from 1.1 s after its last reading.
  const std::string bag_path = test_support::scratch_directory() + "/stale.bag";
  {
    rosbag::Bag bag(bag_path, rosbag::bagmode::Write);
    for (int i = 1; i <= 3000; ++i) {
      ros::Time stamp(1000.0 + 0.1 * i);
      sensor_msgs::Imu imu;
      imu.header.stamp = stamp;
      imu.linear_acceleration.z = 9.8;
      bag.write("/imu/raw", stamp, imu);
      if (i > 1000) continue;
      sensor_msgs::Temperature temperature;
      temperature.header.stamp = stamp;
      temperature.temperature = 20.0 + 0.01 * i;
      bag.write("/imu/temperature", stamp, temperature);
    }
  }
  const auto result =
      run_tool("fit_thermal", bag_path + " --no-scale-factor --out " + test_support::scratch_directory() + "/m.yaml");
  EXPECT_EQ(result.exit_code, 1) << result.output;
  EXPECT_NE(
      result.output.find("temperature is stale at IMU stamp 1101.100000000 s: the nearest reading is 1.100 s away"),
      std::string::npos)
      << result.output;
  EXPECT_NE(result.output.find("recorded through the whole test"), std::string::npos) << result.output;
}

}  // namespace
}  // namespace imu_lab
