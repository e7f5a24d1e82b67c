// The rate PSD of every term of the identification's model (identify::term_psd,
// noise/analytic_psd.h) against its analytic AVAR (identify::term_avar) through the integral of
// doc/noise_families.md eq. (1), 1e-6 relative: a factor 2 (one- vs two-sided) or 2 pi (f vs
// omega) in either fails. And the interval-averaged, aliased PSD of the samples against the
// closed form of an averaged Markov sequence's spectrum.
#include <gtest/gtest.h>

#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <algorithm>
#include <cmath>
#include <complex>
#include <vector>

#include "imu_lab/identify/noise_model.h"
#include "imu_lab/noise/analytic_psd.h"

namespace imu_lab {
namespace identify {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kRelative = 1e-6;

// Eq. (1), 4 int_0^f_max S(f) sin^4(pi f tau) / (pi f tau)^2 df, by Gauss-Kronrod between the
// kernel's zeros k / tau and the PSD's own break points (a cutoff, a resonance's peak).
double avar_integral(const std::function<double(double)>& psd, double tau_s, double f_max_hz,
                     std::vector<double> break_points_hz = {}) {
  for (double f = 0.0; f < f_max_hz; f += 1.0 / tau_s) break_points_hz.push_back(f);
  break_points_hz.push_back(f_max_hz);
  std::sort(break_points_hz.begin(), break_points_hz.end());
  double sum = 0.0;
  for (std::size_t i = 0; i + 1 < break_points_hz.size(); ++i) {
    const double low = std::max(0.0, break_points_hz[i]), high = std::min(f_max_hz, break_points_hz[i + 1]);
    if (!(high > low)) continue;
    sum += boost::math::quadrature::gauss_kronrod<double, 61>::integrate(
        [&](double f) {
          if (f <= 0.0) return 0.0;
          const double x = kPi * f * tau_s, s = std::sin(x);
          return 4.0 * psd(f) * s * s * s * s / (x * x);
        },
        low, high, 4, 1e-12);
  }
  return sum;
}

// The tail of eq. (1) beyond f_max (a multiple of 1 / tau) for a PSD that is S_inf times a
// periodic factor there, whose product with sin^4 averages to `mean_of_kernel_product`:
// 4 S_inf mean / (pi^2 tau^2 f_max), to O(1 / f_max^2).
double tail(double psd_scale, double mean_of_kernel_product, double tau_s, double f_max_hz) {
  return 4.0 * psd_scale * mean_of_kernel_product / (kPi * kPi * tau_s * tau_s * f_max_hz);
}

TEST(NoiseAnalyticPsd, WhiteRateAndQuantizationIntegrateToTheirAvar) {
  const double tau0 = 0.01;
  const Term white = Term{TermKind::kWhiteRate, 2e-4};
  const Term angle = Term{TermKind::kWhiteAngle, 3e-6};
  for (int m : {1, 2, 5, 40}) {
    const double tau = m * tau0, f_max = 200.0 / tau0;
    auto psd = [&](const Term& t) { return [&t, tau0](double f) { return term_psd(t, f, tau0); }; };
    // sin^4 averages to 3/8; sin^2(pi f tau0) sin^4(pi f m tau0) to 5/16 for m = 1, 3/16 above.
    const double white_numeric = avar_integral(psd(white), tau, f_max) + tail(2e-4 * 2e-4, 3.0 / 8.0, tau, f_max);
    EXPECT_NEAR(white_numeric / term_avar(white, tau), 1.0, kRelative) << "m " << m;
    const double angle_numeric = avar_integral(psd(angle), tau, f_max) +
                                 tail(4.0 * 3e-6 * 3e-6 / tau0, m == 1 ? 5.0 / 16.0 : 3.0 / 16.0, tau, f_max);
    EXPECT_NEAR(angle_numeric / term_avar(angle, tau), 1.0, kRelative) << "m " << m;
  }
}

TEST(NoiseAnalyticPsd, EveryColouredTermIntegratesToItsAvar) {
  const double tau0 = 0.01;
  struct Case {
    Term term;
    double f_max_hz;  // the PSD's end (flicker), or where its tail is negligible
    std::vector<double> break_points_hz;
  };
  const std::vector<Case> cases = {
      {Term{TermKind::kWhiteRate, 2e-4, 30.0}, 3e6, {}},       // behind a 30 Hz front end
      {Term{TermKind::kBiasInstability, 5e-5, 2.0}, 2.0, {}},  // zero above f0: the integral ends there
      {Term{TermKind::kBiasInstability, 5e-5, 0.05}, 0.05, {}},
      {Term{TermKind::kRandomWalk, 1e-5}, 1e4, {}},
      {Term{TermKind::kMarkov, 3e-4, 0.7}, 3e5, {}},
      {Term{TermKind::kZeroDcFamily, 1e-3, 0.2}, 400.0, {}},
      {Term{TermKind::kZeroDcGaussian, 1e-3, 0.01}, 80.0, {}},  // e^{-beta f^2} = e^{-64} at the end
      {Term{TermKind::kResonance, 2e-3, 20.0, 1.5}, 3e5, {}},
  };
  for (const Case& c : cases) {
    std::vector<double> breaks = c.break_points_hz;
    if (c.term.kind == TermKind::kResonance) {  // resolve the peak: +-40 widths around f_n
      for (int j = -40; j <= 40; ++j) breaks.push_back(c.term.shape + 0.5 * j * c.term.width);
    }
    for (double tau : {0.01, 0.05, 0.3, 2.0, 20.0}) {
      // At most 5e3 kernel periods; beyond f_max a PSD falling as 1 / f^2 leaves
      // 4 (3/8) int S(f) / (pi f tau)^2 df = S(f_max) / (2 pi^2 tau^2 f_max), added.
      const double f_max = std::min(c.f_max_hz, 5e3 / tau);
      const auto psd = [&](double f) { return term_psd(c.term, f, tau0); };
      const double numeric = avar_integral(psd, tau, f_max, breaks) +
                             (f_max < c.f_max_hz ? psd(f_max) / (2.0 * kPi * kPi * tau * tau * f_max) : 0.0);
      EXPECT_NEAR(numeric / term_avar(c.term, tau), 1.0, kRelative)
          << term_kind_name(c.term.kind) << " shape " << c.term.shape << " tau " << tau;
    }
  }
}

// alpha f^2 / (beta^2 + f^2) = alpha - alpha beta^2 / (beta^2 + f^2): white noise of density
// sqrt(alpha) minus a Markov process of the same density at DC and T_c = 1 / (2 pi beta). Both
// sides are closed forms written independently (table 7.3's angle covariance against eqs. 5.2
// and 5.7), so they agree to rounding. (Its flat tail does not suit the integral above.)
TEST(NoiseAnalyticPsd, HighPassWhiteIsWhiteMinusItsLowPassedPart) {
  const double sqrt_alpha = 3e-4, corner_hz = 0.7, time_constant_s = 1.0 / (2.0 * kPi * corner_hz);
  const Term high_pass{TermKind::kHighPassWhite, sqrt_alpha, corner_hz};
  const Term white{TermKind::kWhiteRate, sqrt_alpha};
  const Term low_passed{TermKind::kMarkov, sqrt_alpha, time_constant_s};
  for (double f : {0.01, 0.7, 3.0, 40.0}) {
    EXPECT_NEAR(term_psd(high_pass, f, 0.01) / (term_psd(white, f, 0.01) - term_psd(low_passed, f, 0.01)), 1.0, 1e-12)
        << f;
  }
  for (double tau : {0.01, 0.1, 0.3, 2.0, 20.0}) {
    EXPECT_NEAR(term_avar(high_pass, tau) / (term_avar(white, tau) - term_avar(low_passed, tau)), 1.0, 1e-9) << tau;
  }
}

TEST(NoiseAnalyticPsd, SinusoidLinesAndRampHaveNoDensity) {
  // Two lines of Omega0^2 / 4 at +-f0 in eq. (1): 4 (Omega0^2 / 4) sin^4(pi f0 tau) / (pi f0 tau)^2.
  const Term line = Term{TermKind::kSinusoid, 1e-3, 0.56};
  for (double tau : {0.01, 0.3, 1.0, 7.0}) {
    const double x = kPi * line.shape * tau, s = std::sin(x);
    EXPECT_NEAR(4.0 * noise::sinusoid_line_power(line.amplitude) * s * s * s * s / (x * x) / term_avar(line, tau), 1.0,
                1e-12);
  }
  EXPECT_EQ(term_psd(line, 0.56, 0.01), 0.0);
  EXPECT_EQ(term_psd(Term{TermKind::kRateRamp, 1e-6}, 0.01, 0.01), 0.0);
  EXPECT_EQ(sampled_term_psd(Term{TermKind::kRateRamp, 1e-6}, 0.01, 0.01), 0.0);
}

TEST(NoiseAnalyticPsd, ModelIsTheSumOfItsTermsAndTheOutputQuantization) {
  NoiseModel model;
  model.terms = {Term{TermKind::kWhiteRate, 2e-4, 30.0}, Term{TermKind::kRandomWalk, 1e-5}};
  model.output_quantization_density = 1e-4;
  const double tau0 = 0.01, f = 3.0;
  EXPECT_DOUBLE_EQ(model_psd(model, f, tau0),
                   term_psd(model.terms[0], f, tau0) + term_psd(model.terms[1], f, tau0) + 1e-8);
  EXPECT_DOUBLE_EQ(sampled_model_psd(model, f, tau0),
                   sampled_term_psd(model.terms[0], f, tau0) + sampled_term_psd(model.terms[1], f, tau0) + 1e-8);
}

// Samples every tau0 of a Markov process (q_c, T_c) averaged over their interval, a = tau0 / T_c,
// sigma^2 = q_c^2 T_c / 2: R(0) = 2 sigma^2 (a - 1 + e^-a) / a^2, R(m >= 1) = sigma^2 (1 - e^-a)^2
// e^(-a (m - 1)) / a^2, so S_d(f) = tau0 [R(0) + 2 Re sum_m R(m) e^(i 2 pi f m tau0)], summed in
// closed form. Independent of the alias sum it checks.
double averaged_markov_sequence_psd(double q_c, double t_c, double tau0, double f) {
  const double a = tau0 / t_c, variance = q_c * q_c * t_c / 2.0, decay = std::exp(-a);
  const double r0 = 2.0 * variance * (a - 1.0 + decay) / (a * a);
  const double r1 = variance * (1.0 - decay) * (1.0 - decay) / (a * a);
  const std::complex<double> phase = std::polar(1.0, 2.0 * kPi * f * tau0);
  return tau0 * (r0 + 2.0 * r1 * (phase / (1.0 - decay * phase)).real());
}

TEST(NoiseAnalyticPsd, SampledPsdFoldsTheAveragedAliases) {
  const double tau0 = 0.01;
  for (double t_c : {0.002, 0.0053, 0.05, 1.0}) {  // corners above, near and below Nyquist
    const Term markov = Term{TermKind::kMarkov, 3e-4, t_c};
    for (double f : {0.01, 1.0, 17.0, 31.0, 49.0, 50.0}) {
      const double exact = averaged_markov_sequence_psd(3e-4 / t_c, t_c, tau0, f);
      // The alias sum's tail beyond 256 / tau0 is below 2 S(256 / tau0) / (pi^2 256) ~ 1e-9 relative here.
      EXPECT_NEAR(sampled_term_psd(markov, f, tau0) / exact, 1.0, 1e-7) << "T_c " << t_c << " f " << f;
    }
  }
  // White noise: the sinc^2 aliases sum to 1, so the flat density is its own sampled PSD.
  const double white = noise::interval_averaged_psd([](double) { return 1.0; }, 37.0, tau0, 20000);
  EXPECT_NEAR(white, 1.0, 2.0 / (kPi * kPi * 20000));
  EXPECT_EQ(sampled_term_psd(Term{TermKind::kWhiteRate, 2e-4}, 37.0, tau0), 4e-8);
}

}  // namespace
}  // namespace identify
}  // namespace imu_lab
