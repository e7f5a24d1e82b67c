// The allan tool's cost against merely reading the bag, all measured in one run: for one hour of
// 400 Hz emulated data (made with the emulate tool if absent)
//   1. a loop that only reads and deserialises the messages with the rosbag API;
//   2. the Allan pass (run_allan_bag_pass: bag reader thread, streaming engine, final snapshot)
//      plus its report files (nine CSVs and the YAML summary), without identification or plot:
//      the figure;
//   3. the noise identification of both triads on that snapshot (the fits alone, then with their
//      files): its CPU time against the Allan pass's is issue 14's speed figure (target <= 1);
//   4. the allan tool itself as a user runs it (a child process: pass, files, identification and
//      the matplotlib plot), with its peak resident set;
//   5. the read loop again; ratios are to the faster read.
// Wall time and CPU time (every thread) are both printed: on a shared machine the wall time also
// measures the neighbours' load. Not a test: run by hand.
// The engine's exact range sets most of its per-sample cost, so it can be given.
//   bench/allan_vs_read [bag=/tmp/imu_lab_bench_400hz_1h.bag] [exact_max_averaging_factor=1000]
#include <rosbag/bag.h>
#include <rosbag/view.h>
#include <sensor_msgs/Imu.h>
#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <stdexcept>

#include "imu_lab/ros_io/bag/allan_bag_pass.h"
#include "imu_lab/ros_io/bag/allan_report.h"

namespace {

constexpr double kRate_hz = 400.0;
constexpr double kDuration_s = 3600.0;
const char* const kReportDirectory = "/tmp/imu_lab_bench_allan_report";

// The emulate tool, as a user makes a bag (its temperature topic rides along; every step below
// reads /imu/raw only).
void make_bag(const std::string& path) {
  const std::string command = "rosrun imu_lab emulate --profile tactical_mems --scenario static --duration-s " +
                              std::to_string(kDuration_s) + " --rate-hz " + std::to_string(kRate_hz) +
                              " --seed 1 --no-truth --no-increments --out " + path;
  if (std::system(command.c_str()) != 0) throw std::runtime_error("cannot make " + path + " with: " + command);
}

double process_cpu_s() {
  timespec now{};
  ::clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &now);
  return now.tv_sec + now.tv_nsec * 1e-9;
}

double children_cpu_s() {
  rusage usage{};
  ::getrusage(RUSAGE_CHILDREN, &usage);
  return usage.ru_utime.tv_sec + usage.ru_stime.tv_sec + 1e-6 * (usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
}

// Wall and CPU time of one step.
struct Cost {
  double wall_s = 0.0;
  double cpu_s = 0.0;
};

class Stopwatch {
 public:
  Cost elapsed() const {
    return {std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start_).count(),
            process_cpu_s() + children_cpu_s() - cpu_start_s_};
  }

 private:
  std::chrono::steady_clock::time_point wall_start_ = std::chrono::steady_clock::now();
  double cpu_start_s_ = process_cpu_s() + children_cpu_s();
};

// What any consumer of the bag pays: iterate and deserialise every message.
Cost read_only(const std::string& path, std::size_t* count) {
  const Stopwatch watch;
  rosbag::Bag bag(path, rosbag::bagmode::Read);
  rosbag::View view(bag, rosbag::TopicQuery("/imu/raw"));
  double checksum = 0.0;
  *count = 0;
  for (const rosbag::MessageInstance& instance : view) {
    const auto message = instance.instantiate<sensor_msgs::Imu>();
    checksum += message->angular_velocity.x;
    ++*count;
  }
  const Cost cost = watch.elapsed();
  if (checksum == 12345.678) std::printf(" ");  // keeps the loop from being optimised away
  return cost;
}

// The allan executable next to this one (both live in devel/lib/imu_lab).
std::string allan_tool_path() {
  return (std::filesystem::read_symlink("/proc/self/exe").parent_path() / "allan").string();
}

void print_step(const char* name, const Cost& cost, const Cost& read) {
  std::printf("%-58s %6.2f s wall %6.2f s CPU   ratio %5.2f wall %5.2f CPU\n", name, cost.wall_s, cost.cpu_s,
              cost.wall_s / read.wall_s, cost.cpu_s / read.cpu_s);
}

