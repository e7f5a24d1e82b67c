// The checkpoint file envelope: magic, format version, payload length, payload, checksum.
// Written atomically; a file of another version, a wrong magic, a short file or a checksum
// mismatch is refused with imu_lab::InputError naming the file and what to do.
#pragma once

#include <cstdint>
#include <string>

namespace imu_lab {
namespace allan {

// Bump whenever the payload layout changes: older files are then refused, never misread.
// 3: phase rings are linear block windows; their stored points and processed count are saved.
// 4: coarser levels have smaller rings (phase_block_points), so their blocks end elsewhere.
constexpr std::uint64_t kStreamingCheckpointVersion = 4;

void write_checkpoint_file(const std::string& path, const std::string& payload);
std::string read_checkpoint_file(const std::string& path);

// FNV-1a, 64 bit: catches truncation and bit rot (not tampering).
std::uint64_t checkpoint_checksum(const std::string& bytes);

}  // namespace allan
}  // namespace imu_lab
