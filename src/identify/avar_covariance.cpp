#include "imu_lab/identify/avar_covariance.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <iterator>
#include <limits>
#include <list>
#include <map>
#include <mutex>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>

#include "imu_lab/common/cancellation.h"
#include "imu_lab/noise/analytic_avar.h"

namespace imu_lab {
namespace identify {

namespace {

constexpr double kPi = 3.14159265358979323846;

// u - T (1 - e^{-u/T}) for u >= 0, without the cancellation at u << T.
double markov_excess(double u, double correlation_time_s) {
  const double x = u / correlation_time_s;
  if (x < 1e-3) return correlation_time_s * x * x * (0.5 - x / 6.0 + x * x / 24.0);
  return u - correlation_time_s * (-std::expm1(-x));
}

// Six-point Gauss-Legendre nodes and weights on [-1, 1].
constexpr std::array<double, 6> kGaussNodes = {-0.9324695142031521, -0.6612093864662645, -0.2386191860831969,
                                               0.2386191860831969,  0.6612093864662645,  0.9324695142031521};
constexpr std::array<double, 6> kGaussWeights = {0.1713244923791704, 0.3607615730481386, 0.4679139345726910,
                                                 0.4679139345726910, 0.3607615730481386, 0.1713244923791704};

// Gauss-Legendre points of the integral over [a, b], on sub-intervals that grow geometrically
// from both ends, where the integrand's kinks and boundary layers (a Markov term's e^{-u/T}) sit.
template <class Visit>
void visit_graded_integral(double a, double b, const Visit& visit) {
  constexpr double kFirstWidth = 8.0;
  constexpr double kGrowth = 4.0;
  std::vector<double> edges = {a};
  const double middle = 0.5 * (a + b);
  for (double width = kFirstWidth; edges.back() + width < middle; width *= kGrowth)
    edges.push_back(edges.back() + width);
  const size_t left_count = edges.size();
  edges.push_back(middle);
  for (size_t i = left_count; i-- > 1;) edges.push_back(b - (edges[i] - a));
  edges.push_back(b);
  for (size_t i = 0; i + 1 < edges.size(); ++i) {
    const double half = 0.5 * (edges[i + 1] - edges[i]);
    if (!(half > 0.0)) continue;
    const double centre = 0.5 * (edges[i + 1] + edges[i]);
    for (size_t k = 0; k < kGaussNodes.size(); ++k) visit(centre + half * kGaussNodes[k], half * kGaussWeights[k]);
  }
}

// The points and weights of sum_{h = lo}^{hi} f(h) over integers for an f smooth between the
// given nodes: every lag within half_width of a node (weight 1), the integral (midpoint
// correspondence) in between.
template <class Visit>
void visit_lags(long long lo, long long hi, std::vector<long long> nodes, long long half_width, const Visit& visit) {
  nodes.push_back(lo);
  nodes.push_back(hi);
  std::vector<std::pair<long long, long long>> windows;
  for (long long node : nodes) {
    const long long first = std::max(lo, node - half_width);
    const long long last = std::min(hi, node + half_width);
    if (first <= last) windows.push_back({first, last});
  }
  std::sort(windows.begin(), windows.end());
  std::vector<std::pair<long long, long long>> merged;
  for (const auto& window : windows) {
    if (!merged.empty() && window.first <= merged.back().second + 1) {
      merged.back().second = std::max(merged.back().second, window.second);
    } else {
      merged.push_back(window);
    }
  }
  for (size_t i = 0; i < merged.size(); ++i) {
    for (long long h = merged[i].first; h <= merged[i].second; ++h) visit(static_cast<double>(h), 1.0);
    if (i + 1 < merged.size() && merged[i + 1].first - merged[i].second > 1) {
      visit_graded_integral(merged[i].second + 0.5, merged[i + 1].first - 0.5, visit);
    }
  }
}

// Everything one pair (m, n) needs: the lag range, the offsets of C_mn and the count of pairs.
struct PairGeometry {
  long long terms_m = 0;  // M_m
  long long terms_n = 0;
  std::array<double, 9> offsets{};  // j n - i m
  std::array<double, 9> weights{};  // w_i w_j
  double scale = 0.0;               // -1 / (4 m n tau0^2)

