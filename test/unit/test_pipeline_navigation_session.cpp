// NavigationSession, the core of both the strapdown_navigator node and the navigate tool: rate
// samples become exactly the increments an ImuIncrement stream would carry, and bad samples are
// skipped and counted without stopping the run.
#include "imu_lab/pipeline/navigation_session.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "imu_lab/common/config_error.h"

namespace {

using imu_lab::pipeline::NavigationSession;
using imu_lab::pipeline::NavigationSettings;
using imu_lab::pipeline::SampleOutcome;

constexpr std::int64_t kStart_ns = 1000000000LL * 1000000000LL;  // 1e9 s in nanoseconds
constexpr std::int64_t kInterval_ns = 5000000;                   // 200 Hz
constexpr double kInterval_s = 0.005;

struct Sample {
  std::int64_t stamp_ns;
  Eigen::Vector3d rate_rad_s;
  Eigen::Vector3d force_m_s2;
};

// A level IMU at rest at 45 deg with a little deterministic "noise" so the paths are not trivial.
std::vector<Sample> static_samples(int count) {
  std::vector<Sample> samples;
  for (int k = 0; k <= count; ++k) {
    const double wobble = std::sin(0.37 * k);
    samples.push_back({kStart_ns + k * kInterval_ns, Eigen::Vector3d(1e-6 * wobble, 5.16e-5, 5.16e-5 + 1e-6 * wobble),
                       Eigen::Vector3d(1e-3 * wobble, -2e-3 * wobble, 9.806)});
  }
  return samples;
}

NavigationSettings settings() {
  NavigationSettings s;
  s.alignment.duration_s = 1.0;
  s.latitude_rad = 45.0 * M_PI / 180.0;
  return s;
}

TEST(NavigateSession, RateSamplesGiveTheSameSolutionAsTheEquivalentIncrements) {
  const auto samples = static_samples(2000);
  NavigationSession rates(settings());
  NavigationSession increments(settings());
  EXPECT_EQ(rates.add_rates(samples[0].stamp_ns, samples[0].rate_rad_s, samples[0].force_m_s2),
            SampleOutcome::kStarted);
  for (std::size_t k = 1; k < samples.size(); ++k) {
    rates.add_rates(samples[k].stamp_ns, samples[k].rate_rad_s, samples[k].force_m_s2);
    imu_lab::nav::ImuIncrement increment;
    increment.delta_angle_rad = samples[k].rate_rad_s * kInterval_s;
    increment.delta_velocity_m_s = samples[k].force_m_s2 * kInterval_s;
    increment.dt_s = kInterval_s;
    increments.add_increment(samples[k].stamp_ns, increment);
    ASSERT_EQ(rates.navigating(), increments.navigating()) << "sample " << k;
    if (!rates.navigating()) continue;
    ASSERT_EQ(rates.stamp_ns(), increments.stamp_ns());
    EXPECT_EQ(rates.state().velocity_enu_m_s, increments.state().velocity_enu_m_s) << "sample " << k;
    EXPECT_EQ(rates.state().q_body_to_enu.coeffs(), increments.state().q_body_to_enu.coeffs()) << "sample " << k;
  }
  ASSERT_TRUE(rates.navigating());
  // One second of intervals after the first stamp (the sum of 0.005 s steps may need one more).
  EXPECT_NEAR(static_cast<double>(rates.alignment()->stamp_ns), static_cast<double>(kStart_ns + 200 * kInterval_ns),
              static_cast<double>(kInterval_ns));
  EXPECT_EQ(rates.counters().used, 2000u);
}

TEST(NavigateSession, SkipsAndCountsNaNUnorderedAndGapSamplesAndKeepsNavigating) {
  const auto samples = static_samples(600);
  NavigationSession session(settings());
  std::vector<SampleOutcome> outcomes;
  for (std::size_t k = 0; k < samples.size(); ++k) {
    Sample s = samples[k];
    if (k == 300) s.rate_rad_s.x() = std::nan("");
    if (k == 350) s.force_m_s2.z() = 1e308;         // finite, but it would overflow the velocity: as unusable as NaN
    if (k >= 400) s.stamp_ns += 10 * kInterval_ns;  // a gap of ten intervals before sample 400
    outcomes.push_back(session.add_rates(s.stamp_ns, s.rate_rad_s, s.force_m_s2));
    if (k == 500) outcomes.push_back(session.add_rates(s.stamp_ns, s.rate_rad_s, s.force_m_s2));  // duplicate
    if (k == 501) outcomes.push_back(session.add_rates(s.stamp_ns - 3 * kInterval_ns, s.rate_rad_s, s.force_m_s2));
  }
  EXPECT_EQ(outcomes[300], SampleOutcome::kSkippedInvalid);
  EXPECT_EQ(outcomes[301], SampleOutcome::kNavigated);  // its own interval only: the NaN's stamp ended the last
  EXPECT_EQ(outcomes[350], SampleOutcome::kSkippedInvalid);
  EXPECT_EQ(outcomes[400], SampleOutcome::kSkippedGap);
  EXPECT_EQ(outcomes[401], SampleOutcome::kNavigated);
  EXPECT_EQ(outcomes[501], SampleOutcome::kSkippedUnordered);
  EXPECT_EQ(outcomes[503], SampleOutcome::kSkippedUnordered);
  EXPECT_EQ(session.counters().invalid, 2u);
  EXPECT_EQ(session.counters().gaps, 1u);
  EXPECT_EQ(session.counters().unordered, 2u);
  EXPECT_EQ(session.counters().used, 600u - 3u);
  EXPECT_TRUE(session.navigating());
  EXPECT_TRUE(session.state().velocity_enu_m_s.allFinite());
  EXPECT_EQ(session.stamp_ns(), samples.back().stamp_ns + 10 * kInterval_ns);
}

TEST(NavigateSession, GivenAttitudeStartsAtTheFirstSample) {
  NavigationSettings s = settings();
  s.align = false;
  s.initial_roll_rad = 0.1;
  s.initial_pitch_rad = -0.2;
  s.initial_yaw_rad = 1.0;
  NavigationSession session(s);
  const auto samples = static_samples(1);
  EXPECT_EQ(session.add_rates(samples[0].stamp_ns, samples[0].rate_rad_s, samples[0].force_m_s2),
            SampleOutcome::kStarted);
  ASSERT_TRUE(session.navigating());
  EXPECT_TRUE(session.new_solution());
  EXPECT_EQ(session.alignment()->method, "given_attitude");
  EXPECT_NEAR(session.alignment()->roll_pitch_yaw_rad.x(), 0.1, 1e-12);
  EXPECT_NEAR(session.alignment()->roll_pitch_yaw_rad.y(), -0.2, 1e-12);
  EXPECT_NEAR(session.alignment()->roll_pitch_yaw_rad.z(), 1.0, 1e-12);
}

// The node's parameters and the tool's options meet this one check. A height of 1e12 m, a
// longitude of 1e6 deg or a yaw of 1e300 deg used to be navigated with exit 0.
TEST(NavigationSettingsCheck, ASiteOrAnAttitudeNoSensorCanHaveIsRefusedByKey) {
  const auto refusal = [](const std::function<void(NavigationSettings&)>& change) -> std::string {
    NavigationSettings s = settings();
    change(s);
    try {
      imu_lab::pipeline::validate(s, "test");
    } catch (const imu_lab::ConfigError& error) {
      return error.what();
    }
    return "";
  };
  constexpr double kDeg = M_PI / 180.0;
  EXPECT_EQ(refusal([](NavigationSettings&) {}), "");
  EXPECT_EQ(refusal([&](NavigationSettings& s) {
              s.longitude_rad = 359.0 * kDeg;
              s.height_m = -400.0;
              s.initial_roll_rad = -180.0 * kDeg;
              s.initial_pitch_rad = 90.0 * kDeg;
              s.initial_yaw_rad = s.alignment.given_yaw_rad = 350.0 * kDeg;
              s.navigator.vertical.fixed_reference_height_m = 8848.0;
            }),
            "")
      << "every way of writing a real site and attitude passes";
  const auto refused = [&](const std::function<void(NavigationSettings&)>& change, const std::string& words) {
    const std::string message = refusal(change);
    EXPECT_NE(message.find(words), std::string::npos) << "'" << words << "' not in '" << message << "'";
  };
  refused([&](NavigationSettings& s) { s.longitude_rad = 1e6 * kDeg; },
          "longitude_deg: must be in [-180, 360] degrees, got 1e+06");
  refused([&](NavigationSettings& s) { s.longitude_rad = NAN; }, "longitude_deg");
  refused([](NavigationSettings& s) { s.height_m = 1e12; }, "height_m: must be in [-11000, 100000] m");
  refused([](NavigationSettings& s) { s.height_m = -1e8; }, "height_m");
  refused([](NavigationSettings& s) { s.height_m = NAN; }, "height_m");
  refused([](NavigationSettings& s) { s.navigator.vertical.fixed_reference_height_m = 1e30; }, "reference_height_m");
  refused([&](NavigationSettings& s) { s.initial_pitch_rad = 100.0 * kDeg; },
          "initial_pitch_deg: must be in [-90, 90]");
  refused([&](NavigationSettings& s) { s.initial_roll_rad = 1e5 * kDeg; }, "initial_roll_deg");
  refused([&](NavigationSettings& s) { s.initial_yaw_rad = 1e300 * kDeg; }, "initial_yaw_deg");
  refused([&](NavigationSettings& s) { s.alignment.given_yaw_rad = -400.0 * kDeg; }, "initial_yaw_deg");
}

TEST(NavigateSession, GivenStateIsTheStateAtTheFirstStampWithEitherInput) {
  NavigationSettings s = settings();
  s.align = false;
  s.initial_velocity_enu_m_s = Eigen::Vector3d(3.0, -1.0, 0.5);
  NavigationSession rates(s), increments(s);
  const auto samples = static_samples(400);
  const auto increment_of = [](const Sample& sample) {
    imu_lab::nav::ImuIncrement increment;
    increment.delta_angle_rad = sample.rate_rad_s * kInterval_s;
    increment.delta_velocity_m_s = sample.force_m_s2 * kInterval_s;
    increment.dt_s = kInterval_s;
    return increment;
  };
  EXPECT_EQ(rates.add_rates(samples[0].stamp_ns, samples[0].rate_rad_s, samples[0].force_m_s2),
            SampleOutcome::kStarted);
  // The first increment ends where the given state holds: it is not integrated.
  EXPECT_EQ(increments.add_increment(samples[0].stamp_ns, increment_of(samples[0])), SampleOutcome::kStarted);
  for (const NavigationSession* session : {&rates, &increments}) {
    ASSERT_TRUE(session->navigating());
    EXPECT_EQ(session->stamp_ns(), samples[0].stamp_ns);
    EXPECT_EQ(session->alignment()->stamp_ns, samples[0].stamp_ns);
    EXPECT_EQ(session->state().velocity_enu_m_s, s.initial_velocity_enu_m_s);
    EXPECT_EQ(session->counters().used, 0u);
  }
  for (std::size_t k = 1; k < samples.size(); ++k) {
    rates.add_rates(samples[k].stamp_ns, samples[k].rate_rad_s, samples[k].force_m_s2);
    increments.add_increment(samples[k].stamp_ns, increment_of(samples[k]));
    ASSERT_EQ(rates.stamp_ns(), increments.stamp_ns());
    EXPECT_EQ(rates.state().velocity_enu_m_s, increments.state().velocity_enu_m_s) << "sample " << k;
    EXPECT_EQ(rates.state().q_body_to_enu.coeffs(), increments.state().q_body_to_enu.coeffs()) << "sample " << k;
  }
  EXPECT_EQ(increments.counters().used, 400u);
}

TEST(NavigateSession, GivenAttitudeQuaternionOverridesTheAngles) {
  NavigationSettings s = settings();
  s.align = false;
  s.initial_yaw_rad = 1.0;
  // Pitch exactly 90 deg: roll and yaw are not separable, the quaternion keeps the attitude.
  const Eigen::Quaterniond nose_up(Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitZ()) *
                                   Eigen::AngleAxisd(-0.5 * M_PI, Eigen::Vector3d::UnitY()));
  s.initial_attitude_body_to_enu = nose_up;
  NavigationSession session(s);
  const auto samples = static_samples(1);
  session.add_rates(samples[0].stamp_ns, samples[0].rate_rad_s, samples[0].force_m_s2);
  EXPECT_LT(session.state().q_body_to_enu.angularDistance(nose_up), 1e-15);
}

