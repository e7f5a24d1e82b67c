// Errors in user-supplied configuration (profiles, scenarios, models): the message always
// names the offending key so the user knows what to fix.
#pragma once

#include <stdexcept>
#include <string>

namespace imu_lab {

class ConfigError : public std::runtime_error {
 public:
  // key: dotted path into the document, e.g. "gyro.noise.white_rate.density_rad_s_sqrt_hz".
  ConfigError(const std::string& source, const std::string& key, const std::string& problem)
      : std::runtime_error(source + ": " + key + ": " + problem), key_(key) {}
  const std::string& key() const { return key_; }

 private:
  std::string key_;
};

// Throws ConfigError(source, key, problem) unless `condition` holds: an options struct's check of
// one field.
inline void require_option(bool condition, const std::string& source, const char* key, const std::string& problem) {
  if (!condition) throw ConfigError(source, key, problem);
}

// Bad data (as opposed to bad configuration): NaN runs, unordered stamps, truncated files...
class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// An output that could not be written (disk full, a path blocked); the message names the file.
class OutputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace imu_lab
