#include "imu_lab/thermal/thermal_model_yaml.h"

#include <yaml-cpp/yaml.h>

#include <cmath>

#include "imu_lab/common/atomic_file.h"
#include "imu_lab/common/config_error.h"
#include "imu_lab/common/yaml_fields.h"

namespace imu_lab {
namespace thermal {
namespace {

const char* const kFormat = "imu_lab_thermal_model";
const char* const kAxisNames[3] = {"x", "y", "z"};

struct TriadKeys {
  std::string bias, bias_rate, bias_second, scale = "scale_factor_polynomial_ppm",
                                            scale_rate = "scale_factor_ppm_per_temperature_rate_per_c_s",
                                            scale_second = "scale_factor_second_sensor_polynomial_ppm";
};

TriadKeys keys_for(const std::string& unit) {
  TriadKeys keys;
  keys.bias = "bias_polynomial_" + unit;
  keys.bias_rate = "bias_per_temperature_rate_" + unit + "_per_c_s";
  keys.bias_second = "bias_second_sensor_polynomial_" + unit;
  return keys;
}

std::vector<double> polynomial(const YamlFields& f, const std::string& key) {
  std::vector<double> out;
  if (!f.has(key)) return out;
  const YAML::Node list = f.raw(key);
  if (!list.IsSequence()) f.fail(key, "expected a list of coefficients (per degC, per degC^2, ...)");
  if (list.size() > 4) f.fail(key, "at most 4 coefficients (order 4)");
  for (std::size_t k = 0; k < list.size(); ++k)
    out.push_back(f.number_at(list[k], key + "[" + std::to_string(k) + "]"));
  return out;
}

TriadThermalTerms read_triad(const YamlFields& triad, const std::string& unit) {
  const TriadKeys keys = keys_for(unit);
  triad.allow_only({"x", "y", "z"});
  TriadThermalTerms terms;
  for (int axis = 0; axis < 3; ++axis) {
    const YamlFields f = triad.child(kAxisNames[axis]);
    f.allow_only({keys.bias.c_str(), keys.bias_rate.c_str(), keys.bias_second.c_str(), keys.scale.c_str(),
                  keys.scale_rate.c_str(), keys.scale_second.c_str()});
    terms[axis].bias_polynomial = polynomial(f, keys.bias);
    terms[axis].bias_per_temperature_rate = f.number_or(keys.bias_rate, 0.0);
    terms[axis].bias_second_sensor_polynomial = polynomial(f, keys.bias_second);
    terms[axis].scale_factor_polynomial_ppm = polynomial(f, keys.scale);
    terms[axis].scale_factor_ppm_per_temperature_rate = f.number_or(keys.scale_rate, 0.0);
    terms[axis].scale_factor_second_sensor_polynomial_ppm = polynomial(f, keys.scale_second);
  }
  return terms;
}

void write_triad(YAML::Emitter& out, const TriadThermalTerms& terms, const std::string& unit) {
  const TriadKeys keys = keys_for(unit);
  out << YAML::BeginMap;
  for (int axis = 0; axis < 3; ++axis) {
    const AxisThermalTerms& axis_terms = terms[axis];
    out << YAML::Key << kAxisNames[axis] << YAML::Value << YAML::BeginMap;
    out << YAML::Key << keys.bias << YAML::Value << YAML::Flow << axis_terms.bias_polynomial;
    out << YAML::Key << keys.bias_rate << YAML::Value << axis_terms.bias_per_temperature_rate;
    if (!axis_terms.bias_second_sensor_polynomial.empty()) {
      out << YAML::Key << keys.bias_second << YAML::Value << YAML::Flow << axis_terms.bias_second_sensor_polynomial;
    }
    out << YAML::Key << keys.scale << YAML::Value << YAML::Flow << axis_terms.scale_factor_polynomial_ppm;
    out << YAML::Key << keys.scale_rate << YAML::Value << axis_terms.scale_factor_ppm_per_temperature_rate;
    if (!axis_terms.scale_factor_second_sensor_polynomial_ppm.empty()) {
      out << YAML::Key << keys.scale_second << YAML::Value << YAML::Flow
          << axis_terms.scale_factor_second_sensor_polynomial_ppm;
    }
    out << YAML::EndMap;
  }
  out << YAML::EndMap;
}

void write_fit(YAML::Emitter& out, const ThermalFitResult& fit) {
  out << YAML::Key << "fit" << YAML::Value << YAML::BeginMap;
  out << YAML::Key << "static_windows" << YAML::Value << fit.static_window_count;
  out << YAML::Key << "orientations" << YAML::Value << fit.orientations.clusters.size();
  out << YAML::Key << "note" << YAML::Value
      << "sigmas assume independent window means; correlated noise (flicker, random walk) makes them optimistic";
  out << YAML::Key << "axes" << YAML::Value << YAML::BeginSeq;
  for (const AxisFitReport& axis : fit.axes) {
    out << YAML::BeginMap;
    out << YAML::Key << "triad" << YAML::Value << axis.triad << YAML::Key << "axis" << YAML::Value
        << kAxisNames[axis.axis];
    out << YAML::Key << "bias_order" << YAML::Value << axis.bias_order;
    out << YAML::Key << "scale_factor_order" << YAML::Value << axis.scale_factor_order;
    out << YAML::Key << "windows" << YAML::Value << axis.window_count;
    out << YAML::Key << "residual_rms" << YAML::Value << axis.residual_rms;
    out << YAML::Key << "cross_validation_rms" << YAML::Value << axis.cross_validation_rms;
    out << YAML::Key << "fitted_delta_bias_peak_to_peak" << YAML::Value << axis.delta_bias_peak_to_peak;
    out << YAML::Key << "parameters" << YAML::Value << YAML::BeginSeq;
    for (const FittedParameter& p : axis.parameters) {
      out << YAML::Flow << YAML::BeginMap << YAML::Key << "name" << YAML::Value << p.name << YAML::Key << "value"
          << YAML::Value << p.value << YAML::Key << "sigma" << YAML::Value << p.sigma << YAML::Key << "unit"
          << YAML::Value << p.unit << YAML::EndMap;
    }
    out << YAML::EndSeq << YAML::EndMap;
  }
  out << YAML::EndSeq << YAML::EndMap;
}

}  // namespace

ThermalModel load_thermal_model(const std::string& path) {
  const YamlFields root(load_yaml_file(path), "", path);
  root.allow_only({"format", "version", "reference_temperature_c", "rate_window_s", "uses_temperature_rate",
                   "uses_second_sensor", "validity", "gyro", "accelerometer", "regime_switch", "dynamic_gyro",
                   "dynamic_accelerometer", "fit"});
  if (root.text("format") != kFormat) root.fail("format", std::string("expected '") + kFormat + "'");
  if (root.number("version") != 1.0) root.fail("version", "this build reads version 1");
  ThermalModel model;
  model.reference_temperature_c = root.number("reference_temperature_c");
  model.rate_window_s = root.positive("rate_window_s");
  const auto flag = [&](const char* key) {
    try {
      return root.raw(key).as<bool>();
    } catch (const YAML::Exception&) {
      root.fail(key, "expected true or false");
    }
  };
  model.uses_temperature_rate = flag("uses_temperature_rate");
  model.uses_second_sensor = flag("uses_second_sensor");
  const YamlFields validity = root.child("validity");
  validity.allow_only({"temperature_min_c", "temperature_max_c", "rate_min_c_s", "rate_max_c_s",
                       "second_temperature_min_c", "second_temperature_max_c"});
  ThermalValidity& box = model.validity;
  box.temperature_min_c = validity.number("temperature_min_c");
  box.temperature_max_c = validity.number("temperature_max_c");
  if (!(box.temperature_max_c >= box.temperature_min_c)) validity.fail("temperature_max_c", "below temperature_min_c");
  box.rate_min_c_s = validity.number_or("rate_min_c_s", 0.0);
  box.rate_max_c_s = validity.number_or("rate_max_c_s", 0.0);
  if (!(box.rate_max_c_s >= box.rate_min_c_s)) validity.fail("rate_max_c_s", "below rate_min_c_s");
  if (model.uses_second_sensor) {
    box.second_temperature_min_c = validity.number("second_temperature_min_c");
    box.second_temperature_max_c = validity.number("second_temperature_max_c");
  }
  model.gyro = read_triad(root.child("gyro"), "rad_s");
  model.accelerometer = read_triad(root.child("accelerometer"), "m_s2");
  // Golovach 2017 eqs. 3.18, 3.19: present only in a model fitted with the regime switch.
  if (root.has("regime_switch")) {
    const YamlFields regime = root.child("regime_switch");
    regime.allow_only({"threshold_c_s2", "window_s", "hold_s"});
    RegimeSwitchSettings& settings = model.regime_switch;
    settings.enabled = true;
    settings.threshold_c_s2 = regime.positive("threshold_c_s2");
    settings.window_s = regime.positive("window_s");
    settings.hold_s = regime.number("hold_s");
    if (settings.hold_s < 0.0) regime.fail("hold_s", "must be 0 s or more");
    model.dynamic_gyro = read_triad(root.child("dynamic_gyro"), "rad_s");
    model.dynamic_accelerometer = read_triad(root.child("dynamic_accelerometer"), "m_s2");
  } else {
    for (const char* key : {"dynamic_gyro", "dynamic_accelerometer"}) {
      if (root.has(key)) root.fail(key, "the dynamic regime's terms need a regime_switch section");
    }
  }
  return model;
}

std::string thermal_model_to_yaml(const ThermalModel& model, const ThermalFitResult* fit) {
  YAML::Emitter out;
  out.SetDoublePrecision(10);
  out << YAML::Comment(
      "imu_lab thermal model: corrected = (raw - delta_bias(T)) / (1 + delta_scale(T)); see "
      "include/imu_lab/thermal/thermal_model.h");
  out << YAML::BeginMap;
  out << YAML::Key << "format" << YAML::Value << kFormat << YAML::Key << "version" << YAML::Value << 1;
  out << YAML::Key << "reference_temperature_c" << YAML::Value << model.reference_temperature_c;
  out << YAML::Key << "rate_window_s" << YAML::Value << model.rate_window_s;
  out << YAML::Key << "uses_temperature_rate" << YAML::Value << model.uses_temperature_rate;
  out << YAML::Key << "uses_second_sensor" << YAML::Value << model.uses_second_sensor;
  const ThermalValidity& box = model.validity;
  out << YAML::Key << "validity" << YAML::Value << YAML::BeginMap;
  out << YAML::Key << "temperature_min_c" << YAML::Value << box.temperature_min_c;
  out << YAML::Key << "temperature_max_c" << YAML::Value << box.temperature_max_c;
  out << YAML::Key << "rate_min_c_s" << YAML::Value << box.rate_min_c_s;
  out << YAML::Key << "rate_max_c_s" << YAML::Value << box.rate_max_c_s;
  if (model.uses_second_sensor) {
    out << YAML::Key << "second_temperature_min_c" << YAML::Value << box.second_temperature_min_c;
    out << YAML::Key << "second_temperature_max_c" << YAML::Value << box.second_temperature_max_c;
  }
  out << YAML::EndMap;
  out << YAML::Key << "gyro" << YAML::Value;
  write_triad(out, model.gyro, "rad_s");
  out << YAML::Key << "accelerometer" << YAML::Value;
  write_triad(out, model.accelerometer, "m_s2");
  if (model.regime_switch.enabled) {
    const RegimeSwitchSettings& settings = model.regime_switch;
    out << YAML::Key << "regime_switch" << YAML::Value << YAML::BeginMap;
    out << YAML::Key << "threshold_c_s2" << YAML::Value << settings.threshold_c_s2;
    out << YAML::Key << "window_s" << YAML::Value << settings.window_s;
    out << YAML::Key << "hold_s" << YAML::Value << settings.hold_s;
    out << YAML::EndMap;
    out << YAML::Key << "dynamic_gyro" << YAML::Value;
    write_triad(out, model.dynamic_gyro, "rad_s");
    out << YAML::Key << "dynamic_accelerometer" << YAML::Value;
    write_triad(out, model.dynamic_accelerometer, "m_s2");
  }
  if (fit) write_fit(out, *fit);
  out << YAML::EndMap;
  return std::string(out.c_str()) + "\n";
}

void save_thermal_model(const std::string& path, const ThermalModel& model, const ThermalFitResult* fit) {
  write_file_atomically(path, thermal_model_to_yaml(model, fit));
}

}  // namespace thermal
}  // namespace imu_lab
