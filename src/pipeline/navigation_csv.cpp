#include "imu_lab/pipeline/navigation_csv.h"

#include <cstdio>
#include <fstream>
#include <sstream>

#include "imu_lab/common/atomic_file.h"
#include "imu_lab/common/config_error.h"
#include "imu_lab/common/stamps.h"

namespace imu_lab {
namespace pipeline {
namespace {

constexpr int kTrajectoryColumns = 17;

// Round-trip precision: a reader gets back the exact doubles.
void write_values(std::ostream& out, std::initializer_list<double> values) {
  char buffer[32];
  for (double value : values) {
    std::snprintf(buffer, sizeof buffer, ",%.17g", value);
    out << buffer;
  }
}

}  // namespace

void write_trajectory_csv(const std::string& path, const std::vector<NavigationSolution>& solutions) {
  write_file_atomically(path, [&](std::ostream& out) {
    out << "stamp_s,latitude_rad,longitude_rad,height_m,east_m,north_m,up_m,velocity_east_m_s,velocity_north_m_s,"
           "velocity_up_m_s,roll_rad,pitch_rad,yaw_rad,qw,qx,qy,qz\n";
    for (const NavigationSolution& s : solutions) {
      out << format_stamp_s(s.stamp_ns);
      write_values(out, {s.latitude_rad, s.longitude_rad, s.height_m, s.position_enu_m.x(), s.position_enu_m.y(),
                         s.position_enu_m.z(), s.velocity_enu_m_s.x(), s.velocity_enu_m_s.y(), s.velocity_enu_m_s.z(),
                         s.roll_pitch_yaw_rad.x(), s.roll_pitch_yaw_rad.y(), s.roll_pitch_yaw_rad.z(),
                         s.q_body_to_enu.w(), s.q_body_to_enu.x(), s.q_body_to_enu.y(), s.q_body_to_enu.z()});
      out << '\n';
    }
  });
}

void write_error_csv(const std::string& path, const std::vector<NavigationError>& errors) {
  write_file_atomically(path, [&](std::ostream& out) {
    out << "stamp_s,time_since_alignment_s,east_error_m,north_error_m,up_error_m,horizontal_position_error_m,"
           "height_error_m,velocity_error_east_m_s,velocity_error_north_m_s,velocity_error_up_m_s,"
           "attitude_error_east_rad,attitude_error_north_rad,attitude_error_up_rad\n";
    for (const NavigationError& e : errors) {
      out << format_stamp_s(e.stamp_ns);
      write_values(out, {e.time_since_alignment_s, e.position_error_enu_m.x(), e.position_error_enu_m.y(),
                         e.position_error_enu_m.z(), e.horizontal_position_error_m, e.height_error_m,
                         e.velocity_error_enu_m_s.x(), e.velocity_error_enu_m_s.y(), e.velocity_error_enu_m_s.z(),
                         e.attitude_error_enu_rad.x(), e.attitude_error_enu_rad.y(), e.attitude_error_enu_rad.z()});
      out << '\n';
    }
  });
}

std::vector<NavigationSolution> read_trajectory_csv(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError("cannot open trajectory " + path);
  std::vector<NavigationSolution> solutions;
  std::string line;
  std::getline(in, line);  // header
  for (int line_number = 2; std::getline(in, line); ++line_number) {
    std::stringstream fields(line);
    std::vector<std::string> cells;
    for (std::string cell; std::getline(fields, cell, ',');) cells.push_back(cell);
    if (static_cast<int>(cells.size()) != kTrajectoryColumns) {
      throw InputError(path + ":" + std::to_string(line_number) + ": expected " + std::to_string(kTrajectoryColumns) +
                       " columns, found " + std::to_string(cells.size()));
    }
    std::vector<double> v;
    try {
      for (std::size_t i = 1; i < cells.size(); ++i) v.push_back(std::stod(cells[i]));
    } catch (const std::exception&) {
      throw InputError(path + ":" + std::to_string(line_number) + ": a value is not a number");
    }
    NavigationSolution s;
    s.stamp_ns = parse_stamp_s(cells[0]);
    s.latitude_rad = v[0];
    s.longitude_rad = v[1];
    s.height_m = v[2];
    s.position_enu_m = {v[3], v[4], v[5]};
    s.velocity_enu_m_s = {v[6], v[7], v[8]};
    s.roll_pitch_yaw_rad = {v[9], v[10], v[11]};
    s.q_body_to_enu = Eigen::Quaterniond(v[12], v[13], v[14], v[15]);
    solutions.push_back(s);
  }
  return solutions;
}

}  // namespace pipeline
}  // namespace imu_lab
