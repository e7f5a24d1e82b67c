// Stable32's per-point estimate of the dominant power-law noise type alpha (frequency PSD
// ~ f^alpha: 2 WPM, 1 FPM, 0 WFM, -1 FFM, -2 RWFM, -3 FWFM, -4 RRFM).
#pragma once

#include <vector>

#include "imu_lab/allan/batch.h"

namespace imu_lab {
namespace allan {

// What the instrument delivered: Stable32 decimates phase data but averages frequency data
// before its lag-1 autocorrelation test, and the two differ in the first differencing step.
enum class SampleKind { kPhase, kFrequency };

// The lag-1 autocorrelation test needs this many decimated/averaged points (NIST SP 1065, 5.6).
constexpr long long kMinimumLag1Points = 30;
// Below this many averages (or estimator terms) the B1 test moves to a shorter tau.
constexpr long long kMinimumB1Points = 8;

// Riley & Greenhall, "Power law noise identification using the lag 1 autocorrelation"
// (EFTF 2004): difference the series until delta = r1 / (1 + r1) < 0.25 or d reaches
// max_differences, then alpha = -round(2 delta) - 2d (+2 for phase data).
int lag1_autocorrelation_alpha(std::vector<double> series, int max_differences, SampleKind kind);

// B1 = (sample variance of n averaged frequencies) / (their two-sample variance), expected
// for phase-PSD exponent mu = -alpha - 1 (Howe, Beard, Greenhall & Riley, PTTI 2000, table 3):
// B1(n, mu) = n (1 - n^mu) / (2 (n - 1) (1 - 2^mu)), with its limit at mu = 0.
double expected_b1_ratio(long long frequency_count, int mu);

// R(n) = MVAR / AVAR expected for WPM (1/m) and FPM (3.37 / (1.04 + 3 ln(pi m)), bandwidth
// 1/(2 tau0)); NIST SP 1065, 5.6.
double expected_modified_ratio(int alpha, int m);

// Stable32's rule: the lag-1 method where the decimated (phase) or averaged (frequency)
// series has at least kMinimumLag1Points points, else the B1 ratio (expected value at the
// statistic's term count; evaluated at the largest m' <= m leaving kMinimumB1Points averages
// and terms), refined by R(n) = MVAR/AVAR where B1 cannot tell WPM, FPM and WFM apart.
// max differences: 2 for the Allan family and TOTDEV, 3 for the Hadamard family.
int estimate_noise_alpha(Statistic statistic, const std::vector<double>& phase, double tau0_s, int m, SampleKind kind);

}  // namespace allan
}  // namespace imu_lab
