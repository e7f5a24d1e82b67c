#include "imu_lab/identify/units.h"

namespace imu_lab {
namespace identify {

std::string sensor_prefix(SensorKind sensor) {
  return sensor == SensorKind::kGyroscope ? "gyro" : "accel";
}

std::string rate_unit_key(SensorKind sensor) {
  return sensor == SensorKind::kGyroscope ? "rad_s" : "m_s2";
}

namespace {
using namespace units;

std::vector<UnitScale> gyro_amplitude_units(TermKind kind) {
  switch (kind) {
    case TermKind::kWhiteAngle:
      return {{"rad", 1.0}, {"arcsec", 1.0 / kArcsecond_rad}, {"microrad", 1e6}};
    case TermKind::kWhiteRate:
    case TermKind::kMarkov:
      return {{"rad_s_per_sqrt_hz", 1.0},
              {"deg_per_sqrt_h", 1.0 / kDegPerSqrtHour_rad_per_sqrt_s},
              {"deg_s_per_sqrt_hz", 1.0 / kDegree_rad}};
    case TermKind::kBiasInstability:
    case TermKind::kSinusoid:
      return {{"rad_s", 1.0}, {"deg_h", 1.0 / kDegPerHour_rad_s}};
    case TermKind::kRandomWalk:
      return {{"rad_s_per_sqrt_s", 1.0},
              {"deg_h_per_sqrt_h", 1.0 / kDegPerHourPerSqrtHour_rad_s_per_sqrt_s}};
    case TermKind::kRateRamp:
      return {{"rad_s2", 1.0}, {"deg_h_per_h", kHour_s / kDegPerHour_rad_s}};
    case TermKind::kZeroDcFamily:
      return {{"rad_s_per_hz_1_5", 1.0}};
  }
  return {};
}

std::vector<UnitScale> accel_amplitude_units(TermKind kind) {
  switch (kind) {
    case TermKind::kWhiteAngle:
      return {{"m_s", 1.0}, {"mm_s", 1e3}};
    case TermKind::kWhiteRate:
    case TermKind::kMarkov:
      return {{"m_s2_per_sqrt_hz", 1.0},
              {"m_s_per_sqrt_h", 1.0 / kMeterPerSecondPerSqrtHour_m_s2_per_sqrt_hz},
              {"micro_g_per_sqrt_hz", 1.0 / kMicroG_m_s2}};
    case TermKind::kBiasInstability:
    case TermKind::kSinusoid:
      return {{"m_s2", 1.0}, {"micro_g", 1.0 / kMicroG_m_s2}};
    case TermKind::kRandomWalk:
      return {{"m_s2_per_sqrt_s", 1.0},
              {"m_s_per_h_per_sqrt_h", kHour_s * kSqrtHour_sqrt_s},
              {"micro_g_per_sqrt_s", 1.0 / kMicroG_m_s2}};
    case TermKind::kRateRamp:
      return {{"m_s3", 1.0}, {"micro_g_per_h", kHour_s / kMicroG_m_s2}};
    case TermKind::kZeroDcFamily:
      return {{"m_s2_per_hz_1_5", 1.0}};
  }
  return {};
}
}  // namespace

std::vector<UnitScale> amplitude_units(SensorKind sensor, TermKind kind) {
  return sensor == SensorKind::kGyroscope ? gyro_amplitude_units(kind)
                                          : accel_amplitude_units(kind);
}

std::vector<UnitScale> shape_units(TermKind kind) {
  switch (kind) {
    case TermKind::kMarkov:
    case TermKind::kZeroDcFamily:
      return {{"s", 1.0}};
    case TermKind::kSinusoid:
    case TermKind::kBiasInstability:
      return {{"hz", 1.0}};
    default:
      return {};
  }
}

}  // namespace identify
}  // namespace imu_lab
