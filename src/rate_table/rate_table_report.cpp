#include "imu_lab/rate_table/rate_table_report.h"

#include <yaml-cpp/yaml.h>

#include <cstdio>

#include "imu_lab/common/format_number.h"

namespace imu_lab {
namespace rate_table {
namespace {

constexpr double kDegPerRad = 180.0 / 3.14159265358979323846;
const char* const kAxisNames[3] = {"x", "y", "z"};

void emit_estimate(YAML::Emitter& out, const std::string& key, const Estimate& estimate, double factor = 1.0) {
  out << YAML::Key << key << YAML::Value << YAML::Flow << YAML::BeginMap << YAML::Key << "value" << YAML::Value
      << estimate.value * factor << YAML::Key << "sigma" << YAML::Value << estimate.sigma * factor << YAML::EndMap;
}

void emit_fit(YAML::Emitter& out, const ScaleFactorFit& fit, bool polynomial) {
  out << YAML::BeginMap;
  emit_estimate(out, "bias_rad_s", fit.bias_rad_s);
  emit_estimate(out, "bias_deg_h", fit.bias_rad_s, kDegPerRad * 3600.0);
  emit_estimate(out, "scale_factor_error_ppm", fit.scale_factor_error_ppm);
  emit_estimate(out, "asymmetry_ppm", fit.asymmetry_ppm);
  if (polynomial) {
    emit_estimate(out, "quadratic_ppm_fs", fit.quadratic_ppm_fs);
    emit_estimate(out, "cubic_ppm_fs", fit.cubic_ppm_fs);
  }
  out << YAML::Key << "chi_squared" << YAML::Value << fit.chi_squared;
  out << YAML::Key << "degrees_of_freedom" << YAML::Value << fit.degrees_of_freedom;
  out << YAML::EndMap;
}

}  // namespace

std::string scale_factor_yaml(const ScaleFactorTestResult& result, const std::string& recording_name) {
  YAML::Emitter out;
  out.SetDoublePrecision(kRoundTripDigits);
  out << YAML::BeginMap;
  out << YAML::Key << "format" << YAML::Value << "imu_lab_rate_table";
  out << YAML::Key << "recording" << YAML::Value << recording_name;
  out << YAML::Key << "table" << YAML::Value << result.setup.source;
  out << YAML::Key << "gyro_axis" << YAML::Value << kAxisNames[result.axis];
  out << YAML::Key << "axis_sign" << YAML::Value << result.axis_sign;
  out << YAML::Key << "earth_rate_on_table_axis_rad_s" << YAML::Value << result.earth_rate_on_axis_rad_s;
  out << YAML::Key << "full_scale_rad_s" << YAML::Value << result.full_scale_rad_s;
  out << YAML::Key << "full_scale_deg_s" << YAML::Value << result.full_scale_rad_s * kDegPerRad;
  out << YAML::Key << "plateau_detection" << YAML::Value << YAML::BeginMap;
  out << YAML::Key << "plateaus" << YAML::Value << result.plateaus.size();
  out << YAML::Key << "window_s" << YAML::Value << result.detection.window_s;
  out << YAML::Key << "window_noise_rad_s" << YAML::Value << result.detection.window_noise_rad_s;
  out << YAML::Key << "threshold_rad_s" << YAML::Value << result.detection.threshold_rad_s;
  out << YAML::Key << "block_s" << YAML::Value << result.block_s;
  out << YAML::EndMap;
  out << YAML::Key << "straight_lines" << YAML::Value;
  emit_fit(out, result.line, false);
  out << YAML::Key << "nonlinearity_ppm_fs" << YAML::Value << YAML::Flow << YAML::BeginMap << YAML::Key << "value"
      << YAML::Value << result.nonlinearity_ppm_fs.value << YAML::Key << "sigma" << YAML::Value
      << result.nonlinearity_ppm_fs.sigma << YAML::EndMap;
  if (result.polynomial) {
    out << YAML::Key << "polynomial" << YAML::Value;
    emit_fit(out, *result.polynomial, true);
  }
  out << YAML::Key << "dead_zone" << YAML::Value << YAML::BeginMap;
  out << YAML::Key << "found" << YAML::Value << result.dead_zone_found;
  if (result.dead_zone_found) {
    out << YAML::Key << "above_rad_s" << YAML::Value << result.dead_zone_above_rad_s;
    if (result.dead_zone_below_rad_s) out << YAML::Key << "below_rad_s" << YAML::Value << *result.dead_zone_below_rad_s;
  } else if (result.slowest_nonzero_rate_rad_s > 0.0) {
    out << YAML::Key << "below_rad_s" << YAML::Value << result.slowest_nonzero_rate_rad_s;
  }
  out << YAML::EndMap;
  out << YAML::EndMap;
  return std::string(out.c_str()) + "\n";
}

std::string plateau_csv(const ScaleFactorTestResult& result) {
  std::string text =
      "start_s,duration_s,nominal_rate_deg_s,input_rad_s,mean_output_rad_s,sigma_of_mean_rad_s,dead,"
      "line_residual_rad_s,polynomial_residual_rad_s\n";
  for (const PlateauMeasurement& m : result.plateaus) {
    text += format_number(m.plateau.start_s) + "," + format_number(m.plateau.duration_s) + "," +
            format_number(m.nominal_rate_rad_s * kDegPerRad) + "," + format_number(m.input_rad_s) + "," +
            format_number(m.mean_output_rad_s) + "," + format_number(m.sigma_of_mean_rad_s) + "," +
            (m.dead ? "1" : "0") + "," + (m.dead ? "" : format_number(m.line_residual_rad_s)) + "," +
            (m.dead || !result.polynomial ? "" : format_number(m.polynomial_residual_rad_s)) + "\n";
  }
  return text;
}

std::string scale_factor_summary(const ScaleFactorTestResult& result) {
  const auto line = [](const std::string& name, const Estimate& e, const char* unit) {
    return "  " + name + format_printf(e.value, "%.2f") + " +- " + format_printf(e.sigma, "%.2f") + " " + unit + "\n";
  };
  std::string text = "gyro " + std::string(kAxisNames[result.axis]) + " on the table axis, " +
                     std::to_string(result.plateaus.size()) + " plateaus, full scale " +
                     format_printf(result.full_scale_rad_s * kDegPerRad, "%.4g") + " deg/s\n";
  text += "straight lines:\n";
  text += line("bias                  ",
               {result.line.bias_rad_s.value * kDegPerRad * 3600.0, result.line.bias_rad_s.sigma * kDegPerRad * 3600.0},
               "deg/h");
  text += line("scale-factor error    ", result.line.scale_factor_error_ppm, "ppm");
  text += line("asymmetry             ", result.line.asymmetry_ppm, "ppm");
  text += line("nonlinearity          ", result.nonlinearity_ppm_fs, "ppm of FS");
  text += "  chi-squared " + format_printf(result.line.chi_squared, "%.3g") + " on " +
          std::to_string(result.line.degrees_of_freedom) + " degrees of freedom\n";
  if (result.polynomial) {
    const ScaleFactorFit& p = *result.polynomial;
    text += "polynomial:\n";
    text += line("scale-factor error    ", p.scale_factor_error_ppm, "ppm");
    text += line("asymmetry             ", p.asymmetry_ppm, "ppm");
    text += line("quadratic             ", p.quadratic_ppm_fs, "ppm of FS");
    text += line("cubic                 ", p.cubic_ppm_fs, "ppm of FS");
    text += "  chi-squared " + format_printf(p.chi_squared, "%.3g") + " on " + std::to_string(p.degrees_of_freedom) +
            " degrees of freedom\n";
  }
  if (result.dead_zone_found) {
    text += "dead zone: above " + format_printf(result.dead_zone_above_rad_s * kDegPerRad, "%.4g") + " deg/s" +
            (result.dead_zone_below_rad_s
                 ? ", below " + format_printf(*result.dead_zone_below_rad_s * kDegPerRad, "%.4g") + " deg/s"
                 : std::string()) +
            "\n";
  } else {
    text += "dead zone: none at the rates tested\n";
  }
  return text;
}

}  // namespace rate_table
}  // namespace imu_lab
