// The allan tool's cost against merely reading the bag: for one hour of 400 Hz emulated data
// (made with the emulate tool if absent), the wall time of a loop that only reads and
// deserialises the messages with the rosbag API, then of the allan pass plus its report files
// (no plot), then the read loop again; the ratio is to the faster read. Also the peak resident
// set (getrusage). Not a test: run by hand.
// The engine's exact range sets most of its per-sample cost, so it can be given.
//   bench/allan_vs_read [bag=/tmp/imu_lab_bench_400hz_1h.bag] [exact_max_averaging_factor=1000]
#include <rosbag/bag.h>
#include <rosbag/view.h>
#include <sensor_msgs/Imu.h>
#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <ctime>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <stdexcept>

#include "imu_lab/ros/allan_bag_pass.h"
#include "imu_lab/ros/allan_report.h"

namespace {

constexpr double kRate_hz = 400.0;
constexpr double kDuration_s = 3600.0;

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// The emulate tool, as a user makes a bag (its temperature topic rides along; both loops below
// read /imu/raw only).
void make_bag(const std::string& path) {
  const std::string command = "rosrun imu_lab emulate --profile tactical_mems --scenario static --duration-s " +
                              std::to_string(kDuration_s) + " --rate-hz " + std::to_string(kRate_hz) +
                              " --seed 1 --no-truth --no-increments --out " + path;
  if (std::system(command.c_str()) != 0) throw std::runtime_error("cannot make " + path + " with: " + command);
}

// What any consumer of the bag pays: iterate and deserialise every message.
// CPU time of the whole process (every thread): on a shared machine the wall time also measures
// the neighbours' load, so both are printed.
double process_cpu_s() {
  timespec now{};
  ::clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &now);
  return now.tv_sec + now.tv_nsec * 1e-9;
}

double peak_resident_mb() {
  rusage usage{};
  ::getrusage(RUSAGE_SELF, &usage);
  return usage.ru_maxrss / 1024.0;
}

double read_only_s(const std::string& path, std::size_t* count) {
  const auto started = std::chrono::steady_clock::now();
  rosbag::Bag bag(path, rosbag::bagmode::Read);
  rosbag::View view(bag, rosbag::TopicQuery("/imu/raw"));
  double checksum = 0.0;
  *count = 0;
  for (const rosbag::MessageInstance& instance : view) {
    const auto message = instance.instantiate<sensor_msgs::Imu>();
    checksum += message->angular_velocity.x;
    ++*count;
  }
  const double elapsed = seconds_since(started);
  if (checksum == 12345.678) std::printf(" ");  // keeps the loop from being optimised away
  return elapsed;
}

}  // namespace

int main(int argc, char** argv) {
  const std::string bag = argc > 1 ? argv[1] : "/tmp/imu_lab_bench_400hz_1h.bag";
  if (!std::ifstream(bag).good()) make_bag(bag);

  std::size_t count = 0;
  double cpu_mark_s = process_cpu_s();
  const double first_read_s = read_only_s(bag, &count);
  const double read_cpu_s = process_cpu_s() - cpu_mark_s;
  const double read_peak_mb = peak_resident_mb();
  cpu_mark_s = process_cpu_s();
  const auto started = std::chrono::steady_clock::now();
  imu_lab::ros_io::AllanBagPassOptions options;
  options.topic = "/imu/raw";
  if (argc > 2) options.engine.exact_max_averaging_factor = std::atoi(argv[2]);
  const auto result = imu_lab::ros_io::run_allan_bag_pass(bag, options);
  const double pass_s = seconds_since(started);
  imu_lab::ros_io::AllanRunDescription run;
  run.bag = bag;
  run.topic = result.topic;
  run.engine = result.engine;
  imu_lab::ros_io::write_allan_report("/tmp/imu_lab_bench_allan_report", run, result.snapshot, false);
  const double allan_s = seconds_since(started);
  const double allan_cpu_s = process_cpu_s() - cpu_mark_s;
  const double second_read_s = read_only_s(bag, &count);
  const double read_s = std::min(first_read_s, second_read_s);

  rusage usage{};
  ::getrusage(RUSAGE_SELF, &usage);
  std::printf("%zu messages (%.0f s at %.0f Hz)\n", count, kDuration_s, kRate_hz);
  std::printf("read and deserialise only: %.2f s and %.2f s\n", first_read_s, second_read_s);
  std::printf("allan pass (exact up to m = %d): %.2f s; with the report files: %.2f s\n",
              options.engine.exact_max_averaging_factor, pass_s, allan_s);
  std::printf("ratio allan / read-only: %.2f in wall time (target < 1.5), %.2f in CPU time (%.2f s / %.2f s)\n",
              allan_s / read_s, allan_cpu_s / read_cpu_s, allan_cpu_s, read_cpu_s);
  std::printf("peak resident set: %.1f MB after the read-only loop (rosbag's index), %.1f MB at the end\n",
              read_peak_mb, usage.ru_maxrss / 1024.0);
  return 0;
}
