// Reproducible standard-normal deviates. std::normal_distribution's output is
// implementation-defined, so the deviates are made here from mt19937_64 bits (Marsaglia polar
// method) and are identical on every platform for a given seed.
#pragma once

#include <cstdint>
#include <random>
#include <string>

namespace imu_lab {
namespace noise {

// Seed of one named stream: the user's seed mixed with a hash of the stream's name, so adding
// a process never shifts another process's deviates.
std::uint64_t stream_seed(std::uint64_t seed, const std::string& stream_name);

class NormalStream {
 public:
  explicit NormalStream(std::uint64_t stream_seed) : engine_(stream_seed) {}
  double next();
  // Uniform on [0, 1) with 53 random bits.
  double next_uniform();

 private:
  std::mt19937_64 engine_;
  bool has_spare_ = false;
  double spare_ = 0.0;
};

}  // namespace noise
}  // namespace imu_lab
