// The AVAR test has power: the same statistic REJECTS a generator broken on purpose (point
// samples of a Markov process with T_c = 2 tau0 instead of interval averages, doc/models.md),
// with the same seed, sample count and taus that accept the exact generator.
#include <gtest/gtest.h>

#include <cmath>

#include "imu_lab/noise/analytic_avar.h"
#include "imu_lab/noise/make_noise_process.h"
#include "imu_lab/noise/normal_stream.h"
#include "test_noise_avar_check.h"

namespace imu_lab {
namespace noise {
namespace {

constexpr double kTau0 = 0.01;
constexpr double kCorrelationTime = 2.0 * kTau0;
constexpr double kQc = 1e-2;
constexpr std::size_t kSamples = std::size_t(1) << 20;
constexpr int kMaxFactor = 1 << 14;
constexpr std::uint64_t kSeed = 41;

double expected(double tau) { return markov_avar(kQc, kCorrelationTime, tau); }

TEST(NoiseAvarPower, ExactIntervalAveragesAccepted) {
  auto process = make_noise_process(MarkovParameters{kQc, kCorrelationTime}, kSeed);
  std::size_t k = 0;
  const auto rates = test::collect(kSamples, [&]() { return process->next_interval_average(kTau0 * k++, kTau0); });
  const auto check = test::check_avar(rates, kTau0, expected, 1, kMaxFactor);
  EXPECT_TRUE(check.passed()) << check.table;
}

TEST(NoiseAvarPower, PointSamplesOfTheSameMarkovProcessRejected) {
  // Exact point samples b(t_k) of the same Ornstein-Uhlenbeck process, used as if they were
  // the interval averages.
  NormalStream normals(kSeed);
  const double decay = std::exp(-kTau0 / kCorrelationTime);
  const double sigma = kQc * std::sqrt(kCorrelationTime / 2.0);
  double state = sigma * normals.next();
  const auto rates = test::collect(kSamples, [&]() {
    state = decay * state + sigma * std::sqrt(1.0 - decay * decay) * normals.next();
    return state;
  });
  const auto check = test::check_avar(rates, kTau0, expected, 1, kMaxFactor);
  EXPECT_FALSE(check.passed()) << check.table;
  EXPECT_GE(check.rejected_points, 3) << check.table;
  std::printf("[power] point samples: %d of %d taus rejected, worst normalised deviation %.1f (ratio %.3f)\n",
              check.rejected_points, check.point_count, check.worst_normalised_deviation, check.worst_ratio);
}

}  // namespace
}  // namespace noise
}  // namespace imu_lab