TEST(NavigateSession, RefusesAnInitialVelocityWithAnAlignment) {
  NavigationSettings s = settings();
  s.initial_velocity_enu_m_s = Eigen::Vector3d(1.0, 0.0, 0.0);
  EXPECT_THROW(NavigationSession{s}, imu_lab::ConfigError);
  s.align = false;
  s.initial_velocity_enu_m_s.x() = std::numeric_limits<double>::infinity();
  EXPECT_THROW(NavigationSession{s}, imu_lab::ConfigError);
}

TEST(NavigateSession, PredictsTheAlignmentErrorOnlyFromGivenExpectedErrors) {
  const auto samples = static_samples(300);
  const auto aligned = [&](const NavigationSettings& s) {
    NavigationSession session(s);
    for (const Sample& sample : samples) session.add_rates(sample.stamp_ns, sample.rate_rad_s, sample.force_m_s2);
    EXPECT_TRUE(session.alignment().has_value());
    return session.alignment()->predicted_error_sigma_rad;
  };
  EXPECT_TRUE(aligned(settings()).array().isNaN().all());
  NavigationSettings s = settings();
  s.expected_errors = imu_lab::pipeline::ExpectedSensorErrors{};
  s.expected_errors->accel_bias_m_s2 = 1e-3;  // sigma_E = sigma_N = b / g (alignment_error_budget.h)
  const Eigen::Vector3d sigma = aligned(s);
  EXPECT_NEAR(sigma.x(), 1e-3 / 9.806, 1e-3 / 9.806 * 0.01);
  EXPECT_NEAR(sigma.y(), sigma.x(), 1e-15);
  EXPECT_TRUE(std::isfinite(sigma.z()));
}

