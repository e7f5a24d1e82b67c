// Per channel, streaming: is every finite value an integer multiple of one step, the output's
// least significant bit (a sensor that outputs n * LSB)? The step found is the largest one all
// values are multiples of: the LSB itself once the noise has visited neighbouring levels (two
// values n and n + 1 steps apart prove it). Quantization noise of that output is white with
// variance step^2 / 12 per sample while the noise spans several levels (doc/models.md).
//
// Tolerance, relative and derived from the arithmetic: values converted to SI in double precision
// (a decimal parsed, times a unit factor) carry a relative error delta of a few ulps (< 1e-15). A
// value fits the step when |v / step - n| <= kOutputStepTolerance * n, with the tolerance 1e-12
// (a thousand times that error). When a value does not fit, v / step = p / k for the true
// multiples, and the step shrinks to step / k: k is the denominator of the first continued-fraction
// convergent of v / step that fits within the tolerance. A convergent p_i / k_i before the true one
// misses v / step by about 1 / (k_i k_(i+1)), so it is never taken for the true one while
// kOutputStepTolerance * kMaxOutputStepMultiple^2 < 1 (0.017 here: multiples up to 2^17, an 18-bit
// output). A value further than that many steps from zero means a step too fine to tell from
// rounding: the channel is reported unquantised (step 0), as are values that passed through single
// precision (relative error 6e-8) and unquantised data, for which the step collapses after a few
// values (a continuous value fits a step by chance with probability 2 * 1e-12 * n). The step itself
// is as exact as the values (relative error about delta).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace imu_lab {
namespace allan {

constexpr double kOutputStepTolerance = 1e-12;
constexpr std::int64_t kMaxOutputStepMultiple = std::int64_t{1} << 17;

struct ChannelOutputStep {
  double step = 0.0;                  // the LSB in the channel's units; 0: not quantised (or undecided)
  bool quantised = false;             // every finite value so far is a multiple of `step` (at least two differ)
  std::int64_t largest_multiple = 0;  // max |value| / step over the values
  std::int64_t finite_value_count = 0;
};

class OutputStepDetector {
 public:
  explicit OutputStepDetector(std::size_t channel_count);

  // One sample of every channel; NaN/Inf values are ignored.
  void push(const double* values);

  std::vector<ChannelOutputStep> channels() const;
  std::size_t channel_count() const { return states_.size(); }

 private:
  struct State {
    double step = 0.0;       // candidate; 0 until a nonzero value
    double max_abs = 0.0;    // largest |value| so far
    bool ruled_out = false;  // some value is no multiple of any step this output could have
    bool varied = false;     // two different values seen
    double first_value = 0.0;
    std::int64_t finite_count = 0;
  };
  static void add(State& state, double value);

  std::vector<State> states_;
};

}  // namespace allan
}  // namespace imu_lab
