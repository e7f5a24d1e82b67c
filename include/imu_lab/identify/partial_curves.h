// The fitted total and each term's partial curve at the measured taus (Krobka 2015 Fig. 5.1), for
// the plotting script: deviations, so they draw on the same axes as the measured curve.
#pragma once

#include <string>
#include <vector>

#include "imu_lab/allan/batch.h"
#include "imu_lab/identify/fit_result.h"

namespace imu_lab {
namespace identify {

struct PartialCurves {
  std::vector<double> tau_s;
  std::vector<double> measured_deviation;
  std::vector<double> total_deviation;
  std::vector<std::string> term_names;               // FitResult::model order
  std::vector<std::vector<double>> term_deviations;  // [term][tau]
  // The 95 % band the fit was checked against (fit_result.h BandPoint), NaN where not checked.
  std::vector<double> band_lower_deviation;
  std::vector<double> band_upper_deviation;
};

PartialCurves partial_curves(const FitResult& fit, const std::vector<allan::StabilityPoint>& measured);

// CSV, unit in every column name (rate_unit_key: "rad_s" or "m_s2"):
//   tau_s,measured_dev_<unit>,fit_total_dev_<unit>,<term>_dev_<unit>,...,band95_low_<unit>,band95_high_<unit>
// with the output's quantization as a term ("output_quantization") when the fit had an LSB.
std::string format_partial_curves_csv(const PartialCurves& curves, const std::string& rate_unit_key);
// Written atomically (common/atomic_file.h).
void write_partial_curves_csv(const std::string& path, const PartialCurves& curves, const std::string& rate_unit_key);

}  // namespace identify
}  // namespace imu_lab
