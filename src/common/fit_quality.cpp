#include "imu_lab/common/fit_quality.h"

#include <cmath>

#include "imu_lab/common/format_number.h"

namespace imu_lab {

std::string chi2_warning(const std::string& what, double chi2_per_dof, const std::string& likely_causes) {
  if (!(chi2_per_dof > kFarAboveNoiseChi2PerDof)) return "";
  return what + ": chi2/dof " + format_number(chi2_per_dof, 4) + " is far above 1 (residuals " +
         format_number(std::sqrt(chi2_per_dof), 3) + " times the noise): the model does not describe the data, so " +
         "its numbers are not to be trusted; " + likely_causes;
}

}  // namespace imu_lab
