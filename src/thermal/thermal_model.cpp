#include "imu_lab/thermal/thermal_model.h"

#include <algorithm>
#include <stdexcept>

#include "imu_lab/common/format_number.h"

namespace imu_lab {
namespace thermal {
namespace {

double clamp_flagged(double value, double low, double high, bool* clamped) {
  const double inside = std::clamp(value, low, high);
  if (inside != value) *clamped = true;
  return inside;
}

Eigen::Vector3d correct_triad(const ThermalModel& model, const TriadThermalTerms& triad, const Eigen::Vector3d& raw,
                              const ThermalInput& input) {
  Eigen::Vector3d corrected;
  for (int axis = 0; axis < 3; ++axis) {
    corrected[axis] =
        (raw[axis] - axis_delta_bias(model, triad[axis], input)) / (1.0 + axis_delta_scale(model, triad[axis], input));
  }
  return corrected;
}

}  // namespace

double polynomial_without_constant(const std::vector<double>& coefficients, double x) {
  double sum = 0.0;  // Horner on x (c0 + x (c1 + ...))
  for (auto it = coefficients.rbegin(); it != coefficients.rend(); ++it) sum = (sum + *it) * x;
  return sum;
}

std::string validity_range_text(const ThermalModel& model) {
  const ThermalValidity& box = model.validity;
  std::string text =
      format_number(box.temperature_min_c, 4) + " .. " + format_number(box.temperature_max_c, 4) + " degC";
  if (model.uses_temperature_rate) {
    text += ", " + format_number(box.rate_min_c_s, 4) + " .. " + format_number(box.rate_max_c_s, 4) + " degC/s";
  }
  if (model.uses_second_sensor) {
    text += ", second sensor " + format_number(box.second_temperature_min_c, 4) + " .. " +
            format_number(box.second_temperature_max_c, 4) + " degC";
  }
  return text;
}

ThermalInput clamp_to_validity(const ThermalModel& model, const ThermalInput& input, bool* clamped) {
  const ThermalValidity& box = model.validity;
  ThermalInput inside = input;
  inside.temperature_c = clamp_flagged(input.temperature_c, box.temperature_min_c, box.temperature_max_c, clamped);
  if (model.uses_temperature_rate) {
    inside.rate_c_s = clamp_flagged(input.rate_c_s, box.rate_min_c_s, box.rate_max_c_s, clamped);
  }
  if (model.uses_second_sensor && input.second_temperature_c) {
    inside.second_temperature_c =
        clamp_flagged(*input.second_temperature_c, box.second_temperature_min_c, box.second_temperature_max_c, clamped);
  }
  return inside;
}

double axis_delta_bias(const ThermalModel& model, const AxisThermalTerms& terms, const ThermalInput& input) {
  const double reference_c = model.reference_temperature_c;
  double delta = polynomial_without_constant(terms.bias_polynomial, input.temperature_c - reference_c);
  if (model.uses_temperature_rate) delta += terms.bias_per_temperature_rate * input.rate_c_s;
  if (model.uses_second_sensor) {
    delta += polynomial_without_constant(terms.bias_second_sensor_polynomial,
                                         input.second_temperature_c.value() - reference_c);
  }
  return delta;
}

double axis_delta_scale(const ThermalModel& model, const AxisThermalTerms& terms, const ThermalInput& input) {
  double ppm = polynomial_without_constant(terms.scale_factor_polynomial_ppm,
                                           input.temperature_c - model.reference_temperature_c);
  if (model.uses_temperature_rate) ppm += terms.scale_factor_ppm_per_temperature_rate * input.rate_c_s;
  if (model.uses_second_sensor && !terms.scale_factor_second_sensor_polynomial_ppm.empty()) {
    ppm += polynomial_without_constant(terms.scale_factor_second_sensor_polynomial_ppm,
                                       input.second_temperature_c.value() - model.reference_temperature_c);
  }
  return 1e-6 * ppm;
}

ThermalCorrection correct(const ThermalModel& model, const Eigen::Vector3d& angular_rate_rad_s,
                          const Eigen::Vector3d& specific_force_m_s2, const ThermalInput& input) {
  if (model.uses_second_sensor && !input.second_temperature_c) {
    throw std::invalid_argument("the thermal model uses a second thermosensor but the input has none");
  }
  ThermalCorrection out;
  const ThermalInput inside = clamp_to_validity(model, input, &out.clamped);
  const bool dynamic = model.regime_switch.enabled && input.dynamic_regime;
  out.angular_rate_rad_s = correct_triad(model, dynamic ? model.dynamic_gyro : model.gyro, angular_rate_rad_s, inside);
  out.specific_force_m_s2 =
      correct_triad(model, dynamic ? model.dynamic_accelerometer : model.accelerometer, specific_force_m_s2, inside);
  return out;
}

}  // namespace thermal
}  // namespace imu_lab
