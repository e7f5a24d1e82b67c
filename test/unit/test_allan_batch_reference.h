// Readers for the Stable32 reference outputs and the NBS14 data set, shared by the
// test_allan_batch_*.cpp suites.
#pragma once

#include <cstdint>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#ifndef IMU_LAB_TEST_DATA_DIR
#define IMU_LAB_TEST_DATA_DIR "test/data"
#endif

namespace imu_lab {
namespace allan {
namespace testing {

inline std::string stable32_path(const std::string& relative) {
  return std::string(IMU_LAB_TEST_DATA_DIR) + "/stable32/" + relative;
}

// One row of a Stable32 run: AF, Tau, #, Alpha, Min Sigma, Sigma, Max Sigma.
struct Stable32Row {
  int averaging_factor = 0;
  double tau_s = 0.0;
  long long term_count = 0;
  int alpha = 0;
  double lower = 0.0;
  double sigma = 0.0;
  double upper = 0.0;
  std::string sigma_text;  // as printed, to derive the rounding half-unit
};

inline std::vector<Stable32Row> read_stable32_table(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot open Stable32 reference " + path);
  std::vector<Stable32Row> rows;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream fields(line);
    Stable32Row row;
    std::string lower, upper;
    fields >> row.averaging_factor >> row.tau_s >> row.term_count >> row.alpha >> lower >> row.sigma_text >> upper;
    if (!fields) throw std::runtime_error("malformed Stable32 row in " + path + ": " + line);
    row.lower = std::stod(lower);
    row.sigma = std::stod(row.sigma_text);
    row.upper = std::stod(upper);
    rows.push_back(row);
  }
  return rows;
}

// Half a unit in the last printed digit of a number printed as d.dddde+xx.
inline double half_last_digit(const std::string& printed) {
  const std::size_t dot = printed.find('.');
  const std::size_t exponent = printed.find_first_of("eE");
  const int decimals = static_cast<int>(exponent - dot - 1);
  const int power = std::stoi(printed.substr(exponent + 1));
  double unit = 1.0;
  for (int i = 0; i < decimals - power; ++i) unit /= 10.0;
  for (int i = 0; i < power - decimals; ++i) unit *= 10.0;
  return 0.5 * unit;
}

// One number per line; lines starting with '#' are comments.
inline std::vector<double> read_column(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot open data file " + path);
  std::vector<double> values;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    values.push_back(std::stod(line));
  }
  return values;
}

// The OCXO record as fractional frequency: Hz / 1e7 - 1 (the deviations ignore the offset).
inline std::vector<double> read_ocxo_fractional_frequency() {
  std::vector<double> hz = read_column(stable32_path("ocxo/ocxo_frequency.txt"));
  for (double& value : hz) value = value / 1e7 - 1.0;
  return hz;
}

// NIST SP 1065's NBS14 1000-point frequency set: a Lehmer generator, n / (2^31 - 1).
inline std::vector<double> nbs14_frequency() {
  std::vector<double> values;
  std::uint64_t n = 1234567890;
  for (int i = 0; i < 1000; ++i) {
    values.push_back(static_cast<double>(n) / 2147483647.0);
    n = (16807 * n) % 2147483647;
  }
  return values;
}

}  // namespace testing
}  // namespace allan
}  // namespace imu_lab
