// The tools' terminal progress line: fraction, counts and the ETA from the average rate so far.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>

#include "imu_lab/common/progress.h"

namespace imu_lab {
namespace {

TEST(CommonProgress, EtaTextBySize) {
  EXPECT_EQ(format_eta(0.0), "0 s");
  EXPECT_EQ(format_eta(42.4), "42 s");
  EXPECT_EQ(format_eta(99.4), "99 s");
  EXPECT_EQ(format_eta(100.0), "1 min 40 s");
  EXPECT_EQ(format_eta(725.0), "12 min 05 s");
  EXPECT_EQ(format_eta(7199.0), "119 min 59 s");
  EXPECT_EQ(format_eta(3.4 * 3600.0), "3.4 h");
  EXPECT_EQ(format_eta(NAN), "?");
  EXPECT_EQ(format_eta(-1.0), "?");
}

TEST(CommonProgress, LineHasTheFractionCountsAndEta) {
  // A quarter done in 30 s: three quarters left at the same rate take 90 s.
  EXPECT_EQ(progress_line("navigate", 2500, 10000, "messages", 30.0),
            "navigate: [#######                       ]  25.0 % 2500/10000 messages, ETA 90 s");
  // Half done in 10 min: 10 min left.
  EXPECT_EQ(progress_line("emulate", 50, 100, "samples", 600.0),
            "emulate: [###############               ]  50.0 % 50/100 samples, ETA 10 min 00 s");
  EXPECT_EQ(progress_line("correct", 10, 10, "messages", 5.0),
            "correct: [##############################] 100.0 % 10/10 messages, ETA 0 s");
  // Nothing done: no rate, no ETA; more than the total (a short count) reads as done.
  EXPECT_EQ(progress_line("fit_thermal", 0, 10, "messages", 5.0),
            "fit_thermal: [                              ]   0.0 % 0/10 messages, ETA ?");
  // The first message, read right after opening the bag, is no rate.
  EXPECT_EQ(progress_line("navigate", 1, 120000, "messages", 0.002),
            "navigate: [                              ]   0.0 % 1/120000 messages, ETA ?");
  EXPECT_EQ(progress_line("allan", 12, 10, "messages", 5.0),
            "allan: [##############################] 100.0 % 12/10 messages, ETA 0 s");
}

TEST(CommonProgress, NoBarWhenStderrIsNotATerminal) {
  // The test runner's stderr is a pipe or a file under scripts/test and CI; forced draws anyway.
  if (!::isatty(2)) {
    EXPECT_FALSE(terminal_progress("allan", "messages"));
  }
  EXPECT_TRUE(terminal_progress("allan", "messages", true));
}

}  // namespace
}  // namespace imu_lab
