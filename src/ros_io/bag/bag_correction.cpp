#include "imu_lab/ros_io/bag/bag_correction.h"

#include <rosbag/view.h>
#include <sensor_msgs/Imu.h>
#include <sensor_msgs/Temperature.h>

#include <deque>
#include <memory>
#include <set>

#include "imu_lab/common/config_error.h"
#include "imu_lab/common/format_number.h"
#include "imu_lab/common/stamps.h"
#include "imu_lab/ros_io/bag/atomic_bag.h"
#include "imu_lab/ros_io/bag/imu_bag_reader.h"
#include "imu_lab/ros_io/bag/strict_imu_reading.h"
#include "imu_lab/ros_io/msg/thermal_compensated_message.h"
#include "imu_lab/ros_io/node/calibration_corrector_node.h"
#include "imu_lab/thermal/thermal_compensator.h"

namespace imu_lab {
namespace ros_io {
namespace {

const char* const kTemperatureType = "sensor_msgs/Temperature";

// The thermosensor topic a thermal model needs: it must exist and hold readings.
void check_temperature_topic(const OpenBag& bag, const std::string& topic, const char* role, const char* option) {
  TopicInfo info;
  try {
    info = bag.choose_topic(topic, kTemperatureType);
  } catch (const InputError& error) {
    throw InputError(std::string(error.what()) + "\nThe thermal model needs the " + role + " (" + kTemperatureType +
                     ", stamped like the IMU): give its topic with " + option + ", or correct with --calibration only");
  }
  if (info.message_count == 0) {
    throw InputError("bag " + bag.path() + ": topic " + topic + " has no messages; the " + role +
                     " was not recorded, so the thermal model cannot be applied");
  }
}

// Counts temperature readings the compensator refused (NaN, or a stamp not after the previous one).
struct TemperatureTopic {
  std::string name;
  std::size_t readings = 0, refused = 0;
  void throw_if_refused(const std::string& bag_path) const {
    if (refused == 0) return;
    throw InputError("bag " + bag_path + ": " + std::to_string(refused) + " of " + std::to_string(readings) +
                     " readings on " + name +
                     " are not finite or not in increasing header-stamp order; nothing "
                     "was written: fix the recording");
  }
};

// One pass over the bag in bag order. IMU messages wait beside the compensator's queue (as in
// thermal_compensator_node.cpp) until their temperature is known, then are written at their own
// receive time; rosbag indexes by time, so the output plays back in the input's order.
class BagCorrector {
 public:
  BagCorrector(OpenBag* bag, const std::string& out_bag_path, const BagCorrectionOptions& options,
               BagCorrectionSummary* summary)
      : bag_(bag), out_(out_bag_path), options_(options), summary_(summary) {
    if (options.thermal_model) {
      compensator_.emplace(*options.thermal_model, options.max_temperature_age_s);
      temperature_.name = options.temperature_topic;
      if (options.thermal_model->uses_second_sensor) second_temperature_.name = options.second_temperature_topic;
    }
  }

  void run() {
    bag_->for_each_message_in_order([&](const rosbag::MessageInstance& instance) { on_message(instance); });
    if (compensator_) {
      std::vector<thermal::CompensatedSample> ready;
      compensator_->flush(&ready);
      write_compensated(ready);
    }
    check_.throw_if_refused(bag_->path(), summary_->imu_topic);
    temperature_.throw_if_refused(bag_->path());
    second_temperature_.throw_if_refused(bag_->path());
    if (summary_->corrected == 0) {
      throw InputError("bag " + bag_->path() + ": none of the " + std::to_string(summary_->imu_messages) +
                       " samples on " + summary_->imu_topic + " could be corrected (" +
                       std::to_string(summary_->stale) + " had no temperature within " +
                       format_number(options_.max_temperature_age_s, 4) + " s of their stamp); nothing was written");
    }
    summary_->copied_topics.assign(copied_topics_.begin(), copied_topics_.end());
    summary_->uncorrected_imu_topics.assign(uncorrected_imu_topics_.begin(), uncorrected_imu_topics_.end());
    out_.commit();
  }

 private:
  void on_message(const rosbag::MessageInstance& instance) {
    const std::string& topic = instance.getTopic();
    if (topic == summary_->imu_topic) {
      on_imu(instance);
      if (summary_->out_topic == summary_->imu_topic) return;
    } else if (compensator_ && (topic == temperature_.name || topic == second_temperature_.name)) {
      on_temperature(instance, topic == temperature_.name ? &temperature_ : &second_temperature_);
    }
    out_.write(topic, instance.getTime(), instance, instance.getConnectionHeader());
    ++summary_->copied_messages;
    copied_topics_.insert(topic);
    const std::string& datatype = instance.getDataType();
    if (datatype == "sensor_msgs/Imu" || datatype == "imu_lab/ImuIncrement") uncorrected_imu_topics_.insert(topic);
  }

