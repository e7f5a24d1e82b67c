// Offline strapdown navigation of a bag: IMU messages -> pipeline::NavigationSession -> solutions, and,
// when the bag holds the emulator's /imu/truth, each solution's error against the truth sample
// with the same stamp. The navigate tool is a thin wrapper around it; the rostest checker and
// the tests use the tool's output to check the live node against it.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "imu_lab/pipeline/navigation_session.h"
#include "imu_lab/pipeline/navigation_settings.h"
#include "imu_lab/ros_io/bag/imu_bag_reader.h"
#include "imu_lab/pipeline/navigation_solution.h"

namespace imu_lab {
namespace ros_io {

enum class InputType { kImu, kIncrement };  // sensor_msgs/Imu or imu_lab/ImuIncrement
InputType parse_input_type(const std::string& key, const std::string& value);
const char* datatype_of(InputType input_type);

struct BagNavigationOptions {
  InputType input_type = InputType::kImu;
  std::string topic;                       // empty: the bag's only topic of the input type
  std::string truth_topic = "/imu/truth";  // used when the bag has it
  double output_interval_s = 0.0;          // keep a solution at most this often; 0 keeps all
};

struct BagNavigationResult {
  std::string topic;
  std::size_t messages = 0;
  std::vector<pipeline::NavigationSolution> solutions;
  bool has_truth = false;
  std::vector<pipeline::NavigationError> errors;  // one per kept solution that has a truth sample
  std::optional<pipeline::AlignmentResult> alignment;
  pipeline::InputCounters counters;
  std::string first_problem;  // the first skipped sample's stamp and reason, if any
};

// Throws InputError naming the bag when it cannot be read, has no suitable topic, is damaged, or
// ends before the navigation starts (too short for the alignment, or an alignment that failed).
// Bad samples are skipped and counted, as in the node; callers decide whether that is fatal.
BagNavigationResult navigate_bag(const BagRecording& recording, const BagNavigationOptions& options,
                                 const pipeline::NavigationSettings& settings);

// The truth where a run starts: the sample at the stamp of the input topic's first sample with
// finite values (where pipeline::NavigationSession starts a run without alignment), if the bag has the
// truth topic. Throws InputError naming the bag when it has the truth topic but no sample at that
// stamp (a start state from another instant would be wrong by the motion in between).
std::optional<TruthRecord> truth_at_start(const BagRecording& recording, const BagNavigationOptions& options);

}  // namespace ros_io
}  // namespace imu_lab
