// Equivalent degrees of freedom (EDF) of the batch stability estimators, as Stable32 computes
// them: Greenhall's generalised algorithm for the difference variances and Howe's b*N/m - c
// for the total variance.
#pragma once

#include "imu_lab/allan/batch.h"

namespace imu_lab {
namespace allan {

// Greenhall & Riley, "Uncertainty of stability variances based on finite differences"
// (35th PTTI, 2003), combined algorithm with J_max = 100:
//   alpha             frequency power-law exponent (2 WPM ... -4 RRFM); needs alpha + 2d > 1
//   difference_order  d: 2 for the Allan variances, 3 for the Hadamard variances
//   m                 averaging factor; phase_count N is the number of phase samples
//   overlapping       stride tau0 (true) or tau (false)
//   modified          averaged-phase (MVAR/TVAR) estimator
// Throws std::invalid_argument for an unsupported (alpha, d) pair or too few samples.
double greenhall_edf(int alpha, int difference_order, int m, long long phase_count, bool overlapping, bool modified);

// NIST SP 1065 (section 5.2.11): TOTVAR EDF = b * N / m - c for N phase samples, with
// (b, c) = (1.50, 0) WFM, (1.17, 0.22) FFM, (0.93, 0.36) RWFM. Total variance is an FM-noise
// estimator; for PM noise (alpha > 0) we use the OADEV EDF, which it never falls below.
double total_variance_edf(int alpha, int m, long long phase_count);

// The EDF of `statistic` at (alpha, m, N). Krobka dispersions: the EDF of their parent
// (OADEV, OHDEV) minus one, since subtracting the sample mean of the differences spends one
// degree of freedom, exactly as the sample variance of n independent terms has n - 1.
// alpha is clamped into the range the statistic can resolve (>= -2 Allan, >= -4 Hadamard).
double equivalent_degrees_of_freedom(Statistic statistic, int alpha, int m, long long phase_count);

}  // namespace allan
}  // namespace imu_lab
