#include "imu_lab/common/atomic_file.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>

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

}  // namespace
