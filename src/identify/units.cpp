#include "imu_lab/identify/units.h"

namespace imu_lab {
namespace identify {

std::string sensor_prefix(SensorKind sensor) { return sensor == SensorKind::kGyroscope ? "gyro" : "accel"; }

std::string rate_unit_key(SensorKind sensor) { return sensor == SensorKind::kGyroscope ? "rad_s" : "m_s2"; }

namespace {
using namespace units;

struct TermUnits {
  TermKind kind;
  std::vector<UnitScale> gyro;
  std::vector<UnitScale> accel;
};

// SI unit first, then the field's units (field value = SI value * per_si).
const std::vector<TermUnits>& unit_table() {
  static const std::vector<TermUnits> table = {
      {TermKind::kWhiteAngle,
       {{"rad", 1.0}, {"arcsec", 1.0 / kArcsecond_rad}, {"microrad", 1e6}},
       {{"m_s", 1.0}, {"mm_s", 1e3}}},
      {TermKind::kWhiteRate,
       {{"rad_s_per_sqrt_hz", 1.0},
        {"deg_per_sqrt_h", 1.0 / kDegPerSqrtHour_rad_per_sqrt_s},
        {"deg_s_per_sqrt_hz", 1.0 / kDegree_rad}},
       {{"m_s2_per_sqrt_hz", 1.0},
        {"m_s_per_sqrt_h", 1.0 / kMeterPerSecondPerSqrtHour_m_s2_per_sqrt_hz},
        {"micro_g_per_sqrt_hz", 1.0 / kMicroG_m_s2}}},
      {TermKind::kBiasInstability,
       {{"rad_s", 1.0}, {"deg_h", 1.0 / kDegPerHour_rad_s}},
       {{"m_s2", 1.0}, {"micro_g", 1.0 / kMicroG_m_s2}}},
      {TermKind::kRandomWalk,
       {{"rad_s_per_sqrt_s", 1.0}, {"deg_h_per_sqrt_h", 1.0 / kDegPerHourPerSqrtHour_rad_s_per_sqrt_s}},
       {{"m_s2_per_sqrt_s", 1.0},
        {"m_s_per_h_per_sqrt_h", kHour_s * kSqrtHour_sqrt_s},
        {"micro_g_per_sqrt_s", 1.0 / kMicroG_m_s2}}},
      {TermKind::kRateRamp,
       {{"rad_s2", 1.0}, {"deg_h_per_h", kHour_s / kDegPerHour_rad_s}},
       {{"m_s3", 1.0}, {"micro_g_per_h", kHour_s / kMicroG_m_s2}}},
      {TermKind::kZeroDcFamily, {{"rad_s_per_hz_1_5", 1.0}}, {{"m_s2_per_hz_1_5", 1.0}}},
  };
  return table;
}

// Markov flanks are densities like N; sinusoid and resonance amplitudes are rates like B.
TermKind unit_twin(TermKind kind) {
  if (kind == TermKind::kMarkov || kind == TermKind::kHighPassWhite) return TermKind::kWhiteRate;
  if (kind == TermKind::kZeroDcGaussian) return TermKind::kZeroDcFamily;
  if (kind == TermKind::kSinusoid || kind == TermKind::kResonance) return TermKind::kBiasInstability;
  return kind;
}
}  // namespace

std::vector<UnitScale> amplitude_units(SensorKind sensor, TermKind kind) {
  for (const TermUnits& row : unit_table()) {
    if (row.kind == unit_twin(kind)) {
      return sensor == SensorKind::kGyroscope ? row.gyro : row.accel;
    }
  }
  return {};
}

std::vector<UnitScale> shape_units(TermKind kind) {
  switch (kind) {
    case TermKind::kMarkov:
    case TermKind::kZeroDcFamily: return {{"s", 1.0}};
    case TermKind::kZeroDcGaussian: return {{"s2", 1.0}};
    case TermKind::kHighPassWhite:
    case TermKind::kSinusoid:
    case TermKind::kBiasInstability:
    case TermKind::kResonance:
    case TermKind::kWhiteRate:  // the front end's corner
      return {{"hz", 1.0}};
    default: return {};
  }
}

UnitScale field_amplitude_unit(SensorKind sensor, TermKind kind) {
  const auto units = amplitude_units(sensor, kind);
  if (units.empty()) return {"si", 1.0};
  return units.size() > 1 ? units[1] : units[0];
}

}  // namespace identify
}  // namespace imu_lab
