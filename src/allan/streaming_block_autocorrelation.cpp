#include "imu_lab/allan/streaming_block_autocorrelation.h"

#include <algorithm>
#include <limits>
#include <utility>

namespace imu_lab {
namespace allan {

void BlockMeanAutocorrelation::SeriesMoments::add(double value) {
  if (count == 0) {
    first = value;
  } else {
    lag1_products.add(last * value);
  }
  last = value;
  sum.add(value);
  squares.add(value * value);
  ++count;
}

void BlockMeanAutocorrelation::add_block_mean(double mean, Chain& chain) {
  double value = mean;
  for (int d = 0; d <= kMaxBlockDifferences; ++d) {
    const bool had_previous = chain[d].count > 0;
    const double previous = chain[d].last;
    chain[d].add(value);
    if (!had_previous) break;
    value -= previous;  // the next difference
  }
}

IMU_LAB_ALLAN_BLOCK_LOOP
void BlockMeanAutocorrelation::add_steady_block_means(const double* first_end, std::int64_t block_count, int m,
                                                      Chain& chain) {
  // The same operations in the same order as add_block_mean, so the same bits.
  LaneVector previous = {chain[0].last, chain[1].last, chain[2].last, chain[3].last};
  ChainPartials partial;
  for (std::int64_t b = 0; b < block_count; ++b) {
    const double* end = first_end + b * m;
    const double mean = (end[0] - end[-m]) / m;
    const double once = mean - previous[0];
    const double twice = once - previous[1];
    const LaneVector values = {mean, once, twice, twice - previous[2]};
    partial.lag1_products += previous * values;
    partial.sum += values;
    partial.squares += values * values;
    previous = values;
  }
  for (int d = 0; d <= kMaxBlockDifferences; ++d) {
    chain[d].sum.add(partial.sum[d]);
    chain[d].squares.add(partial.squares[d]);
    chain[d].lag1_products.add(partial.lag1_products[d]);
    chain[d].last = previous[d];
    chain[d].count += block_count;
  }
}

double BlockMeanAutocorrelation::SeriesMoments::centred_lag1() const {
  if (count < 2) return 0.0;
  const double mean = sum.value() / count;
  const double all_but_last = sum.value() - last;
  const double all_but_first = sum.value() - first;
  return lag1_products.value() - mean * (all_but_last + all_but_first) + (count - 1) * mean * mean;
}

double BlockMeanAutocorrelation::SeriesMoments::centred_squares() const {
  if (count < 1) return 0.0;
  return std::max(0.0, squares.value() - sum.value() * (sum.value() / count));
}

BlockMeanAutocorrelation::BlockMeanAutocorrelation(std::vector<int> averaging_factors)
    : averaging_factors_(std::move(averaging_factors)),
      open_(averaging_factors_.size()),
      closed_(averaging_factors_.size()),
      next_block_end_(averaging_factors_.size()) {
  for (std::size_t i = 0; i < averaging_factors_.size(); ++i) next_block_end_[i] = averaging_factors_[i];
}

void BlockMeanAutocorrelation::fold(const Chain& segment, BlockSeriesSummary& pooled) {
  for (int d = 0; d <= kMaxBlockDifferences; ++d) {
    const SeriesMoments& moments = segment[d];
    if (moments.count == 0) continue;
    pooled.lag1_numerator[d] += moments.centred_lag1();
    pooled.centred_squares[d] += moments.centred_squares();
    pooled.raw_squares[d] += moments.squares.value();
    pooled.count[d] += moments.count;
  }
}

void BlockMeanAutocorrelation::start_segment() {
  for (std::size_t i = 0; i < averaging_factors_.size(); ++i) {
    fold(open_[i], closed_[i]);
    open_[i] = Chain();
    next_block_end_[i] = averaging_factors_[i];
  }
}

void BlockMeanAutocorrelation::update(const PhaseRing& ring) {
  const std::int64_t newest = ring.newest();
  for (std::size_t i = 0; i < averaging_factors_.size(); ++i) {
    std::int64_t& block_end = next_block_end_[i];
    if (block_end > newest) continue;
    const int m = averaging_factors_[i];
    Chain& chain = open_[i];
    const std::int64_t block_count = (newest - block_end) / m + 1;
    // Few block means (push() of one sample), or a segment's first ones: term by term.
    if (block_count < BlockSums::kLanes || chain[kMaxBlockDifferences].count == 0) {
      for (; block_end <= newest; block_end += m)
        add_block_mean((ring.at(block_end) - ring.at(block_end - m)) / m, chain);
      continue;
    }
    add_steady_block_means(ring.point(block_end), block_count, m, chain);
    block_end += block_count * m;
  }
}

BlockSeriesSummary BlockMeanAutocorrelation::summary(std::size_t tau_index) const {
  BlockSeriesSummary pooled = closed_[tau_index];
  fold(open_[tau_index], pooled);
  return pooled;
}

std::size_t BlockMeanAutocorrelation::heap_bytes() const {
  return averaging_factors_.capacity() * sizeof(int) + open_.capacity() * sizeof(Chain) +
         closed_.capacity() * sizeof(BlockSeriesSummary) + next_block_end_.capacity() * sizeof(std::int64_t);
}

void BlockMeanAutocorrelation::save(BinaryWriter& out) const {
  out.put_u64(averaging_factors_.size());
  for (std::size_t i = 0; i < averaging_factors_.size(); ++i) {
    for (const SeriesMoments& moments : open_[i]) {
      moments.sum.save(out);
      moments.squares.save(out);
      moments.lag1_products.save(out);
      out.put_f64(moments.first);
      out.put_f64(moments.last);
      out.put_i64(moments.count);
    }
    const BlockSeriesSummary& pooled = closed_[i];
    for (int d = 0; d <= kMaxBlockDifferences; ++d) {
      out.put_f64(pooled.lag1_numerator[d]);
      out.put_f64(pooled.centred_squares[d]);
      out.put_f64(pooled.raw_squares[d]);
      out.put_i64(pooled.count[d]);
    }
  }
  out.put_i64s(next_block_end_);
}

void BlockMeanAutocorrelation::load(BinaryReader& in, std::int64_t processed_count) {
  in.expect_u64(averaging_factors_.size(), "number of averaging factors");
  for (std::size_t i = 0; i < averaging_factors_.size(); ++i) {
    for (SeriesMoments& moments : open_[i]) {
      moments.sum.load(in);
      moments.squares.load(in);
      moments.lag1_products.load(in);
      moments.first = in.get_finite_f64();
      moments.last = in.get_finite_f64();
      moments.count = in.get_count();
    }
    BlockSeriesSummary& pooled = closed_[i];
    for (int d = 0; d <= kMaxBlockDifferences; ++d) {
      pooled.lag1_numerator[d] = in.get_finite_f64();
      pooled.centred_squares[d] = in.get_finite_f64();
      pooled.raw_squares[d] = in.get_finite_f64();
      pooled.count[d] = in.get_count();
      // The engine's counts never near 2^63; a payload whose open and pooled counts sum past it
      // would overflow when the segment is folded.
      if (open_[i][d].count > std::numeric_limits<std::int64_t>::max() - pooled.count[d]) {
        in.fail("block mean series counts overflow when the open segment is pooled");
      }
    }
  }
  next_block_end_ = load_next_block_ends(in, 1, averaging_factors_, processed_count, "next block mean");
}

}  // namespace allan
}  // namespace imu_lab
