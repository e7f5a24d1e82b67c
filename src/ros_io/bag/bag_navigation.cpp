#include "imu_lab/ros_io/bag/bag_navigation.h"

#include <unordered_map>

#include "imu_lab/common/config_error.h"
#include "imu_lab/common/stamps.h"
#include "imu_lab/pipeline/navigation_csv.h"

namespace imu_lab {
namespace ros_io {
namespace {

bool bag_has_topic(const BagRecording& recording, const std::string& topic, const std::string& datatype) {
  for (const TopicInfo& info : list_topics(recording)) {
    if (info.name == topic && info.datatype == datatype) return true;
  }
  return false;
}

std::unordered_map<std::int64_t, TruthRecord> truth_by_stamp(const BagRecording& recording, const std::string& topic) {
  std::unordered_map<std::int64_t, TruthRecord> truth;
  for_each_truth(recording, topic, [&](const TruthRecord& record) { truth[record.stamp_ns] = record; });
  return truth;
}

// Feeds the session and keeps the solutions the output interval asks for.
class BagRun {
 public:
  BagRun(const BagNavigationOptions& options, const pipeline::NavigationSettings& settings, BagNavigationResult& result)
      : options_(options),
        session_(settings),
        world_(settings.navigator.earth, settings.latitude_rad, settings.longitude_rad, settings.height_m),
        result_(result) {}

  void on_outcome(pipeline::SampleOutcome outcome, std::int64_t stamp_ns) {
    ++result_.messages;
    if ((pipeline::is_skipped(outcome) || outcome == pipeline::SampleOutcome::kAlignmentFailed) &&
        result_.first_problem.empty()) {
      result_.first_problem = "at stamp " + format_stamp_s(stamp_ns) + " s: " + session_.last_problem();
    }
    if (!session_.new_solution()) return;
    const bool due = result_.solutions.empty() ||
                     seconds_between(result_.solutions.back().stamp_ns, stamp_ns) >= options_.output_interval_s - 1e-9;
    if (due) result_.solutions.push_back(pipeline::make_solution(session_, world_));
  }

  pipeline::NavigationSession& session() { return session_; }
  const nav::LocalEnuFrame& world() const { return world_; }

 private:
  const BagNavigationOptions& options_;
  pipeline::NavigationSession session_;
  nav::LocalEnuFrame world_;
  BagNavigationResult& result_;
};

}  // namespace

InputType parse_input_type(const std::string& key, const std::string& value) {
  if (value == "imu") return InputType::kImu;
  if (value == "increment") return InputType::kIncrement;
  throw ConfigError("navigation input", key,
                    "is '" + value +
                        "'; use imu (sensor_msgs/Imu) or increment "
                        "(imu_lab/ImuIncrement)");
}

const char* datatype_of(InputType input_type) {
  return input_type == InputType::kImu ? "sensor_msgs/Imu" : "imu_lab/ImuIncrement";
}

BagNavigationResult navigate_bag(const BagRecording& recording, const BagNavigationOptions& options,
                                 const pipeline::NavigationSettings& settings) {
  BagNavigationResult result;
  result.topic = choose_topic(recording, options.topic, datatype_of(options.input_type));
  BagRun run(options, settings, result);
  if (options.input_type == InputType::kImu) {
    for_each_imu(recording, result.topic, [&](const ImuRecord& record) {
      run.on_outcome(run.session().add_rates(record.stamp_ns, record.angular_rate_rad_s, record.specific_force_m_s2),
                     record.stamp_ns);
    });
  } else {
    for_each_increment(recording, result.topic, [&](const IncrementRecord& record) {
      nav::ImuIncrement increment;
      increment.delta_angle_rad = record.delta_angle_rad;
      increment.delta_velocity_m_s = record.delta_velocity_m_s;
      increment.dt_s = record.interval_s;
      run.on_outcome(run.session().add_increment(record.stamp_ns, increment), record.stamp_ns);
    });
  }
  result.counters = run.session().counters();
  result.alignment = run.session().alignment();
  if (const auto& divergence = run.session().divergence()) {
    throw InputError("bag " + recording.name() + ", topic " + result.topic +
                     ": the navigation state became unusable at stamp " + format_stamp_s(divergence->stamp_ns) +
                     " s (" + divergence->problem +
                     "); nothing written (check the samples around that stamp and their units)");
  }
  if (!run.session().navigating()) {
    std::string why = "the alignment needs " + std::to_string(settings.alignment.duration_s) + " s of data and got " +
                      std::to_string(run.session().alignment_progress_s()) + " s";
    if (result.counters.failed_alignments > 0) why = "the alignment failed: " + result.first_problem;
    throw InputError("bag " + recording.name() + ", topic " + result.topic + " (" + std::to_string(result.messages) +
                     " messages): navigation never started: " + why +
                     " (use a longer bag, a shorter --alignment-duration-s, or --no-align with a given attitude)");
  }

  result.has_truth = bag_has_topic(recording, options.truth_topic, "imu_lab/ImuTruth");
  if (result.has_truth) {
    const auto truth = truth_by_stamp(recording, options.truth_topic);
    for (const pipeline::NavigationSolution& solution : result.solutions) {
      const auto match = truth.find(solution.stamp_ns);
      if (match == truth.end()) continue;
      result.errors.push_back(
          pipeline::navigation_error(solution, match->second, run.world(), result.alignment->stamp_ns));
    }
  }
  return result;
}

std::optional<TruthRecord> truth_at_start(const BagRecording& recording, const BagNavigationOptions& options) {
  if (!bag_has_topic(recording, options.truth_topic, "imu_lab/ImuTruth")) return std::nullopt;
  // The readers visit every message; an exception ends the visit at the one sought.
  struct Found {
    std::int64_t stamp_ns;
  };
  const std::string topic = choose_topic(recording, options.topic, datatype_of(options.input_type));
  std::optional<std::int64_t> start_ns;
  try {
    if (options.input_type == InputType::kImu) {
      for_each_imu(recording, topic, [](const ImuRecord& record) {
        if (record.angular_rate_rad_s.allFinite() && record.specific_force_m_s2.allFinite())
          throw Found{record.stamp_ns};
      });
    } else {
      for_each_increment(recording, topic, [](const IncrementRecord& record) {
        if (record.delta_angle_rad.allFinite() && record.delta_velocity_m_s.allFinite() && record.interval_s > 0.0) {
          throw Found{record.stamp_ns};
        }
      });
    }
  } catch (const Found& found) {
    start_ns = found.stamp_ns;
  }
  if (!start_ns) return std::nullopt;  // nothing to navigate; navigate_bag says so
  struct FoundTruth {
    TruthRecord record;
  };
  try {
    for_each_truth(recording, options.truth_topic, [&](const TruthRecord& record) {
      if (record.stamp_ns == *start_ns) throw FoundTruth{record};
    });
  } catch (const FoundTruth& found) {
    return found.record;
  }
  throw InputError("bag " + recording.name() + ": " + options.truth_topic + " has no sample at " +
                   format_stamp_s(*start_ns) + " s, the first stamp of " + topic +
                   " where the run starts; give the initial state instead");
}

}  // namespace ros_io
}  // namespace imu_lab
