// Files users keep survive a tool killed with SIGKILL in the middle of its run: at every moment
// tried, each output path holds either the file from the run before or the whole new one, byte for
// byte, never a part of one (the atomic writers, common/atomic_file.h and ros_io/bag/atomic_bag.h). The
// kill moments are spread over the tool's measured run time, so some land before, during and after
// its writing; the temporary files a killed writer leaves beside the targets are allowed.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <fcntl.h>
#include <fstream>
#include <map>
#include <utility>
#include <thread>

#include "imu_lab/ros_io/bag/imu_bag_reader.h"
#include "ros_test_support.h"

#ifndef IMU_LAB_BIN_DIR
#define IMU_LAB_BIN_DIR "."
#endif
#ifndef IMU_LAB_CONFIG_DIR
#define IMU_LAB_CONFIG_DIR "config"
#endif

namespace {

using imu_lab::test_support::list_directory;
using imu_lab::test_support::read_file;
using imu_lab::test_support::run_tool;
using imu_lab::test_support::scratch_directory;
using imu_lab::test_support::write_quick_twelve_position_schedule;

constexpr int kKillMoments = 8;

// Starts one of the package's tools (output discarded) and kills it with SIGKILL after delay_s
// unless it ended first. Returns true when the kill landed, false when the tool had finished.
bool run_tool_killed_after(const std::string& tool, const std::vector<std::string>& arguments, double delay_s) {
  const std::string binary = std::string(IMU_LAB_BIN_DIR) + "/" + tool;
  std::vector<char*> argv = {const_cast<char*>(binary.c_str())};
  for (const std::string& argument : arguments) argv.push_back(const_cast<char*>(argument.c_str()));
  argv.push_back(nullptr);
  const pid_t child = ::fork();
  if (child == 0) {
    const int null = ::open("/dev/null", O_WRONLY);
    ::dup2(null, STDOUT_FILENO);
    ::dup2(null, STDERR_FILENO);
    ::execv(binary.c_str(), argv.data());
    ::_exit(127);
  }
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(delay_s);
  int status = 0;
  while (std::chrono::steady_clock::now() < deadline) {
    if (::waitpid(child, &status, WNOHANG) == child) return false;
    std::this_thread::sleep_for(std::chrono::microseconds(200));
  }
  ::kill(child, SIGKILL);
  ::waitpid(child, &status, 0);
  return WIFSIGNALED(status);
}

double seconds_to_run(const std::string& tool, const std::string& arguments) {
  const auto start = std::chrono::steady_clock::now();
  const auto result = run_tool(tool, arguments);
  EXPECT_EQ(result.exit_code, 0) << result.output;
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

using FileContents = std::map<std::string, std::string>;  // file name -> bytes

// The files a finished run left in `directory`, by name (temporary leftovers excluded).
FileContents kept_files(const std::string& directory) {
  FileContents files;
  for (const std::string& name : list_directory(directory)) {
    if (name.find(".tmp") == std::string::npos) files[name] = read_file(directory + "/" + name);
  }
  return files;
}

void restore(const std::string& directory, const FileContents& files) {
  for (const auto& [name, bytes] : files) std::ofstream(directory + "/" + name, std::ios::binary) << bytes;
}

// Counts of what the trials found: how often each file was the old one or the new one.
struct Outcomes {
  int old_files = 0;
  int new_files = 0;
  int kills = 0;
};

// Restores the old files into `directory`, kills `tool` writing over them at kKillMoments moments
// spread over 1.3 x run_time_s, and checks every file after each kill.
Outcomes kill_at_spread_moments(const std::string& tool, const std::vector<std::string>& arguments,
                                const std::string& directory, double run_time_s, const FileContents& old_files,
                                const FileContents& new_files) {
  Outcomes outcomes;
  for (int moment = 0; moment < kKillMoments; ++moment) {
    restore(directory, old_files);
    const double delay_s = 1.3 * run_time_s * (moment + 0.5) / kKillMoments;
    outcomes.kills += run_tool_killed_after(tool, arguments, delay_s) ? 1 : 0;
    for (const auto& [name, new_bytes] : new_files) {
      const std::string bytes = read_file(directory + "/" + name);
      const auto old = old_files.find(name);
      const bool is_old = old != old_files.end() && bytes == old->second;
      const bool is_new = bytes == new_bytes;
      EXPECT_TRUE(is_old || is_new) << name << " after a kill at " << delay_s << " s is neither the old file ("
                                    << (old == old_files.end() ? 0 : old->second.size()) << " bytes) nor the new one ("
                                    << new_bytes.size() << " bytes) but " << bytes.size() << " bytes";
      outcomes.old_files += is_old ? 1 : 0;
      outcomes.new_files += is_new && !is_old ? 1 : 0;
    }
  }
  std::printf("%s: %d of %d runs killed; files found old %d times, new %d times\n", tool.c_str(), outcomes.kills,
              kKillMoments, outcomes.old_files, outcomes.new_files);
  return outcomes;
}

std::vector<std::string> emulate_arguments(const std::string& out, int seed, int duration_s) {
  return {"--profile",
          std::string(IMU_LAB_CONFIG_DIR) + "/sensors/tactical_mems.yaml",
          "--duration-s",
          std::to_string(duration_s),
          "--rate-hz",
          "200",
          "--seed",
          std::to_string(seed),
          "--no-truth",
          "--out",
          out};
}

std::string joined(const std::vector<std::string>& arguments) {
  std::string text;
  for (const std::string& argument : arguments) text += "'" + argument + "' ";
  return text;
}

// The bag grows over the whole run, so most kills land mid-write.
TEST(AtomicWritesKilled, EmulateLeavesTheOldBagOrTheWholeNewOne) {
  const std::string directory = scratch_directory();
  const std::string out = directory + "/run.bag";
  ASSERT_EQ(run_tool("emulate", joined(emulate_arguments(out, 1, 60))).exit_code, 0);
  const std::string reference_directory = scratch_directory();
  const auto new_arguments = emulate_arguments(out, 2, 300);
  const double run_time_s =
      seconds_to_run("emulate", joined(emulate_arguments(reference_directory + "/run.bag", 2, 300)));
  const Outcomes outcomes = kill_at_spread_moments("emulate", new_arguments, directory, run_time_s,
                                                   kept_files(directory), kept_files(reference_directory));
  EXPECT_GE(outcomes.kills, kKillMoments / 4);  // the run time varies with the load: 4-8 land
  EXPECT_GE(outcomes.old_files, 1);
  // Whatever is there is a bag that reads to the end.
  std::size_t samples = 0;
  imu_lab::ros_io::for_each_imu(out, "/imu/raw", [&](const imu_lab::io::ImuRecord&) { ++samples; });
  EXPECT_TRUE(samples == 60u * 200 || samples == 300u * 200) << samples;
}

// The report's files (CSVs, summary, noise model) are written at the end of the pass, one by one:
// each is found old or new, whole.
TEST(AtomicWritesKilled, AllanLeavesEachReportFileOldOrWholeNew) {
  const std::string directory = scratch_directory();
  const std::string old_bag = directory + "/old.bag", new_bag = directory + "/new.bag";
  ASSERT_EQ(run_tool("emulate", joined(emulate_arguments(old_bag, 3, 60))).exit_code, 0);
  ASSERT_EQ(run_tool("emulate", joined(emulate_arguments(new_bag, 4, 300))).exit_code, 0);
  const std::string report = directory + "/report";
  ASSERT_EQ(run_tool("allan", old_bag + " --no-plot --out " + report).exit_code, 0);
  const std::string reference = directory + "/reference";
  const double run_time_s = seconds_to_run("allan", new_bag + " --no-plot --out " + reference);
  const FileContents new_files = kept_files(reference);
  ASSERT_GE(new_files.size(), 10u);
  const Outcomes outcomes = kill_at_spread_moments("allan", {new_bag, "--no-plot", "--out", report}, report, run_time_s,
                                                   kept_files(report), new_files);
  EXPECT_GE(outcomes.kills, kKillMoments / 4);  // the run time varies with the load: 4-8 land
  EXPECT_GE(outcomes.old_files, 1);
}

// fit_calibration writes the calibration, the Kalibr/OpenVINS chain and the report one by one
// after its fit: each is found old or new, whole.
TEST(AtomicWritesKilled, FitCalibrationLeavesEachFileOldOrWholeNew) {
  const std::string directory = scratch_directory();
  const std::string schedule = write_quick_twelve_position_schedule(directory);
  const std::string old_bag = directory + "/old.bag", new_bag = directory + "/new.bag";
  for (const auto& [bag, seed] : {std::pair<std::string, int>{old_bag, 5}, {new_bag, 6}}) {
    const auto made = run_tool("emulate", "--profile tactical_mems --scenario " + schedule + " --rate-hz 100 --seed " +
                                              std::to_string(seed) + " --no-truth --out " + bag);
    ASSERT_EQ(made.exit_code, 0) << made.output;
  }
  const std::string kept = directory + "/kept", reference = directory + "/reference";
  for (const std::string& folder : {kept, reference}) ASSERT_EQ(::mkdir(folder.c_str(), 0755), 0) << folder;
  ASSERT_EQ(run_tool("fit_calibration", old_bag + " --schedule " + schedule + " --out " + kept + "/imu.yaml").exit_code,
            0);
  const double run_time_s =
      seconds_to_run("fit_calibration", new_bag + " --schedule " + schedule + " --out " + reference + "/imu.yaml");
  const FileContents new_files = kept_files(reference);
  ASSERT_EQ(new_files.size(), 3u);
  const Outcomes outcomes =
      kill_at_spread_moments("fit_calibration", {new_bag, "--schedule", schedule, "--out", kept + "/imu.yaml"}, kept,
                             run_time_s, kept_files(kept), new_files);
  EXPECT_GE(outcomes.kills, kKillMoments / 4);  // the run time varies with the load: 4-8 land
  EXPECT_GE(outcomes.old_files, 1);
}

}  // namespace
