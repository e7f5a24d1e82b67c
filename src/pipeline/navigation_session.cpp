#include "imu_lab/pipeline/navigation_session.h"

#include <cmath>
#include <limits>

#include "imu_lab/common/config_error.h"
#include "imu_lab/common/stamps.h"
#include "imu_lab/common/usable_imu_values.h"
#include "imu_lab/emulator/static_motion.h"
#include "imu_lab/nav/alignment_error_budget.h"

namespace imu_lab {
namespace pipeline {
namespace {

// Smoothing of the typical interval: follows a slow rate change, ignores single jitter spikes.
constexpr double kTypicalIntervalSmoothing = 0.01;

// Isotropic per-axis biases (sigma s) enter the first-order alignment error exactly like white
// noise averaged to variance s^2, so one noise covariance with N_eff^2 = s^2 T + N^2 covers both.
Eigen::Vector3d predicted_error_sigma_rad(const NavigationSettings& settings, const nav::EarthModel& earth,
                                          double duration_s) {
  if (!settings.expected_errors) return Eigen::Vector3d::Constant(std::numeric_limits<double>::quiet_NaN());
  const ExpectedSensorErrors& expected = *settings.expected_errors;
  const double gyro_effective =
      std::sqrt(expected.gyro_bias_rad_s * expected.gyro_bias_rad_s * duration_s +
                expected.gyro_noise_density_rad_s_per_sqrt_hz * expected.gyro_noise_density_rad_s_per_sqrt_hz);
  const double accel_effective =
      std::sqrt(expected.accel_bias_m_s2 * expected.accel_bias_m_s2 * duration_s +
                expected.accel_noise_density_m_s2_per_sqrt_hz * expected.accel_noise_density_m_s2_per_sqrt_hz);
  const double gravity = earth.gravity_m_s2(settings.latitude_rad, settings.height_m);
  const double earth_rate = earth.earth_rate_rad_s();
  const Eigen::Matrix3d covariance = nav::alignment_noise_covariance_rad2(
      gyro_effective, accel_effective, duration_s, settings.latitude_rad, gravity, earth_rate > 0.0 ? earth_rate : 1.0);
  Eigen::Vector3d sigma = covariance.diagonal().cwiseSqrt();
  if (settings.alignment.heading_source == nav::HeadingSource::kGiven || !(earth_rate > 0.0)) {
    sigma.z() = std::numeric_limits<double>::quiet_NaN();
  }
  return sigma;
}

AlignmentResult given_attitude(const NavigationSettings& settings) {
  AlignmentResult given;
  given.method = "given_attitude";
  given.q_body_to_enu = settings.initial_attitude_body_to_enu
                            ? *settings.initial_attitude_body_to_enu
                            : emulator::attitude_from_roll_pitch_yaw(
                                  settings.initial_roll_rad, settings.initial_pitch_rad, settings.initial_yaw_rad);
  given.predicted_error_sigma_rad.setConstant(std::numeric_limits<double>::quiet_NaN());
  return given;
}

}  // namespace

bool heading_unobservable(const AlignmentResult& alignment) {
  const double sigma_rad = alignment.predicted_error_sigma_rad.z();
  return std::isfinite(sigma_rad) && sigma_rad > kUnobservableHeadingSigma_rad;
}

bool is_skipped(SampleOutcome outcome) {
  return outcome == SampleOutcome::kSkippedInvalid || outcome == SampleOutcome::kSkippedUnordered ||
         outcome == SampleOutcome::kSkippedGap;
}

NavigationSession::NavigationSession(const NavigationSettings& settings)
    : settings_(settings), aligner_(settings.alignment), navigator_(settings.navigator) {
  validate(settings_, "navigation settings");
}

SampleOutcome NavigationSession::skip(SampleOutcome outcome, std::uint64_t& counter, const std::string& problem) {
  ++counter;
  last_problem_ = problem;
  return outcome;
}

std::optional<SampleOutcome> NavigationSession::begin_sample(std::int64_t stamp_ns,
                                                             std::optional<std::int64_t>& interval_start_ns) {
  last_problem_.clear();
  new_solution_ = false;
  if (divergence_) {
    return skip(SampleOutcome::kHalted, counters_.halted,
                "navigation stopped at " + format_stamp_s(divergence_->stamp_ns) + " s (" + divergence_->problem +
                    "); waiting to be re-initialised");
  }
  if (previous_stamp_ns_ && stamp_ns <= *previous_stamp_ns_) {
    return skip(SampleOutcome::kSkippedUnordered, counters_.unordered,
                "stamp " + format_stamp_s(stamp_ns) + " s is not after the previous one");
  }
  interval_start_ns = previous_stamp_ns_;
  previous_stamp_ns_ = stamp_ns;
  return std::nullopt;
}

void NavigationSession::reinitialise() {
  aligner_.reset();
  navigator_ = nav::Navigator(settings_.navigator);
  alignment_.reset();
  divergence_.reset();
  last_problem_.clear();
  previous_stamp_ns_.reset();
  typical_interval_s_ = 0.0;
  new_solution_ = false;
  body_rate_wrt_enu_rad_s_.setZero();
  ++counters_.reinitialisations;
}

bool NavigationSession::is_gap(double interval_s, double expected_interval_s) const {
  return expected_interval_s > 0.0 && interval_s > settings_.gap_factor * expected_interval_s;
}

SampleOutcome NavigationSession::add_rates(std::int64_t stamp_ns, const Eigen::Vector3d& angular_rate_rad_s,
                                           const Eigen::Vector3d& specific_force_m_s2) {
  std::optional<std::int64_t> start_ns;
  if (const auto early = begin_sample(stamp_ns, start_ns)) return *early;
  if (!is_usable_imu_vector(angular_rate_rad_s) || !is_usable_imu_vector(specific_force_m_s2)) {
    return skip(SampleOutcome::kSkippedInvalid, counters_.invalid,
                "NaN, Inf or a value beyond +-1e100 in the angular rate or specific force");
  }
  // Without alignment the given state is the state at the first usable sample's stamp; with one,
  // the first sample only starts the first interval.
  if (!settings_.align && !navigating()) {
    start_navigation(stamp_ns, given_attitude(settings_));
    return SampleOutcome::kStarted;
  }
  if (!start_ns) {
    last_stamp_ns_ = stamp_ns;
    return SampleOutcome::kStarted;
  }
  const double interval_s = seconds_between(*start_ns, stamp_ns);
  if (is_gap(interval_s, typical_interval_s_)) {
    return skip(
        SampleOutcome::kSkippedGap, counters_.gaps,
        "gap of " + std::to_string(interval_s) + " s (typical interval " + std::to_string(typical_interval_s_) + " s)");
  }
  typical_interval_s_ = typical_interval_s_ > 0.0
                            ? typical_interval_s_ + kTypicalIntervalSmoothing * (interval_s - typical_interval_s_)
                            : interval_s;
  nav::ImuIncrement increment;
  try {
    increment = nav::increment_from_mean_rates(angular_rate_rad_s, specific_force_m_s2, interval_s);
  } catch (const InputError& error) {  // finite rates whose increment overflows
    return skip(SampleOutcome::kSkippedInvalid, counters_.invalid, error.what());
  }
  return integrate(stamp_ns, increment);
}

SampleOutcome NavigationSession::add_increment(std::int64_t stamp_ns, const nav::ImuIncrement& increment) {
  std::optional<std::int64_t> start_ns;
  if (const auto early = begin_sample(stamp_ns, start_ns)) return *early;
  if (!is_usable_imu_vector(increment.delta_angle_rad) || !is_usable_imu_vector(increment.delta_velocity_m_s) ||
      !(increment.dt_s > 0.0) || !std::isfinite(increment.dt_s)) {
    return skip(SampleOutcome::kSkippedInvalid, counters_.invalid,
                "NaN, Inf or a value beyond +-1e100 in the increment, or a non-positive interval_s");
  }
  // Without alignment the given state is the state at the first usable sample's stamp, so the
  // increment ending there is not integrated (as a first rate sample only starts the run). An
  // alignment uses it: it is static data.
  if (!settings_.align && !navigating()) {
    start_navigation(stamp_ns, given_attitude(settings_));
    return SampleOutcome::kStarted;
  }
  if (start_ns && is_gap(seconds_between(*start_ns, stamp_ns), increment.dt_s)) {
    ++counters_.gaps;
    last_problem_ = "gap before this increment; coning/sculling history restarted";
    if (navigating()) navigator_.initialise(navigator_.state());  // forgets the previous increment
  }
  return integrate(stamp_ns, increment);
}

SampleOutcome NavigationSession::integrate(std::int64_t stamp_ns, const nav::ImuIncrement& increment) {
  ++counters_.used;
  if (!navigating()) {
    last_stamp_ns_ = stamp_ns;
    aligner_.add(increment);
    return aligner_.complete() ? finish_alignment(stamp_ns) : SampleOutcome::kAligning;
  }
  try {
    navigator_.update(increment);
  } catch (const nav::UnusableStateError& error) {
    // The solution stays the last usable one, at its own stamp.
    ++counters_.divergences;
    divergence_ = Divergence{stamp_ns, error.what()};
    last_problem_ = error.what();
    return SampleOutcome::kDiverged;
  }
  last_stamp_ns_ = stamp_ns;
  const nav::NavState& state = navigator_.state();
  const Eigen::Vector3d enu_rate =
      navigator_.earth().earth_rate_enu_rad_s(state.latitude_rad) +
      navigator_.earth().transport_rate_enu_rad_s(state.velocity_enu_m_s, state.latitude_rad, state.height_m);
  body_rate_wrt_enu_rad_s_ = increment.delta_angle_rad / increment.dt_s - state.q_body_to_enu.conjugate() * enu_rate;
  new_solution_ = true;
  return SampleOutcome::kNavigated;
}

SampleOutcome NavigationSession::finish_alignment(std::int64_t stamp_ns) {
  Eigen::Quaterniond attitude;
  try {
    attitude = aligner_.attitude();
  } catch (const InputError& error) {
    aligner_.reset();
    return skip(SampleOutcome::kAlignmentFailed, counters_.failed_alignments,
                std::string(error.what()) + "; aligning again");
  }
  AlignmentResult result;
  result.method =
      settings_.alignment.heading_source == nav::HeadingSource::kGyrocompass ? "gyrocompass" : "given_heading";
  result.duration_s = aligner_.accumulated_s();
  result.mean_angular_rate_rad_s = aligner_.mean_angular_rate_rad_s();
  result.mean_specific_force_m_s2 = aligner_.mean_specific_force_m_s2();
  result.predicted_error_sigma_rad = predicted_error_sigma_rad(settings_, navigator_.earth(), result.duration_s);
  result.q_body_to_enu = attitude;
  start_navigation(stamp_ns, result);
  return SampleOutcome::kAligned;
}

void NavigationSession::start_navigation(std::int64_t stamp_ns, AlignmentResult result) {
  result.stamp_ns = stamp_ns;
  result.roll_pitch_yaw_rad = roll_pitch_yaw_from_quaternion(result.q_body_to_enu);
  nav::NavState initial;
  initial.stamp_s = seconds_from_stamp_ns(stamp_ns);
  initial.q_body_to_enu = result.q_body_to_enu;
  initial.velocity_enu_m_s = settings_.initial_velocity_enu_m_s;  // zero with an alignment (validate)
  initial.latitude_rad = settings_.latitude_rad;
  initial.longitude_rad = settings_.longitude_rad;
  initial.height_m = settings_.height_m;
  navigator_.initialise(initial);
  alignment_ = result;
  last_stamp_ns_ = stamp_ns;
  body_rate_wrt_enu_rad_s_.setZero();
  new_solution_ = true;
}

}  // namespace pipeline
}  // namespace imu_lab
