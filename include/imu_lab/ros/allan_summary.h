// The YAML summary of an Allan run (allan_summary.yaml): where the samples came from, the sample
// period tau0 estimated from the stamps and its jitter, every stamp and value irregularity with
// what the policy did about it, and per channel the offset and the minimum OADEV with its tau.
#pragma once

#include <cstdint>
#include <string>

#include "imu_lab/allan/streaming_allan.h"
#include "imu_lab/ros/allan_samples.h"

namespace imu_lab {
namespace ros_io {

struct AllanRunDescription {
  std::string bag;    // the bag read; empty for a live topic
  std::string topic;  // the topic read or subscribed to
  AllanInput input = AllanInput::kRate;
  allan::StreamingOptions engine;
  std::int64_t skipped_before_checkpoint = 0;  // live only: replayed samples a resumed node skipped
};

std::string format_allan_summary(const AllanRunDescription& run, const allan::StreamingSnapshot& snapshot);

// The smallest deviation of a curve (nullptr for an empty curve).
const allan::StabilityPoint* minimum_point(const std::vector<allan::StabilityPoint>& curve);

}  // namespace ros_io
}  // namespace imu_lab
