// The sensor front end in the emulator: the output register's LSB (its rounding error as white
// rate noise), the rate-dependent scale-factor errors (nonlinearity, asymmetry, dead zone) on the
// rate table, cross-axis correlation of the white rate noise, white noise behind the anti-alias
// low-pass with a resonance and the LSB against the profile's analytic AVAR at the exact EDF
// (the shipped mems_front_end profile is checked with the others in
// test_emulator_analytic_profile_avar.cpp).
#include <gtest/gtest.h>

#include <yaml-cpp/yaml.h>

#include <cmath>
#include <memory>
#include <utility>
#include <variant>

#include "imu_lab/common/stamps.h"
#include "imu_lab/emulator/analytic_profile_avar.h"
#include "imu_lab/emulator/imu_emulator.h"
#include "imu_lab/emulator/scenario.h"
#include "imu_lab/emulator/sensor_channel.h"
#include "imu_lab/noise/analytic_avar.h"
#include "imu_lab/spectrum/axis_correlation.h"
#include "test_emulator_paths.h"
#include "test_noise_avar_check.h"

namespace imu_lab {
namespace emulator {
namespace {

constexpr double kDeg = 3.14159265358979323846 / 180.0;

SensorProfile ideal_profile() { return load_sensor_profile(test::config_path("sensors/ideal.yaml")); }
ScenarioConfig static_scenario() { return load_scenario(test::config_path("scenarios/static.yaml")); }

// ---- Output LSB ----

// Gyro: white noise through a 40 Hz anti-alias filter at 200 Hz, sample sigma 1.6 LSB.
SensorProfile lsb_profile(double lsb) {
  SensorProfile profile = ideal_profile();
  profile.gyro.bandwidth_hz = 40.0;
  profile.gyro.output_lsb = Eigen::Vector3d::Constant(lsb);
  for (auto& axis : profile.gyro.noise_per_axis) axis = {noise::WhiteRateParameters{1.75e-4}};
  profile.accelerometer.output_lsb = Eigen::Vector3d(0.0327, 0.0327, 0.0327);  // 3.33 mg
  for (auto& axis : profile.accelerometer.noise_per_axis) axis = {noise::WhiteRateParameters{4e-3}};
  return profile;
}

bool whole_steps(double value, double step) {
  const double steps = value / step;
  return std::abs(steps - std::round(steps)) < 1e-9 * std::max(1.0, std::abs(steps));
}

TEST(EmulatorOutputLsb, EverySampleIsAWholeNumberOfSteps) {
  const double lsb = 1e-3, tau0 = 1.0 / 200.0;
  ImuEmulator emulator(lsb_profile(lsb), static_scenario(), {200.0, 0.0, 3});
  for (int k = 0; k < 20000; ++k) {
    const EmulatedSample sample = emulator.next();
    for (int axis = 0; axis < 3; ++axis) {
      ASSERT_TRUE(whole_steps(sample.angular_rate_rad_s[axis], lsb)) << sample.angular_rate_rad_s[axis];
      ASSERT_TRUE(whole_steps(sample.delta_angle_rad[axis], lsb * tau0));
      ASSERT_TRUE(whole_steps(sample.specific_force_m_s2[axis], 0.0327));
      ASSERT_TRUE(whole_steps(sample.delta_velocity_m_s[axis], 0.0327 * tau0));
    }
    // The truth is the kinematics, not rounded.
    ASSERT_FALSE(whole_steps(sample.truth.angular_rate_rad_s.z(), lsb));
  }
}

TEST(EmulatorOutputLsb, AvarIsTheFilteredWhiteNoisePlusTheRoundingNoise) {
  // Per-sample sigma 1.6 LSB: the rounding error is uniform and white (its characteristic
  // function at 2 pi / LSB, e^{-2 pi^2 sigma^2 / LSB^2}, is ~1e-22), variance LSB^2 / 12, 6 % of
  // the AVAR at tau0: resolved at the short taus, so dropping it from the expectation is rejected.
  const double lsb = 1e-3, rate_hz = 200.0, tau0 = 1.0 / rate_hz;
  const SensorProfile profile = lsb_profile(lsb);
  ImuEmulator emulator(profile, static_scenario(), {rate_hz, 0.0, 5});
  const std::size_t count = std::size_t(1) << 20;
  std::vector<double> rates(count), errors(count);
  for (std::size_t k = 0; k < count; ++k) {
    const EmulatedSample sample = emulator.next();
    rates[k] = sample.angular_rate_rad_s.x();
    errors[k] = sample.angular_rate_rad_s.x() - sample.truth.angular_rate_rad_s.x();
  }
  const double sigma = std::sqrt(emulator.gyro_channel().sample_variance(tau0).x() - lsb * lsb / 12.0);
  std::printf("[lsb] sample sigma of the filtered white noise %.2f LSB\n", sigma / lsb);
  const auto expected = [&](double tau) { return analytic_axis_avar(profile.gyro, 0, tau, tau0); };
  const auto check = test::check_avar(rates, tau0, expected, 1, 1 << 14);
  EXPECT_TRUE(check.passed()) << check.table;
  std::printf("[lsb] with LSB^2/12: worst normalised deviation %.2f, rejected %d of %d\n",
              check.worst_normalised_deviation, check.rejected_points, check.point_count);
  SensorProfile without = profile;
  without.gyro.output_lsb.setZero();
  const auto unrounded = test::check_avar(
      rates, tau0, [&](double tau) { return analytic_axis_avar(without.gyro, 0, tau, tau0); }, 1, 1 << 14);
  EXPECT_FALSE(unrounded.passed()) << unrounded.table;
  std::printf("[lsb] without the rounding term: rejected %d of %d (worst ratio %.4f)\n", unrounded.rejected_points,
              unrounded.point_count, unrounded.worst_ratio);
  // One sample's variance includes LSB^2 / 12 (relative standard error of the estimate about
  // sqrt(2 / N) times the ~2 samples the filter correlates; 5 of them allowed).
  double mean = 0.0, square = 0.0;
  for (double e : errors) mean += e / count;
  for (double e : errors) square += (e - mean) * (e - mean) / count;
  EXPECT_NEAR(square / emulator.gyro_channel().sample_variance(tau0).x(), 1.0, 5.0 * std::sqrt(4.0 / count));
}

TEST(EmulatorOutputLsb, RoundingErrorIsWhiteRateNoise) {
  // Monte Carlo of doc/noise_families.md ("Output register LSB"): the same seed with and without
  // the register gives the rounding error e_k itself (rounding draws no deviates). Each sample is
  // rounded on its own, with no carry, so while the noise spans several LSBs e_k is iid uniform,
  // variance L^2 / 12, and the angle error is its running sum: AVAR(m tau0) = (L^2 / 12) / m,
  // white rate noise (output_quantization_avar). A bounded angle error (white angle noise, what
  // pulses with carry give), 3 (L^2 / 12) / m^2, is rejected.
  const double lsb = 1e-3, rate_hz = 200.0, tau0 = 1.0 / rate_hz;
  SensorProfile unrounded = lsb_profile(lsb);
  unrounded.gyro.output_lsb.setZero();
  ImuEmulator with_register(lsb_profile(lsb), static_scenario(), {rate_hz, 0.0, 13});
  ImuEmulator without_register(unrounded, static_scenario(), {rate_hz, 0.0, 13});
  const std::size_t count = std::size_t(1) << 20;
  std::vector<double> errors(count);
  double worst = 0.0;
  for (std::size_t k = 0; k < count; ++k) {
    errors[k] = with_register.next().angular_rate_rad_s.y() - without_register.next().angular_rate_rad_s.y();
    worst = std::max(worst, std::abs(errors[k]));
  }
  EXPECT_LE(worst, 0.5 * lsb * (1.0 + 1e-9));
  const auto white = test::check_avar(
      errors, tau0, [&](double tau) { return noise::output_quantization_avar(lsb, tau, tau0); }, 1, 1 << 14);
  EXPECT_TRUE(white.passed()) << white.table;
  const auto white_angle = test::check_avar(
      errors, tau0, [&](double tau) { return noise::pulse_quantization_avar(lsb * tau0, tau); }, 1, 1 << 14);
  EXPECT_FALSE(white_angle.passed()) << white_angle.table;
  std::printf(
      "[lsb] rounding error: max |e| %.4f LSB; as white rate noise worst normalised deviation "
      "%.2f, rejected %d of %d; as white angle noise rejected %d of %d\n",
      worst / lsb, white.worst_normalised_deviation, white.rejected_points, white.point_count,
      white_angle.rejected_points, white_angle.point_count);
}

// ---- Rate-dependent scale-factor errors on the rate table ----

TEST(EmulatorScaleFactorNonlinearity, RateTablePlateausAgainstHandComputedValues) {
  // Gyro z on the table's Up axis: full scale 300 deg/s, quadratic 500 and cubic -800 ppm of full
  // scale, asymmetry 1000 ppm, dead zone 2 deg/s; everything else ideal. At a plateau of rate w
  // (the table's rate plus the Earth rate's Up component) the output is
  //   w + 1e-6 FS (500 (w/FS)^2 - 800 (w/FS)^3) + 0.5e-3 |w|, or 0 when |that| < 2 deg/s.
  SensorProfile profile = ideal_profile();
  const double full_scale = 300.0 * kDeg;
  profile.gyro.quadratic_nonlinearity_per_unit.z() = 500e-6 / full_scale;
  profile.gyro.cubic_nonlinearity_per_unit2.z() = -800e-6 / (full_scale * full_scale);
  profile.gyro.scale_factor_asymmetry_ppm.z() = 1000.0;
  profile.gyro.dead_zone.z() = 2.0 * kDeg;
  const ScenarioConfig table = load_scenario(test::config_path("scenarios/rate_table.yaml"));
  const double rate_hz = 100.0;
  ImuEmulator emulator(profile, table, {rate_hz, 0.0, 1});
  ImuEmulator ideal(ideal_profile(), table, {rate_hz, 0.0, 1});
  // Plateau middles: 2 s of acceleration to 1 deg/s ... (20 deg/s^2), then 60 s holds.
  struct Plateau {
    double table_rate_deg_s;
    double hand_error_rad_s;  // output - truth, computed by hand for the table's rate alone
  };
  // +-100 deg/s (w/FS = 1/3): quadratic 1e-6 * 5.235988 * 500 / 9 = 2.908882e-4, cubic
  // -/+ 1e-6 * 5.235988 * 800 / 27 = 1.551404e-4, asymmetry 0.5e-3 * 1.745329 = 8.726646e-4.
  // +-10 deg/s: 2.908882e-6, -/+1.551404e-7, 8.726646e-5. +-1 deg/s: inside the dead zone, the
  // output is 0, the error -w with w = +-0.01745329 + 5.62427e-5 (Earth rate 7.292115e-5 rad/s
  // times sin(50.45 deg)).
  const Plateau plateaus[] = {{1.0, -(0.01745329 + 5.62427e-5)},
                              {-1.0, 0.01745329 - 5.62427e-5},
                              {10.0, 2.908882e-6 - 1.551404e-7 + 8.726646e-5},
                              {-10.0, 2.908882e-6 + 1.551404e-7 + 8.726646e-5},
                              {100.0, 2.908882e-4 - 1.551404e-4 + 8.726646e-4},
                              {-100.0, 2.908882e-4 + 1.551404e-4 + 8.726646e-4}};
  double start_s = 0.0, previous_rate = 0.0;
  int checked = 0;
  for (const Plateau& plateau : plateaus) {
    start_s += std::abs(plateau.table_rate_deg_s - previous_rate) / 20.0;  // the rate change
    const double middle_s = start_s + 30.0;
    start_s += 60.0;
    previous_rate = plateau.table_rate_deg_s;
    EmulatedSample sample, reference;
    while (seconds_from_stamp_ns(sample.stamp_ns) < middle_s) {
      sample = emulator.next();
      reference = ideal.next();
      // Exact truth: the same kinematics as the error-free IMU's, bit for bit.
      ASSERT_EQ(sample.truth.angular_rate_rad_s, reference.truth.angular_rate_rad_s);
      ASSERT_EQ(sample.truth.q_body_to_enu.coeffs(), reference.truth.q_body_to_enu.coeffs());
    }
    const double w = sample.truth.angular_rate_rad_s.z();
    EXPECT_NEAR(w, plateau.table_rate_deg_s * kDeg, 6e-5);  // the Earth rate's Up component
    const double u = w / full_scale;
    double expected = w + 1e-6 * full_scale * (500.0 * u * u - 800.0 * u * u * u) + 0.5e-3 * std::abs(w);
    if (std::abs(expected) < 2.0 * kDeg) expected = 0.0;
    EXPECT_NEAR(sample.angular_rate_rad_s.z(), expected, 1e-15 * std::abs(w) + 1e-18) << plateau.table_rate_deg_s;
    // The hand-computed figure ignores the Earth rate (5.6e-5 rad/s): good to ~1e-7 rad/s.
    EXPECT_NEAR(sample.angular_rate_rad_s.z() - w, plateau.hand_error_rad_s, 2e-7) << plateau.table_rate_deg_s;
    // The other axes see only the Earth rate, unchanged.
    EXPECT_EQ(sample.angular_rate_rad_s.x(), sample.truth.angular_rate_rad_s.x());
    ++checked;
  }
  EXPECT_EQ(checked, 6);
}

TEST(EmulatorScaleFactorNonlinearity, ProfileKeysInPpmOfFullScale) {
  YAML::Node root = YAML::LoadFile(test::config_path("sensors/ideal.yaml"));
  root["gyro"].remove("quadratic_nonlinearity_per_rad_s");
  root["gyro"]["scale_factor_nonlinearity"] =
      YAML::Load("{full_scale_rad_s: 5.2359877559829887, quadratic_ppm_fs: 500, cubic_ppm_fs: [0, 0, -800]}");
  root["gyro"]["scale_factor_asymmetry_ppm"] = 1000.0;
  root["gyro"]["dead_zone_rad_s"] = YAML::Load("[0, 0, 0.0349]");
  const SensorProfile profile = sensor_profile_from_yaml(root, "test.yaml");
  EXPECT_NEAR(profile.gyro.quadratic_nonlinearity_per_unit.z(), 500e-6 / 5.2359877559829887, 1e-18);
  EXPECT_NEAR(profile.gyro.cubic_nonlinearity_per_unit2.z(), -800e-6 / std::pow(5.2359877559829887, 2), 1e-18);
  EXPECT_EQ(profile.gyro.cubic_nonlinearity_per_unit2.x(), 0.0);
  EXPECT_EQ(profile.gyro.scale_factor_asymmetry_ppm.y(), 1000.0);
  EXPECT_EQ(profile.gyro.dead_zone.z(), 0.0349);
}

// ---- Cross-axis correlation of the white rate noise ----

// The axes' correlation as the spectrum tool estimates it (spectrum/axis_correlation.h) against
// the profile's matrix: the truth inside each pair's Fisher interval at 99.9 % (a false failure
// one run in 1000 per pair), and the samples independent in time as that interval assumes.
void expect_correlation(const std::vector<Eigen::Vector3d>& noise, const Eigen::Matrix3d& truth, const char* what) {
  const spectrum::AxisCorrelation estimate = spectrum::axis_correlation(noise, 0.005, 1, 0.999);
  for (int a = 0; a < 3; ++a) {
    for (int b = a + 1; b < 3; ++b) {
      EXPECT_LE(estimate.lower(a, b), truth(a, b)) << what << " pair " << a << b;
      EXPECT_GE(estimate.upper(a, b), truth(a, b)) << what << " pair " << a << b;
      std::printf("[correlation] %s %d%d: r %.4f in [%.4f, %.4f], rho %.4f\n", what, a, b, estimate.correlation(a, b),
                  estimate.lower(a, b), estimate.upper(a, b), truth(a, b));
    }
  }
  EXPECT_TRUE(estimate.blocks_look_independent()) << what << ": " << estimate.block_lag1_autocorrelation.transpose();
}

TEST(EmulatorCrossAxisCorrelation, WhiteRateNoiseCarriesTheProfileMatrix) {
  Eigen::Matrix3d correlation;
  correlation << 1.0, 0.6, -0.3, 0.6, 1.0, 0.2, -0.3, 0.2, 1.0;
  for (double bandwidth_hz : {0.0, 40.0}) {
    SensorProfile profile = ideal_profile();
    profile.gyro.bandwidth_hz = bandwidth_hz;
    profile.gyro.noise_per_axis = {
        {{noise::WhiteRateParameters{1e-4}}, {noise::WhiteRateParameters{3e-4}}, {noise::WhiteRateParameters{2e-4}}}};
    profile.gyro.white_rate_correlation = correlation;
    ImuEmulator emulator(profile, static_scenario(), {200.0, 0.0, 9});
    // Filtered samples are correlated in time (T_c = 4 ms at 5 ms spacing); every 10th is
    // independent to 1e-5, so Fisher's standard error holds.
    const int stride = bandwidth_hz > 0.0 ? 10 : 1;
    std::vector<Eigen::Vector3d> noise;
    for (int k = 0; k < (1 << 17) * stride; ++k) {
      const EmulatedSample sample = emulator.next();
      if (k % stride == 0) noise.push_back(sample.angular_rate_rad_s - sample.truth.angular_rate_rad_s);
    }
    expect_correlation(noise, correlation, bandwidth_hz > 0.0 ? "40 Hz filtered" : "white");
    // The per-axis variance is unchanged (unit diagonal).
    EXPECT_NEAR(emulator.gyro_channel().sample_variance(0.005).y(),
                bandwidth_hz > 0.0 ? emulator.gyro_channel().processes(1)[0]->sample_variance(0.005) : 9e-8 / 0.005,
                1e-20);
  }
}

TEST(EmulatorCrossAxisCorrelation, IdentityLeavesTheStreamsAsBefore) {
  // Without a matrix the axes are independent and the output bit-identical to the default.
  SensorProfile profile = ideal_profile();
  for (auto& axis : profile.gyro.noise_per_axis) axis = {noise::WhiteRateParameters{1e-4}};
  SensorProfile explicit_identity = profile;
  explicit_identity.gyro.white_rate_correlation = Eigen::Matrix3d::Identity();
  ImuEmulator a(profile, static_scenario(), {200.0, 0.0, 9}), b(explicit_identity, static_scenario(), {200.0, 0.0, 9});
  std::vector<Eigen::Vector3d> noise;
  for (int k = 0; k < (1 << 17); ++k) {
    const EmulatedSample sa = a.next(), sb = b.next();
    ASSERT_EQ(sa.angular_rate_rad_s, sb.angular_rate_rad_s);
    noise.push_back(sa.angular_rate_rad_s - sa.truth.angular_rate_rad_s);
  }
  expect_correlation(noise, Eigen::Matrix3d::Identity(), "independent");
}

// ---- White noise through the anti-alias low-pass, a resonance and the LSB together ----

// Gyro z at 100 Hz: white 7.27e-4 rad/s/sqrt(Hz) behind a 50 Hz first-order low-pass, a 20 Hz mode
// 1.5 Hz wide of RMS 4.5e-3 rad/s, and a 4e-3 rad/s LSB (per-sample sigma ~1.6 LSB, so the rounding
// is ~4 % of the AVAR at tau0 and resolved).
struct FrontEnd {
  double density = 7.27e-4, bandwidth_hz = 50.0, lsb = 4e-3;
  noise::ResonanceParameters mode{4.5e-3, 20.0, 1.5};
};

SensorProfile front_end_profile(const FrontEnd& f) {
  SensorProfile profile = ideal_profile();
  profile.gyro.bandwidth_hz = f.bandwidth_hz;
  profile.gyro.output_lsb.z() = f.lsb;
  profile.gyro.noise_per_axis[2] = {noise::WhiteRateParameters{f.density}, f.mode};
  return profile;
}

// Exact EDF of each point (test::exact_overlapping_edf) from the angle's structure function
// V(u) = E[(angle(t + u) - angle(t))^2], the sum of the three independent parts:
//   low-passed white (a Markov rate of time constant T = 1 / (2 pi f_c), white density N):
//     N^2 (u - T (1 - e^{-u/T}));
//   the mode (a stationary angle of variance (rms / w_n)^2): 2 (rms / w_n)^2 (1 - rho(u));
//   the rounding (white rate of variance L^2 / 12 per sample): (L^2 / 12) tau0 u.
// The rounding error is uniform, not Gaussian; its smaller fourth moment only narrows the true
// spread, so the Gaussian EDF is conservative.
test::EdfOfFactor front_end_edf(const FrontEnd& f, double tau0, int max_factor) {
  constexpr double kTwoPi = 6.28318530717958647692;
  const long correlation_samples = static_cast<long>(std::ceil(8.0 / tau0));  // e^{-pi 1.5 u}: 4e-17 at 8 s
  const double time_constant = 1.0 / (kTwoPi * f.bandwidth_hz);
  const double angle_variance = std::pow(f.mode.rms / (kTwoPi * f.mode.natural_frequency_hz), 2);
  auto structure =
      std::make_shared<std::vector<double>>(4 * static_cast<std::size_t>(max_factor) + correlation_samples + 1);
  for (std::size_t j = 0; j < structure->size(); ++j) {
    const double u = j * tau0;
    (*structure)[j] = f.density * f.density * (u + time_constant * std::expm1(-u / time_constant)) +
                      2.0 * angle_variance *
                          (1.0 - noise::resonance_angle_correlation(f.mode.natural_frequency_hz, f.mode.width_hz, u)) +
                      f.lsb * f.lsb / 12.0 * tau0 * u;
  }
  return [structure, correlation_samples](int m, std::size_t count) {
    return test::exact_overlapping_edf([&](long j) { return (*structure)[j]; }, m, count, correlation_samples);
  };
}

TEST(EmulatorFrontEnd, LowPassedWhiteResonanceAndLsbMatchTheProfilesAnalyticAvar) {
  // The emulated overlapping AVAR against analytic_axis_avar at every octave from tau0 to 164 s,
  // each point in its chi-squared band at the exact EDF (Bonferroni, 99.7 % family-wise). The
  // same record is rejected against the profile without the LSB, without the low-pass and
  // without the mode: each term is resolved.
  const FrontEnd f;
  const double rate_hz = 100.0, tau0 = 1.0 / rate_hz;
  constexpr int kMaxFactor = 1 << 14;
  const SensorProfile profile = front_end_profile(f);
  ImuEmulator emulator(profile, static_scenario(), {rate_hz, 0.0, 31});
  const std::size_t count = std::size_t(1) << 20;  // 2.9 h
  std::vector<double> rates(count);
  for (auto& rate : rates) rate = emulator.next().angular_rate_rad_s.z();
  const double sigma = std::sqrt(emulator.gyro_channel().sample_variance(tau0).z());
  std::printf(
      "[front end] per-sample sigma %.2f LSB; the rounding is %.1f %% of the AVAR at tau0\n", sigma / f.lsb,
      100.0 * noise::output_quantization_avar(f.lsb, tau0, tau0) / analytic_axis_avar(profile.gyro, 2, tau0, tau0));
  const test::EdfOfFactor edf = front_end_edf(f, tau0, kMaxFactor);
  auto judge = [&](const TriadErrorModel& model) {
    return test::check_avar(
        rates, tau0, [&](double tau) { return analytic_axis_avar(model, 2, tau, tau0); }, 1, kMaxFactor, 0.997, edf);
  };
  const auto check = judge(profile.gyro);
  EXPECT_TRUE(check.passed()) << check.table;
  std::printf(
      "[front end] against the profile's analytic AVAR: worst normalised deviation %.2f "
      "(ratio %.4f), rejected %d of %d\n",
      check.worst_normalised_deviation, check.worst_ratio, check.rejected_points, check.point_count);
  TriadErrorModel without_lsb = profile.gyro, without_low_pass = profile.gyro, without_mode = profile.gyro;
  without_lsb.output_lsb.setZero();
  without_low_pass.bandwidth_hz = 0.0;
  without_mode.noise_per_axis[2].pop_back();
  for (const auto& [model, what] : {std::pair<const TriadErrorModel*, const char*>{&without_lsb, "the LSB"},
                                    {&without_low_pass, "the low-pass"},
                                    {&without_mode, "the mode"}}) {
    const auto wrong = judge(*model);
    EXPECT_FALSE(wrong.passed()) << "without " << what << "\n" << wrong.table;
    std::printf("[front end] without %-12s rejected %2d of %d (worst ratio %.4f)\n", what, wrong.rejected_points,
                wrong.point_count, wrong.worst_ratio);
  }
}

}  // namespace
}  // namespace emulator
}  // namespace imu_lab