  PairGeometry(int m, int n, double tau0_s, long long sample_count)
      : terms_m(sample_count + 1 - 2LL * m), terms_n(sample_count + 1 - 2LL * n) {
    constexpr std::array<double, 3> kWeights = {1.0, -2.0, 1.0};
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) {
        offsets[3 * i + j] = static_cast<double>(j) * n - static_cast<double>(i) * m;
        weights[3 * i + j] = kWeights[i] * kWeights[j];
      }
    }
    scale = -1.0 / (4.0 * static_cast<double>(m) * n * tau0_s * tau0_s);
  }
  long long lowest_lag() const { return -(terms_m - 1); }
  long long highest_lag() const { return terms_n - 1; }
  double count(double h) const {
    return std::max(0.0, std::min<double>(terms_m - 1, terms_n - 1 - h) - std::max(0.0, -h) + 1.0);
  }
  std::vector<long long> nodes() const {
    std::vector<long long> result = {0, terms_n - terms_m};
    for (double offset : offsets) result.push_back(static_cast<long long>(-offset));
    return result;
  }
  // 2 / (M_m M_n): the factor in front of the lag sum.
  double normaliser() const { return 2.0 / (static_cast<double>(terms_m) * static_cast<double>(terms_n)); }
};

void check_factor(int m, long long sample_count) {
  if (m < 1 || 2LL * m > sample_count - 1) {
    throw std::invalid_argument("oavar_covariance: averaging factor " + std::to_string(m) +
                                " outside [1, (samples - 1) / 2] for " + std::to_string(sample_count) + " samples");
  }
}

// How far, in lags, the terms' correlations reach beyond a filter's own span, and how many lags
// around each kink must be summed exactly (a resonance oscillates every few lags; seven decay
// times leave e^-7 of it to the quadrature between the windows).
struct LagReach {
  double tail_lags = 0.0;
  long long exact_half_width = 8;
  // Above this averaging factor the oscillating terms have decayed within a small part of each
  // filter's span and hold a negligible share of its variance: the default window suffices.
  double oscillation_factor_limit = 0.0;
};

double decay_time_s(const Term& term) {
  switch (term.kind) {
    case TermKind::kMarkov:
    case TermKind::kZeroDcFamily: return term.shape;
    case TermKind::kZeroDcGaussian: return std::sqrt(term.shape);  // C(u) falls as exp(-pi^2 u^2 / beta)
    case TermKind::kHighPassWhite: return 1.0 / (2.0 * kPi * term.shape);
    case TermKind::kWhiteRate: return term.shape > 0.0 ? 1.0 / (2.0 * kPi * term.shape) : 0.0;
    case TermKind::kResonance: return 1.0 / (kPi * term.width);
    default: return 0.0;
  }
}

LagReach lag_reach(const std::vector<Term>& terms, double tau0_s) {
  constexpr double kTailDecayTimes = 30.0;
  constexpr double kExactDecayTimes = 7.0;
  constexpr long long kMaxExactHalfWidth = 4096;
  LagReach reach;
  for (const Term& term : terms) {
    const double decay_s = decay_time_s(term);
    if (term.kind == TermKind::kResonance) {
      const double lags = std::ceil(kExactDecayTimes * decay_s / tau0_s);
      reach.exact_half_width =
          std::max(reach.exact_half_width, static_cast<long long>(std::min<double>(kMaxExactHalfWidth, lags)));
      reach.oscillation_factor_limit = std::max(reach.oscillation_factor_limit, 3.0 * lags);
    }
    reach.tail_lags = std::max(reach.tail_lags, kTailDecayTimes * decay_s / tau0_s);
  }
  return reach;
}

// A lag at which the lag sums evaluate D, prepared once for every unit of a batch.
struct LagArgument {
  double lag_s = 0.0;          // |lag| tau0
  long long integer_lag = -1;  // |lag| if it is an integer (a truncating cast is cheaper than std::round)
};

LagArgument lag_argument(double lag, double tau0_s) {
  const double magnitude = std::abs(lag);
  LagArgument argument;
  argument.lag_s = magnitude * tau0_s;
  if (magnitude < 0x1p62) {
    const long long integer = static_cast<long long>(magnitude);
    if (static_cast<double>(integer) == magnitude) argument.integer_lag = integer;
  }
  return argument;
}

// One unit-amplitude term's D at integer lags 0..size-1 (the exact windows ask for these, most
// of them short), its settled form elsewhere: beyond 30 decay times a short-memory term sits on its
// asymptote, cheaper than the exact form. The lag sums call this tens of millions of times per
// record, so the unit's kind, decay time and asymptote are resolved once (the same operations as
// term_structure_function, hence the same doubles).
class UnitTable {
 public:
  // Entries are filled when first asked for (NaN until then): the sums visit a small part of them.
  UnitTable(const Term& unit, double tau0_s, long long size)
      : unit_(unit),
        tau0_s_(tau0_s),
        values_(static_cast<size_t>(std::max(1LL, size)), std::numeric_limits<double>::quiet_NaN()),
        table_size_(static_cast<double>(values_.size())) {
    constexpr double kSettledDecayTimes = 30.0;
    const double decay_s = decay_time_s(unit);
    if (decay_s > 0.0) {
      settled_from_s_ = kSettledDecayTimes * decay_s;
      if (unit.kind == TermKind::kResonance) {
        const double angle_sigma = unit.amplitude / (2.0 * kPi * unit.shape);
        settled_constant_ = 2.0 * angle_sigma * angle_sigma;
        settled_ = Settled::kConstant;
      } else if (unit.kind == TermKind::kMarkov || unit.kind == TermKind::kWhiteRate) {
        settled_scale_ = unit.amplitude * unit.amplitude;
        settled_offset_s_ = decay_s;
        settled_ = Settled::kLinear;
      }
    }
    if (unit.amplitude == 1.0) {
      switch (unit.kind) {
        case TermKind::kWhiteAngle: exact_ = Exact::kWhiteAngle; break;
        case TermKind::kWhiteRate:
          exact_ = unit.shape > 0.0 ? Exact::kMarkov : Exact::kWhite;
          if (unit.shape > 0.0) correlation_time_s_ = 1.0 / (2.0 * kPi * unit.shape);
          break;
        case TermKind::kBiasInstability: exact_ = Exact::kFlicker; break;
        case TermKind::kRandomWalk: exact_ = Exact::kRandomWalk; break;
        case TermKind::kMarkov:
          exact_ = Exact::kMarkov;
          correlation_time_s_ = unit.shape;
          break;
        default: break;
      }
    }
  }
  double at(const LagArgument& argument) const {
    // An integer lag inside the table.
    if (argument.integer_lag >= 0 && static_cast<double>(argument.integer_lag) < table_size_) {
      const size_t index = static_cast<size_t>(argument.integer_lag);
      double& value = values_[index];
      if (std::isnan(value)) value = exact(index * tau0_s_);
      return value;
    }
    return settled(argument.lag_s);
  }
  const Term& unit() const { return unit_; }

 private:
  enum class Settled { kNever, kConstant, kLinear };
  enum class Exact { kGeneral, kWhiteAngle, kWhite, kFlicker, kRandomWalk, kMarkov };

  // term_structure_function(unit_, u, tau0_s_) for u >= 0 (a unit amplitude squared is 1).
  double exact(double u) const {
    constexpr double a2 = 1.0;
    switch (exact_) {
      case Exact::kWhiteAngle: return u < 0.5 * tau0_s_ ? 0.0 : 2.0 * a2;
      case Exact::kWhite: return a2 * u;
      case Exact::kFlicker: return u > 0.0 ? -a2 / kPi * u * u * std::log(u) : 0.0;
      case Exact::kRandomWalk: return -a2 * u * u * u / 6.0;
      case Exact::kMarkov: return a2 * markov_excess(u, correlation_time_s_);
      case Exact::kGeneral: break;
    }
    return term_structure_function(unit_, u, tau0_s_);
  }
  // D(u), on the asymptote where the term has settled.
  double settled(double u) const {
    if (settled_ != Settled::kNever && u > settled_from_s_) {
      if (settled_ == Settled::kConstant) return settled_constant_;
      return settled_scale_ * (u - settled_offset_s_);
    }
    return exact(u);
  }

