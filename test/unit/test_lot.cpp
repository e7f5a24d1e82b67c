// Lot summary: typical is the median and worst the maximum over the units that identify a term,
// in the field's unit the noise table prints; units without the term are counted and their upper
// bound kept; the typical model takes the terms a majority identifies, with median amplitudes.
#include "imu_lab/repeatability/lot.h"

#include <gtest/gtest.h>

#include <cmath>

#include "imu_lab/common/format_number.h"
#include "imu_lab/identify/units.h"

namespace {

namespace rep = imu_lab::repeatability;
namespace units = imu_lab::identify::units;

const std::string kGyroX = "triads.gyro.axes.gyro_x.";
const std::string kAccelZ = "triads.accel.axes.accel_z.";

// A report's values for a gyro_x white rate N (SI and deg/sqrt(h), as the report writes both)
// and, if given, a bias instability B.
std::map<std::string, double> gyro_report(double n_deg_per_sqrt_h, double b_deg_h) {
  std::map<std::string, double> values;
  const double n_si = n_deg_per_sqrt_h * units::kDegPerSqrtHour_rad_per_sqrt_s;
  values[kGyroX + "terms.white_rate.N_rad_s_per_sqrt_hz"] = n_si;
  values[kGyroX + "terms.white_rate.N_rad_s_per_sqrt_hz_sigma"] = 0.01 * n_si;
  values[kGyroX + "terms.white_rate.N_deg_per_sqrt_h"] = n_deg_per_sqrt_h;
  values[kGyroX + "terms.white_rate.N_deg_per_sqrt_h_sigma"] = 0.01 * n_deg_per_sqrt_h;
  if (std::isfinite(b_deg_h)) {
    values[kGyroX + "terms.bias_instability.B_rad_s"] = b_deg_h * units::kDegPerHour_rad_s;
    values[kGyroX + "terms.bias_instability.B_rad_s_sigma"] = 0.1 * b_deg_h * units::kDegPerHour_rad_s;
    values[kGyroX + "terms.bias_instability.B_deg_h"] = b_deg_h;
    values[kGyroX + "terms.bias_instability.B_deg_h_sigma"] = 0.1 * b_deg_h;
  } else {
    values[kGyroX + "terms.bias_instability.B_rad_s_upper_95"] = 7.0 * units::kDegPerHour_rad_s;
    values[kGyroX + "terms.bias_instability.B_deg_h_upper_95"] = 7.0;
  }
  return values;
}

const rep::LotTerm& find_term(const rep::LotSummary& summary, const std::string& channel, const std::string& term) {
  for (const auto& entry : summary.terms) {
    if (entry.channel == channel && entry.term == term) return entry;
  }
  throw std::runtime_error("no " + channel + " " + term);
}

TEST(Lot, TypicalIsTheMedianAndWorstTheMaximumInTheFieldUnit) {
  // Values in an order where the median is neither the first, the last nor the mean.
  const std::vector<rep::LotUnit> lot = {{"u1", gyro_report(0.30, 2.0)},
                                         {"u2", gyro_report(0.10, 9.0)},
                                         {"u3", gyro_report(0.16, NAN)},
                                         {"u4", gyro_report(0.50, 3.0)},
                                         {"u5", gyro_report(0.20, 1.0)}};
  const rep::LotSummary summary = rep::lot_summary(lot, 0.95);
  EXPECT_EQ(summary.units, (std::vector<std::string>{"u1", "u2", "u3", "u4", "u5"}));
  const rep::LotTerm& n = find_term(summary, "gyro_x", "white_rate");
  EXPECT_EQ(n.parameter, "N_deg_per_sqrt_h");
  EXPECT_EQ(n.field_unit, "deg_per_sqrt_h");
  ASSERT_EQ(n.identified.size(), 5u);
  EXPECT_DOUBLE_EQ(n.typical, 0.20);
  EXPECT_DOUBLE_EQ(n.worst, 0.50);
  EXPECT_DOUBLE_EQ(n.identified[1].sigma, 0.001);
  EXPECT_EQ(n.spread.count, 5u);
  EXPECT_NEAR(n.spread.mean, 0.252, 1e-12);
  EXPECT_TRUE(n.absent_units.empty());

  // B: four units identify it (an even count: the mean of the two middle values), u3 gives a bound.
  const rep::LotTerm& b = find_term(summary, "gyro_x", "bias_instability");
  EXPECT_EQ(b.parameter, "B_deg_h");
  ASSERT_EQ(b.identified.size(), 4u);
  EXPECT_DOUBLE_EQ(b.typical, 2.5);
  EXPECT_DOUBLE_EQ(b.worst, 9.0);
  EXPECT_EQ(b.absent_units, std::vector<std::string>{"u3"});
  EXPECT_DOUBLE_EQ(b.absent_upper_bound_max, 7.0);
  // Channel order, then the order of the term kinds: white rate before bias instability.
  EXPECT_EQ(summary.terms.front().term, "white_rate");

  const std::string csv = rep::lot_csv(summary);
  EXPECT_NE(csv.find("gyro_x,white_rate,N_deg_per_sqrt_h,typical," + imu_lab::format_number(0.2) + ","),
            std::string::npos)
      << csv;
  EXPECT_NE(csv.find("gyro_x,bias_instability,B_deg_h,worst,9,"), std::string::npos) << csv;
  EXPECT_NE(csv.find("gyro_x,bias_instability,B_deg_h,u3,,"), std::string::npos) << csv;
  const std::string page = rep::lot_markdown(summary);
  EXPECT_NE(page.find("| gyro_x | bias_instability | deg_h | 2.5 | 9 |"), std::string::npos) << page;
  EXPECT_NE(page.find("4 of 5 (absent: < 7)"), std::string::npos) << page;
  EXPECT_NE(rep::lot_yaml(summary).find("typical_median: 0.2"), std::string::npos);
}

TEST(Lot, AccelerometerTermsAreInTheirFieldUnits) {
  std::vector<rep::LotUnit> lot;
  for (double n : {0.03, 0.05}) {
    std::map<std::string, double> values;
    values[kAccelZ + "terms.white_rate.N_m_s2_per_sqrt_hz"] = n * units::kMeterPerSecondPerSqrtHour_m_s2_per_sqrt_hz;
    values[kAccelZ + "terms.white_rate.N_m_s2_per_sqrt_hz_sigma"] = 1e-6;
    values[kAccelZ + "terms.white_rate.N_m_s_per_sqrt_h"] = n;
    values[kAccelZ + "terms.white_rate.N_m_s_per_sqrt_h_sigma"] = 1e-3;
    lot.push_back({"unit" + std::to_string(lot.size()), values});
  }
  const rep::LotSummary summary = rep::lot_summary(lot, 0.95);
  const rep::LotTerm& n = find_term(summary, "accel_z", "white_rate");
  EXPECT_EQ(n.parameter, "N_m_s_per_sqrt_h");
  EXPECT_DOUBLE_EQ(n.typical, 0.04);
  EXPECT_DOUBLE_EQ(n.worst, 0.05);
}

TEST(Lot, TheTypicalModelHasTheMajorityTermsAtTheirMedianAmplitude) {
  // B in 2 of 3 units: in the model; a Markov term in 1 of 3: not.
  std::vector<rep::LotUnit> lot = {
      {"a", gyro_report(0.30, 2.0)}, {"b", gyro_report(0.10, 4.0)}, {"c", gyro_report(0.20, NAN)}};
  lot[0].report_values[kGyroX + "terms.markov_1.q_c_T_c_rad_s_per_sqrt_hz"] = 1e-3;
  lot[0].report_values[kGyroX + "terms.markov_1.q_c_T_c_rad_s_per_sqrt_hz_sigma"] = 1e-4;
  lot[0].report_values[kGyroX + "terms.markov_1.q_c_T_c_deg_per_sqrt_h"] = 1e-3 / units::kDegPerSqrtHour_rad_per_sqrt_s;
  lot[0].report_values[kGyroX + "terms.markov_1.q_c_T_c_deg_per_sqrt_h_sigma"] =
      1e-4 / units::kDegPerSqrtHour_rad_per_sqrt_s;
  lot[0].report_values[kGyroX + "terms.markov_1.T_c_s"] = 10.0;
  for (auto& unit : lot) unit.report_values[kGyroX + "front_end.low_pass_corner_hz"] = 40.0;
  lot[1].report_values[kGyroX + "front_end.low_pass_corner_hz"] = 60.0;
  lot[2].report_values[kGyroX + "front_end.low_pass_corner_hz"] = 50.0;
  const auto model = rep::typical_model(lot, "gyro_x");
  ASSERT_EQ(model.terms.size(), 2u);
  EXPECT_EQ(model.terms[0].kind, imu_lab::identify::TermKind::kWhiteRate);
  EXPECT_DOUBLE_EQ(model.terms[0].amplitude, 0.20 * units::kDegPerSqrtHour_rad_per_sqrt_s);
  EXPECT_DOUBLE_EQ(model.terms[0].shape, 50.0);
  EXPECT_EQ(model.terms[1].kind, imu_lab::identify::TermKind::kBiasInstability);
  EXPECT_DOUBLE_EQ(model.terms[1].amplitude, 3.0 * units::kDegPerHour_rad_s);
  EXPECT_EQ(model.output_quantization_density, 0.0);
  // The markov term still appears in the summary, identified by one unit.
  const rep::LotSummary summary = rep::lot_summary(lot, 0.95);
  EXPECT_EQ(find_term(summary, "gyro_x", "markov_1").identified.size(), 1u);
  // The CSV: the model's deviation at tau where white noise dominates, and no model for channels
  // without terms.
  const std::string csv = rep::typical_model_csv(lot, {100.0});
  EXPECT_EQ(csv.substr(0, csv.find('\n')),
            "tau_s,gyro_x_typical_dev_rad_s,gyro_y_typical_dev_rad_s,gyro_z_typical_dev_rad_s,"
            "accel_x_typical_dev_m_s2,accel_y_typical_dev_m_s2,accel_z_typical_dev_m_s2");
  EXPECT_NE(csv.find("\n100,"), std::string::npos) << csv;
  EXPECT_NE(csv.find(",,,,,\n", csv.find("\n100,")), std::string::npos) << csv;
}

TEST(Lot, RefusesTooFewUnitsDuplicateNamesAndEmptyReports) {
  EXPECT_THROW(rep::lot_summary({{"a", gyro_report(0.1, 1.0)}}, 0.95), std::invalid_argument);
  EXPECT_THROW(rep::lot_summary({{"a", gyro_report(0.1, 1.0)}, {"a", gyro_report(0.2, 1.0)}}, 0.95),
               std::invalid_argument);
  EXPECT_THROW(rep::lot_summary({{"a", gyro_report(0.1, 1.0)}, {"b", {}}}, 0.95), std::invalid_argument);
  EXPECT_THROW(rep::median_of({}), std::invalid_argument);
}

}  // namespace
