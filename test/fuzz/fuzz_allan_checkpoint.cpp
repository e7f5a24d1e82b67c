// libFuzzer harness: the streaming Allan checkpoint loader (allan/checkpoint.h and
// StreamingAllan::load_checkpoint). An input that starts with the checkpoint magic is the whole
// file; any other input is a payload, wrapped in a valid envelope (right length and checksum) so
// that the fuzzer reaches the state decoder instead of stopping at the checksum.
// With IMU_LAB_FUZZ_CHECKPOINT_RESUME=1 an accepted checkpoint must also resume: a snapshot and
// one more sample. Not in the test step yet: the accumulators' load() does not check every
// invariant their next run relies on (a ring's history before its first unprocessed point, the
// next non-overlapping end), so a crafted payload with a valid checksum can still crash there.
#include <unistd.h>

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
std::string envelope_path() {
  static const std::string path = [] {
    const char* base = ::access("/dev/shm", W_OK) == 0 ? "/dev/shm" : "/tmp";
    std::string made = std::string(base) + "/imu_lab_fuzz_checkpoint_" + std::to_string(::getpid());
    std::atexit([] { ::unlink(envelope_path().c_str()); });
    return made;
  }();
  return path;
}

void load_and_maybe_resume(const std::string& path) {
  static const bool resume = std::getenv("IMU_LAB_FUZZ_CHECKPOINT_RESUME") != nullptr &&
                             std::string(std::getenv("IMU_LAB_FUZZ_CHECKPOINT_RESUME")) == "1";
  imu_lab::allan::StreamingAllan engine = imu_lab::allan::StreamingAllan::load_checkpoint(path);
  if (!resume) return;
  engine.snapshot();
  const std::vector<double> sample(engine.options().channel_count, 1.0);
  engine.push(engine.last_stamp_ns() + 1000000, sample);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::size_t magic_size = sizeof kCheckpointMagic - 1;
  if (size >= magic_size && std::memcmp(data, kCheckpointMagic, magic_size) == 0) {
    return imu_lab::fuzz::refusals_allowed([&] { load_and_maybe_resume(imu_lab::fuzz::input_file_path(data, size)); });
  }
  imu_lab::allan::write_checkpoint_file(envelope_path(), std::string(reinterpret_cast<const char*>(data), size));
  return imu_lab::fuzz::refusals_allowed([] { load_and_maybe_resume(envelope_path()); });
}
