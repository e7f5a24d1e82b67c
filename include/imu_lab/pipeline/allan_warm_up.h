// The allan tool's optional warm-up removal (--remove-warm-up): a first pass collects each
// channel's block means, thermal/warm_up_transient.h fits the self-heating transient per channel,
// and the Allan pass then sees every value minus its channel's transient at the sample's stamp.
// The removed models, with their sigmas and the linear trend of what is left, go to
// DIR/warm_up.yaml beside the curves (format_warm_up_yaml). A channel whose fit fails (too few
// blocks, no usable value) is left as it is and the reason reported.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>

#include "imu_lab/allan/streaming_snapshot.h"
#include "imu_lab/pipeline/allan_samples.h"
#include "imu_lab/thermal/warm_up_transient.h"

namespace imu_lab {
namespace pipeline {

struct AllanWarmUpOptions {
  bool enabled = false;
  double block_s = 1.0;  // block length of the means the fit sees
  thermal::WarmUpFitOptions fit;
};

struct AllanWarmUpChannel {
  std::optional<thermal::WarmUpFit> fit;  // empty: not fitted, see problem
  std::string problem;
};

struct AllanWarmUp {
  double block_s = 0.0;
  std::int64_t first_stamp_ns = 0;  // t = 0 of every model
  std::array<AllanWarmUpChannel, kAllanChannelCount> channels;

  // Subtracts each fitted channel's transient at the sample's stamp (the constant stays: the
  // Allan statistics do not see it, the offsets in allan_summary.yaml keep their meaning).
  void remove_from(AllanSample& sample) const;
};

// Throws ConfigError naming --warm-up-block-s for a block length that is not a positive number.
void check_warm_up_options(const AllanWarmUpOptions& options);

// Fits every channel of `blocks` (never throws for a failed fit: see the channel's problem).
AllanWarmUp fit_allan_warm_up(const thermal::WarmUpBlockMeans& blocks, const AllanWarmUpOptions& options);

// DIR/warm_up.yaml: per channel the model b(t) = c + sum a_k e^{-t/T_k} with sigmas and the
// F-test's p-values, the trend of what is left and, from the snapshot's curves, the ramp the
// Allan-Krobka dispersion takes out (AVAR - AKVAR = R^2 tau^2 / 2 at the largest common tau).
std::string format_warm_up_yaml(AllanInput input, const AllanWarmUp& warm_up, const allan::StreamingSnapshot& snapshot);

// One line per channel for a person: "gyro_x: 2 terms, T 1003 +- 85 s, ...".
std::string format_warm_up_lines(const std::string& prefix, AllanInput input, const AllanWarmUp& warm_up);

}  // namespace pipeline
}  // namespace imu_lab
