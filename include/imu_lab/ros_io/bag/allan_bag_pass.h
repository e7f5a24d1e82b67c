// One streaming Allan pass over a bag: the allan tool's whole computation, also used by the tests,
// the rostest checkers and the benchmark. A reader thread deserialises messages into batches of
// samples (a bounded queue, so memory stays bounded for any bag length) while the calling thread
// pushes them through the impulse screen (impulse_screen.h: knocks and spikes are recorded and
// their samples dropped, so the engine splits the run there) into the streaming engine, and
// watches every value for the output's step (output_step.h); nothing is written anywhere. With
// the warm-up removal on, a first pass over the bag fits each channel's warm-up transient
// (pipeline/allan_warm_up.h) and the pass above sees the values with it subtracted (the output
// step is watched on the values as read).
#pragma once

#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "imu_lab/allan/impulse_screen.h"
#include "imu_lab/allan/level_shift_screen.h"
#include "imu_lab/allan/output_step.h"
#include "imu_lab/allan/streaming_allan.h"
#include "imu_lab/pipeline/allan_samples.h"
#include "imu_lab/pipeline/allan_warm_up.h"
#include "imu_lab/ros_io/bag/imu_bag_reader.h"

namespace imu_lab {
namespace ros_io {

struct AllanBagPassOptions {
  std::string topic;  // empty: the bag's only topic of the input's message type
  pipeline::AllanInput input = pipeline::AllanInput::kRate;
  // channel_count and input_kind are set from `input`; a bag shorter than warm_up_sample_count
  // warms up on all of its messages instead.
  allan::StreamingOptions engine;
  // channel_count and gap_factor are set from the engine's.
  allan::ImpulseScreenOptions screen;
  allan::LevelShiftScreenOptions level_shifts;
  pipeline::AllanWarmUpOptions warm_up;  // off by default
  // Called on the computing thread after each batch: messages processed and the topic's total.
  std::function<void(std::size_t processed, std::size_t total)> on_progress;
};

struct AllanBagPassResult {
  std::string bag_path;            // the recording's name (BagRecording::name)
  std::vector<std::string> files;  // the recording's files in the order read (stamp order)
  TimeWindow window;               // the part of the recording analysed
  std::vector<FileJoin> joins;     // where one split file handed over to the next
  std::string topic;
  pipeline::AllanInput input = pipeline::AllanInput::kRate;
  allan::StreamingOptions engine;  // as used
  std::size_t message_count = 0;
  // sensor_msgs/Imu messages marking a triad as not provided (covariance[0] = -1): the triad's
  // channels leave them out, as they do NaN values.
  std::size_t messages_without_angular_rate = 0;
  std::size_t messages_without_specific_force = 0;
  allan::StreamingSnapshot snapshot;
  allan::ImpulseScreenReport impulses;                 // events found (and samples dropped) before the engine
  allan::LevelShiftReport level_shifts;                // steps found after the impulse screen (samples dropped)
  std::vector<allan::ChannelOutputStep> output_steps;  // per channel, over every message's values
  std::optional<pipeline::AllanWarmUp> warm_up;        // the transients removed (warm_up.enabled only)
};

// `recording` is one bag or the split files of one, and the window to analyse (imu_bag_reader.h).
// Throws InputError naming the bag (and the topic) for an unreadable, truncated or corrupt bag,
// a missing or ambiguous topic, a topic of the wrong type, one with too few messages, one where no
// channel has a single usable value, and, under StampPolicy::kStop, the first irregular stamp.
// ConfigError for unusable engine options.
AllanBagPassResult run_allan_bag_pass(const BagRecording& recording, const AllanBagPassOptions& options);

}  // namespace ros_io
}  // namespace imu_lab