  Term unit_;
  double tau0_s_;
  mutable std::vector<double> values_;
  double table_size_;
  Settled settled_ = Settled::kNever;
  double settled_from_s_ = 0.0;
  double settled_constant_ = 0.0;
  double settled_scale_ = 0.0;  // amplitude^2
  double settled_offset_s_ = 0.0;
  Exact exact_ = Exact::kGeneral;
  double correlation_time_s_ = 0.0;  // a Markov term's, or a front end's 1 / (2 pi f_c)
};

// The stochastic terms of a model as (unit term, weight = amplitude^2); the output quantization
// is a unit white noise.
std::vector<std::pair<Term, double>> weighted_units(const NoiseModel& model) {
  std::vector<std::pair<Term, double>> units;
  if (model.output_quantization_density > 0.0) {
    units.push_back({Term{TermKind::kWhiteRate, 1.0, 0.0, 0.0},
                     model.output_quantization_density * model.output_quantization_density});
  }
  for (const Term& term : model.terms) {
    if (term.kind == TermKind::kRateRamp || term.kind == TermKind::kSinusoid) continue;
    Term unit = term;
    unit.amplitude = 1.0;
    units.push_back({unit, term.amplitude * term.amplitude});
  }
  return units;
}

std::pair<int, int> unit_pair(int a, int b) { return a < b ? std::make_pair(a, b) : std::make_pair(b, a); }

// The OAVAR differences d_k of a rate ramp R t are all R m tau0 / sqrt(2) (the estimate is
// R^2 tau^2 / 2 on any record); of two ramps, their sum.
double ramp_difference_per_factor(const NoiseModel& model, double tau0_s) {
  double slope = 0.0;
  for (const Term& term : model.terms) {
    if (term.kind == TermKind::kRateRamp) slope += term.amplitude;
  }
  return slope * tau0_s / std::sqrt(2.0);
}

// The sampled rate noise's one-sided density at a line's frequency f, as the line sees it: a
// sinusoid's OAVAR (eq. 5.8) is its integral's, so both are compared before the sample average,
// whose sinc^2 is divided out. Stationary terms from their samples' autocovariance (second
// differences of D, aliases included); flicker, random walk and Markov terms slower than the
// longest lag sum from their continuous PSDs (two-sided B^2 / (2 pi f), K^2 / (2 pi f)^2,
// a^2 / (1 + (2 pi f T)^2); their aliases are negligible).
double line_noise_density(const NoiseModel& model, double frequency_hz, double tau0_s) {
  constexpr long long kMaxLags = 20000;
  constexpr double kTailDecayTimes = 30.0;
  const double angular = 2.0 * kPi * frequency_hz;
  double continuous = 0.0;  // two-sided
  std::vector<Term> stationary;
  if (model.output_quantization_density > 0.0) {
    stationary.push_back({TermKind::kWhiteRate, model.output_quantization_density, 0.0, 0.0});
  }
  for (const Term& term : model.terms) {
    const double a2 = term.amplitude * term.amplitude;
    switch (term.kind) {
      case TermKind::kBiasInstability: continuous += a2 / angular; break;
      case TermKind::kRandomWalk: continuous += a2 / (angular * angular); break;
      case TermKind::kRateRamp:
      case TermKind::kSinusoid: break;
      case TermKind::kMarkov:
        if (kTailDecayTimes * term.shape / tau0_s > kMaxLags) {
          continuous += a2 / (1.0 + std::pow(angular * term.shape, 2));
          break;
        }
        stationary.push_back(term);
        break;
      default: stationary.push_back(term);
    }
  }
  double sampled = 0.0;  // two-sided density of the samples: tau0 sum_j r(j) cos(2 pi f j tau0)
  if (!stationary.empty()) {
    const auto structure = [&](long long lag) {
      double total = 0.0;
      for (const Term& term : stationary) total += term_structure_function(term, lag * tau0_s, tau0_s);
      return total;
    };
    const long long lags =
        std::min<long long>(kMaxLags, static_cast<long long>(lag_reach(stationary, tau0_s).tail_lags) + 2);
    for (long long j = 0; j <= lags; ++j) {
      const double autocovariance =
          (structure(j + 1) - 2.0 * structure(j) + structure(std::abs(j - 1))) / (2.0 * tau0_s * tau0_s);
      sampled += (j == 0 ? 1.0 : 2.0) * autocovariance * std::cos(angular * j * tau0_s);
    }
    sampled *= tau0_s;
  }
  const double x = 0.5 * angular * tau0_s;
  const double sample_average = x > 0.0 ? std::pow(std::sin(x) / x, 2) : 1.0;
  return 2.0 * (sampled / sample_average + continuous);
}

bool close_shape(double a, double b) {
  constexpr double kTolerance = 0.1;
  if (a == b) return true;
  return a > 0.0 && b > 0.0 && std::abs(std::log(a / b)) < kTolerance;
}

// The kernels depend only on the record's geometry (factors, tau0, sample count), the exact
// shapes of their unit pair, the lag reach they were summed with and whether only the diagonal
// was summed. The three axes of a triad, and the two triads of one record, meet the same white,
// flicker, random-walk and white-angle units, the same quantization and the same bank of
// descriptive Markov terms (descriptive_model.h), so such a kernel is summed once per record and
// the others copy it: the same numbers, bit for bit, as summing it again. The last few
// geometries are kept (a monitor refits as its record grows).
struct UnitKey {
  int kind = 0;
  double shape = 0.0;
  double width = 0.0;
  bool operator<(const UnitKey& other) const {
    return std::tie(kind, shape, width) < std::tie(other.kind, other.shape, other.width);
  }
  bool operator==(const UnitKey& other) const { return !(*this < other) && !(other < *this); }
};

UnitKey unit_key(const Term& unit) { return {static_cast<int>(unit.kind), unit.shape, unit.width}; }

struct KernelKey {
  UnitKey first;   // first <= second
  UnitKey second;  // == first for a linear sum
  bool linear = false;
  double tail_lags = 0.0;
  long long exact_half_width = 0;
  double oscillation_factor_limit = 0.0;
  bool operator<(const KernelKey& other) const {
    return std::tie(first, second, linear, tail_lags, exact_half_width, oscillation_factor_limit) <
           std::tie(other.first, other.second, other.linear, other.tail_lags, other.exact_half_width,
                    other.oscillation_factor_limit);
  }
};

struct RecordGeometry {
  std::vector<int> factors;
  double tau0_s = 0.0;
  long long sample_count = 0;
  bool operator==(const RecordGeometry& other) const {
    return factors == other.factors && tau0_s == other.tau0_s && sample_count == other.sample_count;
  }
};

// Per factor pair (i * count + j), C_mn at the lags its sum visits, in order; empty if not summed.
using DifferenceCovariances = std::vector<std::vector<double>>;

class SharedKernels {
 public:
  static SharedKernels& instance() {
    static SharedKernels shared;
    return shared;
  }
  // A whole matrix serves a diagonal request too (its diagonal is summed over the same lags).
  bool find(const RecordGeometry& geometry, const KernelKey& key, bool diagonal_only, Eigen::MatrixXd* full,
            Eigen::VectorXd* diagonal) {
    std::lock_guard<std::mutex> lock(mutex_);
    Kernels& kernels = kernels_of(geometry);
    const auto whole = kernels.full.find(key);
    if (whole != kernels.full.end()) {
      if (diagonal_only) {
        *diagonal = whole->second.diagonal();
      } else {
        *full = whole->second;
      }
      return true;
    }
    if (!diagonal_only) return false;
    const auto part = kernels.diagonal.find(key);
    if (part == kernels.diagonal.end()) return false;
    *diagonal = part->second;
    return true;
  }
  void store(const RecordGeometry& geometry, const KernelKey& key, const Eigen::MatrixXd* full,
             const Eigen::VectorXd* diagonal) {
    std::lock_guard<std::mutex> lock(mutex_);
    Kernels& kernels = kernels_of(geometry);
    if (full != nullptr) kernels.full[key] = *full;
    if (diagonal != nullptr) kernels.diagonal[key] = *diagonal;
  }
  // A unit's C_mn at every lag a batch of this reach visits (key.second == key.first, not linear),
  // per factor pair; null if not kept.
  std::shared_ptr<const DifferenceCovariances> find_differences(const RecordGeometry& geometry, const KernelKey& key) {
    std::lock_guard<std::mutex> lock(mutex_);
    Kernels& kernels = kernels_of(geometry);
    const auto found = kernels.differences.find(key);
    return found == kernels.differences.end() ? nullptr : found->second;
  }
  // Kept while all records' vectors stay within one memory budget (they are the large part).
  void store_differences(const RecordGeometry& geometry, const KernelKey& key,
                         std::shared_ptr<const DifferenceCovariances> differences) {
    constexpr size_t kBudgetBytes = size_t{48} << 20;
    size_t bytes = 0;
    for (const auto& values : *differences) bytes += values.size() * sizeof(double);
    std::lock_guard<std::mutex> lock(mutex_);
    Kernels& kernels = kernels_of(geometry);
    const auto old = kernels.differences.find(key);
    if (old != kernels.differences.end()) {
      for (const auto& values : *old->second) kernels.difference_bytes -= values.size() * sizeof(double);
      kernels.differences.erase(old);
    }
    // One budget for all records kept: the least recent records' vectors go first (their small
    // sums stay).
    size_t total = 0;
    for (const Kernels& each : recent_) total += each.difference_bytes;
    for (auto older = recent_.rbegin(); total + bytes > kBudgetBytes && older != recent_.rend(); ++older) {
      if (&*older == &kernels) continue;
      total -= older->difference_bytes;
      older->differences.clear();
      older->difference_bytes = 0;
    }
    if (total + bytes > kBudgetBytes) return;
    kernels.difference_bytes += bytes;
    kernels.differences[key] = std::move(differences);
  }

