// Integral of a function that is smooth (analytic) between known breakpoints: 8-point
// Gauss-Legendre on each piece, pieces split at the breakpoints and kept no longer than
// max_piece_s. The rule is exact for polynomials up to degree 15; for e^{i w t} its relative error
// is below 1e-20 while w * piece <= 1, so round-off (1e-16 relative) is what remains.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace imu_lab {
namespace emulator {

namespace gauss_legendre_8 {
// Nodes on [-1, 1] (positive half) and their weights (Abramowitz & Stegun table 25.4).
constexpr std::array<double, 4> kNodes = {0.1834346424956498, 0.5255324099163290, 0.7966664774136267,
                                          0.9602898564975363};
constexpr std::array<double, 4> kWeights = {0.3626837833783620, 0.3137066458778873, 0.2223810344533745,
                                            0.1012285362903763};
}  // namespace gauss_legendre_8

// Integrates over [start_s, start_s + length_s]. Pieces are placed by their offsets from start_s
// and the last one ends at offset length_s exactly, so the weights sum to length_s (a constant
// integrand gives value * length_s to round-off even when start_s is large).
// breakpoints_s: sorted instants where f or its derivatives jump; those outside the interval
// are ignored. Value needs +, * double and a zero.
template <typename Value, typename Function>
Value integrate_smooth_pieces(const Function& f, double start_s, double length_s,
                              const std::vector<double>& breakpoints_s, double max_piece_s, const Value& zero) {
  Value total = zero;
  auto integrate_piece = [&](double from_offset, double to_offset) {
    const int parts = std::max(1, static_cast<int>(std::ceil((to_offset - from_offset) / max_piece_s)));
    const double width = (to_offset - from_offset) / parts;
    const double half = 0.5 * width;
    for (int p = 0; p < parts; ++p) {
      const double middle = start_s + (from_offset + (p + 0.5) * width);
      for (std::size_t i = 0; i < gauss_legendre_8::kNodes.size(); ++i) {
        const double offset = half * gauss_legendre_8::kNodes[i];
        total = total + (f(middle - offset) + f(middle + offset)) * (half * gauss_legendre_8::kWeights[i]);
      }
    }
  };
  double piece_offset = 0.0;
  auto first = std::upper_bound(breakpoints_s.begin(), breakpoints_s.end(), start_s);
  for (auto it = first; it != breakpoints_s.end() && *it - start_s < length_s; ++it) {
    integrate_piece(piece_offset, *it - start_s);
    piece_offset = *it - start_s;
  }
  integrate_piece(piece_offset, length_s);
  return total;
}

}  // namespace emulator
}  // namespace imu_lab
