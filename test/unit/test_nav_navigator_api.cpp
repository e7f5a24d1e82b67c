// Navigator refuses what it cannot integrate, naming the problem.
#include <gtest/gtest.h>

#include <limits>
#include <stdexcept>
#include <string>

#include "imu_lab/common/config_error.h"
#include "imu_lab/nav/navigator.h"

namespace imu_lab {
namespace nav {
namespace {

TEST(NavNavigatorApi, UpdateBeforeInitialiseIsAProgrammingError) {
  Navigator navigator;
  EXPECT_THROW(navigator.update(Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(), 0.01), std::logic_error);
}

TEST(NavNavigatorApi, RefusesBadInitialStates) {
  Navigator navigator;
  NavState state;
  state.latitude_rad = 95.0;  // degrees by mistake
  EXPECT_THROW(navigator.initialise(state), InputError);
  state.latitude_rad = 0.5;
  state.height_m = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(navigator.initialise(state), InputError);
  state.height_m = 0.0;
  navigator.initialise(state);
  EXPECT_TRUE(navigator.initialised());
}

TEST(NavNavigatorApi, RefusesBadIncrementsAndKeepsTheState) {
  Navigator navigator;
  navigator.initialise(NavState());
  EXPECT_THROW(navigator.update(Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(), 0.0), InputError);
  EXPECT_THROW(navigator.update(Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(), -0.01), InputError);
  EXPECT_THROW(navigator.update(Eigen::Vector3d::Constant(std::numeric_limits<double>::quiet_NaN()),
                                Eigen::Vector3d::Zero(), 0.01),
               InputError);
  EXPECT_EQ(navigator.state().stamp_s, 0.0);
}

TEST(NavNavigatorApi, RefusesAnInitialHeightBeyond1000Km) {
  Navigator navigator;
  NavState state;
  state.height_m = -1.001e6;
  EXPECT_THROW(navigator.initialise(state), InputError);
  state.height_m = 1.0e6;  // the limit itself is still a state
  navigator.initialise(state);
  EXPECT_TRUE(navigator.initialised());
}

// The navigator checks the state each step makes: absurd but finite increments (a unit error
// upstream) leave it unusable; update() says why, keeps the last usable state and stops.
TEST(NavNavigatorApi, StopsWhenAStepMakesTheStateUnusable) {
  Navigator navigator;
  navigator.initialise(NavState());
  const Eigen::Vector3d up_force(0.0, 0.0, 9.78);
  navigator.update(Eigen::Vector3d::Zero(), up_force * 0.01, 0.01);
  const NavState usable = navigator.state();
  // 1e14 m/s^2 up for 10 ms: 5e9 m of climb in one step.
  try {
    navigator.update(Eigen::Vector3d::Zero(), Eigen::Vector3d(0.0, 0.0, 1e12), 0.01);
    ADD_FAILURE() << "no UnusableStateError";
  } catch (const UnusableStateError& error) {
    EXPECT_NE(std::string(error.what()).find("beyond +-1000 km"), std::string::npos) << error.what();
  }
  EXPECT_FALSE(navigator.initialised());
  EXPECT_EQ(navigator.state().height_m, usable.height_m);
  EXPECT_EQ(navigator.state().stamp_s, usable.stamp_s);
  EXPECT_THROW(navigator.update(Eigen::Vector3d::Zero(), up_force * 0.01, 0.01), std::logic_error);
  // Finite increments whose step overflows: NaN/Inf in the state.
  navigator.initialise(NavState());
  EXPECT_THROW(navigator.update(Eigen::Vector3d::Constant(1e300), Eigen::Vector3d::Constant(1e300), 0.01),
               UnusableStateError);
  EXPECT_TRUE(state_problem(usable).empty());
}

TEST(NavNavigatorApi, RateAveragesBecomeIncrements) {
  const ImuIncrement increment =
      increment_from_mean_rates(Eigen::Vector3d(0.1, 0.2, 0.3), Eigen::Vector3d(0.0, 0.0, 9.8), 0.01);
  EXPECT_TRUE(increment.delta_angle_rad.isApprox(Eigen::Vector3d(1e-3, 2e-3, 3e-3)));
  EXPECT_TRUE(increment.delta_velocity_m_s.isApprox(Eigen::Vector3d(0.0, 0.0, 0.098)));
  EXPECT_EQ(increment.dt_s, 0.01);
  EXPECT_THROW(increment_from_mean_rates(Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(), 0.0), InputError);
}

}  // namespace
}  // namespace nav
}  // namespace imu_lab
