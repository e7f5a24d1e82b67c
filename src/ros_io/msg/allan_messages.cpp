#include "imu_lab/ros_io/msg/allan_messages.h"

#include <limits>
#include <map>

namespace imu_lab {
namespace ros_io {

imu_lab::AllanDeviation to_allan_deviation(const allan::StreamingSnapshot& snapshot, allan::Statistic statistic,
                                           AllanTriad triad, double confidence, const std_msgs::Header& header) {
  const std::size_t first_channel = triad == AllanTriad::kGyro ? 0 : 3;
  imu_lab::AllanDeviation message;
  message.header = header;
  message.statistic = allan::statistic_name(statistic);
  message.sensor = triad == AllanTriad::kGyro ? "gyro" : "accel";
  message.unit = triad == AllanTriad::kGyro ? "rad/s" : "m/s^2";
  message.tau0_s = snapshot.timing.tau0_s;
  message.confidence = confidence;
  message.samples = static_cast<std::uint64_t>(snapshot.timing.input_sample_count);

  std::map<int, double> tau_by_factor;
  for (std::size_t axis = 0; axis < 3; ++axis) {
    for (const auto& point : snapshot.curve(statistic, first_channel + axis)) {
      tau_by_factor[point.averaging_factor] = point.tau_s;
    }
  }
  std::map<int, std::size_t> index_by_factor;
  for (const auto& entry : tau_by_factor) {
    index_by_factor[entry.first] = message.tau_s.size();
    message.tau_s.push_back(entry.second);
  }
  const std::size_t count = message.tau_s.size();
  const double missing = std::numeric_limits<double>::quiet_NaN();
  for (std::size_t axis = 0; axis < 3; ++axis) {
    imu_lab::AllanAxis out;
    out.axis = std::string(1, static_cast<char>('x' + axis));
    out.deviation.assign(count, missing);
    out.lower.assign(count, missing);
    out.upper.assign(count, missing);
    out.edf.assign(count, missing);
    out.term_count.assign(count, 0);
    out.alpha.assign(count, 0);
    for (const auto& point : snapshot.curve(statistic, first_channel + axis)) {
      const std::size_t i = index_by_factor.at(point.averaging_factor);
      out.deviation[i] = point.deviation;
      out.lower[i] = point.deviation_lower;
      out.upper[i] = point.deviation_upper;
      out.edf[i] = point.edf;
      out.term_count[i] = point.term_count;
      out.alpha[i] = static_cast<std::int8_t>(point.alpha);
    }
    message.axes.push_back(out);
  }
  return message;
}

}  // namespace ros_io
}  // namespace imu_lab
