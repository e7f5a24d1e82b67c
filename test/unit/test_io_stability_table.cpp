#include "imu_lab/io/stability_table.h"

#include <gtest/gtest.h>

namespace {

using imu_lab::allan::StabilityPoint;
using imu_lab::io::ChannelCurve;

StabilityPoint point(int m, double deviation) {
  StabilityPoint p;
  p.averaging_factor = m;
  p.tau_s = 0.005 * m;
  p.term_count = 1000 - m;
  p.alpha = -1;
  p.edf = 123.25;
  p.deviation = deviation;
  p.deviation_lower = deviation * 0.9;
  p.deviation_upper = deviation * 1.1 + 1e-17;
  return p;
}

TEST(StabilityTable, RoundTripsEveryFieldExactly) {
  std::vector<ChannelCurve> channels = {{"gyro_x", "rad_s", {point(1, 1.0 / 3.0), point(2, 2.0 / 7.0)}},
                                        {"accel_z", "m_s2", {point(1, 1e-3 / 3.0), point(4, 5e-4)}}};
  const std::string text = imu_lab::io::format_stability_csv(channels);
  EXPECT_EQ(text.substr(0, text.find('\n')),
            "tau_s,m,gyro_x_dev_rad_s,gyro_x_lo_rad_s,gyro_x_hi_rad_s,gyro_x_edf,gyro_x_n,gyro_x_alpha,"
            "accel_z_dev_m_s2,accel_z_lo_m_s2,accel_z_hi_m_s2,accel_z_edf,accel_z_n,accel_z_alpha");
  const auto parsed = imu_lab::io::parse_stability_csv(text);
  ASSERT_EQ(parsed.size(), 2u);
  for (std::size_t c = 0; c < 2; ++c) {
    EXPECT_EQ(parsed[c].name, channels[c].name);
    EXPECT_EQ(parsed[c].unit, channels[c].unit);
    ASSERT_EQ(parsed[c].points.size(), channels[c].points.size());
    for (std::size_t i = 0; i < parsed[c].points.size(); ++i) {
      const auto& a = parsed[c].points[i];
      const auto& b = channels[c].points[i];
      EXPECT_EQ(a.averaging_factor, b.averaging_factor);
      EXPECT_EQ(a.tau_s, b.tau_s);
      EXPECT_EQ(a.deviation, b.deviation);
      EXPECT_EQ(a.deviation_lower, b.deviation_lower);
      EXPECT_EQ(a.deviation_upper, b.deviation_upper);
      EXPECT_EQ(a.edf, b.edf);
      EXPECT_EQ(a.term_count, b.term_count);
      EXPECT_EQ(a.alpha, b.alpha);
    }
  }
}

TEST(StabilityTable, RaggedRowIsRefusedWithItsLineNumber) {
  const std::string text = "tau_s,m,g_dev_u,g_lo_u,g_hi_u,g_edf,g_n,g_alpha\n1,1,1,1,1,1,1,0\n2,2,1\n";
  try {
    imu_lab::io::parse_stability_csv(text);
    FAIL();
  } catch (const std::invalid_argument& error) {
    EXPECT_NE(std::string(error.what()).find("line 3"), std::string::npos) << error.what();
  }
}

}  // namespace
