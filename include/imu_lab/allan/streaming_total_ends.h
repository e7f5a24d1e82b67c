// Total deviation (NIST SP 1065 eq. 25) reflects the phase about both end points: the terms whose
// reach crosses an end use x*[-j] = 2 x[0] - x[j] and x*[N-1+j] = 2 x[N-1] - x[N-1-j]. For N >= 2m+1
// the N-2 terms are the N-2m overlapping Allan terms plus m-1 terms at each end; those end terms
// need only the first 2m and the last 2m phase points, so a head buffer and the phase ring make
// TOTDEV exact for every m the ring covers.
#pragma once

#include <cstdint>
#include <vector>

#include "imu_lab/allan/streaming_phase_ring.h"

namespace imu_lab {
namespace allan {

// Sum of the squared second differences of the 2(m-1) reflected terms of a segment whose
// first points are `head` (at least 2m of them) and whose last points are in `ring`.
// Requires ring.count() >= 2m + 1.
double total_end_terms(const std::vector<double>& head, const PhaseRing& ring, int m);

}  // namespace allan
}  // namespace imu_lab
