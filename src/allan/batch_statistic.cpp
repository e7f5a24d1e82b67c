// Names and term counts of the batch statistics (Stable32's '#' column).
#include <stdexcept>
#include <string>

#include "imu_lab/allan/batch.h"

namespace imu_lab {
namespace allan {

std::string statistic_name(Statistic statistic) {
  switch (statistic) {
    case Statistic::kAllan: return "adev";
    case Statistic::kOverlappingAllan: return "oadev";
    case Statistic::kModifiedAllan: return "mdev";
    case Statistic::kHadamard: return "hdev";
    case Statistic::kOverlappingHadamard: return "ohdev";
    case Statistic::kTime: return "tdev";
    case Statistic::kTotal: return "totdev";
    case Statistic::kAllanKrobka: return "akdev";
    case Statistic::kHadamardKrobka: return "hkdev";
  }
  throw std::invalid_argument("statistic_name: unknown Statistic value " + std::to_string(static_cast<int>(statistic)));
}

int difference_order(Statistic statistic) {
  const bool hadamard = statistic == Statistic::kHadamard || statistic == Statistic::kOverlappingHadamard ||
                        statistic == Statistic::kHadamardKrobka;
  return hadamard ? 3 : 2;
}

long long term_count(Statistic statistic, std::size_t phase_count, int m) {
  if (m < 1) {
    throw std::invalid_argument("term_count: averaging factor m = " + std::to_string(m) + " must be at least 1");
  }
  const long long n = static_cast<long long>(phase_count);
  const long long lag = m;
  if (n < 2) return 0;
  long long terms = 0;
  switch (statistic) {
    case Statistic::kAllan: terms = (n - 1) / lag - 1; break;
    case Statistic::kHadamard: terms = (n - 1) / lag - 2; break;
    case Statistic::kOverlappingAllan:
    case Statistic::kAllanKrobka: terms = n - 2 * lag; break;
    case Statistic::kOverlappingHadamard:
    case Statistic::kHadamardKrobka: terms = n - 3 * lag; break;
    case Statistic::kModifiedAllan:
    case Statistic::kTime: terms = n - 3 * lag + 1; break;
    // The reflected extension supports tau up to half the record (NIST SP 1065, 5.2.11).
    case Statistic::kTotal: terms = (2 * lag <= n - 1 && n >= 3) ? n - 2 : 0; break;
  }
  return terms > 0 ? terms : 0;
}

}  // namespace allan
}  // namespace imu_lab
