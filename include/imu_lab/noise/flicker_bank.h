// Bias instability B (flicker between a low corner and the cutoff f0, eq. 5.3) realised as a
// bank of first-order Markov processes with corners spaced 3 per decade (their summed PSD
// approximates B^2 / (2 pi f) between the corners; a fixed weight q_j^2 = 4 B^2 ln(10) f_j / 3
// would do it to ~10 %). The weights are fitted by least squares to eq. 5.3's AVAR over the
// claimed tau range, and the bank's exact AVAR (the sum of its eq. 5.7 terms) is checked
// against eq. 5.3 there: within kFlickerBankTolerance, else the design is refused.
#pragma once

#include <vector>

#include "imu_lab/noise/integrated_gauss_markov.h"
#include "imu_lab/noise/noise_process.h"
#include "imu_lab/noise/normal_stream.h"
#include "imu_lab/noise/process_parameters.h"

namespace imu_lab {
namespace noise {

struct FlickerBankDesign {
  std::vector<double> corner_frequencies_hz;  // f_j = 1 / (2 pi T_j)
  std::vector<double> drive_densities;        // q_j
  // Largest |AVAR_bank / AVAR_eq5.3 - 1| over the claimed tau range (log grid, 50 per decade).
  double max_relative_error = 0.0;
  double valid_tau_min_s = 0.0;
  double valid_tau_max_s = 0.0;
};

// Relative tolerance the design guarantees over the claimed range (checked, else throws).
constexpr double kFlickerBankTolerance = 0.01;

// Throws std::invalid_argument if the range is empty or the bank cannot follow eq. 5.3 within
// the tolerance over it (in practice: tau_min below ~1 / f0).
FlickerBankDesign design_flicker_bank(const BiasInstabilityParameters& parameters);

// Exact AVAR of the generated bank (sum of eq. 5.7 terms).
double flicker_bank_avar(const FlickerBankDesign& design, double tau_s);

class FlickerBankNoise : public NoiseProcess {
 public:
  FlickerBankNoise(const BiasInstabilityParameters& parameters, NormalStream normals);
  double next_interval_average(double start_s, double interval_s) override;
  double allan_variance(double tau_s, double tau0_s) const override;
  double sample_variance(double interval_s) const override;
  std::string kind() const override { return "bias_instability"; }
  const FlickerBankDesign& design() const { return design_; }

 private:
  FlickerBankDesign design_;
  std::vector<IntegratedGaussMarkov> poles_;
  std::vector<double> states_;
  NormalStream normals_;
};

}  // namespace noise
}  // namespace imu_lab
