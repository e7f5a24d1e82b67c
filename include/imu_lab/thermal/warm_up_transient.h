// The self-heating warm-up of a sensor's output at power-on, fitted and removed before an Allan
// analysis (Golovach 2017 eqs. 3.3-3.6: the temperature, and with it the bias, settles as a sum
// of exponentials). Per channel the output's block means (blocks of block_s seconds, stamps
// counted from the first sample, t = 0) are fitted with
//   b(t) = c + sum_k a_k e^{-t / T_k},   k = 1..K, K in 0..max_terms,
// each block mean against the model's exact average over the block's stamps, by nonlinear least
// squares (Ceres) started from a grid over the time constants (the amplitudes and c are linear
// given them). K grows while the added term passes an F-test at `significance` on the fit's
// residual sum of squares, the residuals' correlation allowed for (below).
//
// Uncertainties: the block means are weighted by their sample count (white noise gives a block
// mean the variance sigma^2 / count). The least-squares covariance is scaled by the residual
// variance and by f, how much more a mean over m blocks varies than for independent blocks:
// r(m) = m AVAR(m) / AVAR(1) of the residual series, measured at octaves up to a 32nd of the
// record, fitted with 1 + c1 m + c2 m^2 (flicker, random walk) and taken at m = the longest time
// constant in blocks (at most an eighth of the record). Random walk and flicker make neighbouring
// block means correlated, so the naive least-squares sigma understates by about sqrt(f)
// (doc/warm_up.md shows the coverage).
//
// The linear trend (a rate ramp R t, the part of the drift the Allan-Krobka dispersion removes:
// AVAR - AKVAR = R^2 tau^2 / 2, doc/models.md) is fitted to what is left after the removal, its
// sigma scaled the same way with f taken at an eighth of the record.
#pragma once

#include <Eigen/Core>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace imu_lab {
namespace thermal {

// One block of one channel: the mean of its usable samples, where they lie.
struct WarmUpBlock {
  double start_s = 0.0;  // first sample's stamp in the block, from the first sample of the input
  double end_s = 0.0;    // last sample's stamp in the block
  double mean = 0.0;
  std::size_t count = 0;
};

// Block means of several channels, accumulated sample by sample in stamp order. A non-finite
// value is left out of its channel's block; blocks without a usable value are not kept.
class WarmUpBlockMeans {
 public:
  // Throws std::invalid_argument for block_s <= 0 or no channel.
  WarmUpBlockMeans(std::size_t channel_count, double block_s);
  // `values` holds channel_count values.
  void push(std::int64_t stamp_ns, const double* values);
  std::vector<WarmUpBlock> blocks(std::size_t channel) const;
  bool empty() const { return !started_; }
  std::int64_t first_stamp_ns() const { return first_stamp_ns_; }
  double block_s() const { return block_s_; }
  std::size_t channel_count() const { return channel_count_; }

 private:
  struct Accumulating {
    long long index = -1;
    double first_s = 0.0;
    double last_s = 0.0;
    std::vector<double> sums;
    std::vector<std::size_t> counts;
  };
  void close_block();

  std::size_t channel_count_;
  double block_s_;
  bool started_ = false;
  std::int64_t first_stamp_ns_ = 0;
  Accumulating current_;
  std::vector<std::vector<WarmUpBlock>> blocks_;
};

struct WarmUpFitOptions {
  int max_terms = 2;           // exponentials tried: 0..max_terms
  double significance = 1e-3;  // a further term is kept when the F-test's p is below this
  // Time constants searched: from min_time_constant_blocks blocks to max_time_constant_records
  // times the record; a fit that ends at either bound is not kept.
  double min_time_constant_blocks = 3.0;
  double max_time_constant_records = 1.0;
};

struct WarmUpTerm {
  double amplitude = 0.0;  // a_k, in the channel's unit
  double amplitude_sigma = 0.0;
  double time_constant_s = 0.0;  // T_k
  double time_constant_sigma_s = 0.0;
};

// A straight line c + slope * t fitted to the output after the warm-up's removal.
struct LinearTrend {
  double slope_per_s = 0.0;  // channel unit per second (rad/s^2 for a gyro's rate)
  double slope_sigma_per_s = 0.0;
  double value_at_start = 0.0;
};

struct WarmUpFit {
  std::vector<WarmUpTerm> terms;  // by increasing time constant; empty: no warm-up found
  double constant = 0.0;          // c
  double constant_sigma = 0.0;
  // Of (c, a_1, T_1, a_2, T_2, ...), the sigmas above are its diagonal's roots.
  Eigen::MatrixXd covariance;
  std::size_t block_count = 0;
  double block_s = 0.0;
  double record_s = 0.0;               // last block's end
  double residual_rms = 0.0;           // of the block means about the model
  double correlation_inflation = 1.0;  // f above (the covariance carries it)
  std::vector<double> added_term_p;    // the F-test's p for term 1, 2, ... as tried
  LinearTrend trend;                   // of what is left after the removal

  // The removed transient sum_k a_k e^{-t/T_k} (without c) and its standard deviation from the
  // covariance (first-order propagation).
  double transient(double time_s) const;
  double transient_sigma(double time_s) const;
};

// Throws std::invalid_argument when there are fewer blocks than the largest model has
// parameters plus a few (the message says how many are needed).
WarmUpFit fit_warm_up(const std::vector<WarmUpBlock>& blocks, double block_s, const WarmUpFitOptions& options = {});

}  // namespace thermal
}  // namespace imu_lab
