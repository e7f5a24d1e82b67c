// The doubt between a line and a resonance for one peak reaches the sigmas of the terms beside it
// (structure_doubt.h). On the noise-free curve of a 20 Hz mode 6 Hz wide beside a 40 Hz front end
// at 100 Hz (the coverage bench's case 5 accelerometer, doc/identification.md), the selection may
// take the mode for a line; the front-end corner and N then move by several of the selected
// structure's own sigmas, and only the widened sigmas hold the truth.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "identify_test_records.h"
#include "imu_lab/identify/fit.h"
#include "imu_lab/identify/record_simulation.h"

namespace imu_lab {
namespace identify {
namespace {

constexpr double kTau0 = 0.01, kLength = 7200.0;

// |ln(estimate / truth)| in units of the estimate's log-sigma.
double sigmas_off(const ParameterEstimate& estimate, double truth) {
  return std::abs(std::log(estimate.value / truth)) / estimate.log_sigma;
}

NoiseModel mode_beside_front_end() {
  NoiseModel truth;
  truth.terms = {{TermKind::kWhiteRate, 4e-3, 40.0},
                 {TermKind::kBiasInstability, 3e-3, 50.0},
                 {TermKind::kRandomWalk, 1e-4},
                 {TermKind::kSinusoid, 6e-3, 0.55},
                 {TermKind::kResonance, 1e-2, 20.0, 6.0}};
  return truth;
}

FitResult fit_mode_beside_front_end() {
  return fit_noise_model(identify_test::exact_octave_curve(mode_beside_front_end(), kTau0, kLength), kTau0, kLength);
}

// Every peak the other kind can hold at its frequency is weighed against that description. The
// 0.55 Hz line is not: a resonance's f_n lies in the top decade below the Nyquist frequency
// (fit_problem.h), so no mode can describe it (clamped to 5 Hz, the refit would describe another
// peak or none).
TEST(IdentifyStructureDoubt, EveryPeakIsWeighedAgainstItsOtherDescription) {
  const FitResult fit = fit_mode_beside_front_end();
  const double lowest_mode_hz = 0.1 / (2.0 * kTau0);
  std::vector<std::string> peaks;
  const std::vector<std::string> names = term_names(fit.model);
  for (size_t i = 0; i < fit.model.terms.size(); ++i) {
    const Term& term = fit.model.terms[i];
    if (term.kind == TermKind::kResonance || (term.kind == TermKind::kSinusoid && term.shape >= lowest_mode_hz)) {
      peaks.push_back(names[i]);
    }
  }
  std::vector<const StructureAlternative*> swaps;
  for (const StructureAlternative& alternative : fit.structure_alternatives) {
    if (!alternative.replaced.empty()) swaps.push_back(&alternative);
  }
  ASSERT_EQ(swaps.size(), peaks.size());
  for (size_t i = 0; i < peaks.size(); ++i) {
    EXPECT_EQ(swaps[i]->replaced, peaks[i]);
    EXPECT_EQ(swaps[i]->replacement, peaks[i].rfind("sinusoid", 0) == 0 ? "resonance" : "sinusoid");
    EXPECT_GE(swaps[i]->peak_frequency_hz, lowest_mode_hz);
  }
}

// An axis of the reference data's real_static units (three ADIS16405, 2.78 h at 100 Hz): its
// overlapping Allan curve at the allan tool's default grid as `allan` wrote it (oadev.csv:
// tau_s, m, deviation, edf, term_count), fitted with the output step the tool found there.
FitResult fit_reference_axis(const std::string& file_name, double output_step) {
  std::ifstream in(std::string(IMU_LAB_TEST_DATA_DIR) + "/identify/" + file_name);
  EXPECT_TRUE(in) << file_name << " missing";
  std::string line;
  std::getline(in, line);  // the header
  std::vector<allan::StabilityPoint> curve;
  while (std::getline(in, line)) {
    allan::StabilityPoint point;
    char comma = 0;
    std::istringstream fields(line);
    fields >> point.tau_s >> comma >> point.averaging_factor >> comma >> point.deviation >> comma >> point.edf >>
        comma >> point.term_count;
    EXPECT_TRUE(fields) << file_name << ": " << line;
    curve.push_back(point);
  }
  FitOptions options;
  options.output_quantization_step = output_step;
  return fit_noise_model(curve, 0.01, 10000.0, options);
}

constexpr double kAccelerometerStep = 0.0326561445;  // m/s^2, the units' accelerometer LSB
constexpr double kGyroStep = 0.000872664626;         // rad/s, the units' gyro LSB

// Unit 6's accelerometer y (doc/identification.md): a 0.56 Hz line and a borderline 10 Hz line.
// Swapping the slow line for a resonance (whose f_n cannot lie below 5 Hz) once refitted by
// moving the resonance onto 10 Hz and the 10 Hz line onto 0.56 Hz; paired slot by slot, the 10 Hz
// line's frequency then took a 95 % interval reaching down to 0.55 Hz. No alternative may trade
// peaks: each line's frequency keeps an interval about its own peak.
TEST(IdentifyStructureDoubt, NoAlternativeTradesTwoPeaks) {
  const FitResult fit = fit_reference_axis("adis16405_unit6_accel_y_oadev.csv", kAccelerometerStep);
  int lines = 0;
  for (const TermEstimate& term : fit.terms) {
    if (term.kind != TermKind::kSinusoid || term.status != TermStatus::kPresent) continue;
    ++lines;
    EXPECT_GT(term.shape.interval_low(1.96), term.shape.value / 2.0)
        << term.name << " at " << term.shape.value << " Hz";
    EXPECT_LT(term.shape.interval_high(1.96), term.shape.value * 2.0)
        << term.name << " at " << term.shape.value << " Hz";
  }
  EXPECT_EQ(lines, 2) << "this test needs the two lines the tool reports";
}

// Unit 5's gyro y: the selection added a 25 Hz resonance, then an 11.3 Hz line; described as a
// line, the 25 Hz peak fits better by 1.2 in J with a parameter fewer (as an alternative it
// outweighed the selection, 0.70, and its front-end corner read 28.8 Hz with a 68.3 % interval of
// 35.7-36.4 Hz that left it out). A dominated structure is not reported: no resonance is left
// whose line fits at least as well, both peaks are lines, and the reported corner lies inside its
// own 68.3 % interval.
TEST(IdentifyStructureDoubt, AModeALineDescribesAtLeastAsWellIsTakenAsTheLine) {
  const FitResult fit = fit_reference_axis("adis16405_unit5_gyro_y_oadev.csv", kGyroStep);
  for (const StructureAlternative& alternative : fit.structure_alternatives) {
    if (alternative.replacement != "sinusoid") continue;
    EXPECT_GT(alternative.distance_change, 0.0) << alternative.replaced << " at " << alternative.peak_frequency_hz;
  }
  int lines = 0, modes = 0;
  for (const TermEstimate& term : fit.terms) {
    if (term.status != TermStatus::kPresent) continue;
    lines += term.kind == TermKind::kSinusoid;
    modes += term.kind == TermKind::kResonance;
  }
  EXPECT_EQ(lines, 2);
  EXPECT_EQ(modes, 0);
  const TermEstimate* white = fit.find("white_rate");
  ASSERT_NE(white, nullptr);
  ASSERT_TRUE(white->shape_fitted);
  EXPECT_GE(white->shape.value, white->shape.interval_low(1.0));
  EXPECT_LE(white->shape.value, white->shape.interval_high(1.0));
}

// Each one-parameter term the selection left out is added as an alternative (from a negligible
// amplitude, so J can only fall), and every alternative widens each shared parameter's variance
// by at least its weight times its squared offset. Here K (in the truth, 1e-4) is left out, and
// adding it moves B.
TEST(IdentifyStructureDoubt, LeftOutTermsAreWeighedAndWidenTheSharedSigmas) {
  const FitResult fit = fit_mode_beside_front_end();
  int additions = 0, left_out = 0;
  for (const TermEstimate& term : fit.terms) {
    // Lines and modes left out are bounded, not added; a left-out Markov term is added where it
    // lowers J.
    const bool peak = term.kind == TermKind::kSinusoid || term.kind == TermKind::kResonance;
    left_out += term.status == TermStatus::kAbsent && !peak && term.kind != TermKind::kMarkov;
  }
  double weights = 0.0;
  const StructureAlternative* walk = nullptr;
  for (const StructureAlternative& alternative : fit.structure_alternatives) {
    weights += alternative.weight;
    ASSERT_EQ(alternative.log_parameter_offsets.size(), fit.log_parameters.size());
    for (size_t p = 0; p < fit.log_parameters.size(); ++p) {
      const double offset = alternative.log_parameter_offsets[p];
      EXPECT_GE(fit.log_covariance(p, p), alternative.weight * offset * offset * (1.0 - 1e-9))
          << alternative.replacement << ", parameter " << p;
    }
    if (!alternative.replaced.empty()) continue;
    if (alternative.replacement == "markov") {
      EXPECT_EQ(alternative.parameter_change, 2);
      EXPECT_LT(alternative.distance_change, 0.0);
      continue;
    }
    ++additions;
    EXPECT_EQ(alternative.parameter_change, 1);
    EXPECT_LE(alternative.distance_change, 1e-9 * fit.quality.distance) << alternative.replacement;
    const TermEstimate* term = fit.find(alternative.replacement);
    ASSERT_NE(term, nullptr) << alternative.replacement;
    EXPECT_EQ(term->status, TermStatus::kAbsent);
    if (alternative.replacement == "random_walk") walk = &alternative;
  }
  EXPECT_EQ(additions, left_out);
  EXPECT_LT(weights, 1.0);  // the selected structure keeps a share
  ASSERT_NE(walk, nullptr) << "K was expected to be left out of this curve's model";
  double largest_offset = 0.0;
  for (double offset : walk->log_parameter_offsets) largest_offset = std::max(largest_offset, std::abs(offset));
  EXPECT_GT(largest_offset, 1e-3);  // 0.9 % on this curve
}

// On this exact curve the first selection (under a 1 % spread) describes the 20 Hz mode as a
// line near 17 Hz and the front end with a corner near 21 Hz, a structure that leaves no spread.
// The line is then weighed as a mode at the estimates' own precision, where the mode's width
// shows: the true structure is reported, its corner and f_n at their truths. (Before that second
// look ran without a spread, this curve was the doubt's test of a corner widened towards the
// mode's alternative; fit.cpp, select_terms.)
TEST(IdentifyStructureDoubt, AModeTakenForALineUnderTheFirstSpreadIsWeighedAsAMode) {
  const FitResult fit = fit_mode_beside_front_end();
  const TermEstimate* mode = fit.find("resonance_1");
  ASSERT_NE(mode, nullptr) << "the mode was described as a line";
  ASSERT_EQ(mode->status, TermStatus::kPresent);
  for (const TermEstimate& term : fit.terms) {
    EXPECT_FALSE(term.kind == TermKind::kSinusoid && term.status == TermStatus::kPresent && term.shape.value > 5.0)
        << term.name << " at " << term.shape.value << " Hz beside the mode";
  }
  // An exact curve: the estimates lie within a small fraction of their sigmas of the truths.
  EXPECT_LT(sigmas_off(mode->shape, 20.0), 0.5) << "f_n " << mode->shape.value << " Hz";
  const TermEstimate* white = fit.find("white_rate");
  ASSERT_NE(white, nullptr);
  ASSERT_TRUE(white->shape_fitted);
  EXPECT_LT(sigmas_off(white->shape, 40.0), 0.5) << "corner " << white->shape.value << " Hz";
  EXPECT_LT(sigmas_off(white->amplitude, 4e-3), 0.5) << "N " << white->amplitude.value;
}

// The normal cumulative distribution, written out here apart from the code under test.
double normal_below(double x) { return 0.5 * (1.0 + std::erf(x / std::sqrt(2.0))); }

// A slow Markov hump on the floor of bias instability, lower than the coverage bench's case 10
// (N behind a 40 Hz front end at 100 Hz, B 3e-4, a Markov term of T_c 30 s standing 1.26x over
// the floor near 60 s where the bench's stands 1.52x, two hours). The selection often leaves the
// hump out (its fall of J, 4-15 here, is under the threshold of a searched shape, 15.9), and B
// alone then carries the floor 8-14 % high with a sigma of 2-4 %. The left-out Markov term is
// weighed as an alternative like every left-out term (its searched shape charged 2 ln(points),
// its own covariance used: B trades with the hump there): B's 95 % interval must hold the truth
// as a 95 % interval should. With nominal coverage, 5 or fewer of 8 records holding it has a
// chance of 0.6 %; these 8 hold it 6 times, and 2 times without the Markov alternative.
TEST(IdentifyStructureDoubt, AMarkovHumpTheSelectionLeftOutWidensTheFloorsInterval) {
  NoiseModel truth;
  truth.terms = {
      {TermKind::kWhiteRate, 5e-4}, {TermKind::kBiasInstability, 3e-4, 50.0}, {TermKind::kMarkov, 2e-3, 30.0}};
  constexpr double kRateHz = 100.0, kLengthS = 7200.0, kFrontEndHz = 40.0;
  constexpr int kRecords = 8, kFewestHolding = 6;
  const double true_b = truth.terms[1].amplitude;
  const auto processes = emulator_processes(truth, 1.0 / kRateHz, kLengthS);
  int holding = 0, hump_left_out = 0;
  std::string misses;
  for (int seed = 1; seed <= kRecords; ++seed) {
    const auto rates = identify_test::emulate_axis_rates(processes, kRateHz, kLengthS, seed, kFrontEndHz);
    const FitResult fit = fit_noise_model(identify_test::default_grid_oadev(rates, kRateHz), 1.0 / kRateHz, kLengthS);
    const TermEstimate* bias = fit.find("bias_instability");
    ASSERT_NE(bias, nullptr) << "seed " << seed;
    ASSERT_EQ(bias->status, TermStatus::kPresent) << "seed " << seed;
    if (fit.find("markov_1") == nullptr) ++hump_left_out;
    const double low = bias->amplitude.interval_low(1.959964), high = bias->amplitude.interval_high(1.959964);
    if (true_b >= low && true_b <= high) {
      ++holding;
    } else {
      misses += " seed " + std::to_string(seed) + ": B " + std::to_string(bias->amplitude.value) + ", 95 % [" +
                std::to_string(low) + ", " + std::to_string(high) + "];";
    }
  }
  // The case this test is about: the hump left out on most records (6 of 8 on these seeds).
  EXPECT_GE(hump_left_out, kRecords / 2);
  EXPECT_GE(holding, kFewestHolding) << misses;
}

TEST(IdentifyStructureDoubt, OneStructureGivesTheSymmetricIntervalInTheLogarithm) {
  const std::vector<LogNormalComponent> alone = {{1.0, 0.0, 0.2}};
  EXPECT_NEAR(mixture_log_quantile(alone, normal_below(1.0)), 0.2, 1e-9);
  EXPECT_NEAR(mixture_log_quantile(alone, normal_below(-1.959964)), -0.2 * 1.959964, 1e-9);
}

// 0.8 N(0, 0.1) + 0.2 N(-1, 0.1): the upper 84.1 % limit is where 0.2 + 0.8 Phi(q / 0.1) = 0.841,
// q = 0.1 Phi^-1(0.8016) = 0.0847; the lower 2.5 % limit lies inside the alternative's component.
TEST(IdentifyStructureDoubt, MixtureLimitsAreWhereTheWeightedTailsReachTheirShare) {
  const std::vector<LogNormalComponent> mixture = {{0.8, 0.0, 0.1}, {0.2, -1.0, 0.1}};
  const auto below = [&](double q) { return 0.8 * normal_below(q / 0.1) + 0.2 * normal_below((q + 1.0) / 0.1); };
  for (double probability : {0.025, 0.1587, 0.5, 0.8413, 0.975}) {
    const double q = mixture_log_quantile(mixture, probability);
    EXPECT_NEAR(below(q), probability, 1e-9) << probability;
  }
  EXPECT_NEAR(mixture_log_quantile(mixture, normal_below(1.0)), 0.0847, 5e-4);
  EXPECT_LT(mixture_log_quantile(mixture, 0.025), -0.9);
  // Zero-sigma components are steps at their offsets.
  const std::vector<LogNormalComponent> steps = {{0.3, -1.0, 0.0}, {0.7, 2.0, 0.0}};
  EXPECT_NEAR(mixture_log_quantile(steps, 0.2), -1.0, 1e-9);
  EXPECT_NEAR(mixture_log_quantile(steps, 0.5), 2.0, 1e-9);
}

// When an alternative outweighs the selected structure (a left-out term whose addition lowers J
// by more than Akaike's 2 but less than the selection's threshold), the intervals lean to its
// values and may leave reported ones out: a warning says so and names them.
TEST(IdentifyStructureDoubt, AnAlternativeThatOutweighsTheSelectionIsWarnedAbout) {
  const FitResult fit = fit_mode_beside_front_end();
  double selected_weight = 1.0;
  const StructureAlternative* walk = nullptr;
  for (const StructureAlternative& alternative : fit.structure_alternatives) {
    selected_weight -= alternative.weight;
    if (alternative.replacement == "random_walk") walk = &alternative;
  }
  ASSERT_NE(walk, nullptr);
  ASSERT_GT(walk->weight, selected_weight) << "this test needs a curve where adding K outweighs the selection";
  const std::string* warning = nullptr;
  for (const std::string& text : fit.warnings) {
    if (text.find("with random_walk added outweighs") != std::string::npos) warning = &text;
  }
  ASSERT_NE(warning, nullptr);
  // Every reported amplitude its 68 % interval leaves out is named.
  for (const TermEstimate& term : fit.terms) {
    if (term.status != TermStatus::kPresent) continue;
    const bool outside =
        term.amplitude.value < term.amplitude.interval_low(1.0) || term.amplitude.value > term.amplitude.interval_high(1.0);
    EXPECT_EQ(outside, warning->find(term.name + " amplitude") != std::string::npos) << term.name << ": " << *warning;
  }
}

}  // namespace
}  // namespace identify
}  // namespace imu_lab
