// Fits a ThermalModel to a thermal test: the IMU static in known orientations while the
// temperature follows a profile (Golovach 2017 section 4.2.1). Per axis, the window means are
//   y = c_o + delta_bias(T, Tdot, T2) + delta_scale(T, Tdot) * input_o
// with one constant c_o per orientation o (it absorbs the bias at the reference temperature, the
// scale factor and misalignment times the known input, and the turn-on bias: those belong to
// calibration, which comes after thermal compensation). So delta_scale needs the axis in at least
// two opposite orientations; one orientation cannot separate bias(T) from scale factor(T).
// Revisits: an orientation turned to again by hand is off by a few tenths of a degree, delta. For
// the axis along gravity that changes its input by g delta^2 / 2 (14 ug at 0.3 deg), so its visits
// share the orientation's constant; for an axis across gravity by g delta (5 mg), more than a
// MEMS accelerometer's whole thermal bias, so there each visit gets its own constant and only the
// temperature changes within a visit inform the fit (unless precise_revisits: a rate table or a
// fixture that repeats orientations to arc-seconds).
// Polynomial orders are fixed or chosen by blocked cross-validation (one-standard-error rule).
// Parameter uncertainties assume independent window means: with flicker and random-walk noise
// over hours they are optimistic.
#pragma once

#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "imu_lab/thermal/orientation_clusters.h"
#include "imu_lab/thermal/thermal_model.h"
#include "imu_lab/thermal/thermal_windows.h"

namespace imu_lab {
namespace thermal {

// The test cannot constrain the asked model; the message says what to change.
class ThermalFitError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct ThermalFitOptions {
  double reference_temperature_c = 20.0;  // normal conditions (Golovach 2017)
  std::optional<int> polynomial_order;    // 1..4 for bias and scale factor; empty: cross-validation
  int max_polynomial_order = 4;
  bool temperature_rate_term = false;  // the dynamic regime (Golovach 2017 eqs. 3.18, 3.19), on the bias
  // ... and on the scale factor: needs opposite orientations while the temperature changes,
  // which a test with positions only at the soaks does not have.
  bool scale_factor_rate_term = false;
  bool second_sensor_term = false;  // a polynomial in the second, lagging thermosensor
  int second_sensor_order = 1;
  // ... in the scale factor too (Golovach 2017 eq. 4.1): needs second_sensor_term, and opposite
  // orientations while the two sensors disagree (during temperature changes), or its sigmas are large.
  bool second_sensor_scale_factor = false;
  // Golovach 2017 eqs. 3.18, 3.19: the bias terms fitted once per regime (the windows'
  // dynamic_fraction, majority), sharing the constants and the scale-factor terms (a thermal test
  // visits the opposite orientations at the soaks, so the dynamic regime cannot separate its own).
  RegimeSwitchSettings regime_switch;
  bool gyro_scale_factor = false;  // from the Earth rate: observable only for navigation-grade gyros
  bool accelerometer_scale_factor = true;
  double min_span_per_order_c = 5.0;  // temperature span needed per polynomial order
  int min_spare_windows = 10;         // windows beyond the parameter count, per axis
  int cross_validation_folds = 5;
  int cross_validation_block_windows = 10;  // neighbouring windows share a fold (they are correlated)
  double cluster_angle_rad = 10.0 * 3.14159265358979323846 / 180.0;
  bool precise_revisits = false;  // one constant per orientation for every axis (see above)
  EarthReference earth;
};

struct FittedParameter {
  std::string name;  // e.g. "bias_polynomial[1]", unit in `unit`
  double value = 0.0;
  double sigma = 0.0;
  std::string unit;
};

struct AxisFitReport {
  std::string triad;  // "gyro" | "accelerometer"
  int axis = 0;
  int bias_order = 0;
  int scale_factor_order = 0;  // 0: not fitted
  std::size_t window_count = 0;
  double residual_rms = 0.0;             // [u]
  double cross_validation_rms = 0.0;     // [u]; 0 when the order was fixed
  double delta_bias_peak_to_peak = 0.0;  // of the fitted delta_bias over the test's windows [u]
  std::size_t constant_count = 0;        // per orientation (along gravity) or per visit (across it)
  // The noise of one window's mean [u], from the change of the residual between neighbouring
  // windows of a visit (Allan deviation at the window's length), and residual_rms over it: 1 to 2
  // when the model describes the data (the slow wander of random walk adds), far above when not.
  double window_noise = 0.0;
  double residual_over_noise = 0.0;
  std::vector<FittedParameter> parameters;
};

// One row per static window and axis, for the plot.
struct WindowResidual {
  std::string triad;
  int axis = 0;
  double stamp_s = 0.0;
  double temperature_c = 0.0;
  double rate_c_s = 0.0;
  int cluster = 0;
  double observed_delta_bias = 0.0;  // y - c_o - every term but the polynomial in T
  double fitted_delta_bias = 0.0;    // the polynomial in T
  double residual = 0.0;             // y - full model
};

struct ThermalFitResult {
  ThermalModel model;
  std::vector<AxisFitReport> axes;  // gyro x, y, z, accelerometer x, y, z
  std::vector<WindowResidual> residuals;
  OrientationAssignment orientations;
  std::size_t static_window_count = 0;
  std::size_t visit_count = 0;        // runs of static windows in one orientation
  std::vector<std::string> warnings;  // axes whose residual is far above the noise (fit_quality.h)
};

// rate_window_s: how the windows' rates were estimated (WindowSettings), stored in the model.
// Throws ThermalFitError when the test cannot constrain the model.
ThermalFitResult fit_thermal_model(const std::vector<ThermalWindow>& windows, double rate_window_s,
                                   const ThermalFitOptions& options);

}  // namespace thermal
}  // namespace imu_lab
