#include "imu_lab/allan/checkpoint.h"

#include <cstring>
#include <fstream>
#include <iterator>

#include "imu_lab/common/atomic_file.h"
#include "imu_lab/common/config_error.h"

namespace imu_lab {
namespace allan {
namespace {

constexpr char kMagic[8] = {'I', 'M', 'U', 'L', 'A', 'B', 'S', 'A'};
constexpr std::size_t kHeaderBytes = sizeof kMagic + 2 * sizeof(std::uint64_t);

std::uint64_t read_u64(const std::string& bytes, std::size_t offset) {
  std::uint64_t value;
  std::memcpy(&value, bytes.data() + offset, sizeof value);
  return value;
}

void append_u64(std::string& bytes, std::uint64_t value) {
  bytes.append(reinterpret_cast<const char*>(&value), sizeof value);
}

}  // namespace

std::uint64_t checkpoint_checksum(const std::string& bytes) {
  std::uint64_t hash = 14695981039346656037ULL;
  for (const char byte : bytes) {
    hash ^= static_cast<unsigned char>(byte);
    hash *= 1099511628211ULL;
  }
  return hash;
}

void write_checkpoint_file(const std::string& path, const std::string& payload) {
  std::string file(kMagic, sizeof kMagic);
  append_u64(file, kStreamingCheckpointVersion);
  append_u64(file, payload.size());
  file += payload;
  append_u64(file, checkpoint_checksum(payload));
  write_file_atomically(path, file);
}

std::string read_checkpoint_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError("checkpoint " + path + ": cannot open it; check the path");
  const std::string file((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::string refused = "checkpoint " + path + ": ";
  if (file.size() < kHeaderBytes + sizeof(std::uint64_t) || std::memcmp(file.data(), kMagic, sizeof kMagic) != 0) {
    throw InputError(refused + "not a streaming Allan checkpoint (wrong magic or too short)");
  }
  const std::uint64_t version = read_u64(file, sizeof kMagic);
  if (version != kStreamingCheckpointVersion) {
    throw InputError(refused + "format version " + std::to_string(version) + ", this build reads only version " +
                     std::to_string(kStreamingCheckpointVersion) +
                     "; resume it with the build that wrote it or start again");
  }
  const std::uint64_t payload_size = read_u64(file, sizeof kMagic + sizeof(std::uint64_t));
  if (file.size() - kHeaderBytes - sizeof(std::uint64_t) != payload_size) {
    throw InputError(refused + "truncated or padded: " + std::to_string(file.size()) +
                     " bytes where the header promises a " + std::to_string(payload_size) +
                     "-byte payload; start the run again");
  }
  std::string payload = file.substr(kHeaderBytes, payload_size);
  if (checkpoint_checksum(payload) != read_u64(file, kHeaderBytes + payload_size)) {
    throw InputError(refused + "checksum mismatch: the file is corrupted; start the run again");
  }
  return payload;
}

}  // namespace allan
}  // namespace imu_lab
