// Factories for the motion of each scenario type (one source file each); make_motion_source
// picks one by ScenarioConfig::type.
#pragma once

#include <memory>

#include "imu_lab/emulator/motion_source.h"
#include "imu_lab/emulator/scenario.h"

namespace imu_lab {
namespace emulator {

std::unique_ptr<MotionSource> make_multi_position_motion(const ScenarioConfig& scenario);
std::unique_ptr<MotionSource> make_rate_table_motion(const ScenarioConfig& scenario);
std::unique_ptr<MotionSource> make_coning_motion(const ScenarioConfig& scenario);
std::unique_ptr<MotionSource> make_sculling_motion(const ScenarioConfig& scenario);
std::unique_ptr<MotionSource> make_trajectory_motion(const ScenarioConfig& scenario);

}  // namespace emulator
}  // namespace imu_lab
