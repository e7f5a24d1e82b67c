// Files users keep (reports, models, calibrations, checkpoints) are written to a temporary
// file in the same directory, flushed to disk, then renamed over the target: a crash leaves
// either the old file or the new one, never half a file. Sets of files that belong together go
// through OutputSet, so a failure leaves the whole old set and success the whole new one.
#pragma once

#include <functional>
#include <ostream>
#include <string>
#include <vector>

namespace imu_lab {

// Calls `write` with a stream on a temporary file beside `path`, then renames it into place.
// Throws OutputError (config_error.h) naming the path and the cause if anything fails; the target
// is then untouched and no temporary is left.
void write_file_atomically(const std::string& path, const std::function<void(std::ostream&)>& write);

// Same for content that is already in memory.
void write_file_atomically(const std::string& path, const std::string& content);

// The last step of both (and of ros_io::AtomicBag): flushes the finished `temporary` to disk,
// renames it over `path` and flushes the directory entry. On failure removes `temporary` and
// throws OutputError starting with `what_is_written` (e.g. "cannot write bag x.bag").
void move_into_place(const std::string& temporary, const std::string& path, const std::string& what_is_written);

// A set of output files that change together: an Allan report (nine curves, summary, noise model,
// plot), a thermal model with its residuals and plot, a calibration with its Kalibr file and
// report. Every member is first written in full to a temporary beside its target, by any writer
// (write_file_atomically, a bag, a plotting child process); commit() then moves them all in. Each
// replaced file is kept aside (hard-linked) until every move succeeded and is put back if one
// fails, so a failure at any point -- a write, a blocked path, a failed plot -- leaves the whole
// old set, and success the whole new one. Each target holds its old or its new file at every
// moment, also if the process is killed (only a kill inside commit's few renames can leave some
// members old and some new). Not thread-safe.
class OutputSet {
 public:
  OutputSet() = default;
  ~OutputSet();  // without a successful commit(): removes what was staged, leaves the targets alone
  OutputSet(const OutputSet&) = delete;
  OutputSet& operator=(const OutputSet&) = delete;

  // The path to write `target`'s new content to (a temporary in the target's directory, created with
  // its missing parents if need be: removed again if the set is discarded).
  std::string stage(const std::string& target);
  // Stages and writes `target` (write_file_atomically into its temporary).
  void write(const std::string& target, const std::string& content);
  // A fresh temporary directory inside `directory` (created, as `directory` if missing) to write
  // any number of the set's files into by name: staging/<name> becomes directory/<name> at commit.
  std::string stage_directory(const std::string& directory);
  // A member of the set that this run does not produce (e.g. the plot of an earlier run made
  // without --no-plot): removed at commit, so the new set has no stale member.
  void remove_at_commit(const std::string& target);
  // Moves the staged files in and removes the members to remove. Throws OutputError naming the
  // path and the cause; the old set is then intact and the temporaries removed.
  void commit();

 private:
  struct Member {
    std::string staged;  // empty: remove the target
    std::string target;
  };
  void discard();

  std::vector<Member> members_;
  std::vector<std::pair<std::string, std::string>> staging_directories_;  // staging, target directory
  std::vector<std::string> removals_;
  std::vector<std::string> created_directories_;  // removed again if the set is discarded
  bool committed_ = false;
};

}  // namespace imu_lab
