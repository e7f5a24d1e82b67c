// rostest checker for node_parameters.h (needs a parameter server): a parameter of the wrong type
// or out of range is refused naming the resolved parameter, the expected type and what was given,
// never replaced by the default; an int does for a double. Then the real binaries: each node
// started with a wrong-typed or negative parameter exits with status 2 (no signal, no core) and
// names the parameter, and a nodelet refused by the manager says so on /rosout while the manager
// lives on. Last, each node's parameter template (config/nodes/) against what the node reads.
#include <gtest/gtest.h>
#include <ros/ros.h>
#include <rosgraph_msgs/Log.h>
#include <sys/wait.h>
#include <unistd.h>

#include <XmlRpcValue.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <fstream>
#include <functional>
#include <iterator>
#include <memory>
#include <mutex>
#include <regex>
#include <set>
#include <string>
#include <vector>

#include "connection_support.h"
#include "imu_lab/common/config_error.h"
#include "imu_lab/ros_io/node/allan_monitor_node.h"
#include "imu_lab/ros_io/node/calibration_corrector_node.h"
#include "imu_lab/ros_io/node/imu_emulator_node.h"
#include "imu_lab/ros_io/node/node_parameters.h"
#include "imu_lab/ros_io/node/strapdown_navigator_node.h"
#include "imu_lab/ros_io/node/thermal_compensator_node.h"

namespace {

using imu_lab::ConfigError;
using imu_lab::ros_io::non_negative_parameter;
using imu_lab::ros_io::parameter;
using imu_lab::ros_io::positive_parameter;
using XmlRpc::XmlRpcValue;

constexpr const char* kScratchNamespace = "/node_parameters_scratch";

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// The message of the ConfigError `read` throws; "" when it throws none.
std::string config_error_of(const std::function<void()>& read) {
  try {
    read();
  } catch (const ConfigError& error) {
    return error.what();
  }
  return "";
}

XmlRpcValue list_of(std::vector<XmlRpcValue> items) {
  XmlRpcValue list;
  list.setSize(static_cast<int>(items.size()));
  for (std::size_t k = 0; k < items.size(); ++k) list[static_cast<int>(k)] = items[k];
  return list;
}

class NodeParameters : public testing::Test {
 protected:
  // Each test uses parameter names of its own, so no test sees another's leftovers.
  void set(const std::string& name, XmlRpcValue value) { node.setParam(name, value); }
  std::string resolved(const std::string& name) const { return std::string(kScratchNamespace) + "/" + name; }

