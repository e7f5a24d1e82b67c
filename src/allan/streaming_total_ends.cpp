#include "imu_lab/allan/streaming_total_ends.h"

namespace imu_lab {
namespace allan {

double total_end_terms(const std::vector<double>& head, const PhaseRing& ring, int m) {
  const std::int64_t last = ring.newest();  // N - 1
  double sum = 0.0;
  for (int i = 1; i < m; ++i) {
    const double reflected_before = 2.0 * head[0] - head[m - i];
    const double d = reflected_before - 2.0 * head[i] + head[i + m];
    sum += d * d;
  }
  for (std::int64_t i = last - m + 1; i <= last - 1; ++i) {
    const double reflected_after = 2.0 * ring.at(last) - ring.at(2 * last - (i + m));
    const double d = ring.at(i - m) - 2.0 * ring.at(i) + reflected_after;
    sum += d * d;
  }
  return sum;
}

}  // namespace allan
}  // namespace imu_lab
