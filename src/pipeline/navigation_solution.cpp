#include "imu_lab/pipeline/navigation_solution.h"

#include "imu_lab/common/stamps.h"
#include "imu_lab/nav/rotation.h"

namespace imu_lab {
namespace pipeline {

NavigationSolution make_solution(const NavigationSession& session, const nav::LocalEnuFrame& world) {
  const nav::NavState& state = session.state();
  NavigationSolution solution;
  solution.stamp_ns = session.stamp_ns();
  solution.latitude_rad = state.latitude_rad;
  solution.longitude_rad = state.longitude_rad;
  solution.height_m = state.height_m;
  solution.position_enu_m = world.enu_m(state.latitude_rad, state.longitude_rad, state.height_m);
  solution.velocity_enu_m_s = state.velocity_enu_m_s;
  solution.q_body_to_enu = state.q_body_to_enu;
  solution.roll_pitch_yaw_rad = roll_pitch_yaw_from_quaternion(state.q_body_to_enu);
  solution.velocity_body_m_s = state.q_body_to_enu.conjugate() * state.velocity_enu_m_s;
  solution.angular_rate_body_rad_s = session.body_rate_wrt_enu_rad_s();
  return solution;
}

NavigationError navigation_error(const NavigationSolution& solution, const io::TruthRecord& truth,
                                 const nav::LocalEnuFrame& world, std::int64_t alignment_stamp_ns) {
  NavigationError error;
  error.stamp_ns = solution.stamp_ns;
  error.time_since_alignment_s = seconds_between(alignment_stamp_ns, solution.stamp_ns);
  error.position_error_enu_m =
      solution.position_enu_m - world.enu_m(truth.latitude_rad, truth.longitude_rad, truth.height_m);
  error.horizontal_position_error_m = error.position_error_enu_m.head<2>().norm();
  error.height_error_m = solution.height_m - truth.height_m;
  error.velocity_error_enu_m_s = solution.velocity_enu_m_s - truth.velocity_enu_m_s;
  error.attitude_error_enu_rad =
      nav::rotation_vector_from_quaternion(solution.q_body_to_enu * truth.q_body_to_enu.conjugate());
  return error;
}

}  // namespace pipeline
}  // namespace imu_lab
