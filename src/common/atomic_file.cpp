#include "imu_lab/common/atomic_file.h"

#include <dirent.h>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <set>

#include "imu_lab/common/config_error.h"

namespace imu_lab {
namespace {

std::string directory_of(const std::string& path) {
  const auto slash = path.find_last_of('/');
  if (slash == std::string::npos) return ".";
  if (slash == 0) return "/";
  return path.substr(0, slash);
}

// rename() is atomic only once the data and the directory entry are on disk.
void sync_path(const std::string& path, int flags) {
  const int fd = ::open(path.c_str(), flags);
  if (fd < 0) return;
  ::fsync(fd);
  ::close(fd);
}

std::string temporary_beside(const std::string& path, const char* role) {
  static int counter = 0;
  return path + "." + role + ".tmp." + std::to_string(::getpid()) + "." + std::to_string(++counter);
}

bool exists(const std::string& path, struct stat* status) { return ::lstat(path.c_str(), status) == 0; }

// Creates `directory` with any missing parents (a report's folder need not exist yet); returns
// the ones it made, deepest first, so that a discarded set can remove them again.
std::vector<std::string> create_missing_directories(const std::string& directory) {
  std::vector<std::string> missing;
  struct stat status {};
  for (std::string level = directory; !exists(level, &status); level = directory_of(level)) {
    missing.push_back(level);
    if (level == directory_of(level)) break;
  }
  std::error_code error;
  std::filesystem::create_directories(directory, error);
  if (error) throw OutputError("cannot create the directory " + directory + ": " + error.message());
  return missing;
}

std::vector<std::string> regular_files_in(const std::string& directory) {
  std::vector<std::string> names;
  DIR* listing = ::opendir(directory.c_str());
  if (listing == nullptr) return names;
  while (const dirent* entry = ::readdir(listing)) {
    const std::string name = entry->d_name;
    struct stat status {};
    if (name != "." && name != ".." && exists(directory + "/" + name, &status) && S_ISREG(status.st_mode)) {
      names.push_back(name);
    }
  }
  ::closedir(listing);
  std::sort(names.begin(), names.end());
  return names;
}

}  // namespace

void write_file_atomically(const std::string& path, const std::function<void(std::ostream&)>& write) {
  const std::string temporary = path + ".tmp." + std::to_string(::getpid());
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    if (!out) {
      throw OutputError("cannot write " + path + ": cannot create " + temporary + ": " + std::strerror(errno));
    }
    try {
      write(out);
    } catch (...) {
      out.close();
      std::remove(temporary.c_str());
      throw;
    }
    errno = 0;
    out.flush();
    out.close();
    if (!out) {
      const std::string reason = errno != 0 ? std::strerror(errno) : "write error";
      std::remove(temporary.c_str());
      throw OutputError("cannot write " + path + ": writing " + temporary + " failed: " + reason);
    }
  }
  move_into_place(temporary, path, "cannot write " + path);
}

void move_into_place(const std::string& temporary, const std::string& path, const std::string& what_is_written) {
  sync_path(temporary, O_RDONLY);
  if (std::rename(temporary.c_str(), path.c_str()) != 0) {
    const std::string reason = std::strerror(errno);
    std::remove(temporary.c_str());
    throw OutputError(what_is_written + ": rename failed: " + reason);
  }
  sync_path(directory_of(path), O_RDONLY | O_DIRECTORY);
}

void write_file_atomically(const std::string& path, const std::string& content) {
  write_file_atomically(path, [&content](std::ostream& out) { out << content; });
}

OutputSet::~OutputSet() {
  if (!committed_) discard();
}

std::string OutputSet::stage(const std::string& target) {
  for (std::string& made : create_missing_directories(directory_of(target))) created_directories_.push_back(made);
  const std::string staged = temporary_beside(target, "new");
  members_.push_back({staged, target});
  return staged;
}

void OutputSet::write(const std::string& target, const std::string& content) {
  write_file_atomically(stage(target), content);
}

