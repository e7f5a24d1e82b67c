#include "imu_lab/common/atomic_file.h"

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>

#include "imu_lab/common/config_error.h"

namespace {

std::string read_all(const std::string& path) {
  std::ifstream in(path);
  std::stringstream buffer;
  buffer << in.rdbuf();
  return buffer.str();
}

std::string scratch_directory() {
  char pattern[] = "/tmp/imu_lab_atomic_XXXXXX";
  const char* made = ::mkdtemp(pattern);
  if (made == nullptr) throw std::runtime_error("mkdtemp failed");
  return made;
}

TEST(AtomicFile, WritesWholeContent) {
  const std::string path = scratch_directory() + "/model.yaml";
  imu_lab::write_file_atomically(path, "a: 1\n");
  EXPECT_EQ(read_all(path), "a: 1\n");
  imu_lab::write_file_atomically(path, "a: 2\n");
  EXPECT_EQ(read_all(path), "a: 2\n");
}

TEST(AtomicFile, FailedWriteLeavesOldFileAndNoTemporary) {
  const std::string directory = scratch_directory();
  const std::string path = directory + "/model.yaml";
  imu_lab::write_file_atomically(path, "old\n");
  EXPECT_THROW(imu_lab::write_file_atomically(path,
                                              [](std::ostream& out) {
                                                out << "half of the new";
                                                throw std::runtime_error("interrupted");
                                              }),
               std::runtime_error);
  EXPECT_EQ(read_all(path), "old\n");
  const std::string listing = directory + "/listing";
  ASSERT_EQ(std::system(("ls " + directory + " > " + listing).c_str()), 0);
  EXPECT_EQ(read_all(listing), "listing\nmodel.yaml\n");
}

TEST(AtomicFile, UnwritableDirectoryNamesThePath) {
  try {
    imu_lab::write_file_atomically("/nonexistent_dir_for_imu_lab/x.yaml", "x");
    FAIL() << "expected an exception";
  } catch (const std::runtime_error& error) {
    EXPECT_NE(std::string(error.what()).find("/nonexistent_dir_for_imu_lab/x.yaml"), std::string::npos);
  }
}

std::string listing_of(const std::string& directory) {
  const std::string listing = directory + ".listing";
  if (std::system(("ls -A " + directory + " > " + listing).c_str()) != 0) return "(ls failed)";
  return read_all(listing);
}

// A set of three files in one directory, an earlier run's, to be replaced.
std::string old_set(const std::string& directory) {
  imu_lab::write_file_atomically(directory + "/model.yaml", "old model\n");
  imu_lab::write_file_atomically(directory + "/residuals.csv", "old residuals\n");
  imu_lab::write_file_atomically(directory + "/plot.png", "old plot\n");
  return listing_of(directory);
}

TEST(OutputSet, CommitReplacesTheWholeSet) {
  const std::string directory = scratch_directory();
  old_set(directory);
  imu_lab::OutputSet set;
  set.write(directory + "/model.yaml", "new model\n");
  imu_lab::write_file_atomically(set.stage(directory + "/residuals.csv"), "new residuals\n");
  set.remove_at_commit(directory + "/plot.png");  // this run makes no plot
  EXPECT_EQ(read_all(directory + "/model.yaml"), "old model\n") << "nothing moves before commit()";
  set.commit();
  EXPECT_EQ(read_all(directory + "/model.yaml"), "new model\n");
  EXPECT_EQ(read_all(directory + "/residuals.csv"), "new residuals\n");
  EXPECT_EQ(listing_of(directory), "model.yaml\nresiduals.csv\n") << "the stale plot and every temporary are gone";
}

// One output path blocked (a directory where a file should go): nothing of the new set appears,
// every old file is as it was, and no temporary is left behind.
TEST(OutputSet, ABlockedPathLeavesTheWholeOldSet) {
  const std::string directory = scratch_directory();
  imu_lab::write_file_atomically(directory + "/model.yaml", "old model\n");
  imu_lab::write_file_atomically(directory + "/plot.png", "old plot\n");
  ASSERT_EQ(::mkdir((directory + "/residuals.csv").c_str(), 0755), 0);
  ASSERT_EQ(::mkdir((directory + "/residuals.csv/blocker").c_str(), 0755), 0);
  const std::string before = listing_of(directory);
  imu_lab::OutputSet set;
  set.write(directory + "/model.yaml", "new model\n");
  set.write(directory + "/residuals.csv", "new residuals\n");
  set.write(directory + "/plot.png", "new plot\n");
  try {
    set.commit();
    FAIL() << "expected an OutputError";
  } catch (const imu_lab::OutputError& error) {
    EXPECT_NE(std::string(error.what()).find(directory + "/residuals.csv: a directory is in the way"),
              std::string::npos)
        << error.what();
  }
  EXPECT_EQ(read_all(directory + "/model.yaml"), "old model\n");
  EXPECT_EQ(read_all(directory + "/plot.png"), "old plot\n");
  EXPECT_EQ(listing_of(directory), before);
}

// A member staged but never written (its writer failed without saying so) stops the commit
// before anything moves.
TEST(OutputSet, AMemberNeverWrittenLeavesTheOldSet) {
  const std::string directory = scratch_directory();
  const std::string before = old_set(directory);
  imu_lab::OutputSet set;
  set.write(directory + "/model.yaml", "new model\n");
  set.stage(directory + "/plot.png");
  EXPECT_THROW(set.commit(), imu_lab::OutputError);
  EXPECT_EQ(read_all(directory + "/model.yaml"), "old model\n");
  EXPECT_EQ(listing_of(directory), before);
}

// A member's folder that does not exist yet (e.g. navigate -o nav/trajectory.csv, issue 46) is
// created with its missing parents; a set given up removes the folders it made, none other.
TEST(OutputSet, CreatesAMembersMissingFolderAndRemovesItIfDiscarded) {
  const std::string directory = scratch_directory();
  {
    imu_lab::OutputSet set;
    set.write(directory + "/nav/run/trajectory.csv", "rows\n");
    set.write(directory + "/nav/errors.csv", "errors\n");
    set.commit();
  }
  EXPECT_EQ(read_all(directory + "/nav/run/trajectory.csv"), "rows\n");
  EXPECT_EQ(listing_of(directory + "/nav"), "errors.csv\nrun\n");
  {
    imu_lab::OutputSet discarded;
    discarded.write(directory + "/other/deeper/trajectory.csv", "rows\n");
    discarded.write(directory + "/other/plot.png", "png\n");
  }
  struct stat status {};
  EXPECT_NE(::stat((directory + "/other").c_str(), &status), 0) << "the folders the discarded set made are gone";
  EXPECT_EQ(::stat((directory + "/nav").c_str(), &status), 0);
}

TEST(OutputSet, AStagingDirectoryBecomesTheDirectorysFilesAndIsRemoved) {
  const std::string directory = scratch_directory() + "/report";
  imu_lab::OutputSet set;
  const std::string staging = set.stage_directory(directory);
  imu_lab::write_file_atomically(staging + "/a.csv", "a\n");
  imu_lab::write_file_atomically(staging + "/b.csv", "b\n");
  EXPECT_EQ(listing_of(directory).find("a.csv"), std::string::npos);
  set.commit();
  EXPECT_EQ(listing_of(directory), "a.csv\nb.csv\n");
}

TEST(OutputSet, WithoutCommitNothingIsLeftAndACreatedDirectoryIsRemoved) {
  const std::string parent = scratch_directory();
  {
    imu_lab::OutputSet set;
    const std::string staging = set.stage_directory(parent + "/report");
    imu_lab::write_file_atomically(staging + "/a.csv", "a\n");
    imu_lab::write_file_atomically(set.stage(parent + "/model.yaml"), "m\n");
  }
  EXPECT_EQ(listing_of(parent), "");
}

}  // namespace