// Finite but absurd input (1e50 rad/s and m/s^2, e.g. a unit or parsing error upstream; beyond
// +-1e100 a sample is skipped as invalid instead) makes the
// state unusable; the session stops there, keeps the last usable solution, ignores what follows
// and starts over only when told to.
TEST(NavigateSession, StopsAtAnUnusableStateAndStartsAgainOnlyWhenTold) {
  NavigationSettings s = settings();
  s.align = false;
  NavigationSession session(s);
  const auto samples = static_samples(40);
  for (int k = 0; k < 10; ++k) session.add_rates(samples[k].stamp_ns, samples[k].rate_rad_s, samples[k].force_m_s2);
  const imu_lab::nav::NavState last_usable = session.state();
  EXPECT_EQ(session.add_rates(samples[10].stamp_ns, Eigen::Vector3d::Constant(1e50), Eigen::Vector3d::Constant(1e50)),
            SampleOutcome::kDiverged);
  EXPECT_FALSE(session.new_solution());
  ASSERT_TRUE(session.halted());
  EXPECT_EQ(session.divergence()->stamp_ns, samples[10].stamp_ns);
  EXPECT_FALSE(session.divergence()->problem.empty());
  EXPECT_EQ(session.stamp_ns(), samples[9].stamp_ns);
  EXPECT_EQ(session.state().velocity_enu_m_s, last_usable.velocity_enu_m_s);
  for (int k = 11; k < 20; ++k) {
    EXPECT_EQ(session.add_rates(samples[k].stamp_ns, samples[k].rate_rad_s, samples[k].force_m_s2),
              SampleOutcome::kHalted);
  }
  EXPECT_EQ(session.counters().halted, 9u);
  EXPECT_EQ(session.counters().divergences, 1u);
  session.reinitialise();
  EXPECT_FALSE(session.halted());
  EXPECT_EQ(session.add_rates(samples[20].stamp_ns, samples[20].rate_rad_s, samples[20].force_m_s2),
            SampleOutcome::kStarted);
  EXPECT_EQ(session.add_rates(samples[21].stamp_ns, samples[21].rate_rad_s, samples[21].force_m_s2),
            SampleOutcome::kNavigated);
  EXPECT_EQ(session.alignment()->stamp_ns, samples[20].stamp_ns);
  EXPECT_EQ(session.counters().reinitialisations, 1u);
}

// A height beyond +-1000 km is unusable too: 1e6 m/s^2 up for one 5 ms interval climbs ~12 m, a
// 1e12 m/s^2 one past 1000 km while the latitude stays put.
TEST(NavigateSession, StopsWhenTheHeightLeavesPlusMinus1000Km) {
  NavigationSettings s = settings();
  s.align = false;
  NavigationSession session(s);
  const auto samples = static_samples(3);
  session.add_rates(samples[0].stamp_ns, samples[0].rate_rad_s, samples[0].force_m_s2);
  EXPECT_EQ(session.add_rates(samples[1].stamp_ns, samples[1].rate_rad_s, Eigen::Vector3d(0.0, 0.0, 1e12)),
            SampleOutcome::kDiverged);
  ASSERT_TRUE(session.halted());
  EXPECT_NE(session.divergence()->problem.find("beyond +-1000 km"), std::string::npos) << session.divergence()->problem;
}

}  // namespace
