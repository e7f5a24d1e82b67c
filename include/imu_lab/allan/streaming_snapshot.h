// What StreamingAllan::snapshot() returns: the curves of every statistic for every channel as
// they stand (final after the last push), and the reports on stamps and channels.
#pragma once

#include <array>
#include <vector>

#include "imu_lab/allan/batch.h"
#include "imu_lab/allan/streaming_report.h"

namespace imu_lab {
namespace allan {

constexpr std::array<Statistic, 9> kStreamingStatistics = {
    Statistic::kAllan,    Statistic::kOverlappingAllan,    Statistic::kModifiedAllan,
    Statistic::kHadamard, Statistic::kOverlappingHadamard, Statistic::kTime,
    Statistic::kTotal,    Statistic::kAllanKrobka,         Statistic::kHadamardKrobka};

struct StreamingSnapshot {
  bool warmed_up = false;  // false: too few samples to fix tau0; curves are empty
  TimingReport timing;
  std::vector<ChannelReport> channels;
  // curves[static_cast<std::size_t>(statistic)][channel], ascending m.
  std::vector<std::vector<std::vector<StabilityPoint>>> curves;

  const std::vector<StabilityPoint>& curve(Statistic statistic, std::size_t channel) const {
    return curves.at(static_cast<std::size_t>(statistic)).at(channel);
  }
};

}  // namespace allan
}  // namespace imu_lab
