// common/stamps.h: integer-nanosecond stamps, their seconds, and their exact text.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <string>

#include "imu_lab/common/config_error.h"
#include "imu_lab/common/stamps.h"

namespace imu_lab {
namespace {

TEST(CommonStamps, SecondsRoundToTheNearestNanosecondFromTheWholeSecond) {
  EXPECT_EQ(stamp_ns_from_seconds(0.0), 0);
  EXPECT_EQ(stamp_ns_from_seconds(0.005), 5000000);
  EXPECT_EQ(stamp_ns_from_seconds(1.0 / 3.0), 333333333);
  EXPECT_EQ(stamp_ns_from_seconds(2.0 / 3.0), 666666667);
  EXPECT_EQ(stamp_ns_from_seconds(-2.5), -2500000000);
  EXPECT_EQ(stamp_ns_from_seconds(-1e-10), 0);
  // 1.7e9 + 1/3 s: the fraction is rounded on its own, not after the product with 1e9, which
  // would lose ~100 ns to the double's 53 bits (1.7e18 ns > 2^53).
  const double stamp_s = 1.7e9 + 1.0 / 3.0;
  const double fraction_s = stamp_s - 1.7e9;  // exact: both are near 1.7e9
  EXPECT_EQ(stamp_ns_from_seconds(stamp_s), 1700000000 * kNanosecondsPerSecond + std::llround(fraction_s * 1e9));
  EXPECT_NE(stamp_ns_from_seconds(stamp_s), std::llround(stamp_s * 1e9));
}

TEST(CommonStamps, SecondsOfAStampAreItsWholeSecondsPlusItsNanoseconds) {
  EXPECT_EQ(seconds_from_stamp_ns(1700000000123456789), 1700000000.0 + 1e-9 * 123456789.0);
  EXPECT_EQ(seconds_from_stamp_ns(-1), -1e-9);
  EXPECT_EQ(seconds_from_stamp_ns(-2500000000), -2.5);
  EXPECT_EQ(seconds_between(1700000000000000000, 1700000000000000001), 1e-9);
  EXPECT_EQ(seconds_between(1700000000000000001, 1700000000000000000), -1e-9);
}

TEST(CommonStamps, TextIsExactAndReadsBack) {
  EXPECT_EQ(format_stamp_s(0), "0.000000000");
  EXPECT_EQ(format_stamp_s(-2500000000), "-2.500000000");
  EXPECT_EQ(format_stamp_s(1700000000000000001), "1700000000.000000001");
  EXPECT_EQ(format_stamp_s(std::numeric_limits<std::int64_t>::min()), "-9223372036.854775808");
  for (const std::int64_t stamp_ns : {std::int64_t{0}, std::int64_t{-1}, std::int64_t{1700000000123456789},
                                      std::int64_t{-42000000007}, std::int64_t{9223372035999999999}}) {
    EXPECT_EQ(parse_stamp_s(format_stamp_s(stamp_ns)), stamp_ns) << stamp_ns;
  }
  EXPECT_EQ(parse_stamp_s("12"), 12 * kNanosecondsPerSecond);
  EXPECT_EQ(parse_stamp_s("12.5"), 12500000000);
}

TEST(CommonStamps, TextThatIsNotAStampIsRefusedNamingIt) {
  for (const std::string text :
       {"", "-", ".5", "1.2.3", "1.1234567891", "1e9", "abc", " 1", "9223372036.0", "99999999999999999999"}) {
    try {
      parse_stamp_s(text);
      ADD_FAILURE() << "accepted '" << text << "'";
    } catch (const InputError& error) {
      EXPECT_NE(std::string(error.what()).find("'" + text + "'"), std::string::npos) << error.what();
    }
  }
}

}  // namespace
}  // namespace imu_lab
