#include "imu_lab/allan/streaming_warm_up.h"

#include <algorithm>
#include <cmath>

#include "imu_lab/common/usable_imu_values.h"

namespace imu_lab {
namespace allan {

void WarmUpBuffer::add(std::int64_t stamp_ns, const double* values) {
  stamps_ns_.push_back(stamp_ns);
  values_.insert(values_.end(), values, values + channel_count_);
}

std::int64_t WarmUpBuffer::median_interval_ns() const {
  std::vector<std::int64_t> intervals;
  for (std::size_t i = 1; i < stamps_ns_.size(); ++i) {
    std::int64_t interval;
    // Stamps over 292 years apart (corrupt input) are no sampling interval either.
    if (__builtin_sub_overflow(stamps_ns_[i], stamps_ns_[i - 1], &interval)) continue;
    if (interval > 0) intervals.push_back(interval);
  }
  if (intervals.empty()) return 0;
  const auto middle = intervals.begin() + intervals.size() / 2;
  std::nth_element(intervals.begin(), middle, intervals.end());
  return *middle;
}

std::vector<double> WarmUpBuffer::finite_means() const {
  std::vector<double> means(channel_count_, 0.0);
  for (std::size_t channel = 0; channel < channel_count_; ++channel) {
    double sum = 0.0;
    std::size_t count = 0;
    for (std::size_t sample = 0; sample < stamps_ns_.size(); ++sample) {
      const double value = values_[sample * channel_count_ + channel];
      if (!is_usable_imu_value(value)) continue;
      sum += value;
      ++count;
    }
    if (count > 0) means[channel] = sum / static_cast<double>(count);
  }
  return means;
}

void WarmUpBuffer::release() {
  std::vector<std::int64_t>().swap(stamps_ns_);
  std::vector<double>().swap(values_);
}

std::size_t WarmUpBuffer::heap_bytes() const {
  return stamps_ns_.capacity() * sizeof(std::int64_t) + values_.capacity() * sizeof(double);
}

void WarmUpBuffer::save(BinaryWriter& out) const {
  out.put_i64s(stamps_ns_);
  out.put_f64s(values_);
}

void WarmUpBuffer::load(BinaryReader& in) {
  stamps_ns_ = in.get_i64s();
  values_ = in.get_f64s();  // raw samples: NaN and Inf are kept here and excluded when accepted
  if (values_.size() != stamps_ns_.size() * channel_count_) in.fail("warm-up buffer of another channel count");
}

}  // namespace allan
}  // namespace imu_lab
