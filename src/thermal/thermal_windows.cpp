#include "imu_lab/thermal/thermal_windows.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>

#include "imu_lab/common/config_error.h"
#include "imu_lab/common/stamps.h"

namespace imu_lab {
namespace thermal {
namespace {

std::string stale_message(const char* which, std::int64_t stamp_ns, double age_s, double max_age_s) {
  std::ostringstream text;
  text << std::fixed << std::setprecision(3) << "the " << which << " is stale at IMU stamp " << format_stamp_s(stamp_ns)
       << " s: the nearest reading is " << age_s << " s away (maximum age " << max_age_s
       << " s); check that the thermosensor was recorded through the whole test, or raise the maximum "
          "temperature age";
  return text.str();
}

Eigen::Vector3d spread(const Eigen::Vector3d& sum, const Eigen::Vector3d& square_sum, double count) {
  const Eigen::Vector3d mean = sum / count;
  return (square_sum / count - mean.cwiseProduct(mean)).cwiseMax(0.0).cwiseSqrt();
}

}  // namespace

ThermalWindowAverager::ThermalWindowAverager(const WindowSettings& settings, const TemperatureHistory& temperature,
                                             const TemperatureHistory* second_temperature,
                                             const RegimeIndicator* regime)
    : settings_(settings), temperature_(temperature), second_temperature_(second_temperature), regime_(regime) {}

void ThermalWindowAverager::add(const io::ImuRecord& reading) {
  if (first_stamp_ns_ && reading.stamp_ns <= last_stamp_ns_) {
    throw InputError("IMU stamps go backwards or repeat at " + format_stamp_s(reading.stamp_ns) + " s (previous " +
                     format_stamp_s(last_stamp_ns_) + " s); re-record or sort the bag by header stamp");
  }
  const auto temperature_c = temperature_.temperature_at(reading.stamp_ns, settings_.max_temperature_age_s);
  if (!temperature_c) {
    throw InputError(stale_message("temperature", reading.stamp_ns, temperature_.age_at(reading.stamp_ns),
                                   settings_.max_temperature_age_s));
  }
  std::optional<double> second_c;
  if (second_temperature_) {
    second_c = second_temperature_->temperature_at(reading.stamp_ns, settings_.max_temperature_age_s);
    if (!second_c) {
      throw InputError(stale_message("second temperature", reading.stamp_ns,
                                     second_temperature_->age_at(reading.stamp_ns), settings_.max_temperature_age_s));
    }
  }
  if (!first_stamp_ns_) first_stamp_ns_ = reading.stamp_ns;
  const double interval_s = seconds_between(last_stamp_ns_, reading.stamp_ns);
  last_stamp_ns_ = reading.stamp_ns;
  const double since_first_s = seconds_between(*first_stamp_ns_, reading.stamp_ns);
  const long index = static_cast<long>(std::floor(since_first_s / settings_.window_s));
  if (index != window_index_) {
    if (count_ > 0) close_window();
    window_index_ = index;
    count_ = 0;
    window_intervals_s_.clear();
    rate_offset_ = reading.angular_rate_rad_s;
    force_offset_ = reading.specific_force_m_s2;
    rate_sum_ = rate_square_sum_ = force_sum_ = force_square_sum_ = Eigen::Vector3d::Zero();
    stamp_sum_ = temperature_sum_ = rate_c_s_sum_ = second_sum_ = 0.0;
    dynamic_count_ = 0;
  }
  const Eigen::Vector3d rate = reading.angular_rate_rad_s - rate_offset_;
  const Eigen::Vector3d force = reading.specific_force_m_s2 - force_offset_;
  if (count_ > 0) window_intervals_s_.push_back(interval_s);
  ++count_;
  rate_sum_ += rate;
  rate_square_sum_ += rate.cwiseProduct(rate);
  force_sum_ += force;
  force_square_sum_ += force.cwiseProduct(force);
  stamp_sum_ += since_first_s;
  temperature_sum_ += *temperature_c;
  rate_c_s_sum_ += temperature_.rate_at(reading.stamp_ns, settings_.rate_window_s);
  if (second_c) second_sum_ += *second_c;
  if (regime_ && regime_->dynamic_at(reading.stamp_ns)) ++dynamic_count_;
}

void ThermalWindowAverager::close_window() {
  const double n = static_cast<double>(count_);
  ThermalWindow window;
  const double first_stamp_s = seconds_from_stamp_ns(*first_stamp_ns_);
  window.start_s = first_stamp_s + static_cast<double>(window_index_) * settings_.window_s;
  window.mid_stamp_s = first_stamp_s + stamp_sum_ / n;
  window.sample_count = count_;
  window.mean_angular_rate_rad_s = rate_offset_ + rate_sum_ / n;
  window.mean_specific_force_m_s2 = force_offset_ + force_sum_ / n;
  window.angular_rate_std_rad_s = spread(rate_sum_, rate_square_sum_, n);
  window.specific_force_std_m_s2 = spread(force_sum_, force_square_sum_, n);
  window.temperature_c = temperature_sum_ / n;
  window.rate_c_s = rate_c_s_sum_ / n;
  if (second_temperature_) window.second_temperature_c = second_sum_ / n;
  if (regime_) window.dynamic_fraction = static_cast<double>(dynamic_count_) / n;
  // The samples a full window holds, from the median interval: real stamps jitter (+-30 % is
  // common), and the smallest interval would ask for more samples than any window has.
  double expected = std::numeric_limits<double>::infinity();
  if (!window_intervals_s_.empty()) {
    auto middle = window_intervals_s_.begin() + window_intervals_s_.size() / 2;
    std::nth_element(window_intervals_s_.begin(), middle, window_intervals_s_.end());
    expected = settings_.window_s / *middle;
  }
  window.is_static = n >= settings_.min_fill_fraction * expected &&
                     window.angular_rate_std_rad_s.maxCoeff() < settings_.static_angular_rate_std_rad_s &&
                     window.specific_force_std_m_s2.maxCoeff() < settings_.static_specific_force_std_m_s2;
  windows_.push_back(window);
}

std::vector<ThermalWindow> ThermalWindowAverager::finish() {
  if (count_ > 0) close_window();
  count_ = 0;
  return std::move(windows_);
}

}  // namespace thermal
}  // namespace imu_lab
