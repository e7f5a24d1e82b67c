#include "imu_lab/thermal/thermal_regime.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

#include "imu_lab/common/format_number.h"
#include "imu_lab/common/stamps.h"

namespace imu_lab {
namespace thermal {
namespace {

constexpr std::int64_t kNever = std::numeric_limits<std::int64_t>::min();
constexpr double kNoiseSigmas = 5.0;   // a steady temperature crosses 5 sigma once in ~3.5 million estimates
constexpr double kPeakFraction = 0.1;  // 20 dB below the sharpest transition

}  // namespace

void check_regime_settings(const RegimeSwitchSettings& settings) {
  if (!(settings.threshold_c_s2 > 0.0) || !std::isfinite(settings.threshold_c_s2)) {
    throw std::invalid_argument(
        "regime switch: the threshold on |d2T/dt2| must be a positive number of degC/s^2, got " +
        format_number(settings.threshold_c_s2, 4));
  }
  if (!(settings.window_s > 0.0) || !std::isfinite(settings.window_s)) {
    throw std::invalid_argument("regime switch: the second-derivative window must be positive, got " +
                                format_number(settings.window_s, 4) + " s");
  }
  if (!(settings.hold_s >= 0.0) || !std::isfinite(settings.hold_s)) {
    throw std::invalid_argument("regime switch: the hold time must be 0 s or more, got " +
                                format_number(settings.hold_s, 4) + " s");
  }
}

RegimeIndicator::RegimeIndicator(const RegimeSwitchSettings& settings) : settings_(settings) {
  check_regime_settings(settings_);
}

void RegimeIndicator::add(std::int64_t stamp_ns, double second_derivative_c_s2) {
  if (!stamps_ns_.empty() && stamp_ns <= stamps_ns_.back()) return;  // the history refused it too
  const bool over = std::abs(second_derivative_c_s2) > settings_.threshold_c_s2;
  const std::int64_t previous = last_over_ns_.empty() ? kNever : last_over_ns_.back();
  stamps_ns_.push_back(stamp_ns);
  over_.push_back(over);
  last_over_ns_.push_back(over ? stamp_ns : previous);
  if (over) ++over_threshold_count_;
}

void RegimeIndicator::update(const TemperatureHistory& history) {
  if (history.empty()) return;
  const std::int64_t stamp_ns = history.newest_stamp_ns();
  add(stamp_ns, history.second_derivative_at(stamp_ns, settings_.window_s));
}

void RegimeIndicator::update_all(const TemperatureHistory& history) {
  for (std::size_t i = 0; i < history.size(); ++i) {
    const std::int64_t stamp_ns = history.stamp_ns_at(i);
    add(stamp_ns, history.second_derivative_at(stamp_ns, settings_.window_s));
  }
}

bool RegimeIndicator::dynamic_at(std::int64_t stamp_ns) const {
  const auto after = std::upper_bound(stamps_ns_.begin(), stamps_ns_.end(), stamp_ns);
  if (after == stamps_ns_.begin()) return false;
  const std::size_t index = static_cast<std::size_t>(after - stamps_ns_.begin()) - 1;
  if (over_[index]) return true;
  const std::int64_t last_ns = last_over_ns_[index];
  return last_ns != kNever && seconds_between(last_ns, stamp_ns) <= settings_.hold_s;
}

void RegimeIndicator::drop_before(std::int64_t stamp_ns) {
  while (stamps_ns_.size() > 1 && stamps_ns_[1] < stamp_ns) {
    stamps_ns_.pop_front();
    over_.pop_front();
    last_over_ns_.pop_front();
  }
}

std::string RegimeThresholdSuggestion::text() const {
  return "threshold " + format_number(threshold_c_s2, 3) + " degC/s^2 (the larger of 5 x the estimate's noise " +
         format_number(noise_c_s2, 3) + " and 0.1 x the largest |d2T/dt2| " + format_number(peak_c_s2, 3) + ")";
}

RegimeThresholdSuggestion suggest_regime_threshold(const TemperatureHistory& history, double window_s) {
  RegimeThresholdSuggestion out;
  const std::size_t n = history.size();
  if (n < 3) return out;
  double square = 0.0;
  std::vector<double> intervals_s;
  for (std::size_t i = 1; i + 1 < n; ++i) {
    const double second =
        history.temperature_c_at(i + 1) - 2.0 * history.temperature_c_at(i) + history.temperature_c_at(i - 1);
    square += second * second;
    intervals_s.push_back(seconds_between(history.stamp_ns_at(i), history.stamp_ns_at(i + 1)));
  }
  const double sigma_reading_c = std::sqrt(square / (6.0 * static_cast<double>(n - 2)));
  auto middle = intervals_s.begin() + intervals_s.size() / 2;
  std::nth_element(intervals_s.begin(), middle, intervals_s.end());
  const double third_s = window_s / 3.0;
  const double per_third = std::max(1.0, third_s / std::max(*middle, 1e-9));
  out.noise_c_s2 = std::sqrt(6.0 / per_third) * sigma_reading_c / (third_s * third_s);
  for (std::size_t i = 0; i < n; ++i) {
    out.peak_c_s2 = std::max(out.peak_c_s2, std::abs(history.second_derivative_at(history.stamp_ns_at(i), window_s)));
  }
  out.threshold_c_s2 = std::max(kNoiseSigmas * out.noise_c_s2, kPeakFraction * out.peak_c_s2);
  return out;
}

}  // namespace thermal
}  // namespace imu_lab
