#include "imu_lab/thermal/thermal_residual_csv.h"

#include <iomanip>

#include "imu_lab/common/atomic_file.h"

namespace imu_lab {
namespace thermal {

void write_thermal_residual_csv(const std::string& path, const ThermalFitResult& result) {
  static const char* const kAxisNames[3] = {"x", "y", "z"};
  write_file_atomically(path, [&](std::ostream& out) {
    out << "triad,axis,unit,stamp_s,temperature_c,rate_c_s,orientation,observed_delta_bias,fitted_delta_bias,"
           "residual\n";
    out << std::setprecision(12);
    for (const WindowResidual& row : result.residuals) {
      out << row.triad << ',' << kAxisNames[row.axis] << ',' << (row.triad == "gyro" ? "rad_s" : "m_s2") << ','
          << row.stamp_s << ',' << row.temperature_c << ',' << row.rate_c_s << ',' << row.cluster << ','
          << row.observed_delta_bias << ',' << row.fitted_delta_bias << ',' << row.residual << '\n';
    }
  });
}

}  // namespace thermal
}  // namespace imu_lab
