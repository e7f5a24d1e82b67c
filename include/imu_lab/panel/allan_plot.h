// What the Allan deviation panel draws, without ROS or Qt: the live stability curves of one axis
// (allan_monitor's allan/gyro, allan/accel) with their confidence band, the identified model's total
// and term curves (allan/noise) and, per term, how much longer the record must run for the term to
// be resolved. Everything is on log10 axes; the widget only maps these numbers to pixels.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace imu_lab {
namespace panel {

// One triad's curves of one statistic, as imu_lab/AllanDeviation carries them.
struct StabilityAxis {
  std::string name;               // x, y or z
  std::vector<double> deviation;  // parallel to StabilityCurves::tau_s; NaN where missing
  std::vector<double> lower;      // bounds at StabilityCurves::confidence
  std::vector<double> upper;
};

struct StabilityCurves {
  std::string statistic;  // oadev, adev, mdev, ...
  std::string sensor;     // gyro or accel
  std::string unit;       // rad/s or m/s^2
  double tau0_s = 0.0;
  double confidence = 0.0;
  std::uint64_t samples = 0;
  std::vector<double> tau_s;
  std::vector<StabilityAxis> axes;
};

// One identified term, as imu_lab/NoiseAxis carries it (SI values).
struct NoiseTerm {
  std::string name;    // white_rate, bias_instability, markov_1, ...
  std::string symbol;  // N, B, K, ...
  std::string status;  // present, unconstrained, absent
  double value = 0.0;  // amplitude; NaN when not estimated
  double shape = 0.0;  // NaN when the term has none
  double width = 0.0;  // resonance only; NaN otherwise
  // Record the fit says the term needs to reach NoiseReport::target_relative_sigma; infinity when
  // no record the search considers suffices, NaN when not computed (absent terms).
  double required_record_length_s = 0.0;
};

struct NoiseAxisModel {
  std::string axis;  // gyro_x, ..., accel_z
  std::vector<NoiseTerm> terms;
  double output_quantization_density = 0.0;  // white noise of the output's rounding, u/sqrt(Hz)
};

struct NoiseReport {
  double tau0_s = 0.0;
  double record_length_s = 0.0;        // what the fit was made on
  double target_relative_sigma = 0.0;  // the precision "resolved" means for the record lengths
  std::vector<std::string> problems;
  std::vector<NoiseAxisModel> axes;
};

struct LogPoint {
  double log10_tau = 0.0;
  double log10_deviation = 0.0;
};

struct BandSegmentPoint {
  double log10_tau = 0.0;
  double log10_lower = 0.0;
  double log10_upper = 0.0;
};

enum class SeriesRole { kMeasured, kModelTotal, kModelTerm };

struct PlotSeries {
  std::string label;
  SeriesRole role = SeriesRole::kMeasured;
  bool constrained = true;  // false: an unconstrained term (its value is an estimate, not a result)
  std::vector<LogPoint> points;
};

// Whole decades enclosing what is drawn.
struct DecadeRange {
  int low = 0;
  int high = 1;
};

struct AllanPlot {
  std::string title;  // "gyro x, oadev (rad/s)"
  PlotSeries measured;
  std::vector<BandSegmentPoint> band;  // the measured curve's confidence band
  std::vector<PlotSeries> model;       // the fitted total first, then each term
  DecadeRange tau_decades;
  DecadeRange deviation_decades;
  std::vector<std::string> status_lines;         // record so far, band, model's origin, problems
  std::vector<std::string> record_length_lines;  // "K: about 3.2 h more", per term in report order
  bool empty() const { return measured.points.empty(); }
};

// "45 s", "12 min", "3.2 h", "2.5 d": two significant digits below ten of the unit, whole units
// above; minutes from 100 s, hours from 100 min, days from 48 h.
std::string duration_text(double duration_s);

// Per term in the model (present or unconstrained): "K: about 3.2 h more" while the record is shorter
// than the term needs, "K: resolved" once it is long enough, "K: not within 10000 x this record" when
// no length the search considered suffices. Terms without a required length are left out.
std::vector<std::string> record_length_lines(const NoiseAxisModel& axis, double recorded_s);

// The model's total and term curves at `tau_s` (deviations), the output's rounding as a term when
// the axis has one. Terms without a finite value are left out of both.
std::vector<PlotSeries> model_series(const NoiseAxisModel& axis, const std::vector<double>& tau_s);

// The latest curves per triad and statistic, the latest noise report, and the plot of a selection.
class AllanPanelModel {
 public:
  // Replaces what was stored for the curves' sensor and statistic.
  void add_curves(StabilityCurves curves);
  void set_noise_report(NoiseReport report);

  // Sensors and statistics seen so far, in arrival order.
  const std::vector<std::string>& sensors() const { return sensors_; }
  std::vector<std::string> statistics(const std::string& sensor) const;
  bool has_noise_report() const { return has_report_; }

  // The plot of one axis (0, 1, 2) of one triad's statistic; empty() when nothing has arrived for it.
  AllanPlot plot(const std::string& sensor, const std::string& statistic, int axis) const;

 private:
  std::map<std::pair<std::string, std::string>, StabilityCurves> curves_;
  std::vector<std::string> sensors_;
  std::map<std::string, std::vector<std::string>> statistics_;
  NoiseReport report_;
  bool has_report_ = false;
};

}  // namespace panel
}  // namespace imu_lab