  void on_imu(const rosbag::MessageInstance& instance) {
    const sensor_msgs::Imu::ConstPtr message = instantiate<sensor_msgs::Imu>(instance, "sensor_msgs/Imu");
    ++summary_->imu_messages;
    const ImuRecord record = to_imu_record(*message);
    if (!check_.accept(record)) return;  // refused at the end of the pass
    if (!compensator_) {
      write_corrected(*message, instance.getTime());
      return;
    }
    std::vector<thermal::CompensatedSample> ready;
    // Strictly ordered finite samples are always taken; the queue stays in step with the compensator's.
    if (!compensator_->add_imu(record, &ready)) {
      // The strict check above already refused what the compensator refuses; kept as a guard.
      throw InputError("bag " + bag_->path() + ", topic " + summary_->imu_topic +
                       ": the thermal compensator refused the sample at " + format_stamp_s(record.stamp_ns) +
                       " s; nothing was written");
    }
    waiting_.push_back({message, instance.getTime()});
    write_compensated(ready);
  }

  void on_temperature(const rosbag::MessageInstance& instance, TemperatureTopic* topic) {
    const auto message = instantiate<sensor_msgs::Temperature>(instance, kTemperatureType);
    ++topic->readings;
    ++summary_->temperature_messages;
    std::vector<thermal::CompensatedSample> ready;
    const auto stamp_ns = static_cast<std::int64_t>(message->header.stamp.toNSec());
    const double temperature_c = message->temperature;
    const bool taken = topic == &temperature_ ? compensator_->add_temperature(stamp_ns, temperature_c, &ready)
                                              : compensator_->add_second_temperature(stamp_ns, temperature_c, &ready);
    if (!taken) ++topic->refused;
    write_compensated(ready);
  }

  // As ThermalCompensatorNode::publish: a stale sample is left out, a clamped one counted.
  void write_compensated(const std::vector<thermal::CompensatedSample>& ready) {
    for (const thermal::CompensatedSample& sample : ready) {
      const WaitingMessage input = waiting_.front();
      waiting_.pop_front();
      if (sample.status == thermal::CompensatedSample::Status::kStale) {
        ++summary_->stale;
        continue;
      }
      if (sample.status == thermal::CompensatedSample::Status::kClamped) ++summary_->clamped;
      write_corrected(thermal_compensated_message(*input.message, sample), input.receive_time);
    }
  }

  void write_corrected(const sensor_msgs::Imu& message, const ros::Time& receive_time) {
    out_.write(summary_->out_topic, receive_time,
               options_.calibration ? corrected_message(message, *options_.calibration) : message);
    ++summary_->corrected;
  }

  template <class Message>
  boost::shared_ptr<const Message> instantiate(const rosbag::MessageInstance& instance, const char* datatype) const {
    const boost::shared_ptr<const Message> message = instance.instantiate<Message>();
    if (!message) {
      throw InputError("bag " + bag_->path() + ": topic " + instance.getTopic() + " carries " + instance.getDataType() +
                       ", not " + datatype);
    }
    return message;
  }

  struct WaitingMessage {
    sensor_msgs::Imu::ConstPtr message;
    ros::Time receive_time;
  };

  OpenBag* bag_;
  AtomicBag out_;
  const BagCorrectionOptions& options_;
  BagCorrectionSummary* summary_;
  std::optional<thermal::ThermalCompensator> compensator_;
  std::deque<WaitingMessage> waiting_;
  StrictImuCheck check_;
  TemperatureTopic temperature_, second_temperature_;
  std::set<std::string> copied_topics_, uncorrected_imu_topics_;
};

}  // namespace

BagCorrectionSummary correct_bag(const BagRecording& recording, const std::string& out_bag_path,
                                 const BagCorrectionOptions& options) {
  OpenBag bag(recording);
  BagCorrectionSummary summary;
  summary.imu_topic = bag.choose_topic(options.imu_topic, "sensor_msgs/Imu").name;
  summary.out_topic = options.out_topic.empty() ? summary.imu_topic : options.out_topic;
  if (summary.out_topic != summary.imu_topic) {
    for (const TopicInfo& topic : bag.topics()) {
      if (topic.name == summary.out_topic) {
        throw InputError("bag " + recording.name() + " already has a topic " + summary.out_topic + " (" +
                         topic.datatype + "); choose another output topic");
      }
    }
  }
  if (options.thermal_model) {
    check_temperature_topic(bag, options.temperature_topic, "thermosensor", "--temperature-topic");
    if (options.thermal_model->uses_second_sensor) {
      check_temperature_topic(bag, options.second_temperature_topic, "second thermosensor",
                              "--second-temperature-topic");
    }
  }
  BagCorrector(&bag, out_bag_path, options, &summary).run();
  return summary;
}

}  // namespace ros_io
}  // namespace imu_lab