 private:
  struct Kernels {
    RecordGeometry geometry;
    std::map<KernelKey, Eigen::MatrixXd> full;
    std::map<KernelKey, Eigen::VectorXd> diagonal;
    std::map<KernelKey, std::shared_ptr<const DifferenceCovariances>> differences;
    size_t difference_bytes = 0;
  };
  // Most recent first; called under the lock.
  Kernels& kernels_of(const RecordGeometry& geometry) {
    constexpr size_t kKeptGeometries = 4;
    auto found = std::find_if(recent_.begin(), recent_.end(),
                              [&](const Kernels& kernels) { return kernels.geometry == geometry; });
    if (found != recent_.end()) {
      recent_.splice(recent_.begin(), recent_, found);
    } else {
      recent_.push_front(Kernels{geometry, {}, {}, {}, 0});
      if (recent_.size() > kKeptGeometries) recent_.pop_back();
    }
    return recent_.front();
  }
  std::mutex mutex_;
  std::list<Kernels> recent_;
};

}  // namespace

struct OavarCovariance::Cache {
  std::vector<int> factors;
  double tau0_s = 0.0;
  long long sample_count = 0;
  std::vector<double> variance_inflation;  // per factor: 1 / pooled term fraction (>= 1)
  // The unit terms met so far (a term within 10 % of one's shape reuses it) and their tables of
  // D, built when a kernel of theirs is first summed.
  std::vector<Term> units;
  std::vector<std::unique_ptr<UnitTable>> tables;
  // Lag sums sum_h count c_i c_j (times the normaliser) per unit pair i <= j: the whole matrix
  // over factor pairs, or its diagonal only.
  std::map<std::pair<int, int>, Eigen::MatrixXd> full;
  std::map<std::pair<int, int>, Eigen::VectorXd> diagonal;
  // Linear lag sums sum_h count c_i / (M_m M_n) per unit: cov(mean d^m, mean d^n), which a
  // deterministic difference (a ramp's) carries into the estimates; needed only with a ramp.
  std::map<int, Eigen::MatrixXd> linear_full;
  std::map<int, Eigen::VectorXd> linear_diagonal;

