// The allan tool's console report (pipeline/noise_table.h). The full table (--verbose): a present
// term reads value ± sigma, and where alternative structures were weighed also the 68.3 %
// interval of their mixture, which can sit off-centre; an absent term reads as its bound. The
// default report: the Kalibr numbers with their upper bounds named, one row per axis of the IEEE
// terms in the table's units, and the warnings grouped by kind in those units.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <sstream>
#include <string>

#include "imu_lab/common/format_number.h"
#include "imu_lab/pipeline/noise_table.h"

namespace imu_lab {
namespace pipeline {
namespace {

using identify::LogNormalComponent;
using identify::SensorKind;
using identify::TermEstimate;
using identify::TermKind;
using identify::TermStatus;
using identify::TriadFit;

constexpr double kDegHPerRadS = 180.0 / 3.14159265358979323846 * 3600.0;
// deg/h/sqrt(h) per rad/s/sqrt(s): deg/h per rad/s times 60 sqrt(s) per sqrt(h).
constexpr double kDegHPerSqrtHPerRadSPerSqrtS = kDegHPerRadS * 60.0;

// P(ln(theta / value) < x) under the mixture, written here apart from the library's.
double mixture_cdf(const std::vector<LogNormalComponent>& mixture, double x) {
  double total = 0.0;
  for (const LogNormalComponent& component : mixture) {
    total += component.weight * 0.5 * std::erfc(-(x - component.log_offset) / (component.log_sigma * std::sqrt(2.0)));
  }
  return total;
}

TermEstimate present_term(TermKind kind, double value_rad_s, double log_sigma) {
  TermEstimate term;
  term.name = identify::term_kind_name(kind);
  term.kind = kind;
  term.status = TermStatus::kPresent;
  term.amplitude.value = value_rad_s;
  term.amplitude.log_sigma = log_sigma;
  term.amplitude.sigma = value_rad_s * log_sigma;
  term.sigma_source = identify::SigmaSource::kMomentCovariance;
  return term;
}

TermEstimate bias_instability(double value_rad_s, double log_sigma) {
  return present_term(TermKind::kBiasInstability, value_rad_s, log_sigma);
}

std::string line_of(const std::string& table, const std::string& start) {
  std::istringstream lines(table);
  for (std::string line; std::getline(lines, line);) {
    if (line.rfind(start, 0) == 0) return line;
  }
  return "";
}

TEST(NoiseTable, AnIntervalFromWeighedStructuresIsShownBesideTheSigma) {
  TriadFit triad;
  triad.sensor = SensorKind::kGyroscope;
  // x: one structure; y: the selected one outweighed by an alternative that lowers B by 10 %.
  const double value_rad_s = 1.6e-4;
  triad.axes[0].terms = {bias_instability(value_rad_s, 0.05)};
  TermEstimate doubted = bias_instability(value_rad_s, 0.09);
  doubted.amplitude.structure_mixture = {{0.1, 0.0, 0.04}, {0.9, -0.1, 0.04}};
  triad.axes[1].terms = {doubted};
  TermEstimate absent;
  absent.name = "random_walk";
  absent.kind = TermKind::kRandomWalk;
  absent.status = TermStatus::kAbsent;
  absent.amplitude.upper_bound = 2e-6;
  triad.axes[2].terms = {absent};

  const std::string table = format_noise_table({triad});
  const std::string plain = line_of(table, "  gyro_x   bias_instability");
  ASSERT_FALSE(plain.empty()) << table;
  EXPECT_NE(plain.find("33 ± 1.65 (moment_covariance)"), std::string::npos) << plain;
  EXPECT_EQ(plain.find("68 %"), std::string::npos) << plain;

  const std::string weighed = line_of(table, "  gyro_y   bias_instability");
  const size_t at = weighed.find(", 68 %: ");
  ASSERT_NE(at, std::string::npos) << weighed;
  double low_deg_h = 0.0, high_deg_h = 0.0;
  ASSERT_EQ(std::sscanf(weighed.c_str() + at, ", 68 %%: %lf to %lf", &low_deg_h, &high_deg_h), 2) << weighed;
  // Four significant digits: the printed limits sit at the mixture's 15.87 and 84.13 %.
  const double value_deg_h = value_rad_s * kDegHPerRadS;
  EXPECT_NEAR(mixture_cdf(doubted.amplitude.structure_mixture, std::log(low_deg_h / value_deg_h)), 0.158655, 2e-3);
  EXPECT_NEAR(mixture_cdf(doubted.amplitude.structure_mixture, std::log(high_deg_h / value_deg_h)), 0.841345, 2e-3);
  EXPECT_LT(high_deg_h, value_deg_h) << "the alternative's weight pulls the whole interval below the value";

  const std::string bound = line_of(table, "  gyro_z   random_walk");
  EXPECT_NE(bound.find("< "), std::string::npos) << bound;
  EXPECT_EQ(bound.find("68 %"), std::string::npos) << bound;
}

// The front end's corner is a fitted parameter like any other: the table gives its sigma beside it.
TEST(NoiseTable, TheFittedCornerOfTheFrontEndCarriesItsSigma) {
  TriadFit triad;
  triad.sensor = SensorKind::kGyroscope;
  for (int axis = 0; axis < 3; ++axis) {
    TermEstimate white = present_term(TermKind::kWhiteRate, 7e-4, 0.002);
    white.shape.value = 53.44;
    if (axis == 0) {  // fitted; y and z at a given corner have none
      white.shape.log_sigma = 0.97 / 53.44;
      white.shape.sigma = 0.97;
      white.shape_fitted = true;
    }
    triad.axes[axis].terms = {white};
  }
  const std::string table = format_noise_table({triad});
  const std::string fitted = line_of(table, "  gyro_x   white_rate");
  EXPECT_NE(fitted.find(", low-pass 53.44 ± 0.97 hz"), std::string::npos) << fitted;
  const std::string given = line_of(table, "  gyro_y   white_rate");
  EXPECT_NE(given.find(", low-pass 53.44 hz"), std::string::npos) << given;
}

TermEstimate absent_term(TermKind kind, double bound_si) {
  TermEstimate term;
  term.name = identify::term_kind_name(kind);
  term.kind = kind;
  term.status = TermStatus::kAbsent;
  term.amplitude.upper_bound = bound_si;
  return term;
}

std::size_t count_of(const std::string& text, const std::string& part) {
  std::size_t count = 0;
  for (std::size_t at = text.find(part); at != std::string::npos; at = text.find(part, at + 1)) ++count;
  return count;
}

// A slope reading of K on two axes, as the fit finds it (SI values).
identify::FitFinding k_slope_reading(double reading_si, double bound_si) {
  identify::FitFinding finding;
  finding.kind = identify::FindingKind::kSlopeReading;
  finding.term = "random_walk";
  finding.term_kind = TermKind::kRandomWalk;
  finding.first_tau_s = 3.0;
  finding.value = reading_si;
  finding.fitted = bound_si;
  finding.fitted_is_bound = true;
  finding.text = "slope reading of K at tau = 3 s ... (the sentence noise.yaml keeps)";
  return finding;
}

TriadFit gyro_with_absent_k() {
  TriadFit triad;
  triad.sensor = SensorKind::kGyroscope;
  for (int axis = 0; axis < 3; ++axis) {
    triad.axes[axis].terms = {present_term(TermKind::kWhiteRate, 7.25e-4, 0.0026),
                              absent_term(TermKind::kRandomWalk, 1.95e-5 * (axis + 1))};
  }
  return triad;
}

TEST(NoiseTable, TheIeeeTableHasOneRowPerAxisInTheFieldsUnits) {
  TriadFit triad = gyro_with_absent_k();
  TermEstimate resonance = present_term(TermKind::kResonance, 5.05e-3, 0.0128);
  resonance.name = "resonance_1";
  resonance.shape.value = 20.11;
  triad.axes[2].terms.push_back(resonance);
  const std::string table = format_ieee_table({triad});
  const std::string head = line_of(table, "  gyro ");
  for (const char* column :
       {"N [deg_per_sqrt_h]", "B [deg_h]", "K [deg_h_per_sqrt_h]", "Q [arcsec]", "R [deg_h_per_h]"})
    EXPECT_NE(head.find(column), std::string::npos) << column << "\n" << table;
  // N = 7.25e-4 rad/s/sqrt(Hz) = 2.492 deg/sqrt(h), its sigma to two digits; K absent: its bound,
  // 1.95e-5 rad/s/sqrt(s) = 241.3 deg/h/sqrt(h); B not a candidate here: "-".
  const std::string x = line_of(table, "  gyro_x ");
  EXPECT_NE(x.find("2.492 ± 0.0065"), std::string::npos) << x;
  EXPECT_NE(x.find("< " + format_number(1.95e-5 * kDegHPerSqrtHPerRadSPerSqrtS, 4)), std::string::npos) << x;
  EXPECT_NE(x.find(" - "), std::string::npos) << x;
  EXPECT_EQ(x.find("moment_covariance"), std::string::npos) << x;
  EXPECT_EQ(count_of(table, "  gyro_"), 3u) << table;
  // The other terms of the model go under their axis's row, one line.
  const std::size_t z = table.find("  gyro_z ");
  ASSERT_NE(z, std::string::npos);
  EXPECT_NE(table.find("also in the model: resonance_1 1042 ± 13 deg_h, f_n 20.11 hz", z), std::string::npos) << table;
  EXPECT_EQ(table.find("also in the model"), table.find("also in the model", z)) << "only gyro_z has one";
}

TEST(NoiseTable, WarningsAreGroupedByKindInTheTablesUnits) {
  TriadFit triad = gyro_with_absent_k();
  triad.axes[0].findings = {k_slope_reading(4.31e-4, 1.95e-5)};
  triad.axes[1].findings = {k_slope_reading(4.56e-4, 2.09e-5)};
  identify::FitFinding borderline;
  borderline.kind = identify::FindingKind::kBorderline;
  borderline.term = "random_walk";
  borderline.term_kind = TermKind::kRandomWalk;
  identify::FitFinding markov_borderline = borderline;
  markov_borderline.term = "markov_1";
  markov_borderline.term_kind = TermKind::kMarkov;
  triad.axes[0].findings.push_back(borderline);
  triad.axes[0].findings.push_back(markov_borderline);
  triad.axes[2].findings = {borderline};

  std::string grouped = format_grouped_findings({triad});
  // One line per kind (long ones wrap onto indented lines), each axis once on it, values in the
  // table's unit (deg/h/sqrt(h) for K).
  for (std::size_t at = grouped.find("\n      "); at != std::string::npos; at = grouped.find("\n      "))
    grouped.replace(at, 7, " ");
  std::istringstream lines(grouped);
  std::vector<std::string> all;
  for (std::string line; std::getline(lines, line);) all.push_back(line);
  ASSERT_EQ(all.size(), 2u) << grouped;
  const std::string reading = "gyro_x K " + format_number(4.31e-4 * kDegHPerSqrtHPerRadSPerSqrtS, 4) +
                              " deg_h_per_sqrt_h at 3 s, fit < " +
                              format_number(1.95e-5 * kDegHPerSqrtHPerRadSPerSqrtS, 4) + "; gyro_y K ";
  EXPECT_NE(grouped.find(reading), std::string::npos) << grouped;
  EXPECT_NE(grouped.find("threshold: another recording may decide otherwise: gyro_x K, markov_1; gyro_z K"),
            std::string::npos)
      << grouped;
  for (const char* jargon : {"Akaike", "statistic", "1.95e-05", "(the sentence noise.yaml keeps)"})
    EXPECT_EQ(grouped.find(jargon), std::string::npos) << jargon << "\n" << grouped;
  EXPECT_EQ(format_grouped_findings({gyro_with_absent_k()}), "");
}

TEST(NoiseTable, TheKalibrLinesNameWhereAnUpperBoundCameFrom) {
  identify::KalibrImuNoise noise;
  noise.gyroscope_noise_density = {4.413e-4, false, 2};
  noise.gyroscope_random_walk = {2.09e-5, true, 1};
  noise.accelerometer_noise_density = {4.749e-3, false, 0};
  noise.accelerometer_random_walk = {7.08e-4, false, 0};
  const std::string lines = format_kalibr_lines(noise);
  EXPECT_EQ(lines,
            "  gyroscope_noise_density      0.0004413 rad/s/sqrt(Hz)\n"
            "  gyroscope_random_walk        2.09e-05 rad/s^2/sqrt(Hz) (an upper bound: K not found on gyro_y)\n"
            "  accelerometer_noise_density  0.004749 m/s^2/sqrt(Hz)\n"
            "  accelerometer_random_walk    0.000708 m/s^3/sqrt(Hz)\n");
}

}  // namespace
}  // namespace pipeline
}  // namespace imu_lab
