#include "imu_lab/emulator/kinematic_motion.h"

#include <algorithm>

#include "imu_lab/emulator/piecewise_quadrature.h"

namespace imu_lab {
namespace emulator {

namespace {
// Rate, force and temperature integrated together so truth_at runs once per node.
struct IntegrandValue {
  Eigen::Vector3d rate = Eigen::Vector3d::Zero();
  Eigen::Vector3d force = Eigen::Vector3d::Zero();
  double temperature = 0.0;
  IntegrandValue operator+(const IntegrandValue& o) const {
    return {rate + o.rate, force + o.force, temperature + o.temperature};
  }
  IntegrandValue operator*(double w) const { return {rate * w, force * w, temperature * w}; }
};
}  // namespace

TruthIncrement KinematicMotion::increment(double start_s, double interval_s) {
  const IntegrandValue integral = integrate_smooth_pieces(
      [this](double t) {
        const TruthState truth = truth_at(t);
        return IntegrandValue{truth.angular_rate_body_rad_s, truth.specific_force_body_m_s2, truth.temperature_c};
      },
      start_s, interval_s, breakpoints_s(), longest_smooth_piece_s(), IntegrandValue{});
  TruthIncrement result;
  result.delta_angle_rad = integral.rate;
  result.delta_velocity_m_s = integral.force;
  result.mean_temperature_c = integral.temperature / interval_s;
  return result;
}

SmoothPeriodicMotion::SmoothPeriodicMotion(const ScenarioConfig& scenario, double frequency_hz)
    : scenario_(scenario), longest_piece_s_(std::min(1.0, 1.0 / (2.0 * 3.14159265358979323846 * frequency_hz))) {}

}  // namespace emulator
}  // namespace imu_lab
