// The bad-input matrix across the bag-reading tools: every tool (allan, bag_summary, fit_thermal,
// fit_calibration, navigate, correct, rate_table, spectrum) given an empty, truncated, garbage or
// missing bag, a bag with several IMU topics, a wrong topic or a topic of the wrong type exits 1
// with a message naming the bag (and what to do), and writes nothing. Tools that cannot use NaN/Inf samples or
// unordered stamps refuse them the same way, naming the bag and the topic (allan and navigate
// have their own policies: test_allan_tool_bad_input.cpp, test_navigate_tool.cpp).
#include <gtest/gtest.h>

#include <fstream>
#include <limits>
#include <string>
#include <vector>

#include "allan_test_support.h"
#include "ros_test_support.h"

namespace {

using namespace imu_lab::test_support;  // NOLINT: the scratch, bag and tool helpers

constexpr std::int64_t kInterval_ns = 10'000'000;  // 100 Hz
constexpr std::size_t kCount = 3000;

// How each tool is run; the output goes into `out_directory`, which must stay empty on failure.
struct Tool {
  const char* name;
  std::string arguments(const std::string& bag, const std::string& out_directory) const {
    const std::string tool = name;
    if (tool == "allan") return bag + " --no-plot --out " + out_directory + "/report";
    if (tool == "bag_summary") return bag;
    if (tool == "fit_thermal") return bag + " --no-scale-factor --out " + out_directory + "/model.yaml";
    if (tool == "fit_calibration") {
      return bag + " --latitude-deg 50 --height-m 0 --out " + out_directory + "/calibration.yaml";
    }
    if (tool == "rate_table") return bag + " --scenario rate_table_scale_factor --out " + out_directory + "/report";
    if (tool == "spectrum") return bag + " --segment-length 256 --no-plot --out " + out_directory + "/report";
    if (tool == "correct") {
      return bag + " --calibration " + std::string(IMU_LAB_TEST_DATA_DIR) + "/calibration_example.yaml --out " +
             out_directory + "/corrected.bag";
    }
    return bag + " --latitude-deg 50 --longitude-deg 10 --height-m 0 --alignment-duration-s 10 --out " + out_directory +
           "/trajectory.csv";
  }
};

const std::vector<Tool> kTools = {{"allan"},    {"bag_summary"}, {"fit_thermal"}, {"fit_calibration"},
                                  {"navigate"}, {"correct"},     {"rate_table"},  {"spectrum"}};

// A scratch directory with inputs, and an empty one for the tools' output.
struct Scratch {
  std::string inputs = scratch_directory();
  std::string outputs = scratch_directory();

