// The allan tool's console table of the identified noise parameters: per axis and term, the value
// ± sigma in the field's customary unit (deg/sqrt(h), deg/h, deg/h/sqrt(h); m/s/sqrt(h),
// micro-g, ...) and, where alternative structures were weighed, the 68.3 % interval; "< bound"
// for absent and unconstrained terms; each triad's worst axis.
#pragma once

#include <string>
#include <vector>

#include "imu_lab/identify/triad_fit.h"
#include "imu_lab/identify/units.h"

namespace imu_lab {
namespace pipeline {

// The unit a term's amplitude is shown in: the first field unit after the SI one (SI if none).
identify::UnitScale display_unit(identify::SensorKind sensor, identify::TermKind kind);

std::string format_noise_table(const std::vector<identify::TriadFit>& triads);

}  // namespace pipeline
}  // namespace imu_lab
