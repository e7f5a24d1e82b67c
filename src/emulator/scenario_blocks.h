// Readers of a scenario's type blocks and of its thermal block (private to src/emulator).
// Angles are read in degrees and stored in radians; every refusal names the dotted key.
#pragma once

#include "imu_lab/common/yaml_fields.h"
#include "imu_lab/emulator/scenario.h"

namespace imu_lab {
namespace emulator {

MultiPositionConfig read_multi_position(const YamlFields& f);
RateTableConfig read_rate_table(const YamlFields& f);
ConingConfig read_coning(const YamlFields& f);
ScullingConfig read_sculling(const YamlFields& f);
TrajectoryConfig read_trajectory(const YamlFields& f);
ThermalConfig read_thermal(const YamlFields& f);

}  // namespace emulator
}  // namespace imu_lab