  int unit_index(const Term& unit) {
    for (size_t i = 0; i < units.size(); ++i) {
      const Term& cached = units[i];
      if (cached.kind == unit.kind && close_shape(cached.shape, unit.shape) && close_shape(cached.width, unit.width)) {
        return static_cast<int>(i);
      }
    }
    units.push_back(unit);
    tables.emplace_back();
    return static_cast<int>(units.size()) - 1;
  }

  const UnitTable& table(int index) {
    if (!tables[index]) {
      int largest = 1;
      for (int m : factors) largest = std::max(largest, m);
      std::vector<Term> alone = {units[index]};
      const LagReach reach = lag_reach(alone, tau0_s);
      constexpr long long kMaxTable = 1LL << 16;
      tables[index].reset(
          new UnitTable(units[index], tau0_s, std::min(kMaxTable, 4LL * largest + 2 * reach.exact_half_width + 2)));
    }
    return *tables[index];
  }

  KernelKey kernel_key(int a, int b, bool linear, const LagReach& reach) const {
    KernelKey key;
    key.first = unit_key(units[a]);
    key.second = unit_key(units[b]);
    if (key.second < key.first) std::swap(key.first, key.second);
    key.linear = linear;
    key.tail_lags = reach.tail_lags;
    key.exact_half_width = reach.exact_half_width;
    key.oscillation_factor_limit = reach.oscillation_factor_limit;
    return key;
  }

