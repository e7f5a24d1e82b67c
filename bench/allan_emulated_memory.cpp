// The long run with the real emulator: a tactical MEMS IMU at rest (config/sensors/tactical_mems.yaml,
// config/scenarios/static.yaml) emulated at 1 kHz for 24 h into the streaming Allan engine with its
// default options, as the allan tool and node run it. Prints every simulated hour the engine's state
// size and the process's resident set, and the time the emulator and the engine each took. The
// core test (test_allan_streaming_memory.cpp) does the same run length with a cheap generator.
// Not a test: run by hand from the repository root.
//   bench/allan_emulated_memory [hours=24] [rate_hz=1000]
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <vector>

#include "imu_lab/allan/streaming_allan.h"
#include "imu_lab/emulator/imu_emulator.h"
#include "imu_lab/emulator/scenario.h"
#include "imu_lab/emulator/sensor_profile.h"

namespace {

constexpr std::size_t kChannels = 6;
constexpr std::size_t kBlockSamples = 4000;

double resident_megabytes() {
  std::ifstream statm("/proc/self/statm");
  std::size_t total_pages = 0, resident_pages = 0;
  statm >> total_pages >> resident_pages;
  return 1e-6 * static_cast<double>(resident_pages * static_cast<std::size_t>(::sysconf(_SC_PAGESIZE)));
}

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

int main(int argc, char** argv) {
  const double hours = argc > 1 ? std::atof(argv[1]) : 24.0;
  const double rate_hz = argc > 2 ? std::atof(argv[2]) : 1000.0;
  const auto profile = imu_lab::emulator::load_sensor_profile("config/sensors/tactical_mems.yaml");
  auto scenario = imu_lab::emulator::load_scenario("config/scenarios/static.yaml");
  imu_lab::emulator::EmulatorSettings settings;
  settings.rate_hz = rate_hz;
  imu_lab::emulator::ImuEmulator emulator(profile, scenario, settings);
  imu_lab::allan::StreamingAllan engine{imu_lab::allan::StreamingOptions{}};

  const auto samples = static_cast<long long>(hours * 3600.0 * rate_hz);
  const auto per_hour = static_cast<long long>(3600.0 * rate_hz);
  std::vector<std::int64_t> stamps_ns(kBlockSamples);
  std::vector<double> values(kBlockSamples * kChannels);
  double emulator_s = 0.0, engine_s = 0.0;
  std::printf("tactical_mems at rest, %.0f Hz, %.1f h (%lld samples), default engine options\n", rate_hz, hours,
              samples);
  for (long long done = 0; done < samples;) {
    const std::size_t block = static_cast<std::size_t>(std::min<long long>(kBlockSamples, samples - done));
    auto start = std::chrono::steady_clock::now();
    for (std::size_t k = 0; k < block; ++k) {
      const imu_lab::emulator::EmulatedSample sample = emulator.next();
      stamps_ns[k] = sample.stamp_ns;
      for (int axis = 0; axis < 3; ++axis) {
        values[k * kChannels + axis] = sample.angular_rate_rad_s[axis];
        values[k * kChannels + 3 + axis] = sample.specific_force_m_s2[axis];
      }
    }
    emulator_s += seconds_since(start);
    start = std::chrono::steady_clock::now();
    engine.push_block(stamps_ns.data(), values.data(), block);
    engine_s += seconds_since(start);
    const long long hour_before = done / per_hour;
    done += static_cast<long long>(block);
    if (done / per_hour != hour_before) {
      std::printf("hour %lld: engine state %zu bytes, resident %.1f MB; emulator %.0f s, engine %.0f s so far\n",
                  done / per_hour, engine.state_size_bytes(), resident_megabytes(), emulator_s, engine_s);
      std::fflush(stdout);
    }
  }
  std::printf("end: engine state %zu bytes, resident %.1f MB; emulator %.2f us, engine %.2f us per sample\n",
              engine.state_size_bytes(), resident_megabytes(), 1e6 * emulator_s / samples, 1e6 * engine_s / samples);
  return 0;
}
