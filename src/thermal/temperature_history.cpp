#include "imu_lab/thermal/temperature_history.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "imu_lab/common/stamps.h"

namespace imu_lab {
namespace thermal {

bool TemperatureHistory::add(std::int64_t stamp_ns, double temperature_c) {
  if (!std::isfinite(temperature_c)) return false;
  if (!stamps_ns_.empty() && !(stamp_ns > stamps_ns_.back())) return false;
  const double previous_sum = running_sums_c_.empty() ? dropped_sum_c_ : running_sums_c_.back();
  stamps_ns_.push_back(stamp_ns);
  temperatures_c_.push_back(temperature_c);
  running_sums_c_.push_back(previous_sum + temperature_c);
  return true;
}

std::size_t TemperatureHistory::first_after(std::int64_t stamp_ns) const {
  return static_cast<std::size_t>(std::upper_bound(stamps_ns_.begin(), stamps_ns_.end(), stamp_ns) -
                                  stamps_ns_.begin());
}

double TemperatureHistory::sum_before(std::size_t index) const {
  return index == 0 ? dropped_sum_c_ : running_sums_c_[index - 1];
}

double TemperatureHistory::age_at(std::int64_t stamp_ns) const {
  if (stamps_ns_.empty()) return std::numeric_limits<double>::infinity();
  const std::size_t after = first_after(stamp_ns);
  double age_s = std::numeric_limits<double>::infinity();
  if (after < stamps_ns_.size()) age_s = seconds_between(stamp_ns, stamps_ns_[after]);
  if (after > 0) age_s = std::min(age_s, seconds_between(stamps_ns_[after - 1], stamp_ns));
  return age_s;
}

std::optional<double> TemperatureHistory::temperature_at(std::int64_t stamp_ns, double max_age_s) const {
  if (!(age_at(stamp_ns) <= max_age_s)) return std::nullopt;
  const std::size_t after = first_after(stamp_ns);
  if (after == 0) return temperatures_c_.front();
  if (after == stamps_ns_.size()) return temperatures_c_.back();
  const std::int64_t t0_ns = stamps_ns_[after - 1], t1_ns = stamps_ns_[after];
  const double weight = static_cast<double>(stamp_ns - t0_ns) / static_cast<double>(t1_ns - t0_ns);
  return temperatures_c_[after - 1] + weight * (temperatures_c_[after] - temperatures_c_[after - 1]);
}

double TemperatureHistory::rate_at(std::int64_t stamp_ns, double window_s) const {
  const double half_s = 0.5 * window_s;
  const std::size_t start = first_after(stamp_ns - stamp_ns_from_seconds(window_s));
  const std::size_t middle = first_after(stamp_ns - stamp_ns_from_seconds(half_s));
  const std::size_t end = first_after(stamp_ns);
  if (middle <= start || end <= middle) return 0.0;
  const double earlier_mean_c = (sum_before(middle) - sum_before(start)) / static_cast<double>(middle - start);
  const double later_mean_c = (sum_before(end) - sum_before(middle)) / static_cast<double>(end - middle);
  return (later_mean_c - earlier_mean_c) / half_s;
}

double TemperatureHistory::second_derivative_at(std::int64_t stamp_ns, double window_s) const {
  const double third_s = window_s / 3.0;
  std::size_t bounds[4];
  for (int k = 0; k < 4; ++k) bounds[k] = first_after(stamp_ns - stamp_ns_from_seconds((3 - k) * third_s));
  // Only a window the record covers whole: at its start a short first third is the mean of a few
  // readings, and its noise crossed a threshold set from the full windows' noise.
  if (bounds[0] == 0) return 0.0;
  double means_c[3];
  for (int k = 0; k < 3; ++k) {
    if (bounds[k + 1] <= bounds[k]) return 0.0;
    means_c[k] = (sum_before(bounds[k + 1]) - sum_before(bounds[k])) / static_cast<double>(bounds[k + 1] - bounds[k]);
  }
  return (means_c[2] - 2.0 * means_c[1] + means_c[0]) / (third_s * third_s);
}

void TemperatureHistory::drop_before(std::int64_t stamp_ns) {
  while (stamps_ns_.size() > 1 && stamps_ns_[1] < stamp_ns) {
    dropped_sum_c_ = running_sums_c_.front();
    stamps_ns_.pop_front();
    temperatures_c_.pop_front();
    running_sums_c_.pop_front();
  }
}

}  // namespace thermal
}  // namespace imu_lab