  // Fills every missing kernel among `indices` (for every factor pair, or the diagonal only),
  // and with `linear` their linear sums too.
  void compute_missing(const std::vector<int>& indices, bool diagonal_only, bool linear) {
    throw_if_cancelled();  // before anything is filled in: the cache stays whole
    std::vector<std::pair<int, int>> missing;
    for (size_t a = 0; a < indices.size(); ++a) {
      for (size_t b = a; b < indices.size(); ++b) {
        const std::pair<int, int> key = unit_pair(indices[a], indices[b]);
        if (full.count(key) || (diagonal_only && diagonal.count(key))) continue;
        if (std::find(missing.begin(), missing.end(), key) == missing.end()) missing.push_back(key);
      }
    }
    std::vector<int> linear_missing;
    for (int index : indices) {
      if (!linear || linear_full.count(index) || (diagonal_only && linear_diagonal.count(index))) continue;
      if (std::find(linear_missing.begin(), linear_missing.end(), index) == linear_missing.end()) {
        linear_missing.push_back(index);
      }
    }
    if (missing.empty() && linear_missing.empty()) return;
    std::vector<int> involved = linear_missing;
    for (const auto& key : missing) {
      for (int index : {key.first, key.second}) {
        if (std::find(involved.begin(), involved.end(), index) == involved.end()) involved.push_back(index);
      }
    }
    std::vector<Term> involved_terms;
    for (int index : involved) involved_terms.push_back(units[index]);
    // The reach rounded up to a power of two: batches whose terms decay at nearly the same rate
    // (a front end's corner refitted, another axis's) visit the same lags and share their sums;
    // a longer reach only adds a few graded quadrature points, and no accuracy is lost.
    LagReach reach = lag_reach(involved_terms, tau0_s);
    if (reach.tail_lags > 0.0) reach.tail_lags = std::exp2(std::ceil(std::log2(reach.tail_lags)));
    const long long exact_half_width = reach.exact_half_width;
    reach.exact_half_width = 1;
    while (reach.exact_half_width < exact_half_width) reach.exact_half_width *= 2;
    reach.oscillation_factor_limit *= static_cast<double>(reach.exact_half_width) / exact_half_width;
    // A tail beyond the record changes no lag range (each is clipped to the record): one key.
    reach.tail_lags = std::min(reach.tail_lags, static_cast<double>(sample_count));
    // Kernels another covariance of this record has summed with this reach are copied.
    SharedKernels& shared = SharedKernels::instance();
    const RecordGeometry geometry{factors, tau0_s, sample_count};
    const auto copy_shared = [&](auto* keys, auto& full_map, auto& diagonal_map, auto key_of) {
      for (size_t k = 0; k < keys->size();) {
        Eigen::MatrixXd whole;
        Eigen::VectorXd part;
        const auto key = (*keys)[k];
        if (shared.find(geometry, key_of(key), diagonal_only, &whole, &part)) {
          if (diagonal_only) {
            diagonal_map[key] = part;
          } else {
            full_map[key] = whole;
          }
          keys->erase(keys->begin() + k);
        } else {
          ++k;
        }
      }
    };
    copy_shared(&missing, full, diagonal,
                [&](const std::pair<int, int>& key) { return kernel_key(key.first, key.second, false, reach); });
    copy_shared(&linear_missing, linear_full, linear_diagonal,
                [&](int index) { return kernel_key(index, index, true, reach); });
    if (missing.empty() && linear_missing.empty()) return;
    // The c values of the units left to sum (the lags stay those of the whole batch's reach).
    involved = linear_missing;
    for (const auto& key : missing) {
      for (int index : {key.first, key.second}) {
        if (std::find(involved.begin(), involved.end(), index) == involved.end()) involved.push_back(index);
      }
    }
    const int count = static_cast<int>(factors.size());
    for (const auto& key : missing) {
      if (diagonal_only) {
        diagonal[key] = Eigen::VectorXd::Zero(count);
      } else {
        full[key] = Eigen::MatrixXd::Zero(count, count);
      }
    }
    for (int index : linear_missing) {
      if (diagonal_only) {
        linear_diagonal[index] = Eigen::VectorXd::Zero(count);
      } else {
        linear_full[index] = Eigen::MatrixXd::Zero(count, count);
      }
    }
    // Each involved unit's C_mn at the visited lags: kept from an earlier batch of this reach
    // (another axis, or an earlier model with this unit) or summed now and kept.
    std::vector<std::shared_ptr<const DifferenceCovariances>> kept(units.size());
    std::vector<std::shared_ptr<DifferenceCovariances>> fresh(units.size());
    for (int index : involved) {
      kept[index] = shared.find_differences(geometry, kernel_key(index, index, false, reach));
      bool complete = kept[index] != nullptr;
      for (int i = 0; complete && i < count; ++i) {
        for (int j = diagonal_only ? i : 0; complete && j < (diagonal_only ? i + 1 : count); ++j) {
          complete = j < i || !(*kept[index])[i * count + j].empty();
        }
      }
      if (!complete) {
        fresh[index] = kept[index] ? std::make_shared<DifferenceCovariances>(*kept[index])
                                   : std::make_shared<DifferenceCovariances>(count * count);
        kept[index] = fresh[index];
      }
    }
    std::vector<const UnitTable*> involved_tables(units.size(), nullptr);
    for (int index : involved) {
      if (fresh[index]) involved_tables[index] = &table(index);
    }
    std::vector<std::pair<double, double>> lags;  // (h, quadrature weight)
    std::vector<double> counted;                  // weight times the count of pairs at h
    std::vector<LagArgument> arguments;           // per lag, D's nine arguments
    std::vector<const double*> c(units.size());
    std::vector<double> sums(missing.size()), linear_sums(linear_missing.size());
    for (int i = 0; i < count; ++i) {
      for (int j = i; j < count; ++j) {
        if (diagonal_only && j != i) break;
        const int m = factors[i], n = factors[j];
        const PairGeometry pair(m, n, tau0_s, sample_count);
        std::fill(sums.begin(), sums.end(), 0.0);
        std::fill(linear_sums.begin(), linear_sums.end(), 0.0);
        // Outside the two filters' joint span C_mn vanishes for white, random-walk and
        // white-angle terms, decays like e^{-u / T} for Markov ones and like (span / u)^2 for
        // flicker, whose squared tail beyond 16 spans holds under 3e-4 of the sum.
        const double span = 2.0 * (static_cast<double>(m) + n);
        const double reach_lags = 16.0 * span + reach.tail_lags;
        const long long lo = std::max<long long>(pair.lowest_lag(), static_cast<long long>(-reach_lags));
        const long long hi = std::min<long long>(pair.highest_lag(), static_cast<long long>(reach_lags));
        constexpr long long kDefaultHalfWidth = 8;
        const bool oscillating = std::min(m, n) < reach.oscillation_factor_limit;
        lags.clear();
        visit_lags(lo, hi, pair.nodes(), oscillating ? reach.exact_half_width : kDefaultHalfWidth,
                   [&](double h, double weight) {
                     lags.push_back({h, weight});
                   });
        constexpr size_t kOffsets = std::tuple_size<decltype(pair.offsets)>::value;
        arguments.clear();
        for (int index : involved) {
          if (fresh[index] && (*fresh[index])[i * count + j].empty()) {
            if (arguments.empty()) {  // the nine lags of each visited lag, shared by the units
              arguments.resize(kOffsets * lags.size());
              for (size_t p = 0; p < lags.size(); ++p) {
                for (size_t k = 0; k < kOffsets; ++k) {
                  arguments[kOffsets * p + k] = lag_argument(lags[p].first + pair.offsets[k], tau0_s);
                }
              }
            }
            std::vector<double>& values = (*fresh[index])[i * count + j];
            values.resize(lags.size());
            const UnitTable& unit_table = *involved_tables[index];
            for (size_t p = 0; p < lags.size(); ++p) {
              double value = 0.0;
              for (size_t k = 0; k < kOffsets; ++k) {
                value += pair.weights[k] * unit_table.at(arguments[kOffsets * p + k]);
              }
              values[p] = value * pair.scale;
            }
          }
          c[index] = (*kept[index])[i * count + j].data();
        }
        counted.resize(lags.size());
        for (size_t p = 0; p < lags.size(); ++p) counted[p] = lags[p].second * pair.count(lags[p].first);
        // Each sum runs over the lags in order (the same additions as lag by lag).
        for (size_t k = 0; k < missing.size(); ++k) {
          const double* first = c[missing[k].first];
          const double* second = c[missing[k].second];
          double sum = 0.0;
          for (size_t p = 0; p < lags.size(); ++p) sum += counted[p] * first[p] * second[p];
          sums[k] = sum;
        }
        for (size_t k = 0; k < linear_missing.size(); ++k) {
          const double* values = c[linear_missing[k]];
          double sum = 0.0;
          for (size_t p = 0; p < lags.size(); ++p) sum += counted[p] * values[p];
          linear_sums[k] = sum;
        }
        for (size_t k = 0; k < missing.size(); ++k) {
          const double value = sums[k] * pair.normaliser();
          if (diagonal_only) {
            diagonal[missing[k]](i) = value;
          } else {
            full[missing[k]](i, j) = full[missing[k]](j, i) = value;
          }
        }
        for (size_t k = 0; k < linear_missing.size(); ++k) {
          const double value = 0.5 * linear_sums[k] * pair.normaliser();
          if (diagonal_only) {
            linear_diagonal[linear_missing[k]](i) = value;
          } else {
            linear_full[linear_missing[k]](i, j) = linear_full[linear_missing[k]](j, i) = value;
          }
        }
      }
    }
    for (int index : involved) {
      if (fresh[index]) shared.store_differences(geometry, kernel_key(index, index, false, reach), fresh[index]);
    }
    for (const auto& key : missing) {
      shared.store(geometry, kernel_key(key.first, key.second, false, reach), diagonal_only ? nullptr : &full.at(key),
                   diagonal_only ? &diagonal.at(key) : nullptr);
    }
    for (int index : linear_missing) {
      shared.store(geometry, kernel_key(index, index, true, reach), diagonal_only ? nullptr : &linear_full.at(index),
                   diagonal_only ? &linear_diagonal.at(index) : nullptr);
    }
  }

