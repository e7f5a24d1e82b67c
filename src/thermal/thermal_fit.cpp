#include "imu_lab/thermal/thermal_fit.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <set>
#include <sstream>

#include "imu_lab/common/fit_quality.h"
#include "imu_lab/thermal/thermal_regime.h"

namespace imu_lab {
namespace thermal {
namespace {

// Regressors are scaled to order one, so the least squares stays well conditioned up to order 4.
constexpr double kTemperatureUnit_c = 10.0;
constexpr double kRateUnit_c_s = 1.0 / 60.0;  // 1 degC/min
constexpr double kSingularRatio = 1e-9;       // smallest / largest singular value

const char* const kAxisNames[3] = {"x", "y", "z"};

struct TriadSpec {
  const char* name;
  const char* unit;
  bool scale_factor;
  double input_reference;  // |input| of the known excitation, for the opposite-orientation test
};

// The rows (static windows) of one axis. `cluster` is the row's constant: its orientation's, or
// (across gravity, thermal_fit.h) its visit's.
struct AxisData {
  std::vector<double> y, delta_t, rate, second_delta_t, input;
  std::vector<int> cluster;
  std::vector<int> regime;  // 0 static, 1 dynamic (always 0 without the regime switch)
  double input_reference = 1.0;
};

struct Structure {
  int clusters = 0;
  int bias_order = 1;
  bool rate = false;
  bool scale_rate = false;
  int second_order = 0;
  int scale_order = 0;         // 0: no scale-factor terms
  int second_scale_order = 0;  // scale factor in the second sensor (only with scale_order > 0)
  int regimes = 1;             // 2: the bias terms once per regime (static, dynamic); the rest shared
  int bias_columns() const { return bias_order + (rate ? 1 : 0) + second_order; }
  int columns() const {
    return clusters + regimes * bias_columns() + scale_order +
           (scale_order > 0 ? (scale_rate ? 1 : 0) + second_scale_order : 0);
  }
};

// Writes one row's regressors (cluster columns mapped through cluster_column, -1 = dropped).
void fill_row(const AxisData& data, std::size_t r, const Structure& s, const std::vector<int>& cluster_column,
              Eigen::Ref<Eigen::RowVectorXd, 0, Eigen::InnerStride<>> row) {
  row.setZero();
  if (cluster_column[data.cluster[r]] >= 0) row[cluster_column[data.cluster[r]]] = 1.0;
  int c = s.clusters + (s.regimes > 1 ? data.regime[r] : 0) * s.bias_columns();
  const double x = data.delta_t[r] / kTemperatureUnit_c;
  for (int k = 1; k <= s.bias_order; ++k) row[c++] = std::pow(x, k);
  const double rate = data.rate[r] / kRateUnit_c_s;
  if (s.rate) row[c++] = rate;
  const double x2 = data.second_delta_t[r] / kTemperatureUnit_c;
  for (int k = 1; k <= s.second_order; ++k) row[c++] = std::pow(x2, k);
  c = s.clusters + s.regimes * s.bias_columns();
  const double input = data.input[r] / data.input_reference;
  for (int k = 1; k <= s.scale_order; ++k) row[c++] = input * std::pow(x, k);
  if (s.scale_order == 0) return;
  if (s.scale_rate) row[c++] = input * rate;
  for (int k = 1; k <= s.second_scale_order; ++k) row[c++] = input * std::pow(x2, k);
}

struct Solution {
  bool ok = false;
  Eigen::VectorXd beta;
  Eigen::MatrixXd covariance;
  double residual_sum_squares = 0.0;
};

Solution solve(const Eigen::MatrixXd& design, const Eigen::VectorXd& y) {
  Solution out;
  if (design.rows() <= design.cols()) return out;
  Eigen::BDCSVD<Eigen::MatrixXd> svd(design, Eigen::ComputeThinU | Eigen::ComputeThinV);
  const Eigen::VectorXd& singular = svd.singularValues();
  if (!(singular.minCoeff() > kSingularRatio * singular.maxCoeff())) return out;
  out.ok = true;
  out.beta = svd.solve(y);
  out.residual_sum_squares = (y - design * out.beta).squaredNorm();
  const double variance = out.residual_sum_squares / static_cast<double>(design.rows() - design.cols());
  out.covariance =
      svd.matrixV() * singular.cwiseInverse().cwiseAbs2().asDiagonal() * svd.matrixV().transpose() * variance;
  return out;
}

// Cluster columns kept for the given rows (clusters without rows are dropped).
std::vector<int> cluster_columns(const AxisData& data, const std::vector<std::size_t>& rows, int clusters, int* kept) {
  std::vector<int> column(clusters, -1);
  for (std::size_t r : rows) column[data.cluster[r]] = 0;
  *kept = 0;
  for (int& c : column) c = c < 0 ? -1 : (*kept)++;
  return column;
}

Solution fit_rows(const AxisData& data, const std::vector<std::size_t>& rows, Structure s,
                  std::vector<int>* cluster_column_out) {
  int kept = 0;
  const std::vector<int> column = cluster_columns(data, rows, s.clusters, &kept);
  s.clusters = kept;
  Eigen::MatrixXd design(rows.size(), s.columns());
  Eigen::VectorXd y(rows.size());
  for (std::size_t i = 0; i < rows.size(); ++i) {
    fill_row(data, rows[i], s, column, design.row(i));
    y[i] = data.y[rows[i]];
  }
  if (cluster_column_out) *cluster_column_out = column;
  return solve(design, y);
}

struct CrossValidation {
  double mean_square = std::numeric_limits<double>::infinity();
  double standard_error = 0.0;
};

// One candidate's held-out errors per fold; `constrained` is false where the fold's training rows
// leave the candidate singular.
struct FoldErrors {
  std::vector<bool> constrained;
  std::vector<double> square;
  std::vector<std::size_t> count;
};

FoldErrors fold_errors(const AxisData& data, const Structure& s, const ThermalFitOptions& options) {
  const int folds = options.cross_validation_folds;
  const std::size_t block = static_cast<std::size_t>(std::max(1, options.cross_validation_block_windows));
  FoldErrors out;
  for (int fold = 0; fold < folds; ++fold) {
    std::vector<std::size_t> train, test;
    for (std::size_t r = 0; r < data.y.size(); ++r)
      ((r / block) % folds == static_cast<std::size_t>(fold) ? test : train).push_back(r);
    std::vector<int> column;
    const Solution solution = fit_rows(data, train, s, &column);
    out.constrained.push_back(solution.ok);
    out.square.push_back(0.0);
    out.count.push_back(0);
    if (!solution.ok) continue;
    Structure kept = s;
    kept.clusters = static_cast<int>(std::count_if(column.begin(), column.end(), [](int c) { return c >= 0; }));
    Eigen::RowVectorXd row(kept.columns());
    for (std::size_t r : test) {
      if (column[data.cluster[r]] < 0) continue;  // an orientation (or visit) seen only in this fold
      fill_row(data, r, kept, column, row);
      const double error = data.y[r] - row.dot(solution.beta);
      out.square.back() += error * error;
      ++out.count.back();
    }
  }
  return out;
}

// The candidates' scores over the same folds: a fold whose training rows leave even the simplest
// candidate singular (it holds, say, every window of an orientation at two of its three
// temperatures) says nothing about the orders and is left out for all; a candidate singular in
// another fold cannot be fitted reliably and scores infinite.
std::vector<CrossValidation> score_on_common_folds(const std::vector<FoldErrors>& candidates) {
  std::vector<CrossValidation> scores(candidates.size());
  if (candidates.empty()) return scores;
  const std::size_t folds = candidates.front().constrained.size();
  std::vector<bool> informative(folds, false);
  for (const FoldErrors& candidate : candidates) {
    for (std::size_t f = 0; f < folds; ++f) informative[f] = informative[f] || candidate.constrained[f];
  }
  for (std::size_t c = 0; c < candidates.size(); ++c) {
    const FoldErrors& errors = candidates[c];
    std::vector<double> fold_mean_square;
    double total_square = 0.0;
    std::size_t total_count = 0;
    bool usable = true;
    for (std::size_t f = 0; f < folds && usable; ++f) {
      if (!informative[f]) continue;
      usable = errors.constrained[f];
      if (!usable || errors.count[f] == 0) continue;
      fold_mean_square.push_back(errors.square[f] / errors.count[f]);
      total_square += errors.square[f];
      total_count += errors.count[f];
    }
    if (!usable || total_count == 0 || fold_mean_square.size() < 2) continue;
    CrossValidation& out = scores[c];
    out.mean_square = total_square / total_count;
    double mean = 0.0, spread = 0.0;
    for (double value : fold_mean_square) mean += value;
    mean /= fold_mean_square.size();
    for (double value : fold_mean_square) spread += (value - mean) * (value - mean);
    out.standard_error = std::sqrt(spread / (fold_mean_square.size() - 1) / fold_mean_square.size());
  }
  return scores;
}

std::string axis_label(const TriadSpec& triad, int axis) { return std::string(triad.name) + " " + kAxisNames[axis]; }

std::string span_text(double min_c, double max_c) {
  std::ostringstream text;
  text << std::fixed << std::setprecision(1) << (max_c - min_c) << " degC (" << min_c << " .. " << max_c << ")";
  return text.str();
}

// Orders 1..max that the span and the window count can constrain.
std::vector<int> admissible_orders(const ThermalFitOptions& options, double span_c, std::size_t rows,
                                   const Structure& base, bool scale) {
  std::vector<int> orders;
  const int low = options.polynomial_order.value_or(1);
  const int high = options.polynomial_order.value_or(options.max_polynomial_order);
  for (int order = low; order <= high; ++order) {
    Structure s = base;
    s.bias_order = order;
    s.scale_order = scale ? order : 0;
    if (span_c >= options.min_span_per_order_c * order &&
        rows >= static_cast<std::size_t>(s.columns() + options.min_spare_windows)) {
      orders.push_back(order);
    }
  }
  return orders;
}

void refuse_unconstrained(const ThermalFitOptions& options, double min_c, double max_c, std::size_t rows,
                          const Structure& base, bool scale) {
  const int order = options.polynomial_order.value_or(1);
  Structure s = base;
  s.bias_order = order;
  s.scale_order = scale ? order : 0;
  std::ostringstream text;
  text << "the thermal test cannot constrain a polynomial of order " << order << ": ";
  if (max_c - min_c < options.min_span_per_order_c * order) {
    text << "the static windows span only " << span_text(min_c, max_c) << ", and order " << order << " needs at least "
         << options.min_span_per_order_c * order << " degC (" << options.min_span_per_order_c
         << " degC per order); run the thermal profile over a wider range"
         << (options.polynomial_order && order > 1 ? " or ask for a lower order" : "");
  } else {
    text << rows << " static windows for " << s.columns() << " parameters (" << options.min_spare_windows
         << " spare windows needed); record a longer test, shorten the averaging window"
         << (options.polynomial_order && order > 1 ? " or ask for a lower order" : "");
  }
  throw ThermalFitError(text.str());
}

// terms[1] (the dynamic regime's) only with s.regimes == 2; it shares the scale-factor terms.
void fill_terms(const Structure& s, const Solution& solution, const AxisData& data, const TriadSpec& triad,
                AxisThermalTerms* const terms[2], AxisFitReport* report) {
  int c = s.clusters;
  const auto add = [&](const std::string& name, double factor, const std::string& unit) {
    const double value = solution.beta[c] * factor;
    report->parameters.push_back({name, value, std::sqrt(solution.covariance(c, c)) * std::abs(factor), unit});
    ++c;
    return value;
  };
  const std::string u = triad.unit;
  const auto per_degree = [](int k) { return "/degC^" + std::to_string(k); };
  for (int regime = 0; regime < s.regimes; ++regime) {
    AxisThermalTerms* const t = terms[regime];
    const std::string prefix = regime == 1 ? "dynamic." : "";
    for (int k = 1; k <= s.bias_order; ++k) {
      t->bias_polynomial.push_back(add(prefix + "bias_polynomial[" + std::to_string(k - 1) + "]",
                                       std::pow(kTemperatureUnit_c, -k), u + per_degree(k)));
    }
    if (s.rate) {
      t->bias_per_temperature_rate = add(prefix + "bias_per_temperature_rate", 1.0 / kRateUnit_c_s, u + "/(degC/s)");
    }
    for (int k = 1; k <= s.second_order; ++k) {
      t->bias_second_sensor_polynomial.push_back(
          add(prefix + "bias_second_sensor_polynomial[" + std::to_string(k - 1) + "]", std::pow(kTemperatureUnit_c, -k),
              u + per_degree(k)));
    }
  }
  AxisThermalTerms* const shared = terms[0];
  const double ppm_per_unit = 1e6 / data.input_reference;
  for (int k = 1; k <= s.scale_order; ++k) {
    shared->scale_factor_polynomial_ppm.push_back(add("scale_factor_polynomial_ppm[" + std::to_string(k - 1) + "]",
                                                      ppm_per_unit * std::pow(kTemperatureUnit_c, -k),
                                                      "ppm" + per_degree(k)));
  }
  if (s.scale_order > 0 && s.scale_rate) {
    shared->scale_factor_ppm_per_temperature_rate =
        add("scale_factor_ppm_per_temperature_rate", ppm_per_unit / kRateUnit_c_s, "ppm/(degC/s)");
  }
  if (s.scale_order > 0) {
    for (int k = 1; k <= s.second_scale_order; ++k) {
      shared->scale_factor_second_sensor_polynomial_ppm.push_back(
          add("scale_factor_second_sensor_polynomial_ppm[" + std::to_string(k - 1) + "]",
              ppm_per_unit * std::pow(kTemperatureUnit_c, -k), "ppm" + per_degree(k)));
    }
  }
  if (s.regimes > 1) {
    terms[1]->scale_factor_polynomial_ppm = shared->scale_factor_polynomial_ppm;
    terms[1]->scale_factor_ppm_per_temperature_rate = shared->scale_factor_ppm_per_temperature_rate;
    terms[1]->scale_factor_second_sensor_polynomial_ppm = shared->scale_factor_second_sensor_polynomial_ppm;
  }
}

// The regime switch needs each regime's bias terms constrained by that regime's own windows.
void refuse_thin_regime(const std::string& axis, const AxisData& data, const Structure& s,
                        const ThermalFitOptions& options) {
  std::size_t rows[2] = {0, 0};
  for (int regime : data.regime) ++rows[regime];
  for (int regime = 0; regime < 2; ++regime) {
    const std::size_t needed = static_cast<std::size_t>(s.bias_columns() + options.min_spare_windows);
    if (rows[regime] >= needed) continue;
    std::ostringstream text;
    text << axis << ": the " << (regime == 1 ? "dynamic" : "static") << " regime (|d2T/dt2| "
         << (regime == 1 ? "above" : "at or below") << " " << options.regime_switch.threshold_c_s2 << " degC/s^2, hold "
         << options.regime_switch.hold_s << " s) holds " << rows[regime]
         << " static windows, and its own bias terms need at least " << needed << " (" << s.bias_columns()
         << " parameter(s) + " << options.min_spare_windows << " spare); "
         << (regime == 1 ? "lower the threshold, lengthen the hold, or record faster or more temperature changes"
                         : "raise the threshold or shorten the hold")
         << ", or fit without the regime switch";
    throw ThermalFitError(text.str());
  }
}

}  // namespace

ThermalFitResult fit_thermal_model(const std::vector<ThermalWindow>& windows, double rate_window_s,
                                   const ThermalFitOptions& options) {
  if (options.polynomial_order && (*options.polynomial_order < 1 || *options.polynomial_order > 4)) {
    throw ThermalFitError("polynomial order must be 1 to 4, got " + std::to_string(*options.polynomial_order));
  }
  ThermalFitResult result;
  result.orientations = cluster_by_gravity(windows, options.cluster_angle_rad, options.earth);
  const OrientationAssignment& orientations = result.orientations;
  std::vector<std::size_t> used;  // static windows
  for (std::size_t w = 0; w < windows.size(); ++w) {
    if (orientations.cluster_of_window[w] >= 0) used.push_back(w);
  }
  if (used.empty()) {
    throw ThermalFitError("the thermal test has no static window (" + std::to_string(windows.size()) +
                          " windows, none with the IMU at rest); a thermal test keeps the IMU still in known "
                          "orientations, or the static thresholds are too tight for this sensor's noise");
  }
  if (options.second_sensor_scale_factor && !options.second_sensor_term) {
    throw ThermalFitError(
        "the second-sensor scale-factor term needs the second-sensor term (a second thermosensor topic)");
  }
  if (options.regime_switch.enabled) {
    try {
      check_regime_settings(options.regime_switch);
    } catch (const std::invalid_argument& error) {
      throw ThermalFitError(error.what());
    }
    if (!windows[used.front()].dynamic_fraction) {
      throw ThermalFitError(
          "the regime switch needs windows averaged with the regime indicator (ThermalWindowAverager with a "
          "RegimeIndicator)");
    }
  }
  if (options.second_sensor_term && !windows[used.front()].second_temperature_c) {
    throw ThermalFitError(
        "the second-sensor term needs a second thermosensor topic; give it, or fit without "
        "the second-sensor term");
  }
  result.static_window_count = used.size();
  // Visits: runs of static windows in one orientation, broken by a move (or any window not static).
  std::vector<int> visit_of_window(windows.size(), -1);
  int visits = 0;
  for (std::size_t w = 0, previous = windows.size(); w < windows.size(); ++w) {
    if (orientations.cluster_of_window[w] < 0) continue;
    const bool continues =
        previous + 1 == w && orientations.cluster_of_window[previous] == orientations.cluster_of_window[w];
    visit_of_window[w] = continues ? visit_of_window[previous] : visits++;
    previous = w;
  }
  result.visit_count = static_cast<std::size_t>(visits);
  const double along_gravity_cosine = std::cos(options.cluster_angle_rad);

  ThermalModel& model = result.model;
  model.reference_temperature_c = options.reference_temperature_c;
  model.rate_window_s = rate_window_s;
  model.uses_temperature_rate = options.temperature_rate_term || options.scale_factor_rate_term;
  model.uses_second_sensor = options.second_sensor_term;
  if (options.regime_switch.enabled) model.regime_switch = options.regime_switch;
  ThermalValidity& box = model.validity;
  box.temperature_min_c = box.rate_min_c_s = box.second_temperature_min_c = std::numeric_limits<double>::infinity();
  box.temperature_max_c = box.rate_max_c_s = box.second_temperature_max_c = -std::numeric_limits<double>::infinity();
  for (std::size_t w : used) {
    box.temperature_min_c = std::min(box.temperature_min_c, windows[w].temperature_c);
    box.temperature_max_c = std::max(box.temperature_max_c, windows[w].temperature_c);
    box.rate_min_c_s = std::min(box.rate_min_c_s, windows[w].rate_c_s);
    box.rate_max_c_s = std::max(box.rate_max_c_s, windows[w].rate_c_s);
    const double second_c = windows[w].second_temperature_c.value_or(windows[w].temperature_c);
    box.second_temperature_min_c = std::min(box.second_temperature_min_c, second_c);
    box.second_temperature_max_c = std::max(box.second_temperature_max_c, second_c);
  }
  // A steady temperature (rate 0) always belongs inside: there the rate term adds nothing, whatever
  // rates the test ran through. Without it, a test whose static windows all saw some drift left 0
  // outside, and a steady temperature was "clamped" to a rate the sensor never had. The margin (a
  // tenth of the largest tested rate) keeps the noise of a steady temperature's rate estimate in.
  const double rate_margin_c_s = 0.1 * std::max(std::abs(box.rate_min_c_s), std::abs(box.rate_max_c_s));
  box.rate_min_c_s = std::min(box.rate_min_c_s, 0.0) - rate_margin_c_s;
  box.rate_max_c_s = std::max(box.rate_max_c_s, 0.0) + rate_margin_c_s;

  const TriadSpec triads[2] = {
      {"gyro", "rad/s", options.gyro_scale_factor, options.earth.earth_rate_rad_s},
      {"accelerometer", "m/s^2", options.accelerometer_scale_factor, options.earth.gravity_m_s2}};
  TriadThermalTerms* terms_of[2] = {&model.gyro, &model.accelerometer};
  TriadThermalTerms* dynamic_terms_of[2] = {&model.dynamic_gyro, &model.dynamic_accelerometer};

  // One orientation cannot separate bias(T) from scale factor(T): refuse before fitting anything.
  std::vector<std::string> single_sided;
  for (const TriadSpec& triad : triads) {
    if (!triad.scale_factor) continue;
    for (int axis = 0; axis < 3; ++axis) {
      bool up = false, down = false;
      for (const OrientationCluster& cluster : orientations.clusters) {
        const Eigen::Vector3d& input =
            triad.name == std::string("gyro") ? cluster.angular_rate_input_rad_s : cluster.specific_force_input_m_s2;
        up = up || input[axis] > 0.5 * triad.input_reference;
        down = down || input[axis] < -0.5 * triad.input_reference;
      }
      if (!(up && down)) single_sided.push_back(axis_label(triad, axis));
    }
  }
  if (!single_sided.empty()) {
    std::string axes;
    for (const auto& label : single_sided) axes += (axes.empty() ? "" : ", ") + label;
    throw ThermalFitError(
        "scale factor vs temperature needs each axis in at least two opposite orientations (input "
        "up and down), but " +
        axes + " saw only one side in the " + std::to_string(orientations.clusters.size()) +
        " orientation(s) of this test: one orientation cannot separate bias(T) from scale "
        "factor(T). Record a multi-position thermal test (e.g. config/scenarios/"
        "thermal_multiposition.yaml) or fit the bias only (no scale-factor term)");
  }

  for (int t = 0; t < 2; ++t) {
    const TriadSpec& triad = triads[t];
    for (int axis = 0; axis < 3; ++axis) {
      AxisData data;
      data.input_reference = triad.input_reference;
      for (std::size_t w : used) {
        const ThermalWindow& window = windows[w];
        const OrientationCluster& cluster = orientations.clusters[orientations.cluster_of_window[w]];
        const bool gyro = t == 0;
        data.y.push_back(gyro ? window.mean_angular_rate_rad_s[axis] : window.mean_specific_force_m_s2[axis]);
        data.delta_t.push_back(window.temperature_c - options.reference_temperature_c);
        data.rate.push_back(window.rate_c_s);
        data.second_delta_t.push_back(window.second_temperature_c.value_or(window.temperature_c) -
                                      options.reference_temperature_c);
        data.input.push_back(gyro ? cluster.angular_rate_input_rad_s[axis] : cluster.specific_force_input_m_s2[axis]);
        const bool along_gravity = std::abs(cluster.up_body[axis]) >= along_gravity_cosine;
        const int clusters = static_cast<int>(orientations.clusters.size());
        data.cluster.push_back(options.precise_revisits || along_gravity ? orientations.cluster_of_window[w]
                                                                         : clusters + visit_of_window[w]);
        // A window is in the regime of most of its samples.
        data.regime.push_back(options.regime_switch.enabled && *window.dynamic_fraction > 0.5 ? 1 : 0);
      }
      Structure base;
      base.clusters = static_cast<int>(orientations.clusters.size()) + visits;
      base.rate = options.temperature_rate_term;
      base.scale_rate = options.scale_factor_rate_term;
      base.second_order = options.second_sensor_term ? options.second_sensor_order : 0;
      base.second_scale_order = options.second_sensor_scale_factor ? options.second_sensor_order : 0;
      base.regimes = options.regime_switch.enabled ? 2 : 1;
      // base.clusters numbers the constants (orientations, then visits); the parameters are the
      // constants this axis uses.
      Structure counted = base;
      counted.clusters = static_cast<int>(std::set<int>(data.cluster.begin(), data.cluster.end()).size());
      const std::vector<int> orders = admissible_orders(options, box.temperature_max_c - box.temperature_min_c,
                                                        data.y.size(), counted, triad.scale_factor);
      if (orders.empty()) {
        refuse_unconstrained(options, box.temperature_min_c, box.temperature_max_c, data.y.size(), counted,
                             triad.scale_factor);
      }
      if (base.regimes > 1) {
        Structure lowest = base;
        lowest.bias_order = orders.front();
        refuse_thin_regime(axis_label(triad, axis), data, lowest, options);
      }

      AxisFitReport report;
      report.triad = triad.name;
      report.axis = axis;
      report.window_count = data.y.size();
      Structure chosen = base;
      if (options.polynomial_order) {
        chosen.bias_order = *options.polynomial_order;
        chosen.scale_order = triad.scale_factor ? chosen.bias_order : 0;
      } else {
        // Every admissible pair of orders; the simplest within one standard error of the best.
        struct Candidate {
          Structure structure;
          CrossValidation score;
        };
        std::vector<Candidate> candidates;
        std::vector<FoldErrors> errors;
        for (int bias_order : orders) {
          for (int scale_order : triad.scale_factor ? orders : std::vector<int>{0}) {
            Structure s = base;
            s.bias_order = bias_order;
            s.scale_order = scale_order;
            candidates.push_back({s, CrossValidation()});
            errors.push_back(fold_errors(data, s, options));
          }
        }
        const std::vector<CrossValidation> scores = score_on_common_folds(errors);
        for (std::size_t c = 0; c < candidates.size(); ++c) candidates[c].score = scores[c];
        const auto best = std::min_element(
            candidates.begin(), candidates.end(),
            [](const Candidate& a, const Candidate& b) { return a.score.mean_square < b.score.mean_square; });
        if (!std::isfinite(best->score.mean_square)) {
          throw ThermalFitError(axis_label(triad, axis) +
                                ": no polynomial order can be fitted: the orientations "
                                "and temperatures of this test leave the model singular; add dwells at more "
                                "temperatures in each orientation");
        }
        const double limit = best->score.mean_square + best->score.standard_error;
        const Candidate* simplest = &*best;
        for (const Candidate& candidate : candidates) {
          if (candidate.score.mean_square <= limit && candidate.structure.columns() < simplest->structure.columns()) {
            simplest = &candidate;
          }
        }
        chosen = simplest->structure;
        report.cross_validation_rms = std::sqrt(simplest->score.mean_square);
      }

      std::vector<std::size_t> all(data.y.size());
      for (std::size_t r = 0; r < all.size(); ++r) all[r] = r;
      std::vector<int> column;
      const Solution solution = fit_rows(data, all, chosen, &column);
      if (!solution.ok) {
        throw ThermalFitError(axis_label(triad, axis) + ": the test cannot constrain a polynomial of order " +
                              std::to_string(chosen.bias_order) +
                              (chosen.scale_order > 0 ? " for bias and scale factor" : " for the bias") +
                              ": the orientations and temperatures leave the model singular (opposite "
                              "orientations seen at too few temperatures?); ask for a lower order or add dwells "
                              "at more temperatures" +
                              (chosen.second_scale_order > 0
                                   ? std::string("; the second-sensor scale factor also needs each axis up and down "
                                                 "while the two sensors disagree (during temperature changes)")
                                   : std::string()));
      }
      // The solution's layout: only the constants (orientations, visits) that have rows.
      chosen.clusters = static_cast<int>(std::count_if(column.begin(), column.end(), [](int c) { return c >= 0; }));
      report.bias_order = chosen.bias_order;
      report.scale_factor_order = chosen.scale_order;
      report.residual_rms = std::sqrt(solution.residual_sum_squares / data.y.size());
      report.constant_count = static_cast<std::size_t>(chosen.clusters);
      AxisThermalTerms* const terms_by_regime[2] = {&(*terms_of[t])[axis], &(*dynamic_terms_of[t])[axis]};
      fill_terms(chosen, solution, data, triad, terms_by_regime, &report);

      double fitted_min = std::numeric_limits<double>::infinity(), fitted_max = -fitted_min;
      Eigen::RowVectorXd row(chosen.columns());
      for (std::size_t r = 0; r < data.y.size(); ++r) {
        const ThermalWindow& window = windows[used[r]];
        ThermalInput input{window.temperature_c, window.rate_c_s, window.second_temperature_c, data.regime[r] == 1};
        const AxisThermalTerms& terms = *terms_by_regime[data.regime[r]];
        const double delta_bias = axis_delta_bias(model, terms, input);
        fill_row(data, r, chosen, column, row);
        const double predicted = row.dot(solution.beta);
        const double polynomial = polynomial_without_constant(terms.bias_polynomial, data.delta_t[r]);
        WindowResidual residual;
        residual.triad = triad.name;
        residual.axis = axis;
        residual.stamp_s = window.mid_stamp_s;
        residual.temperature_c = window.temperature_c;
        residual.rate_c_s = window.rate_c_s;
        residual.cluster = orientations.cluster_of_window[used[r]];  // the orientation, not the visit
        residual.residual = data.y[r] - predicted;
        residual.fitted_delta_bias = polynomial;
        residual.observed_delta_bias = polynomial + residual.residual;
        result.residuals.push_back(residual);
        fitted_min = std::min(fitted_min, delta_bias);
        fitted_max = std::max(fitted_max, delta_bias);
      }
      report.delta_bias_peak_to_peak = fitted_max - fitted_min;
      // The noise of a window mean from the residuals themselves: half the mean square of the
      // change between neighbouring windows of one visit (the Allan variance at the window's
      // length: white noise and flicker, without the slow wander or a misfit between visits).
      double change_square = 0.0;
      std::size_t changes = 0;
      const std::size_t first = result.residuals.size() - data.y.size();
      for (std::size_t r = 0; r + 1 < data.y.size(); ++r) {
        if (used[r + 1] != used[r] + 1 || visit_of_window[used[r + 1]] != visit_of_window[used[r]]) continue;
        const double change = result.residuals[first + r + 1].residual - result.residuals[first + r].residual;
        change_square += change * change;
        ++changes;
      }
      report.window_noise = changes > 0 ? std::sqrt(change_square / (2.0 * changes)) : 0.0;
      report.residual_over_noise = report.window_noise > 0.0 ? report.residual_rms / report.window_noise
                                                             : std::numeric_limits<double>::infinity();
      const std::string warning = chi2_warning(
          axis_label(triad, axis), report.residual_over_noise * report.residual_over_noise,
          "did the IMU move during the rests, or do revisits of an orientation differ in a way one constant per "
          "visit does not absorb (precise revisits claimed for a hand-turned test)? The residuals per window are "
          "in the residual CSV");
      if (!warning.empty()) result.warnings.push_back(warning);
      result.axes.push_back(report);
    }
  }
  return result;
}

}  // namespace thermal
}  // namespace imu_lab
