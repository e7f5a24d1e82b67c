// pipeline::recorded_attitude_motion: the attitude a recording's gyro rates describe, on the
// prediction's uniform grid. At the pole a body turning about Up measures a constant rate (its own
// plus the Earth's, both about Up), so the motion must be constant_rate_scenario_motion's exactly,
// whatever the stamps' jitter; bad stamps are refused naming where.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "imu_lab/common/earth_constants.h"
#include "imu_lab/common/stamps.h"
#include "imu_lab/pipeline/attitude_error_budget.h"

namespace imu_lab {
namespace {

constexpr std::int64_t kStart_ns = 1'700'000'000'000'000'000;

emulator::ScenarioConfig polar_site() {
  emulator::ScenarioConfig site;
  site.latitude_rad = M_PI / 2.0;
  site.roll_rad = 0.1;
  site.pitch_rad = -0.2;
  site.yaw_rad = 0.3;
  return site;
}

// Records every ~interval_ns (jittered by up to +-jitter_ns) of a body turning about its z axis
// at body_rate relative to ENU: with roll and pitch the body's z is not Up, so the Earth rate
// seen in the body changes as it turns; its interval average is taken exactly.
std::vector<io::ImuRecord> turning_records(double body_rate_rad_s, std::int64_t interval_ns, std::int64_t jitter_ns,
                                           int count) {
  std::mt19937_64 random(7);
  std::uniform_int_distribution<std::int64_t> jitter(-jitter_ns, jitter_ns);
  const emulator::ScenarioConfig site = polar_site();
  std::vector<io::ImuRecord> records;
  std::int64_t stamp_ns = kStart_ns;
  for (int k = 0; k < count; ++k) {
    io::ImuRecord record;
    record.stamp_ns = stamp_ns;
    records.push_back(record);
    stamp_ns += interval_ns + jitter(random);
  }
  // The Earth rate (0, 0, W at the pole) in body axes: R_z(w t)' C_start' (0, 0, W), averaged over
  // each interval in closed form.
  const Eigen::Matrix3d start = (Eigen::AngleAxisd(site.yaw_rad, Eigen::Vector3d::UnitZ()) *
                                 Eigen::AngleAxisd(site.pitch_rad, Eigen::Vector3d::UnitY()) *
                                 Eigen::AngleAxisd(site.roll_rad, Eigen::Vector3d::UnitX()))
                                    .toRotationMatrix();
  const Eigen::Vector3d earth_in_start = start.transpose() * Eigen::Vector3d(0.0, 0.0, wgs84::kEarthRate_rad_s);
  const double w = body_rate_rad_s;
  for (std::size_t i = 1; i < records.size(); ++i) {
    const double t0 = seconds_between(kStart_ns, records[i - 1].stamp_ns);
    const double t1 = seconds_between(kStart_ns, records[i].stamp_ns);
    // average over [t0, t1] of R_z(w t)' e: x = e_x cos + e_y sin, y = -e_x sin + e_y cos.
    const double c = (std::sin(w * t1) - std::sin(w * t0)) / (w * (t1 - t0));
    const double s = (std::cos(w * t0) - std::cos(w * t1)) / (w * (t1 - t0));
    records[i].angular_rate_rad_s =
        Eigen::Vector3d(earth_in_start.x() * c + earth_in_start.y() * s,
                        -earth_in_start.x() * s + earth_in_start.y() * c, earth_in_start.z() + w);
  }
  records.front().angular_rate_rad_s = records[1].angular_rate_rad_s;
  return records;
}

TEST(PipelineRecordedAttitudeMotion, EqualsTheConstantRateMotionWhateverTheJitter) {
  const double rate_rad_s = 0.5;
  const auto records = turning_records(rate_rad_s, 10'000'000, 2'000'000, 2001);  // ~20 s at 100 Hz
  const auto motion = pipeline::recorded_attitude_motion(records, polar_site(), 15.0, 0.02);
  const auto expected =
      pipeline::constant_rate_scenario_motion(polar_site(), Eigen::Vector3d(0.0, 0.0, rate_rad_s), 15.0, 0.02);
  ASSERT_EQ(motion.size(), expected.size());
  double worst_rad = 0.0;
  for (std::size_t k = 0; k < motion.size(); ++k) {
    EXPECT_NEAR(motion[k].time_s, expected[k].time_s, 1e-12);
    worst_rad = std::max(worst_rad, motion[k].body_to_navigation.angularDistance(expected[k].body_to_navigation));
    EXPECT_NEAR((motion[k].navigation_rate_rad_s - expected[k].navigation_rate_rad_s).norm(), 0.0, 1e-18);
  }
  // The Earth rate is taken out with the attitude at mid-interval: W w^2 dt^3 ~ 2e-11 rad per
  // step (with the attitude at the interval's start it was W w dt^2 ~ 4e-9, and 5e-7 rad after
  // 15 s: this check failed).
  EXPECT_LT(worst_rad, 1e-9);
}

TEST(PipelineRecordedAttitudeMotion, DefaultDurationIsTheWholeGridTheRecordsCover) {
  const auto records = turning_records(0.1, 10'000'000, 0, 1001);  // exactly 10 s
  const auto motion = pipeline::recorded_attitude_motion(records, polar_site(), 0.0, 0.03);
  EXPECT_NEAR(motion.back().time_s, 9.99, 1e-9);  // 333 steps of 0.03 s
  EXPECT_EQ(motion.size(), 334u);
}

TEST(PipelineRecordedAttitudeMotion, RefusesBadStampsNamingThem) {
  auto records = turning_records(0.1, 10'000'000, 0, 100);
  const auto expect_refused = [&](const std::vector<io::ImuRecord>& bad, const std::string& word) {
    try {
      pipeline::recorded_attitude_motion(bad, polar_site(), 0.0, 0.01);
      FAIL() << "accepted; expected '" << word << "'";
    } catch (const std::invalid_argument& error) {
      EXPECT_NE(std::string(error.what()).find(word), std::string::npos) << error.what();
    }
  };
  auto repeated = records;
  repeated[50].stamp_ns = repeated[49].stamp_ns;
  expect_refused(repeated, format_stamp_s(repeated[50].stamp_ns));
  auto gap = records;
  for (std::size_t i = 60; i < gap.size(); ++i) gap[i].stamp_ns += 200'000'000;
  expect_refused(gap, "gap in the IMU stamps before " + format_stamp_s(gap[60].stamp_ns));
  expect_refused({records.front()}, "at least two");
  EXPECT_NO_THROW(pipeline::recorded_attitude_motion(records, polar_site(), 0.0, 0.01));
  try {  // 0.99 s of records, 5 s asked
    pipeline::recorded_attitude_motion(records, polar_site(), 5.0, 0.01);
    FAIL() << "a duration beyond the records was accepted";
  } catch (const std::invalid_argument& error) {
    EXPECT_NE(std::string(error.what()).find("exceeds"), std::string::npos) << error.what();
  }
}

}  // namespace
}  // namespace imu_lab
