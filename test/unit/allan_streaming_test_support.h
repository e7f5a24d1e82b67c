// Shared by the test_allan_streaming_*.cpp files: synthetic IMU-like rates, feeding an engine,
// and comparing point lists.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "imu_lab/allan/batch.h"
#include "imu_lab/allan/streaming_allan.h"

namespace imu_lab {
namespace allan {
namespace testing_support {

constexpr std::int64_t kMillisecondNs = 1000000;

// White rate noise + rate random walk + a flicker-like sum of first-order Markov processes with
// log-spaced correlation times, + an offset (gravity-like) that the engine must remove.
inline std::vector<double> synthetic_rate(std::size_t count, std::uint64_t seed, double offset = 0.0) {
  std::mt19937_64 generator(seed);
  std::normal_distribution<double> normal(0.0, 1.0);
  const double correlation_samples[] = {3.0, 30.0, 300.0, 3000.0};
  double markov[4] = {0.0, 0.0, 0.0, 0.0};
  double random_walk = 0.0;
  std::vector<double> rate(count);
  for (std::size_t k = 0; k < count; ++k) {
    random_walk += 2e-3 * normal(generator);
    double flicker = 0.0;
    for (int i = 0; i < 4; ++i) {
      const double decay = std::exp(-1.0 / correlation_samples[i]);
      markov[i] = decay * markov[i] + std::sqrt(1.0 - decay * decay) * 0.05 * normal(generator);
      flicker += markov[i];
    }
    rate[k] = offset + normal(generator) + random_walk + flicker;
  }
  return rate;
}

// rates[channel][sample]; stamps k * tau0_ns.
inline void feed(StreamingAllan& engine, const std::vector<std::vector<double>>& rates, std::size_t begin,
                 std::size_t end, std::int64_t tau0_ns = kMillisecondNs) {
  std::vector<double> sample(rates.size());
  for (std::size_t k = begin; k < end; ++k) {
    for (std::size_t c = 0; c < rates.size(); ++c) sample[c] = rates[c][k];
    engine.push(static_cast<std::int64_t>(k) * tau0_ns, sample);
  }
}

inline StreamingOptions test_options(std::size_t channels, int exact_limit, double points_per_decade,
                                     double max_tau_s) {
  StreamingOptions options;
  options.channel_count = channels;
  options.exact_max_averaging_factor = exact_limit;
  options.points_per_decade = points_per_decade;
  options.max_tau_s = max_tau_s;
  return options;
}

inline double relative_difference(double a, double b) {
  if (a == b) return 0.0;  // also equal infinities (bounds of a zero-spread dispersion)
  const double scale = std::max(std::abs(a), std::abs(b));
  return scale > 0.0 ? std::abs(a - b) / scale : 0.0;
}

// Largest relative difference over deviation, EDF and bounds; m, '#' and alpha must match exactly
// and both lists must hold the same points. Returns the largest difference seen.
inline double compare_points(const std::vector<StabilityPoint>& streamed, const std::vector<StabilityPoint>& reference,
                             const std::string& what) {
  EXPECT_EQ(streamed.size(), reference.size()) << what;
  double worst = 0.0;
  for (std::size_t i = 0; i < std::min(streamed.size(), reference.size()); ++i) {
    const StabilityPoint& s = streamed[i];
    const StabilityPoint& r = reference[i];
    const std::string where = what + " m=" + std::to_string(r.averaging_factor);
    EXPECT_EQ(s.averaging_factor, r.averaging_factor) << where;
    EXPECT_EQ(s.term_count, r.term_count) << where;
    EXPECT_EQ(s.alpha, r.alpha) << where;
    EXPECT_NEAR(s.tau_s, r.tau_s, 1e-12 * r.tau_s) << where;
    for (const auto& pair :
         {std::make_pair(s.deviation, r.deviation), std::make_pair(s.edf, r.edf),
          std::make_pair(s.deviation_lower, r.deviation_lower), std::make_pair(s.deviation_upper, r.deviation_upper)}) {
      const double difference = relative_difference(pair.first, pair.second);
      EXPECT_LE(difference, 1e-9) << where << " streamed " << pair.first << " reference " << pair.second;
      worst = std::max(worst, difference);
    }
  }
  return worst;
}

inline std::vector<StabilityPoint> points_up_to(const std::vector<StabilityPoint>& points, int max_m) {
  std::vector<StabilityPoint> kept;
  for (const StabilityPoint& point : points) {
    if (point.averaging_factor <= max_m) kept.push_back(point);
  }
  return kept;
}

inline std::vector<int> factors_of(const std::vector<StabilityPoint>& points) {
  std::vector<int> factors;
  for (const StabilityPoint& point : points) factors.push_back(point.averaging_factor);
  return factors;
}

}  // namespace testing_support
}  // namespace allan
}  // namespace imu_lab
