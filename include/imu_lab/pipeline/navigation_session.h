// One strapdown run over a stream of IMU samples: static alignment (or a given state), then
// navigation, with the input checks a live node needs. The strapdown_navigator node and the
// navigate tool both feed it, so they give the same solution on the same data.
//
// Input: either interval-average rates (sensor_msgs/Imu, turned into increments with the interval
// between consecutive header stamps) or the sensor's own increments (imu_lab/ImuIncrement).
// Stamps are header stamps in integer nanoseconds (a double near 1e9 s would put ~0.1 us of false
// jitter into every interval, i.e. ~20 ppm of scale-factor noise at 200 Hz).
//
// Without alignment the given state (settings: attitude, velocity, position) is the state at the
// first sample's stamp, with either input: a rate sample only starts the first interval, and the
// first increment, which covers the interval ending there, is not integrated either.
//
// The navigator checks its state after every step (nav::state_problem): when it becomes unusable
// (NaN/Inf, |height| > 1000 km, ...) the session stops (kDiverged, then kHalted for every sample),
// keeps the last usable solution and the stamp and reason (divergence()), and starts again from
// scratch only when reinitialise() is called.
//
// Bad samples never stop the run; they are skipped and counted:
//  - NaN/Inf values or a non-positive interval_s: skipped; its stamp still ends the interval,
//    so the next sample integrates only its own interval;
//  - a stamp not after the previous one (duplicate or out of order): ignored altogether;
//  - a stamp interval over gap_factor times the typical one (a gap): a rate sample after it is
//    skipped (its average says nothing about the missing time); an increment, which covers only
//    its own interval, is integrated, and the coning/sculling history is restarted.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cstdint>
#include <optional>
#include <string>

#include "imu_lab/nav/navigator.h"
#include "imu_lab/nav/static_alignment.h"
#include "imu_lab/pipeline/navigation_settings.h"

namespace imu_lab {
namespace pipeline {

enum class SampleOutcome {
  kStarted,           // first sample: only starts the first interval
  kAligning,          // added to the static alignment
  kAligned,           // completed the alignment; navigation starts at this stamp
  kNavigated,         // a new solution
  kSkippedInvalid,    // NaN/Inf or bad interval
  kSkippedUnordered,  // stamp not after the previous one
  kSkippedGap,        // rate sample after a gap
  kAlignmentFailed,   // alignment could not resolve an attitude; it starts again
  kDiverged,          // this sample made the navigation state unusable: navigation stopped
  kHalted,            // ignored: navigation stopped at a divergence, waiting for reinitialise()
};

// True for the outcomes that skip the sample (for logging and diagnostics).
bool is_skipped(SampleOutcome outcome);

struct InputCounters {
  std::uint64_t used = 0;       // samples integrated or added to the alignment
  std::uint64_t invalid = 0;    // NaN/Inf values or non-positive interval
  std::uint64_t unordered = 0;  // duplicate or out-of-order stamps
  std::uint64_t gaps = 0;       // intervals over gap_factor typical intervals
  std::uint64_t failed_alignments = 0;
  std::uint64_t halted = 0;  // samples ignored after a divergence
  std::uint64_t divergences = 0;
  std::uint64_t reinitialisations = 0;
};

// Where and why the navigation state became unusable.
struct Divergence {
  std::int64_t stamp_ns = 0;  // the sample whose step made it unusable
  std::string problem;
};

struct AlignmentResult {
  std::int64_t stamp_ns = 0;  // end of the alignment; the navigation starts here
  std::string method;         // gyrocompass, given_heading or given_attitude
  double duration_s = 0.0;
  Eigen::Quaterniond q_body_to_enu = Eigen::Quaterniond::Identity();
  Eigen::Vector3d roll_pitch_yaw_rad = Eigen::Vector3d::Zero();
  Eigen::Vector3d mean_angular_rate_rad_s = Eigen::Vector3d::Zero();
  Eigen::Vector3d mean_specific_force_m_s2 = Eigen::Vector3d::Zero();
  // 1-sigma error of the small rotation (east tilt, north tilt, heading; alignment_error_budget.h)
  // predicted from the settings' expected sensor errors; NaN where the method does not estimate
  // that angle (a given heading or attitude) and everywhere when no expected errors were given.
  Eigen::Vector3d predicted_error_sigma_rad = Eigen::Vector3d::Zero();
};

// A predicted 1-sigma heading error beyond this makes a gyrocompassed heading no better than a
// guess: the first-order budget (alignment_error_budget.h) no longer holds there, and a heading
// spread evenly over the circle has a sigma of 1.8 rad. A MEMS gyro's bias is typically far above
// the Earth rate's horizontal part (15 deg/h cos L), which is what gyrocompassing measures.
constexpr double kUnobservableHeadingSigma_rad = 1.0;

// Whether the alignment's predicted heading sigma exceeds kUnobservableHeadingSigma_rad (false
// where it was not predicted: no expected errors, or a given heading).
bool heading_unobservable(const AlignmentResult& alignment);

class NavigationSession {
 public:
  // Throws ConfigError (validate()) for settings that cannot work.
  explicit NavigationSession(const NavigationSettings& settings);

