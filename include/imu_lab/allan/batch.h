// Batch stability reference: plain, obviously-correct implementations over a whole series.
// The oracle for the emulator's tests and for the streaming engine.
//
// Input is phase-type data x[k] (for an IMU: the integrated rate, i.e. the angle, or the
// integrated specific force), sampled every tau0_s; frequency-type data y[k] (the rate) is
// turned into phase by phase_from_frequency(). m is the averaging factor, tau_s = m * tau0_s.
// Definitions follow NIST SP 1065 (Riley, "Handbook of Frequency Stability Analysis", 2008);
// term counts, EDF, confidence bounds and noise-type estimates reproduce Stable32 1.60.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace imu_lab {
namespace allan {

// Stable32's family of statistics, plus Krobka's dispersions (Krobka 2015, eq. 5.10).
// Phase-type input x[k] (integrated rate) sampled every tau0.
enum class Statistic {
  kAllan,                // non-overlapping Allan (ADEV)
  kOverlappingAllan,     // OADEV
  kModifiedAllan,        // MDEV
  kHadamard,             // non-overlapping Hadamard (HDEV)
  kOverlappingHadamard,  // OHDEV
  kTime,                 // TDEV
  kTotal,                // TOTDEV
  kAllanKrobka,          // AKDEV: overlapping Allan with the squared mean difference removed
  kHadamardKrobka,       // HKDEV: the same for the overlapping Hadamard variance
};

// Short lowercase name used in file names and reports: "adev", "oadev", ..., "akdev", "hkdev".
std::string statistic_name(Statistic statistic);

// Order d of the phase differences the statistic is built on: 3 for the Hadamard family (hdev,
// ohdev, hkdev: blind to a linear frequency drift, resolving noise down to alpha = -4), 2 for
// the others (resolving down to alpha = -2). It is also the lag-1 test's maximum differencing.
int difference_order(Statistic statistic);

struct StabilityPoint {
  int averaging_factor = 0;  // m = tau / tau0
  double tau_s = 0.0;
  long long term_count = 0;  // number of terms in the average (Stable32's '#')
  // term_count over the terms one contiguous record of all the segments' samples would give:
  // below 1 when the run was split (gaps, knocks) and the segments pooled; 1 for one segment.
  double pooled_term_fraction = 1.0;
  int alpha = 0;                 // power-law noise estimate: frequency PSD ~ f^alpha (2 WPM ... -2 RWFM)
  double edf = 0.0;              // equivalent degrees of freedom
  double deviation = 0.0;        // sigma(tau)
  double deviation_lower = 0.0;  // chi-squared bound at the requested confidence
  double deviation_upper = 0.0;
};

// x[k+1] = x[k] + y[k] * tau0; x[0] = 0. Output has size y.size() + 1.
// Throws std::invalid_argument for tau0_s <= 0 or a non-finite sample.
std::vector<double> phase_from_frequency(const std::vector<double>& frequency, double tau0_s);

// Number of terms the statistic averages at averaging factor m over phase_count phase samples
// (Stable32's '#' column); 0 when the series is too short for that m. Throws for m < 1.
//   adev  floor((N-1)/m) - 1      oadev, akdev  N - 2m      mdev, tdev  N - 3m + 1
//   hdev  floor((N-1)/m) - 2      ohdev, hkdev  N - 3m      totdev      N - 2 (needs 2m <= N-1)
long long term_count(Statistic statistic, std::size_t phase_count, int m);

// Variances (sigma^2) of one statistic at one averaging factor, from phase data.
// Each throws std::invalid_argument when tau0_s <= 0, m < 1, the phase holds a non-finite
// sample, or the series is too short for m (term_count() == 0).
double allan_variance(const std::vector<double>& phase, double tau0_s, int m);
double overlapping_allan_variance(const std::vector<double>& phase, double tau0_s, int m);
double modified_allan_variance(const std::vector<double>& phase, double tau0_s, int m);
double hadamard_variance(const std::vector<double>& phase, double tau0_s, int m);
double overlapping_hadamard_variance(const std::vector<double>& phase, double tau0_s, int m);
// TVAR = tau^2 / 3 * MVAR, in units of phase squared.
double time_variance(const std::vector<double>& phase, double tau0_s, int m);
// Howe's total variance: second differences over the series extended by reflection at both ends.
double total_variance(const std::vector<double>& phase, double tau0_s, int m);
// Krobka dispersions (Krobka 2015, eq. 5.10): with the overlapping differences
// D_k = ybar_{k+m} - ybar_k (Allan) or the analogous second difference of averages (Hadamard),
//   AKVAR = (<D^2> - <D>^2) / 2,  HKVAR = (<D^2> - <D>^2) / 6,
// averages over all k with 1/count. A deterministic rate ramp gives a constant D, which
// AVAR keeps (R^2 tau^2 / 2) and AKVAR removes entirely.
double allan_krobka_variance(const std::vector<double>& phase, double tau0_s, int m);
double hadamard_krobka_variance(const std::vector<double>& phase, double tau0_s, int m);

// Dispatches to the variance of `statistic` above.
double variance(Statistic statistic, const std::vector<double>& phase, double tau0_s, int m);

// Full Stable32-style evaluation: deviation, term count, noise-type estimate, EDF and
// chi-squared bounds (two-sided, `confidence` total, 0.683 by default) at each m.
// An m for which the series is too short is skipped (no point in the output). Throws
// std::invalid_argument for tau0_s <= 0, m < 1, confidence outside (0, 1) or a non-finite sample.
// The noise type is identified from the decimated phase, as Stable32 does for phase data.
std::vector<StabilityPoint> evaluate(Statistic statistic, const std::vector<double>& phase, double tau0_s,
                                     const std::vector<int>& averaging_factors, double confidence = 0.683);

// The same for frequency-type input (rates): integrates it with phase_from_frequency() and
// identifies the noise type from the averaged frequency, as Stable32 does for frequency data.
std::vector<StabilityPoint> evaluate_frequency(Statistic statistic, const std::vector<double>& frequency, double tau0_s,
                                               const std::vector<int>& averaging_factors, double confidence = 0.683);

}  // namespace allan
}  // namespace imu_lab
