// Multi-position sequence: dwell, then a trapezoidal rest-to-rest turn about the single axis
// that carries one orientation into the next (the eigen-axis of C_next C_this^T).
#include "imu_lab/emulator/scenario_motions.h"
#include "imu_lab/emulator/table_motion.h"

namespace imu_lab {
namespace emulator {

std::unique_ptr<MotionSource> make_multi_position_motion(const ScenarioConfig& scenario) {
  const MultiPositionConfig& config = scenario.multi_position.value();
  const auto& positions = config.positions;
  RotationPhaseBuilder phases(positions.front().attitude_body_to_enu);
  for (std::size_t i = 0; i < positions.size(); ++i) {
    phases.dwell(positions[i].attitude_body_to_enu, positions[i].dwell_s);
    if (i + 1 == positions.size()) break;
    const Eigen::AngleAxisd turn(positions[i + 1].attitude_body_to_enu * positions[i].attitude_body_to_enu.conjugate());
    if (turn.angle() == 0.0) continue;
    phases.trapezoidal_turn(turn.axis(), turn.angle(), config.move_rate_rad_s, config.move_acceleration_rad_s2);
  }
  return std::make_unique<TableMotion>(scenario, phases.finish());
}

}  // namespace emulator
}  // namespace imu_lab