std::string OutputSet::stage_directory(const std::string& directory) {
  for (std::string& made : create_missing_directories(directory)) created_directories_.push_back(made);
  const std::string staging = temporary_beside(directory + "/.staging", "set");
  if (::mkdir(staging.c_str(), 0777) != 0) {
    throw OutputError("cannot write into " + directory + ": cannot create " + staging + ": " + std::strerror(errno));
  }
  staging_directories_.push_back({staging, directory});
  return staging;
}

void OutputSet::remove_at_commit(const std::string& target) { removals_.push_back(target); }

void OutputSet::commit() {
  for (const auto& [staging, directory] : staging_directories_) {
    for (const std::string& name : regular_files_in(staging))
      members_.push_back({staging + "/" + name, directory + "/" + name});
  }
  std::set<std::string> produced;
  for (const Member& member : members_) produced.insert(member.target);
  for (const std::string& target : removals_) {
    if (produced.count(target) == 0) members_.push_back({"", target});
  }

  struct Step {
    const Member* member;
    std::string backup;  // the old file, hard-linked aside
    bool done = false;
  };
  std::vector<Step> steps;
  std::string failure;
  const auto fail = [&](const std::string& target, const std::string& problem) {
    failure = "cannot write " + target + ": " + problem + "; the previous files are kept as they were";
  };
  // 1. Every old file aside, before anything is replaced.
  for (const Member& member : members_) {
    struct stat status {};
    if (!member.staged.empty() && !exists(member.staged, &status)) {
      fail(member.target, "its new content was not written");
      break;
    }
    Step step{&member, "", false};
    if (exists(member.target, &status)) {
      if (S_ISDIR(status.st_mode)) {
        fail(member.target, "a directory is in the way");
        break;
      }
      step.backup = temporary_beside(member.target, "old");
      if (::link(member.target.c_str(), step.backup.c_str()) != 0) {
        fail(member.target, std::string("cannot keep the old file aside: ") + std::strerror(errno));
        break;
      }
    } else if (member.staged.empty()) {
      continue;  // nothing to remove
    }
    steps.push_back(step);
  }
  // 2. The new files in, the stale ones out.
  if (failure.empty()) {
    for (Step& step : steps) {
      const Member& member = *step.member;
      if (!member.staged.empty()) sync_path(member.staged, O_RDONLY);
      const int result = member.staged.empty() ? ::unlink(member.target.c_str())
                                               : std::rename(member.staged.c_str(), member.target.c_str());
      if (result != 0) {
        fail(member.target, std::strerror(errno));
        break;
      }
      step.done = true;
    }
  }
  if (!failure.empty()) {
    for (auto step = steps.rbegin(); step != steps.rend(); ++step) {
      if (step->done && !step->backup.empty()) {
        std::rename(step->backup.c_str(), step->member->target.c_str());
      } else if (step->done) {
        ::unlink(step->member->target.c_str());
      } else if (!step->backup.empty()) {
        ::unlink(step->backup.c_str());
      }
    }
    discard();
    throw OutputError(failure);
  }
  std::set<std::string> directories;
  for (const Step& step : steps) {
    if (!step.backup.empty()) ::unlink(step.backup.c_str());
    directories.insert(directory_of(step.member->target));
  }
  for (const std::string& directory : directories) sync_path(directory, O_RDONLY | O_DIRECTORY);
  for (const auto& staging : staging_directories_) ::rmdir(staging.first.c_str());
  committed_ = true;
}

void OutputSet::discard() {
  for (const Member& member : members_) {
    if (!member.staged.empty()) ::unlink(member.staged.c_str());
  }
  for (const auto& staging : staging_directories_) {
    for (const std::string& name : regular_files_in(staging.first)) ::unlink((staging.first + "/" + name).c_str());
    ::rmdir(staging.first.c_str());
  }
  // Deepest first (longest path first: a child is longer than its parent); each only if left empty.
  std::vector<std::string> created = created_directories_;
  std::sort(created.begin(), created.end(),
            [](const std::string& a, const std::string& b) { return a.size() > b.size(); });
  for (const std::string& directory : created) ::rmdir(directory.c_str());
}

}  // namespace imu_lab
