// Batch stability reference: plain, obviously-correct implementations over a whole series.
// The oracle for the emulator's tests and for the streaming engine.
#pragma once

#include <string>
#include <vector>

namespace imu_lab {
namespace allan {

// Stable32's family of statistics. Phase-type input x[k] (integrated rate) sampled every tau0.
enum class Statistic {
  kAllan,                // non-overlapping Allan (ADEV)
  kOverlappingAllan,     // OADEV
  kModifiedAllan,        // MDEV
  kHadamard,             // non-overlapping Hadamard (HDEV)
  kOverlappingHadamard,  // OHDEV
  kTime,                 // TDEV
  kTotal,                // TOTDEV
};

// Short lowercase name used in file names and reports: "adev", "oadev", ...
std::string statistic_name(Statistic statistic);

struct StabilityPoint {
  int averaging_factor = 0;   // m = tau / tau0
  double tau_s = 0.0;
  long long term_count = 0;   // number of terms in the average (Stable32's '#')
  int alpha = 0;              // power-law noise estimate: frequency PSD ~ f^alpha (2 WPM ... -2 RWFM)
  double edf = 0.0;           // equivalent degrees of freedom
  double deviation = 0.0;     // sigma(tau)
  double deviation_lower = 0.0;  // chi-squared bound at the requested confidence
  double deviation_upper = 0.0;
};

// x[k+1] = x[k] + y[k] * tau0; x[0] = 0. Output has size y.size() + 1.
std::vector<double> phase_from_frequency(const std::vector<double>& frequency, double tau0_s);

// Variances (sigma^2) of one statistic at one averaging factor, from phase data.
double overlapping_allan_variance(const std::vector<double>& phase, double tau0_s, int m);
// ... the other statistics have the same shape (see batch.cpp).

// Full Stable32-style evaluation: deviation, term count, noise-type estimate, EDF and
// chi-squared bounds (two-sided, `confidence` total, 0.683 by default) at each m.
std::vector<StabilityPoint> evaluate(Statistic statistic, const std::vector<double>& phase,
                                     double tau0_s, const std::vector<int>& averaging_factors,
                                     double confidence = 0.683);

}  // namespace allan
}  // namespace imu_lab
