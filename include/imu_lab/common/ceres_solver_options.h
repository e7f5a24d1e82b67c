// The Ceres settings every small least-squares fit here uses (tens of parameters: the noise model,
// the bench calibration, the warm-up transient): dense QR, one thread (the same result on any
// machine, and no contention with a tool's own threads), no logging. Only the iteration limit and
// the tolerances differ between the fits.
#pragma once

#include <ceres/solver.h>

namespace imu_lab {

struct SolverLimits {
  int max_iterations = 100;
  double function_tolerance = 1e-10;
  double gradient_tolerance = 1e-12;
  double parameter_tolerance = 1e-10;
};

inline ceres::Solver::Options small_fit_solver_options(const SolverLimits& limits) {
  ceres::Solver::Options options;
  options.linear_solver_type = ceres::DENSE_QR;
  options.max_num_iterations = limits.max_iterations;
  options.function_tolerance = limits.function_tolerance;
  options.gradient_tolerance = limits.gradient_tolerance;
  options.parameter_tolerance = limits.parameter_tolerance;
  options.logging_type = ceres::SILENT;
  options.num_threads = 1;
  return options;
}

}  // namespace imu_lab
