// The command-line arguments every bag tool that reads a recording shares: one bag or the split
// files of one (`rosbag record --split`, read as one recording in stamp order), and for the tools
// that analyse it, a time window (--start-s, --end-s from the first stamp) to leave out a warm-up.
// Header-only: CLI11 is the tools' dependency, not the library's. See doc/recordings.md.
#pragma once

#include <CLI/CLI.hpp>

#include <string>
#include <vector>

#include "imu_lab/common/tool_main.h"
#include "imu_lab/ros_io/bag/imu_bag_reader.h"

namespace imu_lab {
namespace ros_io {

struct RecordingArguments {
  std::vector<std::string> bags;
  TimeWindow window;
  // The tool's terminal progress (terminal_progress in common/progress.h), given to the readers.
  ProgressCallback on_progress;
  BagRecording recording() const {
    BagRecording files(bags, window);
    files.on_progress = on_progress;
    return files;
  }
  // What run_tool_main names in a refusal that does not name the input itself.
  ToolInput tool_input(const std::string& topic) const { return ToolInput{"bag", recording().name(), topic}; }
};

inline void add_recording_arguments(CLI::App& app, RecordingArguments& arguments, const std::string& what,
                                    bool with_window) {
  app.add_option("bags", arguments.bags,
                 what + ", or the split files of one recording (several files are read in stamp order as one)")
      ->required();
  if (!with_window) return;
  app.add_option("--start-s", arguments.window.start_s,
                 "use the recording from this many seconds after its first stamp")
      ->capture_default_str();
  app.add_option("--end-s", arguments.window.end_s,
                 "... up to this many seconds after its first stamp (default: the end)");
}

}  // namespace ros_io
}  // namespace imu_lab
