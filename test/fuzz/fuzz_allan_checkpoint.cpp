// libFuzzer harness: the streaming Allan checkpoint loader (allan/checkpoint.h and
// StreamingAllan::load_checkpoint). An input that starts with the checkpoint magic is the whole
// file; any other input is a payload, wrapped in a valid envelope (right length and checksum) so
// that the fuzzer reaches the state decoder instead of stopping at the checksum.
// An accepted checkpoint must also resume (load_and_resume): the loaders check every invariant
// the next run relies on, so a crafted payload with a valid checksum is refused, not run.
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "fuzz_loader.h"
#include "imu_lab/allan/checkpoint.h"
#include "imu_lab/allan/streaming_allan.h"

namespace {

constexpr char kCheckpointMagic[] = "IMULABSA";  // checkpoint.cpp's magic, without the NUL

// write_checkpoint_file renames into place, which a memfd path cannot do: use a tmpfs directory.
// The path is never destroyed: the exit handler that removes the file runs after the statics'
// destructors would have freed it.
const std::string& envelope_path() {
  static const std::string* const path = [] {
    const char* base = ::access("/dev/shm", W_OK) == 0 ? "/dev/shm" : "/tmp";
    const auto* made = new std::string(std::string(base) + "/imu_lab_fuzz_checkpoint_" + std::to_string(::getpid()));
    std::atexit([] { ::unlink(envelope_path().c_str()); });
    return made;
  }();
  return *path;
}

// More samples than a level-0 block holds (kPhaseBlockPoints), so the resumed accumulators
// run over their block loops and the phase window moves its history at least once.
constexpr std::int64_t kResumedSampleCount = 4200;

// An accepted checkpoint must resume: a snapshot, then samples one tau0 apart (a ramp, so the
// differences are not all zero), then another snapshot.
void load_and_resume(const std::string& path) {
  imu_lab::allan::StreamingAllan engine = imu_lab::allan::StreamingAllan::load_checkpoint(path);
  engine.snapshot();
  // One tau0 (at most a second); stamps wrap around rather than overflow near the int64 end.
  const double tau0_ns = std::clamp(engine.snapshot().timing.tau0_s * 1e9, 1.0, 1e9);
  const auto interval_ns = static_cast<std::uint64_t>(tau0_ns);
  const std::size_t channel_count = engine.options().channel_count;
  std::vector<std::int64_t> stamps_ns(kResumedSampleCount);
  std::vector<double> values(kResumedSampleCount * channel_count);
  for (std::int64_t k = 0; k < kResumedSampleCount; ++k) {
    stamps_ns[k] =
        static_cast<std::int64_t>(static_cast<std::uint64_t>(engine.last_stamp_ns()) + (k + 1) * interval_ns);
    for (std::size_t c = 0; c < channel_count; ++c) values[k * channel_count + c] = 1e-3 * k + static_cast<double>(c);
  }
  engine.push_block(stamps_ns.data(), values.data(), kResumedSampleCount);
  engine.snapshot();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::size_t magic_size = sizeof kCheckpointMagic - 1;
  if (size >= magic_size && std::memcmp(data, kCheckpointMagic, magic_size) == 0) {
    return imu_lab::fuzz::refusals_allowed([&] { load_and_resume(imu_lab::fuzz::input_file_path(data, size)); });
  }
  imu_lab::allan::write_checkpoint_file(envelope_path(), std::string(reinterpret_cast<const char*>(data), size));
  return imu_lab::fuzz::refusals_allowed([] { load_and_resume(envelope_path()); });
}
