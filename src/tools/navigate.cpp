// navigate: bag -> strapdown navigation (static alignment, or a given start state, then free
// inertial navigation) -> trajectory CSV; with the emulator's /imu/truth in the bag, also the error
// against it (printed, written as a CSV beside the trajectory and, on request, plotted). The same
// NavigationSession as the strapdown_navigator node, so both give the same solution on the same
// bag. The start state defaults to the truth's where the bag has it: the position always, and
// without alignment the attitude (unless an angle is given) and the velocity.
#include <CLI/CLI.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "imu_lab/common/atomic_file.h"
#include "imu_lab/common/config_error.h"
#include "imu_lab/common/format_number.h"
#include "imu_lab/common/progress.h"
#include "imu_lab/common/stamps.h"
#include "imu_lab/common/tool_main.h"
#include "imu_lab/common/tool_options.h"
#include "imu_lab/nav/earth_model.h"
#include "imu_lab/pipeline/navigation_csv.h"
#include "imu_lab/ros_io/bag/bag_navigation.h"
#include "imu_lab/ros_io/bag/recording_arguments.h"
#include "imu_lab/ros_io/node/config_paths.h"

namespace {

using imu_lab::pipeline::kDegToRad;
constexpr double kArcsecPerRad = 180.0 / M_PI * 3600.0;
constexpr double kUnset = std::numeric_limits<double>::quiet_NaN();

struct CommandLine {
  imu_lab::ros_io::RecordingArguments recording;
  std::string out_path, errors_path, plot_path, noise_path;
  std::string input_type = "imu", heading_source = "gyrocompass", earth_model = "wgs84", vertical = "held";
  std::string initial_velocity;  // "east,north,up"
  double alignment_duration_s = 300.0, initial_roll_deg = 0.0, initial_pitch_deg = 0.0, initial_yaw_deg = 0.0;
  double latitude_deg = kUnset, longitude_deg = kUnset, height_m = kUnset, reference_height_m = kUnset;
  bool no_align = false, skip_bad_samples = false, no_coning_correction = false, no_sculling_correction = false;
  imu_lab::pipeline::ExpectedSensorErrors expected;
  // Options whose absence means something (take the truth's value, predict nothing); each
  // expected error with the field it sets, so that a given one wins over --noise's.
  std::vector<CLI::Option*> attitude_options;
  std::vector<std::pair<CLI::Option*, double imu_lab::pipeline::ExpectedSensorErrors::*>> expected_options;
  imu_lab::ros_io::BagNavigationOptions bag;
  imu_lab::pipeline::NavigationSettings settings;
  std::string initial_state_source;  // printed: where the start state came from
};

bool any_given(const std::vector<CLI::Option*>& options) {
  return std::any_of(options.begin(), options.end(), [](const CLI::Option* option) { return option->count() > 0; });
}

// The expected sensor errors: --noise's report first, then each one given on the command line over
// it; none at all without either.
std::optional<imu_lab::pipeline::ExpectedSensorErrors> expected_errors(const CommandLine& c) {
  const bool any_option = std::any_of(c.expected_options.begin(), c.expected_options.end(),
                                      [](const auto& option) { return option.first->count() > 0; });
  if (c.noise_path.empty() && !any_option) return std::nullopt;
  imu_lab::pipeline::ExpectedSensorErrors expected;
  if (!c.noise_path.empty()) expected = imu_lab::pipeline::expected_errors_from_noise_report(c.noise_path);
  for (const auto& [option, field] : c.expected_options) {
    if (option->count() > 0) expected.*field = c.expected.*field;
  }
  return expected;
}

// "east,north,up" in m/s: three finite numbers.
Eigen::Vector3d parse_velocity(const std::string& key, const std::string& text) {
  std::vector<std::string> fields(1);
  for (char ch : text) {
    if (ch == ',') {
      fields.emplace_back();
    } else {
      fields.back().push_back(ch);
    }
  }
  Eigen::Vector3d velocity;
  bool good = fields.size() == 3;
  for (std::size_t axis = 0; good && axis < 3; ++axis) {
    char* end = nullptr;
    velocity[axis] = std::strtod(fields[axis].c_str(), &end);
    good = !fields[axis].empty() && end == fields[axis].c_str() + fields[axis].size() && std::isfinite(velocity[axis]);
  }
  if (!good) {
    throw imu_lab::ConfigError(
        "navigate", key, "is '" + text + "'; give three finite numbers east,north,up in m/s (e.g. 0,0,0 at rest)");
  }
  return velocity;
}

void add_options(CLI::App& app, CommandLine& c) {
  imu_lab::ros_io::add_recording_arguments(app, c.recording, "bag to navigate", false);
  app.add_option("-o,--out", c.out_path, "trajectory CSV to write")->required();
  app.add_option("--errors-out", c.errors_path, "error CSV (default: <out>_errors.csv, only with truth)");
  app.add_option("--plot", c.plot_path, "also plot the errors into this PNG (scripts/plot_navigation.py)");
  app.add_option("--topic", c.bag.topic, "input topic (default: the bag's only one of the input type)");
  app.add_option("--input-type", c.input_type, "imu (sensor_msgs/Imu rates) or increment (imu_lab/ImuIncrement)")
      ->capture_default_str();
  app.add_option("--truth-topic", c.bag.truth_topic, "imu_lab/ImuTruth topic to compare with")->capture_default_str();
  app.add_option("--alignment-duration-s", c.alignment_duration_s, "static alignment length [s]")
      ->capture_default_str();
  app.add_option("--heading-source", c.heading_source, "gyrocompass or given (--initial-yaw-deg)")
      ->capture_default_str();
  app.add_flag("--no-align", c.no_align,
               "start from a given state at the first sample instead of aligning at rest (default: the truth's)");
  c.attitude_options = {
      app.add_option("--initial-roll-deg", c.initial_roll_deg, "given roll [deg] (with --no-align; default 0)"),
      app.add_option("--initial-pitch-deg", c.initial_pitch_deg, "given pitch [deg] (with --no-align; default 0)"),
      app.add_option("--initial-yaw-deg", c.initial_yaw_deg, "given yaw [deg], ENU: from east towards north")};
  app.add_option("--initial-velocity-enu-m-s", c.initial_velocity,
                 "east,north,up velocity at the first sample [m/s] (with --no-align; default: the truth's, required "
                 "without truth)");
  app.add_option("--latitude-deg", c.latitude_deg, "initial latitude (default: the truth's, if the bag has it)");
  app.add_option("--longitude-deg", c.longitude_deg, "initial longitude (default: the truth's)");
  app.add_option("--height-m", c.height_m, "initial height (default: the truth's)");
  app.add_option("--earth-model", c.earth_model, "wgs84 or sphere")->capture_default_str();
  app.add_option("--vertical", c.vertical, "vertical channel: free or held (at --reference-height-m)")
      ->capture_default_str();
  app.add_option("--reference-height-m", c.reference_height_m, "height the held channel holds (default: initial)");
  app.add_option("--gap-factor", c.settings.gap_factor, "interval over this many typical ones is a gap")
      ->capture_default_str();
  app.add_flag("--no-coning-correction", c.no_coning_correction, "leave the coning term out");
  app.add_flag("--no-sculling-correction", c.no_sculling_correction, "leave the sculling term out");
  using Expected = imu_lab::pipeline::ExpectedSensorErrors;
  app.add_option("--noise", c.noise_path,
                 "noise report (noise.yaml, as allan writes it) for the expected errors below: per triad the largest "
                 "axis's white noise density and, as the bias, its bias instability (a lower bound: no Allan curve "
                 "shows the turn-on bias); each option below given overrides its value");
  c.expected_options = {
      {app.add_option("--expected-gyro-bias-rad-s", c.expected.gyro_bias_rad_s,
                      "a priori gyro bias, 1 sigma per axis (for the predicted alignment error)"),
       &Expected::gyro_bias_rad_s},
      {app.add_option("--expected-accel-bias-m-s2", c.expected.accel_bias_m_s2,
                      "a priori accelerometer bias, 1 sigma per axis"),
       &Expected::accel_bias_m_s2},
      {app.add_option("--gyro-noise-density-rad-s-per-sqrt-hz", c.expected.gyro_noise_density_rad_s_per_sqrt_hz,
                      "gyro white noise (angle random walk)"),
       &Expected::gyro_noise_density_rad_s_per_sqrt_hz},
      {app.add_option("--accel-noise-density-m-s2-per-sqrt-hz", c.expected.accel_noise_density_m_s2_per_sqrt_hz,
                      "accelerometer white noise (velocity random walk)"),
       &Expected::accel_noise_density_m_s2_per_sqrt_hz}};
  app.add_option("--every-s", c.bag.output_interval_s, "write a row at most this often [s] (0: every sample)")
      ->capture_default_str()
      ->check(imu_lab::option_range::non_negative());
  app.add_flag("--skip-bad-samples", c.skip_bad_samples, "skip NaN/unordered samples instead of refusing the bag");
}

// Command line -> settings; the start state falls back to the bag's truth at the first sample.
void fill_settings(CommandLine& c) {
  using namespace imu_lab::ros_io;
  using namespace imu_lab::pipeline;
  c.bag.input_type = parse_input_type("--input-type", c.input_type);
  NavigationSettings& s = c.settings;
  s.align = !c.no_align;
  s.alignment.duration_s = c.alignment_duration_s;
  s.alignment.heading_source = parse_heading_source("--heading-source", c.heading_source);
  s.alignment.given_yaw_rad = c.initial_yaw_deg * kDegToRad;
  s.initial_roll_rad = c.initial_roll_deg * kDegToRad;
  s.initial_pitch_rad = c.initial_pitch_deg * kDegToRad;
  s.initial_yaw_rad = c.initial_yaw_deg * kDegToRad;
  const bool velocity_given = !c.initial_velocity.empty();
  if (velocity_given) s.initial_velocity_enu_m_s = parse_velocity("--initial-velocity-enu-m-s", c.initial_velocity);
  const bool position_given = !std::isnan(c.latitude_deg) && !std::isnan(c.longitude_deg) && !std::isnan(c.height_m);
  const bool attitude_given = any_given(c.attitude_options);
  const bool truth_wanted = !position_given || (c.no_align && (!attitude_given || !velocity_given));
  const auto truth = truth_wanted ? truth_at_start(c.recording.recording(), c.bag) : std::nullopt;
  if (!position_given && !truth) {
    throw imu_lab::ConfigError(
        "navigate", "--latitude-deg/--longitude-deg/--height-m",
        "the bag has no " + c.bag.truth_topic + " to take the initial position from; give all three");
  }
  // The truth's own values, not converted to degrees and back.
  s.latitude_rad = std::isnan(c.latitude_deg) ? truth->latitude_rad : c.latitude_deg * kDegToRad;
  s.longitude_rad = std::isnan(c.longitude_deg) ? truth->longitude_rad : c.longitude_deg * kDegToRad;
  s.height_m = std::isnan(c.height_m) ? truth->height_m : c.height_m;
  if (velocity_given && !c.no_align) {
    throw imu_lab::ConfigError("navigate", "--initial-velocity-enu-m-s",
                               "needs --no-align: a static alignment starts at rest");
  }
  if (c.no_align) {
    if (!velocity_given) {
      if (!truth) {
        throw imu_lab::ConfigError("navigate", "--initial-velocity-enu-m-s",
                                   "is required with --no-align when the bag has no " + c.bag.truth_topic +
                                       " to take it from: give east,north,up in m/s (0,0,0 if the IMU is at rest)");
      }
      s.initial_velocity_enu_m_s = truth->velocity_enu_m_s;
    }
    if (!attitude_given && truth) s.initial_attitude_body_to_enu = truth->q_body_to_enu;
    c.initial_state_source = std::string("attitude ") + (s.initial_attitude_body_to_enu ? "from the truth" : "given") +
                             ", velocity " + (velocity_given ? "given" : "from the truth") + ", position " +
                             (position_given ? "given" : "from the truth");
  }
  s.navigator.earth = parse_earth_model("--earth-model", c.earth_model);
  s.navigator.vertical.mode = parse_vertical_channel("--vertical", c.vertical);
  s.navigator.vertical.fixed_reference_height_m = std::isnan(c.reference_height_m) ? s.height_m : c.reference_height_m;
  s.navigator.corrections.coning_correction = !c.no_coning_correction;
  s.navigator.corrections.sculling_correction = !c.no_sculling_correction;
  s.expected_errors = expected_errors(c);
  validate(s, "navigate");
}

// The alignment's predicted 1-sigma error as far as it can be predicted (alignment_error_budget.h).
std::string predicted_error_text(const imu_lab::pipeline::AlignmentResult& a, bool expected_given) {
  const Eigen::Vector3d arcsec = a.predicted_error_sigma_rad * kArcsecPerRad;
  if (a.method == "given_attitude") return "no predicted error (attitude given, not estimated)";
  if (!expected_given) {
    return "no predicted error (give allan's noise report, --noise noise.yaml, or the expected sensor errors: "
           "--expected-gyro-bias-rad-s, --expected-accel-bias-m-s2, --gyro-noise-density-rad-s-per-sqrt-hz, "
           "--accel-noise-density-m-s2-per-sqrt-hz)";
  }
  const std::string tilts = imu_lab::format_number(arcsec.x(), 3) + " " + imu_lab::format_number(arcsec.y(), 3);
  if (!std::isfinite(arcsec.z()))
    return "predicted 1-sigma tilt error E/N " + tilts + " arcsec (heading given, not estimated)";
  return "predicted 1-sigma error E/N/U " + tilts + " " + imu_lab::format_number(arcsec.z(), 3) + " arcsec";
}

void print_summary(const CommandLine& c, const imu_lab::ros_io::BagNavigationResult& result) {
  const auto& n = result.counters;
  std::printf(
      "navigate: %s, topic %s: %zu messages, %llu used, skipped %llu invalid, %llu unordered, %llu after gaps\n",
      c.recording.recording().name().c_str(), result.topic.c_str(), result.messages,
      static_cast<unsigned long long>(n.used), static_cast<unsigned long long>(n.invalid),
      static_cast<unsigned long long>(n.unordered), static_cast<unsigned long long>(n.gaps));
  const auto& a = *result.alignment;
  std::printf("alignment (%s, %.1f s, ends %s): roll %.6f pitch %.6f yaw %.6f deg; %s\n", a.method.c_str(),
              a.duration_s, imu_lab::format_stamp_s(a.stamp_ns).c_str(), a.roll_pitch_yaw_rad.x() / kDegToRad,
              a.roll_pitch_yaw_rad.y() / kDegToRad, a.roll_pitch_yaw_rad.z() / kDegToRad,
              predicted_error_text(a, c.settings.expected_errors.has_value()).c_str());
  if (imu_lab::pipeline::heading_unobservable(a)) {
    const double horizontal_earth_rate_deg_h = imu_lab::nav::EarthModel(c.settings.navigator.earth).earth_rate_rad_s() *
                                               std::cos(c.settings.latitude_rad) / kDegToRad * 3600.0;
    std::printf(
        "navigate: heading not observable: its predicted 1-sigma error, %s deg, exceeds %.0f deg: gyrocompassing "
        "needs gyro errors well below the Earth rate's horizontal part (%.3g deg/h here), so the yaw above and every "
        "heading and position after it are not referenced to north\n",
        imu_lab::format_number(a.predicted_error_sigma_rad.z() / kDegToRad, 3).c_str(),
        imu_lab::pipeline::kUnobservableHeadingSigma_rad / kDegToRad, horizontal_earth_rate_deg_h);
  }
  if (!c.initial_state_source.empty()) {
    const Eigen::Vector3d& v = c.settings.initial_velocity_enu_m_s;
    std::printf("start without alignment (%s): velocity ENU %.6f %.6f %.6f m/s\n", c.initial_state_source.c_str(),
                v.x(), v.y(), v.z());
  }
  const auto& last = result.solutions.back();
  std::printf("final (%s): lat %.9f lon %.9f deg, height %.3f m, ENU %.3f %.3f %.3f m\n",
              imu_lab::format_stamp_s(last.stamp_ns).c_str(), last.latitude_rad / kDegToRad,
              last.longitude_rad / kDegToRad, last.height_m, last.position_enu_m.x(), last.position_enu_m.y(),
              last.position_enu_m.z());
  if (result.errors.empty()) return;
  double max_horizontal = 0.0, max_height = 0.0, max_attitude = 0.0;
  for (const auto& e : result.errors) {
    max_horizontal = std::max(max_horizontal, e.horizontal_position_error_m);
    max_height = std::max(max_height, std::abs(e.height_error_m));
    max_attitude = std::max(max_attitude, e.attitude_error_enu_rad.norm());
  }
  const auto& e = result.errors.back();
  std::printf(
      "error vs truth after %.1f s: horizontal position %.4f m (max %.4f), height %.4f m (max |%.4f|), "
      "attitude E/N/U %.3f %.3f %.3f arcsec (max |%.3f|)\n",
      e.time_since_alignment_s, e.horizontal_position_error_m, max_horizontal, e.height_error_m, max_height,
      e.attitude_error_enu_rad.x() * kArcsecPerRad, e.attitude_error_enu_rad.y() * kArcsecPerRad,
      e.attitude_error_enu_rad.z() * kArcsecPerRad, max_attitude * kArcsecPerRad);
}

std::string default_errors_path(const std::string& out_path) {
  const std::string suffix = ".csv";
  const bool has_suffix =
      out_path.size() > suffix.size() && out_path.compare(out_path.size() - suffix.size(), suffix.size(), suffix) == 0;
  return (has_suffix ? out_path.substr(0, out_path.size() - suffix.size()) : out_path) + "_errors.csv";
}

void plot(const std::string& errors_path, const std::string& png_path, const std::string& final_png_path) {
  const std::string problem = imu_lab::ros_io::run_plot_script("plot_navigation.py", {errors_path, png_path});
  if (!problem.empty())
    throw imu_lab::OutputError("cannot plot " + final_png_path + ": " + problem + "; nothing written");
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Strapdown navigation of an IMU bag: trajectory CSV, and errors against the truth if the bag has it."};
  CommandLine c;
  add_options(app, c);
  if (const auto status = imu_lab::parse_tool_options("navigate", app, argc, argv)) return *status;
  c.recording.on_progress = imu_lab::terminal_progress("navigate", "messages");
  imu_lab::ToolInput input = c.recording.tool_input(c.bag.topic);
  return imu_lab::run_tool_main("navigate", input, [&] {
    fill_settings(c);
    const auto result = imu_lab::ros_io::navigate_bag(c.recording.recording(), c.bag, c.settings);
    const auto& n = result.counters;
    if (!c.skip_bad_samples && n.invalid + n.unordered > 0) {
      throw imu_lab::InputError("bag " + c.recording.recording().name() + ", topic " + result.topic + ": " +
                                std::to_string(n.invalid) +
                                " samples with NaN/Inf, a value beyond +-1e100 or a bad interval and " +
                                std::to_string(n.unordered) + " unordered stamps, first " + result.first_problem +
                                "; nothing written (repair the bag, or pass --skip-bad-samples to skip them)");
    }
    print_summary(c, result);
    // Trajectory, errors and plot are one set: all new, or (on any failure) all as they were.
    imu_lab::OutputSet outputs;
    imu_lab::pipeline::write_trajectory_csv(outputs.stage(c.out_path), result.solutions);
    const std::string errors_path = c.errors_path.empty() ? default_errors_path(c.out_path) : c.errors_path;
    if (result.has_truth) {
      const std::string staged_errors = outputs.stage(errors_path);
      imu_lab::pipeline::write_error_csv(staged_errors, result.errors);
      if (!c.plot_path.empty()) plot(staged_errors, outputs.stage(c.plot_path), c.plot_path);
    } else {
      outputs.remove_at_commit(errors_path);  // an earlier run's, which would not belong to this trajectory
      if (!c.plot_path.empty())
        std::cerr << "navigate: no " << c.bag.truth_topic << " in the bag, so no error to plot\n";
    }
    outputs.commit();
    std::printf("navigate: wrote %s (%zu rows)\n", c.out_path.c_str(), result.solutions.size());
    if (result.has_truth) std::printf("navigate: wrote %s (%zu rows)\n", errors_path.c_str(), result.errors.size());
    if (result.has_truth && !c.plot_path.empty()) std::printf("navigate: wrote %s\n", c.plot_path.c_str());
    return 0;
  });
}
