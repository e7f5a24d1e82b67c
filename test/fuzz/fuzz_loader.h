// Shared by the libFuzzer harnesses: hands the fuzzer's bytes to a loader and accepts only the
// loaders' documented refusals. Any other exception escapes, which libFuzzer reports as a
// crash: a loader must turn every bad file into a ConfigError or InputError naming the problem.
#pragma once

#include <sys/mman.h>
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "imu_lab/common/config_error.h"

namespace imu_lab {
namespace fuzz {

// The loaders take a path: the bytes go into an in-memory file (memfd) opened by that path, so
// an execution costs no disk I/O.
inline std::string input_file_path(const std::uint8_t* data, std::size_t size) {
  static const int descriptor = ::memfd_create("imu_lab_fuzz_input", 0);
  if (descriptor < 0 || ::ftruncate(descriptor, 0) != 0 ||
      ::pwrite(descriptor, data, size, 0) != static_cast<ssize_t>(size)) {
    std::abort();  // the harness itself is broken, not the loader
  }
  return "/proc/self/fd/" + std::to_string(descriptor);
}

// Runs `action`; the loaders' refusals are the expected outcome of most inputs.
template <class Action>
int refusals_allowed(Action action) {
  try {
    action();
  } catch (const ConfigError&) {
  } catch (const InputError&) {
  }
  return 0;
}

}  // namespace fuzz
}  // namespace imu_lab
