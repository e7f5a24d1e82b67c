// SI and field units of the identified parameters. Values are SI inside; reports add the units
// the field uses (IEEE Std 952 / 1293 conventions), always with the unit in the key.
#pragma once

#include <string>
#include <vector>

#include "imu_lab/identify/noise_model.h"

namespace imu_lab {
namespace identify {

enum class SensorKind { kGyroscope, kAccelerometer };

// "gyro", "accel" (channel-name prefixes, as in io/stability_table.h).
std::string sensor_prefix(SensorKind sensor);
// Rate unit key: "rad_s" or "m_s2".
std::string rate_unit_key(SensorKind sensor);

namespace units {
constexpr double kPi = 3.14159265358979323846;
constexpr double kDegree_rad = kPi / 180.0;
constexpr double kArcsecond_rad = kDegree_rad / 3600.0;
constexpr double kHour_s = 3600.0;
constexpr double kSqrtHour_sqrt_s = 60.0;
constexpr double kStandardGravity_m_s2 = 9.80665;
constexpr double kMicroG_m_s2 = 1e-6 * kStandardGravity_m_s2;
// 1 deg/sqrt(h) = pi / 180 / 60 rad/sqrt(s) (= rad/s/sqrt(Hz)).
constexpr double kDegPerSqrtHour_rad_per_sqrt_s = kDegree_rad / kSqrtHour_sqrt_s;
constexpr double kDegPerHour_rad_s = kDegree_rad / kHour_s;
// 1 deg/h/sqrt(h) = pi / 180 / 3600 / 60 rad/s/sqrt(s).
constexpr double kDegPerHourPerSqrtHour_rad_s_per_sqrt_s = kDegPerHour_rad_s / kSqrtHour_sqrt_s;
// 1 m/s/sqrt(h) = 1/60 m/s^2/sqrt(Hz).
constexpr double kMeterPerSecondPerSqrtHour_m_s2_per_sqrt_hz = 1.0 / kSqrtHour_sqrt_s;
}  // namespace units

// One unit a quantity is reported in: field value = SI value * per_si.
struct UnitScale {
  std::string key;  // e.g. "deg_per_sqrt_h"
  double per_si = 1.0;
};

// The SI unit of a term's amplitude or shape, then the field's units. Shapes: T_c and beta in
// s, frequencies in Hz (SI only). The zero-DC family's sqrt(alpha) is reported in SI only.
std::vector<UnitScale> amplitude_units(SensorKind sensor, TermKind kind);
std::vector<UnitScale> shape_units(TermKind kind);
// The unit a term's amplitude is shown in to people: the first field unit after the SI one (SI
// if none).
UnitScale field_amplitude_unit(SensorKind sensor, TermKind kind);

}  // namespace identify
}  // namespace imu_lab
