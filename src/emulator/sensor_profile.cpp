#include "imu_lab/emulator/sensor_profile.h"

#include <cmath>
#include <functional>
#include <stdexcept>

#include <Eigen/Cholesky>

#include "imu_lab/common/config_error.h"
#include "imu_lab/common/yaml_fields.h"
#include "imu_lab/noise/flicker_bank.h"
#include "imu_lab/noise/zero_dc_noise.h"

namespace imu_lab {
namespace emulator {

namespace {

// Unit suffixes of one triad's keys: rate "u", integral "v", squared rate.
struct TriadUnits {
  std::string rate;
  std::string integral;
  std::string rate_squared;
};

using noise::ProcessParameters;

// Adds one parameter set per axis, built from per-axis field values.
template <typename Make>
void add_per_axis(TriadErrorModel& model, Make make) {
  for (int axis = 0; axis < 3; ++axis) model.noise_per_axis[axis].push_back(make(axis));
}

// Adds a parameter set on the axes whose amplitude is non-zero (the others get no process).
template <typename Make>
void add_nonzero_axes(TriadErrorModel& model, const Eigen::Vector3d& amplitude, Make make) {
  for (int axis = 0; axis < 3; ++axis) {
    if (amplitude[axis] != 0.0) model.noise_per_axis[axis].push_back(make(axis));
  }
}

// A block holding one per-axis field, e.g. white_rate: {density_rad_s_per_sqrt_hz: 1e-4}.
template <typename Make>
void read_one_field_block(const YamlFields& noise_fields, const std::string& name, const std::string& key,
                          bool non_negative_only, TriadErrorModel& model, Make make) {
  if (!noise_fields.has(name)) return;
  const YamlFields f = noise_fields.child(name);
  f.allow_only({key.c_str()});
  const Eigen::Vector3d value = f.per_axis(key, non_negative_only);
  add_per_axis(model, [&](int a) -> ProcessParameters { return make(value[a]); });
}

void read_list_or_single(const YamlFields& noise_fields, const std::string& key,
                         const std::function<void(const YamlFields&)>& read_one) {
  const YAML::Node value = noise_fields.raw(key);
  if (value.IsMap()) {
    read_one(YamlFields(value, noise_fields.key_path(key), noise_fields.source()));
    return;
  }
  if (!value.IsSequence()) noise_fields.fail(key, "expected a mapping or a list of mappings");
  for (std::size_t i = 0; i < value.size(); ++i) {
    const std::string path = noise_fields.key_path(key) + "[" + std::to_string(i) + "]";
    if (!value[i].IsMap()) throw ConfigError(noise_fields.source(), path, "expected a mapping");
    read_one(YamlFields(value[i], path, noise_fields.source()));
  }
}

// white_rate: {density_<u>_per_sqrt_hz, axis_correlation: 3x3 (optional, identity)}.
void read_white_rate(const YamlFields& f, const TriadUnits& u, TriadErrorModel& model) {
  const std::string key = "density_" + u.rate + "_per_sqrt_hz";
  f.allow_only({key.c_str(), "axis_correlation"});
  const Eigen::Vector3d density = f.per_axis(key, true);
  add_per_axis(model, [&](int a) -> ProcessParameters { return noise::WhiteRateParameters{density[a]}; });
  if (!f.has("axis_correlation")) return;
  const Eigen::Matrix3d r = f.matrix3("axis_correlation");
  if ((r - r.transpose()).cwiseAbs().maxCoeff() > 1e-12) f.fail("axis_correlation", "must be symmetric");
  if ((r.diagonal().array() != 1.0).any()) f.fail("axis_correlation", "the diagonal must be 1");
  Eigen::LLT<Eigen::Matrix3d> cholesky(r);
  if (cholesky.info() != Eigen::Success || cholesky.matrixL().toDenseMatrix().diagonal().minCoeff() <= 0.0) {
    f.fail("axis_correlation", "must be positive definite (a correlation matrix of three axes)");
  }
  for (int a = 0; a < 3; ++a) {
    for (int b = 0; b < 3; ++b) {
      if (a != b && r(a, b) != 0.0 && density[a] == 0.0) {
        f.fail("axis_correlation", std::string("axis ") + "xyz"[a] + " has no white rate noise to correlate");
      }
    }
  }
  model.white_rate_correlation = r;
}

void read_noise(const YamlFields& fields, const TriadUnits& u, TriadErrorModel& model) {
  const std::string flicker = "bias_instability", markov = "markov", sinusoid = "sinusoid", zero_dc = "zero_dc_family";
  fields.allow_only({"white_rate", "bias_instability", "random_walk", "rate_ramp", "markov", "sinusoid", "white_angle",
                     "zero_dc_family", "zero_dc_gaussian", "high_pass_white", "resonance"});
  if (fields.has("white_rate")) read_white_rate(fields.child("white_rate"), u, model);
  read_one_field_block(fields, "random_walk", "density_" + u.rate + "_per_sqrt_s", true, model,
                       [](double k) { return noise::RandomWalkParameters{k}; });
  read_one_field_block(fields, "rate_ramp", "slope_" + u.rate + "_per_s", false, model,
                       [](double r) { return noise::RateRampParameters{r}; });
  read_one_field_block(fields, "white_angle", "density_" + u.integral + "_per_sqrt_hz", true, model, [](double d) {
    return noise::WhiteAngleParameters{0.0, d};
  });
  if (fields.has(flicker)) {
    const YamlFields f = fields.child(flicker);
    const std::string key = "coefficient_" + u.rate;
    f.allow_only({key.c_str(), "cutoff_frequency_hz", "valid_tau_range_s"});
    const Eigen::Vector3d b = f.per_axis(key, true);
    const double cutoff = f.positive("cutoff_frequency_hz");
    const YAML::Node range = f.raw("valid_tau_range_s");
    if (!range.IsSequence() || range.size() != 2) {
      f.fail("valid_tau_range_s", "expected [tau_min_s, tau_max_s]");
    }
    const double tau_min = f.number_at(range[0], "valid_tau_range_s[0]");
    const double tau_max = f.number_at(range[1], "valid_tau_range_s[1]");
    for (int a = 0; a < 3; ++a) {
      if (b[a] == 0.0) continue;
      noise::BiasInstabilityParameters p{b[a], cutoff, tau_min, tau_max};
      try {
        noise::design_flicker_bank(p);
      } catch (const std::invalid_argument& error) {
        f.fail("valid_tau_range_s", error.what());
      }
      model.noise_per_axis[a].push_back(p);
    }
  }
  if (fields.has(markov)) {
    read_list_or_single(fields, markov, [&](const YamlFields& f) {
      const std::string key = "q_c_" + u.rate + "_per_sqrt_s";
      f.allow_only({key.c_str(), "correlation_time_s"});
      const Eigen::Vector3d q = f.per_axis(key, true);
      const Eigen::Vector3d t = f.per_axis("correlation_time_s", true);
      if (t.minCoeff() <= 0.0) f.fail("correlation_time_s", "must be positive");
      add_per_axis(model, [&](int a) -> ProcessParameters { return noise::MarkovParameters{q[a], t[a]}; });
    });
  }
  if (fields.has(sinusoid)) {
    read_list_or_single(fields, sinusoid, [&](const YamlFields& f) {
      const std::string key = "amplitude_" + u.rate;
      f.allow_only({key.c_str(), "frequency_hz", "phase_rad"});
      const Eigen::Vector3d amplitude = f.per_axis(key, true);
      const double frequency = f.positive("frequency_hz");
      const Eigen::Vector3d phase = f.per_axis_or_zero("phase_rad");
      add_per_axis(model, [&](int a) -> ProcessParameters {
        return noise::SinusoidParameters{amplitude[a], frequency, phase[a]};
      });
    });
  }
  const std::string alpha_key = "alpha_" + u.rate_squared + "_per_hz_n_plus_1";
  // n > 1: the angle is stationary only then (n = 1 has the AVAR zero_dc_family_avar gives, but
  // no generator).
  auto exponent = [](const YamlFields& f) {
    const double n = f.number("exponent_n");
    if (!(n > 1.0)) f.fail("exponent_n", "must be > 1 (below, the angle's variance diverges)");
    return n;
  };
  if (fields.has(zero_dc)) {
    read_list_or_single(fields, zero_dc, [&](const YamlFields& f) {
      f.allow_only({"exponent_n", alpha_key.c_str(), "beta_s", "cosine_s", "cosine_weight"});
      const double n = exponent(f);
      const Eigen::Vector3d alpha = f.per_axis(alpha_key, true);
      const double beta = f.positive("beta_s");
      const double cosine_s = f.has("cosine_s") ? f.non_negative("cosine_s") : 0.0;
      const double weight = f.number_or("cosine_weight", 0.0);
      if (!(std::abs(weight) <= 1.0)) {
        f.fail("cosine_weight", "must lie in [-1, 1] (beyond, the PSD is negative somewhere)");
      }
      add_nonzero_axes(model, alpha, [&](int a) -> ProcessParameters {
        return noise::ZeroDcFamilyParameters{n, alpha[a], beta, cosine_s, weight};
      });
    });
  }
  if (fields.has("zero_dc_gaussian")) {
    read_list_or_single(fields, "zero_dc_gaussian", [&](const YamlFields& f) {
      f.allow_only({"exponent_n", alpha_key.c_str(), "beta_s2"});
      const double n = exponent(f);
      const Eigen::Vector3d alpha = f.per_axis(alpha_key, true);
      const double beta = f.positive("beta_s2");
      add_nonzero_axes(model, alpha, [&](int a) -> ProcessParameters {
        return noise::ZeroDcGaussianParameters{n, alpha[a], beta};
      });
    });
  }
  if (fields.has("high_pass_white")) {
    read_list_or_single(fields, "high_pass_white", [&](const YamlFields& f) {
      const std::string key = "density_" + u.rate + "_per_sqrt_hz";
      f.allow_only({key.c_str(), "corner_frequency_hz"});
      const Eigen::Vector3d density = f.per_axis(key, true);
      const double corner = f.positive("corner_frequency_hz");
      add_nonzero_axes(model, density, [&](int a) -> ProcessParameters {
        return noise::HighPassWhiteParameters{density[a], corner};
      });
    });
  }
  if (fields.has("resonance")) {
    read_list_or_single(fields, "resonance", [&](const YamlFields& f) {
      const std::string key = "rms_" + u.rate;
      f.allow_only({key.c_str(), "natural_frequency_hz", "width_hz"});
      const Eigen::Vector3d rms = f.per_axis(key, true);
      const double natural = f.positive("natural_frequency_hz");
      const double width = f.positive("width_hz");
      if (!(width < 2.0 * natural)) {
        f.fail("width_hz",
               "must be below 2 natural_frequency_hz (the -3 dB width 2 zeta f_n of an "
               "underdamped mode)");
      }
      add_nonzero_axes(model, rms, [&](int a) -> ProcessParameters {
        return noise::ResonanceParameters{rms[a], natural, width};
      });
    });
  }
}

void read_quantization(const YamlFields& f, const TriadUnits& u, TriadErrorModel& model) {
  const std::string pulse_key = "pulse_weight_" + u.integral;
  const std::string sigma_key = "q_" + u.integral;
  f.allow_only({"model", pulse_key.c_str(), sigma_key.c_str()});
  const std::string kind = f.text("model");
  if (kind == "pulses") {
    model.pulse_weight = f.positive(pulse_key);
  } else if (kind == "white_angle") {
    const Eigen::Vector3d q = f.per_axis(sigma_key, true);
    add_per_axis(model, [&](int a) -> ProcessParameters { return noise::WhiteAngleParameters{q[a], 0.0}; });
  } else {
    f.fail("model", "expected 'pulses' or 'white_angle', got '" + kind + "'");
  }
}

// thermal: {reference_temperature_c, bias_polynomial_<u>: [row, ...], scale_factor_polynomial_ppm:
// [row, ...], bias_per_temperature_rate_<u>_per_c_s, scale_factor_ppm_per_temperature_rate_per_c_s,
// bias_second_sensor_polynomial_<u>, scale_factor_second_sensor_polynomial_ppm (rows in T2 - T_ref)};
// a row is one number or [x, y, z], row k multiplying (T - T_ref)^(k+1).
ThermalSensitivity read_thermal_sensitivity(const YamlFields& f, const TriadUnits& u) {
  const std::string bias_key = "bias_polynomial_" + u.rate;
  const std::string bias_rate_key = "bias_per_temperature_rate_" + u.rate + "_per_c_s";
  const std::string scale_key = "scale_factor_polynomial_ppm";
  const std::string scale_rate_key = "scale_factor_ppm_per_temperature_rate_per_c_s";
  const std::string bias_second_key = "bias_second_sensor_polynomial_" + u.rate;
  const std::string scale_second_key = "scale_factor_second_sensor_polynomial_ppm";
  f.allow_only({"reference_temperature_c", bias_key.c_str(), scale_key.c_str(), bias_rate_key.c_str(),
                scale_rate_key.c_str(), bias_second_key.c_str(), scale_second_key.c_str()});
  auto rows = [&](const std::string& key) {
    std::vector<Eigen::Vector3d> result;
    if (!f.has(key)) return result;
    const YAML::Node list = f.raw(key);
    if (!list.IsSequence()) f.fail(key, "expected a list of rows (row k multiplies (T - T_ref)^(k+1))");
    for (std::size_t k = 0; k < list.size(); ++k) {
      result.push_back(f.per_axis_at(list[k], key + "[" + std::to_string(k) + "]", false));
    }
    return result;
  };
  ThermalSensitivity thermal;
  thermal.reference_temperature_c = f.number("reference_temperature_c");
  thermal.bias_polynomial = rows(bias_key);
  thermal.scale_factor_polynomial_ppm = rows(scale_key);
  thermal.bias_per_temperature_rate = f.per_axis_or_zero(bias_rate_key);
  thermal.scale_factor_ppm_per_temperature_rate = f.per_axis_or_zero(scale_rate_key);
  thermal.bias_second_sensor_polynomial = rows(bias_second_key);
  thermal.scale_factor_second_sensor_polynomial_ppm = rows(scale_second_key);
  return thermal;
}

// scale_factor_nonlinearity: {full_scale_<u>, quadratic_ppm_fs, cubic_ppm_fs}: the error at full
// scale, in ppm of full scale, of a term in (input / full scale)^2 and ^3.
void read_scale_factor_nonlinearity(const YamlFields& f, const TriadUnits& u, const std::string& direct_quadratic_key,
                                    bool direct_given, TriadErrorModel& model) {
  const std::string full_scale_key = "full_scale_" + u.rate;
  f.allow_only({full_scale_key.c_str(), "quadratic_ppm_fs", "cubic_ppm_fs"});
  const Eigen::Vector3d full_scale = f.per_axis(full_scale_key, true);
  if (full_scale.minCoeff() <= 0.0) f.fail(full_scale_key, "must be positive");
  if (f.has("quadratic_ppm_fs")) {
    if (direct_given) {
      f.fail("quadratic_ppm_fs", "the same term as " + direct_quadratic_key + "; give one of the two");
    }
    model.quadratic_nonlinearity_per_unit = 1e-6 * f.per_axis("quadratic_ppm_fs", false).cwiseQuotient(full_scale);
  }
  model.cubic_nonlinearity_per_unit2 = 1e-6 * f.per_axis_or_zero("cubic_ppm_fs").cwiseQuotient(full_scale.cwiseAbs2());
}

TriadErrorModel read_triad(const YamlFields& f, const TriadUnits& u, bool is_gyro) {
  const std::string bias = "bias_fixed_" + u.rate, turn_on = "bias_turn_on_sigma_" + u.rate,
                    quadratic = "quadratic_nonlinearity_per_" + u.rate, g_sensitivity = "g_sensitivity_rad_s_per_m_s2",
                    dead_zone = "dead_zone_" + u.rate, lsb = "output_lsb_" + u.rate;
  if (is_gyro) {
    f.allow_only({bias.c_str(), turn_on.c_str(), "scale_factor_error_ppm", "misalignment_rad", quadratic.c_str(),
                  "scale_factor_nonlinearity", "scale_factor_asymmetry_ppm", dead_zone.c_str(), g_sensitivity.c_str(),
                  "bandwidth_hz", "quantization", lsb.c_str(), "noise", "thermal"});
  } else {
    f.allow_only({bias.c_str(), turn_on.c_str(), "scale_factor_error_ppm", "misalignment_rad", quadratic.c_str(),
                  "scale_factor_nonlinearity", "scale_factor_asymmetry_ppm", dead_zone.c_str(), "bandwidth_hz",
                  "quantization", lsb.c_str(), "noise", "thermal"});
  }
  TriadErrorModel model;
  model.bias_fixed = f.per_axis(bias, false);
  model.bias_turn_on_sigma = f.per_axis(turn_on, true);
  model.scale_factor_error_ppm = f.per_axis("scale_factor_error_ppm", false);
  if (!f.has("misalignment_rad")) f.fail("misalignment_rad", "missing required key");
  model.misalignment_rad = f.matrix3_or_zero("misalignment_rad");
  if (model.misalignment_rad.diagonal().cwiseAbs().maxCoeff() != 0.0) {
    f.fail("misalignment_rad", "the diagonal must be zero (scale errors go in scale_factor_error_ppm)");
  }
  model.quadratic_nonlinearity_per_unit = f.per_axis_or_zero(quadratic);
  if (f.has("scale_factor_nonlinearity")) {
    read_scale_factor_nonlinearity(f.child("scale_factor_nonlinearity"), u, quadratic, f.has(quadratic), model);
  }
  model.scale_factor_asymmetry_ppm = f.per_axis_or_zero("scale_factor_asymmetry_ppm");
  if (f.has(dead_zone)) model.dead_zone = f.per_axis(dead_zone, true);
  if (is_gyro) model.g_sensitivity = f.matrix3_or_zero(g_sensitivity);
  if (f.has("bandwidth_hz")) model.bandwidth_hz = f.positive("bandwidth_hz");
  if (f.has("quantization")) read_quantization(f.child("quantization"), u, model);
  if (f.has(lsb)) {
    model.output_lsb = f.per_axis(lsb, true);
    if (model.pulse_weight > 0.0 && model.output_lsb.maxCoeff() > 0.0) {
      f.fail(lsb,
             "a pulse-counting output (quantization.model: pulses) has no rate register; "
             "give one of the two");
    }
  }
  read_noise(f.child("noise"), u, model);
  if (f.has("thermal")) model.thermal = read_thermal_sensitivity(f.child("thermal"), u);
  return model;
}

}  // namespace

Eigen::Matrix3d TriadErrorModel::scale_misalignment_matrix() const {
  Eigen::Matrix3d k = Eigen::Matrix3d::Identity() + misalignment_rad;
  k.diagonal() += scale_factor_error_ppm * 1e-6;
  return k;
}

SensorProfile sensor_profile_from_yaml(const YAML::Node& root, const std::string& source_name) {
  const YamlFields fields(root, "", source_name);
  fields.allow_only({"name", "description", "gyro", "accelerometer"});
  SensorProfile profile;
  profile.source = source_name;
  profile.name = fields.text("name");
  profile.gyro = read_triad(fields.child("gyro"), {"rad_s", "rad", "rad2_s2"}, true);
  profile.accelerometer = read_triad(fields.child("accelerometer"), {"m_s2", "m_s", "m2_s4"}, false);
  return profile;
}

SensorProfile load_sensor_profile(const std::string& path) {
  return sensor_profile_from_yaml(load_yaml_file(path), path);
}

}  // namespace emulator
}  // namespace imu_lab