Cost operator+(const Cost& a, const Cost& b) { return {a.wall_s + b.wall_s, a.cpu_s + b.cpu_s}; }

}  // namespace

int main(int argc, char** argv) {
  const std::string bag = argc > 1 ? argv[1] : "/tmp/imu_lab_bench_400hz_1h.bag";
  if (!std::ifstream(bag).good()) make_bag(bag);
  const int exact_max_averaging_factor = argc > 2 ? std::atoi(argv[2]) : 1000;

  std::size_t count = 0;
  const Cost first_read = read_only(bag, &count);

  imu_lab::ros_io::AllanBagPassOptions options;
  options.topic = "/imu/raw";
  options.engine.exact_max_averaging_factor = exact_max_averaging_factor;
  Stopwatch watch;
  const auto result = imu_lab::ros_io::run_allan_bag_pass(bag, options);
  const Cost pass = watch.elapsed();
  imu_lab::pipeline::AllanRunDescription run;
  run.bag = bag;
  run.topic = result.topic;
  run.engine = result.engine;
  run.impulses = result.impulses;
  run.output_steps = result.output_steps;
  imu_lab::pipeline::AllanIdentifyOptions no_identify;
  no_identify.enabled = false;
  watch = Stopwatch();
  imu_lab::ros_io::write_allan_report(kReportDirectory, run, result.snapshot, false, no_identify);
  const Cost files = watch.elapsed();
  watch = Stopwatch();
  const auto fits = imu_lab::pipeline::identify_triads(run, result.snapshot, imu_lab::pipeline::AllanIdentifyOptions());
  const Cost fitting = watch.elapsed();
  if (fits.triads.size() != 2) throw std::runtime_error("identification failed: " + fits.problems.front());
  watch = Stopwatch();
  imu_lab::pipeline::write_allan_noise_report(kReportDirectory, run, result.snapshot,
                                              imu_lab::pipeline::AllanIdentifyOptions());
  const Cost identification = watch.elapsed();

  const std::string tool_command = allan_tool_path() + " " + bag + " --topic /imu/raw --exact-m " +
                                   std::to_string(exact_max_averaging_factor) + " --out " + kReportDirectory +
                                   " > /dev/null 2>&1";
  watch = Stopwatch();
  if (std::system(tool_command.c_str()) != 0) throw std::runtime_error("failed: " + tool_command);
  const Cost tool = watch.elapsed();
  rusage children{};
  ::getrusage(RUSAGE_CHILDREN, &children);

  const Cost second_read = read_only(bag, &count);
  const Cost read{std::min(first_read.wall_s, second_read.wall_s), std::min(first_read.cpu_s, second_read.cpu_s)};
  std::printf("%zu messages (%.0f s at %.0f Hz), engine exact up to m = %d\n", count, kDuration_s, kRate_hz,
              exact_max_averaging_factor);
  std::printf("read and deserialise only: %.2f s and %.2f s wall, %.2f s and %.2f s CPU\n", first_read.wall_s,
              second_read.wall_s, first_read.cpu_s, second_read.cpu_s);
  print_step("allan pass (reader thread, engine, snapshot)", pass, read);
  print_step("allan pass + CSV and summary files (target < 1.5)", pass + files, read);
  print_step("noise identification of both triads (fits only)", fitting, read);
  print_step("noise identification and its files", identification, read);
  print_step("allan tool (child: files, identification, plot)", tool, read);
  std::printf("identification of both triads %.2f s CPU, Allan pass %.2f s CPU: ratio %.2f (target <= 1)\n",
              fitting.cpu_s, pass.cpu_s, fitting.cpu_s / pass.cpu_s);
  rusage self{};
  ::getrusage(RUSAGE_SELF, &self);
  std::printf("peak resident set: allan tool %.1f MB; this process (read loop, pass) %.1f MB\n",
              children.ru_maxrss / 1024.0, self.ru_maxrss / 1024.0);
  return 0;
}
