// Simultaneous test of an emulated Allan-variance curve against an expected one: octave-spaced
// taus, each point's overlapping AVAR scaled by its EDF is chi-squared; all points must lie in
// their Bonferroni-corrected two-sided bounds (99.7 % family-wise).
#pragma once

#include <functional>
#include <string>
#include <vector>

namespace imu_lab {
namespace test {

struct AvarCheck {
  int point_count = 0;
  int rejected_points = 0;
  double worst_normalised_deviation = 0.0;  // max |ratio - 1| / sqrt(2 / edf)
  double worst_ratio = 1.0;                 // measured / expected at that point
  double per_point_level = 0.0;             // two-sided tail probability allowed per point
  std::string table;                        // one line per tau, for failure messages
  bool passed() const { return rejected_points == 0; }
};

// EDF of each point: by default from the local power-law slope of the expected curve
// (allan::equivalent_degrees_of_freedom); a non-power-law process passes its exact EDF.
using EdfOfFactor = std::function<double(int m, std::size_t rate_count)>;

// rates: interval averages every tau0_s. Averaging factors 1, 2, 4, ... from m_min to m_max.
AvarCheck check_avar(const std::vector<double>& rates, double tau0_s,
                     const std::function<double(double tau_s)>& expected_avar, int m_min, int m_max,
                     double family_confidence = 0.997, const EdfOfFactor& edf = {});

// Exact EDF of the overlapping AVAR at factor m from rate_count samples of a Gaussian process
// whose phase x (integrated rate) has the structure function V(j) = E[(x_{k+j} - x_k)^2] at lags
// of j samples. The estimator sums d_k^2, d_k = x_{k+2m} - 2 x_{k+m} + x_k, a quadratic form:
// Var = 2 sum_{|j|<M} (M - |j|) gamma(j)^2, gamma(j) = Cov(d_k, d_{k+j}) =
// -1/2 sum_{p,q} w_p w_q V(|j + (p - q) m|), w = (1, -2, 1); EDF = 2 mean^2 / Var. gamma(j) is
// taken as zero beyond |j| = 2m + correlation_samples.
double exact_overlapping_edf(const std::function<double(long lag)>& structure, int m, std::size_t rate_count,
                             long correlation_samples);

// AVAR = 4 int_0^f_max S(f) sin^4(pi f tau) / (pi f tau)^2 df (eq. 5.1, S two-sided) by
// Gauss-Kronrod over each period 1 / tau of the kernel (relative tolerance 1e-12 per piece).
double numerical_avar(const std::function<double(double f_hz)>& psd, double tau_s, double f_max_hz);

// The power-law EDF of each point taken from another curve's local slope: for a mixture with
// deterministic terms (a sinusoid), pass its stochastic part. Judging the whole measured AVAR
// at that EDF is conservative: the deterministic part adds a cross term of variance
// 4 D S / edf at most, and 2 S (S + 2 D) <= 2 (S + D)^2.
EdfOfFactor power_law_edf(const std::function<double(double tau_s)>& stochastic_avar, double tau0_s);

// exact_overlapping_edf for a rate that is the derivative of a stationary angle with covariance
// C (V(j) = 2 (C(0) - C(j tau0)), tabulated once up to the lags factors <= max_factor need).
EdfOfFactor stationary_angle_edf(const std::function<double(double lag_s)>& angle_covariance, double tau0_s,
                                 long correlation_samples, int max_factor);

// Runs `sample` n times and collects the values.
std::vector<double> collect(std::size_t count, const std::function<double()>& sample);

}  // namespace test
}  // namespace imu_lab
