#include "imu_lab/identify/noise_model.h"

#include <array>
#include <cmath>
#include <functional>
#include <stdexcept>

#include "imu_lab/noise/analytic_avar.h"
#include "imu_lab/noise/analytic_psd.h"

namespace imu_lab {
namespace identify {

namespace {
constexpr double kTwoPi = 6.28318530717958647692;

struct KindNames {
  TermKind kind;
  const char* name;
  const char* amplitude_symbol;
  const char* shape_symbol;
  const char* width_symbol;
};
constexpr KindNames kKinds[] = {
    {TermKind::kWhiteAngle, "white_angle", "Q", "", ""},
    {TermKind::kWhiteRate, "white_rate", "N", "low_pass_corner", ""},
    {TermKind::kBiasInstability, "bias_instability", "B", "f0", ""},
    {TermKind::kRandomWalk, "random_walk", "K", "", ""},
    {TermKind::kRateRamp, "rate_ramp", "R", "", ""},
    {TermKind::kMarkov, "markov", "q_c_T_c", "T_c", ""},
    {TermKind::kSinusoid, "sinusoid", "Omega0", "f", ""},
    {TermKind::kZeroDcFamily, "zero_dc_family", "sqrt_alpha", "beta", ""},
    {TermKind::kResonance, "resonance", "rms", "f_n", "width"},
    {TermKind::kZeroDcGaussian, "zero_dc_gaussian", "sqrt_alpha", "beta", ""},
    {TermKind::kHighPassWhite, "high_pass_white", "sqrt_alpha", "beta", ""},
};

const KindNames& names_of(TermKind kind) {
  for (const auto& entry : kKinds) {
    if (entry.kind == kind) return entry;
  }
  throw std::invalid_argument("unknown noise term kind");
}

// Eq. 5.3 per unit B^2. The fit evaluates the same few (f0, tau) pairs many thousands of times
// and each costs two cosine integrals, so the last values are remembered per thread.
double unit_bias_instability_avar(double cutoff_hz, double tau_s) {
  struct Entry {
    double cutoff_hz = -1.0;
    double tau_s = -1.0;
    double value = 0.0;
  };
  thread_local std::array<Entry, 1024> remembered;
  const size_t slot = (std::hash<double>()(tau_s) ^ (std::hash<double>()(cutoff_hz) * 31)) % remembered.size();
  Entry& entry = remembered[slot];
  if (entry.cutoff_hz != cutoff_hz || entry.tau_s != tau_s) {
    entry = {cutoff_hz, tau_s, noise::bias_instability_avar(1.0, cutoff_hz, tau_s)};
  }
  return entry.value;
}

// Kinds that may appear more than once, numbered in reports by their shape.
bool is_numbered(TermKind kind) {
  return kind == TermKind::kMarkov || kind == TermKind::kSinusoid || kind == TermKind::kResonance;
}
}  // namespace

std::string term_kind_name(TermKind kind) { return names_of(kind).name; }
std::string amplitude_symbol(TermKind kind) { return names_of(kind).amplitude_symbol; }
std::string shape_symbol(TermKind kind) { return names_of(kind).shape_symbol; }
std::string width_symbol(TermKind kind) { return names_of(kind).width_symbol; }
bool has_shape(TermKind kind) { return !shape_symbol(kind).empty(); }
int shape_count(TermKind kind) { return (has_shape(kind) ? 1 : 0) + (width_symbol(kind).empty() ? 0 : 1); }

TermKind term_kind_from_name(const std::string& name) {
  for (const auto& entry : kKinds) {
    if (name == entry.name) return entry.kind;
  }
  throw std::invalid_argument("unknown noise term '" + name + "'");
}

double term_avar(const Term& term, double tau_s) {
  const double a = term.amplitude;
  switch (term.kind) {
    case TermKind::kWhiteAngle: return noise::white_angle_avar(a, tau_s);
    case TermKind::kWhiteRate:
      if (term.shape > 0.0) {
        const double time_constant_s = 1.0 / (kTwoPi * term.shape);
        return noise::markov_avar(a / time_constant_s, time_constant_s, tau_s);
      }
      return noise::white_rate_avar(a, tau_s);
    case TermKind::kBiasInstability: return a * a * unit_bias_instability_avar(term.shape, tau_s);
    case TermKind::kRandomWalk: return noise::random_walk_avar(a, tau_s);
    case TermKind::kRateRamp: return noise::rate_ramp_avar(a, tau_s);
    case TermKind::kMarkov: return noise::markov_avar(a / term.shape, term.shape, tau_s);
    case TermKind::kSinusoid: return noise::sinusoid_avar(a, term.shape, tau_s);
    case TermKind::kZeroDcFamily: return noise::zero_dc_family_avar(2.0, a * a, term.shape, tau_s);
    case TermKind::kResonance: return noise::resonance_avar(a, term.shape, term.width, tau_s);
    case TermKind::kZeroDcGaussian: return noise::zero_dc_gaussian_avar(2.0, a * a, term.shape, tau_s);
    case TermKind::kHighPassWhite: return noise::high_pass_white_avar(a * a, term.shape, tau_s);
  }
  throw std::invalid_argument("unknown noise term kind");
}

double model_avar(const NoiseModel& model, double tau_s) {
  double total = noise::white_rate_avar(model.output_quantization_density, tau_s);
  for (const Term& term : model.terms) total += term_avar(term, tau_s);
  return total;
}

double term_psd(const Term& term, double frequency_hz, double tau0_s) {
  const double a = term.amplitude;
  switch (term.kind) {
    case TermKind::kWhiteAngle: return noise::white_angle_psd(a, tau0_s, frequency_hz);
    case TermKind::kWhiteRate:
      if (term.shape > 0.0) {  // as in term_avar: the low-passed white noise is a Markov process
        const double time_constant_s = 1.0 / (kTwoPi * term.shape);
        return noise::markov_psd(a / time_constant_s, time_constant_s, frequency_hz);
      }
      return noise::white_rate_psd(a);
    case TermKind::kBiasInstability: return noise::bias_instability_psd(a, term.shape, frequency_hz);
    case TermKind::kRandomWalk: return noise::random_walk_psd(a, frequency_hz);
    case TermKind::kRateRamp: return 0.0;
    case TermKind::kMarkov: return noise::markov_psd(a / term.shape, term.shape, frequency_hz);
    case TermKind::kSinusoid: return 0.0;
    case TermKind::kZeroDcFamily: return noise::zero_dc_family_psd(2.0, a * a, term.shape, frequency_hz);
    case TermKind::kResonance: return noise::resonance_psd(a, term.shape, term.width, frequency_hz);
    case TermKind::kZeroDcGaussian: return noise::zero_dc_gaussian_psd(2.0, a * a, term.shape, frequency_hz);
    case TermKind::kHighPassWhite: return noise::high_pass_white_psd(a * a, term.shape, frequency_hz);
  }
  throw std::invalid_argument("unknown noise term kind");
}

double sampled_term_psd(const Term& term, double frequency_hz, double tau0_s) {
  // Flat and periodic densities are their own interval-averaged, aliased PSD.
  const bool flat = term.kind == TermKind::kWhiteRate && !(term.shape > 0.0);
  if (flat || term.kind == TermKind::kWhiteAngle) return term_psd(term, frequency_hz, tau0_s);
  if (term.kind == TermKind::kRateRamp || term.kind == TermKind::kSinusoid) return 0.0;
  return noise::interval_averaged_psd([&](double f) { return term_psd(term, f, tau0_s); }, frequency_hz, tau0_s);
}

double model_psd(const NoiseModel& model, double frequency_hz, double tau0_s) {
  double total = noise::white_rate_psd(model.output_quantization_density);
  for (const Term& term : model.terms) total += term_psd(term, frequency_hz, tau0_s);
  return total;
}

double sampled_model_psd(const NoiseModel& model, double frequency_hz, double tau0_s) {
  double total = noise::white_rate_psd(model.output_quantization_density);
  for (const Term& term : model.terms) total += sampled_term_psd(term, frequency_hz, tau0_s);
  return total;
}

bool term_order_less(const Term& a, const Term& b) {
  if (a.kind != b.kind) return static_cast<int>(a.kind) < static_cast<int>(b.kind);
  if (!is_numbered(a.kind)) return false;
  // Markov terms by correlation time; sinusoids and resonances by frequency.
  return a.shape < b.shape;
}

std::vector<std::string> term_names(const NoiseModel& model) {
  std::vector<std::string> names;
  for (size_t i = 0; i < model.terms.size(); ++i) {
    const TermKind kind = model.terms[i].kind;
    std::string name = term_kind_name(kind);
    if (is_numbered(kind)) {
      int number = 1;
      for (size_t j = 0; j < i; ++j) number += model.terms[j].kind == kind ? 1 : 0;
      name += "_" + std::to_string(number);
    }
    names.push_back(name);
  }
  return names;
}

}  // namespace identify
}  // namespace imu_lab
