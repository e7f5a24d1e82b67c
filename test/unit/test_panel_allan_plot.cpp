// The Allan panel's logic: curves to log-log series with their band, the identified model's total
// and term curves, and the record-length text.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "imu_lab/identify/noise_model.h"
#include "imu_lab/panel/allan_plot.h"

namespace imu_lab {
namespace panel {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInfinity = std::numeric_limits<double>::infinity();

NoiseTerm make_term(const std::string& name, const std::string& symbol, const std::string& status, double value,
                    double shape, double required_s) {
  NoiseTerm term;
  term.name = name;
  term.symbol = symbol;
  term.status = status;
  term.value = value;
  term.shape = shape;
  term.width = kNaN;
  term.required_record_length_s = required_s;
  return term;
}

// N, B (cutoff at Nyquist of 100 Hz), K, a Markov term numbered as reports number it, an absent R.
NoiseAxisModel gyro_x_model() {
  NoiseAxisModel axis;
  axis.axis = "gyro_x";
  axis.terms = {make_term("white_rate", "N", "present", 2.0e-4, kNaN, 60.0),
                make_term("bias_instability", "B", "present", 5.0e-6, 50.0, 5.0 * 3600.0),
                make_term("random_walk", "K", "unconstrained", 3.0e-7, kNaN, kInfinity),
                make_term("markov_1", "q_c_T_c", "present", 1.0e-5, 30.0, 2.0 * 3600.0),
                make_term("rate_ramp", "R", "absent", kNaN, kNaN, kNaN)};
  axis.output_quantization_density = 1.0e-5;
  return axis;
}

identify::NoiseModel gyro_x_identify_model() {
  identify::NoiseModel model;
  model.terms = {{identify::TermKind::kWhiteRate, 2.0e-4, 0.0, 0.0},
                 {identify::TermKind::kBiasInstability, 5.0e-6, 50.0, 0.0},
                 {identify::TermKind::kRandomWalk, 3.0e-7, 0.0, 0.0},
                 {identify::TermKind::kMarkov, 1.0e-5, 30.0, 0.0}};
  model.output_quantization_density = 1.0e-5;
  return model;
}

StabilityCurves gyro_curves(const std::string& statistic, std::uint64_t samples) {
  StabilityCurves curves;
  curves.statistic = statistic;
  curves.sensor = "gyro";
  curves.unit = "rad/s";
  curves.tau0_s = 0.01;
  curves.confidence = 0.683;
  curves.samples = samples;
  curves.tau_s = {0.01, 0.1, 1.0, 10.0, 100.0};
  for (const char* name : {"x", "y", "z"}) {
    StabilityAxis axis;
    axis.name = name;
    axis.deviation = {2e-3, 6e-4, kNaN, 6e-5, 3e-5};
    axis.lower = {1.9e-3, 5.5e-4, kNaN, 5e-5, 1e-5};
    axis.upper = {2.1e-3, 6.5e-4, kNaN, 7e-5, 9e-5};
    curves.axes.push_back(axis);
  }
  return curves;
}

TEST(PanelDurationText, PicksAUnitAPersonReads) {
  EXPECT_EQ(duration_text(45.0), "45 s");
  EXPECT_EQ(duration_text(5.0), "5 s");
  EXPECT_EQ(duration_text(90.0), "90 s");
  EXPECT_EQ(duration_text(720.0), "12 min");
  EXPECT_EQ(duration_text(3.2 * 3600.0), "3.2 h");
  EXPECT_EQ(duration_text(30.0 * 3600.0), "30 h");
  EXPECT_EQ(duration_text(2.5 * 86400.0), "2.5 d");
}

TEST(PanelRecordLength, SaysHowMuchLongerEachModelTermNeeds) {
  const NoiseAxisModel axis = gyro_x_model();
  // 1.8 h recorded: B needs 5 h, 3.2 h more; N needed a minute; K cannot be resolved; R is absent.
  const auto lines = record_length_lines(axis, 1.8 * 3600.0);
  ASSERT_EQ(lines.size(), 4u);
  EXPECT_EQ(lines[0], "N: resolved");
  EXPECT_EQ(lines[1], "B: about 3.2 h more");
  EXPECT_EQ(lines[2], "K: not within 10000 x this record");
  EXPECT_EQ(lines[3], "q_c_T_c: about 12 min more");
}

TEST(PanelRecordLength, ATermIsResolvedOnceTheRecordIsLongEnough) {
  const auto lines = record_length_lines(gyro_x_model(), 5.0 * 3600.0);
  ASSERT_EQ(lines.size(), 4u);
  EXPECT_EQ(lines[1], "B: resolved");
}

TEST(PanelModelSeries, TotalAndTermsAreTheIdentifiedModelsDeviations) {
  const std::vector<double> tau_s = {0.01, 0.1, 1.0, 10.0, 100.0, 1000.0};
  const auto series = model_series(gyro_x_model(), tau_s);
  // The total, N, B, K, the Markov term, the output's rounding; no absent R.
  ASSERT_EQ(series.size(), 6u);
  EXPECT_EQ(series[0].role, SeriesRole::kModelTotal);
  EXPECT_EQ(series[1].label, "N");
  EXPECT_EQ(series[3].label, "K");
  EXPECT_FALSE(series[3].constrained) << "K is unconstrained: drawn as an estimate";
  EXPECT_TRUE(series[2].constrained);
  EXPECT_EQ(series[5].label, "output rounding");
  const identify::NoiseModel model = gyro_x_identify_model();
  for (std::size_t k = 0; k < tau_s.size(); ++k) {
    ASSERT_EQ(series[0].points.size(), tau_s.size());
    EXPECT_DOUBLE_EQ(series[0].points[k].log10_tau, std::log10(tau_s[k]));
    EXPECT_NEAR(series[0].points[k].log10_deviation, 0.5 * std::log10(identify::model_avar(model, tau_s[k])), 1e-12)
        << "tau " << tau_s[k];
    for (std::size_t term = 0; term < model.terms.size(); ++term) {
      EXPECT_NEAR(series[term + 1].points[k].log10_deviation,
                  0.5 * std::log10(identify::term_avar(model.terms[term], tau_s[k])), 1e-12)
          << series[term + 1].label << " at tau " << tau_s[k];
    }
  }
}

TEST(PanelModelSeries, NoTermWithAValueMeansNoModel) {
  NoiseAxisModel axis;
  axis.terms = {make_term("rate_ramp", "R", "absent", kNaN, kNaN, kNaN)};
  EXPECT_TRUE(model_series(axis, {1.0, 10.0}).empty());
}

TEST(AllanPanelModel, CurvesBecomeLogLogSeriesWithTheirBand) {
  AllanPanelModel model;
  model.add_curves(gyro_curves("oadev", 360000));
  const AllanPlot plot = model.plot("gyro", "oadev", 1);
  ASSERT_FALSE(plot.empty());
  EXPECT_EQ(plot.title, "gyro y, oadev (rad/s)");
  ASSERT_EQ(plot.measured.points.size(), 4u) << "the NaN point is left out";
  EXPECT_DOUBLE_EQ(plot.measured.points[0].log10_tau, -2.0);
  EXPECT_DOUBLE_EQ(plot.measured.points[2].log10_tau, 1.0);
  EXPECT_NEAR(plot.measured.points[2].log10_deviation, std::log10(6e-5), 1e-12);
  ASSERT_EQ(plot.band.size(), 4u);
  EXPECT_NEAR(plot.band[3].log10_lower, -5.0, 1e-12);
  EXPECT_NEAR(plot.band[3].log10_upper, std::log10(9e-5), 1e-12);
  EXPECT_EQ(plot.tau_decades.low, -2);
  EXPECT_EQ(plot.tau_decades.high, 2);
  EXPECT_EQ(plot.deviation_decades.low, -5) << "the band's lowest bound, 1e-5";
  EXPECT_EQ(plot.deviation_decades.high, -2);
  EXPECT_TRUE(plot.model.empty());
  ASSERT_EQ(plot.status_lines.size(), 2u);
  EXPECT_EQ(plot.status_lines[0], "recorded 60 min (360000 samples), band 68.3 %");
  EXPECT_EQ(plot.status_lines[1], "no noise report yet");
}

TEST(AllanPanelModel, KeepsTheLatestCurvesPerTriadAndStatistic) {
  AllanPanelModel model;
  model.add_curves(gyro_curves("oadev", 100));
  model.add_curves(gyro_curves("mdev", 100));
  model.add_curves(gyro_curves("oadev", 200));
  StabilityCurves accel = gyro_curves("oadev", 200);
  accel.sensor = "accel";
  model.add_curves(accel);
  EXPECT_EQ(model.sensors(), (std::vector<std::string>{"gyro", "accel"}));
  EXPECT_EQ(model.statistics("gyro"), (std::vector<std::string>{"oadev", "mdev"}));
  EXPECT_NE(model.plot("gyro", "oadev", 0).status_lines[0].find("(200 samples)"), std::string::npos);
  EXPECT_TRUE(model.plot("accel", "mdev", 0).empty());
  EXPECT_TRUE(model.plot("gyro", "oadev", 3).empty());
}

TEST(AllanPanelModel, TheModelIsDrawnOnOadevWithTheRecordItNeeds) {
  AllanPanelModel model;
  model.add_curves(gyro_curves("oadev", 648000));  // 1.8 h at 100 Hz
  model.add_curves(gyro_curves("mdev", 648000));
  NoiseReport report;
  report.tau0_s = 0.01;
  report.record_length_s = 1.5 * 3600.0;  // the report is older than the curves
  report.target_relative_sigma = 0.1;
  report.axes = {gyro_x_model()};
  model.set_noise_report(report);

  const AllanPlot oadev = model.plot("gyro", "oadev", 0);
  ASSERT_EQ(oadev.model.size(), 6u);
  EXPECT_EQ(oadev.model[0].points.size(), oadev.measured.points.size()) << "the model at the measured taus";
  ASSERT_EQ(oadev.record_length_lines.size(), 5u);
  EXPECT_EQ(oadev.record_length_lines[0], "record for 10 % (1 sigma):");
  EXPECT_EQ(oadev.record_length_lines[2], "B: about 3.2 h more") << "counted from the record so far, 1.8 h";
  EXPECT_EQ(oadev.status_lines[1], "model fitted on 90 min of record");

  const AllanPlot mdev = model.plot("gyro", "mdev", 0);
  EXPECT_TRUE(mdev.model.empty()) << "the fit is on oadev; mdev expects other values for the same noise";
  EXPECT_EQ(mdev.record_length_lines, oadev.record_length_lines);

  const AllanPlot other_axis = model.plot("gyro", "oadev", 1);
  EXPECT_TRUE(other_axis.model.empty()) << "the report has no gyro_y";
  EXPECT_TRUE(other_axis.record_length_lines.empty());
}

TEST(AllanPanelModel, AnUnknownTermIsSaidNotDrawn) {
  AllanPanelModel model;
  model.add_curves(gyro_curves("oadev", 1000));
  NoiseReport report;
  NoiseAxisModel axis = gyro_x_model();
  axis.terms[0].name = "mystery";
  report.axes = {axis};
  model.set_noise_report(report);
  const AllanPlot plot = model.plot("gyro", "oadev", 0);
  EXPECT_TRUE(plot.model.empty());
  ASSERT_EQ(plot.status_lines.size(), 3u);
  EXPECT_EQ(plot.status_lines[2], "model not drawn: unknown noise term 'mystery'");
}

TEST(AllanPanelModel, IdentificationProblemsAreShown) {
  AllanPanelModel model;
  model.add_curves(gyro_curves("oadev", 1000));
  NoiseReport report;
  report.problems = {"gyro: record too short"};
  model.set_noise_report(report);
  const AllanPlot plot = model.plot("gyro", "oadev", 0);
  ASSERT_EQ(plot.status_lines.size(), 2u);
  EXPECT_EQ(plot.status_lines[1], "identification: gyro: record too short");
}

}  // namespace
}  // namespace panel
}  // namespace imu_lab