  ros::NodeHandle node{kScratchNamespace};
};

TEST_F(NodeParameters, AnAbsentParameterTakesTheDefault) {
  EXPECT_EQ(parameter(node, "absent_rate_hz", 200.0), 200.0);
  EXPECT_EQ(parameter(node, "absent_seed", 7), 7);
  EXPECT_EQ(parameter(node, "absent_flag", true), true);
  EXPECT_EQ(parameter<std::string>(node, "absent_frame", "imu_link"), "imu_link");
  EXPECT_EQ(positive_parameter(node, "absent_period_s", 1.5), 1.5);
}

TEST_F(NodeParameters, ParametersOfTheRightTypeAreRead) {
  set("right_rate_hz", XmlRpcValue(100.5));
  set("right_seed", XmlRpcValue(42));
  set("right_flag", XmlRpcValue(false));
  set("right_frame", XmlRpcValue(std::string("base_link")));
  set("right_statistics", list_of({XmlRpcValue(std::string("oadev")), XmlRpcValue(std::string("mdev"))}));
  EXPECT_EQ(parameter(node, "right_rate_hz", 200.0), 100.5);
  EXPECT_EQ(parameter(node, "right_seed", 1), 42);
  EXPECT_EQ(parameter(node, "right_flag", true), false);
  EXPECT_EQ(parameter<std::string>(node, "right_frame", "imu_link"), "base_link");
  EXPECT_EQ(parameter(node, "right_statistics", std::vector<std::string>()),
            (std::vector<std::string>{"oadev", "mdev"}));
}

TEST_F(NodeParameters, AnIntWillDoForADouble) {
  set("int_rate_hz", XmlRpcValue(400));
  EXPECT_EQ(parameter(node, "int_rate_hz", 200.0), 400.0);
  EXPECT_EQ(positive_parameter(node, "int_rate_hz", 200.0), 400.0);
}

TEST_F(NodeParameters, AStringForADoubleIsRefusedNamingTheParameter) {
  set("string_rate_hz", XmlRpcValue(std::string("fast")));
  const std::string message = config_error_of([&] { parameter(node, "string_rate_hz", 200.0); });
  EXPECT_TRUE(contains(message, resolved("string_rate_hz"))) << message;
  EXPECT_TRUE(contains(message, "expected a number")) << message;
  EXPECT_TRUE(contains(message, "the string 'fast'")) << message;
  // The range-checked readers refuse the same way (they read through parameter()).
  EXPECT_TRUE(
      contains(config_error_of([&] { positive_parameter(node, "string_rate_hz", 200.0); }), "the string 'fast'"));
}

TEST_F(NodeParameters, ADoubleForAnIntIsRefused) {
  set("double_seed", XmlRpcValue(1.5));
  const std::string message = config_error_of([&] { parameter(node, "double_seed", 1); });
  EXPECT_TRUE(contains(message, resolved("double_seed"))) << message;
  EXPECT_TRUE(contains(message, "expected an int")) << message;
  EXPECT_TRUE(contains(message, "the double 1.5")) << message;
}

TEST_F(NodeParameters, AStringOrAnIntForABoolIsRefused) {
  set("string_flag", XmlRpcValue(std::string("yes")));
  set("int_flag", XmlRpcValue(1));
  const std::string message = config_error_of([&] { parameter(node, "string_flag", true); });
  EXPECT_TRUE(contains(message, resolved("string_flag"))) << message;
  EXPECT_TRUE(contains(message, "expected a bool")) << message;
  EXPECT_TRUE(contains(message, "the string 'yes'")) << message;
  EXPECT_TRUE(contains(config_error_of([&] { parameter(node, "int_flag", false); }), "the int 1"));
}

TEST_F(NodeParameters, ANumberForAStringIsRefused) {
  set("int_frame", XmlRpcValue(5));
  const std::string message = config_error_of([&] { parameter<std::string>(node, "int_frame", "imu_link"); });
  EXPECT_TRUE(contains(message, resolved("int_frame"))) << message;
  EXPECT_TRUE(contains(message, "expected a string")) << message;
  EXPECT_TRUE(contains(message, "the int 5")) << message;
}

TEST_F(NodeParameters, AListForANumberAndANumberInAStringListAreRefused) {
  set("list_rate_hz", list_of({XmlRpcValue(1.0), XmlRpcValue(2.0)}));
  set("mixed_statistics", list_of({XmlRpcValue(std::string("oadev")), XmlRpcValue(3)}));
  const std::string message = config_error_of([&] { parameter(node, "list_rate_hz", 200.0); });
  EXPECT_TRUE(contains(message, resolved("list_rate_hz"))) << message;
  EXPECT_TRUE(contains(message, "the list [1, 2]")) << message;
  const std::string list_message =
      config_error_of([&] { parameter(node, "mixed_statistics", std::vector<std::string>()); });
  EXPECT_TRUE(contains(list_message, resolved("mixed_statistics"))) << list_message;
  EXPECT_TRUE(contains(list_message, "expected a list of strings, got the list ['oadev', 3]")) << list_message;
}

TEST_F(NodeParameters, ANegativeOrZeroRateIsRefused) {
  set("negative_rate_hz", XmlRpcValue(-5.0));
  set("zero_rate_hz", XmlRpcValue(0));
  const std::string message = config_error_of([&] { positive_parameter(node, "negative_rate_hz", 200.0); });
  EXPECT_TRUE(contains(message, resolved("negative_rate_hz"))) << message;
  EXPECT_TRUE(contains(message, "must be a positive number, got -5")) << message;
  EXPECT_TRUE(contains(config_error_of([&] { positive_parameter(node, "zero_rate_hz", 200.0); }), "got 0"));
  EXPECT_TRUE(contains(config_error_of([&] { positive_parameter(node, "zero_rate_hz", 10); }), "got 0"));
}

TEST_F(NodeParameters, NonNegativeTakesZeroAndRefusesANegativeNumber) {
  set("zero_duration_s", XmlRpcValue(0.0));
  set("negative_duration_s", XmlRpcValue(-1));
  EXPECT_EQ(non_negative_parameter(node, "zero_duration_s", 10.0), 0.0);
  const std::string message = config_error_of([&] { non_negative_parameter(node, "negative_duration_s", 0.0); });
  EXPECT_TRUE(contains(message, resolved("negative_duration_s"))) << message;
  EXPECT_TRUE(contains(message, ">= 0, got -1")) << message;
}

struct ProcessResult {
  int exit_code = -1;
  bool signalled = false;
  std::string output;
};

// A shell command (stderr with stdout) running under a time limit: a node that wrongly starts
// is stopped after kTimeLimit_s (exit 124), so a broken reader fails the test instead of hanging it.
constexpr int kTimeLimit_s = 30;

FILE* start(const std::string& command) {
  return popen(("timeout " + std::to_string(kTimeLimit_s) + " " + command + " 2>&1").c_str(), "r");
}

ProcessResult finish(FILE* pipe) {
  ProcessResult result;
  if (pipe == nullptr) return result;
  std::array<char, 4096> buffer;
  while (const std::size_t count = std::fread(buffer.data(), 1, buffer.size(), pipe))
    result.output.append(buffer.data(), count);
  const int status = pclose(pipe);
  result.signalled = WIFSIGNALED(status);
  if (WIFEXITED(status)) result.exit_code = WEXITSTATUS(status);
  return result;
}

// The package's executables are built beside this checker.
std::string binary_directory() {
  std::array<char, 4096> path{};
  const ssize_t length = readlink("/proc/self/exe", path.data(), path.size() - 1);
  const std::string self(path.data(), length > 0 ? static_cast<std::size_t>(length) : 0);
  return self.substr(0, self.rfind('/'));
}

struct BadStart {
  std::string binary;
  std::string node_name;
  std::string arguments;
  std::string parameter;  // as the message must name it
};

TEST(NodeBinaries, AWrongTypedOrNegativeParameterStopsTheNodeNamingIt) {
  const std::vector<BadStart> cases = {
      {"imu_emulator", "bad_rate_emulator", "_rate_hz:=fast", "/bad_rate_emulator/rate_hz"},
      {"imu_emulator", "bad_seed_emulator", "_seed:=1.5", "/bad_seed_emulator/seed"},
      {"imu_emulator", "bad_truth_emulator", "_publish_truth:=yes", "/bad_truth_emulator/publish_truth"},
      {"imu_emulator", "negative_rate_emulator", "_rate_hz:=-100", "/negative_rate_emulator/rate_hz"},
      {"allan_monitor", "bad_plot_monitor", "_plot:=1", "/bad_plot_monitor/plot"},
      {"strapdown_navigator", "bad_latitude_navigator", "_latitude_deg:=north", "/bad_latitude_navigator/latitude_deg"},
      // Without alignment the start velocity must be given: a silent [0, 0, 0] was a moving start's error.
      {"strapdown_navigator", "no_velocity_navigator", "_align:=false",
       "/no_velocity_navigator/initial_velocity_enu_m_s"},
      {"thermal_compensator", "bad_queue_compensator", "_model_file:=/nonexistent.yaml _queue_size:=-3",
       "/bad_queue_compensator/queue_size"},
      {"calibration_corrector", "bad_file_corrector", "_calibration_file:=5", "/bad_file_corrector/calibration_file"},
  };
  const std::string directory = binary_directory();
  std::vector<FILE*> running;  // all at once: a broken reader costs one time limit, not one per case
  for (const BadStart& bad : cases) {
    running.push_back(start(directory + "/" + bad.binary + " __name:=" + bad.node_name + " " + bad.arguments));
  }
  for (std::size_t k = 0; k < cases.size(); ++k) {
    const BadStart& bad = cases[k];
    const ProcessResult result = finish(running[k]);
    EXPECT_FALSE(result.signalled) << bad.binary << " " << bad.arguments << ":\n" << result.output;
    EXPECT_EQ(result.exit_code, 2) << bad.binary << " " << bad.arguments << ":\n" << result.output;
    EXPECT_TRUE(contains(result.output, "bad configuration")) << result.output;
    EXPECT_TRUE(contains(result.output, bad.parameter)) << bad.parameter << " not in:\n" << result.output;
  }
}

class RosoutWatch {
 public:
  explicit RosoutWatch(ros::NodeHandle& node)
      : subscriber_(node.subscribe("/rosout", 1000, &RosoutWatch::on_log, this)) {}

