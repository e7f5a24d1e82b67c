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
constexpr std::array<double, 4> kNodes = {0.1834346424956498, 0.5255324099163290,
                                          0.7966664774136267, 0.9602898564975363};
constexpr std::array<double, 4> kWeights = {0.3626837833783620, 0.3137066458778873,
                                            0.2223810344533745, 0.1012285362903763};
}  // namespace gauss_legendre_8

// breakpoints_s: sorted instants where f or its derivatives jump; those outside the interval
// are ignored. Value needs +, * double and a zero.
template <typename Value, typename Function>
Value integrate_smooth_pieces(const Function& f, double start_s, double end_s,
                              const std::vector<double>& breakpoints_s, double max_piece_s,
                              const Value& zero) {
  Value total = zero;
  auto integrate_piece = [&](double a, double b) {
    const int parts = std::max(1, static_cast<int>(std::ceil((b - a) / max_piece_s)));
    const double width = (b - a) / parts;
    for (int p = 0; p < parts; ++p) {
      const double middle = a + (p + 0.5) * width;
      const double half = 0.5 * width;
      for (std::size_t i = 0; i < gauss_legendre_8::kNodes.size(); ++i) {
        const double offset = half * gauss_legendre_8::kNodes[i];
        total = total + (f(middle - offset) + f(middle + offset)) * (half * gauss_legendre_8::kWeights[i]);
      }
    }
  };
  double piece_start = start_s;
  auto first = std::upper_bound(breakpoints_s.begin(), breakpoints_s.end(), start_s);
  for (auto it = first; it != breakpoints_s.end() && *it < end_s; ++it) {
    integrate_piece(piece_start, *it);
    piece_start = *it;
  }
  integrate_piece(piece_start, end_s);
  return total;
}

}  // namespace emulator
}  // namespace imu_lab
