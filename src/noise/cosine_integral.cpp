// Ci(x): power series for small x, continued fraction of E1(ix) (Ci(x) = -Re E1(ix)) beyond.
#include <cmath>
#include <complex>
#include <stdexcept>

#include "imu_lab/noise/analytic_avar.h"

namespace imu_lab {
namespace noise {

namespace {
constexpr double kEulerGamma = 0.57721566490153286061;

double cosine_integral_series(double x) {
  // Ci(x) = gamma + ln x + sum_{k>=1} (-1)^k x^{2k} / (2k (2k)!)
  const double x2 = x * x;
  double term = 1.0, sum = 0.0;
  for (int k = 1; k < 100; ++k) {
    term *= -x2 / ((2.0 * k - 1.0) * (2.0 * k));
    const double contribution = term / (2.0 * k);
    sum += contribution;
    if (std::abs(contribution) < 1e-17 * std::abs(sum)) break;
  }
  return kEulerGamma + std::log(x) + sum;
}

double cosine_integral_continued_fraction(double x) {
  // E1(z) = e^{-z} / (z + 1 - 1/(z + 3 - 4/(z + 5 - ...))), modified Lentz.
  const std::complex<double> z(0.0, x);
  const double tiny = 1e-300;
  std::complex<double> b = z + 1.0;
  std::complex<double> c = 1.0 / tiny;
  std::complex<double> d = 1.0 / b;
  std::complex<double> h = d;
  for (int i = 1; i < 1000; ++i) {
    const double a = -static_cast<double>(i) * i;
    b += 2.0;
    d = 1.0 / (a * d + b);
    c = b + a / c;
    const std::complex<double> delta = c * d;
    h *= delta;
    if (std::abs(delta - 1.0) < 1e-16) break;
  }
  const std::complex<double> e1 = h * std::exp(-z);
  return -e1.real();
}
}  // namespace

double cosine_integral(double x) {
  if (!(x > 0.0)) throw std::domain_error("cosine_integral: x must be positive");
  return x <= 4.0 ? cosine_integral_series(x) : cosine_integral_continued_fraction(x);
}

}  // namespace noise
}  // namespace imu_lab