  // Whether a FATAL line containing `words` arrived within timeout_s.
  bool wait_for_fatal(const std::string& words, double timeout_s) {
    const ros::WallTime deadline = ros::WallTime::now() + ros::WallDuration(timeout_s);
    while (ros::WallTime::now() < deadline) {
      {
        std::lock_guard<std::mutex> lock(mutex_);
        for (const std::string& line : fatal_lines_) {
          if (contains(line, words)) return true;
        }
      }
      ros::WallDuration(0.05).sleep();
    }
    return false;
  }

 private:
  void on_log(const rosgraph_msgs::Log::ConstPtr& log) {
    if (log->level != rosgraph_msgs::Log::FATAL) return;
    std::lock_guard<std::mutex> lock(mutex_);
    fatal_lines_.push_back(log->msg);
  }

  std::mutex mutex_;
  std::vector<std::string> fatal_lines_;
  ros::Subscriber subscriber_;
};

TEST(NodeletManager, AWrongTypedParameterRefusesTheNodeletAndTheManagerLivesOn) {
  ros::NodeHandle node;
  ros::AsyncSpinner spinner(1);
  spinner.start();
  RosoutWatch rosout(node);
  ASSERT_TRUE(ros::service::waitForService("/parameter_manager/load_nodelet", ros::Duration(60.0)));
  // The manager's log reaches this checker only once its /rosout connection to it exists.
  ASSERT_TRUE(imu_lab::connection_check::wait_until(
      [] { return imu_lab::connection_check::sends("/parameter_manager", "/rosout", ros::this_node::getName()); },
      60.0));

  const ProcessResult result =
      finish(start("rosrun nodelet nodelet load imu_lab/ImuEmulatorNodelet /parameter_manager "
                   "__name:=bad_rate_nodelet _rate_hz:=fast"));
  EXPECT_FALSE(result.signalled) << result.output;
  EXPECT_NE(result.exit_code, 0) << result.output;
  EXPECT_TRUE(rosout.wait_for_fatal("/bad_rate_nodelet/rate_hz", 20.0));
  EXPECT_TRUE(ros::service::exists("/parameter_manager/list", false)) << "the manager did not survive";
}

// ---- The parameter templates, config/nodes/<node>.yaml ----

// The template's keys: the top-level keys of its mapping, and the parameters without a default,
// written as "#? key: example" lines.
std::set<std::string> template_keys(const std::string& path) {
  std::set<std::string> keys;
  const YAML::Node root = YAML::LoadFile(path);
  for (const auto& entry : root) keys.insert(entry.first.as<std::string>());
  std::ifstream stream(path);
  const std::regex optional_key(R"(^#\? ([a-z0-9_]+):)");
  std::smatch match;
  for (std::string line; std::getline(stream, line);) {
    if (std::regex_search(line, match, optional_key)) keys.insert(match[1]);
  }
  return keys;
}

std::string text_of(const std::set<std::string>& names) {
  std::string text;
  for (const auto& name : names) text += " " + name;
  return text.empty() ? " (none)" : text;
}

struct NodeTemplate {
  std::string node;
  // Parameters the test gives beyond the template: the files a node requires (the template leaves
  // them empty, and the node refuses to start without them), and where a report goes.
  std::vector<std::pair<std::string, std::string>> filled_in;
  std::function<std::shared_ptr<void>(ros::NodeHandle&, ros::NodeHandle&)> start;
};

template <class Node>
std::function<std::shared_ptr<void>(ros::NodeHandle&, ros::NodeHandle&)> starts() {
  return [](ros::NodeHandle& node, ros::NodeHandle& private_node) -> std::shared_ptr<void> {
    return std::make_shared<Node>(node, private_node);
  };
}

// Each node started with its template loaded as a launch file loads it: it starts (every value is
// one it accepts), and the parameters it asks for are exactly the template's keys, so a parameter
// added to a node without its template entry, or a template entry no node reads, fails here.
TEST(NodeTemplates, EachNodeAcceptsItsTemplateAndReadsExactlyItsKeys) {
  using namespace imu_lab::ros_io;
  char scratch[] = "/tmp/imu_lab_templates_XXXXXX";
  ASSERT_NE(mkdtemp(scratch), nullptr);
  const std::string data = IMU_LAB_TEST_DATA_DIR;
  const std::vector<NodeTemplate> templates = {
      {"imu_emulator", {}, starts<ImuEmulatorNode>()},
      {"allan_monitor", {{"report_dir", std::string(scratch) + "/allan_report"}}, starts<AllanMonitorNode>()},
      {"thermal_compensator",
       {{"model_file", data + "/thermal/model_uncompensated_mems_gyro.yaml"}},
       starts<ThermalCompensatorNode>()},
      {"calibration_corrector",
       {{"calibration_file", data + "/calibration_example.yaml"}},
       starts<CalibrationCorrectorNode>()},
      {"strapdown_navigator", {}, starts<StrapdownNavigatorNode>()},
  };
  for (const NodeTemplate& node_template : templates) {
    SCOPED_TRACE(node_template.node);
    const std::string path = std::string(IMU_LAB_CONFIG_DIR) + "/nodes/" + node_template.node + ".yaml";
    const std::string private_namespace = "/template_check/" + node_template.node;
    const ProcessResult loaded = finish(start("rosparam load " + path + " " + private_namespace));
    ASSERT_EQ(loaded.exit_code, 0) << loaded.output;
    for (const auto& [name, value] : node_template.filled_in) ros::param::set(private_namespace + "/" + name, value);

    imu_lab::ros_io::take_parameters_asked();
    ros::NodeHandle node("/template_check/topics_" + node_template.node);
    ros::NodeHandle private_node(private_namespace);
    try {
      node_template.start(node, private_node).reset();
    } catch (const ConfigError& error) {
      ADD_FAILURE() << path << " is refused: " << error.what();
      continue;
    }
    std::set<std::string> asked;
    for (const std::string& name : imu_lab::ros_io::take_parameters_asked()) {
      ASSERT_EQ(name.rfind(private_namespace + "/", 0), 0u) << "a parameter outside the private namespace: " << name;
      asked.insert(name.substr(private_namespace.size() + 1));
    }
    const std::set<std::string> keys = template_keys(path);
    std::set<std::string> missing;
    std::set<std::string> unread;
    std::set_difference(asked.begin(), asked.end(), keys.begin(), keys.end(), std::inserter(missing, missing.end()));
    std::set_difference(keys.begin(), keys.end(), asked.begin(), asked.end(), std::inserter(unread, unread.end()));
    EXPECT_TRUE(missing.empty()) << path << " lacks parameters the node reads:" << text_of(missing);
    EXPECT_TRUE(unread.empty()) << path << " has keys the node does not read:" << text_of(unread);
  }
}

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "node_parameters_check");
  return RUN_ALL_TESTS();
}
