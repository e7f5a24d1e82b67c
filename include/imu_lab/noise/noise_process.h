// Common shape of every noise process on one sensor axis.
#pragma once

#include <string>

namespace imu_lab {
namespace noise {

class NoiseProcess {
 public:
  virtual ~NoiseProcess() = default;

  // Average of this process's rate over [start_s, start_s + interval_s] (the increment divided
  // by the interval, as a real sensor reports). Calls must cover consecutive intervals of one
  // fixed length.
  virtual double next_interval_average(double start_s, double interval_s) = 0;

  // Expected overlapping Allan variance of the generated interval averages at tau, for data
  // sampled every tau0 (only bandwidth-defined processes depend on tau0).
  virtual double allan_variance(double tau_s, double tau0_s) const = 0;

  // Stationary variance of one interval average; 0 for deterministic or non-stationary terms.
  virtual double sample_variance(double interval_s) const = 0;

  virtual std::string kind() const = 0;
};

}  // namespace noise
}  // namespace imu_lab
