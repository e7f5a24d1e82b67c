// The record length the fit says it needs, from the Fisher information of the octave points.
#include <gtest/gtest.h>

#include <cmath>

#include "imu_lab/identify/record_length.h"

namespace imu_lab {
namespace identify {
namespace {

TEST(IdentifyRecordLength, WhiteNoiseSigmaFallsAsOneOverRootLength) {
  ModelStructure structure;
  structure.slots = {{TermKind::kWhiteRate, false, 0.0}};
  const std::vector<double> log_parameters = {std::log(1e-4)};
  const double one_hour = predicted_relative_sigma(structure, log_parameters, 0, 0.01, 3600.0);
  const double four_hours = predicted_relative_sigma(structure, log_parameters, 0, 0.01, 14400.0);
  EXPECT_NEAR(one_hour / four_hours, 2.0, 0.05);
  // Dominated by the shortest taus, whose EDF is ~1.5 x the sample count.
  EXPECT_LT(one_hour, 1e-2);
}

TEST(IdentifyRecordLength, RequiredLengthReachesTheTarget) {
  ModelStructure structure;
  structure.slots = {{TermKind::kWhiteRate, false, 0.0},
                     {TermKind::kBiasInstability, false, 0.5},
                     {TermKind::kRandomWalk, false, 0.0}};
  const std::vector<double> log_parameters = {std::log(2.9e-7), std::log(7.8e-9), std::log(1e-9)};
  const double needed = required_record_length_s(structure, log_parameters, 1, 1.0, 3600.0, 0.15);
  ASSERT_TRUE(std::isfinite(needed));
  EXPECT_NEAR(predicted_relative_sigma(structure, log_parameters, 1, 1.0, needed), 0.15, 0.01);
  EXPECT_GT(predicted_relative_sigma(structure, log_parameters, 1, 1.0, 0.8 * needed), 0.15);
}

}  // namespace
}  // namespace identify
}  // namespace imu_lab
