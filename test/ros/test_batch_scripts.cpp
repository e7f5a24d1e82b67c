// scripts/batch, scripts/slurm_array_example.sh and scripts/merge_results as a user runs them:
// a batch over recordings (one of them split) gives one result directory and log per recording
// and the merged table; the Slurm example's array tasks, run here as plain processes with
// SLURM_ARRAY_TASK_ID set, give the same merged table; a failed job is named and fails the batch.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "allan_test_support.h"
#include "ros_test_support.h"

namespace {

using imu_lab::test_support::file_exists;
using imu_lab::test_support::read_file;
using imu_lab::test_support::run_command;
using imu_lab::test_support::scratch_directory;
using imu_lab::test_support::white_noise_samples;
using imu_lab::test_support::write_imu_bag;

const std::string kScripts = std::string(IMU_LAB_CONFIG_DIR) + "/../scripts/";

std::size_t count_lines_containing(const std::string& text, const std::string& needle) {
  std::istringstream lines(text);
  std::size_t count = 0;
  for (std::string line; std::getline(lines, line);) count += line.find(needle) != std::string::npos ? 1 : 0;
  return count;
}

TEST(BatchScripts, BatchSlurmArrayAndMergeGiveOneTable) {
  const std::string directory = scratch_directory();
  const auto samples = white_noise_samples(6000, 5'000'000, 7);
  write_imu_bag(directory + "/unit_a.bag", samples);
  write_imu_bag(directory + "/unit_b_0.bag", {samples.begin(), samples.begin() + 2500});
  write_imu_bag(directory + "/unit_b_1.bag", {samples.begin() + 2500, samples.end()});
  write_imu_bag(directory + "/unit_c.bag", white_noise_samples(4000, 5'000'000, 8));
  const std::vector<std::string> recordings = {
      directory + "/unit_a.bag", directory + "/unit_b_0.bag," + directory + "/unit_b_1.bag", directory + "/unit_c.bag"};
  std::string list;
  for (const auto& recording : recordings) list += " " + recording;

  const auto batch =
      run_command(kScripts + "batch -o " + directory + "/batch -j 2" + list + " -- --no-plot --no-identify");
  ASSERT_EQ(batch.exit_code, 0) << batch.output;
  EXPECT_NE(batch.output.find("3/3 done"), std::string::npos) << batch.output;
  for (const char* name : {"unit_a", "unit_b_0", "unit_c"}) {
    EXPECT_TRUE(file_exists(directory + "/batch/" + name + "/oadev.csv")) << name;
    EXPECT_NE(read_file(directory + "/batch/" + name + "/job.log").find("allan: wrote"), std::string::npos) << name;
  }
  // The split recording analysed as one: the same curves as the unsplit bag of the same samples.
  EXPECT_EQ(read_file(directory + "/batch/unit_a/oadev.csv"), read_file(directory + "/batch/unit_b_0/oadev.csv"));

  // The Slurm example's array tasks as plain processes.
  {
    std::string lines;
    for (const auto& recording : recordings) lines += recording + "\n";
    std::ofstream(directory + "/recordings.txt") << lines;
  }
  for (int task = 0; task < 3; ++task) {
    const auto run =
        run_command("SLURM_ARRAY_TASK_ID=" + std::to_string(task) + " " + kScripts + "slurm_array_example.sh " +
                    directory + "/recordings.txt " + directory + "/array -- --no-plot --no-identify");
    ASSERT_EQ(run.exit_code, 0) << run.output;
  }
  const auto merged_batch =
      run_command(kScripts + "merge_results -o " + directory + "/merged_batch " + directory + "/batch/unit_a " +
                  directory + "/batch/unit_b_0 " + directory + "/batch/unit_c");
  ASSERT_EQ(merged_batch.exit_code, 0) << merged_batch.output;
  const auto merged_array =
      run_command(kScripts + "merge_results -o " + directory + "/merged_array " + directory + "/array/unit_a " +
                  directory + "/array/unit_b_0 " + directory + "/array/unit_c");
  ASSERT_EQ(merged_array.exit_code, 0) << merged_array.output;
  const std::string table = read_file(directory + "/merged_batch/results.csv");
  EXPECT_EQ(table, read_file(directory + "/merged_array/results.csv"));
  EXPECT_EQ(count_lines_containing(table, ",all,samples,"), 3u) << table;
  EXPECT_NE(table.find("unit_b_0,all,samples,6000"), std::string::npos) << table;
  EXPECT_EQ(count_lines_containing(table, "min_oadev_"), 36u) << table;  // value and tau, 6 channels, 3 recordings
  EXPECT_TRUE(file_exists(directory + "/merged_batch/results.md"));
}

TEST(BatchScripts, AFailedJobIsNamedAndFailsTheBatchAndTheMerge) {
  const std::string directory = scratch_directory();
  write_imu_bag(directory + "/good.bag", white_noise_samples(3000, 5'000'000, 9));
  const auto batch = run_command(kScripts + "batch -o " + directory + "/out -j 2 " + directory + "/good.bag " +
                                 directory + "/missing.bag -- --no-plot --no-identify");
  EXPECT_EQ(batch.exit_code, 1) << batch.output;
  EXPECT_NE(batch.output.find("missing failed"), std::string::npos) << batch.output;
  EXPECT_NE(batch.output.find(directory + "/out/missing/job.log"), std::string::npos) << batch.output;
  const auto merge = run_command(kScripts + "merge_results -o " + directory + "/merged " + directory + "/out/good " +
                                 directory + "/out/missing");
  EXPECT_EQ(merge.exit_code, 1) << merge.output;
  EXPECT_NE(merge.output.find(directory + "/out/missing"), std::string::npos) << merge.output;
}

// The batch's progress line at unit level: its ETA is the jobs left at the throughput so far, in
// the C++ tools' format (common/progress.h).
TEST(BatchScripts, ProgressLineGivesTheEtaFromTheThroughput) {
  const std::string program =
      "import importlib.machinery, sys; "
      "batch = importlib.machinery.SourceFileLoader('batch', sys.argv[1]).load_module(); "
      "print(batch.progress_line(3, 12, 2, 1, 45.0)); "   // 3 jobs in 45 s: 9 left take 135 s
      "print(batch.progress_line(0, 12, 2, 0, 10.0)); "   // no job done: no rate yet
      "print(batch.progress_line(1, 50, 4, 0, 300.0)); "  // 49 x 300 s = 4.08 h
      "print(batch.format_eta(42.4), batch.format_eta(725))";
  const auto run = run_command("/usr/bin/python3 -c \"" + program + "\" " + kScripts + "batch");
  ASSERT_EQ(run.exit_code, 0) << run.output;
  EXPECT_EQ(run.output,
            "batch: 3/12 done, 2 running, 1 failed, 45 s, ETA 2 min 15 s\n"
            "batch: 0/12 done, 2 running, 0 failed, 10 s, ETA ?\n"
            "batch: 1/50 done, 4 running, 0 failed, 300 s, ETA 4.1 h\n"
            "42 s 12 min 05 s\n");
}

}  // namespace
