#include "imu_lab/identify/partial_curves.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "imu_lab/common/atomic_file.h"

namespace imu_lab {
namespace identify {

PartialCurves partial_curves(const FitResult& fit, const std::vector<allan::StabilityPoint>& measured) {
  PartialCurves curves;
  curves.term_names = term_names(fit.model);
  // Rounding is white noise behind the front end: a white rate term of its density.
  std::vector<Term> terms = fit.model.terms;
  if (fit.model.output_quantization_density > 0.0) {
    curves.term_names.push_back("output_quantization");
    terms.push_back({TermKind::kWhiteRate, fit.model.output_quantization_density, 0.0});
  }
  curves.term_deviations.assign(terms.size(), {});
  for (const auto& point : measured) {
    curves.tau_s.push_back(point.tau_s);
    curves.measured_deviation.push_back(point.deviation);
    curves.total_deviation.push_back(std::sqrt(model_avar(fit.model, point.tau_s)));
    for (size_t i = 0; i < terms.size(); ++i) {
      curves.term_deviations[i].push_back(std::sqrt(term_avar(terms[i], point.tau_s)));
    }
    const auto checked = std::find_if(fit.band.begin(), fit.band.end(),
                                      [&point](const BandPoint& band) { return band.tau_s == point.tau_s; });
    const bool found = checked != fit.band.end();
    curves.band_lower_deviation.push_back(found ? checked->lower : std::nan(""));
    curves.band_upper_deviation.push_back(found ? checked->upper : std::nan(""));
  }
  return curves;
}

std::string format_partial_curves_csv(const PartialCurves& curves, const std::string& rate_unit_key) {
  std::ostringstream out;
  out.precision(10);
  out << "tau_s,measured_dev_" << rate_unit_key << ",fit_total_dev_" << rate_unit_key;
  for (const std::string& name : curves.term_names) out << "," << name << "_dev_" << rate_unit_key;
  out << ",band95_low_" << rate_unit_key << ",band95_high_" << rate_unit_key << "\n";
  for (size_t k = 0; k < curves.tau_s.size(); ++k) {
    out << curves.tau_s[k] << "," << curves.measured_deviation[k] << "," << curves.total_deviation[k];
    for (const auto& term : curves.term_deviations) out << "," << term[k];
    out << "," << curves.band_lower_deviation[k] << "," << curves.band_upper_deviation[k] << "\n";
  }
  return out.str();
}

void write_partial_curves_csv(const std::string& path, const PartialCurves& curves, const std::string& rate_unit_key) {
  write_file_atomically(path, format_partial_curves_csv(curves, rate_unit_key));
}

}  // namespace identify
}  // namespace imu_lab