  // A sinusoid's differences are A_m cos(w (k + m) tau0 + phi), so nu_m gains 2 mean(d^s d^m):
  // on a record of many periods, 2 |H_m(f)|^2 = 4 sigma_s^2(tau_m) / Omega0^2 times one random
  // variable, the noise's Fourier component at f in the line's phase, whatever the factor. Its
  // variance, S(f) Omega0^2 / (4 T) with S the noise's one-sided density there and T the record
  // spanned by the longer average, gives cov += 4 sigma_s^2(tau_m) sigma_s^2(tau_n) S(f) /
  // (Omega0^2 max(M_m, M_n) tau0): nearly rank one, and independent of the phase. Lines of
  // different frequencies see independent components.
  template <class Result>
  void add_sinusoid_cross_terms(const NoiseModel& model, bool diagonal_only, Result* result) {
    const int count = static_cast<int>(factors.size());
    for (const Term& line : model.terms) {
      if (line.kind != TermKind::kSinusoid || !(line.amplitude > 0.0)) continue;
      const double scale =
          4.0 * line_noise_density(model, line.shape, tau0_s) / (line.amplitude * line.amplitude * tau0_s);
      std::vector<double> line_avar(count);
      std::vector<double> terms(count);
      for (int i = 0; i < count; ++i) {
        line_avar[i] = term_avar(line, factors[i] * tau0_s);
        terms[i] = static_cast<double>(sample_count + 1 - 2LL * factors[i]);
      }
      for (int i = 0; i < count; ++i) {
        for (int j = diagonal_only ? i : 0; j < (diagonal_only ? i + 1 : count); ++j) {
          // A diagonal result is a vector: its (i, 0).
          result->coeffRef(i, diagonal_only ? 0 : j) +=
              scale * line_avar[i] * line_avar[j] / std::max(terms[i], terms[j]);
        }
      }
    }
  }

  // sum over unit pairs of weight_i weight_j (2 for i != j) times their kernel.
  template <class Kernel, class Result>
  void assemble(const NoiseModel& model, bool diagonal_only, Result* result) {
    const auto weighted = weighted_units(model);
    std::vector<int> indices;
    for (const auto& entry : weighted) indices.push_back(unit_index(entry.first));
    const double ramp_difference = ramp_difference_per_factor(model, tau0_s);
    compute_missing(indices, diagonal_only, ramp_difference != 0.0);
    for (size_t a = 0; a < weighted.size(); ++a) {
      for (size_t b = 0; b < weighted.size(); ++b) {
        const std::pair<int, int> key = unit_pair(indices[a], indices[b]);
        const double weight = weighted[a].second * weighted[b].second;
        if (diagonal_only) {
          *result += weight * (full.count(key) ? Eigen::VectorXd(full[key].diagonal()) : diagonal[key]);
        } else {
          *result += weight * full[key];
        }
      }
    }
    add_sinusoid_cross_terms(model, diagonal_only, result);
    if (ramp_difference == 0.0) return;
    // A ramp's differences c_m = ramp_difference m are the same at every k, so
    // nu_m = c_m^2 + 2 c_m mean(d^m) + (noise alone): cov(nu_m, nu_n) gains 4 c_m c_n
    // cov(mean d^m, mean d^n) (Gaussian third moments vanish). Where the ramp dominates, this is
    // most of the estimates' variance.
    Eigen::VectorXd difference(static_cast<int>(factors.size()));
    for (size_t i = 0; i < factors.size(); ++i) difference(i) = ramp_difference * factors[i];
    for (size_t a = 0; a < weighted.size(); ++a) {
      const double weight = 4.0 * weighted[a].second;
      if (diagonal_only) {
        const Eigen::VectorXd sums = linear_full.count(indices[a]) ? Eigen::VectorXd(linear_full[indices[a]].diagonal())
                                                                   : linear_diagonal[indices[a]];
        *result += weight * sums.cwiseProduct(difference.cwiseProduct(difference));
      } else {
        *result += weight * (difference * difference.transpose()).cwiseProduct(linear_full[indices[a]]);
      }
    }
  }
};

OavarCovariance::OavarCovariance(std::vector<int> averaging_factors, double tau0_s, long long sample_count)
    : cache_(new Cache) {
  for (int m : averaging_factors) check_factor(m, sample_count);
  cache_->factors = std::move(averaging_factors);
  cache_->tau0_s = tau0_s;
  cache_->sample_count = sample_count;
  cache_->variance_inflation.assign(cache_->factors.size(), 1.0);
}

OavarCovariance::~OavarCovariance() = default;

void OavarCovariance::set_pooled_term_fractions(const std::vector<double>& fractions) {
  if (fractions.size() != cache_->factors.size()) {
    throw std::invalid_argument("OavarCovariance: " + std::to_string(fractions.size()) + " term fractions for " +
                                std::to_string(cache_->factors.size()) + " averaging factors");
  }
  for (size_t i = 0; i < fractions.size(); ++i) {
    if (!(fractions[i] > 0.0 && fractions[i] <= 1.0)) {
      throw std::invalid_argument("OavarCovariance: a pooled term fraction must lie in (0, 1], not " +
                                  std::to_string(fractions[i]));
    }
    cache_->variance_inflation[i] = 1.0 / fractions[i];
  }
}

Eigen::MatrixXd OavarCovariance::covariance(const NoiseModel& model) {
  const int count = static_cast<int>(cache_->factors.size());
  Eigen::MatrixXd result = Eigen::MatrixXd::Zero(count, count);
  cache_->assemble<Eigen::MatrixXd>(model, false, &result);
  const Eigen::VectorXd scale = Eigen::Map<const Eigen::VectorXd>(cache_->variance_inflation.data(), count).cwiseSqrt();
  return scale.asDiagonal() * result * scale.asDiagonal();
}

