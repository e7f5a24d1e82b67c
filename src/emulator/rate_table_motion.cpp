// Rate table: from rest, each step changes the rate at the configured acceleration and holds.
#include "imu_lab/emulator/scenario_motions.h"
#include "imu_lab/emulator/table_motion.h"

namespace imu_lab {
namespace emulator {

std::unique_ptr<MotionSource> make_rate_table_motion(const ScenarioConfig& scenario) {
  const RateTableConfig& config = scenario.rate_table.value();
  RotationPhaseBuilder phases(config.mount_body_to_enu);
  for (const RateTableConfig::Step& step : config.steps) {
    phases.change_rate(config.axis_enu, step.rate_rad_s, config.acceleration_rad_s2);
    phases.hold_rate(config.axis_enu, step.hold_s);
  }
  return std::make_unique<TableMotion>(scenario, phases.finish());
}

}  // namespace emulator
}  // namespace imu_lab