  // A sensor_msgs/Imu-like sample: rates averaged over the interval ending at stamp_ns.
  SampleOutcome add_rates(std::int64_t stamp_ns, const Eigen::Vector3d& angular_rate_rad_s,
                          const Eigen::Vector3d& specific_force_m_s2);
  // An imu_lab/ImuIncrement-like sample over increment.dt_s, ending at stamp_ns.
  SampleOutcome add_increment(std::int64_t stamp_ns, const nav::ImuIncrement& increment);

  bool navigating() const { return navigator_.initialised(); }
  // The navigation stopped at a divergence (until reinitialise()).
  bool halted() const { return divergence_.has_value(); }
  const std::optional<Divergence>& divergence() const { return divergence_; }
  // Starts over as a new session would (alignment or the given state at the next sample's stamp);
  // the counters carry on.
  void reinitialise();
  // Whether the last add_* produced a solution to publish (navigation started or advanced).
  bool new_solution() const { return new_solution_; }
  // The latest solution (valid while navigating(), and the last usable one after a divergence)
  // and its stamp.
  const nav::NavState& state() const { return navigator_.state(); }
  std::int64_t stamp_ns() const { return last_stamp_ns_; }
  // Angular rate of the body relative to the ENU frame, body axes, over the last interval.
  const Eigen::Vector3d& body_rate_wrt_enu_rad_s() const { return body_rate_wrt_enu_rad_s_; }
  const std::optional<AlignmentResult>& alignment() const { return alignment_; }
  double alignment_progress_s() const { return aligner_.accumulated_s(); }
  const InputCounters& counters() const { return counters_; }
  // Why the last sample was skipped or the alignment failed (empty otherwise).
  const std::string& last_problem() const { return last_problem_; }
  const NavigationSettings& settings() const { return settings_; }
  // Height aiding for a held vertical channel (e.g. from a topic).
  void set_reference_height(double reference_height_m) { navigator_.set_reference_height(reference_height_m); }

 private:
  // Resets the per-sample flags. Returns the outcome (counted) of a sample that goes no further: a
  // halted session's, or one whose stamp is not after the previous one; otherwise sets the
  // interval's start (none for the first sample) and this stamp becomes the previous one.
  std::optional<SampleOutcome> begin_sample(std::int64_t stamp_ns, std::optional<std::int64_t>& interval_start_ns);
  SampleOutcome skip(SampleOutcome outcome, std::uint64_t& counter, const std::string& problem);
  SampleOutcome integrate(std::int64_t stamp_ns, const nav::ImuIncrement& increment);
  SampleOutcome finish_alignment(std::int64_t stamp_ns);
  void start_navigation(std::int64_t stamp_ns, AlignmentResult result);
  bool is_gap(double interval_s, double expected_interval_s) const;

  NavigationSettings settings_;
  nav::StaticAligner aligner_;
  nav::Navigator navigator_;
  std::optional<AlignmentResult> alignment_;
  std::optional<Divergence> divergence_;
  InputCounters counters_;
  std::string last_problem_;
  std::optional<std::int64_t> previous_stamp_ns_;
  double typical_interval_s_ = 0.0;  // smoothed accepted rate-sample interval
  std::int64_t last_stamp_ns_ = 0;
  bool new_solution_ = false;
  Eigen::Vector3d body_rate_wrt_enu_rad_s_ = Eigen::Vector3d::Zero();
};

}  // namespace pipeline
}  // namespace imu_lab
