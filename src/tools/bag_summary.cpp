// bag_summary: what an IMU bag holds (samples, rate, per-axis mean and standard deviation) and
// its overlapping Allan deviation at a few taus from the batch reference, beside the analytic
// values of a sensor profile when one is given (e.g. the profile the bag was emulated with). Every
// sample is in it: where allan's screens would leave knocks or steps out, a note says so.
#include <CLI/CLI.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <numeric>
#include <tuple>

#include "imu_lab/allan/batch.h"
#include "imu_lab/allan/confidence.h"
#include "imu_lab/common/config_error.h"
#include "imu_lab/common/tool_main.h"
#include "imu_lab/common/tool_options.h"
#include "imu_lab/emulator/analytic_profile_avar.h"
#include "imu_lab/pipeline/unscreened_disturbances.h"
#include "imu_lab/ros_io/node/config_paths.h"
#include "imu_lab/ros_io/bag/imu_bag_reader.h"
#include "imu_lab/ros_io/bag/recording_arguments.h"
#include "imu_lab/ros_io/bag/strict_imu_reading.h"

namespace {

constexpr std::array<const char*, 6> kChannelNames = {"gyro_x", "gyro_y", "gyro_z", "accel_x", "accel_y", "accel_z"};
constexpr std::array<const char*, 6> kUnits = {"rad/s", "rad/s", "rad/s", "m/s^2", "m/s^2", "m/s^2"};

double mean_of(const std::vector<double>& values) {
  return std::accumulate(values.begin(), values.end(), 0.0) / values.size();
}

double standard_deviation(const std::vector<double>& values, double mean) {
  double sum = 0.0;
  for (double v : values) sum += (v - mean) * (v - mean);
  return std::sqrt(sum / (values.size() - 1));
}

// The median interval is the sample period even where samples are missing; an interval over
// kIrregularFactor periods (a gap, a slower rate) or under 1/kIrregularFactor (a faster rate) is
// irregular, which the batch Allan deviation cannot see.
constexpr double kIrregularFactor = 1.5;

struct SampleTiming {
  double tau0_s = 0.0;
  std::size_t irregular_count = 0;
  double shortest_interval_s = 0.0, longest_interval_s = 0.0;
};

SampleTiming timing_of(const std::vector<std::int64_t>& stamps_ns) {
  std::vector<double> intervals_s;
  for (std::size_t k = 1; k < stamps_ns.size(); ++k) intervals_s.push_back((stamps_ns[k] - stamps_ns[k - 1]) * 1e-9);
  SampleTiming timing;
  const auto [shortest, longest] = std::minmax_element(intervals_s.begin(), intervals_s.end());
  timing.shortest_interval_s = *shortest;
  timing.longest_interval_s = *longest;
  auto middle = intervals_s.begin() + intervals_s.size() / 2;
  std::nth_element(intervals_s.begin(), middle, intervals_s.end());
  timing.tau0_s = *middle;
  timing.irregular_count = std::count_if(intervals_s.begin(), intervals_s.end(), [&](double interval_s) {
    return interval_s > kIrregularFactor * timing.tau0_s || interval_s * kIrregularFactor < timing.tau0_s;
  });
  return timing;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Summarise an IMU bag: samples, rate, mean and deviation, Allan deviation at a few taus."};
  imu_lab::ros_io::RecordingArguments recording;
  std::string topic;
  std::string profile_name;
  std::vector<double> taus_s = {0.1, 1.0, 10.0, 100.0, 1000.0};
  imu_lab::ros_io::add_recording_arguments(app, recording, "bag to read", true);
  app.add_option("--topic", topic, "sensor_msgs/Imu topic (default: the only one in the bag)");
  app.add_option("--profile", profile_name, "sensor profile whose analytic ADEV to print beside the measured");
  app.add_option("--taus-s", taus_s, "averaging times [s]")
      ->capture_default_str()
      ->check(imu_lab::option_range::positive());
  if (const auto status = imu_lab::parse_tool_options("bag_summary", app, argc, argv)) return *status;

  imu_lab::ToolInput input = recording.tool_input(topic);
  return imu_lab::run_tool_main("bag_summary", input, [&] {
    const imu_lab::ros_io::BagRecording bag = recording.recording();
    const std::string bag_name = bag.name();
    input.topic = topic = imu_lab::ros_io::choose_imu_topic(bag, topic);
    std::array<std::vector<double>, 6> channels;
    std::vector<std::int64_t> stamps_ns;
    // A triad no message carries (covariance[0] = -1) is left out; one that some lack is refused.
    imu_lab::ros_io::StrictImuCheck check(imu_lab::ros_io::ImuTriadsNeeded{false, false});
    imu_lab::pipeline::DisturbanceFinder disturbances;  // what allan would leave out, to say so
    imu_lab::ros_io::for_each_imu_strictly(
        bag, topic,
        [&](const imu_lab::io::ImuRecord& record) {
          disturbances.push(record);
          stamps_ns.push_back(record.stamp_ns);
          for (int axis = 0; axis < 3; ++axis) {
            channels[axis].push_back(record.angular_rate_rad_s[axis]);
            channels[axis + 3].push_back(record.specific_force_m_s2[axis]);
          }
        },
        &check);
    std::array<bool, 6> present{};
    for (int c = 0; c < 6; ++c) {
      present[c] = c < 3 ? !check.angular_rate_absent_throughout() : !check.specific_force_absent_throughout();
    }
    for (const auto& [absent, triad, field] :
         {std::tuple{check.angular_rate_absent_throughout(), "gyro", "angular_velocity"},
          std::tuple{check.specific_force_absent_throughout(), "accelerometer", "linear_acceleration"}}) {
      if (absent) {
        std::fprintf(stderr,
                     "bag_summary: bag %s, topic %s: no message carries the %s triad (%s_covariance[0] = -1, "
                     "not provided by the driver): left out\n",
                     bag_name.c_str(), topic.c_str(), triad, field);
      }
    }
    const std::size_t count = channels[0].size();
    if (count < 3) throw imu_lab::InputError("bag " + bag_name + ": topic " + topic + " has too few messages");
    const SampleTiming timing = timing_of(stamps_ns);
    const double tau0_s = timing.tau0_s;
    std::printf("%s, topic %s: %zu samples over %.3f s, rate %.4f Hz (median interval)\n", bag_name.c_str(),
                topic.c_str(), count, (stamps_ns.back() - stamps_ns.front()) * 1e-9, 1.0 / tau0_s);
    if (timing.irregular_count > 0) {
      std::fprintf(stderr,
                   "bag_summary: warning: bag %s, topic %s: %zu intervals off the sample period by over a "
                   "factor %.1f (%.6g .. %.6g s): gaps or a rate change; the Allan deviation below assumes evenly "
                   "spaced samples (the allan tool splits the record at gaps)\n",
                   bag_name.c_str(), topic.c_str(), timing.irregular_count, kIrregularFactor,
                   timing.shortest_interval_s, timing.longest_interval_s);
    }

    std::optional<imu_lab::emulator::SensorProfile> profile;
    if (!profile_name.empty()) {
      profile = imu_lab::emulator::load_sensor_profile(imu_lab::ros_io::resolve_config("sensors", profile_name));
    }
    std::printf("\n%-8s %16s %16s  %s\n", "channel", "mean", "std", "unit");
    std::array<double, 6> means{};
    for (int c = 0; c < 6; ++c) {
      if (!present[c]) continue;
      means[c] = mean_of(channels[c]);
      std::printf("%-8s %16.9g %16.9g  %s\n", kChannelNames[c], means[c], standard_deviation(channels[c], means[c]),
                  kUnits[c]);
    }

    std::vector<int> factors;
    for (double tau : taus_s) {
      const int m = static_cast<int>(std::lround(tau / tau0_s));
      if (m >= 1 && 2 * static_cast<std::size_t>(m) < count) factors.push_back(m);
    }
    const std::string disturbance_note = imu_lab::pipeline::unscreened_disturbance_note(
        "bag_summary", disturbances.finish(), "the means, deviations and Allan deviations of this summary");
    if (!disturbance_note.empty()) std::printf("\n%s", disturbance_note.c_str());
    std::printf("\nOverlapping Allan deviation (batch reference, 68.3 %% chi-squared bounds)%s\n",
                profile ? " beside the profile's analytic value;\n'in 95 %' says whether the analytic value lies in "
                          "the measured point's 95 % chi-squared interval (about 1 point in 20 will not)"
                        : "");
    std::printf("%-8s %10s %14s %14s %14s %14s %8s\n", "channel", "tau_s", "measured", "lower", "upper",
                profile ? "analytic" : "", profile ? "in 95 %" : "");
    for (int c = 0; c < 6; ++c) {
      if (!present[c]) continue;
      std::vector<double> centred(channels[c]);
      for (double& v : centred) v -= means[c];  // keeps the integrated phase small (round-off)
      const auto phase = imu_lab::allan::phase_from_frequency(centred, tau0_s);
      const auto points =
          imu_lab::allan::evaluate(imu_lab::allan::Statistic::kOverlappingAllan, phase, tau0_s, factors);
      for (const auto& p : points) {
        std::printf("%-8s %10.4g %14.6g %14.6g %14.6g", kChannelNames[c], p.tau_s, p.deviation, p.deviation_lower,
                    p.deviation_upper);
        if (profile) {
          const auto& triad = c < 3 ? profile->gyro : profile->accelerometer;
          const double analytic = std::sqrt(imu_lab::emulator::analytic_axis_avar(triad, c % 3, p.tau_s, tau0_s));
          const auto wide = imu_lab::allan::chi_squared_bounds(p.deviation, p.edf, 0.95);
          const bool inside = analytic >= wide.lower && analytic <= wide.upper;
          std::printf(" %14.6g %8s", analytic, inside ? "yes" : "no");
        }
        std::printf("\n");
      }
    }
    return 0;
  });
}
