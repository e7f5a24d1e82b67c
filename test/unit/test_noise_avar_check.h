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

// rates: interval averages every tau0_s. Averaging factors 1, 2, 4, ... from m_min to m_max.
AvarCheck check_avar(const std::vector<double>& rates, double tau0_s,
                     const std::function<double(double tau_s)>& expected_avar, int m_min,
                     int m_max, double family_confidence = 0.997);

// Runs `sample` n times and collects the values.
std::vector<double> collect(std::size_t count, const std::function<double()>& sample);

}  // namespace test
}  // namespace imu_lab
