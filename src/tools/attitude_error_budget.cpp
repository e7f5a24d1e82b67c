// attitude_error_budget: an identified gyro noise model (noise.yaml, as `allan` writes it) and an
// angular motion (an emulator scenario, constant body rates or a recorded bag's gyro rates) in;
// the predicted 1-sigma
// attitude error per ENU axis over time of a strapdown system and of a platform system with the
// same gyros out, as a CSV (written atomically) and a summary. See
// include/imu_lab/nav/attitude_error_growth.h and doc/navigation.md.
#include <CLI/CLI.hpp>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <stdexcept>

#include "imu_lab/common/atomic_file.h"
#include "imu_lab/common/config_error.h"
#include "imu_lab/common/tool_main.h"
#include "imu_lab/common/tool_options.h"
#include "imu_lab/emulator/scenario.h"
#include "imu_lab/pipeline/attitude_error_budget.h"
#include "imu_lab/ros_io/bag/strict_imu_reading.h"
#include "imu_lab/ros_io/node/config_paths.h"

int main(int argc, char** argv) {
  CLI::App app{"Predicted attitude error growth of a strapdown and a platform system with the same gyros."};
  using namespace imu_lab::option_range;
  std::string noise_path, scenario_name, motion_bag, motion_topic, out_path = "attitude_error_budget.csv";
  std::vector<double> body_rate_deg_s, start_rpy_deg = {0.0, 0.0, 0.0};
  double latitude = 0.0, duration_s = 0.0, step_s = 0.0, output_interval_s = 1.0, turn_on_bias_rad_s = 0.0;
  app.add_option("--noise", noise_path, "noise report of the gyros (noise.yaml, as allan writes it)");
  app.add_option("--scenario", scenario_name, "emulator scenario for the motion (name in config/scenarios or path)");
  app.add_option("--body-rate-deg-s", body_rate_deg_s, "or constant body rates relative to ENU")
      ->expected(3)
      ->type_name("X Y Z");
  app.add_option("--motion-bag", motion_bag, "or the angular rates a recording measured (sensor_msgs/Imu)");
  app.add_option("--motion-topic", motion_topic, "with --motion-bag: the IMU topic (default: the only one)");
  CLI::Option* start_option =
      app.add_option("--start-rpy-deg", start_rpy_deg,
                     "with --body-rate-deg-s or --motion-bag: the body's roll, pitch, yaw (ENU) at 0")
          ->expected(3)
          ->type_name("R P Y")
          ->capture_default_str();
  app.add_option("--latitude-deg", latitude, "with --body-rate-deg-s or --motion-bag: the site (Earth rate)")
      ->capture_default_str()
      ->check(latitude_deg());
  app.add_option("--duration-s", duration_s, "horizon (default: the scenario's duration, the recording's length)")
      ->check(positive());
  app.add_option("--step-s", step_s, "propagation step (default: the report's sample interval)")->check(positive());
  app.add_option("--output-interval-s", output_interval_s, "time between CSV rows")
      ->capture_default_str()
      ->check(positive());
  app.add_option("--turn-on-bias-rad-s", turn_on_bias_rad_s, "run-to-run bias, 1 sigma per axis (no AVAR shows it)")
      ->capture_default_str()
      ->check(non_negative());
  app.add_option("-o,--out", out_path, "CSV written (atomically)")->capture_default_str();
  if (const auto status = imu_lab::parse_tool_options("attitude_error_budget", app, argc, argv)) return *status;

  imu_lab::ToolInput input;
  input.kind = "noise report";
  input.path = noise_path;
  return imu_lab::run_tool_main("attitude_error_budget", input, [&] {
    if (noise_path.empty()) throw imu_lab::ConfigError("attitude_error_budget", "--noise", "give the noise report");
    if (!scenario_name.empty() + !body_rate_deg_s.empty() + !motion_bag.empty() != 1) {
      throw imu_lab::ConfigError("attitude_error_budget", "--scenario/--body-rate-deg-s/--motion-bag",
                                 "give exactly one of the three");
    }
    if (start_option->count() > 0 && !scenario_name.empty()) {
      throw imu_lab::ConfigError("attitude_error_budget", "--start-rpy-deg", "the scenario has its own attitude");
    }
    if (!motion_topic.empty() && motion_bag.empty()) {
      throw imu_lab::ConfigError("attitude_error_budget", "--motion-topic", "only with --motion-bag");
    }
    const auto gyros = imu_lab::pipeline::gyros_from_noise_report(noise_path, turn_on_bias_rad_s);
    double sample_interval_s = 0.0;
    for (const auto& gyro : gyros) sample_interval_s = std::max(sample_interval_s, gyro.sample_interval_s);
    if (step_s == 0.0) step_s = sample_interval_s;
    if (step_s < sample_interval_s * (1.0 - 1e-9)) {
      throw imu_lab::ConfigError("attitude_error_budget", "--step-s",
                                 "must be at least the report's sample interval, " + std::to_string(sample_interval_s) +
                                     " s (a white-angle term is per sample)");
    }
    std::vector<imu_lab::nav::AttitudeSample> motion;
    std::string described;
    imu_lab::emulator::ScenarioConfig site;  // where the body rates or the recording are
    site.latitude_rad = latitude * M_PI / 180.0;
    site.roll_rad = start_rpy_deg[0] * M_PI / 180.0;
    site.pitch_rad = start_rpy_deg[1] * M_PI / 180.0;
    site.yaw_rad = start_rpy_deg[2] * M_PI / 180.0;
    if (!scenario_name.empty()) {
      const std::string path = imu_lab::ros_io::resolve_config("scenarios", scenario_name);
      motion = imu_lab::pipeline::scenario_attitude_motion(imu_lab::emulator::load_scenario(path), duration_s, step_s);
      described = "scenario " + path;
    } else if (!motion_bag.empty()) {
      const imu_lab::ros_io::BagRecording bag(motion_bag);
      motion_topic = imu_lab::ros_io::choose_imu_topic(bag, motion_topic);
      std::vector<imu_lab::io::ImuRecord> records;
      imu_lab::ros_io::ImuTriadsNeeded needed;
      needed.specific_force = false;
      imu_lab::ros_io::StrictImuCheck check(needed);
      imu_lab::ros_io::for_each_imu_strictly(
          bag, motion_topic, [&](const imu_lab::io::ImuRecord& record) { records.push_back(record); }, &check);
      try {
        motion = imu_lab::pipeline::recorded_attitude_motion(records, site, duration_s, step_s);
      } catch (const std::invalid_argument& error) {
        throw imu_lab::InputError(bag.name() + " (" + motion_topic + "): " + error.what());
      }
      described = "rates of " + bag.name() + " " + motion_topic;
    } else {
      const Eigen::Vector3d rate_rad_s =
          Eigen::Vector3d(body_rate_deg_s[0], body_rate_deg_s[1], body_rate_deg_s[2]) * M_PI / 180.0;
      motion = imu_lab::pipeline::constant_rate_scenario_motion(site, rate_rad_s, duration_s, step_s);
      described = "constant body rate";
    }
    const int output_every = std::max(1, static_cast<int>(std::lround(output_interval_s / step_s)));
    std::vector<imu_lab::nav::AttitudeErrorPoint> points;
    try {
      points = imu_lab::nav::predict_attitude_error_growth(gyros, motion, output_every);
    } catch (const std::invalid_argument& error) {
      throw imu_lab::InputError(error.what());  // a term the prediction has no model for
    }
    imu_lab::write_file_atomically(out_path, imu_lab::pipeline::attitude_error_csv(points));
    std::cout << "attitude_error_budget: " << noise_path << ", " << described << ", " << motion.size() - 1
              << " steps of " << step_s << " s (largest turn per step "
              << imu_lab::pipeline::largest_step_turn_rad(motion) * 180.0 / M_PI << " deg)\n"
              << imu_lab::pipeline::attitude_error_summary(points) << "wrote " << out_path << "\n";
    return 0;
  });
}
