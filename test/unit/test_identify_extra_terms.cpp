// Terms beyond the IEEE five on exact (noise-free) curves: a sinusoid (eq. 5.8), a second Markov
// process and, when enabled, Krobka 2015's zero-at-DC terms (section 7). Each must be selected and
// recovered.
#include <gtest/gtest.h>

#include <cmath>

#include "identify_test_records.h"
#include "imu_lab/identify/fit.h"

namespace imu_lab {
namespace identify {
namespace {

constexpr double kTau0 = 0.01, kLength = 7200.0;

std::vector<allan::StabilityPoint> exact_curve(const NoiseModel& model) {
  return identify_test::exact_octave_curve(model, kTau0, kLength);
}

const TermEstimate& expect_present(const FitResult& fit, const std::string& name) {
  const TermEstimate* term = fit.find(name);
  EXPECT_NE(term, nullptr) << name;
  static const TermEstimate missing;
  if (term == nullptr) return missing;
  EXPECT_EQ(term->status, TermStatus::kPresent) << name;
  return *term;
}

TEST(IdentifyExtraTerms, SinusoidIsFoundWithItsFrequency) {
  NoiseModel truth;
  truth.terms = {{TermKind::kWhiteRate, 1e-4, 0.0}, {TermKind::kSinusoid, 2e-4, 0.05}};
  const FitResult fit = fit_noise_model(exact_curve(truth), kTau0, kLength);
  const TermEstimate& sinusoid = expect_present(fit, "sinusoid_1");
  EXPECT_NEAR(sinusoid.amplitude.value, 2e-4, 2e-6);
  EXPECT_NEAR(sinusoid.shape.value, 0.05, 5e-4);
  EXPECT_EQ(fit.model.terms.size(), 2u);
}

TEST(IdentifyExtraTerms, TwoMarkovProcessesAreSeparated) {
  NoiseModel truth;
  truth.terms = {{TermKind::kWhiteRate, 1e-5, 0.0}, {TermKind::kMarkov, 3e-4, 0.05}, {TermKind::kMarkov, 1e-3, 20.0}};
  const FitResult fit = fit_noise_model(exact_curve(truth), kTau0, kLength);
  EXPECT_NEAR(expect_present(fit, "markov_1").shape.value, 0.05, 0.005);
  EXPECT_NEAR(expect_present(fit, "markov_2").shape.value, 20.0, 2.0);
  EXPECT_NEAR(expect_present(fit, "white_rate").amplitude.value, 1e-5, 1e-6);
}

TEST(IdentifyExtraTerms, ZeroDcFamilyWhenEnabled) {
  NoiseModel truth;
  truth.terms = {{TermKind::kWhiteRate, 1e-4, 0.0}, {TermKind::kZeroDcFamily, 3e-4, 0.5}};
  FitOptions options;
  options.allow_zero_dc_family = true;
  const FitResult fit = fit_noise_model(exact_curve(truth), kTau0, kLength, options);
  const TermEstimate& zero_dc = expect_present(fit, "zero_dc_family");
  EXPECT_NEAR(zero_dc.amplitude.value, 3e-4, 3e-5);
  EXPECT_NEAR(zero_dc.shape.value, 0.5, 0.05);
}

// Each zero-at-DC kind enabled by its report name, as `allan --zero-dc-terms` does; the others
// stay out, and on a curve that has one of them the fit recovers its two parameters.
TEST(IdentifyExtraTerms, EachZeroDcKindIsSelectableByName) {
  struct Case {
    Term truth;
    const char* name;
  };
  const std::vector<Case> cases = {
      {{TermKind::kZeroDcGaussian, 3e-4, 0.04}, "zero_dc_gaussian"},  // PSD peak at 1 / sqrt(beta) = 5 Hz
      {{TermKind::kHighPassWhite, 3e-4, 0.2}, "high_pass_white"},     // white above 0.2 Hz, none below
  };
  for (const Case& c : cases) {
    NoiseModel truth;
    truth.terms = {{TermKind::kWhiteRate, 3e-5, 0.0}, {TermKind::kRandomWalk, 1e-6, 0.0}, c.truth};
    FitOptions options;
    allow_zero_dc_term(c.name, &options);
    const FitResult fit = fit_noise_model(exact_curve(truth), kTau0, kLength, options);
    const TermEstimate& zero_dc = expect_present(fit, c.name);
    EXPECT_NEAR(zero_dc.amplitude.value / c.truth.amplitude, 1.0, 0.05) << c.name;
    EXPECT_NEAR(zero_dc.shape.value / c.truth.shape, 1.0, 0.05) << c.name;
    for (const std::string& other : zero_dc_term_names()) {
      if (other != c.name) EXPECT_EQ(fit.find(other), nullptr) << other << " was not enabled";
    }
  }
}

TEST(IdentifyExtraTerms, UnknownZeroDcNameIsRefusedByName) {
  FitOptions options;
  try {
    allow_zero_dc_term("markov", &options);
    FAIL() << "markov accepted as a zero-at-DC term";
  } catch (const std::invalid_argument& error) {
    EXPECT_NE(std::string(error.what()).find("'markov'"), std::string::npos) << error.what();
    EXPECT_NE(std::string(error.what()).find("high_pass_white"), std::string::npos) << error.what();
  }
  EXPECT_FALSE(options.allow_zero_dc_family || options.allow_zero_dc_gaussian || options.allow_high_pass_white);
}

// A left-out Markov term, line or mode reports the fall of the distance its addition would bring,
// as a left-out K does, so that one the selection nearly took is marked borderline. A 0.5 Hz line
// on white noise and bias instability, its amplitude stepped across the decision: the statistic
// grows with it (about as its fourth power) and changes side with the decision; within a factor
// 2 of the threshold the term is borderline on either side.
TEST(IdentifyExtraTerms, ALeftOutLineCarriesItsStatisticAndIsBorderlineNearItsThreshold) {
  double previous_statistic = 0.0;
  int borderline_absent = 0, clear_absent = 0, clear_present = 0;
  for (double amplitude = 2.0e-4; amplitude < 6.0e-4; amplitude *= 1.1) {
    NoiseModel truth;
    truth.terms = {{TermKind::kWhiteRate, 1e-3, 0.0},
                   {TermKind::kBiasInstability, 2e-5, 50.0},
                   {TermKind::kSinusoid, amplitude, 0.5}};
    const FitResult fit = fit_noise_model(exact_curve(truth), kTau0, kLength);
    const TermEstimate* absent = fit.find("sinusoid");
    const TermEstimate* present = fit.find("sinusoid_1");
    ASSERT_TRUE((absent == nullptr) != (present == nullptr)) << "amplitude " << amplitude;
    const TermEstimate& line = absent != nullptr ? *absent : *present;
    ASSERT_TRUE(std::isfinite(line.selection_statistic)) << "amplitude " << amplitude;
    ASSERT_GT(line.selection_threshold, 0.0);
    EXPECT_EQ(absent != nullptr, line.selection_statistic < line.selection_threshold)
        << "amplitude " << amplitude << ": statistic " << line.selection_statistic << " against "
        << line.selection_threshold;
    EXPECT_EQ(line.borderline, line.selection_statistic > 0.5 * line.selection_threshold &&
                                   line.selection_statistic < 2.0 * line.selection_threshold)
        << "amplitude " << amplitude << ": statistic " << line.selection_statistic;
    EXPECT_GT(line.selection_statistic, previous_statistic) << "amplitude " << amplitude;
    previous_statistic = line.selection_statistic;
    if (absent != nullptr) (line.borderline ? borderline_absent : clear_absent) += 1;
    if (present != nullptr && !line.borderline) ++clear_present;
    // The other left-out shaped kinds carry theirs too.
    for (const char* name : {"markov", "resonance"}) {
      const TermEstimate* other = fit.find(name);
      ASSERT_NE(other, nullptr) << name;
      EXPECT_TRUE(std::isfinite(other->selection_statistic) && other->selection_threshold > 0.0) << name;
    }
  }
  // Statistics 1.3 to 11.8 left out (8.1 and 11.8 borderline), 16 to 170 in the model.
  EXPECT_GE(borderline_absent, 2);
  EXPECT_GE(clear_absent, 2);
  EXPECT_GE(clear_present, 2);
}

}  // namespace
}  // namespace identify
}  // namespace imu_lab
