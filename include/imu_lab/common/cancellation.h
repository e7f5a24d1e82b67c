// Cooperative cancellation of a long computation running on a thread of its own (the
// allan_monitor node's periodic noise identification, abandoned when the node shuts down, so
// that the report is written within roslaunch's SIGINT timeout). The thread that runs the
// computation opens a CancellationScope over a flag another thread may set; the computation
// calls throw_if_cancelled() at points where nothing shared is half updated (the identification:
// before each AVAR covariance is summed and each solve), and it throws Cancelled once the flag
// is set. Outside a scope throw_if_cancelled() does nothing, so the tools never pay for it.
#pragma once

#include <atomic>
#include <stdexcept>

namespace imu_lab {

class Cancelled : public std::runtime_error {
 public:
  Cancelled() : std::runtime_error("cancelled") {}
};

// While it lives, throw_if_cancelled() on this thread throws once `requested` is true. Scopes
// nest: the inner one's flag is checked, then the outer ones' when it closes.
class CancellationScope {
 public:
  explicit CancellationScope(const std::atomic<bool>& requested);
  ~CancellationScope();
  CancellationScope(const CancellationScope&) = delete;
  CancellationScope& operator=(const CancellationScope&) = delete;

 private:
  const std::atomic<bool>* outer_;
};

// Whether the innermost scope's flag is set (false outside a scope): for a loop that must end
// cleanly first (a Ceres solve told to abort), then throw.
bool cancellation_requested();
void throw_if_cancelled();

}  // namespace imu_lab
