#include "imu_lab/allan/output_step.h"

#include "imu_lab/common/usable_imu_values.h"

#include <cmath>

namespace imu_lab {
namespace allan {
namespace {

// The smallest k <= max_denominator with ratio * k within the tolerance of an integer p >= 1,
// from the continued fraction of ratio; 0 when there is none.
std::int64_t fitting_denominator(double ratio, std::int64_t max_denominator) {
  // Convergents p_i / k_i: p_i = a_i p_(i-1) + p_(i-2), k_i likewise.
  double p_previous = 1.0, p_before = 0.0;
  double k_previous = 0.0, k_before = 1.0;
  double rest = ratio;
  for (int term = 0; term < 64; ++term) {
    const double a = std::floor(rest);
    const double p = a * p_previous + p_before;
    const double k = a * k_previous + k_before;
    if (k > static_cast<double>(max_denominator)) return 0;
    if (p >= 1.0 && std::abs(ratio * k - p) <= kOutputStepTolerance * p) return static_cast<std::int64_t>(k);
    const double fraction = rest - a;
    if (fraction <= 0.0) return 0;
    rest = 1.0 / fraction;
    p_before = p_previous;
    p_previous = p;
    k_before = k_previous;
    k_previous = k;
  }
  return 0;
}

}  // namespace

OutputStepDetector::OutputStepDetector(std::size_t channel_count) : states_(channel_count) {}

void OutputStepDetector::push(const double* values) {
  for (std::size_t c = 0; c < states_.size(); ++c) {
    if (is_usable_imu_value(values[c])) add(states_[c], values[c]);
  }
}

void OutputStepDetector::add(State& state, double value) {
  if (state.finite_count == 0) state.first_value = value;
  ++state.finite_count;
  if (value != state.first_value) state.varied = true;
  if (state.ruled_out) return;
  const double magnitude = std::abs(value);
  if (magnitude == 0.0) return;  // a multiple of every step
  if (magnitude > state.max_abs) state.max_abs = magnitude;
  if (state.step == 0.0) {
    state.step = magnitude;
    return;
  }
  const double ratio = magnitude / state.step;
  const double multiple = std::nearbyint(ratio);
  if (multiple >= 1.0 && std::abs(ratio - multiple) <= kOutputStepTolerance * multiple) {
    if (multiple > static_cast<double>(kMaxOutputStepMultiple)) state.ruled_out = true;
    return;
  }
  // magnitude = p * step / k: every value so far is a multiple of step / k as well.
  const std::int64_t k = fitting_denominator(ratio, kMaxOutputStepMultiple);
  if (k == 0 || state.max_abs / (state.step / static_cast<double>(k)) > static_cast<double>(kMaxOutputStepMultiple)) {
    state.ruled_out = true;
    return;
  }
  state.step /= static_cast<double>(k);
}

std::vector<ChannelOutputStep> OutputStepDetector::channels() const {
  std::vector<ChannelOutputStep> channels;
  for (const State& state : states_) {
    ChannelOutputStep channel;
    channel.finite_value_count = state.finite_count;
    channel.quantised = !state.ruled_out && state.varied && state.step > 0.0;
    if (channel.quantised) {
      channel.step = state.step;
      channel.largest_multiple = static_cast<std::int64_t>(std::llround(state.max_abs / state.step));
    }
    channels.push_back(channel);
  }
  return channels;
}

}  // namespace allan
}  // namespace imu_lab
