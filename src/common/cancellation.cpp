#include "imu_lab/common/cancellation.h"

namespace imu_lab {
namespace {

thread_local const std::atomic<bool>* current_request = nullptr;

}  // namespace

CancellationScope::CancellationScope(const std::atomic<bool>& requested) : outer_(current_request) {
  current_request = &requested;
}

CancellationScope::~CancellationScope() { current_request = outer_; }

bool cancellation_requested() {
  return current_request != nullptr && current_request->load(std::memory_order_relaxed);
}

void throw_if_cancelled() {
  if (cancellation_requested()) throw Cancelled();
}

}  // namespace imu_lab
