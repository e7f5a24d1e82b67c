// Where the emulator tests find the shipped profiles and scenarios.
#pragma once

#include <string>

#ifndef IMU_LAB_CONFIG_DIR
#define IMU_LAB_CONFIG_DIR "config"
#endif

namespace imu_lab {
namespace test {

inline std::string config_path(const std::string& relative) { return std::string(IMU_LAB_CONFIG_DIR) + "/" + relative; }

}  // namespace test
}  // namespace imu_lab