std::vector<double> OavarCovariance::variance(const NoiseModel& model) {
  Eigen::VectorXd result = Eigen::VectorXd::Zero(static_cast<int>(cache_->factors.size()));
  cache_->assemble<Eigen::VectorXd>(model, true, &result);
  std::vector<double> variances(result.data(), result.data() + result.size());
  for (size_t i = 0; i < variances.size(); ++i) variances[i] *= cache_->variance_inflation[i];
  return variances;
}

double term_structure_function(const Term& term, double lag_s, double tau0_s) {
  const double u = std::abs(lag_s);
  const double a2 = term.amplitude * term.amplitude;
  switch (term.kind) {
    case TermKind::kWhiteAngle: return u < 0.5 * tau0_s ? 0.0 : 2.0 * a2;
    case TermKind::kWhiteRate:
      if (term.shape > 0.0) return a2 * markov_excess(u, 1.0 / (2.0 * kPi * term.shape));
      return a2 * u;
    case TermKind::kBiasInstability:
      // Flicker rate: generalised covariance u^2 ln u (its AVAR tends to 2 ln 2 B^2 / pi); the
      // cutoff only shapes taus near 1 / f0.
      return u > 0.0 ? -a2 / kPi * u * u * std::log(u) : 0.0;
    case TermKind::kRandomWalk: return -a2 * u * u * u / 6.0;
    case TermKind::kMarkov: return a2 * markov_excess(u, term.shape);
    case TermKind::kZeroDcFamily: {
      // PSD alpha f^2 e^{-beta f}: D(u) = alpha / pi^2 Re[1 / beta - 1 / (beta - 2 pi i u)].
      const std::complex<double> z(term.shape, -2.0 * kPi * u);
      return a2 / (kPi * kPi) * (1.0 / term.shape - (1.0 / z).real());
    }
    case TermKind::kZeroDcGaussian:  // D(u) = 2 (C(0) - C(u)) of the stationary angle
      return 2.0 * (noise::zero_dc_gaussian_angle_covariance(2.0, a2, term.shape, 0.0) -
                    noise::zero_dc_gaussian_angle_covariance(2.0, a2, term.shape, u));
    case TermKind::kHighPassWhite:
      return 2.0 * (noise::high_pass_white_angle_covariance(a2, term.shape, 0.0) -
                    noise::high_pass_white_angle_covariance(a2, term.shape, u));
    case TermKind::kResonance: {
      const double angle_sigma = term.amplitude / (2.0 * kPi * term.shape);
      return 2.0 * angle_sigma * angle_sigma * (1.0 - noise::resonance_angle_correlation(term.shape, term.width, u));
    }
    case TermKind::kRateRamp:
    case TermKind::kSinusoid: return 0.0;
  }
  return 0.0;
}

double model_structure_function(const NoiseModel& model, double lag_s, double tau0_s) {
  const double quantization = model.output_quantization_density;
  double total = quantization * quantization * std::abs(lag_s);
  for (const Term& term : model.terms) total += term_structure_function(term, lag_s, tau0_s);
  return total;
}

Eigen::MatrixXd oavar_covariance(const NoiseModel& model, const std::vector<int>& averaging_factors, double tau0_s,
                                 long long sample_count) {
  OavarCovariance covariance(averaging_factors, tau0_s, sample_count);
  return covariance.covariance(model);
}

std::vector<double> oavar_variance(const NoiseModel& model, const std::vector<int>& averaging_factors, double tau0_s,
                                   long long sample_count) {
  OavarCovariance covariance(averaging_factors, tau0_s, sample_count);
  return covariance.variance(model);
}

double oavar_covariance_by_direct_sum(const NoiseModel& model, int m, int n, double tau0_s, long long sample_count) {
  check_factor(m, sample_count);
  check_factor(n, sample_count);
  const PairGeometry pair(m, n, tau0_s, sample_count);
  // A sinusoid's differences at factor m are A_m cos(w (k + m) tau0 + phi) with
  // A_m = 4 Omega0 sin^2(w m tau0 / 2) / (sqrt 2 w m tau0); averaged over the phase, its cross
  // term adds 2 A_m A_n / (M_m M_n) sum_h count(h) cos(w (h + n - m) tau0) C_mn(h), summed here
  // exactly (the covariance's rank-one form holds for many periods).
  std::vector<Term> lines;
  for (const Term& term : model.terms) {
    if (term.kind == TermKind::kSinusoid) lines.push_back(term);
  }
  std::vector<double> line_sums(lines.size(), 0.0);
  double sum = 0.0, linear_sum = 0.0;
  for (long long h = pair.lowest_lag(); h <= pair.highest_lag(); ++h) {
    double c = 0.0;
    for (size_t k = 0; k < pair.offsets.size(); ++k) {
      c += pair.weights[k] * model_structure_function(model, (h + pair.offsets[k]) * tau0_s, tau0_s);
    }
    c *= pair.scale;
    const double counted = pair.count(static_cast<double>(h));
    sum += counted * c * c;
    linear_sum += counted * c;
    for (size_t s = 0; s < lines.size(); ++s) {
      line_sums[s] += counted * c * std::cos(2.0 * kPi * lines[s].shape * (h + n - m) * tau0_s);
    }
  }
  double line_part = 0.0;
  for (size_t s = 0; s < lines.size(); ++s) {
    const double angular = 2.0 * kPi * lines[s].shape;
    const auto difference_amplitude = [&](int factor) {
      const double t = angular * factor * tau0_s;
      return 4.0 * lines[s].amplitude * std::pow(std::sin(0.5 * t), 2) / (std::sqrt(2.0) * t);
    };
    line_part += difference_amplitude(m) * difference_amplitude(n) * line_sums[s];
  }
  const double ramp_difference = ramp_difference_per_factor(model, tau0_s);
  return (sum + 2.0 * ramp_difference * m * ramp_difference * n * linear_sum + line_part) * pair.normaliser();
}

}  // namespace identify
}  // namespace imu_lab
