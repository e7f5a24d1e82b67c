// Run-to-run (switch-on to switch-on) repeatability of one unit from N recordings, in the form of
// the bias tables of a test report (one row per run, then mean and spread):
//   per run and channel: the bias (mean over the run or its window), the standard uncertainty of
//   that mean from the run's own noise, and the in-run stability (the minimum of the overlapping
//   Allan deviation with its tau); per channel across runs: the sample standard deviation (n - 1)
//   of the run biases with its two-sided chi-squared confidence interval (IEEE Std 952 / NIST SP
//   1065's chi-squared bounds with n - 1 degrees of freedom). What the spread estimates is the
//   switch-on sigma combined in quadrature with the uncertainty of a run's mean. Identified noise
//   terms per run are carried as name, value, sigma, so this does not depend on how a fit stores
//   them. See doc/repeatability.md.
#pragma once

#include <array>
#include <cstddef>
#include <map>
#include <string>
#include <vector>

namespace imu_lab {
namespace repeatability {

constexpr std::size_t kChannelCount = 6;
// Channel names and units as in the Allan CSVs: gyro x..z [rad/s], accelerometer x..z [m/s^2].
constexpr std::array<const char*, kChannelCount> kChannelNames = {"gyro_x",  "gyro_y",  "gyro_z",
                                                                  "accel_x", "accel_y", "accel_z"};
constexpr std::array<const char*, kChannelCount> kChannelUnits = {"rad_s", "rad_s", "rad_s", "m_s2", "m_s2", "m_s2"};

// A sample standard deviation with its chi-squared confidence interval.
struct SpreadEstimate {
  std::size_t count = 0;
  double mean = 0.0;
  double standard_deviation = 0.0;  // with n - 1
  double lower = 0.0, upper = 0.0;  // two-sided interval at `confidence`
  double confidence = 0.0;
};
// Throws std::invalid_argument for fewer than 2 values, a non-finite one or confidence outside (0, 1).
SpreadEstimate spread_of(const std::vector<double>& values, double confidence);

// The median (mean of the two middle values for an even count). Throws std::invalid_argument for
// no values.
double median_of(std::vector<double> values);

struct RunChannel {
  double bias = 0.0;              // mean of the run (window)
  double mean_uncertainty = 0.0;  // standard uncertainty of that mean from the run's noise
  double allan_minimum = 0.0;     // smallest overlapping Allan deviation (octave taus)
  double allan_minimum_tau_s = 0.0;
};

// An identified noise term of one run (e.g. channel gyro_x, term bias_instability).
struct IdentifiedTerm {
  std::string channel, term, parameter;  // parameter: symbol and unit, e.g. N_rad_s_per_sqrt_hz
  double value = 0.0, sigma = 0.0;
};

// The identified terms of a noise report, from its numeric leaves as
// identify::read_noise_report_values gives them ("triads.gyro.axes.gyro_x.terms.white_rate.
// N_rad_s_per_sqrt_hz" with its "..._sigma"): every value that has a sigma, in each unit the
// report gives.
std::vector<IdentifiedTerm> identified_terms(const std::map<std::string, double>& report_values);

struct RunSummary {
  std::string name;
  std::size_t sample_count = 0;
  double duration_s = 0.0;
  std::array<RunChannel, kChannelCount> channels{};
  std::vector<IdentifiedTerm> terms;
};

// One run's samples (each row gyro x..z, accelerometer x..z) at sample period tau0_s. The mean's
// uncertainty is the overlapping Allan deviation extrapolated to tau = the run's length T along an
// EDF-weighted log-log line through its octave points from T/64 on (slope clamped to [-1/2, +1/2],
// white rate to rate random walk): for white noise and a random walk from zero, AVAR(tau) is
// exactly the variance of a tau-average (IEEE Std 952 annex C), so at T, that of the run's mean.
// Throws std::invalid_argument for fewer than 16 samples, tau0_s <= 0 or a non-finite value.
RunSummary summarise_run(const std::string& name, const std::vector<std::array<double, kChannelCount>>& samples,
                         double tau0_s);

struct RepeatabilityTable {
  std::vector<RunSummary> runs;
  double confidence = 0.95;
  std::array<SpreadEstimate, kChannelCount> bias_spread{};   // run-to-run, per channel
  std::array<double, kChannelCount> rms_mean_uncertainty{};  // of the runs' means, per channel
  std::array<double, kChannelCount> median_allan_minimum{};
};
// Throws std::invalid_argument for fewer than 2 runs.
RepeatabilityTable repeatability_table(const std::vector<RunSummary>& runs, double confidence);

// One row per run and channel, then the channel's mean and spread rows (CSV, SI units in the header).
std::string repeatability_csv(const RepeatabilityTable& table);
std::string repeatability_yaml(const RepeatabilityTable& table);

// Repeatability of calibration parameters (scale factor, misalignment) from several calibrations
// of one unit: one named value per parameter per calibration, the same names in each.
struct ParameterSpread {
  std::string name, unit;
  std::vector<double> values;  // one per calibration, in order
  SpreadEstimate spread;
};
// Throws std::invalid_argument when the calibrations do not name the same parameters, or fewer than 2.
std::vector<ParameterSpread> parameter_spreads(
    const std::vector<std::vector<std::pair<std::string, double>>>& calibrations, const std::string& unit,
    double confidence);
std::string parameter_spreads_csv(const std::vector<ParameterSpread>& spreads);

}  // namespace repeatability
}  // namespace imu_lab
