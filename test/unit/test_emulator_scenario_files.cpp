// Every file in config/scenarios/ loads and runs (globbed: a new file is tested automatically);
// each kind of bad scenario is refused with a ConfigError naming the dotted key.
#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <filesystem>
#include <functional>
#include <string>

#include "imu_lab/common/config_error.h"
#include "imu_lab/emulator/imu_emulator.h"
#include "test_emulator_paths.h"

namespace imu_lab {
namespace emulator {
namespace {

TEST(EmulatorScenarioFiles, EveryShippedScenarioLoadsAndRuns) {
  const SensorProfile profile = load_sensor_profile(test::config_path("sensors/tactical_mems.yaml"));
  int files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(test::config_path("scenarios"))) {
    if (entry.path().extension() != ".yaml") continue;
    ++files;
    const ScenarioConfig scenario = load_scenario(entry.path().string());
    ImuEmulator emulator(profile, scenario, {200.0, 1.0e9, 5});
    for (int k = 0; k < 400; ++k) {
      const EmulatedSample s = emulator.next();
      ASSERT_TRUE(s.angular_rate_rad_s.allFinite() && s.specific_force_m_s2.allFinite()) << entry.path();
      ASSERT_TRUE(std::isfinite(s.temperature_c)) << entry.path();
      ASSERT_NEAR(s.truth.q_body_to_enu.norm(), 1.0, 1e-12) << entry.path();
    }
    // The truth is defined to the scenario's end (and beyond).
    auto motion = make_motion_source(scenario);
    const TruthState end = motion->truth_at(scenario.duration_s);
    EXPECT_TRUE(end.angular_rate_body_rad_s.allFinite() && end.specific_force_body_m_s2.allFinite() &&
                std::isfinite(end.latitude_rad))
        << entry.path();
    std::printf("[files] %s (%s): ran 2 s, truth at %.0f s finite\n", entry.path().filename().c_str(),
                scenario.type.c_str(), scenario.duration_s);
  }
  EXPECT_GE(files, 10);
}

// Applies `edit` to a shipped scenario and returns the key the ConfigError names ("" if none).
std::string refused_key(const std::string& file, const std::function<void(YAML::Node&)>& edit) {
  YAML::Node root = YAML::LoadFile(test::config_path("scenarios/" + file));
  edit(root);
  try {
    scenario_from_yaml(root, file);
  } catch (const ConfigError& error) {
    std::printf("[refused] %s\n", error.what());
    return error.key();
  }
  return "";
}

TEST(EmulatorScenarioFiles, ShippedFilesAreAccepted) {
  EXPECT_EQ(refused_key("multiposition_6.yaml", [](YAML::Node&) {}), "");
  EXPECT_EQ(refused_key("thermal_multiposition.yaml", [](YAML::Node&) {}), "");
}

TEST(EmulatorScenarioFiles, MissingKeyNamed) {
  EXPECT_EQ(refused_key("multiposition_6.yaml", [](YAML::Node& r) { r["multi_position"].remove("move_rate_deg_s"); }),
            "multi_position.move_rate_deg_s");
  EXPECT_EQ(refused_key("coning.yaml", [](YAML::Node& r) { r.remove("coning"); }), "coning");
}

TEST(EmulatorScenarioFiles, WrongTypeNamed) {
  EXPECT_EQ(refused_key("multiposition_6.yaml",
                        [](YAML::Node& r) { r["multi_position"]["positions"][1]["dwell_s"] = "long"; }),
            "multi_position.positions[1].dwell_s");
  EXPECT_EQ(refused_key("rate_table.yaml", [](YAML::Node& r) { r["rate_table"]["steps"] = 3; }), "rate_table.steps");
}

TEST(EmulatorScenarioFiles, UnknownTypeNamed) {
  EXPECT_EQ(refused_key("static.yaml", [](YAML::Node& r) { r["type"] = "vibration"; }), "type");
}

TEST(EmulatorScenarioFiles, NegativeDwellNamed) {
  EXPECT_EQ(
      refused_key("multiposition_6.yaml", [](YAML::Node& r) { r["multi_position"]["positions"][2]["dwell_s"] = -5.0; }),
      "multi_position.positions[2].dwell_s");
}

TEST(EmulatorScenarioFiles, RampWithoutRateNamed) {
  EXPECT_EQ(
      refused_key("thermal_chamber.yaml", [](YAML::Node& r) { r["thermal"]["segments"][1].remove("rate_c_per_min"); }),
      "thermal.segments[1].rate_c_per_min");
}

TEST(EmulatorScenarioFiles, SoakAndRampInOneSegmentNamed) {
  EXPECT_EQ(refused_key("thermal_chamber.yaml", [](YAML::Node& r) { r["thermal"]["segments"][0]["ramp_to_c"] = 30.0; }),
            "thermal.segments[0].soak_s");
}

TEST(EmulatorScenarioFiles, TemperatureBesideThermalBlockNamed) {
  EXPECT_EQ(refused_key("thermal_chamber.yaml", [](YAML::Node& r) { r["temperature_c"] = 25.0; }), "temperature_c");
}

TEST(EmulatorScenarioFiles, GrowingSelfHeatingNamed) {
  EXPECT_EQ(refused_key("thermal_chamber.yaml", [](YAML::Node& r) { r["thermal"]["self_heating"]["p4_per_s"] = 1e-3; }),
            "thermal.self_heating.p4_per_s");
}

TEST(EmulatorScenarioFiles, BlockOfAnotherTypeNamed) {
  EXPECT_EQ(refused_key("coning.yaml", [](YAML::Node& r) { r["sculling"] = r["coning"]; }), "sculling");
}

TEST(EmulatorScenarioFiles, OrientationOutsideTheBlockNamed) {
  EXPECT_EQ(refused_key("coning.yaml", [](YAML::Node& r) { r["roll_deg"] = 3.0; }), "roll_deg");
}

TEST(EmulatorScenarioFiles, UnknownKeyInBlockNamed) {
  EXPECT_EQ(refused_key("rate_table.yaml", [](YAML::Node& r) { r["rate_table"]["steps"][0]["rate_rpm"] = 1.0; }),
            "rate_table.steps[0].rate_rpm");
}

TEST(EmulatorScenarioFiles, InconsistentValuesNamed) {
  EXPECT_EQ(refused_key("sculling.yaml", [](YAML::Node& r) { r["sculling"]["vibration_axis"] = "x"; }),
            "sculling.vibration_axis");
  EXPECT_EQ(
      refused_key("trajectory.yaml", [](YAML::Node& r) { r["trajectory"]["legs"][6]["acceleration_m_s2"] = -5.0; }),
      "trajectory.legs[6].acceleration_m_s2");
  EXPECT_EQ(refused_key("rate_table.yaml",
                        [](YAML::Node& r) {
                          r["rate_table"]["axis_enu"] = std::vector<double>{0, 0, 0};
                        }),
            "rate_table.axis_enu");
  EXPECT_EQ(refused_key("coning.yaml", [](YAML::Node& r) { r["coning"]["half_angle_deg"] = 95.0; }),
            "coning.half_angle_deg");
  EXPECT_EQ(refused_key("multiposition_6.yaml",
                        [](YAML::Node& r) { r["multi_position"]["positions"] = YAML::Node(YAML::NodeType::Sequence); }),
            "multi_position.positions");
}

TEST(EmulatorScenarioFiles, ProfileThermalBlockRefusalsNamed) {
  YAML::Node root = YAML::LoadFile(test::config_path("sensors/tactical_mems.yaml"));
  auto key_of = [&](const std::function<void(YAML::Node&)>& edit) -> std::string {
    YAML::Node copy = YAML::Clone(root);
    edit(copy);
    try {
      sensor_profile_from_yaml(copy, "tactical_mems.yaml");
    } catch (const ConfigError& error) {
      std::printf("[refused] %s\n", error.what());
      return error.key();
    }
    return "";
  };
  EXPECT_EQ(key_of([](YAML::Node&) {}), "");
  EXPECT_EQ(key_of([](YAML::Node& r) { r["gyro"]["thermal"]["bias_polynomial_rad_s"][1] = "warm"; }),
            "gyro.thermal.bias_polynomial_rad_s[1]");
  EXPECT_EQ(key_of([](YAML::Node& r) { r["accelerometer"]["thermal"].remove("reference_temperature_c"); }),
            "accelerometer.thermal.reference_temperature_c");
  EXPECT_EQ(key_of([](YAML::Node& r) { r["gyro"]["thermal"]["bias_polynomial_m_s2"] = 1.0; }),
            "gyro.thermal.bias_polynomial_m_s2");
}

}  // namespace
}  // namespace emulator
}  // namespace imu_lab
