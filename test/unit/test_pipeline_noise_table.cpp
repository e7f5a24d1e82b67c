// The allan tool's console table (pipeline/noise_table.h): a present term reads value ± sigma, and
// where alternative structures were weighed also the 68.3 % interval of their mixture, which can
// sit off-centre; an absent term reads as its bound.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <sstream>
#include <string>

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

}  // namespace
}  // namespace pipeline
}  // namespace imu_lab
