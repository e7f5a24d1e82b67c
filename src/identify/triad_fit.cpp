#include "imu_lab/identify/triad_fit.h"

#include <cmath>
#include <sstream>

namespace imu_lab {
namespace identify {

namespace {
// Geometric mean of the fitted deviation over the fitted taus.
double log_mean_deviation(const FitResult& fit) {
  double sum = 0.0;
  for (const FitPoint& point : fit.points) sum += 0.5 * std::log(model_avar(fit.model, point.tau_s));
  return std::exp(sum / fit.points.size());
}
}  // namespace

std::string axis_name(SensorKind sensor, int axis) {
  static const char* const kAxes[3] = {"x", "y", "z"};
  return sensor_prefix(sensor) + "_" + kAxes[axis];
}

void flag_worst_axis(TriadFit* triad) {
  double worst = -1.0;
  for (int axis = 0; axis < 3; ++axis) {
    const double level = log_mean_deviation(triad->axes[axis]);
    if (level > worst) {
      worst = level;
      triad->worst_axis = axis;
    }
  }
  std::ostringstream reason;
  reason.precision(4);
  reason << "largest fitted deviation averaged (in log) over the fitted taus: " << worst << " "
         << rate_unit_key(triad->sensor);
  triad->worst_axis_reason = reason.str();
}

TriadFit fit_triad(SensorKind sensor, const std::array<std::vector<allan::StabilityPoint>, 3>& curves, double tau0_s,
                   double record_length_s, const FitOptions& options) {
  return fit_triad(sensor, curves, tau0_s, record_length_s, std::array<FitOptions, 3>{options, options, options});
}

TriadFit fit_triad(SensorKind sensor, const std::array<std::vector<allan::StabilityPoint>, 3>& curves, double tau0_s,
                   double record_length_s, const std::array<FitOptions, 3>& options_per_axis) {
  TriadFit triad;
  triad.sensor = sensor;
  for (int axis = 0; axis < 3; ++axis) {
    triad.axes[axis] = fit_noise_model(curves[axis], tau0_s, record_length_s, options_per_axis[axis]);
  }
  flag_worst_axis(&triad);
  return triad;
}

}  // namespace identify
}  // namespace imu_lab
