// The allan tool's console report of the identified noise, for a person:
//   - the four numbers Kalibr and OpenVINS take (format_kalibr_lines);
//   - one row per axis of the five IEEE Std 952 terms N, B, K, Q, R in the field's customary units
//     (deg/sqrt(h), deg/h, deg/h/sqrt(h); m/s/sqrt(h), micro-g, ...) with one sigma, or "< bound"
//     where the term was not found, and under the row the other terms in the model
//     (format_ieee_table; axis_summary builds one axis's row and lines);
//   - the fit's warnings grouped by kind in plain words, each with the axes and values it
//     concerns in the table's units (format_grouped_findings);
//   - with --verbose, the full table: every term with its status, sigma source, 68.3 % interval
//     and shape, each axis's warnings as noise.yaml words them, and each triad's worst axis
//     (format_noise_table).
#pragma once

#include <string>
#include <vector>

#include "imu_lab/identify/kalibr_yaml.h"
#include "imu_lab/identify/triad_fit.h"
#include "imu_lab/identify/units.h"

namespace imu_lab {
namespace pipeline {

// The unit a term's amplitude is shown in: the first field unit after the SI one (SI if none).
identify::UnitScale display_unit(identify::SensorKind sensor, identify::TermKind kind);

std::string format_noise_table(const std::vector<identify::TriadFit>& triads);

// "  gyroscope_noise_density      4.413e-04 rad/s/sqrt(Hz)" for each of the four keys of
// kalibr_imu.yaml, SI as written there, and which are upper bounds (and on which axis).
std::string format_kalibr_lines(const identify::KalibrImuNoise& noise);

// One axis of the IEEE table: its cells (N, B, K, Q, R) and the lines printed under its row.
struct AxisSummary {
  std::string axis;                      // "gyro_x"
  std::vector<std::string> cells;        // "2.492 ± 0.0064", "< 241.1", "-" (not a candidate)
  std::vector<std::string> lines_below;  // the other terms in the model; further advice per axis
};
AxisSummary axis_summary(const identify::TriadFit& triad, int axis);

// Per triad a header naming each column's term and unit, then each axis's row and lines.
std::string format_ieee_table(const std::vector<identify::TriadFit>& triads);

// One line per kind of warning found on any axis (in the order of identify::FindingKind): what
// it means in plain words, then the axes with their terms or values. Empty when there is none.
std::string format_grouped_findings(const std::vector<identify::TriadFit>& triads);

// How many warnings the fits gave, over all axes.
std::size_t warning_count(const std::vector<identify::TriadFit>& triads);

}  // namespace pipeline
}  // namespace imu_lab
