// What the estimator refuses, and that it says why: too few rests (with the number still needed),
// a schedule that leaves parameters unobservable (named), no rests at all, and a schedule that
// does not match the recording.
#include <gtest/gtest.h>

#include "calib_test_support.h"
#include "imu_lab/common/config_error.h"
#include "imu_lab/common/stamps.h"

namespace imu_lab {
namespace {

using calib_test::kDeg;

calib_test::Attitudes from_roll_pitch_yaw(const std::vector<std::array<double, 3>>& degrees) {
  calib_test::Attitudes attitudes;
  for (const auto& rpy : degrees) {
    attitudes.push_back(emulator::attitude_from_roll_pitch_yaw(rpy[0] * kDeg, rpy[1] * kDeg, rpy[2] * kDeg));
  }
  return attitudes;
}

calib_test::TableRun short_run() {
  calib_test::TableRun run;
  run.dwell_s = 4.0;
  run.rate_hz = 100.0;
  return run;
}

std::string refusal(const std::vector<io::ImuRecord>& samples, const calib::CalibrationOptions& options) {
  try {
    calib::calibrate(samples, options);
  } catch (const InputError& error) {
    return error.what();
  }
  return "(accepted)";
}

TEST(CalibRefusals, TooFewKnownPositionsSaysHowManyMore) {
  const auto run = calib_test::emulate_table_run(
      calib_test::tactical_test_profile(), from_roll_pitch_yaw({{0, 0, 0}, {0, -90, 0}, {90, 0, 0}}), short_run());
  calib::CalibrationOptions options;
  options.schedule = run.schedule;
  const std::string message = refusal(run.samples, options);
  EXPECT_NE(message.find("3 static positions"), std::string::npos) << message;
  EXPECT_NE(message.find("at least 4: record 1 more position"), std::string::npos) << message;
}

TEST(CalibRefusals, UnknownOrientationsNeedNineRests) {
  const auto run = calib_test::emulate_table_run(calib_test::tactical_test_profile(),
                                                 calib_test::shipped_positions("multiposition_6.yaml"), short_run());
  calib::CalibrationOptions options;
  options.site = run.schedule.site;
  const std::string message = refusal(run.samples, options);
  EXPECT_NE(message.find("unknown orientations needs at least 9: record 3 more positions"), std::string::npos)
      << message;
}

TEST(CalibRefusals, RankDeficientScheduleNamesWhatItCannotObserve) {
  // Always z up: gravity never excites the accelerometers' x and y inputs.
  const auto run = calib_test::emulate_table_run(calib_test::tactical_test_profile(),
                                                 from_roll_pitch_yaw({{0, 0, 0}, {0, 0, 90}, {0, 0, 180}, {0, 0, 270}}),
                                                 short_run());
  calib::CalibrationOptions options;
  options.schedule = run.schedule;
  const std::string message = refusal(run.samples, options);
  EXPECT_NE(message.find("cannot observe"), std::string::npos) << message;
  EXPECT_NE(message.find("accelerometer.K.xx"), std::string::npos) << message;
  // A constant z input cannot be told from a bias either.
  EXPECT_NE(message.find("accelerometer.bias.x"), std::string::npos) << message;
}

TEST(CalibRefusals, NoStaticIntervalsInAContinuousRotation) {
  emulator::ScenarioConfig scenario;
  scenario.type = "rate_table";
  scenario.latitude_rad = 50.0 * kDeg;
  emulator::RateTableConfig table;
  table.acceleration_rad_s2 = 20.0 * kDeg;
  table.steps = {{10.0 * kDeg, 60.0}};
  scenario.rate_table = table;
  emulator::EmulatorSettings settings;
  settings.rate_hz = 100.0;
  emulator::ImuEmulator imu(calib_test::tactical_test_profile(), scenario, settings);
  std::vector<io::ImuRecord> samples;
  imu.next();  // the table starts at rest: skip past the first instant
  for (int k = 0; k < 3000; ++k) {
    const auto sample = imu.next();
    if (sample.stamp_ns > kNanosecondsPerSecond) samples.push_back(emulator::to_imu_record(sample));
  }
  calib::CalibrationOptions options;
  options.site.latitude_rad = scenario.latitude_rad;
  const std::string message = refusal(samples, options);
  std::printf("%s\n", message.c_str());
  EXPECT_NE(message.find("no static intervals found"), std::string::npos) << message;
  EXPECT_NE(message.find("threshold"), std::string::npos) << message;
}

TEST(CalibRefusals, ScheduleThatDoesNotMatchTheRecording) {
  const auto run = calib_test::emulate_table_run(
      calib_test::tactical_test_profile(), calib_test::shipped_positions("multiposition_12_thesis.yaml"), short_run());
  calib::CalibrationOptions options;
  options.schedule =
      calib::schedule_from_scenario(emulator::load_scenario(test::config_path("scenarios/multiposition_6.yaml")));
  const std::string message = refusal(run.samples, options);
  EXPECT_NE(message.find("found 12 static intervals but the schedule"), std::string::npos) << message;
  EXPECT_NE(message.find("has 6 positions"), std::string::npos) << message;
}

}  // namespace
}  // namespace imu_lab
