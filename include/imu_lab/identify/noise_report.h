// The YAML noise report: per triad and axis, each term with its status, value, sigma (and where
// the sigma came from) and bound, in SI and in the field's units (unit always in the key); fit
// quality; the graphical readings, labelled as such; warnings; the selection steps.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "imu_lab/identify/triad_fit.h"

namespace imu_lab {
namespace identify {

// A disturbance found before the Allan pass (a knock, a spike): its samples were left out and the
// record split there, so the curves and this fit never saw it; listed so that nothing hides it.
struct ReportEvent {
  double onset_s = 0.0;         // first sample over the screen's threshold, from the first stamp
  double window_start_s = 0.0;  // the samples left out, from the first stamp
  double window_end_s = 0.0;
  std::string peak_channel;  // "accel_z", ...
  double peak_sigma = 0.0;   // signed, in the channel's robust scales
  long long dropped_samples = 0;
};

// A step in the level with no impulse (a tilt, a bias jump) found before the Allan pass: the
// stepping triad's record was split there, so the step lies between two pooled segments.
struct ReportLevelShift {
  double step_s = 0.0;          // where the largest difference in scales lies, from the first stamp
  double window_start_s = 0.0;  // the samples left out (of the stepping triad), from the first stamp
  double window_end_s = 0.0;
  std::string peak_channel;
  double peak_sigma = 0.0;
  std::vector<std::pair<std::string, double>> shifts;  // per channel over the threshold: key with unit, step
  long long masked_samples = 0;
};

struct ReportMetadata {
  std::string source;            // bag or file the curves came from
  double update_rate_hz = 0.0;   // measured
  bool events_screened = false;  // whether a screen looked for events at all
  long long event_count = 0;     // all events (the list may be truncated)
  std::vector<ReportEvent> events;
  bool level_shifts_screened = false;
  long long level_shift_count = 0;
  std::vector<ReportLevelShift> level_shifts;
};

// Key of a parameter in the report: "<symbol>_<unit>" (e.g. "N_deg_per_sqrt_h"), with suffix
// "_sigma" for its uncertainty and "_upper_<confidence %>" for its bound.
std::string parameter_key(const std::string& symbol, const std::string& unit_key);
std::string upper_bound_suffix(double confidence);  // 0.95 -> "_upper_95"

std::string format_noise_report(const std::vector<TriadFit>& triads, const ReportMetadata& metadata);
// Atomic (common/atomic_file.h).
void write_noise_report(const std::string& path, const std::vector<TriadFit>& triads, const ReportMetadata& metadata);

// Every numeric leaf of a report, keyed by its dotted path
// ("triads.gyro.axes.gyro_x.terms.white_rate.N_rad_s_per_sqrt_hz"). Throws InputError if the
// text is not a noise report.
std::map<std::string, double> read_noise_report_values(const std::string& yaml_text);
// The same from a file; InputError names the file when it cannot be read or is not a report.
std::map<std::string, double> read_noise_report_file(const std::string& path);

// One axis's identified model as a report gives it: the terms with status "present" (absent and
// unconstrained terms carry bounds only and are left out), the front end's fitted or given
// low-pass as the white rate's shape, the output quantization step as its white density
// (step sqrt(tau0 / 12)), and the axis's tau0.
struct ReportedAxisModel {
  std::string axis;  // "gyro_x", ...
  NoiseModel model;
  double tau0_s = 0.0;
};
// The three axes of `sensor`'s triad. Throws InputError naming the dotted key that is missing or
// not a number, or the triad when the report has none.
std::vector<ReportedAxisModel> read_reported_axis_models(const std::string& yaml_text, SensorKind sensor);
// The same from a file; every InputError names it.
std::vector<ReportedAxisModel> load_reported_axis_models(const std::string& path, SensorKind sensor);

}  // namespace identify
}  // namespace imu_lab
