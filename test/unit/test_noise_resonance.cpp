// The exact generators of rates that are the derivative of a stationary Markov angle: the
// damped second-order resonance and white noise through a first-order high-pass (Krobka
// table 7.3). Their transition against the matrix exponential, their AVAR against the closed
// forms (Bonferroni, each point at its exact EDF: these are not power-law processes), the
// resonance's spectral peak and width, and reproducibility per seed.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <unsupported/Eigen/FFT>
#include <unsupported/Eigen/MatrixFunctions>
#include <cmath>

#include "imu_lab/allan/edf.h"
#include "imu_lab/noise/analytic_avar.h"
#include "imu_lab/noise/make_noise_process.h"
#include "imu_lab/noise/resonance_noise.h"
#include "test_noise_avar_check.h"

namespace imu_lab {
namespace noise {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr std::size_t kSamples = std::size_t(1) << 20;
constexpr int kMaxFactor = 1 << 14;

std::vector<double> generate(NoiseProcess& process, std::size_t count, double tau0) {
  std::size_t k = 0;
  return test::collect(count, [&]() { return process.next_interval_average(tau0 * k++, tau0); });
}

test::EdfOfFactor angle_edf(const std::function<double(double)>& covariance, double tau0, long correlation_samples) {
  return test::stationary_angle_edf(covariance, tau0, correlation_samples, kMaxFactor);
}

void expect_avar_matches(const std::vector<double>& rates, double tau0, const std::function<double(double)>& expected,
                         const test::EdfOfFactor& edf, const char* what) {
  const test::AvarCheck check = test::check_avar(rates, tau0, expected, 1, kMaxFactor, 0.997, edf);
  EXPECT_TRUE(check.passed()) << what << "\n" << check.table;
  std::printf("[avar] %-36s points %2d  worst |ratio-1|/sqrt(2/edf) = %.2f (ratio %.4f)  rejected %d\n", what,
              check.point_count, check.worst_normalised_deviation, check.worst_ratio, check.rejected_points);
}

TEST(NoiseResonance, ExactEdfOfWhiteNoise) {
  // White rate noise (V(j) = j): at m = 1 the second differences have gamma = (2, -1, 0, ...), so
  // EDF = 4 M^2 / (4 M + 2 (M - 1)) exactly; at larger m it is near the power-law (Greenhall)
  // EDF the other tests use (which at m = 1 is 17 % higher).
  const long terms = static_cast<long>(kSamples) - 1;
  EXPECT_NEAR(test::exact_overlapping_edf([](long j) { return double(j); }, 1, kSamples, 0),
              4.0 * terms * terms / (4.0 * terms + 2.0 * (terms - 1)), 1e-6 * terms);
  for (int m : {16, 1024}) {
    const double exact = test::exact_overlapping_edf([](long j) { return double(j); }, m, kSamples, 0);
    const double power_law = allan::equivalent_degrees_of_freedom(allan::Statistic::kOverlappingAllan, 0, m,
                                                                  static_cast<long long>(kSamples + 1));
    EXPECT_NEAR(exact / power_law, 1.0, 0.1) << m;
  }
}

TEST(NoiseResonance, TransitionIsTheMatrixExponentialAndNoiseKeepsItStationary) {
  const double fn = 20.0, width = 1.5, rms = 2e-3, h = 0.01;
  ResonanceNoise resonance(ResonanceParameters{rms, fn, width}, NormalStream(1));
  const double wn = 2 * kPi * fn, zeta = width / (2 * fn);
  Eigen::Matrix2d a;
  a << 0.0, 1.0, -wn * wn, -2.0 * zeta * wn;
  const Eigen::Matrix2d expm = (a * h).exp();
  EXPECT_LT((resonance.transition(h) - expm).norm(), 1e-13 * expm.norm());
  // Van Loan: the discrete noise covariance integral_0^h e^{As} G G^T e^{A^T s} ds, G = (0, q),
  // q^2 = 4 zeta w_n rms^2 (the drive that gives Var(z') = rms^2), from one matrix exponential.
  const double q2 = 4.0 * zeta * wn * rms * rms;
  Eigen::Matrix4d van_loan = Eigen::Matrix4d::Zero();
  van_loan.topLeftCorner<2, 2>() = -a;
  van_loan(1, 3) = q2;
  van_loan.bottomRightCorner<2, 2>() = a.transpose();
  const Eigen::Matrix4d e = (van_loan * h).exp();
  const Eigen::Matrix2d q_discrete = e.bottomRightCorner<2, 2>().transpose() * e.topRightCorner<2, 2>();
  const Eigen::Matrix2d l = resonance.noise_factor(h);
  EXPECT_LT((l * l.transpose() - q_discrete).norm(), 1e-9 * q_discrete.norm());
}

TEST(NoiseResonance, AvarMatchesTheClosedForm) {
  // A 20 Hz mode 1.5 Hz wide at 100 Hz, and a 70 Hz mode above the Nyquist frequency: exact
  // interval averages carry its aliased AVAR exactly.
  for (double fn : {20.0, 70.0}) {
    const ResonanceParameters parameters{1e-3, fn, 1.5};
    auto process = make_noise_process(parameters, fn == 20.0 ? 51 : 52);
    const double tau0 = 0.01;
    const auto rates = generate(*process, kSamples, tau0);
    const double sigma2 = std::pow(1e-3 / (2 * kPi * fn), 2);
    // The angle's correlation e^{-pi width u} is 1e-16 after 8 s.
    expect_avar_matches(
        rates, tau0, [&](double tau) { return resonance_avar(1e-3, fn, 1.5, tau); },
        angle_edf([&](double u) { return sigma2 * resonance_angle_correlation(fn, 1.5, u); }, tau0, 800),
        fn == 20.0 ? "resonance 20 Hz at 100 Hz" : "resonance 70 Hz at 100 Hz");
  }
}

TEST(NoiseResonance, PointSamplesOfTheRateRejected) {
  // Power: the mode's rate z' sampled at the interval ends instead of averaged (what a generator
  // that forgot the interval average would emit) is rejected with the same seed and taus.
  ResonanceNoise resonance(ResonanceParameters{1e-3, 20.0, 1.5}, NormalStream(51));
  const double tau0 = 0.01;
  std::vector<double> rates;
  for (std::size_t k = 0; k < kSamples; ++k) {
    resonance.next_interval_average(k * tau0, tau0);
    rates.push_back(resonance.angle_rate());
  }
  const double sigma2 = std::pow(1e-3 / (2 * kPi * 20.0), 2);
  const auto check = test::check_avar(
      rates, tau0, [&](double tau) { return resonance_avar(1e-3, 20.0, 1.5, tau); }, 1, kMaxFactor, 0.997,
      angle_edf([&](double u) { return sigma2 * resonance_angle_correlation(20.0, 1.5, u); }, tau0, 800));
  EXPECT_FALSE(check.passed()) << check.table;
  std::printf("[power] resonance point samples: %d of %d taus rejected (worst ratio %.3f)\n", check.rejected_points,
              check.point_count, check.worst_ratio);
}

TEST(NoiseResonance, SpectralPeakAtTheNaturalFrequencyWithTheGivenWidth) {
  // Welch (rectangular, non-overlapping segments) at 200 Hz, divided by the interval average's
  // sinc^2; near the peak f^2 / S(f) = (f^4 - (2 f_n^2 - w^2) f^2 + f_n^4) / C is linear in
  // (f^4, f^2, 1), so a weighted least-squares fit gives f_n and the -3 dB width w with their
  // standard errors (each bin's periodogram is S chi^2_2K / 2K over K segments; the scale is
  // estimated from the residuals). Both must lie within 4 standard errors of the truth.
  const double fn = 20.0, width = 1.5, tau0 = 0.005;
  auto process = make_noise_process(ResonanceParameters{1e-3, fn, width}, 53);
  const std::size_t segment = 1 << 13, segments = 256;
  const auto rates = generate(*process, segment * segments, tau0);
  Eigen::FFT<double> fft;
  std::vector<double> psd(segment / 2, 0.0);
  for (std::size_t s = 0; s < segments; ++s) {
    std::vector<double> piece(rates.begin() + s * segment, rates.begin() + (s + 1) * segment);
    std::vector<std::complex<double>> spectrum;
    fft.fwd(spectrum, piece);
    for (std::size_t j = 0; j < segment / 2; ++j) psd[j] += std::norm(spectrum[j]) * tau0 / segment / segments;
  }
  const double resolution = 1.0 / (segment * tau0);
  std::vector<double> f, y;
  for (std::size_t j = 1; j < segment / 2; ++j) {
    const double freq = j * resolution;
    if (std::abs(freq - fn) > 3.0 * width) continue;
    const double x = kPi * freq * tau0;
    const double sinc2 = std::pow(std::sin(x) / x, 2);
    f.push_back(freq);
    y.push_back(freq * freq / (psd[j] / sinc2));
  }
  const Eigen::Index n = static_cast<Eigen::Index>(f.size());
  Eigen::MatrixXd design(n, 3);
  Eigen::VectorXd observed(n), weights = Eigen::VectorXd::Ones(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    design.row(i) << std::pow(f[i], 4), f[i] * f[i], 1.0;
    observed[i] = y[i];
  }
  Eigen::Vector3d p = Eigen::Vector3d::Zero();
  Eigen::Matrix3d covariance;
  for (int pass = 0; pass < 3; ++pass) {  // weights 1 / fitted^2 (relative errors are equal)
    const Eigen::MatrixXd wx = weights.asDiagonal() * design;
    p = (design.transpose() * wx).ldlt().solve(wx.transpose() * observed);
    const Eigen::VectorXd fitted = design * p;
    const Eigen::VectorXd residual = observed - fitted;
    const double scale = residual.cwiseProduct(residual).cwiseProduct(weights).sum() / (n - 3);
    covariance = scale * (design.transpose() * wx).inverse();
    weights = fitted.cwiseInverse().cwiseAbs2();
  }
  const double a = p[0], b = p[1], d = p[2];
  const double fn_hat = std::pow(d / a, 0.25);
  const double w_hat = std::sqrt(b / a + 2.0 * std::sqrt(d / a));
  Eigen::Vector3d grad_f(-0.25 * fn_hat / a, 0.0, 0.25 * fn_hat / d);
  Eigen::Vector3d grad_w(-(b / (a * a) + std::sqrt(d) * std::pow(a, -1.5)) / (2 * w_hat), 1.0 / (2 * w_hat * a),
                         1.0 / (2 * w_hat * std::sqrt(a * d)));
  const double sigma_f = std::sqrt(grad_f.dot(covariance * grad_f));
  const double sigma_w = std::sqrt(grad_w.dot(covariance * grad_w));
  std::printf(
      "[psd] peak %.4f +- %.4f Hz (truth %.1f), width %.4f +- %.4f Hz (truth %.2f), %ld bins, "
      "resolution %.4f Hz\n",
      fn_hat, sigma_f, fn, w_hat, sigma_w, width, static_cast<long>(n), resolution);
  EXPECT_LT(std::abs(fn_hat - fn), 4.0 * sigma_f);
  EXPECT_LT(std::abs(w_hat - width), 4.0 * sigma_w);
  EXPECT_LT(sigma_w, 0.02 * width);  // the test resolves the width to better than 2 %
}

TEST(NoiseResonance, ReproduciblePerSeed) {
  for (const ProcessParameters& parameters : {ProcessParameters{ResonanceParameters{1e-3, 20.0, 1.5}},
                                              ProcessParameters{HighPassWhiteParameters{1e-3, 0.5}}}) {
    auto first = make_noise_process(parameters, 7), again = make_noise_process(parameters, 7),
         other = make_noise_process(parameters, 8);
    const auto a = generate(*first, 1000, 0.01), b = generate(*again, 1000, 0.01), c = generate(*other, 1000, 0.01);
    EXPECT_EQ(a, b);
    EXPECT_NE(a, c);
  }
}

TEST(NoiseHighPassWhite, AvarMatchesTable73) {
  // Corner 0.5 Hz: white (alpha / tau) below ~0.3 s, white-angle-like 3 alpha / (4 pi beta tau^2)
  // beyond.
  const double density = 1e-3, corner = 0.5, tau0 = 0.01;
  auto process = make_noise_process(HighPassWhiteParameters{density, corner}, 54);
  const auto rates = generate(*process, kSamples, tau0);
  const double alpha = density * density;
  // e^{-2 pi 0.5 u} is 1e-16 after 12 s.
  expect_avar_matches(
      rates, tau0, [&](double tau) { return high_pass_white_avar(alpha, corner, tau); },
      angle_edf([&](double u) { return high_pass_white_angle_covariance(alpha, corner, u); }, tau0, 1200),
      "high-pass white 0.5 Hz");
  // One sample's variance, 2 (C(0) - C(tau0)) / tau0^2, against the generated samples' (nearly
  // white: relative standard error sqrt(2 / N); 5 of them allowed).
  double sum_squares = 0.0;
  for (double r : rates) sum_squares += r * r;
  EXPECT_NEAR(sum_squares / rates.size() / process->sample_variance(tau0), 1.0, 5.0 * std::sqrt(2.0 / rates.size()));
}

}  // namespace
}  // namespace noise
}  // namespace imu_lab
