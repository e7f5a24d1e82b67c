// Noise identification at the end of an Allan run, shared by the allan tool and the allan_monitor
// node (through allan_report.h): each triad fitted on the snapshot's OADEV curves (gyro channels
// 0-2, accel 3-5), then DIR/noise.yaml (identify/noise_report.h), DIR/kalibr_imu.yaml and
// DIR/kalibr_imu_chain.yaml for OpenVINS (identify/kalibr_yaml.h; update rate 1 / tau0, the run's
// topic) and one partial-curve CSV per
// channel, DIR/noise_partial_<channel>.csv (identify/partial_curves.h), for the plot.
// A triad whose fit fails (a record too short, unusable points) is reported in `problems` and
// left out; the other triad is still written, and the Allan curves never depend on the fit.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "imu_lab/allan/streaming_snapshot.h"
#include "imu_lab/identify/fit_options.h"
#include "imu_lab/identify/kalibr_yaml.h"
#include "imu_lab/identify/triad_fit.h"
#include "imu_lab/pipeline/allan_summary.h"

namespace imu_lab {
namespace pipeline {

struct AllanIdentifyOptions {
  bool enabled = true;
  identify::FitOptions fit;
  // 0: sigmas from the fit's moment covariance (fast). >= 2: parametric bootstrap with this many
  // replicas per axis (slow: each replica is a simulated record and a refit).
  int bootstrap_replicas = 0;
  std::uint64_t bootstrap_seed = 1;
};

struct AllanNoiseReport {
  std::vector<identify::TriadFit> triads;  // the triads that were identified
  std::optional<identify::KalibrImuNoise> kalibr;  // the Kalibr / OpenVINS numbers (both triads identified)
  std::vector<std::string> written;        // paths, in the order written
  std::vector<std::string> problems;       // why a triad or a file is missing; empty when all went well
};

// What is wrong with a bootstrap replica count ("" when it is 0 or at least 2).
std::string bootstrap_replicas_problem(int replicas);

// "noise_partial_gyro_x.csv", ...
std::string partial_curves_file_name(const std::string& channel_name);

// The record length the fit assumes: the accepted samples times tau0 (gaps excluded: the pooled
// segments hold no more data than that).
double record_length_s(const allan::StreamingSnapshot& snapshot);

// The fits alone (no files): `triads` and `problems` as below, `written` empty. Throws Cancelled
// (common/cancellation.h) when the thread's cancellation scope asks for it.
AllanNoiseReport identify_triads(const AllanRunDescription& run, const allan::StreamingSnapshot& snapshot,
                                 const AllanIdentifyOptions& options);

// Fits (identify_triads) and writes; never throws for a failed fit (see `problems`). Throws
// std::runtime_error when a file cannot be written.
AllanNoiseReport write_allan_noise_report(const std::string& directory, const AllanRunDescription& run,
                                          const allan::StreamingSnapshot& snapshot,
                                          const AllanIdentifyOptions& options);

// YAML block appended to allan_summary.yaml: "identification:" with status, sigma source,
// files and problems.
std::string format_identification_summary(const AllanIdentifyOptions& options, const AllanNoiseReport& report);

}  // namespace pipeline
}  // namespace imu_lab
