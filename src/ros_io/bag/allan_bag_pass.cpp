#include "imu_lab/ros_io/bag/allan_bag_pass.h"

#include <algorithm>
#include <exception>
#include <functional>
#include <thread>
#include <vector>

#include "imu_lab/common/config_error.h"
#include "imu_lab/common/bounded_queue.h"

namespace imu_lab {
namespace ros_io {
namespace {

// Large enough to amortise the queue's locking, small enough for a smooth progress bar.
constexpr std::size_t kBatchSamples = 4096;
constexpr std::size_t kQueuedBatches = 8;
// tau0 needs a few intervals; below this a bag is refused rather than analysed on noise.
constexpr std::size_t kMinimumMessages = 16;

using SampleBatch = std::vector<pipeline::AllanSample>;

// Thrown inside the reader's callback to stop the bag iteration when the consumer gave up.
struct ReadingCancelled {};

// Every message of the topic as an Allan sample; `on_imu` also sees each sensor_msgs/Imu record.
void for_each_sample(OpenBag& bag, const std::string& topic, pipeline::AllanInput input,
                     const std::function<void(const pipeline::AllanSample&)>& add,
                     const std::function<void(const ImuRecord&)>& on_imu = {}) {
  if (input == pipeline::AllanInput::kRate) {
    bag.for_each_imu(topic, [&](const ImuRecord& record) {
      if (on_imu) on_imu(record);
      add(pipeline::to_allan_sample(record));
    });
  } else {
    bag.for_each_increment(topic, [&](const IncrementRecord& record) { add(pipeline::to_allan_sample(record)); });
  }
}

void read_batches(OpenBag& bag, const std::string& topic, pipeline::AllanInput input, BoundedQueue<SampleBatch>& queue,
                  AllanBagPassResult& result) {
  SampleBatch batch;
  batch.reserve(kBatchSamples);
  const auto add = [&](const pipeline::AllanSample& sample) {
    batch.push_back(sample);
    if (batch.size() < kBatchSamples) return;
    if (!queue.push(std::move(batch))) throw ReadingCancelled{};
    batch = SampleBatch();
    batch.reserve(kBatchSamples);
  };
  for_each_sample(bag, topic, input, add, [&](const ImuRecord& record) {
    result.messages_without_angular_rate += record.has_angular_rate ? 0 : 1;
    result.messages_without_specific_force += record.has_specific_force ? 0 : 1;
  });
  if (!batch.empty()) queue.push(std::move(batch));
}

// The warm-up removal's first pass: every sample's values into block means, then the fits.
pipeline::AllanWarmUp fit_warm_up_first(OpenBag& bag, const std::string& topic, pipeline::AllanInput input,
                                        const pipeline::AllanWarmUpOptions& options) {
  thermal::WarmUpBlockMeans blocks(pipeline::kAllanChannelCount, options.block_s);
  for_each_sample(bag, topic, input,
                  [&](const pipeline::AllanSample& sample) { blocks.push(sample.stamp_ns, sample.values.data()); });
  return pipeline::fit_allan_warm_up(blocks, options);
}

}  // namespace

AllanBagPassResult run_allan_bag_pass(const BagRecording& recording, const AllanBagPassOptions& options) {
  AllanBagPassResult result;
  result.bag_path = recording.name();
  result.window = recording.window;
  result.input = options.input;
  // Opened once: each opening reads the bag's whole index again.
  OpenBag bag(recording);
  result.files = bag.ordered_paths();
  const TopicInfo topic = bag.choose_topic(options.topic, allan_input_datatype(options.input));
  result.topic = topic.name;
  const std::string where = "bag " + recording.name() + ", topic " + result.topic;
  const std::size_t total = topic.message_count;
  if (total < kMinimumMessages) {
    throw InputError(where + " has " + std::to_string(total) + " messages; an Allan analysis needs at least " +
                     std::to_string(kMinimumMessages) + " (and thousands for useful curves)");
  }
  result.engine = options.engine;
  result.engine.channel_count = pipeline::kAllanChannelCount;
  result.engine.input_kind = pipeline::engine_input_kind(options.input);
  result.engine.warm_up_sample_count = std::min(result.engine.warm_up_sample_count, total);
  allan::StreamingAllan engine(result.engine);
  allan::ImpulseScreenOptions screen_options = options.screen;
  screen_options.channel_count = pipeline::kAllanChannelCount;
  screen_options.gap_factor = result.engine.gap_factor;
  allan::ImpulseScreen screen(screen_options);
  allan::LevelShiftScreenOptions shift_options = options.level_shifts;
  shift_options.channel_count = pipeline::kAllanChannelCount;
  shift_options.gap_factor = result.engine.gap_factor;
  allan::LevelShiftScreen shift_screen(shift_options);
  allan::OutputStepDetector steps(pipeline::kAllanChannelCount);
  if (options.warm_up.enabled) {
    pipeline::check_warm_up_options(options.warm_up);
    result.warm_up = fit_warm_up_first(bag, result.topic, options.input, options.warm_up);
  }

  BoundedQueue<SampleBatch> queue(kQueuedBatches);
  std::exception_ptr reader_error;
  std::thread reader([&] {
    try {
      read_batches(bag, result.topic, options.input, queue, result);
    } catch (const ReadingCancelled&) {
    } catch (...) {
      reader_error = std::current_exception();
    }
    queue.close();
  });
  // The engine runs each statistic over a whole block in one loop (push_block), several times
  // cheaper than sample by sample; it wants stamps and row-major values side by side, as the
  // screen hands them over.
  allan::ScreenedSamples passed;
  allan::ScreenedSamples unshifted;
  const auto push_passed = [&] {
    shift_screen.push(passed, unshifted);
    passed.clear();
    engine.push_block(unshifted.stamps_ns.data(), unshifted.values.data(), unshifted.size());
    unshifted.clear();
  };
  try {
    while (std::optional<SampleBatch> batch = queue.pop()) {
      for (pipeline::AllanSample& sample : *batch) {
        steps.push(sample.values.data());
        if (result.warm_up) result.warm_up->remove_from(sample);
        screen.push(sample.stamp_ns, sample.values.data(), passed);
      }
      push_passed();
      result.message_count += batch->size();
      if (options.on_progress) options.on_progress(result.message_count, total);
    }
    screen.finish(passed);
    shift_screen.push(passed, unshifted);
    passed.clear();
    shift_screen.finish(unshifted);
    push_passed();
  } catch (const InputError& error) {
    queue.close();
    reader.join();
    const bool stopped_by_policy = result.engine.stamp_policy == allan::StampPolicy::kStop;
    throw InputError(where + ": " + error.what() +
                     (stopped_by_policy ? " (the split policy, --on-gap split, pools the segments instead)" : ""));
  } catch (...) {
    queue.close();
    reader.join();
    throw;
  }
  reader.join();
  if (reader_error) std::rethrow_exception(reader_error);
  result.joins = bag.joins();
  const std::string window_text = " in the window (" + describe_time_window(result.window) + ")";
  if (result.message_count < kMinimumMessages) {
    throw InputError(where + " has " + std::to_string(result.message_count) + " messages" + window_text +
                     "; an Allan analysis needs at least " + std::to_string(kMinimumMessages));
  }
  // A window leaves the progress short of the topic's total; say it is done.
  if (options.on_progress && result.message_count < total) options.on_progress(total, total);

  result.snapshot = engine.snapshot();
  result.impulses = screen.report();
  result.level_shifts = shift_screen.report();
  result.output_steps = steps.channels();
  if (!result.snapshot.warmed_up) {
    throw InputError(where + ": the " + std::to_string(result.message_count) + " messages" +
                     (result.window.is_whole() ? "" : window_text) +
                     " have too few regular stamps to estimate the sample period");
  }
  bool any_usable = false;
  for (const allan::ChannelReport& channel : result.snapshot.channels) any_usable |= channel.finite_sample_count > 0;
  if (!any_usable) {
    throw InputError(where + ": none of the " + std::to_string(result.message_count) +
                     " messages has a usable value in any channel (NaN/Inf, beyond +-1e100, or covariance[0] = -1 "
                     "for a triad not provided), so there are no curves; nothing written");
  }
  return result;
}

}  // namespace ros_io
}  // namespace imu_lab