  std::string good_bag(const std::string& name, const ImuBagLayout& layout = with_temperature()) const {
    const std::string bag = inputs + "/" + name;
    write_imu_bag(bag, white_noise_samples(kCount, kInterval_ns, 1), layout);
    return bag;
  }
  static ImuBagLayout with_temperature() {
    ImuBagLayout layout;
    layout.with_temperature = true;
    return layout;
  }
};

// Exit 1, the words in the message, nothing written.
void expect_refused(const Tool& tool, const Scratch& scratch, const std::string& arguments,
                    const std::vector<std::string>& words) {
  const CommandResult result = run_tool(tool.name, arguments);
  EXPECT_EQ(result.exit_code, 1) << tool.name << " " << arguments << "\n" << result.output;
  for (const std::string& word : words) {
    EXPECT_NE(result.output.find(word), std::string::npos) << tool.name << ": no '" << word << "' in\n"
                                                           << result.output;
  }
  EXPECT_EQ(list_directory(scratch.outputs), std::vector<std::string>{}) << tool.name << " left a partial output";
}

class ToolsBadBag : public ::testing::TestWithParam<Tool> {
 protected:
  Scratch scratch;
  std::string arguments(const std::string& bag) const { return GetParam().arguments(bag, scratch.outputs); }
};

TEST_P(ToolsBadBag, EmptyBag) {
  const std::string bag = scratch.inputs + "/empty.bag";
  write_imu_bag(bag, {});
  expect_refused(GetParam(), scratch, arguments(bag), {bag, "no sensor_msgs/Imu topic"});
}

TEST_P(ToolsBadBag, TruncatedBag) {
  const std::string bag =
      imu_lab::test_support::write_truncated_copy(scratch.good_bag("whole.bag"), scratch.inputs + "/cut.bag", 0.5);
  expect_refused(GetParam(), scratch, arguments(bag), {bag});
}

TEST_P(ToolsBadBag, GarbageAndMissingFiles) {
  const std::string garbage = scratch.inputs + "/garbage.bag";
  std::ofstream(garbage) << "this is not a bag\n";
  expect_refused(GetParam(), scratch, arguments(garbage), {"cannot read bag " + garbage});
  const std::string missing = scratch.inputs + "/missing.bag";
  expect_refused(GetParam(), scratch, arguments(missing), {"cannot read bag " + missing});
}

TEST_P(ToolsBadBag, SeveralImuTopicsAskForTopic) {
  ImuBagLayout layout = Scratch::with_temperature();
  layout.imu_topics = {"/imu/a", "/imu/b"};
  const std::string bag = scratch.good_bag("two_imus.bag", layout);
  expect_refused(GetParam(), scratch, arguments(bag), {bag, "/imu/a", "/imu/b", "--topic"});
}

TEST_P(ToolsBadBag, WrongTopicListsTheTopicsThatExist) {
  const std::string bag = scratch.good_bag("one_imu.bag");
  expect_refused(GetParam(), scratch, arguments(bag) + " --topic /imu/nothing", {bag, "/imu/nothing", "/imu/raw"});
}

TEST_P(ToolsBadBag, TopicOfAnotherTypeIsNamed) {
  const std::string bag = scratch.good_bag("one_imu.bag");
  expect_refused(GetParam(), scratch, arguments(bag) + " --topic /imu/temperature", {bag, "sensor_msgs/Temperature"});
}

INSTANTIATE_TEST_SUITE_P(Matrix, ToolsBadBag, ::testing::ValuesIn(kTools),
                         [](const ::testing::TestParamInfo<Tool>& info) { return std::string(info.param.name); });

// bag_summary, fit_thermal, fit_calibration, rate_table and spectrum average or fit every sample,
// and correct would pass a NaN/Inf sample or an unordered stamp on into the corrected bag: they
// refuse the bag.
class StrictTools : public ToolsBadBag {};

TEST_P(StrictTools, NanSamplesAreRefusedNamingTheTopic) {
  auto samples = white_noise_samples(kCount, kInterval_ns, 2);
  samples[1234].values[1] = std::numeric_limits<double>::quiet_NaN();
  samples[2345].values[4] = std::numeric_limits<double>::infinity();
  const std::string bag = scratch.inputs + "/nan.bag";
  write_imu_bag(bag, samples, Scratch::with_temperature());
  expect_refused(GetParam(), scratch, arguments(bag), {bag, "/imu/raw", "2 samples with NaN/Inf"});
}

TEST_P(StrictTools, UnorderedStampsAreRefusedNamingTheTopic) {
  auto samples = white_noise_samples(kCount, kInterval_ns, 3);
  std::swap(samples[1500], samples[1501]);
  samples.insert(samples.begin() + 2000, samples[1999]);
  const std::string bag = scratch.inputs + "/unordered.bag";
  write_imu_bag(bag, samples, Scratch::with_temperature());
  expect_refused(GetParam(), scratch, arguments(bag), {bag, "/imu/raw", "2 stamps not after the previous one"});
}

INSTANTIATE_TEST_SUITE_P(Matrix, StrictTools,
                         ::testing::Values(Tool{"bag_summary"}, Tool{"fit_thermal"}, Tool{"fit_calibration"},
                                           Tool{"correct"}, Tool{"rate_table"}, Tool{"spectrum"}),
                         [](const ::testing::TestParamInfo<Tool>& info) { return std::string(info.param.name); });

// Samples at 100 Hz, from `from` on at `interval_ns` (a rate change) or shifted by `shift_ns` (a gap).
std::string irregular_bag(const Scratch& scratch, std::size_t from, std::int64_t interval_ns, std::int64_t shift_ns) {
  auto samples = white_noise_samples(kCount, kInterval_ns, 4);
  for (std::size_t i = from; i < kCount; ++i) {
    samples[i].stamp_ns = samples[from - 1].stamp_ns + static_cast<std::int64_t>(i - from + 1) * interval_ns + shift_ns;
  }
  const std::string bag = scratch.inputs + "/irregular.bag";
  write_imu_bag(bag, samples);
  return bag;
}

// bag_summary writes nothing and its mean and deviation stay right; it takes the median interval
// as the sample period and warns that the Allan deviation assumes even spacing.
TEST(BagSummaryIrregularStamps, AGapOrARateChangeIsWarnedAbout) {
  const Scratch scratch;
  const CommandResult gap = run_tool("bag_summary", irregular_bag(scratch, 2000, kInterval_ns, 500'000'000));
  EXPECT_EQ(gap.exit_code, 0) << gap.output;
  EXPECT_NE(gap.output.find("rate 100.0000 Hz (median interval)"), std::string::npos) << gap.output;
  EXPECT_NE(gap.output.find("1 intervals off the sample period by over a factor 1.5 (0.01 .. 0.51 s)"),
            std::string::npos)
      << gap.output;
  const CommandResult slower = run_tool("bag_summary", irregular_bag(scratch, 2000, 2 * kInterval_ns, 0));
  EXPECT_EQ(slower.exit_code, 0) << slower.output;
  EXPECT_NE(slower.output.find("1000 intervals off the sample period"), std::string::npos) << slower.output;
}

// The allan tool fixes tau0 in its warm-up: after a rate halving every interval is a gap, which
// it counts and pools around (or stops at, with --on-gap stop).
TEST(AllanToolRateChange, ASlowerRateIsCountedAsGapsOrStopsTheRun) {
  const Scratch scratch;
  const std::string bag = irregular_bag(scratch, 2000, 2 * kInterval_ns, 0);
  const CommandResult pooled = run_tool("allan", bag + " --no-plot --out " + scratch.outputs + "/report");
  EXPECT_EQ(pooled.exit_code, 0) << pooled.output;
  EXPECT_NE(pooled.output.find("1000 gaps"), std::string::npos) << pooled.output;
  const CommandResult stopped =
      run_tool("allan", bag + " --no-plot --on-gap stop --out " + scratch.outputs + "/stopped");
  EXPECT_EQ(stopped.exit_code, 1) << stopped.output;
  EXPECT_NE(stopped.output.find(bag), std::string::npos) << stopped.output;
  EXPECT_FALSE(file_exists(scratch.outputs + "/stopped"));
}

// A spectrum needs uniform sampling: spectrum refuses a gap, naming the bag, where it is and how
// to leave it out, and writes nothing.
TEST(SpectrumGap, AGapIsRefusedNamingWhereItIs) {
  const Scratch scratch;
  const std::string bag = irregular_bag(scratch, 2000, kInterval_ns, 500'000'000);
  expect_refused(Tool{"spectrum"}, scratch, Tool{"spectrum"}.arguments(bag, scratch.outputs),
                 {bag, "interval 0.51 s at 20.5 s after the first stamp", "--start-s"});
}

}  // namespace
