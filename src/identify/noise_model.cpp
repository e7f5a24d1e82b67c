#include "imu_lab/identify/noise_model.h"

#include <cmath>
#include <stdexcept>

#include "imu_lab/noise/analytic_avar.h"

namespace imu_lab {
namespace identify {

namespace {
constexpr double kTwoPi = 6.28318530717958647692;

struct KindNames {
  TermKind kind;
  const char* name;
  const char* amplitude_symbol;
  const char* shape_symbol;
};
constexpr KindNames kKinds[] = {
    {TermKind::kWhiteAngle, "white_angle", "Q", ""},
    {TermKind::kWhiteRate, "white_rate", "N", ""},
    {TermKind::kBiasInstability, "bias_instability", "B", "f0"},
    {TermKind::kRandomWalk, "random_walk", "K", ""},
    {TermKind::kRateRamp, "rate_ramp", "R", ""},
    {TermKind::kMarkov, "markov", "q_c_T_c", "T_c"},
    {TermKind::kSinusoid, "sinusoid", "Omega0", "f"},
    {TermKind::kZeroDcFamily, "zero_dc_family", "sqrt_alpha", "beta"},
};

const KindNames& names_of(TermKind kind) {
  for (const auto& entry : kKinds) {
    if (entry.kind == kind) return entry;
  }
  throw std::invalid_argument("unknown noise term kind");
}
}  // namespace

std::string term_kind_name(TermKind kind) { return names_of(kind).name; }
std::string amplitude_symbol(TermKind kind) { return names_of(kind).amplitude_symbol; }
std::string shape_symbol(TermKind kind) { return names_of(kind).shape_symbol; }
bool has_shape(TermKind kind) { return !shape_symbol(kind).empty(); }

TermKind term_kind_from_name(const std::string& name) {
  for (const auto& entry : kKinds) {
    if (name == entry.name) return entry.kind;
  }
  throw std::invalid_argument("unknown noise term '" + name + "'");
}

double term_avar(const Term& term, double tau_s, double white_rate_corner_hz) {
  const double a = term.amplitude;
  switch (term.kind) {
    case TermKind::kWhiteAngle:
      return noise::white_angle_avar(a, tau_s);
    case TermKind::kWhiteRate:
      if (white_rate_corner_hz > 0.0) {
        const double time_constant_s = 1.0 / (kTwoPi * white_rate_corner_hz);
        return noise::markov_avar(a / time_constant_s, time_constant_s, tau_s);
      }
      return noise::white_rate_avar(a, tau_s);
    case TermKind::kBiasInstability:
      return noise::bias_instability_avar(a, term.shape, tau_s);
    case TermKind::kRandomWalk:
      return noise::random_walk_avar(a, tau_s);
    case TermKind::kRateRamp:
      return noise::rate_ramp_avar(a, tau_s);
    case TermKind::kMarkov:
      return noise::markov_avar(a / term.shape, term.shape, tau_s);
    case TermKind::kSinusoid:
      return noise::sinusoid_avar(a, term.shape, tau_s);
    case TermKind::kZeroDcFamily:
      return noise::zero_dc_family_avar(2.0, a * a, term.shape, tau_s);
  }
  throw std::invalid_argument("unknown noise term kind");
}

double model_avar(const NoiseModel& model, double tau_s) {
  double total = 0.0;
  for (const Term& term : model.terms) total += term_avar(term, tau_s, model.white_rate_corner_hz);
  return total;
}

bool term_order_less(const Term& a, const Term& b) {
  if (a.kind != b.kind) return static_cast<int>(a.kind) < static_cast<int>(b.kind);
  return a.kind == TermKind::kMarkov && a.shape < b.shape;
}

std::vector<std::string> term_names(const NoiseModel& model) {
  std::vector<std::string> names;
  int markov_count = 0;
  for (const Term& term : model.terms) {
    std::string name = term_kind_name(term.kind);
    if (term.kind == TermKind::kMarkov) name += "_" + std::to_string(++markov_count);
    names.push_back(name);
  }
  return names;
}

}  // namespace identify
}  // namespace imu_lab
