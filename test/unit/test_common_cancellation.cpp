// Cooperative cancellation (common/cancellation.h): nothing happens outside a scope or before
// the flag is set; a set flag ends the noise identification with Cancelled, from the thread's
// scope only; scopes nest and restore the outer one.
#include "imu_lab/common/cancellation.h"

#include <gtest/gtest.h>

#include <atomic>
#include <thread>

#include "identify_test_records.h"
#include "imu_lab/identify/fit.h"

namespace imu_lab {
namespace {

constexpr double kTau0_s = 0.01;
constexpr double kLength_s = 3600.0;

std::vector<allan::StabilityPoint> white_and_random_walk_curve() {
  identify::NoiseModel truth;
  truth.terms = {{identify::TermKind::kWhiteRate, 1e-4, 0.0}, {identify::TermKind::kRandomWalk, 1e-6, 0.0}};
  return identify_test::exact_octave_curve(truth, kTau0_s, kLength_s);
}

TEST(Cancellation, OutsideAScopeOrWithTheFlagClearNothingIsThrown) {
  EXPECT_NO_THROW(throw_if_cancelled());
  EXPECT_FALSE(cancellation_requested());
  std::atomic<bool> requested{false};
  CancellationScope scope(requested);
  EXPECT_NO_THROW(throw_if_cancelled());
  const identify::FitResult fit = identify::fit_noise_model(white_and_random_walk_curve(), kTau0_s, kLength_s);
  EXPECT_EQ(fit.find("white_rate")->status, identify::TermStatus::kPresent);
}

TEST(Cancellation, ASetFlagEndsTheIdentification) {
  std::atomic<bool> requested{true};
  CancellationScope scope(requested);
  EXPECT_TRUE(cancellation_requested());
  EXPECT_THROW(identify::fit_noise_model(white_and_random_walk_curve(), kTau0_s, kLength_s), Cancelled);
}

TEST(Cancellation, AnotherThreadsScopeDoesNotReachThisOne) {
  std::atomic<bool> requested{true};
  CancellationScope scope(requested);
  bool other_thread_throws = true;
  std::thread other([&] {
    try {
      identify::fit_noise_model(white_and_random_walk_curve(), kTau0_s, kLength_s);
      other_thread_throws = false;
    } catch (const Cancelled&) {
    }
  });
  other.join();
  EXPECT_FALSE(other_thread_throws);
}

TEST(Cancellation, ScopesNestAndTheOuterOneComesBack) {
  std::atomic<bool> outer_flag{true};
  std::atomic<bool> inner_flag{false};
  CancellationScope outer(outer_flag);
  {
    CancellationScope inner(inner_flag);
    EXPECT_NO_THROW(throw_if_cancelled());
  }
  EXPECT_THROW(throw_if_cancelled(), Cancelled);
}

}  // namespace
}  // namespace imu_lab
