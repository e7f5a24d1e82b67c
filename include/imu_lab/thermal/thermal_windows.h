// Averaging windows of a thermal test: the IMU samples are averaged over fixed windows (so the
// fit sees the noise floor of the window, not of one sample), each sample's temperature taken
// from the thermosensor history at the sample's own stamp. Windows during a move (rotation to
// the next position) are marked not static and left out of the fit.
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "imu_lab/io/imu_records.h"
#include "imu_lab/thermal/temperature_history.h"
#include "imu_lab/thermal/thermal_regime.h"

namespace imu_lab {
namespace thermal {

struct ThermalWindow {
  double start_s = 0.0;      // header stamp in seconds (common/stamps.h); window [start, start + window)
  double mid_stamp_s = 0.0;  // the mean stamp of its samples, in seconds
  std::size_t sample_count = 0;
  Eigen::Vector3d mean_angular_rate_rad_s = Eigen::Vector3d::Zero();
  Eigen::Vector3d mean_specific_force_m_s2 = Eigen::Vector3d::Zero();
  Eigen::Vector3d angular_rate_std_rad_s = Eigen::Vector3d::Zero();
  Eigen::Vector3d specific_force_std_m_s2 = Eigen::Vector3d::Zero();
  double temperature_c = 0.0;  // means over the window's samples
  double rate_c_s = 0.0;
  std::optional<double> second_temperature_c;
  // Fraction of its samples in the dynamic regime (thermal_regime.h), when averaged with the indicator.
  std::optional<double> dynamic_fraction;
  bool is_static = false;
};

struct WindowSettings {
  double window_s = 60.0;
  double rate_window_s = 60.0;
  double max_temperature_age_s = 1.0;
  // A window is static when every axis's sample spread stays below these (a move of a few
  // degrees per second, or a change of orientation, exceeds them by far).
  double static_angular_rate_std_rad_s = 0.005;
  double static_specific_force_std_m_s2 = 0.05;
  // of the samples the window should hold at its median sample interval (robust to stamp jitter;
  // a gap leaves the window short of samples and so not static)
  double min_fill_fraction = 0.9;
};

class ThermalWindowAverager {
 public:
  // The histories and the indicator must outlive the averager; `second` and `regime` may be null.
  ThermalWindowAverager(const WindowSettings& settings, const TemperatureHistory& temperature,
                        const TemperatureHistory* second_temperature, const RegimeIndicator* regime = nullptr);

  // Samples in stamp order. Throws InputError when the temperature is stale at the sample's
  // stamp (no reading within max_temperature_age_s) or stamps go backwards.
  void add(const io::ImuRecord& reading);
  // Closes the last window and returns all of them.
  std::vector<ThermalWindow> finish();

 private:
  void close_window();

  WindowSettings settings_;
  const TemperatureHistory& temperature_;
  const TemperatureHistory* second_temperature_;
  const RegimeIndicator* regime_;
  std::vector<ThermalWindow> windows_;
  std::optional<std::int64_t> first_stamp_ns_;
  std::int64_t last_stamp_ns_ = 0;
  std::vector<double> window_intervals_s_;  // between the current window's samples, for the fill check
  long window_index_ = -1;
  std::size_t count_ = 0;
  Eigen::Vector3d rate_sum_, rate_square_sum_, force_sum_, force_square_sum_;
  Eigen::Vector3d rate_offset_, force_offset_;  // first sample of the window, against cancellation
  // stamp_sum_: seconds after first_stamp_ns_
  double stamp_sum_ = 0.0, temperature_sum_ = 0.0, rate_c_s_sum_ = 0.0, second_sum_ = 0.0;
  std::size_t dynamic_count_ = 0;
};

}  // namespace thermal
}  // namespace imu_lab
