// Argument checks shared by the batch statistics: each names the input, what is wrong and
// what to do, and throws std::invalid_argument.
#pragma once

#include <string>
#include <vector>

#include "imu_lab/allan/batch.h"

namespace imu_lab {
namespace allan {
namespace detail {

void require_positive_tau0(double tau0_s, const std::string& caller);
void require_positive_averaging_factor(int m, const std::string& caller);
void require_finite_samples(const std::vector<double>& samples, const std::string& caller);

// All of the above plus enough samples for `statistic` at m; returns the term count.
long long require_computable(Statistic statistic, const std::vector<double>& phase, double tau0_s, int m);

}  // namespace detail
}  // namespace allan
}  // namespace imu_lab
