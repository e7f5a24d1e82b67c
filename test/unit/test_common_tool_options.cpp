// The tools' shared command-line parsing (common/tool_options.h) and refusal (common/tool_main.h):
// every option error exits 2 with one line naming the option, never CLI11's own codes; numeric
// options are finite and in range; every refusal of bad data names the input.
#include <gtest/gtest.h>

#include <algorithm>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <tuple>
#include <vector>

#include "imu_lab/common/config_error.h"
#include "imu_lab/common/tool_main.h"
#include "imu_lab/common/tool_options.h"

namespace {

struct Parsed {
  std::optional<int> status;
  std::string error_output;
};

// A small tool's options: a positional bag, a rate, a count and a latitude.
struct ToyTool {
  CLI::App app{"toy"};
  std::string bag;
  double rate_hz = 200.0;
  std::size_t count = 3;
  double latitude_deg = 0.0;
  std::vector<double> taus_s;
  ToyTool() {
    app.add_option("bag", bag)->required();
    app.add_option("--rate-hz", rate_hz)->check(imu_lab::option_range::positive());
    app.add_option("--count", count);
    app.add_option("--latitude-deg", latitude_deg)->check(imu_lab::option_range::latitude_deg());
    app.add_option("--taus-s", taus_s)->check(imu_lab::option_range::positive());
  }
  Parsed parse(std::vector<std::string> arguments) {
    arguments.insert(arguments.begin(), "toy");
    std::vector<char*> argv;
    for (std::string& argument : arguments) argv.push_back(argument.data());
    testing::internal::CaptureStderr();
    Parsed parsed;
    parsed.status = imu_lab::parse_tool_options("toy", app, static_cast<int>(argv.size()), argv.data());
    parsed.error_output = testing::internal::GetCapturedStderr();
    return parsed;
  }
};

void expect_refused(std::vector<std::string> arguments, const std::string& words) {
  ToyTool tool;
  const Parsed parsed = tool.parse(arguments);
  ASSERT_TRUE(parsed.status.has_value()) << words;
  EXPECT_EQ(*parsed.status, 2) << parsed.error_output;
  EXPECT_EQ(parsed.error_output.rfind("toy: bad configuration: ", 0), 0u) << parsed.error_output;
  EXPECT_NE(parsed.error_output.find(words), std::string::npos) << parsed.error_output;
  EXPECT_EQ(std::count(parsed.error_output.begin(), parsed.error_output.end(), '\n'), 1) << "one line";
}

TEST(ToolOptions, GoodOptionsParse) {
  ToyTool tool;
  const Parsed parsed = tool.parse({"x.bag", "--rate-hz", "100", "--count", "5", "--latitude-deg", "-45.5"});
  EXPECT_FALSE(parsed.status.has_value()) << parsed.error_output;
  EXPECT_EQ(tool.rate_hz, 100.0);
  EXPECT_EQ(tool.count, 5u);
}

// CLI11 itself would exit 105 (no arguments: 106, an unknown option: 109); the tools document 2.
TEST(ToolOptions, ParserErrorsExitTwoNamingTheProblem) {
  expect_refused({}, "bag is required");
  expect_refused({"x.bag", "--no-such-option"}, "--no-such-option");
  expect_refused({"x.bag", "--count", "many"}, "--count");
  expect_refused({"x.bag", "--rate-hz"}, "--rate-hz");
}

TEST(ToolOptions, NonFiniteNumbersAreRefusedForEveryNumericOption) {
  expect_refused({"x.bag", "--rate-hz", "nan"}, "--rate-hz");
  expect_refused({"x.bag", "--latitude-deg", "inf"}, "--latitude-deg");
  expect_refused({"x.bag", "--taus-s", "1", "nan"}, "--taus-s");
}

TEST(ToolOptions, RangesAreCheckedAndAnUnsignedOptionIsNotWrappedAround) {
  expect_refused({"x.bag", "--rate-hz", "-5"}, "--rate-hz: must be > 0, got -5");
  expect_refused({"x.bag", "--rate-hz", "0"}, "must be > 0");
  expect_refused({"x.bag", "--latitude-deg", "95"}, "--latitude-deg: must be in [-90, 90], got 95");
  expect_refused({"x.bag", "--taus-s", "-1"}, "--taus-s: must be > 0, got -1");
  expect_refused({"x.bag", "--count", "-1"}, "--count: must not be negative");  // CLI11 made it 2^64 - 1
}

TEST(ToolOptions, HelpExitsZero) {
  ToyTool tool;
  testing::internal::CaptureStdout();
  const Parsed parsed = tool.parse({"--help"});
  const std::string help = testing::internal::GetCapturedStdout();
  ASSERT_TRUE(parsed.status.has_value());
  EXPECT_EQ(*parsed.status, 0);
  EXPECT_NE(help.find("--rate-hz"), std::string::npos);
}

// An error from deep in a computation names the input it came from, once.
TEST(ToolMain, EveryRefusalOfBadDataNamesTheInput) {
  imu_lab::ToolInput input{"bag", "/data/x.bag", ""};
  const auto run = [&](const std::function<void()>& body) {
    testing::internal::CaptureStderr();
    const int status = imu_lab::run_tool_main("toy", input, [&] {
      body();
      return 0;
    });
    return std::make_pair(status, testing::internal::GetCapturedStderr());
  };
  input.topic = "/imu/raw";
  auto [status, output] = run([] { throw imu_lab::InputError("no static intervals found"); });
  EXPECT_EQ(status, 1);
  EXPECT_EQ(output, "toy: bag /data/x.bag, topic /imu/raw: no static intervals found\n");
  std::tie(status, output) = run([] { throw std::invalid_argument("greenhall_edf: alpha = 7"); });
  EXPECT_EQ(output, "toy: bag /data/x.bag, topic /imu/raw: greenhall_edf: alpha = 7\n");
  std::tie(status, output) = run([] { throw imu_lab::InputError("bag /data/x.bag: too few messages"); });
  EXPECT_EQ(output, "toy: bag /data/x.bag: too few messages\n") << "named once";
  // Configuration names its key, and a file that could not be written its path: not the input.
  std::tie(status, output) = run([] { throw imu_lab::ConfigError("--schedule", "schedule", "no such file"); });
  EXPECT_EQ(status, 2);
  EXPECT_EQ(output, "toy: bad configuration: --schedule: schedule: no such file\n");
  std::tie(status, output) = run([] { throw imu_lab::OutputError("cannot write out.yaml: No space left on device"); });
  EXPECT_EQ(status, 1);
  EXPECT_EQ(output, "toy: cannot write out.yaml: No space left on device\n");
}

}  // namespace
