// The spread the fit adds to every point (FitQuality::discrepancy) when its model does not
// describe the curve to the precision of the estimates. A right model must not get one: the
// distance that decides it is measured at a fit under the weights it tests (doc/identification.md,
// "The discrepancy"), not at the selection's first fit under a 1 % spread, which sits many sigma
// off at the shortest taus (EDF ~1e5).
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "identify_test_records.h"
#include "imu_lab/identify/fit.h"
#include "imu_lab/identify/model_selection.h"
#include "imu_lab/identify/record_simulation.h"

namespace imu_lab {
namespace identify {
namespace {

// The coverage bench's case 6 accelerometer, axis x: an 80 Hz front end at 200 Hz, a Markov hump
// (T_c 5 s), a 1.7 Hz line, a 30 Hz mode 8 Hz wide and a rate ramp, one hour.
TEST(IdentifyDiscrepancy, ARightModelOfANoisyRecordGetsNoSpread) {
  NoiseModel truth;
  truth.terms = {{TermKind::kWhiteRate, 1e-3},
                 {TermKind::kRateRamp, 5e-7},
                 {TermKind::kMarkov, 4e-3, 5.0},
                 {TermKind::kSinusoid, 2e-3, 1.7},
                 {TermKind::kResonance, 8e-3, 30.0, 8.0}};
  constexpr double kRateHz = 200.0, kLengthS = 3600.0, kFrontEndHz = 80.0;
  const auto processes = emulator_processes(truth, 1.0 / kRateHz, kLengthS);
  // A model that describes the curve leaves J ~ chi2(dof), dof 8-9 here, and gets a spread only
  // when J exceeds dof + 2 sqrt(2 dof): about 4 % of records. Over six records, two or more
  // spreads has a chance of 2 %; the first fit's distance gave a spread on seeds 3 and 6.
  constexpr int kRecords = 6, kMostSpreads = 1;
  int spreads = 0;
  std::string where;
  for (int seed = 1; seed <= kRecords; ++seed) {
    const auto rates = identify_test::emulate_axis_rates(processes, kRateHz, kLengthS, seed, kFrontEndHz);
    const FitResult fit = fit_noise_model(identify_test::octave_oadev(rates, kRateHz), 1.0 / kRateHz, kLengthS);
    if (fit.quality.discrepancy > 0.0) {
      ++spreads;
      where += " seed " + std::to_string(seed) + ": spread " + std::to_string(fit.quality.discrepancy) + " at J " +
               std::to_string(fit.quality.distance) + " on " + std::to_string(fit.quality.degrees_of_freedom) +
               " dof;";
    }
  }
  EXPECT_LE(spreads, kMostSpreads) << where;
}

// The coverage bench's case 5 accelerometer, axis x: a 20 Hz mode 6 Hz wide beside a 40 Hz front
// end at 100 Hz, B, K, a 0.55 Hz line, two hours. Under the first 1 % spread the selection takes
// the mode for a line, and that structure refitted without spread leaves one of 1-8 %: the
// selection must then look again at the estimates' own precision, where the mode shows its width.
TEST(IdentifyDiscrepancy, AModeTakenForALineUnderTheSpreadIsFoundAtThePrecisionOfTheEstimates) {
  NoiseModel truth;
  truth.terms = {{TermKind::kWhiteRate, 4e-3},
                 {TermKind::kBiasInstability, 3e-3, 50.0},
                 {TermKind::kRandomWalk, 1e-4},
                 {TermKind::kSinusoid, 6e-3, 0.55},
                 {TermKind::kResonance, 1e-2, 20.0, 6.0}};
  constexpr double kRateHz = 100.0, kLengthS = 7200.0, kFrontEndHz = 40.0;
  const auto processes = emulator_processes(truth, 1.0 / kRateHz, kLengthS);
  // Seeds 2-4: each took the line with a spread of 1.1-7.9 % before the second look.
  for (int seed = 2; seed <= 4; ++seed) {
    const auto rates = identify_test::emulate_axis_rates(processes, kRateHz, kLengthS, seed, kFrontEndHz);
    const FitResult fit = fit_noise_model(identify_test::octave_oadev(rates, kRateHz), 1.0 / kRateHz, kLengthS);
    EXPECT_EQ(fit.quality.discrepancy, 0.0) << "seed " << seed;
    const TermEstimate* mode = fit.find("resonance_1");
    ASSERT_NE(mode, nullptr) << "seed " << seed << ": the mode was not found as a resonance";
    // In the model; its widened sigmas may leave it unconstrained (seed 2: f_n 25 Hz, 18 Hz wide).
    ASSERT_NE(mode->status, TermStatus::kAbsent) << "seed " << seed;
    if (mode->status != TermStatus::kPresent) continue;
    // Inside its 95 % interval (each record misses with a chance of 5 %).
    EXPECT_LT(std::abs(std::log(mode->shape.value / 20.0)), 1.96 * mode->shape.log_sigma)
        << "seed " << seed << ": f_n " << mode->shape.value << " Hz";
  }
}

// Where the model leaves a spread the terms stay as selected under a smaller one, and a term's
// statistic reported under the spread may lie on the other side of its threshold (unit 4's accel
// y: a 0.0019 Hz line in the model at 2.78 against 15.8, a line its periodogram does not show).
// Such a decision is borderline however far the statistic lies from the threshold.
TEST(IdentifyDiscrepancy, ADecisionTheReportedStatisticContradictsIsBorderline) {
  constexpr double kThreshold = 15.8;
  EXPECT_TRUE(is_borderline(2.78, kThreshold, true));
  EXPECT_TRUE(is_borderline(20.0, kThreshold, true));
  EXPECT_FALSE(is_borderline(40.0, kThreshold, true));
  EXPECT_FALSE(is_borderline(INFINITY, kThreshold, true));  // the model's only term
  EXPECT_FALSE(is_borderline(2.0, kThreshold, false));
  EXPECT_TRUE(is_borderline(10.0, kThreshold, false));
  EXPECT_TRUE(is_borderline(40.0, kThreshold, false));
}

}  // namespace
}  // namespace identify
}  // namespace imu_lab
