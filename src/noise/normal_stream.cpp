#include "imu_lab/noise/normal_stream.h"

#include <cmath>

namespace imu_lab {
namespace noise {

namespace {
// splitmix64 finaliser: spreads nearby seeds over the whole state space.
std::uint64_t mix64(std::uint64_t z) {
  z += 0x9e3779b97f4a7c15ULL;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

std::uint64_t fnv1a(const std::string& text) {
  std::uint64_t hash = 0xcbf29ce484222325ULL;
  for (unsigned char c : text) {
    hash ^= c;
    hash *= 0x100000001b3ULL;
  }
  return hash;
}
}  // namespace

std::uint64_t stream_seed(std::uint64_t seed, const std::string& stream_name) {
  return mix64(seed ^ fnv1a(stream_name));
}

double NormalStream::next_uniform() { return static_cast<double>(engine_() >> 11) * 0x1.0p-53; }

double NormalStream::next() {
  if (has_spare_) {
    has_spare_ = false;
    return spare_;
  }
  double u, v, s;
  do {
    u = 2.0 * next_uniform() - 1.0;
    v = 2.0 * next_uniform() - 1.0;
    s = u * u + v * v;
  } while (s >= 1.0 || s == 0.0);
  const double factor = std::sqrt(-2.0 * std::log(s) / s);
  spare_ = v * factor;
  has_spare_ = true;
  return u * factor;
}

}  // namespace noise
}  // namespace imu_lab
