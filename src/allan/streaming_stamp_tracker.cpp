#include "imu_lab/allan/streaming_stamp_tracker.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "imu_lab/common/config_error.h"

namespace imu_lab {
namespace allan {
namespace {

const char* describe(StampEventKind kind) {
  switch (kind) {
    case StampEventKind::kGap: return "a gap";
    case StampEventKind::kDuplicate: return "a duplicate stamp";
    case StampEventKind::kOutOfOrder: return "an out-of-order stamp";
  }
  return "an irregular stamp";
}

}  // namespace

StampTracker::StampTracker(std::int64_t tau0_ns, double gap_factor, StampPolicy policy)
    : tau0_ns_(tau0_ns), gap_threshold_ns_(gap_factor * static_cast<double>(tau0_ns)), policy_(policy) {}

void StampTracker::record(StampEventKind kind, std::int64_t sample_index, std::int64_t stamp_ns) {
  if (policy_ == StampPolicy::kStop) {
    throw InputError("sample " + std::to_string(sample_index) + " (stamp " + std::to_string(stamp_ns) +
                     " ns) follows the stamp " + std::to_string(last_stamp_ns_) + " ns: " + describe(kind) +
                     " with tau0 " + std::to_string(tau0_ns_) +
                     " ns; fix the input or use StampPolicy::kSplitAndPool to split and pool");
  }
  if (events_.size() < kMaxRecordedStampEvents) events_.push_back({kind, sample_index, last_stamp_ns_, stamp_ns});
}

StampVerdict StampTracker::classify(std::int64_t stamp_ns, std::int64_t sample_index) {
  if (!has_last_) {
    has_last_ = true;
    last_stamp_ns_ = stamp_ns;
    ++accepted_count_;
    return StampVerdict::kFirst;
  }
  std::int64_t interval_ns;
  if (__builtin_sub_overflow(stamp_ns, last_stamp_ns_, &interval_ns)) {
    // Stamps over 292 years apart (a corrupt input): backwards, or the longest gap there is.
    interval_ns = stamp_ns < last_stamp_ns_ ? -1 : std::numeric_limits<std::int64_t>::max();
  }
  StampVerdict verdict = StampVerdict::kNext;
  if (interval_ns == 0) {
    record(StampEventKind::kDuplicate, sample_index, stamp_ns);
    ++duplicate_count_;
    return StampVerdict::kDuplicate;
  }
  if (interval_ns < 0) {
    record(StampEventKind::kOutOfOrder, sample_index, stamp_ns);
    ++out_of_order_count_;
    return StampVerdict::kOutOfOrder;
  }
  const double deviation_s = static_cast<double>(interval_ns - tau0_ns_) * 1e-9;
  if (static_cast<double>(interval_ns) > gap_threshold_ns_) {
    record(StampEventKind::kGap, sample_index, stamp_ns);
    ++gap_count_;
    gap_time_s_.add(deviation_s);
    verdict = StampVerdict::kGap;
  } else {
    ++regular_interval_count_;
    squared_deviation_s2_.add(deviation_s * deviation_s);
    max_deviation_s_ = std::max(max_deviation_s_, std::abs(deviation_s));
  }
  last_stamp_ns_ = stamp_ns;
  ++accepted_count_;
  return verdict;
}

void StampTracker::fill(TimingReport& report) const {
  report.tau0_s = static_cast<double>(tau0_ns_) * 1e-9;
  report.interval_rms_deviation_s =
      regular_interval_count_ > 0 ? std::sqrt(squared_deviation_s2_.value() / regular_interval_count_) : 0.0;
  report.interval_max_deviation_s = max_deviation_s_;
  report.accepted_sample_count = accepted_count_;
  report.gap_count = gap_count_;
  report.gap_time_s = gap_time_s_.value();
  report.duplicate_count = duplicate_count_;
  report.out_of_order_count = out_of_order_count_;
  report.events = events_;
}

void StampTracker::save(BinaryWriter& out) const {
  out.put_i64(tau0_ns_);
  out.put_f64(gap_threshold_ns_);
  out.put_i64(static_cast<std::int64_t>(policy_));
  out.put_i64(has_last_ ? 1 : 0);
  out.put_i64(last_stamp_ns_);
  out.put_i64(accepted_count_);
  out.put_i64(regular_interval_count_);
  squared_deviation_s2_.save(out);
  out.put_f64(max_deviation_s_);
  out.put_i64(gap_count_);
  gap_time_s_.save(out);
  out.put_i64(duplicate_count_);
  out.put_i64(out_of_order_count_);
  out.put_u64(events_.size());
  for (const StampEvent& event : events_) {
    out.put_i64(static_cast<std::int64_t>(event.kind));
    out.put_i64(event.sample_index);
    out.put_i64(event.previous_stamp_ns);
    out.put_i64(event.stamp_ns);
  }
}

void StampTracker::load(BinaryReader& in) {
  tau0_ns_ = in.get_i64();
  gap_threshold_ns_ = in.get_finite_f64();
  if (tau0_ns_ <= 0 || !(gap_threshold_ns_ > static_cast<double>(tau0_ns_)))
    in.fail("stamp tracker's tau0 or gap threshold");
  policy_ = in.get_enum(StampPolicy::kStop, "stamp policy");
  has_last_ = in.get_i64() != 0;
  last_stamp_ns_ = in.get_i64();
  accepted_count_ = in.get_count();
  regular_interval_count_ = in.get_count();
  squared_deviation_s2_.load(in);
  max_deviation_s_ = in.get_finite_f64();
  gap_count_ = in.get_count();
  gap_time_s_.load(in);
  duplicate_count_ = in.get_count();
  out_of_order_count_ = in.get_count();
  const std::uint64_t event_count = in.get_u64();
  if (event_count > kMaxRecordedStampEvents) in.fail("more stamp events than are ever recorded");
  events_.resize(event_count);
  for (StampEvent& event : events_) {
    event.kind = in.get_enum(StampEventKind::kOutOfOrder, "stamp event kind");
    event.sample_index = in.get_i64();
    event.previous_stamp_ns = in.get_i64();
    event.stamp_ns = in.get_i64();
  }
}

}  // namespace allan
}  // namespace imu_lab
