// Files users keep (reports, models, calibrations, checkpoints) are written to a temporary
// file in the same directory, flushed to disk, then renamed over the target: a crash leaves
// either the old file or the new one, never half a file.
#pragma once

#include <functional>
#include <ostream>
#include <string>

namespace imu_lab {

// Calls `write` with a stream on a temporary file beside `path`, then renames it into place.
// Throws std::runtime_error naming the path if anything fails; the target is then untouched.
void write_file_atomically(const std::string& path, const std::function<void(std::ostream&)>& write);

// Same for content that is already in memory.
void write_file_atomically(const std::string& path, const std::string& content);

// The last step of both (and of ros_io::AtomicBag): flushes the finished `temporary` to disk,
// renames it over `path` and flushes the directory entry. On failure removes `temporary` and
// throws std::runtime_error starting with `what_is_written` (e.g. "cannot write bag x.bag").
void move_into_place(const std::string& temporary, const std::string& path, const std::string& what_is_written);

}  // namespace imu_lab
