// Profile and scenario loading: every shipped file loads and runs; each kind of bad input is
// refused with a ConfigError naming the dotted key.
#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <cmath>
#include <string>
#include <variant>

#include "imu_lab/common/config_error.h"
#include "imu_lab/common/stamps.h"
#include "imu_lab/emulator/imu_emulator.h"
#include "imu_lab/emulator/sensor_channel.h"
#include "test_emulator_paths.h"

namespace imu_lab {
namespace emulator {
namespace {

const char* const kValidProfile = R"(
name: test
gyro:
  bias_fixed_rad_s: 0.0
  bias_turn_on_sigma_rad_s: 0.0
  scale_factor_error_ppm: 0.0
  misalignment_rad: [[0, 0, 0], [0, 0, 0], [0, 0, 0]]
  noise:
    white_rate: {density_rad_s_per_sqrt_hz: 1.0e-4}
    markov:
      - {q_c_rad_s_per_sqrt_s: 1.0e-3, correlation_time_s: 0.1}
      - {q_c_rad_s_per_sqrt_s: 1.0e-4, correlation_time_s: 10.0}
accelerometer:
  bias_fixed_m_s2: 0.0
  bias_turn_on_sigma_m_s2: 0.0
  scale_factor_error_ppm: 0.0
  misalignment_rad: [[0, 0, 0], [0, 0, 0], [0, 0, 0]]
  noise:
    white_rate: {density_m_s2_per_sqrt_hz: 1.0e-3}
)";

// Applies `edit` to the valid profile and returns the key the ConfigError names ("" if none).
std::string refused_key(const std::function<void(YAML::Node&)>& edit) {
  YAML::Node root = YAML::Load(kValidProfile);
  edit(root);
  try {
    sensor_profile_from_yaml(root, "test.yaml");
  } catch (const ConfigError& error) {
    std::printf("[refused] %s\n", error.what());
    return error.key();
  }
  return "";
}

TEST(EmulatorProfiles, ValidProfileLoads) {
  const SensorProfile profile = sensor_profile_from_yaml(YAML::Load(kValidProfile), "test.yaml");
  EXPECT_EQ(profile.gyro.noise_per_axis[0].size(), 3u);  // white + two Markov
  EXPECT_EQ(profile.accelerometer.noise_per_axis[2].size(), 1u);
}

TEST(EmulatorProfiles, MissingKeyNamed) {
  EXPECT_EQ(refused_key([](YAML::Node& r) { r["gyro"].remove("scale_factor_error_ppm"); }),
            "gyro.scale_factor_error_ppm");
  EXPECT_EQ(
      refused_key([](YAML::Node& r) { r["accelerometer"]["noise"]["white_rate"].remove("density_m_s2_per_sqrt_hz"); }),
      "accelerometer.noise.white_rate.density_m_s2_per_sqrt_hz");
  EXPECT_EQ(refused_key([](YAML::Node& r) { r.remove("name"); }), "name");
}

TEST(EmulatorProfiles, WrongTypeNamed) {
  EXPECT_EQ(refused_key([](YAML::Node& r) { r["gyro"]["noise"]["white_rate"]["density_rad_s_per_sqrt_hz"] = "loud"; }),
            "gyro.noise.white_rate.density_rad_s_per_sqrt_hz");
  EXPECT_EQ(refused_key([](YAML::Node& r) { r["gyro"]["misalignment_rad"][1] = 3.0; }), "gyro.misalignment_rad[1]");
  EXPECT_EQ(refused_key([](YAML::Node& r) { r["gyro"]["noise"] = "none"; }), "gyro.noise");
}

TEST(EmulatorProfiles, NegativeVarianceNamed) {
  EXPECT_EQ(refused_key([](YAML::Node& r) { r["gyro"]["noise"]["white_rate"]["density_rad_s_per_sqrt_hz"] = -1e-4; }),
            "gyro.noise.white_rate.density_rad_s_per_sqrt_hz");
  EXPECT_EQ(refused_key([](YAML::Node& r) { r["gyro"]["noise"]["markov"][1]["q_c_rad_s_per_sqrt_s"] = -1.0; }),
            "gyro.noise.markov[1].q_c_rad_s_per_sqrt_s");
  EXPECT_EQ(refused_key([](YAML::Node& r) { r["accelerometer"]["bias_turn_on_sigma_m_s2"] = -0.1; }),
            "accelerometer.bias_turn_on_sigma_m_s2");
}

TEST(EmulatorProfiles, UnknownNoiseNameNamed) {
  EXPECT_EQ(refused_key([](YAML::Node& r) { r["gyro"]["noise"]["pink_noise"]["density"] = 1.0; }),
            "gyro.noise.pink_noise");
}

TEST(EmulatorProfiles, UnknownKeysNamed) {
  EXPECT_EQ(refused_key([](YAML::Node& r) { r["magnetometer"]["x"] = 1.0; }), "magnetometer");
  // A unit mix-up is an unknown key: gyro keys are in rad/s.
  EXPECT_EQ(refused_key([](YAML::Node& r) { r["gyro"]["noise"]["white_rate"]["density_m_s2_per_sqrt_hz"] = 1.0; }),
            "gyro.noise.white_rate.density_m_s2_per_sqrt_hz");
}

TEST(EmulatorProfiles, InconsistentValuesNamed) {
  EXPECT_EQ(refused_key([](YAML::Node& r) { r["gyro"]["misalignment_rad"][0][0] = 1e-3; }), "gyro.misalignment_rad");
  EXPECT_EQ(refused_key([](YAML::Node& r) { r["gyro"]["noise"]["markov"][0]["correlation_time_s"] = 0.0; }),
            "gyro.noise.markov[0].correlation_time_s");
  EXPECT_EQ(refused_key([](YAML::Node& r) {
              r["gyro"]["noise"]["bias_instability"] =
                  YAML::Load("{coefficient_rad_s: 1e-5, cutoff_frequency_hz: 1.0, valid_tau_range_s: [0.01, 100]}");
            }),
            "gyro.noise.bias_instability.valid_tau_range_s");
  EXPECT_EQ(refused_key([](YAML::Node& r) { r["gyro"]["quantization"] = YAML::Load("{model: rounding}"); }),
            "gyro.quantization.model");
  EXPECT_EQ(refused_key([](YAML::Node& r) {
              r["gyro"]["noise"]["zero_dc_family"] =
                  YAML::Load("{exponent_n: 1, alpha_rad2_s2_per_hz_n_plus_1: 1e-6, beta_s: 0.1}");
            }),
            "gyro.noise.zero_dc_family.exponent_n");
}

TEST(EmulatorProfiles, FrontEndAndNoiseFamilyKeysLoad) {
  YAML::Node root = YAML::Load(kValidProfile);
  root["gyro"]["noise"]["resonance"] = YAML::Load(
      "[{rms_rad_s: [0, 0, 1e-3], natural_frequency_hz: 20, width_hz: 1.5},"
      " {rms_rad_s: 2e-4, natural_frequency_hz: 140, width_hz: 6}]");
  root["gyro"]["noise"]["high_pass_white"] = YAML::Load("{density_rad_s_per_sqrt_hz: 1e-4, corner_frequency_hz: 0.5}");
  root["gyro"]["noise"]["zero_dc_family"] = YAML::Load(
      "{exponent_n: 3, alpha_rad2_s2_per_hz_n_plus_1: 1e-8, beta_s: 0.05, cosine_s: 0.6,"
      " cosine_weight: -0.5}");
  root["gyro"]["noise"]["zero_dc_gaussian"] =
      YAML::Load("{exponent_n: 3, alpha_rad2_s2_per_hz_n_plus_1: [1e-8, 0, 1e-8], beta_s2: 4e-4}");
  root["gyro"]["noise"]["white_rate"]["axis_correlation"] = YAML::Load("[[1, 0.2, 0], [0.2, 1, -0.1], [0, -0.1, 1]]");
  root["gyro"]["output_lsb_rad_s"] = 8.7e-4;
  root["accelerometer"]["output_lsb_m_s2"] = YAML::Load("[0.0327, 0.0327, 0]");
  const SensorProfile profile = sensor_profile_from_yaml(root, "test.yaml");
  // white + two Markov + resonance (z only for the first) + high-pass + zero-DC + Gaussian (not y)
  EXPECT_EQ(profile.gyro.noise_per_axis[0].size(), 7u);
  EXPECT_EQ(profile.gyro.noise_per_axis[1].size(), 6u);
  EXPECT_EQ(profile.gyro.noise_per_axis[2].size(), 8u);
  const auto& p = std::get<noise::ZeroDcFamilyParameters>(profile.gyro.noise_per_axis[0][3]);
  EXPECT_EQ(p.exponent_n, 3.0);
  EXPECT_EQ(p.cosine_weight, -0.5);
  EXPECT_EQ(profile.gyro.white_rate_correlation(1, 2), -0.1);
  EXPECT_EQ(profile.accelerometer.output_lsb, Eigen::Vector3d(0.0327, 0.0327, 0.0));
  ImuEmulator emulator(profile, load_scenario(test::config_path("scenarios/static.yaml")), {200.0, 0.0, 1});
  for (int k = 0; k < 10; ++k) ASSERT_TRUE(emulator.next().angular_rate_rad_s.allFinite());
}

TEST(EmulatorProfiles, FrontEndAndNoiseFamilyRefusalsNamed) {
  auto with = [](const char* triad, const char* key, const char* yaml) {
    return refused_key([&](YAML::Node& r) { r[triad][key] = YAML::Load(yaml); });
  };
  auto with_noise = [](const char* key, const char* yaml) {
    return refused_key([&](YAML::Node& r) { r["gyro"]["noise"][key] = YAML::Load(yaml); });
  };
  const struct {
    const char* block;
    const char* yaml;
    const char* named;
  } noise_refusals[] = {
      {"resonance", "{rms_rad_s: 1e-3, natural_frequency_hz: 20, width_hz: 40}", "gyro.noise.resonance.width_hz"},
      {"resonance",
       "[{rms_rad_s: 1e-3, natural_frequency_hz: 20, width_hz: 1}, {rms_rad_s: 1e-3, natural_frequency_hz: -5, "
       "width_hz: 1}]",
       "gyro.noise.resonance[1].natural_frequency_hz"},
      {"resonance", "{rms_rad_s: -1e-3, natural_frequency_hz: 20, width_hz: 1}", "gyro.noise.resonance.rms_rad_s"},
      {"resonance", "{rms_m_s2: 1e-3, natural_frequency_hz: 20, width_hz: 1}", "gyro.noise.resonance.rms_m_s2"},
      {"high_pass_white", "{density_rad_s_per_sqrt_hz: 1e-4, corner_frequency_hz: 0}",
       "gyro.noise.high_pass_white.corner_frequency_hz"},
      {"zero_dc_family",
       "{exponent_n: 2, alpha_rad2_s2_per_hz_n_plus_1: 1e-8, beta_s: 0.05, cosine_s: 0.5, cosine_weight: 1.5}",
       "gyro.noise.zero_dc_family.cosine_weight"},
      {"zero_dc_family", "{exponent_n: 2, alpha_rad2_s2_per_hz_n_plus_1: 1e-8, beta_s: 0.05, cosine_s: -0.5}",
       "gyro.noise.zero_dc_family.cosine_s"},
      {"zero_dc_gaussian", "{exponent_n: 0.5, alpha_rad2_s2_per_hz_n_plus_1: 1e-8, beta_s2: 1e-3}",
       "gyro.noise.zero_dc_gaussian.exponent_n"},
      {"zero_dc_gaussian", "{exponent_n: 3, alpha_rad2_s2_per_hz_n_plus_1: 1e-8, beta_s: 1e-3}",
       "gyro.noise.zero_dc_gaussian.beta_s"},
  };
  for (const auto& refusal : noise_refusals) {
    EXPECT_EQ(with_noise(refusal.block, refusal.yaml), refusal.named) << refusal.yaml;
  }
  EXPECT_EQ(with("gyro", "output_lsb_rad_s", "-1e-3"), "gyro.output_lsb_rad_s");
  EXPECT_EQ(refused_key([](YAML::Node& r) {
              r["gyro"]["quantization"] = YAML::Load("{model: pulses, pulse_weight_rad: 1e-6}");
              r["gyro"]["output_lsb_rad_s"] = 1e-3;
            }),
            "gyro.output_lsb_rad_s");
  EXPECT_EQ(with("accelerometer", "dead_zone_m_s2", "[0, -1, 0]"), "accelerometer.dead_zone_m_s2");
  EXPECT_EQ(with("gyro", "scale_factor_asymmetry_ppm", "high"), "gyro.scale_factor_asymmetry_ppm");
  EXPECT_EQ(with("gyro", "scale_factor_nonlinearity", "{quadratic_ppm_fs: 100}"),
            "gyro.scale_factor_nonlinearity.full_scale_rad_s");
  EXPECT_EQ(with("gyro", "scale_factor_nonlinearity", "{full_scale_rad_s: [5, 0, 5], cubic_ppm_fs: 100}"),
            "gyro.scale_factor_nonlinearity.full_scale_rad_s");
  EXPECT_EQ(refused_key([](YAML::Node& r) {
              r["gyro"]["quadratic_nonlinearity_per_rad_s"] = 1e-4;
              r["gyro"]["scale_factor_nonlinearity"] = YAML::Load("{full_scale_rad_s: 5, quadratic_ppm_fs: 100}");
            }),
            "gyro.scale_factor_nonlinearity.quadratic_ppm_fs");
  auto correlation = [](const char* matrix) {
    return refused_key(
        [&](YAML::Node& r) { r["gyro"]["noise"]["white_rate"]["axis_correlation"] = YAML::Load(matrix); });
  };
  EXPECT_EQ(correlation("[[1, 0.2, 0], [0.3, 1, 0], [0, 0, 1]]"), "gyro.noise.white_rate.axis_correlation");
  EXPECT_EQ(correlation("[[2, 0, 0], [0, 1, 0], [0, 0, 1]]"), "gyro.noise.white_rate.axis_correlation");
  EXPECT_EQ(correlation("[[1, 0.9, -0.9], [0.9, 1, 0.9], [-0.9, 0.9, 1]]"), "gyro.noise.white_rate.axis_correlation");
  EXPECT_EQ(correlation("[[1, 0, 0], [0, 1, 0]]"), "gyro.noise.white_rate.axis_correlation");
  EXPECT_EQ(
      refused_key([](YAML::Node& r) {
        r["gyro"]["noise"]["white_rate"] = YAML::Load(
            "{density_rad_s_per_sqrt_hz: [1e-4, 0, 1e-4], axis_correlation: [[1, 0.5, 0], [0.5, 1, 0], [0, 0, 1]]}");
      }),
      "gyro.noise.white_rate.axis_correlation");
}

TEST(EmulatorProfiles, MissingFileNamed) {
  try {
    load_sensor_profile(test::config_path("sensors/no_such_profile.yaml"));
    FAIL() << "no error";
  } catch (const ConfigError& error) {
    EXPECT_EQ(error.key(), "(file)");
  }
}

TEST(EmulatorProfiles, ScenarioRefusalsNamed) {
  const YAML::Node valid = YAML::LoadFile(test::config_path("scenarios/static.yaml"));
  auto key_of = [&](const std::function<void(YAML::Node&)>& edit) -> std::string {
    YAML::Node root = YAML::Clone(valid);
    edit(root);
    try {
      scenario_from_yaml(root, "static.yaml");
    } catch (const ConfigError& error) {
      return error.key();
    }
    return "";
  };
  EXPECT_EQ(key_of([](YAML::Node&) {}), "");
  EXPECT_EQ(key_of([](YAML::Node& r) { r["earth_model"] = "flat"; }), "earth_model");
  EXPECT_EQ(key_of([](YAML::Node& r) { r.remove("latitude_deg"); }), "latitude_deg");
  // A site no sensor can be at used to be emulated (gravity and Earth rate of a height of 1e12 m).
  EXPECT_EQ(key_of([](YAML::Node& r) { r["height_m"] = 1e12; }), "height_m");
  EXPECT_EQ(key_of([](YAML::Node& r) { r["height_m"] = -20000.0; }), "height_m");
  EXPECT_EQ(key_of([](YAML::Node& r) { r["longitude_deg"] = 1e6; }), "longitude_deg");
  EXPECT_EQ(key_of([](YAML::Node& r) { r["longitude_deg"] = 359.0; }), "") << "east-only longitudes are common";
  EXPECT_EQ(key_of([](YAML::Node& r) { r["yaw_deg"] = "north"; }), "yaw_deg");
  EXPECT_EQ(key_of([](YAML::Node& r) { r["speed_m_s"] = 3.0; }), "speed_m_s");
}

TEST(EmulatorProfiles, FogHumpScreensTheWhiteNoise) {
  // Seed 003 Figs. 6.9-6.12: at tau = 1 s (T_c = 5 ms) the hump's flank reads as white noise
  // q_c T_c, thousands of times the true N; in AVAR the ratio is (q_c T_c / N)^2.
  const SensorProfile profile = load_sensor_profile(test::config_path("sensors/fog_markov_hump.yaml"));
  ImuEmulator emulator(profile, load_scenario(test::config_path("scenarios/static.yaml")), {2000.0, 0.0, 1});
  double white = 0.0, markov = 0.0;
  for (const auto& process : emulator.gyro_channel().processes(0)) {
    if (process->kind() == "white_rate") white += process->allan_variance(1.0, 5e-4);
    if (process->kind() == "markov") markov += process->allan_variance(1.0, 5e-4);
  }
  const double adev_ratio = std::sqrt(markov / white);
  std::printf("[fog] ADEV(1 s) of the hump / of the white noise = %.0f\n", adev_ratio);
  EXPECT_GT(adev_ratio, 3000.0);
}

struct ShippedProfile {
  const char* file;
  double rate_hz;
};

class EmulatorShippedProfiles : public ::testing::TestWithParam<ShippedProfile> {};

TEST_P(EmulatorShippedProfiles, LoadsAndRunsFourSeconds) {
  const SensorProfile profile = load_sensor_profile(test::config_path(std::string("sensors/") + GetParam().file));
  const ScenarioConfig scenario = load_scenario(test::config_path("scenarios/static.yaml"));
  ImuEmulator emulator(profile, scenario, {GetParam().rate_hz, 100.0, 7});
  const auto count = static_cast<int>(4.0 * GetParam().rate_hz);
  Eigen::Vector3d force_sum = Eigen::Vector3d::Zero();
  EmulatedSample sample;
  for (int k = 0; k < count; ++k) {
    sample = emulator.next();
    ASSERT_TRUE(sample.angular_rate_rad_s.allFinite() && sample.specific_force_m_s2.allFinite());
    force_sum += sample.specific_force_m_s2;
  }
  EXPECT_EQ(sample.stamp_ns, 104 * kNanosecondsPerSecond);
  // Gravity seen through bias, scale and nonlinearity: a consumer part is off by ~0.4 m/s^2.
  EXPECT_NEAR((force_sum / count).norm(), 9.8157, 0.5) << GetParam().file;
  EXPECT_GT(sample.angular_rate_variance_rad2_s2.minCoeff(), 0.0);
  EXPECT_GT(sample.specific_force_variance_m2_s4.minCoeff(), 0.0);
}

INSTANTIATE_TEST_SUITE_P(Shipped, EmulatorShippedProfiles,
                         ::testing::Values(ShippedProfile{"consumer_mems.yaml", 200.0},
                                           ShippedProfile{"tactical_mems.yaml", 400.0},
                                           ShippedProfile{"fog_markov_hump.yaml", 2000.0},
                                           ShippedProfile{"rlg_navigation.yaml", 100.0},
                                           ShippedProfile{"mems_front_end.yaml", 100.0}));

}  // namespace
}  // namespace emulator
}  // namespace imu_lab
