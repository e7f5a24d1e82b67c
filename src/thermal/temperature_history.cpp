#include "imu_lab/thermal/temperature_history.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace imu_lab {
namespace thermal {

bool TemperatureHistory::add(double stamp_s, double temperature_c) {
  if (!std::isfinite(stamp_s) || !std::isfinite(temperature_c)) return false;
  if (!stamps_s_.empty() && !(stamp_s > stamps_s_.back())) return false;
  const double previous_sum = running_sums_c_.empty() ? dropped_sum_c_ : running_sums_c_.back();
  stamps_s_.push_back(stamp_s);
  temperatures_c_.push_back(temperature_c);
  running_sums_c_.push_back(previous_sum + temperature_c);
  return true;
}

std::size_t TemperatureHistory::first_after(double stamp_s) const {
  return static_cast<std::size_t>(std::upper_bound(stamps_s_.begin(), stamps_s_.end(), stamp_s) - stamps_s_.begin());
}

double TemperatureHistory::sum_before(std::size_t index) const {
  return index == 0 ? dropped_sum_c_ : running_sums_c_[index - 1];
}

double TemperatureHistory::age_at(double stamp_s) const {
  if (stamps_s_.empty()) return std::numeric_limits<double>::infinity();
  const std::size_t after = first_after(stamp_s);
  double age = std::numeric_limits<double>::infinity();
  if (after < stamps_s_.size()) age = stamps_s_[after] - stamp_s;
  if (after > 0) age = std::min(age, stamp_s - stamps_s_[after - 1]);
  return age;
}

std::optional<double> TemperatureHistory::temperature_at(double stamp_s, double max_age_s) const {
  if (!(age_at(stamp_s) <= max_age_s)) return std::nullopt;
  const std::size_t after = first_after(stamp_s);
  if (after == 0) return temperatures_c_.front();
  if (after == stamps_s_.size()) return temperatures_c_.back();
  const double t0 = stamps_s_[after - 1], t1 = stamps_s_[after];
  const double weight = (stamp_s - t0) / (t1 - t0);
  return temperatures_c_[after - 1] + weight * (temperatures_c_[after] - temperatures_c_[after - 1]);
}

double TemperatureHistory::rate_at(double stamp_s, double window_s) const {
  const double half_s = 0.5 * window_s;
  const std::size_t start = first_after(stamp_s - window_s);
  const std::size_t middle = first_after(stamp_s - half_s);
  const std::size_t end = first_after(stamp_s);
  if (middle <= start || end <= middle) return 0.0;
  const double earlier_mean_c = (sum_before(middle) - sum_before(start)) / static_cast<double>(middle - start);
  const double later_mean_c = (sum_before(end) - sum_before(middle)) / static_cast<double>(end - middle);
  return (later_mean_c - earlier_mean_c) / half_s;
}

void TemperatureHistory::drop_before(double stamp_s) {
  while (stamps_s_.size() > 1 && stamps_s_[1] < stamp_s) {
    dropped_sum_c_ = running_sums_c_.front();
    stamps_s_.pop_front();
    temperatures_c_.pop_front();
    running_sums_c_.pop_front();
  }
}

}  // namespace thermal
}  // namespace imu_lab
